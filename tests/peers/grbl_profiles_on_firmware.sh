#!/usr/bin/env bash
# Every shipped grbl machine profile's cut file, run to the end on the real grbl 1.1h firmware
# (its host simulator, built by tests/peers/build_grbl_sim.sh). For each config/machines profile
# with format "gcode": a generated last is flattened, its molds nested as a pair, the layout turned
# into that profile's cut file, and `lastcut send` streams it to the firmware over a pty. Passes when
# every line is acknowledged, the machine ends Idle at the file's last target, and the firmware
# executed at least one planner block per motion line (arcs add more). A profile with a rotary
# axis (rotary_axis = "A": a grblHAL table) cannot run on grbl 1.1h, which has X, Y and Z only: it
# must be refused before the first line, with the firmware not having moved at all.
# Usage: grbl_profiles_on_firmware.sh BUILD_DIR GRBL_SIM_EXE SOURCE_DIR
set -euo pipefail
build="$1"; grbl_sim="$2"; source="$3"
bin="$build/bin"
work="$(mktemp -d)"
cleanup() { [ -n "${socat_pid:-}" ] && kill "$socat_pid" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

"$bin/lastcut" generate --size 36 --triangles 20000 --seed 7 -o "$work/last.stl" >/dev/null
"$bin/lastcut" flatten "$work/last.stl" -o "$work/molds" >/dev/null
"$bin/lastcut" nest "$work/molds" --time-limit 1 --seed 1 --threads 1 --roll-width 500 -o "$work/layout.json" >/dev/null

failures=0
for profile in "$source"/config/machines/*.toml; do
  grep -q '^format *= *"gcode"' "$profile" || continue
  name="$(basename "$profile" .toml)"
  run="$work/$name"; mkdir -p "$run"
  "$bin/lastcut" toolpath "$work/layout.json" -p "$profile" -o "$run/cut.nc" >/dev/null
  motion_lines="$(grep -c '^G[0-3]\b' "$run/cut.nc")"
  # The firmware keeps its settings in ./EEPROM.DAT: one fresh folder per run.
  (cd "$run" && exec socat PTY,raw,echo=0,link="$run/tty" \
     EXEC:"$grbl_sim -n -t ${GRBL_TIME_FACTOR:-1} -s /dev/null -b $run/blocks.txt",pty,raw,echo=0) &
  socat_pid=$!
  for _ in $(seq 100); do [ -e "$run/tty" ] && break; sleep 0.1; done
  start=$(date +%s)
  set +e
  "$bin/lastcut" send "$run/cut.nc" --protocol grbl --port "$run/tty" --timeout 30 --stall-timeout 60 \
    --grbl-setting '$110=60000,$111=60000,$112=60000,$120=500000,$121=500000,$122=500000' >"$run/send.log" 2>&1
  status=$?
  set -e
  # Where the machine stands now, against the file's last X/Y/Z.
  position="$(python3 - "$run/tty" <<'PY'
import os, select, sys, time, tty
fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY); tty.setraw(fd)
os.write(fd, b"?"); out = b""; end = time.time() + 3
while time.time() < end and b">" not in out:
    if select.select([fd], [], [], 0.1)[0]: out += os.read(fd, 256)
os.write(fd, b"\x06")  # grbl-sim: shut down cleanly
print(out.decode(errors="replace").strip())
PY
)"
  wait "$socat_pid" 2>/dev/null || true
  socat_pid=""
  expected="$(python3 - "$run/cut.nc" <<'PY'
import re, sys
pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
for line in open(sys.argv[1]):
    if re.match(r"G[0-3]\b", line):
        for axis, value in re.findall(r"([XYZ])(-?[\d.]+)", line): pos[axis] = float(value)
print("MPos:%.3f,%.3f,%.3f" % (pos["X"], pos["Y"], pos["Z"]))
PY
)"
  blocks="$(wc -l < "$run/blocks.txt")"
  verdict=PASS
  if grep -q '^rotary_axis *= *"[A-Z]"' "$profile"; then
    [ "$status" -eq 1 ] || verdict=FAIL
    grep -q "moves the A axis, but the controller has 3 axes (X Y Z); nothing was sent" "$run/send.log" || verdict=FAIL
    [ "$blocks" -eq 0 ] || verdict=FAIL
  else
    [ "$status" -eq 0 ] || verdict=FAIL
    [[ "$position" == "<Idle|$expected|"* ]] || verdict=FAIL
    [ "$blocks" -ge "$motion_lines" ] || verdict=FAIL
  fi
  echo "$verdict $name: send exit $status in $(( $(date +%s) - start )) s, $motion_lines motion lines, $blocks firmware blocks, end $position (expected $expected)"
  if [ "$verdict" = FAIL ]; then failures=$((failures + 1)); tail -5 "$run/send.log"; fi
done
exit "$failures"
