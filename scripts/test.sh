#!/usr/bin/env bash
# The whole test suite, from a fresh machine: install dependencies, build, run every test,
# then build once more under AddressSanitizer + UndefinedBehaviorSanitizer and run the
# tests labelled `sanitize` (bad input, parsers, protocols) there too.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"

bash scripts/setup.sh

echo "== build (RelWithDebInfo)"
bash scripts/build.sh build
echo "== tests"
# firmware-slow: every shipped profile's whole cut file on the real grbl firmware (minutes; see
# docs/grbl-firmware.md), run on its own with `ctest --test-dir build -L firmware-slow`.
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600 -LE firmware-slow

echo "== build (ASan + UBSan)"
bash scripts/build.sh build-asan -DLASTCUT_SANITIZE=ON -DLASTCUT_BUILD_BENCH=OFF
echo "== tests under ASan + UBSan (label: sanitize)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -L sanitize --no-tests=error --timeout 600
