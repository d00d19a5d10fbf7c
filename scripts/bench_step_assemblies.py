#!/usr/bin/env python3
"""STEP benchmark (issue 43): pdcheck against the exact checker a user would script in FreeCAD.

usage: bench_step_assemblies.py [--pdcheck build/bin/pdcheck] [--freecadcmd freecadcmd]
                                [--out build/bench_step] [--runs 3] [--jobs 1] [--only NAME ...]
                                [--quick] [--no-generate] [--timeout 1800]

Writes the mechanisms of scripts/make_step_assemblies.py into OUT/mechanisms (--no-generate takes
them as they are), then per mechanism and per run, side by side, in an order that turns by one
every run:
  asm-cold     pdcheck scene-assembly.json --no-cache   (the assembly file)
  parts-cold   pdcheck scene-parts.json --no-cache      (one file per part)
  asm-cached   pdcheck scene-assembly.json --cache DIR  (DIR filled by one run before the timed ones)
  parts-cached pdcheck scene-parts.json --cache DIR
  freecad      freecadcmd scripts/freecad_exact_check.py on scene-assembly.json: Import.insert, then
               for every pair whose boxes come within the tolerance distToShape, and
               common().Volume where the distance is 0
pdcheck runs with --jobs N (default 1) and --quiet: --jobs 2 on a 2-core machine is pdcheck's
default there (FreeCAD's script uses one core either way); pin the whole benchmark to one core with
`taskset -c 0` and --jobs 1 so that both checkers get the same single core. Times are wall seconds of the whole
process (FreeCAD: also its pair loop alone, `check`), medians over the runs.

Scored per mechanism on the cold runs' reports (the last run; the cached reports must say the same):
  right      relations whose pdcheck status is one expected.json's `statuses` allow (contact:
             separated or false_positive; clearance: separated; interference: interference, or
             false_positive within the tolerance); a pair the broad phase culled counts as separated
  undecided  pairs with status undecided
  decisive   findings (status interference, false_positive, undecided or clearance_violation,
             plus every nominal contact) whose exact.verdict is interference, false_positive,
             touching or separated
  wrong      decisive exact verdicts that contradict the nominal relation: not among the
             relation's `exact`, a contact's `separated` farther apart than its `allowance`, a
             clearance's distance off its gap by more than the allowance, or an interference's
             depth_bounds that exclude its nominal thickness (beyond the allowance)
  ratio      pdcheck asm-cold / freecad, whole processes
FreeCAD's answers are scored too (right: a contact at distance 0 with no common volume above
1e-6 mm^3, a clearance at a distance > 0, an interference with a common volume).
Ends with Markdown tables (for docs/performance.md); OUT/results.json keeps every number,
OUT/reports/NAME-MODE.json the last run's pdcheck reports, OUT/freecad-NAME.json FreeCAD's. A run that
fails (pdcheck exit other than 0, 1 or 3, no report, or past --timeout) is reported and the
benchmark goes on. Python 3 stdlib.
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
sys.path.insert(0, HERE)
# One pdcheck run, timed, its report parsed: the same as the CAD-assembly benchmark's.
from bench_cad_assemblies import run as run_pdcheck  # noqa: E402
MODES = ("asm-cold", "parts-cold", "asm-cached", "parts-cached", "freecad")
FINDINGS = ("interference", "false_positive", "undecided", "clearance_violation")
DECISIVE = ("interference", "false_positive", "touching", "separated")
FC_TOUCH, FC_VOLUME = 1e-7, 1e-6


def run_freecad(freecadcmd, scene, out, timeout):
    env = dict(os.environ, PDCHECK_FC_SCENE=scene, PDCHECK_FC_OUT=out)
    if os.path.exists(out):
        os.remove(out)
    t0 = time.monotonic()
    try:
        p = subprocess.run([freecadcmd, os.path.join(HERE, "freecad_exact_check.py")], env=env,
                           capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return time.monotonic() - t0, None, "timed out after %g s" % timeout
    dt = time.monotonic() - t0
    if p.returncode != 0 or not os.path.exists(out):
        return dt, None, "exit %d: %s" % (p.returncode, (p.stdout + p.stderr).strip()[-300:])
    return dt, json.load(open(out)), None


def leaf(pid):
    return pid.rsplit("/", 1)[-1]


def pairs_by_name(pairs):
    return {frozenset((leaf(p["a"]), leaf(p["b"]))): p for p in pairs}


def exact_wrong(e, p):
    """Why a decisive exact verdict contradicts the nominal relation, or None."""
    x = p.get("exact") or {}
    v = x.get("verdict")
    if v not in DECISIVE:
        return None
    allow = e["allowance"] + 1e-7
    if v not in e["exact"]:
        return "exact %s" % v
    dist = x.get("distance")
    if e["expect"] == "contact" and v == "separated" and dist is not None and dist > allow:
        return "exact separated at %.3g > allowance %.3g" % (dist, e["allowance"])
    if e["expect"] == "clearance" and dist is not None:
        if dist < e["gap"] - allow or (not e.get("gap_is_lower_bound") and dist > e["gap"] + allow + 1e-6):
            return "exact distance %.9g, gap %s" % (dist, e["gap"])
    if e["expect"] == "interference" and x.get("depth_bounds"):
        lo, hi = x["depth_bounds"]
        d = e["nominal_depth"]
        if lo > d + allow or hi < d - allow:
            return "exact depth_bounds [%.6g, %.6g] exclude the nominal %g" % (lo, hi, d)
    return None


def score(report, expected):
    got = pairs_by_name(report["pairs"])
    s = {"right": 0, "wrong_status": [], "undecided": 0, "findings": 0, "decisive": 0,
         "wrong_exact": [], "indecisive": [], "unlisted": [], "by": {}}
    listed = set()
    for e in expected["pairs"]:
        k = frozenset((e["a"], e["b"]))
        listed.add(k)
        p = got.get(k)
        st = p["status"] if p else "culled"
        if st in e["statuses"] or (st == "culled" and "separated" in e["statuses"]):
            s["right"] += 1
        else:
            s["wrong_status"].append(describe(e, p, st))
        if p is None:
            continue
        why = exact_wrong(e, p)
        if why:
            s["wrong_exact"].append("%s / %s (%s): %s" % (e["a"], e["b"], e["expect"], why))
        if st in FINDINGS or e["expect"] == "contact":
            s["findings"] += 1
            x = p.get("exact") or {}
            if x.get("verdict") in DECISIVE:
                s["decisive"] += 1
                s["by"][x.get("by")] = s["by"].get(x.get("by"), 0) + 1
            else:
                s["indecisive"].append(describe(e, p, st))
    for k, p in got.items():
        if p["status"] == "undecided":
            s["undecided"] += 1
        if k not in listed and p["status"] != "separated":
            s["unlisted"].append("%s / %s %s depth %s" % (p["a"], p["b"], p["status"], p.get("depth")))
    return s


def describe(e, p, st):
    s = "%s / %s: expected %s" % (e["a"], e["b"], e["expect"])
    if "nominal_depth" in e:
        s += " (%g)" % e["nominal_depth"]
    if "gap" in e:
        s += " (gap %g)" % e["gap"]
    s += ", got %s" % st
    if p:
        s += ", depth %s, depth_bounds %s, depth_source %s" % (p.get("depth"), json.dumps(p.get("depth_bounds")),
                                                             p.get("depth_source"))
        if p.get("reason") or p.get("error"):
            s += ", reason: %s" % (p.get("reason") or p.get("error"))
        s += ", exact %s" % json.dumps(p.get("exact"))
    return s


def score_freecad(result, expected):
    got = pairs_by_name(result["pairs"])
    right, wrong = 0, []
    for e in expected["pairs"]:
        p = got.get(frozenset((e["a"], e["b"])))
        if p is None:
            verdict = "separated (boxes apart)"
        elif "error" in p:
            verdict = "error: " + p["error"]
        elif p["distance"] > FC_TOUCH:
            verdict = "separated"
        elif p.get("volume", 0.0) > FC_VOLUME:
            verdict = "overlap"
        else:
            verdict = "touching"
        want = {"contact": "touching", "clearance": "separated", "interference": "overlap"}[e["expect"]]
        if verdict.startswith(want):
            right += 1
        else:
            wrong.append("%s / %s: expected %s, FreeCAD %s (distance %s, volume %s)" % (
                e["a"], e["b"], e["expect"], verdict, p and p.get("distance"), p and p.get("volume")))
    return right, wrong


def med(xs):
    return statistics.median(xs) if xs else None


def fmt_s(x):
    return "-" if x is None else "%.2f" % x


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pdcheck", default=os.path.join(HERE, "..", "build", "bin", "pdcheck"))
    ap.add_argument("--freecadcmd", default=shutil.which("freecadcmd") or "freecadcmd")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "build", "bench_step"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--quick", action="store_true", help="the generator's --quick set")
    ap.add_argument("--no-generate", action="store_true", help="use OUT/mechanisms as they are")
    ap.add_argument("--timeout", type=float, default=1800.0, help="seconds per run")
    a = ap.parse_args()
    if a.runs < 1 or a.jobs < 1:
        ap.error("--runs and --jobs must be >= 1")
    if not (os.path.isfile(a.pdcheck) and os.access(a.pdcheck, os.X_OK)):
        ap.error("no pdcheck executable at %s" % a.pdcheck)
    if not shutil.which(a.freecadcmd):
        ap.error("freecadcmd not found (Debian package freecad)")
    out = os.path.abspath(a.out)
    mech_dir = os.path.join(out, "mechanisms")
    if not a.no_generate:
        cmd = [sys.executable, os.path.join(HERE, "make_step_assemblies.py"), mech_dir,
               "--freecadcmd", a.freecadcmd]
        cmd += ["--quick"] if a.quick else []
        cmd += ["--only"] + a.only if a.only else []
        if subprocess.run(cmd).returncode != 0:
            sys.exit("the mechanisms could not be generated")
    index_path = os.path.join(mech_dir, "index.json")
    if not os.path.exists(index_path):
        ap.error("no %s (run without --no-generate)" % index_path)
    names = [x["name"] for x in json.load(open(index_path))["mechanisms"]]
    if a.only:
        names = [n for n in names if n in a.only]
    try:
        cpus = sorted(os.sched_getaffinity(0))
    except AttributeError:
        cpus = []
    print("cpus %s, pdcheck --jobs %d, %d runs" % (cpus, a.jobs, a.runs), file=sys.stderr)
    jobs = ["--jobs", str(a.jobs)]
    rows = []
    for name in names:
        d = os.path.join(mech_dir, name)
        scenes = {"asm": os.path.join(d, "scene-assembly.json"), "parts": os.path.join(d, "scene-parts.json")}
        expected = json.load(open(os.path.join(d, "expected.json")))
        caches = {k: os.path.join(out, "cache", name, k) for k in scenes}
        for k, c in caches.items():  # the cached runs' cache: filled once, untimed
            shutil.rmtree(c, ignore_errors=True)
            run_pdcheck(a.pdcheck, scenes[k], ["--cache", c] + jobs, a.timeout)
        times = {m: [] for m in MODES}
        reports, errors, fc_check, fc_load = {}, [], [], []
        fc_out = os.path.join(out, "freecad-%s.json" % name)
        for r in range(a.runs):
            order = MODES[r % len(MODES):] + MODES[:r % len(MODES)]
            for mode in order:
                if mode == "freecad":
                    t, rep, err = run_freecad(a.freecadcmd, scenes["asm"], fc_out, a.timeout)
                    if rep:
                        fc_check.append(rep["check_seconds"])
                        fc_load.append(rep["load_seconds"])
                else:
                    scene_key, kind = mode.split("-")
                    args = ["--no-cache"] if kind == "cold" else ["--cache", caches[scene_key]]
                    t, rep, err = run_pdcheck(a.pdcheck, scenes[scene_key], args + jobs, a.timeout)
                times[mode].append(t)
                if rep is None:
                    errors.append("%s run %d: %s" % (mode, r + 1, err))
                else:
                    reports[mode] = rep
            print("%s run %d: %s" % (name, r + 1, ", ".join("%s %.2f s" % (m, times[m][-1]) for m in MODES)),
                  file=sys.stderr)
        os.makedirs(os.path.join(out, "reports"), exist_ok=True)
        for mode, rep in reports.items():  # the last run's, for a closer look
            if mode != "freecad":
                with open(os.path.join(out, "reports", "%s-%s.json" % (name, mode)), "w") as f:
                    json.dump(rep, f, indent=1)
        m = {k: med(v) for k, v in times.items()}
        row = {"name": name, "description": expected["description"], "parts": len(expected["parts"]),
               "faces": sum(p["faces"] for p in expected["parts"].values()),
               "relations": len(expected["pairs"]), "median_seconds": m,
               "freecad_check_seconds": med(fc_check), "freecad_load_seconds": med(fc_load), "errors": errors}
        print("\n## %s: %s" % (name, expected["description"]))
        print("parts %d (%d faces), nominal relations %d, tolerance %g" % (row["parts"], row["faces"],
                                                                        row["relations"], expected["tolerance"]))
        print("median of %d runs: %s; FreeCAD load %s s, check %s s" % (
            a.runs, ", ".join("%s %s s" % (k, fmt_s(v)) for k, v in m.items()), fmt_s(row["freecad_load_seconds"]),
            fmt_s(row["freecad_check_seconds"])))
        for e in errors:
            print("  failed: " + e)
        for mode in MODES[:4]:
            rep = reports.get(mode)
            if rep is None:
                row[mode] = None
                continue
            s = score(rep, expected)
            row[mode] = s
            print("%s: %d/%d right, %d undecided, %d/%d findings decisive (%s), %d exact verdicts wrong; "
                  "stages %s" % (mode, s["right"], row["relations"], s["undecided"], s["decisive"], s["findings"],
                                 ", ".join("%s %d" % kv for kv in sorted(s["by"].items())), len(s["wrong_exact"]),
                                 ", ".join("%s %.2f" % kv for kv in rep.get("stage_seconds", {}).items())))
            for w in s["wrong_status"]:
                print("  wrong: " + w)
            for w in s["wrong_exact"]:
                print("  exact contradicts: " + w)
            for w in s["indecisive"]:
                print("  not decisive: " + w)
            for w in s["unlisted"]:
                print("  unlisted pair flagged: " + w)
        if "freecad" in reports:
            fr, fw = score_freecad(reports["freecad"], expected)
            row["freecad"] = {"right": fr, "wrong": fw, "pairs": len(reports["freecad"]["pairs"])}
            print("freecad: %d/%d right, %d pairs checked" % (fr, row["relations"], len(reports["freecad"]["pairs"])))
            for w in fw:
                print("  freecad: " + w)
            slow = sorted(reports["freecad"]["pairs"], key=lambda p: -p["seconds"])[:3]
            print("  slowest FreeCAD pairs: " + ", ".join("%s/%s %.2f s" % (leaf(p["a"]), leaf(p["b"]), p["seconds"])
                                                     for p in slow))
        else:
            row["freecad"] = None
        if reports.get("asm-cold"):
            slow = sorted(reports["asm-cold"]["pairs"], key=lambda p: -((p.get("exact") or {}).get("seconds") or 0))[:3]
            print("  slowest pdcheck exact checks: " + ", ".join(
                "%s/%s %.2f s" % (leaf(p["a"]), leaf(p["b"]), (p.get("exact") or {}).get("seconds") or 0) for p in slow))
        rows.append(row)
        sys.stdout.flush()
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({"pdcheck": a.pdcheck, "runs": a.runs, "jobs": a.jobs, "cpus": cpus, "mechanisms": rows}, f,
                  indent=1)
    print_tables(rows, a)


def print_tables(rows, a):
    def cell(r, mode, fn):
        s = r.get(mode)
        return "err" if s is None else fn(s)

    print("\n| mechanism | parts | faces | relations | right: assembly | right: part files | undecided "
          "| decisive: assembly | decisive: part files | exact wrong | FreeCAD right |")
    print("|---|" + "---:|" * 10)
    tot = {"parts": 0, "faces": 0, "relations": 0}
    agg = {k: [0, 0] for k in ("ra", "rp", "da", "dp")}
    und = wrong = fcr = 0
    for r in rows:
        for k in tot:
            tot[k] += r[k]
        ok = all(r.get(m) for m in MODES[:2])
        if ok:
            agg["ra"][0] += r["asm-cold"]["right"]
            agg["rp"][0] += r["parts-cold"]["right"]
            agg["da"][0] += r["asm-cold"]["decisive"]
            agg["da"][1] += r["asm-cold"]["findings"]
            agg["dp"][0] += r["parts-cold"]["decisive"]
            agg["dp"][1] += r["parts-cold"]["findings"]
            und += r["asm-cold"]["undecided"] + r["parts-cold"]["undecided"]
            wrong += len(r["asm-cold"]["wrong_exact"]) + len(r["parts-cold"]["wrong_exact"])
        fcr += r["freecad"]["right"] if r.get("freecad") else 0
        print("| %s | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            r["name"], r["parts"], r["faces"], r["relations"],
            cell(r, "asm-cold", lambda s: "%d" % s["right"]), cell(r, "parts-cold", lambda s: "%d" % s["right"]),
            "err" if not ok else "%d" % (r["asm-cold"]["undecided"] + r["parts-cold"]["undecided"]),
            cell(r, "asm-cold", lambda s: "%d/%d" % (s["decisive"], s["findings"])),
            cell(r, "parts-cold", lambda s: "%d/%d" % (s["decisive"], s["findings"])),
            "err" if not ok else "%d" % (len(r["asm-cold"]["wrong_exact"]) + len(r["parts-cold"]["wrong_exact"])),
            cell(r, "freecad", lambda s: "%d" % s["right"])))
    if rows:
        pct = lambda x: "%d/%d (%.0f %%)" % (x[0], x[1], 100.0 * x[0] / x[1]) if x[1] else "-"
        print("| **all** | %d | %d | %d | %d | %d | %d | %s | %s | %d | %d |" % (
            tot["parts"], tot["faces"], tot["relations"], agg["ra"][0], agg["rp"][0], und, pct(agg["da"]),
            pct(agg["dp"]), wrong, fcr))

    print("\n| mechanism | pdcheck assembly, cold s | part files, cold s | assembly, cached s "
          "| part files, cached s | FreeCAD process s | FreeCAD pair loop s | pdcheck / FreeCAD "
          "(assembly, cold) |")
    print("|---|" + "---:|" * 7)
    sums = {m: 0.0 for m in MODES}
    loop = 0.0
    for r in rows:
        m = r["median_seconds"]
        for k in MODES:
            sums[k] += m[k] or 0.0
        loop += r["freecad_check_seconds"] or 0.0
        ratio = m["asm-cold"] / m["freecad"] if m["asm-cold"] and m["freecad"] else None
        print("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["name"], fmt_s(m["asm-cold"]), fmt_s(m["parts-cold"]), fmt_s(m["asm-cached"]), fmt_s(m["parts-cached"]),
            fmt_s(m["freecad"]), fmt_s(r["freecad_check_seconds"]), "-" if ratio is None else "%.2f" % ratio))
    if rows:
        print("| **all** | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
            sums["asm-cold"], sums["parts-cold"], sums["asm-cached"], sums["parts-cached"], sums["freecad"], loop,
            sums["asm-cold"] / sums["freecad"] if sums["freecad"] else 0.0))
    print("\nmedians of %d runs, pdcheck --jobs %d; wall seconds of whole processes (FreeCAD's pair loop: "
          "its own timer); ratio of the totals in the last row" % (a.runs, a.jobs))


if __name__ == "__main__":
    main()
