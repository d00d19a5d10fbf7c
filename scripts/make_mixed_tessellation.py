#!/usr/bin/env python3
"""A small assembly mixing coarse and fine tessellations, rendered by a CAD kernel (OpenSCAD), for
`tolerance: auto` (issue 27): no single fixed tolerance classifies all of its nominal relations.

usage: make_mixed_tessellation.py OUTDIR [--openscad PATH]

Writes OUTDIR/*.stl (binary float32, the assembly moved to x = 30,000 mm as an exporter in plant
coordinates would), OUTDIR/scene.json ("tolerance": "auto") and OUTDIR/expected.json
({"pairs": [{"a", "b", "expect", "note"}]}). Renders are cached in OUTDIR/.render-cache
(scripts/make_cad_assemblies.py's renderer and STL writer).

Nominal relations, by construction of the exact solids:
  bushing/pin     contact: a 24-segment pin of radius 20 in a 32-segment bore of radius 20. The
                  bore's chords cut up to 20 (1 - cos(pi/32)) = 0.096 mm into the hole, so the
                  meshes overlap by up to that (about 0.085 mm where a pin vertex meets a chord).
  pin/base        contact: the pin's end face on the base's top face (flat, no sag).
  sleeve/shaft    interference: a 128-segment shaft of radius 5.05 in a 128-segment bore of
                  radius 5: a genuine 0.05 mm overlap, below the coarse fit's artefact.
  collar/dowel    contact: a 96-segment dowel of radius 5 in a 128-segment bore of radius 5
                  (sag 0.0015 mm).
A fixed tolerance that passes the coarse fit (>= 0.085) hides the 0.05 mm interference; one that
catches it (< 0.05) flags the coarse fit.
"""
import argparse
import importlib.util
import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("cad", os.path.join(HERE, "make_cad_assemblies.py"))
cad = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cad)

OFFSET = (3000.0, 0.0, 0.0)

PARTS = {
    "bushing": "difference(){cylinder(r=30,h=20,$fn=32);"
               "translate([0,0,-1])cylinder(r=20,h=22,$fn=32);}",
    "pin": "translate([0,0,-10])cylinder(r=20,h=40,$fn=24);",
    "base": "translate([-60,-60,-30])cube([120,120,20]);",
    "sleeve": "translate([200,0,0])difference(){cylinder(r=8,h=20,$fn=128);"
              "translate([0,0,-1])cylinder(r=5,h=22,$fn=128);}",
    "shaft": "translate([200,0,-10])cylinder(r=5.05,h=40,$fn=128);",
    "collar": "translate([-200,0,0])difference(){cylinder(r=8,h=20,$fn=128);"
              "translate([0,0,-1])cylinder(r=5,h=22,$fn=128);}",
    "dowel": "translate([-200,0,-10])cylinder(r=5,h=40,$fn=96);",
}

EXPECTED = [
    {"a": "bushing", "b": "pin", "expect": "contact",
     "note": "24-segment pin in a 32-segment bore, r 20: bore sag 0.096 mm"},
    {"a": "pin", "b": "base", "expect": "contact", "note": "end face on a flat face"},
    {"a": "sleeve", "b": "shaft", "expect": "interference",
     "note": "128-segment shaft r 5.05 in a 128-segment bore r 5: 0.05 mm overlap"},
    {"a": "collar", "b": "dowel", "expect": "contact",
     "note": "96-segment dowel in a 128-segment bore, r 5: bore sag 0.0015 mm"},
]


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
    parts = []
    for name, src in PARTS.items():
        tris = cad.render(src, cache, a.openscad, version)
        moved = [tuple(tuple(v[i] + OFFSET[i] for i in range(3)) for v in t) for t in tris]
        cad.write_stl(os.path.join(a.outdir, name + ".stl"), moved, "pdcheck mixed " + name)
        parts.append({"id": name, "mesh": name + ".stl"})
    with open(os.path.join(a.outdir, "scene.json"), "w") as f:
        json.dump({"version": 1, "units": "mm", "tolerance": "auto", "parts": parts}, f, indent=1)
    with open(os.path.join(a.outdir, "expected.json"), "w") as f:
        json.dump({"pairs": EXPECTED}, f, indent=1)


if __name__ == "__main__":
    main()
