#!/usr/bin/env bash
# Every shipped grbl profile's cut file (tests/peers/grbl_profiles_on_firmware.sh: the drag knife
# with its pens lowered and raised by M8/M9 buffer syncs, the oscillating knife, ...) run to the end
# on the real grbl 1.1h firmware RUNS times in a row while two busy processes keep both cores
# loaded. Prints each run's per-profile lines and a summary; exits non-zero if any run failed.
# Usage: grbl_profiles_under_load.sh BUILD_DIR [RUNS=10]
set -euo pipefail
build="$(cd "$1" && pwd)"; runs="${2:-10}"
source_dir="$(cd "$(dirname "$0")/../.." && pwd)"
firmware="$build/peers/grbl/grbl_sim.exe"
[ -x "$firmware" ] || { echo "no firmware at $firmware: build the project first" >&2; exit 1; }
loaders=()
trap 'kill "${loaders[@]}" 2>/dev/null || true' EXIT
for _ in 1 2; do yes >/dev/null & loaders+=($!); done
echo "load: 2 busy processes (yes), $(nproc) cores"
failed_runs=0
for ((run = 1; run <= runs; run++)); do
  start=$(date +%s)
  if bash "$source_dir/tests/peers/grbl_profiles_on_firmware.sh" "$build" "$firmware" "$source_dir" >"$build/.profiles_run.log" 2>&1; then
    verdict=PASS
  else
    verdict=FAIL; failed_runs=$((failed_runs + 1))
  fi
  echo "run $run: $verdict in $(( $(date +%s) - start )) s"
  sed 's/^/  /' "$build/.profiles_run.log"
done
rm -f "$build/.profiles_run.log"
echo "$((runs - failed_runs)) of $runs runs: every profile passed (each 3-axis profile ran to the end; a rotary-axis profile was refused before its first line)"
[ "$failed_runs" -eq 0 ]
