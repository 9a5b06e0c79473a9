#!/usr/bin/env bash
# Builds the real grbl 1.1h firmware's host simulator from ../shared/peers/grbl (its sources, GPL-3.0,
# never linked into or shipped with lastcut) into OUT/grbl_sim.exe, with three test-harness fixes
# to the simulator (none to the firmware's parser, planner or protocol). Each is checked after it is
# applied, so a changed source tarball fails loudly instead of building an unpatched simulator.
#
# 1. Serial input with read(2) instead of stdio's getchar (the peer's own build does the same):
#    with getchar every reply lags one line behind.
# 2. Interrupts closer to the AVR's rules (the details at the patch below). grbl-sim runs the
#    firmware's main loop and its simulated interrupts on two threads at once; where the AVR
#    would have paused the main loop for an interrupt, the two interleaved and the firmware
#    stopped in Run at a frozen MPos for ever (its stepper interrupt off), now and then.
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

# 1. read(2) for serial input.
sed -i 's/\t char_in = getchar();/\t { unsigned char c; char_in = (read(0, \&c, 1) == 1) ? c : EOF; }/' "$sim/platform_LINUX.c"
require "$sim/platform_LINUX.c" 'read(0, &c, 1)' "serial input"

# 2. Interrupts closer to the AVR. grbl-sim runs the firmware's main loop and its simulated
#    interrupts on two threads at once; on the AVR an interrupt runs between two main-loop
#    instructions and the main loop waits for it. This stopped the firmware here, in Run at
#    one position for ever with a feed hold never completing (docs/grbl-firmware.md):
#    a. Both threads read-modify-write the one emulated status register: an interrupt
#       restoring a stale SREG cleared the interrupt-enable bit for good (gdb on a stalled
#       simulator: io.sreg == 0, TIFR1 pending, master clock running). The interrupt thread
#       gets its own SREG (the AVR saves it around an interrupt), and every emulated register
#       update is an atomic read-modify-write (st_wake_up sets TIMSK1 while an interrupt may
#       change it).
#    What is left: an interrupt can still run in the middle of a main-loop statement, which the
#    AVR never allows. A stall in Run is rarer now but still seen (about one in three runs of a
#    1,400-line drag-knife file whose pen moves are M8/M9 buffer syncs); a lock between the
#    timer interrupts and the main loop's stepper calls made it garble serial output instead.
#    (The sources have CRLF line ends, hence \r\?.)
sed -i 's/^#define SREG io\.sreg\r\?$/volatile uint8_t* sim_sreg(void);\n#define SREG (*sim_sreg())/' "$sim/avr/io.h"
require "$sim/avr/io.h" 'define SREG (\*sim_sreg())' "SREG"
sed -i '/^typedef struct io_sim {/,/^} io_sim_t;/ s/^\( *\)uint\(8\|16\)_t /\1_Atomic uint\2_t /' "$sim/avr/io.h"
require "$sim/avr/io.h" '_Atomic uint8_t timsk' "atomic registers"
sed -i 's/^void sei() {io\.sreg|=SEI;}/void sei() {SREG|=SEI;}/; s/^void cli() {io\.sreg&=~SEI;}/void cli() {SREG\&=~SEI;}/' "$sim/avr/interrupt.c"
require "$sim/avr/interrupt.c" 'void sei() {SREG|=SEI;}' "sei"
require "$sim/avr/interrupt.c" 'void cli() {SREG&=~SEI;}' "cli"
cat >>"$sim/avr/interrupt.c" <<'EOF'

/* lastcut test harness (build_grbl_sim.sh, fix 2): the interrupt thread's own SREG. */
__thread int sim_in_hardware_thread;
volatile uint8_t* sim_sreg(void) {
  static __thread uint8_t interrupt_context_sreg = 0;
  return sim_in_hardware_thread ? &interrupt_context_sreg : (volatile uint8_t*)&io.sreg;
}
EOF
sed -i 's/^void sim_loop(){\r\?$/extern __thread int sim_in_hardware_thread;\nvoid sim_loop(){ sim_in_hardware_thread = 1;/' "$sim/simulator.c"
require "$sim/simulator.c" 'sim_in_hardware_thread = 1' "the hardware thread"

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
