#!/usr/bin/env bash
# The whole test suite, from a fresh machine: install dependencies, build, run every test,
# then build once more under AddressSanitizer + UndefinedBehaviorSanitizer and run the
# tests labelled `sanitize` (bad input, parsers, protocols) there too; then build the clang
# libFuzzer targets and run each over its seed corpus; last, build the Debian package.
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
# Only what the sanitized tests need (the target sanitize_tests, cmake/lastcut_target.cmake): the
# other test programs are not run there, and building them took a quarter of CI's time.
LASTCUT_BUILD_TARGET=sanitize_tests bash scripts/build.sh build-asan -DLASTCUT_SANITIZE=ON -DLASTCUT_BUILD_BENCH=OFF
echo "== tests under ASan + UBSan (label: sanitize)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -L sanitize --no-tests=error --timeout 600

# The clang libFuzzer tree (docs/fuzzing.md): gcc accepts some constructs clang refuses, and once
# the fuzz build broke unseen. Built here so it cannot again, and each fuzz binary runs its seed
# corpus (the regression inputs) once under clang's ASan + UBSan: no fuzzing, nothing random.
echo "== fuzz targets (clang + libFuzzer): build, then each over its seed corpus"
bash scripts/fuzz.sh --replay

# The Debian package an IT admin installs (docs/packaging.md): built from HEAD with dpkg-buildpackage
# and checked by lintian. Nothing else builds it, and once a missing comma in debian/control kept
# it from building for days unseen. (scripts/check_package.sh, the install into a fresh debootstrap
# root, needs mount and chroot and stays a manual step.)
echo "== the Debian package (scripts/package.sh)"
bash scripts/package.sh
