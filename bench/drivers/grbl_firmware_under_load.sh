#!/usr/bin/env bash
# No motion line lost or duplicated under CPU load: the 3,000-move job of
# tests/peers/grbl_firmware_test.cpp, streamed by `lastcut send` to the real grbl 1.1h firmware
# (tests/peers/run_grbl_firmware.sh) RUNS times in a row while two busy processes keep both cores
# loaded. Each run starts a fresh firmware and compares the firmware's block log (one line per
# planner block it committed) with the motion lines of the file, and its last block with home.
# Prints one row per run and exits non-zero if any run differs.
# Usage: grbl_firmware_under_load.sh BUILD_DIR [RUNS=10]
set -euo pipefail
build="$(cd "$1" && pwd)"; runs="${2:-10}"
here="$(cd "$(dirname "$0")" && pwd)"
runner="$here/../../tests/peers/run_grbl_firmware.sh"
firmware="$build/peers/grbl/grbl_sim.exe"
[ -x "$firmware" ] || { echo "no firmware at $firmware: build the project first" >&2; exit 1; }
work="$(mktemp -d)"
loaders=()
cleanup() { kill "${loaders[@]}" "${runner_pid:-}" 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

# The job: 3,000 short zigzag moves (each a real move: one planner block), then home.
{
  echo "G21"; echo "G90"; echo "G1 F60000"
  awk 'BEGIN { for (i = 0; i < 3000; i++) printf "G1 X%g Y%g\n", 10 + (i % 2) * 1.5 + (i % 7) * 0.1, 10 + i * 0.05 }'
  echo "G0 X0 Y0"; echo "M2"
} >"$work/job.nc"
motion_lines="$(grep -cE '^G[01] X' "$work/job.nc")"

for _ in 1 2; do yes >/dev/null & loaders+=($!); done
echo "load: 2 busy processes (yes), $(nproc) cores; job: $motion_lines motion lines"
printf "%-4s %-9s %-8s %-13s %-10s %s\n" run seconds blocks motion_lines last_block result
failures=0
for ((run = 1; run <= runs; run++)); do
  dir="$work/run$run"
  bash "$runner" "$firmware" "$dir" >"$work/runner.log" 2>&1 & runner_pid=$!
  for _ in $(seq 200); do grep -q '^ready:' "$work/runner.log" 2>/dev/null && break; sleep 0.05; done
  start=$(date +%s.%N)
  if "$build/bin/lastcut" send "$work/job.nc" --protocol grbl --port "$dir/tty" --timeout 60 \
       --grbl-setting '$110=60000,$111=60000,$112=60000,$120=500000,$121=500000,$122=500000' >"$dir/send.log" 2>&1; then
    sent=ok
  else
    sent="send failed: $(grep -m1 '^lastcut:' "$dir/send.log" | cut -c1-160)"
  fi
  seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  kill "$runner_pid"; wait "$runner_pid" 2>/dev/null || true
  blocks="$(wc -l <"$dir/blocks.txt")"
  last="$(tail -1 "$dir/blocks.txt" | cut -d, -f1-3 | tr -d ' ')"
  result=PASS
  if [ "$sent" != ok ] || [ "$blocks" -ne "$motion_lines" ] || [ "$last" != "0,0,0" ]; then result="FAIL $sent"; failures=$((failures + 1)); fi
  printf "%-4s %-9s %-8s %-13s %-10s %s\n" "$run" "$seconds" "$blocks" "$motion_lines" "$last" "$result"
done
echo "$((runs - failures)) of $runs runs executed every block"
[ "$failures" -eq 0 ]
