#!/usr/bin/env python3
"""A FreeCAD-made STEP mechanism (scripts/make_step_assemblies.py --quick): pdcheck's relations.

usage: test_step_assemblies.py PDCHECK SOURCE_DIR BINARY_DIR

Generates the quick mechanism (pcb_board with short headers: exact, press and clearance fits, a
sunk chip, a buried part, a multi-solid header) into BINARY_DIR/step_assemblies_quick and checks
the files (STEP, one product per part file, the assembly's instances) and, from the assembly file
(in a scene and in a part list) and from the part files alike, pdcheck's answers as
scripts/bench_step_assemblies.py scores them:
every nominal relation right, no undecided pair, every finding with a decisive exact verdict,
none contradicting its relation, and exit 1 (the sunk and buried parts). Exits 77 (skipped) when
freecadcmd is not installed.
"""
import json
import os
import shutil
import subprocess
import sys

SKIP = 77
failures = []


def check(ok, what):
    if not ok:
        print("FAIL " + what)
        failures.append(what)
    return ok


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    pdcheck, src, build = sys.argv[1:]
    if not shutil.which("freecadcmd"):
        print("freecadcmd not installed: skipped")
        return SKIP
    sys.path.insert(0, os.path.join(src, "scripts"))
    import bench_step_assemblies as bench
    out = os.path.join(build, "step_assemblies_quick")
    gen = subprocess.run([sys.executable, os.path.join(src, "scripts", "make_step_assemblies.py"), out, "--quick"],
                         capture_output=True, text=True)
    if not check(gen.returncode == 0, "generator exit 0 (got %d: %s)" % (gen.returncode, gen.stderr[-2000:])):
        return 1
    names = [x["name"] for x in json.load(open(os.path.join(out, "index.json")))["mechanisms"]]
    check(len(names) == 1, "one quick mechanism")
    for name in names:
        d = os.path.join(out, name)
        exp = json.load(open(os.path.join(d, "expected.json")))
        parts = json.load(open(os.path.join(d, "scene-parts.json")))["parts"]
        check(sorted(p["id"] for p in parts) == sorted(exp["parts"]), "%s: a part file per part" % name)
        check(any("transform" in p for p in parts) and any("transform" not in p for p in parts),
              "%s: baked and transform-placed part files" % name)
        for p in parts:
            with open(os.path.join(d, p["mesh"]), "rb") as f:
                text = f.read().decode("latin-1")
            check(text.startswith("ISO-10303-21;"), "%s/%s: a STEP file" % (name, p["mesh"]))
            check(text.count("= PRODUCT(") == 1, "%s/%s: one product" % (name, p["mesh"]))
        with open(os.path.join(d, "assembly.step"), "rb") as f:
            text = f.read().decode("latin-1")
        check(text.count("NEXT_ASSEMBLY_USAGE_OCCURRENCE(") == len(parts),
              "%s: an assembly instance per part" % name)
        check(any(p["solids"] > 1 for p in exp["parts"].values()), "%s: a multi-solid part" % name)
        kinds = {e["expect"] for e in exp["pairs"]}
        check(kinds == {"contact", "clearance", "interference"}, "%s: every kind of relation" % name)
        runs = {"scene-assembly.json": ([os.path.join(d, "scene-assembly.json")], None),
                "scene-parts.json": ([os.path.join(d, "scene-parts.json")], None),
                "a part list of the assembly file": (["-", "--tolerance", str(exp["tolerance"]), "--units", "mm"],
                                                     os.path.join(d, "assembly.step") + "\n")}
        for scene, (args, stdin) in runs.items():
            run = subprocess.run([pdcheck] + args + ["--quiet", "--no-cache"], input=stdin or "", capture_output=True,
                                 text=True, timeout=120)
            if not check(run.returncode == 1, "%s %s: exit 1 (got %d: %s)" % (name, scene, run.returncode,
                                                                             run.stderr[-500:])):
                continue
            try:
                rep = json.loads(run.stdout)
            except ValueError:
                check(False, "%s %s: the report parses" % (name, scene))
                continue
            check(rep["summary"]["part_errors"] == 0, "%s %s: no part errors" % (name, scene))
            check(len(rep["parts"]) == len(parts), "%s %s: %d parts" % (name, scene, len(parts)))
            s = bench.score(rep, exp)
            n = len(exp["pairs"])
            check(s["right"] == n, "%s %s: %d/%d relations right: %s" % (name, scene, s["right"], n,
                                                                       "; ".join(s["wrong_status"])))
            check(s["undecided"] == 0, "%s %s: no undecided pair" % (name, scene))
            check(s["decisive"] == s["findings"], "%s %s: %d/%d findings decisive: %s" % (
                name, scene, s["decisive"], s["findings"], "; ".join(s["indecisive"])))
            check(not s["wrong_exact"], "%s %s: exact verdicts agree: %s" % (name, scene, "; ".join(s["wrong_exact"])))
            check(not s["unlisted"], "%s %s: no unlisted finding: %s" % (name, scene, "; ".join(s["unlisted"])))
            print("ok   %s %s: %d/%d relations right, %d/%d findings decisive" % (name, scene, s["right"], n,
                                                                               s["decisive"], s["findings"]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
