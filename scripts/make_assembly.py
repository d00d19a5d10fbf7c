#!/usr/bin/env python3
"""Writes a synthetic aircraft-like assembly of convex parts as one scene file.

usage: make_assembly.py OUT.json [--parts 10000] [--vertices 20:200] [--seed 1]

Parts are n-gon prisms (2n hull vertices, n drawn so that 2n is in the vertex
range) in a lattice of bays along a fuselage-like box at x ~ 1e4 mm, turned
about their axes so that neighbouring boxes often overlap while the hulls stay
apart. In ~1% of the bays two half-height prisms are stacked exactly touching
(a shared face at the same coordinates); a few bays hold a genuine interference
(5 mm) and a few a tessellation-sized one (0.05 mm, below the 0.1 mm
tolerance). The expected counts are printed on stderr and written to
OUT.expected.json (the scene format refuses unknown keys).
"""
import argparse
import json
import math
import os
import random
import sys


def prism(n, radius, x, y, z0, z1, turn):
    pts = []
    for z in (z0, z1):
        for k in range(n):
            t = turn + 2 * math.pi * k / n
            pts.append([round(x + radius * math.cos(t), 6), round(y + radius * math.sin(t), 6), z])
    return pts


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--parts", type=int, default=10000)
    ap.add_argument("--vertices", default="20:200")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--all-overlapping", action="store_true",
                    help="every bay holds two prisms overlapping by 0.01-10 mm (a solver load)")
    a = ap.parse_args()
    lo, hi = (int(v) for v in a.vertices.split(":"))
    rng = random.Random(a.seed)
    spacing = 300.0  # mm between bay centres
    parts, expected = [], {"touching": 0, "interference": 0, "false_positive": 0}
    bay = 0
    # Bays fill a 16 x 12 cross-section, then march along x (the fuselage). Rows
    # are 150 mm apart in y and staggered by 150 mm in x, so a part's diagonal
    # neighbours are 212 mm away: with radii <= 100 mm their boxes overlap (they
    # reach the narrow phase) while the hulls stay >= 12 mm apart.
    while len(parts) < a.parts:
        i, j, k = bay // 192, (bay // 12) % 16, bay % 12
        bay += 1
        x = 10000.0 + spacing * i + (spacing / 2) * (j % 2)
        y, z = (spacing / 2) * (j - 8), spacing * (k - 6)
        n = rng.randint(max(3, lo // 2), max(3, hi // 2))
        radius = rng.uniform(80.0, 100.0)
        h = rng.uniform(60.0, 140.0)
        roll = rng.random()
        left = a.parts - len(parts)
        if a.all_overlapping:
            if left < 2:
                break
            parts.append(prism(n, radius * 0.5, x, y, z - h, z, rng.random()))
            parts.append(prism(n, radius * 0.4, x + rng.uniform(-20, 20), y, z - rng.uniform(0.01, 10),
                               z + h, rng.random()))
            expected["interference" if parts[-1][0][2] < z - 0.1 else "false_positive"] += 1
        elif left >= 2 and roll < 0.01:  # two prisms sharing a face: touching
            parts.append(prism(n, radius * 0.5, x, y, z - h, z, rng.random()))
            parts.append(prism(n, radius * 0.4, x, y, z, z + h, rng.random()))
            expected["touching"] += 1
        elif left >= 2 and roll < 0.0103:  # a genuine interference of 5 mm
            parts.append(prism(n, radius * 0.5, x, y, z - h, z, rng.random()))
            parts.append(prism(n, radius * 0.4, x, y, z - 5.0, z + h, rng.random()))
            expected["interference"] += 1
        elif left >= 2 and roll < 0.0153:  # tessellation-sized: 0.05 mm
            parts.append(prism(n, radius * 0.5, x, y, z - h, z, rng.random()))
            parts.append(prism(n, radius * 0.4, x, y, z - 0.05, z + h, rng.random()))
            expected["false_positive"] += 1
        else:
            parts.append(prism(n, radius, x, y, z - h / 2, z + h / 2, rng.random()))
    scene = {"version": 1, "units": "mm", "tolerance": 0.1,
             "parts": [{"id": f"p{q:05d}", "vertices": v} for q, v in enumerate(parts)]}
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(scene, f, separators=(",", ":"))
    os.replace(tmp, a.out)
    with open(a.out + ".expected.json", "w") as f:
        json.dump(expected, f)
    print(f"make_assembly: {len(parts)} parts, {bay} bays, expected {expected}", file=sys.stderr)


if __name__ == "__main__":
    main()
