#!/usr/bin/env bash
# One benchmark run on a tiny problem, as a CTest test (bench/CMakeLists.txt, label bench): passes when
# the program exits 0 and its output matches PATTERN (an extended regex, e.g. its table's last row).
# No figure is judged: the test only shows the benchmark still runs, so the figures in docs/ can
# be measured again.
# Usage: smoke_test.sh PATTERN COMMAND [ARGS...]
set -uo pipefail
pattern="$1"; shift
output="$("$@" 2>&1)"
status=$?
printf '%s\n' "$output"
if [ "$status" -ne 0 ]; then
  echo "smoke test: '$*' exited with $status" >&2
  exit 1
fi
if ! grep -qE -- "$pattern" <<<"$output"; then
  echo "smoke test: the output of '$*' has no line matching: $pattern" >&2
  exit 1
fi
