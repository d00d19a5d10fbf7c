#!/usr/bin/env python3
"""Seated contacts rendered by a CAD kernel (OpenSCAD), whose status must not depend on the
tolerance (issue 44): a bolt head seated on a bracket, its shank in a clearance hole, and a pin
pressed into a coarser bore (a tessellation overlap).

usage: make_seated_contacts.py OUTDIR [--openscad PATH]

Writes OUTDIR/PLACE/*.stl (binary float32) and OUTDIR/PLACE/scene.json for two placements of the
same parts: `origin` (OpenSCAD's own coordinates) and `far` (the assembly turned by a seeded
rotation and moved to x = 28,000 mm, as a plant model exports it), and OUTDIR/expected.json
({"pairs": [{"a", "b", "expect", "note"}]}). Renders are cached in OUTDIR/.render-cache
(scripts/make_cad_assemblies.py's renderer and STL writer). The scenes carry no tolerance: the
test gives it on the command line.

Nominal relations, by construction of the exact solids:
  bracket/bolt   touching: the hex head's underside (z 6) lies on the bracket's top face (z 6); the
                 shank (r 4, 48 segments) passes through an r 4.2 hole (the 8.4 mm clearance hole
                 of an M8 bolt). The meshes meet on a flat face only: no overlap but the
                 coordinates' rounding.
  bore/pin       a tessellation overlap: a 48-segment pin of r 5 in a 24-segment bore of r 5. The
                 bore's chords cut up to 5 (1 - cos(pi/24)) = 0.043 mm into the hole, so the meshes
                 overlap by a few hundredths of a millimetre: a false positive at every tolerance
                 above that, an interference below it.
  tray/lid       a clash: a 60 x 40 lid 1 mm down into an open tray's 2 mm walls, an overlap 1 mm
                 thick wherever the assembly sits.
"""
import argparse
import importlib.util
import json
import math
import os
import random
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("cad", os.path.join(HERE, "make_cad_assemblies.py"))
cad = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cad)

HEX_R = 13.0 / math.sqrt(3.0)  # 13 mm across flats

PARTS = {
    "bracket": "difference(){ translate([-20,-15,0]) cube([40,30,6]);"
               " translate([0,0,-1]) cylinder(r=4.2, h=8, $fn=48); }",
    "bolt": "union(){ translate([0,0,-14]) cylinder(r=4, h=20.5, $fn=48);"
            " translate([0,0,6]) cylinder(r=%r, h=5.3, $fn=6); }" % HEX_R,
    "bore": "translate([60,0,0]) difference(){ cylinder(r=12, h=10, $fn=48);"
            " translate([0,0,-1]) cylinder(r=5, h=12, $fn=24); }",
    "pin": "translate([60,0,-5]) cylinder(r=5, h=20, $fn=48);",
    "tray": "translate([-130,-20,0]) difference(){ cube([60,40,30]); translate([2,2,2]) cube([56,36,29]); }",
    "lid": "translate([-130,-20,29]) cube([60,40,3]);",
}

EXPECTED = [
    {"a": "bracket", "b": "bolt", "expect": "touching",
     "note": "hex head seated on the bracket's top face; shank r 4 in an r 4.2 hole"},
    {"a": "bore", "b": "pin", "expect": "overlap",
     "note": "48-segment pin r 5 in a 24-segment bore r 5: bore sag 0.043 mm"},
    {"a": "tray", "b": "lid", "expect": "clash", "depth": 1.0,
     "note": "a lid 1 mm down into an open tray's 2 mm walls: a slab 1 mm thick"},
]

FAR = (28000.0, -3000.0, 1500.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--openscad", default=shutil.which("openscad") or "openscad")
    a = ap.parse_args()
    if not shutil.which(a.openscad):
        sys.exit("openscad not found (Debian package openscad)")
    version = cad.openscad_version(a.openscad)
    cache = os.path.join(a.outdir, ".render-cache")
    os.makedirs(cache, exist_ok=True)
    R = cad.random_rotation(random.Random("pdcheck-seated-contacts"))
    placements = {"origin": lambda p: p, "far": lambda p: cad.apply(R, FAR, p)}
    for place, move in placements.items():
        d = os.path.join(a.outdir, place)
        os.makedirs(d, exist_ok=True)
        parts = []
        for name, src in PARTS.items():
            tris = cad.render(src, cache, a.openscad, version)
            moved = [tuple(move(v) for v in t) for t in tris]
            cad.write_stl(os.path.join(d, name + ".stl"), moved, "pdcheck seated " + name)
            parts.append({"id": name, "mesh": name + ".stl"})
        with open(os.path.join(d, "scene.json"), "w") as f:
            json.dump({"version": 1, "units": "mm", "parts": parts}, f, indent=1)
    with open(os.path.join(a.outdir, "expected.json"), "w") as f:
        json.dump({"placements": list(placements), "pairs": EXPECTED}, f, indent=1)


if __name__ == "__main__":
    main()
