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
# The tests on the real grbl firmware (labels firmware, firmware-slow) run on their own:
# `ctest --test-dir build -L firmware`. Its simulator (grbl-sim, not ours) still stalls now and
# then under load (docs/grbl-firmware.md), and a stall must not make this run a lottery. The
# firmware itself is still built here (target grbl_firmware), so its build is checked.
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600 -LE firmware

echo "== build (ASan + UBSan)"
bash scripts/build.sh build-asan -DLASTCUT_SANITIZE=ON -DLASTCUT_BUILD_BENCH=OFF
echo "== tests under ASan + UBSan (label: sanitize)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -L sanitize --no-tests=error --timeout 600
