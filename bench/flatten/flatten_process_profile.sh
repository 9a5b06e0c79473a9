#!/usr/bin/env bash
# The whole `lastcut flatten --no-segment` process on the ~100k-triangle halves of real foot
# geometry (FIND, MIT: the reference half subdivided + decimated, and the medial and lateral halves
# of the FIND foot template cut by lastcut's own segmentation), pinned to one core: wall seconds of
# the process (start to exit) and of each stage in report.json's "profile", min and median of RUNS.
# Usage: bench/flatten/flatten_process_profile.sh BUILD_DIR [RUNS]      (docs/benchmarks-flatten.md)
set -euo pipefail
build="$1"; runs="${2:-5}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$build/bin/bench_flatten" --arap-only --no-400k --only FIND --save "$work" >/dev/null
python3 - "$build/bin/lastcut" "$work" "$runs" <<'PY'
import json, os, statistics, subprocess, sys, time
lastcut, work, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
halves = sorted(f for f in os.listdir(work) if f.endswith(".off"))
print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}; {runs} runs per half, taskset -c 0\n")
for half in halves:
    walls, stages, refused = [], {}, None
    for run in range(runs):
        out = os.path.join(work, f"out-{half}-{run}")
        start = time.perf_counter()
        done = subprocess.run(["taskset", "-c", "0", lastcut, "flatten", os.path.join(work, half), "--no-segment",
                               "--unit", "mm", "-o", out], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        walls.append(time.perf_counter() - start)
        if done.returncode != 0:
            refused = done.stderr.strip()
            break
        report = json.load(open(os.path.join(out, "report.json")))
        for stage in report["profile"]:
            stages.setdefault(stage["stage"], []).append(stage["seconds"])
        segment = report["segments"][0]
    if refused:
        print(f"### {half[:-4]} triangles: REFUSED after {walls[-1]:.3f} s: {refused}\n")
        continue
    print(f"### {half[:-4]} triangles: {segment['iterations']} ARAP iterations, D_angle {segment['D_angle']:.4f}, "
          f"converged {segment['converged']}\n")
    print("| stage | min s | median s |\n|---|---|---|")
    for name, values in stages.items():
        print(f"| {name} | {min(values):.3f} | {statistics.median(values):.3f} |")
    print(f"| **whole process (wall, start to exit)** | **{min(walls):.3f}** | **{statistics.median(walls):.3f}** |\n")
PY
