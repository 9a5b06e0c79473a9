#!/usr/bin/env bash
# Runs the real grbl 1.1h firmware (its host simulator, built by build_grbl_sim.sh) behind a
# pseudo-terminal, the way a USB-serial grbl board appears to lastcut: DIR/tty is the port,
# DIR/blocks.txt the firmware's log of every planner block (one line each), DIR/EEPROM.DAT its
# settings. Prints "ready: DIR/tty" once the port exists (what the tests' SimProcess waits for)
# and stops the firmware and the pty on SIGTERM, exiting 0.
# Usage: run_grbl_firmware.sh GRBL_SIM_EXE DIR
set -euo pipefail
grbl_sim="$1"; dir="$2"
mkdir -p "$dir"
cd "$dir"
rm -f tty
# grbl-sim -n: no step log; -s /dev/null: no per-tick output; -b: the block log.
socat PTY,raw,echo=0,link="$dir/tty" EXEC:"$grbl_sim -n -s /dev/null -b $dir/blocks.txt",pty,raw,echo=0 &
socat_pid=$!
stop() { kill "$socat_pid" 2>/dev/null; wait "$socat_pid" 2>/dev/null; exit 0; }
trap stop TERM INT
for _ in $(seq 200); do
  [ -e "$dir/tty" ] && break
  kill -0 "$socat_pid" 2>/dev/null || { echo "failed: socat or the firmware did not start"; exit 1; }
  sleep 0.05
done
[ -e "$dir/tty" ] || { echo "failed: no pty at $dir/tty after 10 s"; exit 1; }
echo "ready: $dir/tty"
wait "$socat_pid"
