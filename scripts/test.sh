#!/usr/bin/env bash
# The whole test suite, from a fresh machine: install dependencies, build, run every test,
# then build once more with clang under AddressSanitizer + UndefinedBehaviorSanitizer, run the
# tests labelled `sanitize` (bad input, parsers, protocols) there and each libFuzzer target over
# its seed corpus; last, build the Debian package.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"
# Each stage's heading says when it started, so a slow CI run shows where its time went.
stage() { echo "== $* (at $((SECONDS / 60)) min $((SECONDS % 60)) s)"; }

bash scripts/setup.sh

stage "build (RelWithDebInfo)"
# Tests and benchmarks on, also in a build folder the demo configured without them.
# The fuzz corpora are replayed by the clang tree below, under ASan + UBSan: not built twice.
bash scripts/build.sh build -DLASTCUT_BUILD_TESTS=ON -DLASTCUT_BUILD_BENCH=ON -DLASTCUT_BUILD_FUZZ_REPLAYS=OFF
stage "tests"
# Every test, the ones on the real grbl 1.1h firmware included (labels firmware, firmware-slow:
# tests/peers, docs/grbl-firmware.md); they share one resource lock, so one firmware runs at a time.
ctest --test-dir build --output-on-failure -j "$jobs" --timeout 600

# One clang tree (build-fuzz/, docs/fuzzing.md) for both sanitizer stages: every library and program
# is compiled there with ASan + UBSan (and libFuzzer's coverage, which the tests do not notice), so
# the sanitized tests and the fuzz targets share one build of the libraries instead of two. It also
# keeps the code building with clang: gcc accepts some constructs clang refuses.
stage "build (clang, ASan + UBSan): the tests labelled sanitize and the libFuzzer targets"
# Without libFuzzer's coverage instrumentation (only needed to fuzz, not to replay): a tenth faster.
export LASTCUT_FUZZ_COVERAGE=OFF
bash scripts/fuzz.sh --build sanitize_tests
stage "tests under ASan + UBSan (label: sanitize)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-fuzz --output-on-failure -j "$jobs" -L sanitize --no-tests=error --timeout 600
# Each fuzz binary runs its seed corpus (the regression inputs) once: no fuzzing, nothing random.
stage "fuzz targets: each over its seed corpus"
bash scripts/fuzz.sh --replay

# The Debian package an IT admin installs (docs/packaging.md): built from HEAD with dpkg-buildpackage
# and checked by lintian. Nothing else builds it, and once a missing comma in debian/control kept
# it from building for days unseen. (scripts/check_package.sh, the install into a fresh debootstrap
# root, needs mount and chroot and stays a manual step.)
# Unoptimised and without debug information (noopt, -g0): CI checks the packaging (rules, install
# lists, systemd files, lintian), and the optimised code is what the stages above tested; an
# admin's scripts/package.sh optimises (it took 9.5 minutes here, this one a few).
stage "the Debian package (scripts/package.sh)"
DEB_BUILD_OPTIONS="noopt noautodbgsym" DEB_CXXFLAGS_APPEND="-g0" bash scripts/package.sh
stage "done"
