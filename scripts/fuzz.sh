#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz for SECONDS each, two at a time (docs/fuzzing.md).
#   bash scripts/fuzz.sh SECONDS [TARGET...]      e.g. bash scripts/fuzz.sh 600   or   scripts/fuzz.sh 60 stl layout
#   bash scripts/fuzz.sh --table [TARGET...]      the table of the last runs again, from build-fuzz/logs/
#   bash scripts/fuzz.sh --replay [TARGET...]     build, then run each target once over its in-tree seed
#                                                 corpus (CI: the clang tree compiles and every libFuzzer
#                                                 binary runs its regression inputs; no new inputs are made)
#   bash scripts/fuzz.sh --build [CMAKE_TARGET...] build every fuzz target and these CMake targets
#                                                 (CI: sanitize_tests, the tests run under ASan + UBSan)
# Configures and builds the clang tree build-fuzz/ (-DLASTCUT_FUZZ=ON) when needed. Each target
# starts from a copy of its in-tree seed corpus in build-fuzz/corpus/<target> (new inputs stay
# there, not in the tree); crashes go to build-fuzz/artifacts/<target>/, logs to build-fuzz/logs/.
# Prints a table of the runs; exits non-zero when any target crashed.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ] || ! [[ "$1" =~ ^([0-9]+|--table|--replay|--build)$ ]]; then
  echo "usage: scripts/fuzz.sh SECONDS [TARGET...] | scripts/fuzz.sh --table [TARGET...] | scripts/fuzz.sh --replay [TARGET...] | scripts/fuzz.sh --build [CMAKE_TARGET...]" >&2
  exit 2
fi
seconds="$1"
shift
build=build-fuzz
# libFuzzer's coverage instrumentation of every library: needed to fuzz, not to replay stored inputs
# or run the sanitizer tests. CI sets LASTCUT_FUZZ_COVERAGE=OFF for --build and --replay.
coverage=ON
if [[ "$seconds" =~ ^(--build|--replay)$ ]] && [ "${LASTCUT_FUZZ_COVERAGE:-ON}" = OFF ]; then coverage=OFF; fi
if [ "$seconds" = --build ]; then
  extra_cmake_targets=("$@")
  set --
fi
if [ $# -gt 0 ]; then
  targets=("$@")
else
  targets=()
  for source in tests/fuzz/*_fuzz.cpp; do
    name="$(basename "$source")"
    targets+=("${name%_fuzz.cpp}")
  done
fi
# Several targets hand each input to the parser as a file. On a busy machine, opening a file on a
# disk-backed /tmp once stalled for over 30 s and was reported as a timeout: use memory (/dev/shm).
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi

# The biggest input libFuzzer makes: meshes need room for a few hundred triangles.
max_len_of() {
  case "$1" in
    stl | obj | ply | off) echo 65536 ;;
    scan_last) echo 131072 ;;  # a 2000-triangle last as OFF is ~46 kB
    scan_patch) echo 65536 ;;
    nest_instance | layout) echo 32768 ;;
    grbl_reply) echo 4096 ;;
    hpgl_reply) echo 512 ;;  # a full ESC.B buffer ("0") makes the driver sleep 20 ms: keep runs short
    compare) echo 256 ;;  # two outlines of at most 24 points and five marks (compare_fuzz.cpp)
    *) echo 16384 ;;
  esac
}

# build_targets [CMAKE_TARGET...]: every fuzz binary and these targets, in the clang tree.
build_targets() {
  export CCACHE_BASEDIR="$(pwd)" CCACHE_NOHASHDIR=true
  if [ ! -f "$build/CMakeCache.txt" ]; then
    # -O1, as sanitizer builds usually are.
    CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DLASTCUT_FUZZ=ON -DLASTCUT_BUILD_BENCH=OFF \
      -DLASTCUT_FUZZ_COVERAGE="$coverage" >/dev/null
  elif ! grep -qx "LASTCUT_FUZZ_COVERAGE:BOOL=$coverage" "$build/CMakeCache.txt"; then
    cmake -S . -B "$build" -DLASTCUT_FUZZ_COVERAGE="$coverage" >/dev/null
  fi
  nice cmake --build "$build" --target lastcut_fuzz_all "$@" -j "$(nproc)"
}

run_target() {
  local target="$1"
  local corpus="$build/corpus/$target" artifacts="$build/artifacts/$target" logs="$build/logs"
  mkdir -p "$corpus" "$artifacts" "$logs"
  cp tests/fuzz/corpus/"$target"/* "$corpus"/
  touch "$logs/$target.started"
  local started=$SECONDS
  # stdout closed (-close_fd_mask=1): parsers' chatter; libFuzzer reports on stderr.
  nice "$build/bin/${target}_fuzz" "$corpus" -max_total_time="$seconds" -print_final_stats=1 \
    -rss_limit_mb=2048 -max_len="$(max_len_of "$target")" -timeout=30 -close_fd_mask=1 \
    -artifact_prefix="$artifacts/" >"$logs/$target.log" 2>&1 || true
  echo $((SECONDS - started)) >"$logs/$target.seconds"
  echo "finished $target"
}

run_all() {
  local target running=0
  for target in "${targets[@]}"; do
    if [ ! -x "$build/bin/${target}_fuzz" ]; then
      echo "no fuzz target '$target' (tests/fuzz/${target}_fuzz.cpp)" >&2
      exit 2
    fi
  done
  echo "fuzzing ${#targets[@]} targets for $seconds s each, two at a time; logs in $build/logs/"
  for target in "${targets[@]}"; do
    if [ "$running" -ge 2 ]; then
      wait -n
      running=$((running - 1))
    fi
    run_target "$target" &
    running=$((running + 1))
  done
  wait
}

# The table: figures from libFuzzer's final stats and its last status line. Crashes are the
# crash-, leak-, timeout- and oom- files of the target's last run (slow-unit- files are only slow).
# Returns non-zero when any target crashed.
print_table() {
  local target log last_status cov ft corpus crashes crashed=0
  printf '%-16s %8s %12s %8s %8s %8s %12s %8s\n' target seconds executions exec/s cov ft corpus crashes
  for target in "${targets[@]}"; do
    log="$build/logs/$target.log"
    if [ ! -f "$log" ]; then
      printf '%-16s not run\n' "$target"
      continue
    fi
    last_status="$(grep -aE '(cov|ft): [0-9]+' "$log" | tail -1 || true)"
    cov="$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<<"$last_status")"
    ft="$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<<"$last_status")"
    corpus="$(sed -n 's/.*corp: \([0-9]*\/[0-9]*[a-zA-Z]*\).*/\1/p' <<<"$last_status")"
    crashes="$(find "$build/artifacts/$target" -type f -newer "$build/logs/$target.started" \
      \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)"
    if [ "$crashes" -gt 0 ] || grep -aqE '^==[0-9]+==ERROR|^SUMMARY: (Address|Undefined)|deadly signal' "$log"; then
      crashed=1
      [ "$crashes" -gt 0 ] || crashes="see log"
    fi
    # sed, not grep: libFuzzer logs may hold bytes of the inputs.
    printf '%-16s %8s %12s %8s %8s %8s %12s %8s\n' "$target" "$(cat "$build/logs/$target.seconds")" \
      "$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)" \
      "$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)" "${cov:--}" "${ft:--}" "${corpus:--}" "$crashes"
  done
  if [ "$crashed" -ne 0 ]; then
    echo "crashes: see $build/artifacts/<target>/ and $build/logs/<target>.log" >&2
    return 1
  fi
}

# Each target once over the files of its in-tree seed corpus (libFuzzer's run-these-files mode):
# deterministic, so a failure is a crash of that build on a stored input, never a new find.
replay_all() {
  local target files failed=() logs="$build/logs"
  mkdir -p "$logs"
  for target in "${targets[@]}"; do
    mapfile -t files < <(find "tests/fuzz/corpus/$target" -type f | sort)
    if [ ${#files[@]} -eq 0 ]; then
      echo "fuzz replay: no seed corpus for '$target' (tests/fuzz/corpus/$target/)" >&2
      failed+=("$target")
      continue
    fi
    if "$build/bin/${target}_fuzz" -rss_limit_mb=2048 -timeout=30 -close_fd_mask=1 "${files[@]}" \
      >"$logs/$target.replay.log" 2>&1; then
      echo "fuzz replay: $target ran ${#files[@]} inputs"
    else
      echo "fuzz replay: $target FAILED on its seed corpus; the end of $logs/$target.replay.log:" >&2
      tail -n 30 "$logs/$target.replay.log" | sed -n 'l 200' >&2  # escaped: the log may hold input bytes
      failed+=("$target")
    fi
  done
  if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz replay failed: ${failed[*]}" >&2
    return 1
  fi
}

case "$seconds" in
  --table) print_table ;;
  --build) build_targets "${extra_cmake_targets[@]}" ;;
  --replay)
    build_targets
    replay_all
    ;;
  *)
    build_targets
    run_all
    print_table
    ;;
esac
