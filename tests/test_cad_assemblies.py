#!/usr/bin/env python3
"""The CAD-assembly generator (scripts/make_cad_assemblies.py --quick), not the solver's answers.

usage: test_cad_assemblies.py PDCHECK SOURCE_DIR BINARY_DIR

Generates the quick set into BINARY_DIR/cad_assemblies_quick (renders cached there) and checks:
every STL is a binary STL (size 84 + 50 n, header not starting with "solid") of finite float32
coordinates, every vertex at least 10,000 mm from the origin; every scene loads with
`pdcheck --pieces hull` (exit 0, 1 or 3, a report that parses, no part errors); expected.json
names parts of the scene, has the scene's tolerance and lists every pair the hull run flags, and
every listed interference is flagged by the hull run (the hull overlap contains the parts').
Exits 77 (skipped) when openscad is not installed.
"""
import json
import math
import os
import shutil
import struct
import subprocess
import sys

SKIP = 77
failures = []


def check(ok, what):
    if not ok:
        print("FAIL " + what)
        failures.append(what)
    return ok


def check_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    if not check(len(data) >= 84 and not data.startswith(b"solid"), "%s: binary STL header" % path):
        return 0
    n = struct.unpack_from("<I", data, 80)[0]
    if not check(n > 0 and len(data) == 84 + 50 * n, "%s: size is 84 + 50 x %d" % (path, n)):
        return 0
    nearest = math.inf
    for i in range(n):
        v = struct.unpack_from("<9f", data, 84 + 50 * i + 12)
        if not check(all(math.isfinite(x) for x in v), "%s: finite coordinates" % path):
            return n
        for k in (0, 3, 6):
            nearest = min(nearest, math.sqrt(v[k] ** 2 + v[k + 1] ** 2 + v[k + 2] ** 2))
    check(nearest >= 10000.0, "%s: far from the origin (nearest vertex %.1f mm)" % (path, nearest))
    return n


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    pdcheck, src, build = sys.argv[1:]
    if not shutil.which("openscad"):
        print("openscad not installed: skipped")
        return SKIP
    out = os.path.join(build, "cad_assemblies_quick")
    gen = subprocess.run([sys.executable, os.path.join(src, "scripts", "make_cad_assemblies.py"), out,
                          "--quick"], capture_output=True, text=True)
    if not check(gen.returncode == 0, "generator exit 0 (got %d: %s)" % (gen.returncode, gen.stderr[-2000:])):
        return 1
    names = [x["name"] for x in json.load(open(os.path.join(out, "index.json")))["assemblies"]]
    check(len(names) >= 2, "at least two quick assemblies")
    for name in names:
        d = os.path.join(out, name)
        scene = json.load(open(os.path.join(d, "scene.json")))
        exp = json.load(open(os.path.join(d, "expected.json")))
        ids = [p["id"] for p in scene["parts"]]
        check(exp["tolerance"] == scene["tolerance"], "%s: expected tolerance = scene tolerance" % name)
        for p in scene["parts"]:
            tris = check_stl(os.path.join(d, p["mesh"]))
            check(tris == exp["parts"][p["id"]]["triangles"], "%s/%s: triangle count" % (name, p["id"]))
        check(any("transform" in p for p in scene["parts"]) and any("transform" not in p for p in scene["parts"]),
              "%s: baked and transform-placed parts" % name)
        listed = {}
        for e in exp["pairs"]:
            check(e["a"] in ids and e["b"] in ids, "%s: %s/%s are scene parts" % (name, e["a"], e["b"]))
            check(e["expect"] in ("contact", "clearance", "interference"), "%s: relation %s" % (name, e["expect"]))
            listed[frozenset((e["a"], e["b"]))] = e
        run = subprocess.run([pdcheck, os.path.join(d, "scene.json"), "--pieces", "hull", "--quiet",
                              "--jobs", "1"], capture_output=True, text=True, timeout=120)
        if not check(run.returncode in (0, 1, 3), "%s: pdcheck --pieces hull exit 0/1/3 (got %d: %s)"
                     % (name, run.returncode, run.stderr[-500:])):
            continue
        try:
            rep = json.loads(run.stdout)
        except ValueError:
            check(False, "%s: the report parses" % name)
            continue
        check(rep["summary"]["part_errors"] == 0, "%s: no part errors" % name)
        flagged = {frozenset((p["a"], p["b"])): p["status"] for p in rep["pairs"]}
        for k, st in flagged.items():
            check(st == "separated" or k in listed, "%s: flagged pair %s is listed" % (name, "/".join(sorted(k))))
        for k, e in listed.items():
            if e["expect"] == "interference":
                check(flagged.get(k) == "interference", "%s: hull run flags %s/%s" % (name, e["a"], e["b"]))
        print("ok   %s: %d parts, %d relations, %d candidate pairs" % (name, len(ids), len(listed),
                                                                   len(rep["pairs"])))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
