#!/usr/bin/env python3
"""Writes docs/accuracy-vs-time.md and its plot from pdbench's JSON output.

usage: accuracy_vs_time.py corpus.json paper.json docs_dir [pairs budget]
"""
import datetime
import json
import os
import platform
import sys

import matplotlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peer_table import table_lines  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The paper's Table I (depth) and Table II (function evaluations; totals, CPU s).
PAPER_DEPTH = {"GS-10": [1.000, 22.038, 35.224, 32.658, 27.500, 22.315, 14.719, 30.310, 35.854,
                         35.402, 37.936, 27.104, 21.729, 16977.000],
               "GS-40": [1.000, 19.496, 32.537, 30.112, 23.263, 21.614, 11.970, 27.288, 34.875,
                         34.004, 35.370, 25.372, 19.854, 16977.000],
               "GS-180": [1.000, 19.390, 31.877, 29.095, 22.291, 21.413, 11.500, 26.587, 34.148,
                          33.651, 35.124, 24.754, 19.866, 16977.000],
               "MLSL": [1.000, 19.314, 31.842, 28.911, 22.147, 21.314, 11.479, 26.406, 34.128,
                        33.644, 34.971, 24.446, 19.710, 16970.909],
               "GS-SQP": [1.000, 19.314, 31.842, 28.911, 22.147, 21.314, 11.479, 26.406, 34.128,
                          33.644, 34.971, 24.446, 19.710, 16970.909]}
PAPER_TOTALS = {"GS-10": (3080, 0.051), "GS-40": (45920, 0.36), "GS-180": (912240, 6.29),
                "MLSL": (15891, 5.66), "GS-SQP": (704, 0.97)}  # MLSL: its SQP column
OURS = {"GS-10": "grid 10", "GS-40": "grid 40", "GS-180": "grid 180", "MLSL": "mlsl-paper",
        "GS-SQP": "gs-local 3x3"}
COUNTS = ["(8, 8)", "(6, 9)", "(14, 5)", "(8, 10)", "(9, 7)", "(10, 5)", "(13, 6)", "(9, 8)",
          "(15, 9)", "(15, 11)", "(8, 11)", "(10, 6)", "(10, 8)", "(103, 93)"]
FLOOR = 1e-17  # errors of exactly 0 are drawn here on the log axis


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}"


def corpus_tables(rows):
    out = []
    for s in dict.fromkeys(r["set"] for r in rows):
        out.append(f"\n### {s}\n")
        out.append("| method | pairs | median ms | p99 ms | p99 CPU ms | median rel. err "
                   "| max rel. err | median α evals | median Ipopt calls | fallbacks "
                   "| stop reasons |")
        out.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
        for r in rows:
            if r["set"] == s:
                stops = ", ".join(f"{k} {v}" for k, v in sorted(r.get("stop_reasons", {}).items()))
                out.append(f"| {r['method']} | {r['pairs']} | {r['median_ms']:.3g} | "
                           f"{r.get('p99_ms', 0):.3g} | {r.get('p99_cpu_ms', 0):.3g} | "
                           f"{r['median_rel_err']:.1e} | {r['max_rel_err']:.1e} | "
                           f"{r['median_alpha_evals']:.0f} | {r['median_ipopt_calls']:.0f} | "
                           f"{r['fallbacks']} | {stops} |")
    return out


def paper_tables(paper):
    out = ["| problem | " + " | ".join(f"{k} paper | {k} ours ({OURS[k]})" for k in OURS)
           + " | exact (ours) |",
           "|---|" + "---:|" * (2 * len(OURS) + 1)]
    for i, p in enumerate(paper["problems"]):
        cells = []
        for k, ours in OURS.items():
            cells += [f"{PAPER_DEPTH[k][i]:.3f}", f"{p[ours]['depth']:.3f}"]
        out.append(f"| {i + 1}: {COUNTS[i]} | " + " | ".join(cells)
                   + f" | {p['exact']['depth']:.3f} |")
    out += ["", "| totals | " + " | ".join(f"{k} paper | {k} ours" for k in OURS)
            + " | mlsl (ours) |", "|---|" + "---:|" * (2 * len(OURS) + 1)]
    t = paper["totals"]
    out.append("| α evaluations | " + " | ".join(
        f"{PAPER_TOTALS[k][0]} | {t[OURS[k]]['evals']:.0f}" for k in OURS)
        + f" | {t['mlsl tau=0.9']['evals']:.0f} |")
    out.append("| CPU time (s) | " + " | ".join(
        f"{PAPER_TOTALS[k][1]} | {t[OURS[k]]['seconds']:.3g}" for k in OURS)
        + f" | {t['mlsl tau=0.9']['seconds']:.3g} |")
    return out


def plot(rows, path):
    fig, ax = plt.subplots(figsize=(8, 5.5))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    markers = "osD^v<>ph*"
    for i, m in enumerate(methods):
        pts = [pt for r in rows if r["method"] == m for pt in r["points"]]
        ax.scatter([p[0] for p in pts], [max(p[1], FLOOR) for p in pts], s=9, alpha=0.55,
                   marker=markers[i % len(markers)], label=m)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(1e-9, color="grey", lw=0.8, ls="--")
    ax.text(ax.get_xlim()[0] * 1.1, 1.4e-9, "1e-9 (exactness target)", fontsize=8, color="grey")
    ax.set_xlabel("time per pair (ms, one core)")
    ax.set_ylabel(f"relative error vs exact (0 drawn at {FLOOR:g})")
    ax.set_title("pdcheck: accuracy vs time, every pair of every set")
    ax.legend(fontsize=8, markerscale=2)
    fig.tight_layout()
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, path)


def main():
    corpus_path, paper_path, docs = sys.argv[1:4]
    run = " ".join(f"{k}={v}" for k, v in zip(("PAIRS", "BUDGET"), sys.argv[4:6]))
    with open(corpus_path) as f:
        rows = json.load(f)
    with open(paper_path) as f:
        paper = json.load(f)
    plot(rows, os.path.join(docs, "accuracy-vs-time.png"))
    lines = [
        "# Accuracy vs time",
        "",
        f"Produced by `{run + ' ' if run else ''}bash scripts/accuracy_vs_time.sh` on "
        f"{datetime.date.today()} ({machine()}). Every number below comes from that run; rerun it "
        "to refresh. The machine may have been shared with other jobs: read times within one "
        "table as ratios (the p99 includes scheduler stalls; `p99 CPU ms` is the same pairs' p99 "
        "of the solving thread's CPU time, CLOCK_THREAD_CPUTIME_ID, which other processes "
        "do not inflate except through shared caches).",
        "",
        "Each set is a seeded corpus of overlapping pairs (`src/corpus/generators.h`): vertex-count "
        "classes n+n (points on random ellipsoids, every point a hull vertex), the paper-like "
        "pairs, problem-14-like pairs (about 100 vertices, coordinates in the tens of thousands) "
        "and Zhou et al.'s sphere pairs; the contact sets (`src/corpus/contacts.h`, issue 12) are "
        "CAD contacts: plates face on face, a component seated on a board, shafts in bores and "
        "balls in sockets (clearance 0.05, exact fit, interference 0.05), plates 1e-6…1e-2 apart, "
        "each axis-aligned, rotated, and rotated at x ≈ 20,000 mm in float32 (n: vertices of the "
        "larger part); `apart 100+100`: box-overlapping pairs whose hulls are apart; `hard cases`: "
        "those of tests/test_hard_cases.cpp (identical cubes, 1e-9 overlaps, coplanar faces, "
        "containment, thin plates, a flat square, a pin in a panel; half of them rotated); "
        "`contained n`: deep containment (a shaft through a pulley hub's hull, a ball deep in an "
        "ellipsoid, issue 29). `fcl` and `bullet` (when pdbench was built with Debian's "
        "libfcl-dev and libbullet-dev) are FCL 0.7's signed distance (libccd GJK + EPA) and "
        "Bullet 3.24's btGjkEpaSolver2 (single precision, as Debian builds it) on the same "
        "pairs, in world coordinates, their query alone timed (shapes built before). Times are "
        "single-core, one pair after another in one process. The error is |depth − exact| / exact "
        "against the Minkowski-difference hull; depths at or below the contact resolution (kTouch "
        "of the pair's scale) count as contact for both methods. `stop reasons` say how each "
        "solve ended (docs/report-format.md, `stop_reason`). "
        "`fallbacks` counts pairs the method handed to the exact hull (reported per pair). A slow "
        "method stops after its time budget per set, so its `pairs` may be fewer.",
        "",
        "**Reading it.** `mlsl` (any τ) is exact to rounding on every set. It starts with the "
        "GJK + EPA bracket (docs/solver.md): on overlapping pairs the bracket closes "
        "(`epa-certificate`) in tens of support evaluations; separated pairs stop at GJK's "
        "separating direction; contacts, and the few pairs whose bracket stays open, go on to "
        "the sampling, whose optimum is proved global by the certificate, so τ only changes "
        "how long the sampling would run without it. `mlsl-paper` is the paper's Algorithm 1 as printed: exact on most "
        "pairs, but it misses near-tied optima on finely tessellated parts and costs 100–1000× "
        "more. The grids never reach 1e-9; `grid 180` is within ~1% at 65,160 evaluations.",
        "",
        "![error vs time](accuracy-vs-time.png)",
        "",
        "## Side by side: exact, the default, FCL and Bullet (issue 29)",
        "",
        "Medians per pair from the tables below (µs); ratios of the medians; the largest "
        "error against exact of each.",
        "",
    ]
    lines += table_lines(rows)
    lines += [
        "",
        "## Per set",
    ]
    lines += corpus_tables(rows)
    lines += [
        "",
        "## The paper's Tables I and II, side by side",
        "",
        "The paper's 14 polytope pairs are not published, so ours are 14 new random overlapping "
        "pairs with the same vertex counts (problem 14 with coordinates in the thousands). Depths "
        "therefore differ problem by problem; what compares is the pattern: which methods reach "
        "the best depth, and at what cost. Evaluation counts of the grids match the paper's "
        "exactly (2k(k+1) directions). The paper's MLSL column in Table II is its SQP solver; "
        "its times are Matlab/Python on its own machine.",
        "",
    ]
    lines += paper_tables(paper)
    lines.append("")
    tmp = os.path.join(docs, "accuracy-vs-time.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.replace(tmp, os.path.join(docs, "accuracy-vs-time.md"))


if __name__ == "__main__":
    main()
