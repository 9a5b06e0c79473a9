#!/usr/bin/env bash
# The whole test suite, from a fresh machine: install dependencies, build, run every test,
# then build once more under AddressSanitizer + UndefinedBehaviorSanitizer and run the
# tests labelled `sanitize` (bad input, parsers, protocols) there too; last, build the clang
# libFuzzer targets and run each over its seed corpus.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"

bash scripts/setup.sh

echo "== build (RelWithDebInfo)"
bash scripts/build.sh build
echo "== tests"
# Every test, the ones on the real grbl 1.1h firmware included (labels firmware, firmware-slow:
# tests/peers, docs/grbl-firmware.md); they share one resource lock, so one firmware runs at a time.
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600

echo "== build (ASan + UBSan)"
bash scripts/build.sh build-asan -DLASTCUT_SANITIZE=ON -DLASTCUT_BUILD_BENCH=OFF
echo "== tests under ASan + UBSan (label: sanitize)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -L sanitize --no-tests=error --timeout 600

# The clang libFuzzer tree (docs/fuzzing.md): gcc accepts some constructs clang refuses, and once
# the fuzz build broke unseen. Built here so it cannot again, and each fuzz binary runs its seed
# corpus (the regression inputs) once under clang's ASan + UBSan: no fuzzing, nothing random.
echo "== fuzz targets (clang + libFuzzer): build, then each over its seed corpus"
bash scripts/fuzz.sh --replay
