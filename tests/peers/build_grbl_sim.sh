#!/usr/bin/env bash
# Builds the real grbl 1.1h firmware's host simulator from ../shared/peers/grbl (its sources, GPL-3.0,
# never linked into or shipped with lastcut) into OUT/grbl_sim.exe, with three test-harness fixes
# to the simulator (none to the firmware's parser, planner or protocol). Each is checked after it is
# applied, so a changed source tarball fails loudly instead of building an unpatched simulator.
#
# 1. Serial input with read(2), without a terminal-mode system call per simulated byte.
# 2. One thread (the details at the patch below). grbl-sim ran the firmware's main loop and its
#    simulated interrupts on two threads at once; where the AVR would have paused the main loop
#    for an interrupt, the two interleaved and the firmware stopped in Run at a frozen MPos for
#    ever (its stepper interrupt off), now and then. Here the hardware runs on the firmware's
#    thread, at the points where the firmware polls or waits.
# 3. The block log (-b) records every block the planner commits, at the moment it commits it. The
#    simulator printed only the newest planner block once per simulated serial byte, so blocks added
#    between two byte ticks (an arc's segments, or a main loop catching up under CPU load) never
#    reached the log: the log under-counted while the firmware executed every block.
# Usage: build_grbl_sim.sh PEER_DIR OUT_DIR      (needs gcc and make)
set -euo pipefail
peer="$(cd "$1" && pwd)"
out="$(mkdir -p "$2" && cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tar xzf "$peer/grbl-1.1h-with-sim.tar.gz" -C "$work"
grbl="$work/grbl/grbl"
sim="$grbl/sim"

require() { # require FILE PATTERN WHAT: fail when a patch did not take
  grep -q -- "$2" "$1" || { echo "build_grbl_sim: could not patch $3 in $(basename "$1")" >&2; exit 1; }
}

# 1. Serial input with read(2) instead of stdio's getchar (with getchar every reply lags one line
#    behind), and without the terminal-mode system calls grbl-sim made for every simulated byte
#    time (tcgetattr, tcsetattr twice, select: about a million calls per simulated second, which
#    kept the simulator far behind the wall clock once it ran on one thread, fix 2). The input
#    is read in chunks into a small buffer and handed to the serial interrupt one byte per byte
#    time, as before; an empty line is looked at every 16th byte time. End of input (or ^F)
#    still asks the simulator to exit.
perl -0pi -e 's|uint8_t platform_poll_stdin\(\) \{.*?\n\}|uint8_t platform_poll_stdin() {\n  /* lastcut test harness (build_grbl_sim.sh, fix 1) */\n  static unsigned char pending[256];\n  static int pending_len = 0, pending_pos = 0, idle_byte_times = 0;\n  if (pending_pos < pending_len) return pending[pending_pos++];\n  if (++idle_byte_times < 16) return 0;\n  idle_byte_times = 0;\n  struct pollfd input = {0, POLLIN, 0};\n  if (poll(&input, 1, 0) <= 0) return 0;\n  ssize_t got = read(0, pending, sizeof pending);\n  if (got <= 0) return 0xFF; /* end of input: as getchar\x27s EOF, an exit request */\n  pending_len = (int)got;\n  pending_pos = 0;\n  return pending[pending_pos++];\n}|s; s|(#include <unistd.h>\r?\n)|${1}#include <poll.h>\n|' "$sim/platform_LINUX.c"
require "$sim/platform_LINUX.c" 'fix 1' "serial input"
require "$sim/platform_LINUX.c" '#include <poll.h>' "serial input's poll"

# 2. One thread, as on the AVR. grbl-sim ran the firmware's main loop and its simulated hardware
#    (timers, stepper interrupt, serial) on two threads at once, so an "interrupt" could run in the
#    middle of any main-loop statement and both threads read-modify-wrote the one emulated status
#    register: now and then the stepper interrupt was left disabled for good and the firmware
#    stood in Run at one MPos for ever (docs/grbl-firmware.md). Here the firmware runs on the
#    process's only thread, and the simulated hardware catches up with the wall clock at the
#    points where the firmware itself waits or polls (the AVR runs interrupts at any instruction
#    boundary; grbl is written so that these are the points where that matters):
#      - grbl's realtime check (protocol_exec_rt_system: every wait loop of the planner, a buffer
#        sync, a feed hold, a dwell and the idle main loop go through it);
#      - reading serial input (the main loop, when it asks for the next byte);
#      - a full serial transmit buffer (serial_write waits for the transmit interrupt);
#      - _delay_ms/_delay_us (busy waits that let interrupts run, as on the AVR);
#      - the hard-limit alarm loop (waits for a reset from the serial interrupt).
#    An interrupt runs with the main loop's status register saved and restored around it (the
#    AVR does that in hardware), so an interrupt's sei()/cli() cannot leak into the main loop.
#    (The simulator's sources have CRLF line ends, grbl's have LF; the patterns take both.)
perl -0pi -e 's{plat_thread_t\*th = platform_start_thread\(avr_main_thread\);.*?sim_loop\(\);}{avr_main(); /* lastcut test harness: one thread; sim_poll() ends the process */}s; s{platform_kill_thread\(th\);[^\r\n]*}{}' "$sim/main.c"
require "$sim/main.c" 'avr_main(); /\* lastcut test harness' "the main thread"
cat >>"$sim/main.c" <<'END_OF_C'

/* lastcut test harness (build_grbl_sim.sh, fix 2): the clean exit, called by sim_poll(). */
void sim_finish(void) {
  shutdown_simulator();
  fclose(args.block_out_file);
  fclose(args.step_out_file);
  fclose(args.serial_out_file);
  platform_terminate();
  exit(EXIT_SUCCESS);
}
END_OF_C
cat >>"$sim/simulator.c" <<'END_OF_C'

/* lastcut test harness (build_grbl_sim.sh, fix 2): runs the simulated hardware up to the wall
   clock, on the firmware's own thread, at the points where the firmware polls or waits.
   Returns 0 when called from inside the hardware simulation (an interrupt), 1 otherwise. */
void sim_finish(void);
int sim_poll(void) {
  static int inside = 0;
  static int started = 0;
  static uint32_t ns_prev = 0;
  static double simulated_ns = 0.0;
  static uint64_t next_byte_tick = F_CPU; /* wait 1 s before reading serial input, as sim_loop did */
  if (inside) return 0;
  inside = 1;
  uint32_t ns_now = platform_ns();
  if (!started) { ns_prev = ns_now; started = 1; }
  uint64_t simulated_ticks;
  if (sim.speedup) {
    simulated_ns += (double)(uint32_t)(ns_now - ns_prev) * sim.speedup;
    simulated_ticks = (uint64_t)(simulated_ns * (F_CPU / 1e9));
  } else {
    simulated_ticks = sim.masterclock + 1; /* as fast as possible */
  }
  ns_prev = ns_now;
  /* A host too busy to keep up (other processes on every core) would fall further behind with
     every poll, and the firmware would get a turn only between ever longer catch-ups. More than
     20 ms behind, the simulated clock lets the rest go (the machine runs in slow motion, as a
     busy host's timing would anyway), and one poll runs at most 1 ms of hardware. */
  const uint64_t max_lag_ticks = F_CPU / 50, max_ticks_per_poll = F_CPU / 1000;
  if (simulated_ticks > sim.masterclock + max_lag_ticks) {
    simulated_ticks = sim.masterclock + max_lag_ticks;
    simulated_ns = (double)simulated_ticks / (F_CPU / 1e9);
  }
  if (simulated_ticks > sim.masterclock + max_ticks_per_poll) simulated_ticks = sim.masterclock + max_ticks_per_poll;
  while (sim.masterclock < simulated_ticks) {
    bool read_serial = (sim.masterclock >= next_byte_tick);
    uint8_t main_loop_sreg = io.sreg; /* the AVR saves SREG around an interrupt */
    simulate_hardware(read_serial);
    io.sreg = main_loop_sreg;
    sim_hook[sh_TICK]();
    if (read_serial) {
      sim.baud_ticks = 2*((UBRR0H<<8)+UBRR0L)+1;
      if (UCSR0A & (1<<U2X0)) { sim.baud_ticks*=2; }
      next_byte_tick += sim.baud_ticks;
      sim_hook[sh_BYTE]();
    }
  }
  inside = 0;
  if (sim.exit == exit_OK) sim_finish();
  return 1;
}
END_OF_C
require "$sim/simulator.c" 'int sim_poll(void)' "the hardware poll"
poll='{ int sim_poll(void); sim_poll(); }'
perl -pi -e 's|^(\s*)platform_sleep\(0\);|${1}{ int sim_poll(void); sim_poll(); }|' "$sim/serial.c"
require "$sim/serial.c" "$poll" "serial_read's poll"
perl -0pi -e 's|(void protocol_exec_rt_system\(\)\r?\n\{\r?\n)|${1}  { int sim_poll(void); sim_poll(); }\n|; s|(\n)(\s*\} while \(bit_isfalse\(sys_rt_exec_state,EXEC_RESET\)\);)|${1}      { int sim_poll(void); sim_poll(); }\n${2}|' "$grbl/protocol.c"
[ "$(grep -cF "$poll" "$grbl/protocol.c")" = 2 ] || { echo "build_grbl_sim: could not patch the realtime checks in protocol.c" >&2; exit 1; }
perl -0pi -e 's|(while \(next_head == serial_tx_buffer_tail\) \{\r?\n)|${1}    { int sim_poll(void); sim_poll(); }\n|' "$grbl/serial.c"
require "$grbl/serial.c" "$poll" "serial_write's wait"
perl -0pi -e 's|void _delay_ms\(int i\) \{.*?\}|void _delay_ms(int i) { sim_busy_wait_ticks((uint64_t)i * (F_CPU / 1000)); }|s; s|void _delay_us\(int i\) \{.*?\}|void _delay_us(int i) { sim_busy_wait_ticks((uint64_t)i * (F_CPU / 1000000)); }|s; s|(#include "\.\./simulator\.h"\r?\n)|${1}#include <stdint.h>\nint sim_poll(void);\n/* lastcut test harness (fix 2): a busy wait that lets the simulated interrupts run, as on the AVR. */\nstatic void sim_busy_wait_ticks(uint64_t ticks) {\n  uint64_t end = sim.masterclock + ticks;\n  while (sim.masterclock < end) { if (!sim_poll()) return; }\n}\n|' "$sim/util/delay.c"
[ "$(grep -c 'sim_busy_wait_ticks' "$sim/util/delay.c")" = 3 ] || { echo "build_grbl_sim: could not patch util/delay.c" >&2; exit 1; }

# 3. Log each block as the planner commits it.
sed -i 's/^    block_buffer_head = next_buffer_head;$/    { void sim_log_committed_block(plan_block_t *b); sim_log_committed_block(block); }\n    block_buffer_head = next_buffer_head;/' "$grbl/planner.c"
require "$grbl/planner.c" 'sim_log_committed_block(block)' "the planner commit"
sed -i 's/^  printBlock();\r\?$/  \/* blocks are logged by sim_log_committed_block *\//' "$sim/grbl_interface.c"
require "$sim/grbl_interface.c" 'blocks are logged by sim_log_committed_block' "the per-byte block print"
cat >>"$sim/grbl_interface.c" <<'EOF'

/* lastcut test harness: one log line per block the planner commits (end position in steps, entry speed). */
void sim_log_committed_block(plan_block_t *b) {
  int i;
  for (i = 0; i < N_AXIS; i++) {
    if (b->direction_bits & get_direction_pin_mask(i)) block_position[i] -= b->steps[i];
    else block_position[i] += b->steps[i];
    fprintf(args.block_out_file, "%d, ", block_position[i]);
  }
  fprintf(args.block_out_file, "%f\n", b->entry_speed_sqr);
  fflush(args.block_out_file);
}
EOF

cd "$sim"
make clean >/dev/null
make main FLAGS="-g -fcommon" >"$work/make.log" 2>&1 || { tail -20 "$work/make.log"; exit 1; }
cp grbl_sim.exe "$out/.grbl_sim.exe.new" && mv -f "$out/.grbl_sim.exe.new" "$out/grbl_sim.exe"  # a running copy keeps its file
echo "built $out/grbl_sim.exe"
