#!/usr/bin/env bash
# Configures and builds lastcut into build/ (or the folder given as $1, with extra CMake options after it).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build}"
# ccache keys on absolute paths and, for builds with debug info, on the working folder; with the
# base folder set and the folder left out of the key, clones in other folders share the cache.
export CCACHE_BASEDIR="$(pwd)"
export CCACHE_NOHASHDIR=true
shift || true
# The shared reference data may live elsewhere than ../shared/data: LASTCUT_SHARED_DATA_DIR=/path.
data_option=()
if [ -n "${LASTCUT_SHARED_DATA_DIR:-}" ]; then data_option=(-DLASTCUT_SHARED_DATA_DIR="$LASTCUT_SHARED_DATA_DIR"); fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${data_option[@]}" "$@" >/dev/null
# LASTCUT_BUILD_TARGET="name ..." builds these targets (and what they need) instead of everything.
# shellcheck disable=SC2086 # the list is split into its names on purpose
cmake --build "$build_dir" -j "$(nproc)" ${LASTCUT_BUILD_TARGET:+--target $LASTCUT_BUILD_TARGET}
