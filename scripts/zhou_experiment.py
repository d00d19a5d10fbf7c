#!/usr/bin/env python3
"""Zhou et al.'s motion experiment as a pdcheck scene, and its plot.

usage: zhou_experiment.py scene OUT.json [--m 100]
       zhou_experiment.py plot REPORT.json OUT.png

Two sphere polytopes of m points (a Fibonacci lattice) of radius 10 centred at
(0,0,0) and (20,10,30); the first turns at 0.05 rad/s about z, the second moves
at -0.01*(2,1,3) per second; dt = 1 s, 2000 steps.
"""
import json
import math
import os
import sys


def sphere(m, c, r=10.0):
    golden = math.pi * (3.0 - math.sqrt(5.0))
    pts = []
    for i in range(m):
        z = 1.0 - 2.0 * (i + 0.5) / m
        rho = math.sqrt(1.0 - z * z)
        t = golden * i
        pts.append([c[0] + r * rho * math.cos(t), c[1] + r * rho * math.sin(t), c[2] + r * z])
    return pts


def scene(out, m):
    doc = {"version": 1, "units": "mm", "tolerance": 0.1,
           "parts": [{"id": "P", "vertices": sphere(m, (0, 0, 0)),
                      "motion": {"angular_velocity": [0, 0, 0.05], "about": [0, 0, 0]}},
                     {"id": "Q", "vertices": sphere(m, (20, 10, 30)),
                      "motion": {"velocity": [-0.02, -0.01, -0.03]}}],
           "checks": {"motion": {"t0": 0, "t1": 1999, "dt": 1, "series": True}}}
    with open(out + ".tmp", "w") as f:
        json.dump(doc, f)
    os.replace(out + ".tmp", out)


def plot(report, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(report) as f:
        r = json.load(f)
    pair = r["pairs"][0]
    ts = [p[0] for p in pair["motion"]["series"]]
    vs = [p[1] for p in pair["motion"]["series"]]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(ts, vs, lw=1.2)
    ax.axhline(0, color="grey", lw=0.8)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("signed distance (mm): depth > 0, -separation < 0")
    m = pair["motion"]
    ax.set_title(f"Zhou et al.'s experiment: max depth {m['max_depth']:.4f} at t = "
                 f"{m['t_max_depth']:g} s")
    fig.tight_layout()
    fig.savefig(out + ".tmp.png", dpi=110)
    os.replace(out + ".tmp.png", out)


if __name__ == "__main__":
    if sys.argv[1] == "scene":
        m = int(sys.argv[sys.argv.index("--m") + 1]) if "--m" in sys.argv else 100
        scene(sys.argv[2], m)
    else:
        plot(sys.argv[2], sys.argv[3])
