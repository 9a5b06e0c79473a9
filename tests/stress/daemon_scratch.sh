# Sourced by tests/stress/crash_test.sh and bench/daemon/load_bench.sh: the scratch installation
# both run lastcutd in (one calf material, one simulated HPGL pen plotter "cutter-1" on a
# pseudo-terminal, inotify watch folder), so the two scripts test the same set-up.

# write_daemon_config FILE SOURCE_DIR WATCH_KEYS JOBS_KEYS BATCH_KEYS CUTTER_KEYS
# Writes lastcut.toml; each *_KEYS argument holds the script's own lines for that table.
write_daemon_config() {
  local file="$1" source_dir="$2" watch_keys="$3" jobs_keys="$4" batch_keys="$5" cutter_keys="$6"
  cat > "$file" <<TOML
[paths]
watch = "incoming"
spool = "spool"
machines = "$source_dir/config/machines"
[watch]
mode = "inotify"
stable_checks = 1
$watch_keys
[jobs]
duplicate_policy = "process"
default_material = "calf"
default_cutter = "cutter-1"
$jobs_keys
[batch]
$batch_keys
[materials.calf]
width_mm = 800
length_mm = 1200
[cutters.cutter-1]
protocol = "hpgl"
port = "cutter-1.tty"
flow = "xonxoff"
machine = "hpgl-pen-plotter"
$cutter_keys
TOML
}

# generate_left_lasts BIN_DIR OUT_DIR TRIANGLES SIZE... -> OUT_DIR/last-SIZE.stl (seed = size)
generate_left_lasts() {
  local bin="$1" out="$2" triangles="$3"
  shift 3
  for size in "$@"; do
    "$bin/lastcut" generate -o "$out/last-$size.stl" --size "$size" --side left --triangles "$triangles" \
      --seed "$size" >/dev/null
  done
}

# wait_for_line FILE PATTERN: up to 10 s for a program's log to show PATTERN.
wait_for_line() {
  for _ in $(seq 100); do grep -qs "$2" "$1" && return 0; sleep 0.1; done
  return 1
}
