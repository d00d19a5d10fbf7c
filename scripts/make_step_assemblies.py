#!/usr/bin/env python3
"""Mechanisms written as exact STEP by FreeCAD (issue 43): one file per part and one assembly file.

usage: make_step_assemblies.py OUTDIR [--only NAME ...] [--quick] [--list] [--freecadcmd PATH]

The B-rep counterpart of scripts/make_cad_assemblies.py (same conventions, and its designs where
they carry over): real CAD-kernel solids built with FreeCAD's Part API (Open CASCADE) - boxes,
cylinders, cones, spheres, tori, revolved profiles, Booleans, fillets, and involute gear profiles
as B-spline curves extruded into free-form faces - placed by an assembly with rotations, some far
from the origin, and written as STEP AP214 by `freecadcmd` (Debian's FreeCAD 0.20; Python 3
stdlib here, this same file runs inside freecadcmd to build the solids). Nothing is shaped to
pdcheck.

Per mechanism OUTDIR/NAME/ holds:
  assembly.step        the whole mechanism, one App::Part exported with Import.export: one
                       product per part, each an instance placed by a rotation and a translation
                       (instance names = the part ids; the bolted flange nests its fasteners in a
                       sub-assembly "bolting" with a placement of its own)
  <part>.step          one file per part (one product), as a supplier's part file: about half of
                       them in the part's own frame (rotated against the mechanism) and placed by
                       the scene's `transform`, the others "baked" (the file holds the solids at
                       their place in the mechanism, far from the origin where it is)
  scene-assembly.json  version 1, units mm, the tolerance; one part: the assembly file (its id
                       is NAME, so pdcheck's part ids are NAME/<instance>, see the docs)
  scene-parts.json     one part per part file, ids = the part ids
  expected.json        {"mechanism", "description", "tolerance", "parts": {id: {file,
                       placement, solids, faces, surfaces}}, "pairs": [{"a", "b", "expect",
                       "statuses", "exact", "gap"?, "gap_is_lower_bound"?, "nominal_depth"?,
                       "allowance", "measured"?, "stated", "note"}]}
OUTDIR/index.json lists the mechanisms written. The STEP header's time stamp is fixed, so the files
are the same on every run of the same FreeCAD.

Multi-body parts: a bolt is its shank and its hex head as two solids face to face in one product,
a nut file holds the nut and its washer, a 1x12 header its housing and 12 pins as overlapping
solids.

Nominal relations (expected.json), by construction of the exact solids (as make_cad_assemblies):
  contact       the solids touch (faces on faces, a pin in a bore of the same radius, an O-ring
                in its groove, a ball in its race, gear teeth on the line of action): expected
                status separated or false_positive
  clearance     the solids are apart by `gap`: expected status separated
  interference  the solids overlap; `nominal_depth` is the overlap's thickness (the diameter of
                the largest ball inside the overlap; for a slab or a shell its thickness):
                expected status interference, or false_positive when the thickness is within the
                tolerance (the 1e-4 mm press fit)
`statuses` lists the pdcheck statuses that recover the relation and `exact` the exact verdicts
(report field exact.verdict) that agree with it: contact: touching, false_positive, or separated
at a distance within `allowance`; clearance: separated; interference: interference or, within the
tolerance, false_positive. `allowance` (mm) is how far the files may be from the design: the
B-spline flanks' fitting error and STEP's 12 significant digits (5e-12 x the coordinates' size:
about 1e-7 mm for a solid baked 30,000 mm from the origin).

Every pair whose boxes (the placed solids' Open CASCADE boxes, grown by the tolerance) meet is
listed. Each stated relation is checked here on the design solids (Open CASCADE distances
between every two solids, `measured`: contact within 1e-7 + the model error, clearance within
1e-6 + the model error of the gap, interference meeting); a pair the mechanism does not state is
a clearance whose `gap` is a lower bound (`gap_is_lower_bound`): its boxes in the mechanism's
axes apart by >= 0.1 mm (that separation the gap), or else its solids' distance >= 0.1 mm (that
distance) and neither part with a solid inside the other's (point classification); otherwise the
script stops, asking for the relation.

Tolerance 0.05 mm everywhere; pdcheck meshes at tolerance/4. --quick writes pcb_board only,
with shorter headers (the ctest).
"""
import argparse
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
JOB_ENV = "PDCHECK_STEP_ASSEMBLIES_JOB"
MARKER = "make_step_assemblies: "
QUICK = ("pcb_board",)
NAMES = ("hinge", "pulley_shaft", "bearing_housing", "bolted_flange", "gearbox", "pcb_board")
TOL = 0.05
FIXED_STAMP = "2000-01-01T00:00:00"


# ---------------------------------------------------------------------------------------------
# The driver (python3, stdlib): runs this file inside freecadcmd

def driver():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?")
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--quick", action="store_true", help="%s, shorter headers" % ", ".join(QUICK))
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--freecadcmd", default=shutil.which("freecadcmd") or "freecadcmd")
    a = ap.parse_args()
    if a.list:
        for n in NAMES:
            print(n + (" (quick)" if n in QUICK else ""))
        return 0
    if not a.outdir:
        ap.error("OUTDIR is required")
    chosen = a.only or (list(QUICK) if a.quick else list(NAMES))
    for n in chosen:
        if n not in NAMES:
            ap.error("unknown mechanism %r (--list)" % n)
    if not shutil.which(a.freecadcmd):
        sys.exit("freecadcmd not found (Debian package freecad)")
    out = os.path.abspath(a.outdir)
    os.makedirs(out, exist_ok=True)
    job = {"outdir": out, "names": chosen, "quick": a.quick}
    env = dict(os.environ, **{JOB_ENV: json.dumps(job)})
    t0 = time.monotonic()
    p = subprocess.run([a.freecadcmd, os.path.abspath(__file__)], env=env, capture_output=True,
                       text=True, errors="replace")
    lines = [ln[len(MARKER):] for ln in (p.stdout + p.stderr).splitlines() if ln.startswith(MARKER)]
    for ln in lines:
        if ln != "done":
            print(ln, file=sys.stderr)
    if p.returncode != 0 or "done" not in lines:
        tail = "\n".join((p.stdout + p.stderr).splitlines()[-40:])
        sys.exit("freecadcmd failed (exit %d):\n%s" % (p.returncode, tail))
    print("written in %.1f s" % (time.monotonic() - t0), file=sys.stderr)
    return 0


# ---------------------------------------------------------------------------------------------
# Inside freecadcmd

def say(msg):
    print(MARKER + msg, flush=True)


def freecad_job():
    import traceback
    try:
        build_all(json.loads(os.environ[JOB_ENV]))
    except BaseException as e:  # freecadcmd exits 0 on an exception: say it and exit 1
        if isinstance(e, SystemExit) and not e.code:
            os._exit(0)
        for ln in traceback.format_exc().splitlines():
            say(ln)
        os._exit(1)
    say("done")
    os._exit(0)


def build_all(job):
    global App, Part, Import, V, mca
    import FreeCAD as App  # noqa: F811
    import Part  # noqa: F811
    import Import  # noqa: F811
    V = App.Vector
    sys.path.insert(0, HERE)
    import make_cad_assemblies as mca  # noqa: F811  (its placements, gear outlines and checks)
    builders = {"hinge": hinge, "pulley_shaft": pulley_shaft, "bearing_housing": bearing_housing,
                "bolted_flange": bolted_flange, "gearbox": gearbox, "pcb_board": pcb_board}
    index = []
    for name in job["names"]:
        t0 = time.monotonic()
        exp = build(name, builders[name], job["quick"], job["outdir"])
        counts = {}
        for r in exp["pairs"]:
            counts[r["expect"]] = counts.get(r["expect"], 0) + 1
        faces = sum(p["faces"] for p in exp["parts"].values())
        say("%-16s %2d parts, %4d faces, relations: %s (%.1f s)" % (
            name, len(exp["parts"]), faces, ", ".join("%d %s" % (v, k) for k, v in sorted(counts.items())),
            time.monotonic() - t0))
        index.append({"name": name, "description": exp["description"], "parts": len(exp["parts"]),
                      "faces": faces, "relations": counts})
    with open(os.path.join(job["outdir"], "index.json"), "w") as f:
        json.dump({"quick": job["quick"], "mechanisms": index}, f, indent=1)
        f.write("\n")


# --- solids -----------------------------------------------------------------------------------

def solid_of(shape, what):
    """The one valid solid of a Boolean's result."""
    solids = shape.Solids
    if len(solids) != 1:
        raise RuntimeError("%s: %d solids" % (what, len(solids)))
    s = solids[0]
    if not s.isValid():
        raise RuntimeError("%s: not a valid solid" % what)
    return s


def cyl(r, h, z0=0.0, x=0.0, y=0.0, axis=(0, 0, 1)):
    return Part.makeCylinder(r, h, V(x, y, z0), V(*axis))


def cyl_y(r, h, x, y0, z):
    """A cylinder along +y from (x, y0, z)."""
    return Part.makeCylinder(r, h, V(x, y0, z), V(0, 1, 0))


def box(x0, y0, z0, dx, dy, dz):
    return Part.makeBox(dx, dy, dz, V(x0, y0, z0))


def revolve(profile):
    """A solid of revolution about z of a closed (rho, z) polygon."""
    pts = [V(r, 0, z) for r, z in profile]
    face = Part.Face(Part.makePolygon(pts + [pts[0]]))
    return solid_of(face.revolve(V(0, 0, 0), V(0, 0, 1), 360), "revolved profile")


def ring(r_in, r_out, z0, h):
    return cyl(r_out, h, z0).cut(cyl(r_in, h + 2.0, z0 - 1.0))


def cut_all(s, tools):
    for t in tools:
        s = s.cut(t)
    return s


def fuse_all(s, others):
    for o in others:
        s = s.fuse(o)
    return s.removeSplitter()


def vertical_edges_at(shape, pred):
    """Straight edges parallel to z whose (x, y) satisfies pred."""
    out = []
    for e in shape.Edges:
        b = e.BoundBox
        if b.XLength < 1e-9 and b.YLength < 1e-9 and b.ZLength > 1e-9 and pred(b.XMin, b.YMin):
            out.append(e)
    return out


def circle_edges(shape, radius, z):
    return [e for e in shape.Edges if isinstance(e.Curve, Part.Circle) and abs(e.Curve.Radius - radius) < 1e-9
            and abs(e.BoundBox.ZMin - z) < 1e-9 and abs(e.BoundBox.ZMax - z) < 1e-9]


def moved(shape, angle_deg=0.0, t=(0.0, 0.0, 0.0)):
    """The shape turned about z by angle_deg, then moved by t: geometry rewritten, no location."""
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    return transformed(shape, [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]], list(t))


def transformed(shape, R, t):
    m = App.Matrix(R[0][0], R[0][1], R[0][2], t[0], R[1][0], R[1][1], R[1][2], t[1],
                   R[2][0], R[2][1], R[2][2], t[2], 0.0, 0.0, 0.0, 1.0)
    out = shape.copy()
    out.transformShape(m, True)  # copy: the surfaces themselves are moved
    if not out.Placement.isIdentity():
        raise RuntimeError("transformShape left a location")
    return out


class P:
    """A part: its solids in mechanism coordinates (mm)."""

    def __init__(self, pid, *solids, group=None):
        self.id = pid
        self.solids = list(solids)
        self.group = group


def rel(a, b, expect, note, depth=None, gap=None, model_error=0.0):
    r = {"a": a, "b": b, "expect": expect}
    if depth is not None:
        r["nominal_depth"] = depth
    if gap is not None:
        r["gap"] = gap
    r["model_error"] = model_error
    r["note"] = note
    return r


def contact(a, b, note, model_error=0.0):
    return rel(a, b, "contact", note, model_error=model_error)


def clearance(a, b, gap, note, model_error=0.0):
    return rel(a, b, "clearance", note, gap=gap, model_error=model_error)


def interference(a, b, depth, note):
    return rel(a, b, "interference", note, depth=depth)


# --- hinge (make_cad_assemblies' hinge_thick_washer) ------------------------------------------
# Pin r 3 along z through five knuckles (leaf A: 1, 3, 5; leaf B: 2, 4) with bores r 3 (exact
# fit), its filleted head on knuckle 5's end face; a washer (bore 3.4, r 6) between neighbouring
# knuckles, the second 0.3 mm too thick. Each leaf is cut back to r 6.5 where the other leaf's
# knuckles and the washers turn; its plate's free corners are filleted.

KN_A = [(0.0, 11.0), (24.0, 35.0), (48.0, 59.0)]
KN_B = [(12.0, 23.0), (36.0, 47.0)]
WASHERS = [(11.0, 12.0), (23.0, 24.0), (35.0, 36.0), (47.0, 48.0)]


def hinge_leaf(side):
    own = KN_A if side > 0 else KN_B
    cuts = [(11.0, 24.0), (35.0, 48.0)] if side > 0 else [(-1.0, 12.0), (23.0, 36.0), (47.0, 60.0)]
    x0 = -40.0 if side > 0 else 0.0
    free_x = -40.0 if side > 0 else 40.0
    plate = box(x0, -1.5, 0.0, 40.0, 3.0, 59.0)
    plate = plate.makeFillet(1.0, vertical_edges_at(plate, lambda x, y: abs(x - free_x) < 1e-9))
    s = fuse_all(plate, [cyl(6.0, z1 - z0, z0) for z0, z1 in own])
    s = cut_all(s, [cyl(6.5, z1 - z0, z0) for z0, z1 in cuts] + [cyl(3.0, 61.0, -1.0)] +
                [cyl_y(2.25, 10.0, -26.0 * side, -5.0, z) for z in (8.0, 29.5, 51.0)])
    return solid_of(s, "hinge leaf")


def hinge(quick):
    thick = 0.3
    pin = fuse_all(cyl(3.0, 59.0), [cyl(5.0, 2.0, 59.0)])
    pin = solid_of(pin.makeFillet(0.5, circle_edges(pin, 5.0, 61.0)), "pin")
    parts = [P("leaf_a", hinge_leaf(1)), P("leaf_b", hinge_leaf(-1)), P("pin", pin)]
    for i, (z0, z1) in enumerate(WASHERS):
        parts.append(P("washer_%d" % (i + 1), solid_of(ring(3.4, 6.0, z0, z1 - z0 + (thick if i == 1 else 0.0)),
                                                        "washer")))
    rels = [contact("pin", "leaf_a", "exact fit: pin r 3 in the bores r 3 of knuckles 1, 3, 5; its head "
                    "(r 5, top edge filleted 0.5) on knuckle 5's end face (z 59)"),
            contact("pin", "leaf_b", "exact fit: pin r 3 in the bores r 3 of knuckles 2 and 4"),
            clearance("leaf_a", "leaf_b", 0.5, "knuckles r 6 turn in the other leaf's r 6.5 cut-outs; "
                      "1 mm washer gaps between knuckle ends")]
    for i, (z0, z1) in enumerate(WASHERS):
        w = "washer_%d" % (i + 1)
        rels.append(clearance("pin", w, 0.4, "washer bore r 3.4 around the pin r 3"))
        below, above = ("leaf_a", "leaf_b") if i % 2 == 0 else ("leaf_b", "leaf_a")
        rels.append(contact(w, below, "washer face on the knuckle end below (z %g)" % z0))
        if i == 1:
            rels.append(interference(w, above, thick, "washer 0.3 mm too thick: an annular slab 0.3 thick "
                                     "(r 3.4 to 6) in knuckle 3"))
        else:
            rels.append(contact(w, above, "washer face on the knuckle end above (z %g)" % z1))
    return ("hinge: pin (exact fit, filleted head) through five knuckles, four washers, one 0.3 mm too "
            "thick", parts, rels)


# --- pulley on a keyed shaft, two pillow-block housings ---------------------------------------

def pillow_block(z0, bore):
    base = box(-45.0, -25.0, z0, 90.0, 12.0, 30.0)
    base = base.makeFillet(3.0, vertical_edges_at(base, lambda x, y: abs(abs(x) - 45.0) < 1e-9))
    s = fuse_all(base, [box(-22.0, -25.0, z0, 44.0, 25.0, 30.0), cyl(22.0, 30.0, z0)])
    s = cut_all(s, [cyl(bore, 32.0, z0 - 1.0), cyl_y(4.5, 20.0, -34.0, -30.0, z0 + 15.0),
                    cyl_y(4.5, 20.0, 34.0, -30.0, z0 + 15.0), cyl_y(1.5, 30.0, 0.0, 0.0, z0 + 15.0)])
    return solid_of(s, "pillow block")


def pulley_shaft(quick):
    shaft = solid_of(cyl(10.0, 200.0, -60.0).cut(box(-3.0, 6.5, 5.0, 6.0, 5.0, 30.0)), "shaft")
    profile = [(10, 0), (22, 0), (22, 14), (50, 14), (50, 5), (60, 5), (60, 12), (54, 17), (54, 23),
               (60, 28), (60, 35), (50, 35), (50, 26), (22, 26), (22, 40), (10, 40)]
    pulley = revolve([(float(r), float(z)) for r, z in profile])
    pulley = pulley.makeFillet(1.0, circle_edges(pulley, 60.0, 5.0) + circle_edges(pulley, 60.0, 35.0))
    tools = [box(-3.0, 0.0, -1.0, 6.0, 12.8, 42.0), cyl_y(2.5, 30.0, 0.0, 0.0, 33.0)]
    for k in range(5):
        a = math.radians(72.0 * k + 36.0)
        tools.append(cyl(8.0, 20.0, 10.0, 36.0 * math.cos(a), 36.0 * math.sin(a)))
    pulley = solid_of(cut_all(pulley, tools), "pulley")
    key = box(-3.0, 6.5, 5.0, 6.0, 6.0, 30.0)
    screw = cyl_y(2.5, 8.5, 0.0, 12.5, 33.0)
    parts = [P("shaft", shaft), P("pulley", pulley), P("key", key), P("set_screw", screw),
             P("housing_fixed", pillow_block(60.0, 10.0)), P("housing_float", pillow_block(100.0, 10.1))]
    rels = [contact("shaft", "pulley", "exact fit: shaft r 10 in the hub bore r 10"),
            contact("shaft", "key", "key 6x6x30 seated in the shaft's keyseat (bottom, sides, ends)"),
            contact("key", "pulley", "key sides on the hub keyway's sides; 0.3 mm over its top"),
            contact("set_screw", "key", "set screw end face on the key's top face"),
            contact("set_screw", "pulley", "set screw r 2.5 in its hole r 2.5"),
            contact("shaft", "housing_fixed", "exact fit: shaft r 10 in the housing bore r 10"),
            clearance("shaft", "housing_float", 0.1, "clearance fit: shaft r 10 in the bore r 10.1")]
    return ("keyed shaft through a pulley (filleted rim) with a set screw, in two pillow blocks (exact "
            "fit, clearance fit 0.1)", parts, rels)


# --- deep-groove ball bearing in a bored housing, with a buried insert ------------------------
# 6204-like: bore 20, OD 47, width 14, 8 balls r 4 on the pitch radius 16.75; each race a torus
# groove r 4.16 whose core is offset 0.16 so that the ball touches it at its deepest point
# (internally tangent circles in the meridian plane; make_cad_assemblies samples it in 3-D).

def bearing_housing(quick):
    RP, RB, RG = mca.RP, mca.RB, mca.RG
    co, ci = RP + RB - RG, RP - RB + RG
    outer = solid_of(revolve([(RP + 2.0, -7.0), (23.5, -7.0), (23.5, 7.0), (RP + 2.0, 7.0)])
                     .cut(Part.makeTorus(co, RG)), "outer ring")
    inner = solid_of(revolve([(10.0, -7.0), (RP - 2.0, -7.0), (RP - 2.0, 7.0), (10.0, 7.0)])
                     .cut(Part.makeTorus(ci, RG)), "inner ring")
    block = box(-40.0, -35.0, -7.0, 80.0, 70.0, 27.0)
    block = block.makeFillet(5.0, vertical_edges_at(block, lambda x, y: True))
    housing = cut_all(block, [cyl(23.5, 15.0, -8.0), cyl(20.0, 15.0, 6.0),
                              revolve([(27.0, -3.0), (32.0, -3.0), (32.0, 14.0), (27.0, 14.0)])] +
                      [cyl(4.5, 30.0, -8.0, x, y) for x in (-33.0, 33.0) for y in (-28.0, 28.0)])
    housing = solid_of(housing, "housing")
    parts = [P("housing", housing), P("outer_ring", outer), P("inner_ring", inner),
             P("shaft", cyl(10.0, 75.0, -30.0)), P("insert", cyl(2.5, 10.0, 0.0, 36.0, 0.0))]
    wo, wi = mca.bearing_balls_check()
    assert wo <= 1e-9 and wi <= 1e-9, (wo, wi)
    rels = [contact("outer_ring", "housing", "exact fit: ring OD r 23.5 in the seat r 23.5; its face on "
                    "the shoulder (z 7)"),
            contact("inner_ring", "shaft", "exact fit: shaft r 10 in the ring bore r 10"),
            clearance("shaft", "housing", 10.0, "shaft r 10 through the housing's r 20 hole"),
            interference("insert", "housing", 5.0, "insert r 2.5 x 10 buried in the housing wall (1.5 mm "
                         "of material all round): the overlap is the insert, thickness 5")]
    for k in range(8):
        b = "ball_%d" % (k + 1)
        a = math.radians(360.0 * k / 8 + 11.25)
        parts.append(P(b, Part.makeSphere(RB, V(RP * math.cos(a), RP * math.sin(a), 0.0))))
        rels.append(contact(b, "outer_ring", "ball r 4 touches the torus groove r 4.16 at its deepest point "
                            "(sampled: ball within the groove's tube, max excess %.1e)" % wo))
        rels.append(contact(b, "inner_ring", "ball r 4 touches the torus groove r 4.16 at its deepest point "
                            "(sampled: max excess %.1e)" % wi))
    return ("deep-groove ball bearing (torus races, 8 balls) in a filleted housing with a closed cored "
            "cavity and a buried insert, on a shaft", parts, rels)


# --- bolted flange with an O-ring -------------------------------------------------------------
# Two weld-neck flanges (conical necks) face to face (z 0), an O-ring (torus r 1.5) seated in a
# rectangular groove 3 x 3 of the top flange's face: tangent to its bottom and both walls and to
# the bottom flange's face. 6 M10 bolts on PCD 90 in 11 mm holes: a bolt is two solids (shank,
# hex head chamfered by a cone) face to face at z 12; a nut file holds the nut and its washer.

def bolted_flange(quick):
    holes = [cyl(5.5, 14.0, -1.0, 45.0 * math.cos(math.radians(a)), 45.0 * math.sin(math.radians(a)))
             for a in range(0, 360, 60)]
    top = revolve([(25.0, 0.0), (60.0, 0.0), (60.0, 12.0), (33.0, 12.0), (30.0, 40.0), (25.0, 40.0)])
    top = solid_of(cut_all(top, holes + [revolve([(30.5, -1.0), (33.5, -1.0), (33.5, 3.0), (30.5, 3.0)])]),
                   "top flange")
    bottom = revolve([(25.0, 0.0), (25.0, -40.0), (30.0, -40.0), (33.0, -12.0), (60.0, -12.0), (60.0, 0.0)])
    bottom = solid_of(cut_all(bottom, [moved(h, 0.0, (0.0, 0.0, -12.0)) for h in holes]), "bottom flange")
    oring = Part.makeTorus(32.0, 1.5, V(0.0, 0.0, 1.5))
    parts = [P("flange_top", top), P("flange_bottom", bottom), P("o_ring", oring)]
    rels = [contact("flange_top", "flange_bottom", "flange faces on each other (z 0)"),
            contact("o_ring", "flange_top", "O-ring r 1.5 (torus, R 32) seated in the 3 x 3 groove: tangent "
                    "to its bottom (z 3) and both walls (r 30.5, 33.5)"),
            contact("o_ring", "flange_bottom", "O-ring tangent to the bottom flange's face (z 0)")]
    hex_r = 16.0 / math.sqrt(3.0)
    hexagon = Part.Face(Part.makePolygon([V(hex_r * math.cos(math.radians(60 * i)),
                                            hex_r * math.sin(math.radians(60 * i)), 0.0) for i in range(7)]))
    head = hexagon.extrude(V(0, 0, 6.4)).common(Part.makeCone(hex_r + 4.0, 7.9, 6.4))
    head = solid_of(moved(head, 0.0, (0.0, 0.0, 12.0)), "bolt head")
    nut = solid_of(moved(hexagon.extrude(V(0, 0, 8.0)), 0.0, (0.0, 0.0, -22.0)).cut(cyl(5.0, 10.0, -23.0)), "nut")
    washer = solid_of(ring(5.3, 10.0, -14.0, 2.0), "washer")
    for k in range(6):
        place = lambda s: moved(moved(s, 0.0, (45.0, 0.0, 0.0)), 60.0 * k)
        b, n = "bolt_%d" % (k + 1), "nut_%d" % (k + 1)
        parts += [P(b, place(cyl(5.0, 37.0, -25.0)), place(head), group="bolting"),
                  P(n, place(nut), place(washer), group="bolting")]
        rels += [contact(b, "flange_top", "two-solid bolt (shank r 5 + chamfered hex head): head face on "
                         "the flange face (z 12); shank in an r 5.5 hole"),
                 clearance(b, "flange_bottom", 0.5, "shank r 5 in the r 5.5 hole"),
                 contact(n, "flange_bottom", "two-solid nut + washer: washer face on the flange face (z -12)"),
                 contact(n, b, "nut bore r 5 on the shank r 5; washer bore r 5.3")]
    return ("two weld-neck flanges with an O-ring in a face groove, 6 two-solid bolts and 6 nut + washer "
            "files in a sub-assembly", parts, rels)


# --- two-stage gearbox: involute spur gears as B-spline flanks --------------------------------
# Shafts r 8 (at the origin) and r 10 (at x 84); m 2, z 36 / 48 at the standard centre distance
# 84 (pitch circles roll). Stage 1 (z 0 to 20): pinion 36 on shaft 1, gear 48 on shaft 2, no
# backlash (both flanks on the lines of action). Stage 2 (z 25 to 45): gear 48 on shaft 1,
# pinion 36 on shaft 2, backlash 0.2 (flanks b cos(20 deg) / 2 = 0.094 apart on both sides). Each
# flank is a B-spline interpolating the involute (roll-angle parameters); its distance from the
# involute is measured here and carried as the relation's model error.

M, ALPHA = 2.0, 20.0
FLANK_POINTS = 25


def involute_flank(z, backlash, centre_angle, sign, r0, ra):
    """B-spline through the involute flank (polar: rho, centre_angle + sign * half(rho)), from r0
    to ra, and its largest distance from the involute (sampled between the nodes)."""
    a = math.radians(ALPHA)
    r, rb = M * z / 2.0, M * z / 2.0 * math.cos(a)
    inv = lambda phi: math.tan(phi) - phi
    psi = (math.pi * M / 2.0 - backlash / 2.0) / (2.0 * r)
    half = lambda rho: psi + inv(a) - inv(math.acos(min(1.0, rb / rho)))
    t0, t1 = math.sqrt(max(r0 * r0 / (rb * rb) - 1.0, 0.0)), math.sqrt(ra * ra / (rb * rb) - 1.0)

    def point(t):
        rho = rb * math.sqrt(1.0 + t * t)
        th = centre_angle + sign * half(rho)
        return V(rho * math.cos(th), rho * math.sin(th), 0.0)
    ts = [t0 + (t1 - t0) * k / (FLANK_POINTS - 1) for k in range(FLANK_POINTS)]
    pts = [point(t) for t in ts]
    # the end radii exactly (the root arc and the tip arc start there)
    pts[0] = V(r0 * math.cos(centre_angle + sign * half(r0)), r0 * math.sin(centre_angle + sign * half(r0)), 0)
    pts[-1] = V(ra * math.cos(centre_angle + sign * half(ra)), ra * math.sin(centre_angle + sign * half(ra)), 0)
    bs = Part.BSplineCurve()
    bs.interpolate(Points=pts, Parameters=ts)
    err = 0.0
    for k in range(FLANK_POINTS - 1):
        for j in (1, 2, 3):
            p = point(ts[k] + (ts[k + 1] - ts[k]) * j / 4.0)
            err = max(err, (bs.value(bs.parameter(p)) - p).Length)
    return bs, err


def gear_solid(z, backlash, phase, bore, z0, h, lighten=None):
    a = math.radians(ALPHA)
    r, rb = M * z / 2.0, M * z / 2.0 * math.cos(a)
    ra, rf = r + M, r - 1.25 * M
    r0 = max(rb, rf)
    inv = lambda phi: math.tan(phi) - phi
    psi = (math.pi * M / 2.0 - backlash / 2.0) / (2.0 * r)
    half = lambda rho: psi + inv(a) - inv(math.acos(min(1.0, rb / rho)))
    pol = lambda rho, th: V(rho * math.cos(th), rho * math.sin(th), 0.0)
    edges, err = [], 0.0
    for k in range(z):
        c = phase + 2.0 * math.pi * k / z
        if rf < rb:
            edges.append(Part.LineSegment(pol(rf, c - half(rb)), pol(rb, c - half(rb))).toShape())
        left, e1 = involute_flank(z, backlash, c, -1.0, r0, ra)
        right, e2 = involute_flank(z, backlash, c, 1.0, r0, ra)
        err = max(err, e1, e2)
        edges.append(left.toShape())
        edges.append(Part.Arc(pol(ra, c - half(ra)), pol(ra, c), pol(ra, c + half(ra))).toShape())
        right.reverse()
        edges.append(right.toShape())
        if rf < rb:
            edges.append(Part.LineSegment(pol(rb, c + half(rb)), pol(rf, c + half(rb))).toShape())
        s, e = c + half(r0), c + 2.0 * math.pi / z - half(r0)
        edges.append(Part.Arc(pol(rf, s), pol(rf, 0.5 * (s + e)), pol(rf, e)).toShape())
    wire = Part.Wire(edges)
    if not wire.isClosed():
        raise RuntimeError("gear outline not closed")
    g = Part.Face(wire).extrude(V(0, 0, h))
    tools = [cyl(bore, h + 2.0, -1.0)]
    if lighten:
        tools += [cyl(lighten[1], h + 2.0, -1.0, lighten[0] * math.cos(math.radians(t)),
                      lighten[0] * math.sin(math.radians(t))) for t in range(0, 360, 60)]
    return solid_of(moved(cut_all(g, tools), 0.0, (0.0, 0.0, z0)), "gear z %d" % z), err


def mesh_phases(z_a, z_b, fraction, backlash):
    """Phases of gear a (at the origin) and gear b (at x = centre distance) in mesh; checked in the
    plane on make_cad_assemblies' fine polyline outlines (no overlap; the gap expected)."""
    ca = M * (z_a + z_b) / 2.0
    ph_a = fraction * 2.0 * math.pi / z_a
    ph_b = math.pi + math.pi / z_b - ph_a * z_a / z_b
    e1 = mca.gear_outline(M, z_a, backlash, 100, ph_a, tip=20, root=20)
    e2 = [(x + ca, y) for x, y in mca.gear_outline(M, z_b, backlash, 100, ph_b, tip=20, root=20)]
    gap, pen = mca.mesh_check(mca.StarPolygon(e1, (0, 0)), mca.StarPolygon(e2, (ca, 0)), (M * z_a / 2.0, 0.0),
                              4.0 * M, 260)
    assert pen < 1e-6, pen
    want = backlash * math.cos(math.radians(ALPHA)) / 2.0
    assert abs(gap - want) < 2e-3, (gap, want)
    return ph_a, ph_b, gap


def gearbox(quick):
    ca = M * (36 + 48) / 2.0
    ph1a, ph1b, g1 = mesh_phases(36, 48, 0.3, 0.0)
    ph2a, ph2b, g2 = mesh_phases(48, 36, 0.15, 0.2)
    pinion_1, e1 = gear_solid(36, 0.0, ph1a, 8.0, 0.0, 20.0)
    gear_1, e2 = gear_solid(48, 0.0, ph1b, 10.0, 0.0, 20.0, (29.0, 7.0))
    gear_2, e3 = gear_solid(48, 0.2, ph2a, 8.0, 25.0, 20.0, (29.0, 7.0))
    pinion_2, e4 = gear_solid(36, 0.2, ph2b, 10.0, 25.0, 20.0)
    gear_1, pinion_2 = moved(gear_1, 0.0, (ca, 0.0, 0.0)), moved(pinion_2, 0.0, (ca, 0.0, 0.0))
    flank = max(e1, e2, e3, e4)
    parts = [P("pinion_1", pinion_1), P("gear_1", gear_1), P("gear_2", gear_2), P("pinion_2", pinion_2),
             P("shaft_1", cyl(8.0, 60.0, -10.0)), P("shaft_2", cyl(10.0, 60.0, -10.0, ca))]
    how = ("m 2, z 36/48, pressure angle 20, centre distance 84; B-spline flanks (%d nodes) within "
           "%.1e of the involutes" % (FLANK_POINTS, flank))
    gap2 = round(0.2 * math.cos(math.radians(ALPHA)) / 2.0, 6)
    rels = [contact("pinion_1", "gear_1", "stage 1, no backlash: both flanks touch on the lines of action; "
                    + how + " (polylines in the plane: gap %.1e)" % g1, model_error=2.0 * flank),
            clearance("gear_2", "pinion_2", gap2, "stage 2, backlash 0.2 on the pitch circle: flanks "
                      "%.4f apart on both sides along the line of action; " % gap2 + how,
                      model_error=2.0 * flank),
            contact("shaft_1", "pinion_1", "exact fit: shaft r 8 in the bore r 8"),
            contact("shaft_1", "gear_2", "exact fit: shaft r 8 in the bore r 8"),
            contact("shaft_2", "gear_1", "exact fit: shaft r 10 in the bore r 10"),
            contact("shaft_2", "pinion_2", "exact fit: shaft r 10 in the bore r 10")]
    return ("two-stage spur gearbox: involute B-spline flanks in mesh without backlash (contact) and "
            "with 0.2 backlash (clearance)", parts, rels)


# --- through-hole board: headers, fitted pins, a sunk and a buried part -----------------------

def pcb_board(quick):
    n_a, n_b = (4, 6) if quick else (8, 12)
    pins_a = [(5.0 + 1.27 + 2.54 * i, 8.0 + 1.27 + 2.54 * j) for i in range(n_a) for j in range(2)]
    pins_b = [(5.0 + 1.27 + 2.54 * i, 25.0 + 1.27) for i in range(n_b)]
    loose = {"pin_exact": (45.0, 25.0, 0.5), "pin_press": (50.0, 25.0, 0.5001), "pin_clear": (55.0, 25.0, 0.4)}
    board = box(0.0, 0.0, -1.6, 60.0, 40.0, 1.6)
    board = board.makeFillet(2.0, vertical_edges_at(board, lambda x, y: True))
    tools = [cyl(0.5, 5.0, -3.0, x, y) for x, y in pins_a + pins_b]
    tools += [cyl(0.5, 5.0, -3.0, x, y) for x, y, _ in loose.values()]
    tools += [cyl(1.6, 5.0, -3.0, x, y) for x in (3.5, 56.5) for y in (3.5, 36.5)]
    board = solid_of(cut_all(board, tools), "board")
    wa = 2.54 * n_a
    housing_a = box(5.0, 8.0, 0.0, wa, 5.08, 8.5).cut(box(5.0 + wa / 2 - 1.66, 12.58, 4.0, 3.32, 1.0, 5.0))
    header_a = solid_of(fuse_all(housing_a, [box(x - 0.32, y - 0.32, -3.2, 0.64, 0.64, 14.7) for x, y in pins_a]),
                        "header 2x%d" % n_a)
    header_b = [box(5.0, 25.0, 0.0, 2.54 * n_b, 2.54, 8.5)] + [cyl(0.4, 14.7, -3.2, x, y) for x, y in pins_b]
    chip = box(36.0, 4.0, -0.3, 16.0, 10.0, 3.0)
    chip = solid_of(chip.makeFillet(0.5, [e for e in chip.Edges if abs(e.BoundBox.ZMin - 2.7) < 1e-9
                                          and abs(e.BoundBox.ZMax - 2.7) < 1e-9]), "chip")
    ha, hb = "header_2x%d" % n_a, "header_1x%d" % n_b
    parts = [P("board", board), P(ha, header_a), P(hb, *header_b), P("chip", chip),
             P("buried", box(40.0, 30.0, -1.2, 4.0, 3.0, 0.8))]
    parts += [P(k, cyl(r, 6.0, -3.0, x, y)) for k, (x, y, r) in loose.items()]
    rels = [contact(ha, "board", "housing face on the board (z 0); %d square pins 0.64 in r 0.5 holes "
                    "(corner gap 0.047)" % len(pins_a)),
            contact(hb, "board", "housing face on the board (z 0); %d round pins r 0.4 in r 0.5 holes (gap "
                    "0.1); %d solids, the pins overlapping the housing" % (n_b, n_b + 1)),
            contact("pin_exact", "board", "exact fit: pin r 0.5 in its hole r 0.5"),
            interference("pin_press", "board", 1e-4, "press fit: pin r 0.5001 in its hole r 0.5, a shell 1e-4 "
                         "thick (within the tolerance: a false positive)"),
            clearance("pin_clear", "board", 0.1, "clearance fit: pin r 0.4 in its hole r 0.5"),
            interference("chip", "board", 0.3, "chip body (top edges filleted) sunk 0.3 into the board: a slab "
                         "0.3 thick (16 x 10)"),
            interference("buried", "board", 0.8, "part 4 x 3 x 0.8 buried inside the board: the overlap is the "
                         "part, thickness 0.8")]
    return ("drilled board with two headers (one of %d overlapping solids), pins in exact, press (1e-4) and "
            "clearance (0.1) fits, a sunk chip and a buried part" % (n_b + 1), parts, rels)


# --- placement and writing --------------------------------------------------------------------
# name: (assembly turned, where its origin goes)
PLACES = {"hinge": (True, "far"), "pulley_shaft": (True, (150.25, -80.5, 40.0)),
          "bearing_housing": (False, (0.0, 0.0, 0.0)), "bolted_flange": (True, "far"),
          "gearbox": (True, "far"), "pcb_board": (True, (120.0, -40.0, 15.0))}
SUB_PLACEMENT = ([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 250.0])


def apply(R, t, p):
    return [R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2] + t[i] for i in range(3)]


def placement(R, t):
    m = App.Matrix(R[0][0], R[0][1], R[0][2], t[0], R[1][0], R[1][1], R[1][2], t[1],
                   R[2][0], R[2][1], R[2][2], t[2], 0.0, 0.0, 0.0, 1.0)
    return App.Placement(m)


def fix_stamp(path):
    with open(path, "rb") as f:
        data = f.read()
    data = re.sub(rb"(FILE_NAME\('[^']*',')[^']*'", rb"\g<1>" + FIXED_STAMP.encode() + b"'", data, count=1)
    with open(path, "wb") as f:
        f.write(data)


def export(objs, path):
    Import.export(objs, path)
    if not os.path.exists(path):
        raise RuntimeError("Import.export wrote no " + path)
    fix_stamp(path)


def solids_distance(sa, sb):
    return min(x.distToShape(y)[0] for x in sa for y in sb)


def box_gap(a, b):
    """The largest separation of two boxes along an axis (<= 0 when they meet): a lower bound on
    the distance between what they hold."""
    return max(b.XMin - a.XMax, a.XMin - b.XMax, b.YMin - a.YMax, a.YMin - b.YMax, b.ZMin - a.ZMax,
               a.ZMin - b.ZMax)


def one_inside(sa, sb):
    """Is a vertex of a solid of one strictly inside a solid of the other?"""
    for src, dst in ((sa, sb), (sb, sa)):
        for s in src:
            p = s.Vertexes[0].Point
            if any(d.isInside(p, 1e-7, False) for d in dst):
                return True
    return False


def face_kinds(solids):
    kinds = {}
    for s in solids:
        for f in s.Faces:
            k = type(f.Surface).__name__
            kinds[k] = kinds.get(k, 0) + 1
    return kinds


def build(name, builder, quick, outdir):
    desc, parts, rels = builder(quick)
    ids = [p.id for p in parts]
    assert len(set(ids)) == len(ids) and "assembly" not in ids
    by_id = {p.id: p for p in parts}
    rng = random.Random("pdcheck-step-" + name)
    turned, where = PLACES[name]
    R = mca.random_rotation(rng) if turned else [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    t = [round(x, 3) for x in mca.far_offset(rng)] if where == "far" else list(where)
    d = os.path.join(outdir, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    modes = ["transform" if rng.random() < 0.5 else "baked" for _ in parts]
    if len(set(modes)) == 1:
        modes[rng.randrange(len(parts))] = "baked" if modes[0] == "transform" else "transform"
    # each part's own frame: its solids turned about the mechanism's origin by Rf^-1
    frames = {p.id: mca.random_rotation(rng) for p in parts}
    size = max(abs(x) for x in t) + 300.0  # a bound on |coordinates| of the placed mechanism (mm)

    doc = App.newDocument("step_" + name)
    asm = doc.addObject("App::Part", "Assembly")
    asm.Label = name
    sub = None
    scene_parts, info, world_box = [], {}, {}
    for part, mode in zip(parts, modes):
        Rf = frames[part.id]
        local = [transformed(s, mca.transpose(Rf), [0.0, 0.0, 0.0]) for s in part.solids]
        shape = local[0] if len(local) == 1 else Part.Compound(local)
        W = mca.matmul(R, Rf)  # world = W local + t
        obj = doc.addObject("Part::Feature", "p_" + part.id)
        obj.Shape = shape
        obj.Label = part.id
        if part.group:
            if sub is None:
                sub = doc.addObject("App::Part", "Sub_" + part.group)
                sub.Label = part.group
                Rs, ts = SUB_PLACEMENT
                sub.Placement = placement(Rs, ts)
                asm.addObject(sub)
            Rs, ts = SUB_PLACEMENT  # the sub-assembly's placement is undone in its members'
            RsT = mca.transpose(Rs)
            obj.Placement = placement(mca.matmul(RsT, W), apply(RsT, [0.0, 0.0, 0.0],
                                                                [t[i] - ts[i] for i in range(3)]))
            sub.addObject(obj)
        else:
            obj.Placement = placement(W, t)
            asm.addObject(obj)
        # the part's own file
        pdoc = App.newDocument("part_" + part.id)
        pobj = pdoc.addObject("Part::Feature", "p_" + part.id)
        if mode == "baked":
            world = [transformed(s, W, t) for s in local]
            pobj.Shape = world[0] if len(world) == 1 else Part.Compound(world)
        else:
            pobj.Shape = shape
        pobj.Label = part.id
        fname = part.id + ".step"
        export([pobj], os.path.join(d, fname))
        App.closeDocument(pdoc.Name)
        entry = {"id": part.id, "mesh": fname}
        if mode == "transform":
            entry["transform"] = [W[0] + [t[0]], W[1] + [t[1]], W[2] + [t[2]], [0.0, 0.0, 0.0, 1.0]]
        scene_parts.append(entry)
        bb = Part.Compound([transformed(s, W, t) for s in local]).BoundBox
        world_box[part.id] = bb
        info[part.id] = {"file": fname, "placement": mode, "solids": len(part.solids),
                         "faces": sum(len(s.Faces) for s in part.solids), "surfaces": face_kinds(part.solids),
                         "group": part.group}
        if mode == "baked":
            info[part.id]["step_rounding"] = 5e-12 * size * math.sqrt(3.0)
        else:
            info[part.id]["step_rounding"] = 5e-12 * 300.0 * math.sqrt(3.0)
    doc.recompute()
    export([asm], os.path.join(d, "assembly.step"))
    App.closeDocument(doc.Name)

    # the relations: stated ones checked, every other pair whose boxes meet checked apart
    design_box = {p.id: Part.Compound(p.solids).BoundBox for p in parts}
    stated = {frozenset((r["a"], r["b"])) for r in rels}
    for r in rels:
        assert r["a"] in by_id and r["b"] in by_id, r
    auto = []
    for i, a in enumerate(ids):
        for b in ids[i + 1:]:
            if frozenset((a, b)) in stated:
                continue
            ba, bb = world_box[a], world_box[b]
            grown = App.BoundBox(ba)
            grown.enlarge(TOL)
            if not grown.intersect(bb):
                continue
            gap = box_gap(design_box[a], design_box[b])
            if gap >= 0.1:  # their boxes in the mechanism's axes are apart: a lower bound
                how = "their boxes in the mechanism's axes %.4f apart" % gap
            else:
                gap = solids_distance(by_id[a].solids, by_id[b].solids)
                if gap < 0.1 or one_inside(by_id[a].solids, by_id[b].solids):
                    raise RuntimeError("%s: %s/%s: boxes meet and the solids are %.3g apart%s: state the "
                                       "relation" % (name, a, b, gap, " (one inside)" if gap >= 0.1 else ""))
                how = "Open CASCADE distance %.4f, neither inside the other" % gap
            r = clearance(a, b, math.floor(gap * 1e4) / 1e4, "apart by construction (%s); boxes meet" % how)
            r["stated"] = False
            r["gap_is_lower_bound"] = True
            auto.append(r)
    for r in rels:
        r["stated"] = True
        dist = solids_distance(by_id[r["a"]].solids, by_id[r["b"]].solids)
        r["measured"] = dist
        slack = 1e-7 + r["model_error"]
        if r["expect"] == "contact":
            ok = dist <= slack
        elif r["expect"] == "clearance":
            ok = abs(dist - r["gap"]) <= 1e-6 + r["model_error"]
        else:
            ok = dist <= 1e-9
        if not ok:
            raise RuntimeError("%s: %s/%s %s: the design solids are %.9g apart" % (name, r["a"], r["b"],
                                                                                   r["expect"], dist))
    pairs = []
    for r in rels + auto:
        rounding = info[r["a"]]["step_rounding"] + info[r["b"]]["step_rounding"]
        r["allowance"] = float("%.3g" % (r.pop("model_error") + rounding))
        if r["expect"] == "contact":
            r["statuses"] = ["separated", "false_positive"]
            r["exact"] = ["touching", "false_positive", "separated"]
        elif r["expect"] == "clearance":
            r["statuses"] = ["separated"]
            r["exact"] = ["separated"]
        elif r["nominal_depth"] <= TOL:
            r["statuses"] = ["false_positive"]
            r["exact"] = ["false_positive"]
        else:
            r["statuses"] = ["interference"]
            r["exact"] = ["interference"]
        ba, bb = world_box[r["a"]], world_box[r["b"]]
        grown = App.BoundBox(ba)
        grown.enlarge(TOL)
        if not grown.intersect(bb):
            r["note"] += " [boxes apart: culled]"
        pairs.append({k: r[k] for k in ("a", "b", "expect", "statuses", "exact", "gap", "nominal_depth",
                                        "gap_is_lower_bound", "allowance", "measured", "stated", "note") if k in r})

    with open(os.path.join(d, "scene-assembly.json"), "w") as f:
        json.dump({"version": 1, "units": "mm", "tolerance": TOL,
                   "parts": [{"id": name, "mesh": "assembly.step"}]}, f, indent=1)
        f.write("\n")
    scene = {"version": 1, "units": "mm", "tolerance": TOL, "parts": scene_parts}
    with open(os.path.join(d, "scene-parts.json"), "w") as f:
        f.write(json.dumps(scene, indent=1).split('"parts"')[0] + '"parts": [\n  ' +
                ",\n  ".join(json.dumps(p) for p in scene_parts) + "\n ]\n}\n")
    exp = {"mechanism": name, "description": desc, "tolerance": TOL, "placement": {
        "rotation": R, "translation": t, "sub_assembly": {"bolting": SUB_PLACEMENT} if sub else None},
        "parts": info, "pairs": pairs}
    with open(os.path.join(d, "expected.json"), "w") as f:
        json.dump(exp, f, indent=1)
        f.write("\n")
    return exp


if __name__ == "__main__":
    sys.exit(driver())
elif os.environ.get(JOB_ENV):
    freecad_job()
