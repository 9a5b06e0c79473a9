#!/usr/bin/env bash
# Load benchmark of lastcutd: N scans (default 200, small generated lasts, each with its own
# bytes) dropped into the watch folder at once while the daemon runs with one simulated HPGL
# cutter. Prints: time until every job is done, jobs per minute, inotify overflows seen, files
# lost (must be 0), and lastcutd's peak resident memory (VmHWM) next to its memory after start,
# to show the memory stays bounded (the queues hold ids, not geometry). With WATCHERS > 0 the
# daemon serves its operator page and that many pages of it watch in one headless chromium
# (page_watchers.js): the table gains the watchers, the events they saw and how late (median,
# p99, max, and how many over 1 s); compare with a run of 0 watchers (page_load_bench.sh does both).
# KIND `stream` (default) makes the pages' requests without browsers (stream_watchers.js: the
# daemon's cost of serving them, as on a shop floor where the pages run on other computers);
# `browser` runs the real page in chromium on this machine (page_watchers.js: the browsers' own
# rendering then competes with the daemon for the same cores).
# Usage: load_bench.sh BUILD_DIR [SCANS] [TRIANGLES] [WATCHERS] [KIND]
# STATION_CPUS=0 WATCHER_CPUS=1 (taskset lists): the station (lastcutd, its workers, the simulated
# cutter) and the watching pages on separate cores, as the pages are on other computers in a shop;
# compute workers = the station's cores. Give both runs of a comparison the same STATION_CPUS.
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
scans="${2:-200}"
triangles="${3:-2000}"
watchers="${4:-0}"
kind="${5:-stream}"
source_dir="$(cd "$(dirname "$0")/../.." && pwd)"
bin="$build/bin"
root="$build/bench-scratch/daemon-load"
rm -rf "$root"
mkdir -p "$root/incoming" "$root/staging" "$root/lasts"

station=() watcher_cpus=()
workers="$(nproc)"
if [ -n "${STATION_CPUS:-}" ]; then station=(taskset -c "$STATION_CPUS"); workers="$(taskset -c "$STATION_CPUS" nproc)"; fi
if [ -n "${WATCHER_CPUS:-}" ]; then watcher_cpus=(taskset -c "$WATCHER_CPUS"); fi

source "$source_dir/tests/stress/daemon_scratch.sh"
write_daemon_config "$root/lastcut.toml" "$source_dir" \
  'stable_interval_s = 0.1' \
  "compute_workers = $workers" \
  $'window_s = 5\nmax_pieces = 16\nnest_time_s = 1' \
  'retry_interval_s = 0.5'
if [ "$watchers" -gt 0 ]; then
  web_port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  printf '[web]\nlisten = "127.0.0.1:%s"\nassets = "%s/daemon/web/assets"\nmax_watchers = 48\nrequests_per_s = 1000\n' \
    "$web_port" "$source_dir" >> "$root/lastcut.toml"
fi

generate_left_lasts "$bin" "$root/lasts" "$triangles" 38 40 42 44
python3 - "$root" "$scans" <<'PY'
import sys, os
root, count = sys.argv[1], int(sys.argv[2])
bases = [open(os.path.join(root, 'lasts', f'last-{s}.stl'), 'rb').read() for s in (38, 40, 42, 44)]
for i in range(count):
    data = bytearray(bases[i % 4])
    data[0:80] = f'load scan {i}'.ljust(80).encode()
    open(os.path.join(root, 'staging', f'scan-{i:04d}.stl'), 'wb').write(data)
PY

"${station[@]}" "$bin/lastcut-sim" hpgl --link "$root/cutter-1.tty" --record "$root/record" --time-scale 0 > "$root/sim.log" 2>&1 &
sim=$!
trap 'kill $sim 2>/dev/null || true; [ -n "${daemon:-}" ] && kill $daemon 2>/dev/null || true' EXIT
wait_for_line "$root/sim.log" "ready:" || true
"${station[@]}" "$bin/lastcutd" --config "$root/lastcut.toml" > "$root/lastcutd.log" 2>&1 &
daemon=$!
wait_for_line "$root/lastcutd.log" "lastcutd ready" || true
if [ "$watchers" -gt 0 ] && [ "$kind" = browser ]; then
  "${watcher_cpus[@]}" node "$source_dir/bench/daemon/page_watchers.js" "http://127.0.0.1:$web_port/" "$watchers" \
    "$source_dir/tests/node/node_modules" > "$root/watchers.json" 2> "$root/watchers.log" &
  watcher_pid=$!
elif [ "$watchers" -gt 0 ]; then
  "${watcher_cpus[@]}" node "$source_dir/bench/daemon/stream_watchers.js" "http://127.0.0.1:$web_port/" "$watchers" \
    "$root/watchers.json" 2> "$root/watchers.log" &
  watcher_pid=$!
fi
if [ "$watchers" -gt 0 ]; then
  for _ in $(seq 600); do grep -q "pages live" "$root/watchers.log" && break; sleep 0.1; done
  grep -q "pages live" "$root/watchers.log" || { echo "the watching pages did not start:"; cat "$root/watchers.log"; exit 1; }
fi
rss_start_kb=$(awk '/VmRSS/ {print $2}' /proc/$daemon/status)

start=$(date +%s.%N)
mv "$root"/staging/*.stl "$root/incoming/"      # all at once
while :; do
  finished=$(( $(ls "$root/spool/done" 2>/dev/null | wc -l) + $(ls "$root/spool/failed" 2>/dev/null | wc -l) + $(ls "$root/spool/held" 2>/dev/null | wc -l) ))
  [ "$finished" -ge "$scans" ] && break
  kill -0 $daemon || { echo "lastcutd died"; tail "$root/lastcutd.log"; exit 1; }
  sleep 0.5
done
end=$(date +%s.%N)
peak_kb=$(awk '/VmHWM/ {print $2}' /proc/$daemon/status)
# The last events (the final cut) reach the watchers within a second or two.
if [ "$watchers" -gt 0 ]; then sleep 3; kill -TERM "$watcher_pid"; wait "$watcher_pid" || true; fi
kill -TERM $daemon; wait $daemon || true; daemon=""
kill -TERM $sim; wait $sim || true

done_count=$(ls "$root/spool/done" | wc -l)
failed_count=$(ls "$root/spool/failed" | wc -l)
held_count=$(ls "$root/spool/held" | wc -l)
left=$(ls "$root/incoming" | wc -l)
overflows=$(grep -c "queue overflow" "$root/lastcutd.log" || true)
cut_jobs=$(python3 - "$root" <<'PY'
import json, os, sys
root = sys.argv[1]
record = open(os.path.join(root, 'record', 'hpgl-received.hpgl')).read()
total = 0
for batch in os.listdir(os.path.join(root, 'spool', 'batches')):
    info = json.load(open(os.path.join(root, 'spool', 'batches', batch, 'batch.json')))
    if info.get('cut_file') and info.get('stage') == 'cut':
        program = open(os.path.join(root, 'spool', 'batches', batch, info['cut_file'])).read()
        if record.count(program) == 1:
            total += len(info['jobs'])
print(total)
PY
)
elapsed=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')
echo "| scans | triangles each | workers | time to all done (s) | jobs/min | done | failed | held | left in watch folder | jobs cut (record) | inotify overflows | RSS after start (MB) | peak RSS (MB) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
awk -v n="$scans" -v t="$triangles" -v w="$workers" -v e="$elapsed" -v d="$done_count" -v f="$failed_count" -v h="$held_count" \
    -v l="$left" -v c="$cut_jobs" -v o="$overflows" -v r0="$rss_start_kb" -v r="$peak_kb" \
  'BEGIN { printf "| %d | %d | %d | %.1f | %.1f | %d | %d | %d | %d | %d | %d | %.1f | %.1f |\n", n, t, w, e, 60 * n / e, d, f, h, l, c, o, r0 / 1024, r / 1024 }'
if [ "$watchers" -gt 0 ]; then
  echo "watching pages ($kind): $(cat "$root/watchers.json")"
  grep -q '"over_1s":0' "$root/watchers.json" || echo "SOME EVENTS ARRIVED LATER THAN 1 s"
fi
[ "$done_count" -eq "$scans" ] && [ "$left" -eq 0 ] && [ "$cut_jobs" -eq "$scans" ]
