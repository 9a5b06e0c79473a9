#!/usr/bin/env bash
# The load bench twice in one run: 200 scans with no page watching, then with 20 operator pages
# watching (Debian's chromium), and the ratio of their throughputs (docs/operator-page.md).
# KIND: stream (default, the pages' requests without browsers) or browser (load_bench.sh).
# Usage: page_load_bench.sh BUILD_DIR [SCANS] [WATCHERS] [KIND]
set -euo pipefail
build="${1:-build}"
scans="${2:-200}"
watchers="${3:-20}"
kind="${4:-stream}"
here="$(cd "$(dirname "$0")" && pwd)"
without="$(bash "$here/load_bench.sh" "$build" "$scans" 2000 0 | tail -1)"
with_output="$(bash "$here/load_bench.sh" "$build" "$scans" 2000 "$watchers" "$kind")"
echo "$with_output" | grep -v '^|' || true
with="$(echo "$with_output" | grep '^| ' | tail -1)"
echo "| watchers | scans | triangles each | workers | time to all done (s) | jobs/min | done | failed | held | left | jobs cut | overflows | RSS after start (MB) | peak RSS (MB) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
echo "| 0 $without"
echo "| $watchers $with"
awk -v a="$(echo "$without" | cut -d'|' -f6)" -v b="$(echo "$with" | cut -d'|' -f6)" \
  'BEGIN { printf "throughput with the pages watching: %.3f of the run without them (%+.1f %%)\n", b / a, 100 * (b / a - 1) }'
