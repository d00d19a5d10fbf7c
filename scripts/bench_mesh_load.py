#!/usr/bin/env python3
"""Times the parts stage (mesh files read, reduced and hulled) of pdcheck binaries.

usage: bench_mesh_load.py OUT_DIR PDCHECK [PDCHECK ...] [--files 400] [--triangles 2000]
                          [--format stl|ply] [--runs 5] [--jobs 2] [--scene SCENE.json]
                          [--pieces MODE] [--cache-modes]

Writes OUT_DIR/scene.json: --files distinct binary STL (or PLY) files (UV
spheres of about --triangles triangles each, jittered so no two are equal) on a
lattice, touching nobody; or times the given --scene instead. Each binary is
run --runs times in turn (interleaved, so load on the machine hits all alike)
with --method exact and --quiet; the median of the report's
stage_seconds.parts per binary, and the ratio to the first, are printed.
--pieces passes a pieces mode. --cache-modes times each binary three ways per
run, interleaved: --no-cache, an empty --cache directory (cold: computes and
stores) and a --cache directory filled once before the runs (warm).
"""
import argparse
import json
import math
import os
import random
import shutil
import statistics
import struct
import subprocess
import sys


def sphere_stl(path, triangles, rng):
    rings = max(3, int(math.sqrt(triangles / 2)))
    segs = max(3, triangles // (2 * rings))
    pts = []
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segs):
            ph = 2 * math.pi * j / segs
            r = 1 + 0.01 * rng.random()
            pts.append((r * math.sin(th) * math.cos(ph), r * math.sin(th) * math.sin(ph),
                        r * math.cos(th)))
    tris = []
    for i in range(rings):
        for j in range(segs):
            a, b = i * segs + j, i * segs + (j + 1) % segs
            c, d = a + segs, b + segs
            tris += [(a, c, b), (b, c, d)]
    if path.endswith(".ply"):
        with open(path, "wb") as f:
            f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
                     "property float y\nproperty float z\nelement face %d\n"
                     "property list uchar int vertex_indices\nend_header\n"
                     % (len(pts), len(tris))).encode())
            for p in pts:
                f.write(struct.pack("<3f", *p))
            for t in tris:
                f.write(struct.pack("<B3i", 3, *t))
        return
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            for k in t:
                f.write(struct.pack("<3f", *pts[k]))
            f.write(b"\0\0")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("binaries", nargs="+")
    ap.add_argument("--files", type=int, default=400)
    ap.add_argument("--triangles", type=int, default=2000)
    ap.add_argument("--format", choices=["stl", "ply"], default="stl")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--scene")
    ap.add_argument("--pieces")
    ap.add_argument("--cache-modes", action="store_true")
    a = ap.parse_args()
    scene = a.scene
    if not scene:
        os.makedirs(a.out, exist_ok=True)
        rng = random.Random(1)
        parts = []
        side = math.ceil(math.sqrt(a.files))
        for k in range(a.files):
            name = "m%04d.%s" % (k, a.format)
            sphere_stl(os.path.join(a.out, name), a.triangles, rng)
            parts.append({"id": "p%d" % k, "mesh": name,
                          "transform": [1, 0, 0, 3 * (k % side), 0, 1, 0, 3 * (k // side),
                                        0, 0, 1, 0, 0, 0, 0, 1]})
        scene = os.path.join(a.out, "scene.json")
        with open(scene, "w") as f:
            json.dump({"tolerance": 0.01, "parts": parts}, f)
    extra = ["--pieces", a.pieces] if a.pieces else []
    cache_root = os.path.join(a.out, "caches")
    os.makedirs(cache_root, exist_ok=True)

    def parts_seconds(b, args):
        r = subprocess.run([b, scene, "--quiet", "--method", "exact", "-j", str(a.jobs)] + extra +
                           args, capture_output=True, text=True)
        if r.returncode not in (0, 1, 3):
            sys.exit("%s failed (%d): %s" % (b, r.returncode, r.stderr))
        return json.loads(r.stdout)["stage_seconds"]["parts"]

    def fresh(d):
        shutil.rmtree(d, ignore_errors=True)
        return d

    shutil.rmtree(cache_root, ignore_errors=True)
    modes = {"": lambda b, k: ["--no-cache"] if a.cache_modes else []}
    if a.cache_modes:
        modes = {"no-cache": modes[""],
                 "cold": lambda b, k: ["--cache", fresh(os.path.join(
                     cache_root, "cold-%d-%d" % (a.binaries.index(b), k)))],
                 "warm": lambda b, k: ["--cache", os.path.join(
                     cache_root, "warm-%d" % a.binaries.index(b))]}
        for b in a.binaries:
            parts_seconds(b, modes["warm"](b, 0))  # fills the warm cache
    times = {(b, m): [] for b in a.binaries for m in modes}
    for k in range(a.runs):
        for b in a.binaries:
            for m, args in modes.items():
                times[(b, m)].append(parts_seconds(b, args(b, k)))
    base = statistics.median(times[(a.binaries[0], next(iter(modes)))])
    for (b, m), t in times.items():
        med = statistics.median(t)
        print("%-40s %-8s parts stage median %.3f s (runs: %s), ratio %.2f" %
              (b, m, med, " ".join("%.3f" % x for x in t), med / base))

if __name__ == "__main__":
    main()
