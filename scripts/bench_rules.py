#!/usr/bin/env python3
"""Times rules (issue 28) on the 10,000-part assembly of scripts/make_assembly.py.

usage: bench_rules.py PDCHECK OUTDIR [--parts 10000] [--repeat 5] [--jobs 2]

Writes OUTDIR/assembly.json (make_assembly.py) with each part given tags and a
group, and a rules file of 20 sets and 10 tests:

- full: the tests together cover every candidate pair (one self test over all
  parts among them), so the run solves exactly the pairs the run without rules
  solves: what the rules cost, nothing they save;
- scoped: the same sets, tests between some of them only: what scope saves.

Runs the scene without rules, with `--rules full` and `--rules scoped`,
interleaved, REPEAT times each, and prints a markdown table: median wall time,
min-max, pairs checked, out of scope, the report's median stage_seconds.rules
(resolving the rules and deciding every candidate pair) and the wall-time ratio
to the run without rules.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def labelled_scene(out, parts):
    scene = os.path.join(out, "assembly.json")
    subprocess.run([sys.executable, os.path.join(HERE, "make_assembly.py"), scene, "--parts",
                    str(parts)], check=True)
    with open(scene) as f:
        s = json.load(f)
    for q, p in enumerate(s["parts"]):
        p["tags"] = [f"t{q % 8}", "structure" if q % 3 else "system"]
        p["group"] = f"fuselage/bay-{q // 100:03d}/frame-{q // 10 % 10}"
    with open(scene, "w") as f:
        json.dump(s, f, separators=(",", ":"))
    return scene


def rules(scoped):
    sets = {"all": {"ids": ["*"]}}
    for k in range(8):
        sets[f"tag{k}"] = {"tags": [f"t{k}"]}
    for k in range(6):
        sets[f"bays{k}"] = {"groups": [f"fuselage/bay-0{k}*"]}
    for k in range(5):
        sets[f"ids{k}"] = {"ids": [f"p{k}*", f"p?{k}*"], "optional": True}
    tests = [] if scoped else [{"name": "all-self", "a": "all"}]
    for k in range(10 - len(tests)):
        t = {"name": f"t{k}", "a": f"tag{k % 8}", "b": f"bays{k % 6}" if k % 2 else f"tag{(k + 3) % 8}"}
        if k % 3 == 0:
            t["tolerance"] = "0.08 mm"
        tests.append(t)
    return {"sets": sets, "tests": tests,
            "ignore": [{"name": "id-pairs", "a": "ids0", "b": "ids1", "reason": "bench"}] if scoped else [],
            "expected": [{"name": "touching", "a": "tag0", "b": "tag1", "max_depth": "0.01 mm",
                          "reason": "bench"}]}


def run(pdcheck, scene, extra, report, jobs):
    start = time.perf_counter()
    code = subprocess.run([pdcheck, scene, "-q", "--no-cache", "--jobs", str(jobs), "-o", report] + extra).returncode
    wall = time.perf_counter() - start
    if code not in (0, 1):
        sys.exit(f"pdcheck {scene} {extra} exited with {code}")
    with open(report) as f:
        r = json.load(f)
    return wall, r["summary"], r["stage_seconds"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pdcheck")
    ap.add_argument("out")
    ap.add_argument("--parts", type=int, default=10000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    scene = labelled_scene(a.out, a.parts)
    configs = {"no rules": []}
    for name in ("full", "scoped"):
        path = os.path.join(a.out, f"rules-{name}.json")
        with open(path, "w") as f:
            json.dump(rules(name == "scoped"), f, indent=1)
        configs[f"rules {name}"] = ["--rules", path]
    runs = {k: [] for k in configs}
    for _ in range(a.repeat):
        for name, extra in configs.items():
            runs[name].append(run(a.pdcheck, scene, extra, os.path.join(a.out, "report.json"), a.jobs))
    base = statistics.median(r[0] for r in runs["no rules"])
    print(f"{a.parts} parts, --jobs {a.jobs}, median of {a.repeat} runs per row (interleaved).\n")
    print("| run | wall s (median) | min–max | pairs checked | out of scope | rules s (median) | vs no rules |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, rs in runs.items():
        walls = [r[0] for r in rs]
        med = statistics.median(walls)
        summ = rs[0][1]
        rules_s = statistics.median(r[2].get("rules", 0.0) for r in rs)
        print(f"| {name} | {med:.2f} | {min(walls):.2f}–{max(walls):.2f} | {summ['candidate_pairs']} "
              f"| {summ.get('out_of_scope', '-')} | {rules_s:.3f} | {med / base:.3f} |")


if __name__ == "__main__":
    main()
