#!/usr/bin/env bash
# Crash test of lastcutd: the daemon is killed with SIGKILL at random moments while scans keep
# arriving and a simulated HPGL cutter cuts. After every restart the spool must be consistent:
#   - no job lost: every scan dropped is in exactly one job folder (done/, failed/ or held/)
#   - none cut twice: the exact cut file of every batch appears at most once in the simulator's
#     record, exactly once for jobs in done/; a job interrupted while being sent is in held/
#   - nothing half-written visible: every state/batch/report file parses, no temporary left
# Usage: crash_test.sh TRIALS BUILD_DIR [SEED]     (CI: 10 trials; the full run: 50)
set -euo pipefail
trials="${1:-50}"
build="$(cd "${2:-build}" && pwd)"
seed="${3:-$$}"
RANDOM=$seed
source_dir="$(cd "$(dirname "$0")/../.." && pwd)"
bin="$build/bin"
for program in lastcutd lastcut lastcut-sim; do
  [ -x "$bin/$program" ] || { echo "FAIL: $bin/$program is not built"; exit 1; }
done
root="$build/test-scratch/stress-crash"
rm -rf "$root"
mkdir -p "$root/incoming" "$root/staging" "$root/lasts"
echo "crash test: $trials trials, seed $seed, folder $root"

source "$source_dir/tests/stress/daemon_scratch.sh"
write_daemon_config "$root/lastcut.toml" "$source_dir" \
  $'rescan_interval_s = 2\nstable_interval_s = 0.05\nincomplete_grace_s = 0.5' \
  $'# Kills from outside land during computations too; they must not fail good scans.\nmax_attempts = 100\nstop_grace_s = 10' \
  $'window_s = 0.3\nnest_time_s = 0.2' \
  $'timeout_s = 5\nretry_interval_s = 0.3'

generate_left_lasts "$bin" "$root/lasts" 2000 39 41 43

# An HPGL plotter (the simulator records the exact bytes received); the wire is modelled at
# 38400 baud, so a cut takes long enough to be killed in the middle.
"$bin/lastcut-sim" hpgl --link "$root/cutter-1.tty" --record "$root/record" --time-scale 0 --baud 38400 \
  > "$root/sim.log" 2>&1 &
sim_pid=$!
daemon_pid=""
cleanup() {
  [ -n "$daemon_pid" ] && kill -9 "$daemon_pid" 2>/dev/null || true
  kill "$sim_pid" 2>/dev/null || true
}
trap cleanup EXIT
wait_for_line "$root/sim.log" "ready:" || true

# A new scan: a generated last with its own 80-byte header, so every file has its own hash.
dropped=0
drop_scan() {
  local name="scan-$1.stl" base="$root/lasts/last-$(( 39 + 2 * (RANDOM % 3) )).stl"
  python3 - "$base" "$root/staging/$name" "$1" <<'PY'
import sys
data = bytearray(open(sys.argv[1], 'rb').read())
data[0:80] = ('crash test scan ' + sys.argv[3]).ljust(80).encode()
open(sys.argv[2], 'wb').write(data)
PY
  mv "$root/staging/$name" "$root/incoming/$name"
  dropped=$((dropped + 1))
}

for trial in $(seq "$trials"); do
  drop_scan "$trial-a"
  drop_scan "$trial-b"
  "$bin/lastcutd" --config "$root/lastcut.toml" >> "$root/lastcutd.log" 2>&1 &
  daemon_pid=$!
  sleep "$(awk -v r=$RANDOM 'BEGIN { printf "%.2f", 0.2 + 2.3 * r / 32767 }')"
  kill -9 "$daemon_pid" 2>/dev/null || true
  wait "$daemon_pid" 2>/dev/null || true
  daemon_pid=""
  echo "trial $trial: killed; done $(ls "$root/spool/done" 2>/dev/null | wc -l), held $(ls "$root/spool/held" 2>/dev/null | wc -l), work $(ls "$root/spool/work" 2>/dev/null | wc -l)"
done

# Final run: everything still pending must finish, then a clean stop.
"$bin/lastcutd" --config "$root/lastcut.toml" >> "$root/lastcutd.log" 2>&1 &
daemon_pid=$!
for _ in $(seq 1200); do
  if [ -z "$(ls -A "$root/incoming")" ] && [ -z "$(ls "$root/spool/work")" ]; then break; fi
  sleep 0.1
done
kill -TERM "$daemon_pid"
wait "$daemon_pid" || { echo "FAIL: lastcutd did not stop cleanly"; exit 1; }
daemon_pid=""
kill -TERM "$sim_pid"
wait "$sim_pid" || true

python3 - "$root" "$dropped" <<'PY'
import json, os, re, sys
root, dropped = sys.argv[1], int(sys.argv[2])
spool = os.path.join(root, 'spool')
problems = []
where = {}
for folder in ('work', 'done', 'failed', 'held'):
    base = os.path.join(spool, folder)
    for job in sorted(os.listdir(base)):
        if job.startswith('.'):
            continue
        for name in os.listdir(os.path.join(base, job)):
            if name.startswith('.tmp-'):
                problems.append(f'{folder}/{job}: leftover temporary {name}')
        for name in ('state.json', 'report.json'):
            path = os.path.join(base, job, name)
            if os.path.exists(path):
                try:
                    json.load(open(path))
                except ValueError:
                    problems.append(f'{folder}/{job}/{name} is half-written')
        state = json.load(open(os.path.join(base, job, 'state.json')))
        where.setdefault(state['scan'], []).append((folder, job, state))
for batch in os.listdir(os.path.join(spool, 'batches')):
    try:
        json.load(open(os.path.join(spool, 'batches', batch, 'batch.json')))
    except (ValueError, FileNotFoundError) as error:
        problems.append(f'batches/{batch}: {error}')
leftover = [n for n in os.listdir(os.path.join(root, 'incoming'))]
if leftover:
    problems.append(f'still in the watch folder: {leftover}')
if len(where) != dropped:
    problems.append(f'{dropped} scans dropped, {len(where)} found in the spool')
for scan, places in where.items():
    if len(places) != 1:
        problems.append(f'{scan} is in {len(places)} job folders: {[p[:2] for p in places]}')
record = open(os.path.join(root, 'record', 'hpgl-received.hpgl')).read()
cut_counts = {}
for batch in os.listdir(os.path.join(spool, 'batches')):
    info = json.load(open(os.path.join(spool, 'batches', batch, 'batch.json')))
    if not info.get('cut_file'):
        continue
    program = open(os.path.join(spool, 'batches', batch, info['cut_file'])).read()
    sent = record.count(program) if program else 0
    for job in info.get('jobs', []):
        cut_counts[job] = cut_counts.get(job, 0) + sent
counts = {'work': 0, 'done': 0, 'failed': 0, 'held': 0}
for scan, places in where.items():
    folder, job, state = places[0]
    counts[folder] += 1
    sent = cut_counts.get(job, 0)
    if sent > 1:
        problems.append(f'job {job} ({scan}) was sent to the cutter {sent} times')
    if folder == 'done' and state['stage'] == 'cut' and sent != 1:
        problems.append(f'job {job} ({scan}) is done but was sent {sent} times')
    if folder == 'failed':
        problems.append(f'job {job} ({scan}) failed: {state["reason"]}')
    if folder == 'work':
        problems.append(f'job {job} ({scan}) still in work/ after the final run')
held_reasons = sorted({p[0][2]['reason'][:90] for p in where.values() if p[0][0] == 'held'})
print(f"scans dropped {dropped}; done {counts['done']}, held {counts['held']}, failed {counts['failed']}, "
      f"work {counts['work']}; cut programs recorded {sum(cut_counts.values())}")
for reason in held_reasons:
    print(f'  held because: {reason}')
if problems:
    print('FAIL:')
    for problem in problems:
        print('  ' + problem)
    sys.exit(1)
print('OK: no job lost, none cut twice, nothing half-written')
PY
