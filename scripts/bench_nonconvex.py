#!/usr/bin/env python3
"""Nonconvex benchmark (issue 17): cold, cached and hull-only runs of one assembly.

usage: bench_nonconvex.py [--pdcheck build/bin/pdcheck] [--out build/bench_nonconvex]
                          [--copies 8] [--segments 96] [--runs 3] [--jobs 2] [--tolerance auto]

Writes the assembly with scripts/make_nonconvex.py --bench (per copy 4 nonconvex parts of
1,440-2,112 triangles and a 76-triangle component, with bolts, a pin; 8 copies = 32 + 8
nonconvex parts), then per run, in this order: `--pieces hull --no-cache`, a cold run
(the default, pieces auto, with an empty cache) and a cached rerun (same cache). Prints the median wall
time of each, the ratios cold/hull and cached/hull, and for the auto runs the share of
nominal relations recovered and the hull artefacts reported as confirmed interferences.
`--tolerance VALUE` passes `--tolerance VALUE` to every run (`auto`: issue 27's measured bands).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run(pdcheck, scene, args):
    t0 = time.monotonic()
    p = subprocess.run([pdcheck, scene, "--quiet"] + args, capture_output=True, text=True)
    dt = time.monotonic() - t0
    if p.returncode not in (0, 1):
        sys.exit("pdcheck failed (%d): %s" % (p.returncode, p.stderr))
    return dt, json.loads(p.stdout)


def score(report, expected):
    pairs = {}
    for p in report["pairs"]:
        pairs[tuple(sorted((p["a"], p["b"])))] = p
    ok = artefacts = 0
    wrong = []
    for e in expected["pairs"]:
        p = pairs.get(tuple(sorted((e["a"], e["b"]))))
        st = p["status"] if p else "culled"
        want = e["expect"]
        good = (st == "interference" if want == "interference" else
                st in ("separated", "false_positive") if want == "contact" else st == "separated")
        ok += good
        if not good:
            wrong.append("%s:%s %s -> %s" % (e["a"], e["b"], want, st))
        if want != "interference" and st == "interference" and p.get("confirmed", True):
            artefacts += 1
    return ok, len(expected["pairs"]), artefacts, wrong


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pdcheck", default=os.path.join(HERE, "..", "build", "bin", "pdcheck"))
    ap.add_argument("--out", default=os.path.join(HERE, "..", "build", "bench_nonconvex"))
    ap.add_argument("--copies", type=int, default=8)
    ap.add_argument("--segments", type=int, default=96)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--tolerance", help="passed to every run as --tolerance (e.g. auto)")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    subprocess.run([sys.executable, os.path.join(HERE, "make_nonconvex.py"), a.out, "--bench",
                    "--copies", str(a.copies), "--segments", str(a.segments)], check=True)
    scene = os.path.join(a.out, "scene.json")
    expected = json.load(open(os.path.join(a.out, "expected.json")))
    nonconvex = [(k, v["triangles"]) for k, v in expected["parts"].items() if not v["convex"]]
    print("parts: %d (%d nonconvex, %d-%d triangles), nominal relations: %d" %
          (len(expected["parts"]), len(nonconvex), min(t for _, t in nonconvex),
           max(t for _, t in nonconvex), len(expected["pairs"])), file=sys.stderr)
    jobs = ["--jobs", str(a.jobs)] + (["--tolerance", a.tolerance] if a.tolerance else [])
    times = {"hull": [], "cold": [], "cached": []}
    reports = {}
    for r in range(a.runs):
        cache = os.path.join(a.out, "cache")
        shutil.rmtree(cache, ignore_errors=True)
        t, reports["hull"] = run(a.pdcheck, scene, ["--pieces", "hull", "--no-cache"] + jobs)
        times["hull"].append(t)
        t, reports["cold"] = run(a.pdcheck, scene, ["--cache", cache] + jobs)  # pieces auto
        times["cold"].append(t)
        t, reports["cached"] = run(a.pdcheck, scene, ["--cache", cache] + jobs)
        times["cached"].append(t)
        print("run %d: hull %.2f s, cold %.2f s, cached %.2f s" %
              (r + 1, times["hull"][-1], times["cold"][-1], times["cached"][-1]), file=sys.stderr)
    med = {k: statistics.median(v) for k, v in times.items()}
    print("median of %d runs (--jobs %d): hull %.2f s, cold %.2f s (%.2fx), cached %.2f s (%.2fx)"
          % (a.runs, a.jobs, med["hull"], med["cold"], med["cold"] / med["hull"], med["cached"],
             med["cached"] / med["hull"]))
    for name in ("hull", "cold", "cached"):
        stages = reports[name]["stage_seconds"]
        print("%s run stages: " % name + ", ".join("%s %.2f s" % kv for kv in stages.items()))
    for name in ("hull", "cold", "cached"):
        ok, n, art, wrong = score(reports[name], expected)
        print("%s: %d/%d nominal relations recovered (%.0f%%), %d hull artefacts reported as "
              "confirmed interferences" % (name, ok, n, 100.0 * ok / n, art))
        for w in wrong[:10]:
            print("  " + w)


if __name__ == "__main__":
    main()
