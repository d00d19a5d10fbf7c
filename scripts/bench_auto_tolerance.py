#!/usr/bin/env python3
"""What `tolerance: auto` costs (issue 27): cold and cached runs of the 10,000-part assembly, fixed
tolerance against auto, with its parts inline (as scripts/make_assembly.py writes them: auto only
reads their double step) and as binary STL files (auto measures every file's sag).

usage: bench_auto_tolerance.py PDCHECK OUTDIR [--parts 10000] [--runs 3] [--only inline|stl]
                               [--measure-only] [--baseline OTHER_PDCHECK]

Writes OUTDIR/a.json (make_assembly.py), OUTDIR/meshes/*.stl (each prism as a closed float32 mesh:
its n-gon caps fanned from their first vertex, its sides two triangles each) and OUTDIR/m.json (the
same parts as mesh files), then times `pdcheck SCENE -q -j 2 --cache DIR` for each scene and
tolerance (the scene's 0.1 and auto): cold (an empty cache directory) and cached (the same
directory again). Prints a Markdown table of the medians, and per build the ratios of the CPU
medians to the fixed tolerance's (and the median of the per-run ratios). `--baseline OTHER_PDCHECK`
runs a second build in the same loop (each run: both builds, their order alternating between runs),
so that a before/after comparison sees the same machine load.
"""
import argparse
import json
import os
import resource
import shutil
import statistics
import struct
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def write_prism_stl(path, pts):
    n = len(pts) // 2
    lo, hi = pts[:n], pts[n:]
    tris = []
    for k in range(1, n - 1):  # caps: bottom facing -z, top facing +z
        tris.append((lo[0], lo[k + 1], lo[k]))
        tris.append((hi[0], hi[k], hi[k + 1]))
    for k in range(n):
        k1 = (k + 1) % n
        tris.append((lo[k], lo[k1], hi[k1]))
        tris.append((lo[k], hi[k1], hi[k]))
    with open(path, "wb") as f:
        f.write(b"pdcheck bench prism".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")


def timed(cmd):
    """Wall seconds and CPU seconds (user + system of pdcheck and its workers: steadier than the
    wall time on a shared machine), and the report."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode not in (0, 1, 3):
        sys.exit("%s: exit %d\n%s" % (" ".join(cmd), p.returncode, p.stderr[-2000:]))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, json.loads(p.stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pdcheck")
    ap.add_argument("outdir")
    ap.add_argument("--parts", type=int, default=10000)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--only", choices=["inline", "stl"])
    ap.add_argument("--measure-only", action="store_true",
                    help="only 0.1 and auto clamped at 0.1: what measuring costs, the same decisions")
    ap.add_argument("--baseline", metavar="OTHER_PDCHECK",
                    help="a second build, run interleaved with PDCHECK (labelled 'baseline')")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.outdir, "meshes"), exist_ok=True)
    inline = os.path.join(a.outdir, "a.json")
    subprocess.run([sys.executable, os.path.join(HERE, "make_assembly.py"), inline, "--parts",
                    str(a.parts)], check=True, capture_output=True)
    with open(inline) as f:
        scene = json.load(f)
    parts = []
    for p in scene["parts"]:
        name = os.path.join("meshes", p["id"] + ".stl")
        write_prism_stl(os.path.join(a.outdir, name), p["vertices"])
        parts.append({"id": p["id"], "mesh": name})
    meshes = os.path.join(a.outdir, "m.json")
    with open(meshes, "w") as f:
        json.dump(dict(scene, parts=parts), f)
    # auto clamped at the fixed tolerance decides the same pairs the same way: the difference to
    # 0.1 is the measuring alone. Plain auto also decides against each pair's own (smaller) band.
    scenes = {}
    for label, path, sc in (("inline", inline, scene), ("STL files", meshes, dict(scene, parts=parts))):
        clamped = path[:-5] + "_auto_min.json"
        with open(clamped, "w") as f:
            json.dump(dict(sc, tolerance={"auto": True, "min": 0.1}), f)
        scenes[label] = [("0.1", [path]), ("auto, min 0.1", [clamped]),
                         ("auto", [path, "--tolerance", "auto"])][:2 if a.measure_only else 3]
    builds = [("new", a.pdcheck)] + ([("baseline", a.baseline)] if a.baseline else [])
    print("| scene | build | tolerance | cold: wall, CPU (s) | cached: wall, CPU (s) | interference / "
          "false_positive |")
    print("|---|---|---|---|---|---|")
    labels = {"inline": ["inline"], "stl": ["STL files"]}.get(a.only, ["inline", "STL files"])
    med = statistics.median
    for label in labels:
        # per (build, tolerance): cold wall, cold CPU, cached wall, cached CPU, the last report
        results = {(b, name): [[], [], [], [], None] for b, _ in builds for name, _ in scenes[label]}
        for run in range(a.runs):  # interleaved, so a change in the machine's load hits all alike
            order = builds if run % 2 == 0 else builds[::-1]
            for b, pdcheck in order:
                for name, args in scenes[label]:
                    cache = os.path.join(a.outdir, "cache")
                    shutil.rmtree(cache, ignore_errors=True)
                    cmd = [pdcheck] + args + ["-q", "-j", "2", "--cache", cache]
                    r = results[(b, name)]
                    w, c, _ = timed(cmd)
                    r[0].append(w), r[1].append(c)
                    w, c, rep = timed(cmd)
                    r[2].append(w), r[3].append(c)
                    r[4] = rep
            print("run %d of %d done" % (run + 1, a.runs), file=sys.stderr)
        for b, _ in builds:
            for name, _ in scenes[label]:
                r = results[(b, name)]
                s = r[4]["summary"]
                print("| %s | %s | %s | %.2f, %.2f | %.2f, %.2f | %d / %d |" % (
                    label, b, name, med(r[0]), med(r[1]), med(r[2]), med(r[3]), s["interference"],
                    s["false_positive"]))
        fixed = scenes[label][0][0]
        for b, _ in builds:
            for name, _ in scenes[label][1:]:
                r, f = results[(b, name)], results[(b, fixed)]
                print("%s, %s: %s / %s CPU: cold %.3f (per run %.3f), cached %.3f (per run %.3f)" % (
                    label, b, name, fixed, med(r[1]) / med(f[1]),
                    med([x / y for x, y in zip(r[1], f[1])]), med(r[3]) / med(f[3]),
                    med([x / y for x, y in zip(r[3], f[3])])))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
