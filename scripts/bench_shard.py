#!/usr/bin/env python3
"""Measures sharding and --reuse (issue 14; numbers in docs/scale-out.md and docs/performance.md).

usage: bench_shard.py PDCHECK OUTDIR [--parts 10000] [--shards 4] [--repeat 3] [--jobs 1]
                      [--million PARTS] [--million-shards 100]

1. The assembly of scripts/make_assembly.py: one unsharded run and N shards run one after
   another (runs interleaved, REPEAT of each), total CPU time (user + system of pdcheck and
   its workers, from wait4) and wall time; the merged report is checked against the
   unsharded one (timings aside); per shard the vertices it loaded and its pairs.
2. --reuse after moving 1 % of the parts (every 100th part 1 mm up): the solve stage of the
   rerun against a full run of the moved scene, and the two reports compared.
3. --million P: a P-part assembly (small prisms) and one shard of it under /usr/bin/time -v:
   peak resident memory and the stage times.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run(cmd, ok=(0, 1, 3)):
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read()
    wall = time.perf_counter() - start
    code = os.waitstatus_to_exitcode(status)
    if code not in ok:
        sys.exit(f"{' '.join(cmd)} exited with {code}: {err}")
    return {"wall": wall, "cpu": usage.ru_utime + usage.ru_stime, "rss": usage.ru_maxrss / 1024,
            "code": code, "err": err}


def timeless(doc):
    doc = dict(doc)
    doc.pop("seconds", None)
    doc.pop("stage_seconds", None)
    doc["pairs"] = [{k: v for k, v in p.items() if k not in ("time_ms", "reused")}
                    for p in doc["pairs"]]
    return doc


def load(path):
    with open(path) as f:
        return json.load(f)


def assembly(out, parts, extra=()):
    if not os.path.exists(out):
        subprocess.run([sys.executable, os.path.join(HERE, "make_assembly.py"), out, "--parts",
                        str(parts), *extra], check=True, stderr=subprocess.DEVNULL)
    return out


def sharding(a, pdcheck, out, scene):
    jobs = str(a.jobs)
    full_runs, shard_runs, merge_runs = [], [], []
    for _ in range(a.repeat):
        full = os.path.join(out, "full.json")
        full_runs.append(run([pdcheck, scene, "-q", "--jobs", jobs, "-o", full]))
        runs, paths = [], []
        for k in range(1, a.shards + 1):
            p = os.path.join(out, f"shard{k}.json")
            runs.append(run([pdcheck, scene, "-q", "--jobs", jobs, "--shard", f"{k}/{a.shards}",
                             "-o", p]))
            paths.append(p)
        shard_runs.append(runs)
        merged = os.path.join(out, "merged.json")
        merge_runs.append(run([pdcheck, "merge", *paths, "-q", "-o", merged]))
        if timeless(load(merged)) != timeless(load(full)):
            sys.exit("the merged report differs from the unsharded one")
    cpu_full = statistics.median(r["cpu"] for r in full_runs)
    cpu_shards = statistics.median(sum(r["cpu"] for r in runs) for runs in shard_runs)
    cpu_merge = statistics.median(r["cpu"] for r in merge_runs)
    wall_full = statistics.median(r["wall"] for r in full_runs)
    wall_shards = statistics.median(sum(r["wall"] for r in runs) for runs in shard_runs)
    f = load(os.path.join(out, "full.json"))
    print(f"## Sharding: {a.parts}-part assembly, {a.shards} shards one after another, --jobs {jobs}, "
          f"median of {a.repeat} (runs interleaved)\n")
    print(f"{f['summary']['candidate_pairs']} candidate pairs; merged report equal to the unsharded "
          "one (timings aside) in every repeat.\n")
    print("| | CPU s | wall s | peak RSS MB |")
    print("|---|---:|---:|---:|")
    print(f"| unsharded | {cpu_full:.2f} | {wall_full:.2f} | {max(r['rss'] for r in full_runs):.0f} |")
    print(f"| {a.shards} shards, sum | {cpu_shards:.2f} | {wall_shards:.2f} | "
          f"{max(r['rss'] for runs in shard_runs for r in runs):.0f} (largest shard) |")
    print(f"| merge | {cpu_merge:.2f} | {statistics.median(r['wall'] for r in merge_runs):.2f} | "
          f"{max(r['rss'] for r in merge_runs):.0f} |")
    print(f"| **shards / unsharded** | **{cpu_shards / cpu_full:.3f}x** "
          f"(with merge {(cpu_shards + cpu_merge) / cpu_full:.3f}x) | {wall_shards / wall_full:.3f}x | |\n")
    st = f["stage_seconds"]
    print("Unsharded stages (s, last repeat): " +
          ", ".join(f"{k} {v:.2f}" for k, v in st.items()) + "\n")
    print("| shard | vertices loaded | share of all vertices | parts loaded | pairs planned | pairs "
          "checked | CPU s (median) | stages (s, last repeat) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---|")
    for k in range(a.shards):
        d = load(os.path.join(out, f"shard{k + 1}.json"))
        m = d["shard"]
        cpu = statistics.median(runs[k]["cpu"] for runs in shard_runs)
        stages = ", ".join(f"{n} {v:.2f}" for n, v in d["stage_seconds"].items())
        print(f"| {k + 1} | {m['vertices_loaded']} | {m['vertices_loaded'] / m['vertices_total']:.3f} "
              f"(goal ≤ {1 / a.shards + 0.1:.3f}) | {len(m['part_index'])} | {m['pairs_planned']} | "
              f"{m['pairs_checked']} | {cpu:.2f} | {stages} |")
    print()


def move_one_percent(scene, moved):
    doc = load(scene)
    for k, p in enumerate(doc["parts"]):
        if k % 100 == 50:
            p["vertices"] = [[x, y, z + 1.0] for x, y, z in p["vertices"]]
    with open(moved, "w") as f:
        json.dump(doc, f)
    return sum(1 for k in range(len(doc["parts"])) if k % 100 == 50)


def reuse(a, pdcheck, out, scene):
    jobs = str(a.jobs)
    old = os.path.join(out, "reuse-old.json")
    run([pdcheck, scene, "-q", "--jobs", jobs, "-o", old])
    moved = os.path.join(out, "moved.json")
    n = move_one_percent(scene, moved)
    fulls, reruns = [], []
    for _ in range(a.repeat):
        full = os.path.join(out, "moved-full.json")
        rerun = os.path.join(out, "moved-reuse.json")
        r1 = run([pdcheck, moved, "-q", "--jobs", jobs, "-o", full])
        r2 = run([pdcheck, moved, "-q", "--jobs", jobs, "--reuse", old, "-o", rerun])
        fulls.append((r1, load(full)["stage_seconds"]))
        reruns.append((r2, load(rerun)["stage_seconds"]))
        if timeless(load(full)) != timeless(load(rerun)):
            sys.exit("the --reuse report differs from the full run's")
    d = load(os.path.join(out, "moved-reuse.json"))
    reused = sum(1 for p in d["pairs"] if p.get("reused"))
    solve_full = statistics.median(s["solve"] for _, s in fulls)
    solve_re = statistics.median(s["solve"] for _, s in reruns)
    print(f"## --reuse after moving {n} of {a.parts} parts 1 mm, --jobs {jobs}, median of {a.repeat}\n")
    print(f"{reused} of {len(d['pairs'])} pairs reused, {len(d['pairs']) - reused} solved; report "
          "equal to a full run's (timings and `reused` aside) in every repeat.\n")
    print("| | solve s | wall s | CPU s |")
    print("|---|---:|---:|---:|")
    print(f"| full run | {solve_full:.3f} | {statistics.median(r['wall'] for r, _ in fulls):.2f} | "
          f"{statistics.median(r['cpu'] for r, _ in fulls):.2f} |")
    print(f"| --reuse | {solve_re:.3f} | {statistics.median(r['wall'] for r, _ in reruns):.2f} | "
          f"{statistics.median(r['cpu'] for r, _ in reruns):.2f} |")
    print(f"| **ratio** | **{solve_re / solve_full:.3f}** (goal ≤ 0.05) | | |\n")


def million(a, pdcheck, out):
    scene = assembly(os.path.join(out, f"a{a.million}.json"), a.million, ("--vertices", "8:16"))
    size = os.path.getsize(scene) / 1e6
    report = os.path.join(out, "million-shard.json")
    cmd = ["/usr/bin/time", "-v", pdcheck, scene, "-q", "--jobs", str(a.jobs), "--shard",
           f"1/{a.million_shards}", "-o", report]
    r = run(cmd)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", r["err"])
    d = load(report)
    m = d["shard"]
    print(f"## One shard of a {a.million}-part assembly ({size:.0f} MB scene, prisms of 8-16 "
          f"vertices), shard 1/{a.million_shards}, --jobs {a.jobs}\n")
    print("| | |")
    print("|---|---|")
    print(f"| peak resident memory (/usr/bin/time -v) | {int(rss.group(1)) / 1024:.0f} MB |")
    print(f"| wall / CPU | {r['wall']:.1f} s / {r['cpu']:.1f} s |")
    print("| stages (s) | " + ", ".join(f"{k} {v:.2f}" for k, v in d["stage_seconds"].items()) + " |")
    print(f"| parts loaded | {len(m['part_index'])} of {m['parts_total']} "
          f"({m['vertices_loaded'] / m['vertices_total']:.4f} of the vertices) |")
    print(f"| pairs planned / checked | {m['pairs_planned']} / {m['pairs_checked']} |\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pdcheck")
    ap.add_argument("out")
    ap.add_argument("--parts", type=int, default=10000)
    ap.add_argument("--shards", type=int, default=4)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--million", type=int, default=0)
    ap.add_argument("--million-shards", type=int, default=100)
    ap.add_argument("--skip", default="", help="comma-separated: sharding, reuse")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    pdcheck = os.path.abspath(a.pdcheck)
    scene = assembly(os.path.join(a.out, f"a{a.parts}.json"), a.parts)
    skip = set(a.skip.split(","))
    if "sharding" not in skip:
        sharding(a, pdcheck, a.out, scene)
    if "reuse" not in skip:
        reuse(a, pdcheck, a.out, scene)
    if a.million:
        million(a, pdcheck, a.out)


if __name__ == "__main__":
    main()
