#!/usr/bin/env bash
# Configures and builds lastcut into build/ (or the folder given as $1, with extra CMake options after it).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build}"
# ccache keys on absolute paths; with the base folder set, clones in other folders share the cache.
export CCACHE_BASEDIR="$(pwd)"
shift || true
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
