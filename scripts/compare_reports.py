#!/usr/bin/env python3
"""Checks that two pdcheck binaries write the same reports, timings aside: the
check behind refactorings that must not change what a user sees (issue 26).

    scripts/compare_reports.py BEFORE_PDCHECK AFTER_PDCHECK [SCENE ...]

Without scenes it runs the bundled ones (testdata/examples/*.json,
testdata/demo/scene.json) and a few it writes into a temporary directory to
reach every field of a pair entry: clearance (met and violated), motion with
its series, a part that cannot be read, a listed pair, the other methods and a
nonconvex part refined by pieces. Each scene is run as: a JSON report, JSON
Lines, JUnit and SARIF; two shards and their merge; a --reuse of the first
report; and twice over one fresh cache directory (the second run reads the
caches). Compared: exit code, the report's text and stderr, each with the
timings (seconds, stage_seconds, time_ms, decomposition_seconds, JUnit's
time="..." and the summary line's "in N s") set to 0. Key order counts: the
JSON text is compared, not the parsed values.

Exit 0 when every run matches; 1 otherwise, printing the first differing line
of each run that differs.
"""
import difflib
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
TIMING_KEYS = {"seconds", "stage_seconds", "time_ms", "decomposition_seconds"}


def box(x0, y0, z0, x1, y1, z1):
    return [[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]


def generated_scenes(directory):
    """Scenes reaching the fields the bundled ones may not: written to `directory`."""
    scenes = {
        "clearance": {
            "version": 1, "units": "mm", "tolerance": 0.05,
            "parts": [
                {"id": "a", "vertices": box(0, 0, 0, 1, 1, 1)},
                {"id": "b", "vertices": box(1.5, 0, 0, 2.5, 1, 1)},
                {"id": "c", "vertices": box(0.5, 0.5, 0.5, 1.7, 1.5, 1.5)},
                {"id": "d", "vertices": box(9, 9, 9, 10, 10, 10)},
            ],
            "checks": {"clearance": {"min": 0.8, "pairs": [{"pair": ["a", "d"], "min": 20}]}},
        },
        "motion": {
            "version": 1, "units": "mm", "tolerance": 0.05,
            "parts": [
                {"id": "still", "vertices": box(0, 0, 0, 1, 1, 1)},
                {"id": "moving", "vertices": box(3, 0, 0, 4, 1, 1),
                 "motion": {"velocity": [-1, 0, 0], "angular_velocity": [0, 0, 0.1],
                            "about": [3.5, 0.5, 0.5]}},
            ],
            "checks": {"motion": {"t0": 0, "t1": 4, "dt": 0.5, "series": True},
                       "clearance": {"min": 0.3}},
        },
        "errors": {
            "version": 1, "units": "cm", "tolerance": 0.01,
            "parts": [
                {"id": "gone", "mesh": "no-such-file.stl"},
                {"id": "a", "vertices": box(0, 0, 0, 1, 1, 1)},
                {"id": "b", "vertices": box(0.9, 0, 0, 2, 1, 1)},
                {"id": "c", "vertices": box(0.95, 0.2, 0.2, 1.5, 0.8, 0.8)},
            ],
            "pairs": [["a", "b"], ["b", "c"], ["gone", "a"]],
            "solver": {"method": "grid", "grid": 12},
        },
        "paper": {
            "version": 1, "units": "mm", "tolerance": 0.1,
            "parts": [
                {"id": "a", "vertices": box(0, 0, 0, 1, 1, 1)},
                {"id": "b", "vertices": box(0.8, 0.1, 0.1, 2, 0.9, 0.9)},
            ],
            "solver": {"method": "mlsl-paper", "seed": 7},
        },
    }
    demo = json.load(open(os.path.join(ROOT, "testdata", "demo", "scene.json")))
    for part in demo["parts"]:
        if "mesh" in part:
            part["mesh"] = os.path.join(ROOT, "testdata", "demo", part["mesh"])
            part["pieces"] = "decompose"
    scenes["demo-decompose"] = demo
    paths = []
    for name, scene in scenes.items():
        path = os.path.join(directory, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        paths.append(path)
    return paths


def zero_timings(value):
    if isinstance(value, dict):
        return {k: (0 if k in TIMING_KEYS else zero_timings(v)) for k, v in value.items()}
    if isinstance(value, list):
        return [zero_timings(v) for v in value]
    return value


def normal_text(text):
    """The text with its timings at 0: JSON (one document or lines) or XML."""
    try:
        return json.dumps(zero_timings(json.loads(text)), indent=1) + "\n"
    except ValueError:
        pass
    lines = []
    for line in text.splitlines():
        try:
            lines.append(json.dumps(zero_timings(json.loads(line))))
        except ValueError:
            lines.append(re.sub(r'time="[^"]*"', 'time="0"', line))
    return "\n".join(lines) + "\n"


def normal_stderr(text):
    """Without the progress lines (rates, ETA) and with the summary line's time at 0."""
    lines = [l for l in re.split(r"[\r\n]+", text) if l and not re.match(r"pdcheck: \d+/\d+ ", l)]
    return re.sub(r" in [0-9.]+ s$", " in 0 s", "\n".join(lines), flags=re.M)


def run_in(binary, args, out_path, cwd):
    p = subprocess.run([binary] + args, capture_output=True, text=True, cwd=cwd)
    text = p.stdout
    if out_path and os.path.exists(out_path):
        with open(out_path) as f:
            text = f.read()
    return p.returncode, normal_text(text) if text.strip() else "", normal_stderr(p.stderr)


def runs_of(binary, scene, work, tag):
    """Every run of one scene with one binary: {name: (exit, report text, stderr)}.
    Run in a directory of their own under paths relative to it, which stderr names."""
    d = os.path.join(work, tag)
    os.makedirs(d, exist_ok=True)
    nc = ["--no-cache", "-j", "2"]
    out = {}
    report = os.path.join(d, "report.json")

    def run(binary, args, out_path=None):
        return run_in(binary, args, out_path, d)

    out["json"] = run(binary, [scene, "-o", "report.json"] + nc, report)
    # To a file: the lines in report order (on stdout they come as pairs end).
    lines = os.path.join(d, "report.jsonl")
    out["jsonl"] = run(binary, [scene, "--format", "jsonl", "-q", "-o", "report.jsonl"] + nc, lines)
    out["junit"] = run(binary, [scene, "--format", "junit", "-q"] + nc)
    out["sarif"] = run(binary, [scene, "--format", "sarif", "-q"] + nc)
    shards = []
    for k in (1, 2):
        name = f"shard{k}.json"
        out[f"shard{k}"] = run(binary, [scene, "--shard", f"{k}/2", "-o", name] + nc,
                               os.path.join(d, name))
        shards.append(name)
    out["merge"] = run(binary, ["merge"] + shards + ["-o", "merged.json"],
                       os.path.join(d, "merged.json"))
    if os.path.exists(report):
        out["reuse"] = run(binary, [scene, "--reuse", "report.json", "-o", "reused.json"] + nc,
                           os.path.join(d, "reused.json"))
    run(binary, [scene, "--cache", "cache", "-q", "-j", "2"])
    out["cached"] = run(binary, [scene, "--cache", "cache", "-q", "-j", "2"])
    return out


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    before, after = (os.path.abspath(b) for b in sys.argv[1:3])
    with tempfile.TemporaryDirectory(prefix="pdcheck-compare-") as work:
        scenes = [os.path.abspath(s) for s in sys.argv[3:]]
        if not scenes:
            scenes = sorted(glob.glob(os.path.join(ROOT, "testdata", "examples", "*.json")))
            scenes.append(os.path.join(ROOT, "testdata", "demo", "scene.json"))
            scenes += generated_scenes(work)
        differing = 0
        compared = 0
        for n, scene in enumerate(scenes):
            a = runs_of(before, scene, work, f"{n}-before")
            b = runs_of(after, scene, work, f"{n}-after")
            for name in a:
                compared += 1
                for what, x, y in zip(("exit code", "report", "stderr"), a[name], b[name]):
                    if x == y:
                        continue
                    differing += 1
                    print(f"{os.path.basename(scene)} [{name}]: {what} differs")
                    if isinstance(x, str):
                        diff = difflib.unified_diff(x.splitlines(), y.splitlines(), lineterm="", n=1)
                        for line in list(diff)[:12]:
                            print("    " + line)
                    else:
                        print(f"    {x} != {y}")
            print(f"{os.path.basename(scene)}: {len(a)} runs compared "
                  f"(exit codes {sorted(set(r[0] for r in a.values()))})")
        print(f"{compared} runs, {differing} difference(s)")
        return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
