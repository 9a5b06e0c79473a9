#!/usr/bin/env bash
# The main job, end to end, on this machine: installs and builds lastcut, starts two simulated
# cutters (a grbl drag-knife table and an HPGL plotter on pseudo-terminals), runs the daemon
# lastcutd with config/demo/lastcut.toml (watch folder and spool under ./demo/), drops the sample
# lasts into the watch folder, waits until every job is cut and shows where the molds, layouts, cut
# files and reports are. lastcutd serves the operator's page (http://127.0.0.1:8631/): run in a
# terminal, the daemon and the page stay up until Ctrl-C; run without one (tests, CI, scripts),
# the daemon is stopped cleanly once the jobs are done.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"

# LASTCUT_DEMO_BUILD=build-folder: reuse an existing build (developers), skipping setup and build.
if [ -n "${LASTCUT_DEMO_BUILD:-}" ]; then
  bin="$(cd "$LASTCUT_DEMO_BUILD" && pwd)/bin"
else
  # Only what the three programs the demo runs need, not the test suite's browser, servers and tools.
  bash scripts/setup.sh --programs
  # Only those three programs, not the tests and benchmarks. A new build folder is configured
  # without them (so their frameworks need not be installed); one the test suite configured is
  # kept as it is, and only the programs are brought up to date in it.
  options=()
  if [ ! -f build/CMakeCache.txt ]; then options=(-DLASTCUT_BUILD_TESTS=OFF -DLASTCUT_BUILD_BENCH=OFF); fi
  LASTCUT_BUILD_TARGET="lastcutd lastcut lastcut-sim" bash scripts/build.sh build "${options[@]}"
  bin="$root/build/bin"
fi

# LASTCUT_DEMO_DIR=folder: run the demo there instead of ./demo/ (the test suite's run of this script);
# the shipped demo configuration is copied there with its paths pointing into that folder.
demo="${LASTCUT_DEMO_DIR:-$root/demo}"
config="$root/config/demo/lastcut.toml"
rm -rf "$demo/incoming" "$demo/spool" "$demo/staging" "$demo/cutter-records"
mkdir -p "$demo/incoming" "$demo/staging" "$demo/cutter-records"
if [ -n "${LASTCUT_DEMO_DIR:-}" ]; then
  demo="$(cd "$demo" && pwd)"
  # ... and the page on a port of the system's choice, so that a test run never meets a demo running.
  sed -e "s|\"../../demo/|\"$demo/|" -e "s|\"../machines\"|\"$root/config/machines\"|" \
      -e "s|\"../../daemon/web/assets\"|\"$root/daemon/web/assets\"|" -e "s|^listen = .*|listen = \"127.0.0.1:0\"|" \
      "$config" > "$demo/lastcut.toml"
  config="$demo/lastcut.toml"
fi

pids=()
cleanup() { for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done; }
trap cleanup EXIT

echo "== simulated cutters"
"$bin/lastcut-sim" grbl --link "$demo/cutter-1.tty" --record "$demo/cutter-records/cutter-1" --time-scale 0 \
  > "$demo/cutter-1.log" 2>&1 &
pids+=($!)
"$bin/lastcut-sim" hpgl --link "$demo/plotter-1.tty" --record "$demo/cutter-records/plotter-1" --time-scale 0 \
  > "$demo/plotter-1.log" 2>&1 &
pids+=($!)
for log in "$demo/cutter-1.log" "$demo/plotter-1.log"; do
  for _ in $(seq 100); do grep -q "ready:" "$log" && break; sleep 0.1; done
  grep -q "ready:" "$log" || { echo "demo: a simulated cutter did not start:"; cat "$log"; exit 1; }
done
echo "grbl table on $demo/cutter-1.tty, HPGL plotter on $demo/plotter-1.tty"

echo "== lastcutd"
"$bin/lastcutd" --check-config "$config"
"$bin/lastcutd" --config "$config" > "$demo/lastcutd.log" 2>&1 &
daemon=$!
pids+=($daemon)
for _ in $(seq 100); do grep -q "lastcutd ready" "$demo/lastcutd.log" && break; sleep 0.1; done
page="$(grep -o 'operator page on http://[^ ]*' "$demo/lastcutd.log" | head -1 | sed 's/operator page on //')"
[ -n "$page" ] && echo "the operator's page: $page"

echo "== dropping the sample lasts into $demo/incoming"
# The bundled sample lasts: the first goes to the default cutter (the grbl table) with a sidecar
# giving its order and both feet; the second names the HPGL plotter in its sidecar.
samples=(config/samples/sample-last-eu42-left.stl config/samples/sample-last-eu38-right.stl)
printf 'order = "4711"\ncustomer = "demo"\nsize = "EU 42"\nside = "pair"\n' \
  > "$demo/incoming/sample-last-eu42-left.job.toml"
printf 'order = "4712"\ncustomer = "demo"\nsize = "EU 38"\ncutter = "plotter-1"\n' \
  > "$demo/incoming/sample-last-eu38-right.job.toml"
count=0
for sample in "${samples[@]}"; do
  [ -f "$sample" ] || { echo "demo: the sample last $sample is missing"; exit 1; }
  name="$(basename "$sample")"
  cp "$sample" "$demo/incoming/.$name.part"
  mv "$demo/incoming/.$name.part" "$demo/incoming/$name"   # complete files appear at once
  echo "  $name"
  count=$((count + 1))
done

echo "== waiting for the jobs (lastcut status)"
for _ in $(seq 360); do
  if ! kill -0 "$daemon" 2>/dev/null; then echo "demo: lastcutd stopped:"; cat "$demo/lastcutd.log"; exit 1; fi
  finished=$(( $(ls "$demo/spool/done" 2>/dev/null | wc -l) + $(ls "$demo/spool/failed" 2>/dev/null | wc -l) + $(ls "$demo/spool/held" 2>/dev/null | wc -l) ))
  [ "$finished" -ge "$count" ] && [ -z "$(ls "$demo/spool/work" 2>/dev/null)" ] && break
  sleep 0.5
done
"$bin/lastcut" status --config "$config" || true

if [ -t 1 ] && [ -z "${LASTCUT_DEMO_DIR:-}" ]; then
  echo "== the jobs are cut; lastcutd and the page stay up: $page"
  echo "   drop more scans into $demo/incoming; Ctrl-C stops the daemon and shows the results"
  trap 'echo' INT
  wait "$daemon" || true
  trap - INT
fi
echo "== stopping lastcutd (SIGTERM)"
kill -TERM "$daemon"
wait "$daemon" || true
cleanup
wait 2>/dev/null || true

echo "== the operator's log ($demo/lastcutd.log)"
cat "$demo/lastcutd.log"
echo
echo "== results"
for job in "$demo"/spool/done/* "$demo"/spool/failed/* "$demo"/spool/held/*; do
  [ -d "$job" ] || continue
  echo "job $(basename "$job") ($(basename "$(dirname "$job")")):"
  ls "$job/molds"/*.dxf "$job/molds"/*.svg 2>/dev/null | sed 's/^/  mold:      /'
  for file in layout.json cut.nc cut.plt preview.svg report.json; do
    [ -f "$job/$file" ] && echo "  $(printf '%-10s' "${file%%.*}:") $job/$file"
  done
  # Why a job failed or is held; a done job has no reason.
  grep -h '"reason": "[^"]' "$job/state.json" | head -1 | sed -E 's/^ *"reason": (.*[^,]),?$/  reason:    \1/' || true
done
echo "what the simulated cutters received: $demo/cutter-records/"
failed=$(ls "$demo/spool/failed" 2>/dev/null | wc -l)
held=$(ls "$demo/spool/held" 2>/dev/null | wc -l)
done_count=$(ls "$demo/spool/done" 2>/dev/null | wc -l)
echo "demo: $done_count job(s) done, $failed failed, $held held"
[ "$done_count" -eq "$count" ]
