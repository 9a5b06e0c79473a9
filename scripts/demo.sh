#!/usr/bin/env bash
# The main job: builds lastcut and runs it on the bundled sample last, output in ./demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
mkdir -p demo
build/bin/lastcut flatten config/samples/sample-last-eu42-left.stl -o demo/molds
echo "molds, meshes and report in $(pwd)/demo/molds"
