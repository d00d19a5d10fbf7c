#!/usr/bin/env python3
"""Times pdcheck with --jobs 1 and --jobs 2 on the given scenes (runs interleaved,
REPEAT of each) and prints a markdown table: median wall time, its spread, pairs/s,
the report's median stage times, peak resident memory, and the speedup of the medians.

usage: bench_jobs.py PDCHECK OUTDIR REPEAT SCENE.json...
"""
import json
import os
import statistics
import subprocess
import sys
import time


def run(pdcheck, scene, jobs, report):
    start = time.perf_counter()
    proc = subprocess.Popen([pdcheck, scene, "-q", "--jobs", str(jobs), "-o", report])
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 1):  # 1 = interference found, as the scenes hold some
        sys.exit(f"pdcheck {scene} --jobs {jobs} exited with {code}")
    with open(report) as f:
        r = json.load(f)
    return wall, usage.ru_maxrss / 1024, r["summary"]["candidate_pairs"], r["stage_seconds"]


def main():
    pdcheck, out, repeat, scenes = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    print(f"Median of {repeat} runs per row (runs interleaved); stages from the report.\n")
    print("| scene | jobs | wall s (median) | min–max | pairs | pairs/s | load s | parts s | solve s"
          " | peak RSS MB |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        runs = {1: [], 2: []}
        for _ in range(repeat):
            for jobs in (1, 2):
                runs[jobs].append(run(pdcheck, scene, jobs, os.path.join(out, f"{name}-j{jobs}.json")))
        median = {}
        for jobs in (1, 2):
            walls = [r[0] for r in runs[jobs]]
            median[jobs] = statistics.median(walls)
            pairs = runs[jobs][0][2]
            stage = {k: statistics.median(r[3][k] for r in runs[jobs]) for k in ("load", "parts", "solve")}
            rss = max(r[1] for r in runs[jobs])
            print(f"| {name} | {jobs} | {median[jobs]:.2f} | {min(walls):.2f}–{max(walls):.2f} | {pairs} "
                  f"| {pairs / median[jobs]:.0f} | {stage['load']:.2f} | {stage['parts']:.2f} "
                  f"| {stage['solve']:.2f} | {rss:.0f} |")
        print(f"| {name} | **speedup** | **{median[1] / median[2]:.2f}x** | | | | | | | |")


if __name__ == "__main__":
    main()
