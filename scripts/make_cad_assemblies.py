#!/usr/bin/env python3
"""Nonconvex CAD assemblies made with a real CAD kernel (OpenSCAD), written as exporters write them.

usage: make_cad_assemblies.py OUTDIR [--only NAME ...] [--quick] [--list] [--openscad PATH]

Independent test data for pair-local decisions on nonconvex parts (issue 24): hinges, a pulley on
a keyed shaft, a bearing in a bored housing, a bolted flange with multi-body bolts, an L-bracket
with a block in its corner, through-hole connectors on a drilled board, involute spur gears in
mesh, parts in a closed housing cavity. The geometry is OpenSCAD CSG (Python 3 stdlib + the
`openscad` CLI, Debian package `openscad`); nothing is shaped to a depth method.

Per assembly OUTDIR/NAME/ holds:
  *.stl          one binary STL per part (float32, 80-byte header not starting with "solid")
  scene.json     version 1, units mm, the assembly's tolerance, parts with `mesh` relative to it
  expected.json  {"assembly", "tolerance", "parts": {id: {triangles, bodies, placement, file}},
                  "pairs": [{"a", "b", "expect", "nominal_depth"?, "gap"?, "max_sag", "note"}]}
OUTDIR/.render-cache/ keeps OpenSCAD's output per CSG text (SHA-256), so a rerun, or a variant
reusing a part, renders nothing again. Triangles are written in a canonical order: the files are
the same byte for byte on every run (OpenSCAD's own order is not). OUTDIR/index.json lists the
assemblies written.

How the files are written (the habits of real exporters):
  - each part is OpenSCAD CSG in assembly coordinates, rendered with `openscad --export-format
    binstl` at the $fn a CAD user sets (32-128 for round features; coarse and fine side by side in
    several assemblies);
  - the whole assembly is turned by a rotation drawn from a generator seeded with its name
    (uniform on SO(3)) and moved far from the origin (x 20,000-35,000 mm), then stored as float32;
  - about half of the parts (chosen by the same seeded generator, at least one of each kind per
    assembly) are "baked" (the file holds world coordinates); the others are written in a frame of
    their own (another seeded rotation, also 20,000-35,000 mm from the origin, as a part exported
    in a supplier's or another assembly's coordinates) and placed by the scene's `transform`;
  - multi-body files: a bolt is its shank and its head as two closed bodies face to face (rendered
    separately, concatenated into one STL), a nut file holds the nut and its washer, one connector
    holds its housing and pins as overlapping closed bodies.

Nominal relations (expected.json), by construction of the exact solids:
  contact       the exact solids touch (faces on faces, a pin in a bore of the same diameter,
                teeth touching on the line of action): expected status separated or false_positive
  clearance     the exact solids are apart by `gap`: expected status separated
  interference  the exact solids overlap; `nominal_depth` is the overlap's thickness (the diameter
                of the largest ball inside the overlap of the exact solids; for a slab or a shell,
                its thickness): expected status interference
Every pair whose world boxes (grown by the tolerance) meet is listed. A pair that the assembly
does not state explicitly is only listed after the script has checked it apart on the rendered
meshes: no triangle box of one within 0.1 mm of a triangle box of the other, and no body of one
inside a body of the other (ray parity); otherwise the script stops, asking for the relation.

Tolerances (why each relation keeps its class after tessellation and float32):
  - Chord sag. A round feature of radius r rendered with n segments has its vertices on the
    circle and its chords inside by at most s = r (1 - cos(pi/n)). A convex feature (a pin, a
    shaft, a ball) therefore lies inside its exact solid; a concave one (a bore, a groove) has
    material up to s inside the exact hole. So in a contact the meshes overlap by at most the sum
    of the sags of the concave surfaces at the contact; in a clearance the gap shrinks by at most
    that; an interference's thickness changes by at most that. The involute flanks, tip and root
    arcs of the gears are likewise polylines with vertices on the exact curves (inside the exact
    tooth: convex flanks), so meshed teeth can only gain gap.
  - float32. World coordinates stay below 40,000 mm in magnitude, where float32 spacing is at most
    2^-8 mm: a vertex moves by at most half of it per axis, 0.0034 mm in 3-D, 0.0068 mm between the
    two parts of a pair (F32_PAIR). OpenSCAD's own binary STL at assembly coordinates (< 200 mm) adds
    at most 1e-5 mm.
  - So each relation is checked here when written: contact: max_sag + F32_PAIR <= 0.75 tolerance;
    clearance: gap - max_sag - F32_PAIR >= 0.02 mm; interference: nominal_depth - max_sag - F32_PAIR
    >= 2 tolerance. The tolerances are 0.05 mm where round fits meet (the largest contact sag is
    0.022 mm: a ring r 23.5 in a seat of n = 72) or 0.1 mm (flat contacts only); the interferences
    are 0.25-1.0 mm. --quick caps every $fn at 24 and keeps only assemblies whose contacts still
    pass this check.
  - $fn: 32-128 for round features; tiny ones as exporters tessellate them by chord error (pins
    r 0.4 and a grease hole r 1.5 at 16), hexagons at 6.

The gears' nominal relations are checked in the plane here too (see gear_pair): the exact
involute profiles (sampled finely) and the rendered polylines are tested for overlap (vertex in
the other gear, the outline being star-shaped about its centre) and their smallest gap measured;
the numbers go into the relation's note.

Assemblies (--list prints them): see ASSEMBLIES at the end.
"""
import argparse
import bisect
import hashlib
import json
import math
import os
import random
import shutil
import struct
import subprocess
import sys
import tempfile

F32_PAIR = 0.0068  # float32 rounding between two parts at |coordinates| < 40,000 mm (see above)
QUICK_FN = 24
QUICK = ("hinge_fit", "l_bracket_pushed", "cavity_housing")


# ---------------------------------------------------------------------------------------------
# Assemblies: parts (OpenSCAD bodies in assembly coordinates) and nominal relations

class Part:
    def __init__(self, pid, *bodies):
        self.id = pid
        self.bodies = list(bodies)  # OpenSCAD source, one closed body each


class Ctx:
    """$fn and chord sag of the round features. `fine` multiplies every $fn (1: the assemblies as
    documented; scripts/make_scale_assembly.py renders them finer); the sags follow it."""

    def __init__(self, quick, fine=1):
        self.quick = quick
        self.fine = fine

    def fn(self, n):
        return min(n, QUICK_FN) if self.quick else n * self.fine

    def fx(self, n):
        """A $fn that --quick leaves as it is (its sag is taken at fn(n), an upper bound)."""
        return n * self.fine

    def sag(self, r, n):
        return r * (1.0 - math.cos(math.pi / self.fn(n)))


def rel(a, b, expect, note, max_sag=0.0, depth=None, gap=None):
    r = {"a": a, "b": b, "expect": expect}
    if depth is not None:
        r["nominal_depth"] = depth
    if gap is not None:
        r["gap"] = gap
    r["max_sag"] = round(max_sag, 5)
    r["note"] = note
    return r


def contact(a, b, note, max_sag=0.0):
    return rel(a, b, "contact", note, max_sag)


def clearance(a, b, gap, note, max_sag=0.0):
    return rel(a, b, "clearance", note, max_sag, gap=gap)


def interference(a, b, depth, note, max_sag=0.0):
    return rel(a, b, "interference", note, max_sag, depth=depth)


def cyl(r, h, fn, z0=0.0):
    return "translate([0,0,%r]) cylinder(r=%r, h=%r, $fn=%d);" % (z0, r, h, fn)


# --- hinge ------------------------------------------------------------------------------------
# Pin along z through five knuckles (leaf A: 1, 3, 5; leaf B: 2, 4), a 1 mm washer between
# neighbouring knuckles. Knuckle radius 6, bore radius 3; each leaf is cut back to radius 6.5
# where the other leaf's knuckles and the washers turn (0.5 mm radial clearance between leaves).

KN_A = [(0.0, 11.0), (24.0, 35.0), (48.0, 59.0)]
KN_B = [(12.0, 23.0), (36.0, 47.0)]
WASHERS = [(11.0, 12.0), (23.0, 24.0), (35.0, 36.0), (47.0, 48.0)]


def hinge_leaf(ctx, side, fn):
    own = KN_A if side > 0 else KN_B
    cuts = [(11.0, 24.0), (35.0, 48.0)] if side > 0 else [(-1.0, 12.0), (23.0, 36.0), (47.0, 60.0)]
    plate_x = -40.0 if side > 0 else 0.0
    holes = "".join("translate([%r,0,%r]) rotate([90,0,0]) cylinder(r=2.25, h=10, center=true, "
                    "$fn=%d);" % (-26.0 * side, z, ctx.fn(32)) for z in (8.0, 29.5, 51.0))
    return ("difference(){ union(){ translate([%r,-1.5,0]) cube([40,3,59]); %s }\n %s\n %s\n %s }"
            % (plate_x, "".join(cyl(6.0, z1 - z0, ctx.fn(fn), z0) for z0, z1 in own),
               "".join(cyl(6.5, z1 - z0, ctx.fn(fn), z0) for z0, z1 in cuts),
               cyl(3.0, 61.0, ctx.fn(fn), -1.0), holes))


def washer(ctx, z0, t, fn=48):
    return "difference(){ %s %s }" % (cyl(6.0, t, ctx.fn(fn), z0), cyl(3.4, t + 2.0, ctx.fn(fn), z0 - 1.0))


def hinge(ctx, name):
    pin_r = {"hinge_clearance": 2.9, "hinge_oversize_pin": 3.25}.get(name, 3.0)
    thick = 0.3 if name == "hinge_thick_washer" else 0.0
    fk, fp = 64, 96  # knuckles coarser than the pin: the bore's chords cut into the pin
    parts = [Part("leaf_a", hinge_leaf(ctx, 1, fk)), Part("leaf_b", hinge_leaf(ctx, -1, fk)),
             Part("pin", "union(){ %s %s }" % (cyl(pin_r, 59.0, ctx.fn(fp)),
                                                 cyl(5.0, 2.0, ctx.fn(fp), 59.0)))]
    for i, (z0, z1) in enumerate(WASHERS):
        parts.append(Part("washer_%d" % (i + 1), washer(ctx, z0, z1 - z0 + (thick if i == 1 else 0.0))))
    bore = ctx.sag(3.0, fk)
    rels = []
    head = "; its head (r 5) rests on knuckle 5's end face (z 59)"
    if pin_r == 3.0:
        rels += [contact("pin", "leaf_a", "exact fit: pin r 3 in bores r 3 (pin $fn %d, bores $fn %d)"
                         % (ctx.fn(fp), ctx.fn(fk)) + head, bore),
                 contact("pin", "leaf_b", "exact fit: pin r 3 in knuckles 2 and 4 (bores r 3)", bore)]
    elif pin_r < 3.0:
        rels += [contact("pin", "leaf_a", "clearance fit (pin r 2.9 in bores r 3)" + head, bore),
                 clearance("pin", "leaf_b", 0.1, "clearance fit: pin r 2.9 in bores r 3", bore)]
    else:
        d = pin_r - 3.0
        rels += [interference("pin", "leaf_a", d, "oversize pin r 3.25 in bores r 3: a shell 0.25 thick",
                              bore),
                 interference("pin", "leaf_b", d, "oversize pin r 3.25 in bores r 3: a shell 0.25 thick",
                              bore)]
    rels.append(clearance("leaf_a", "leaf_b", 0.5, "knuckles r 6 turn in the other leaf's r 6.5 cut-outs;"
                          " 1 mm washer gaps between knuckle ends"))
    for i, (z0, z1) in enumerate(WASHERS):
        w = "washer_%d" % (i + 1)
        rels.append(clearance("pin", w, 3.4 - pin_r, "washer bore r 3.4 around the pin r %g" % pin_r,
                              ctx.sag(3.4, 48)))
        below, above = ("leaf_a", "leaf_b") if i % 2 == 0 else ("leaf_b", "leaf_a")
        rels.append(contact(w, below, "washer face on the knuckle end below (z %g)" % z0))
        if thick and i == 1:
            rels.append(interference(w, above, thick, "washer 0.3 mm too thick: an annular slab 0.3 "
                                     "thick (radial width 2.6) in knuckle 3"))
        else:
            rels.append(contact(w, above, "washer face on the knuckle end above (z %g)" % z1))
    desc = {"hinge_fit": "hinge, pin r 3 in bores r 3 (exact fit)",
            "hinge_clearance": "hinge, pin r 2.9 in bores r 3 (clearance fit 0.1)",
            "hinge_thick_washer": "hinge, exact fit, one washer 0.3 mm too thick (interference)",
            "hinge_oversize_pin": "hinge, oversize pin r 3.25 in bores r 3 (interference 0.25)"}[name]
    return desc, 0.05, parts, rels


# --- pulley on a keyed shaft, two pillow-block housings ---------------------------------------

def pulley_shaft(ctx, name):
    fs, fpul, fh = 96, 128, 48
    shaft = ("difference(){ %s translate([-3,6.5,5]) cube([6,5,30]); }" % cyl(10.0, 200.0, ctx.fn(fs), -60.0))
    profile = [(10, 0), (22, 0), (22, 14), (50, 14), (50, 5), (60, 5), (60, 12), (54, 17), (54, 23),
               (60, 28), (60, 35), (50, 35), (50, 26), (22, 26), (22, 40), (10, 40)]
    pulley = ("difference(){ rotate_extrude($fn=%d) polygon(%s);\n"
              " translate([-3,0,-1]) cube([6,12.8,42]);\n"  # keyway, 2.8 deep beyond the bore
              " translate([0,0,33]) rotate([-90,0,0]) cylinder(r=2.5, h=30, $fn=%d);\n"  # set screw
              " for (a=[0:72:359]) rotate([0,0,a+36]) translate([36,0,10]) cylinder(r=8, h=20, $fn=%d);"
              " }" % (ctx.fn(fpul), json.dumps(profile), ctx.fn(32), ctx.fn(48)))
    key = "translate([-3,6.5,5]) cube([6,6,30]);"
    screw = "translate([0,12.5,33]) rotate([-90,0,0]) cylinder(r=2.5, h=8.5, $fn=%d);" % ctx.fn(32)

    def housing(z0, bore):
        return ("difference(){ union(){ translate([-45,-25,%r]) cube([90,12,30]);"
                " translate([-22,-25,%r]) cube([44,25,30]); translate([0,0,%r]) cylinder(r=22, h=30, $fn=%d); }\n"
                " translate([0,0,%r]) cylinder(r=%r, h=32, $fn=%d);\n"
                " for (x=[-34,34]) translate([x,-30,%r]) rotate([-90,0,0]) cylinder(r=4.5, h=20, $fn=%d);\n"
                " translate([0,0,%r]) rotate([-90,0,0]) cylinder(r=1.5, h=30, $fn=%d); }"
                % (z0, z0, z0, ctx.fn(fh), z0 - 1.0, bore, ctx.fn(fh), z0 + 15.0, ctx.fn(32),
                   z0 + 15.0, ctx.fn(16)))
    parts = [Part("shaft", shaft), Part("pulley", pulley), Part("key", key), Part("set_screw", screw),
             Part("housing_fixed", housing(60.0, 10.0)), Part("housing_float", housing(100.0, 10.15))]
    rels = [contact("shaft", "pulley", "exact fit: shaft r 10 ($fn %d) in the hub bore r 10 ($fn %d)"
                    % (ctx.fn(fs), ctx.fn(fpul)), ctx.sag(10.0, fpul)),
            contact("shaft", "key", "key 6x6x30 seated in the shaft's keyseat (bottom, sides, ends)"),
            contact("key", "pulley", "key sides on the hub keyway sides; 0.3 mm gap over its top"),
            contact("set_screw", "key", "set screw end face on the key's top face"),
            contact("set_screw", "pulley", "set screw r 2.5 in its hole r 2.5", ctx.sag(2.5, 32)),
            contact("shaft", "housing_fixed", "exact fit: shaft r 10 in the housing bore r 10 ($fn %d)"
                    % ctx.fn(fh), ctx.sag(10.0, fh)),
            clearance("shaft", "housing_float", 0.15, "shaft r 10 in the bore r 10.15", ctx.sag(10.15, fh))]
    return "shaft through a keyed pulley hub with a set screw, and in two housings", 0.05, parts, rels


# --- deep-groove ball bearing in a hollow, bored housing, on a shaft --------------------------
# 6204-like: bore 20, OD 47, width 14, 8 balls r 4 on the pitch radius 16.75. Groove radius 4.16;
# the groove centres are offset by 0.16 so that each ball touches each groove at its deepest
# point (internally tangent circles in the meridian plane; checked on samples below).

RP, RB, RG = 16.75, 4.0, 4.16


def bearing_balls_check():
    """Largest (distance to the groove's core circle - groove radius) over ball points that lie
    where the ring has material: must be <= 0 (the ball stays inside the groove's tube)."""
    worst_o = worst_i = -1e9
    co, ci = RP + RB - RG, RP - RB + RG
    for i in range(1, 120):
        th = math.pi * i / 120
        for j in range(240):
            ph = 2 * math.pi * j / 240
            x = RP + RB * math.sin(th) * math.cos(ph)
            y = RB * math.sin(th) * math.sin(ph)
            z = RB * math.cos(th)
            rho = math.hypot(x, y)
            if rho >= RP + 2.0:
                worst_o = max(worst_o, math.hypot(rho - co, z) - RG)
            if rho <= RP - 2.0:
                worst_i = max(worst_i, math.hypot(rho - ci, z) - RG)
    return worst_o, worst_i


def bearing_housing(ctx, name):
    fr, fh, fb, fs = 96, 72, 32, 64
    co, ci = RP + RB - RG, RP - RB + RG
    outer = ("rotate_extrude($fn=%d) difference(){ translate([%r,-7]) square([%r,14]);"
             " translate([%r,0]) circle(r=%r, $fn=%d); }" % (ctx.fn(fr), RP + 2.0, 23.5 - RP - 2.0, co, RG,
                                                             ctx.fx(48)))
    inner = ("rotate_extrude($fn=%d) difference(){ translate([10,-7]) square([%r,14]);"
             " translate([%r,0]) circle(r=%r, $fn=%d); }" % (ctx.fn(fr), RP - 2.0 - 10.0, ci, RG, ctx.fx(48)))
    housing = ("difference(){ translate([-40,-35,-7]) cube([80,70,27]);\n"
               " translate([0,0,-8]) cylinder(r=23.5, h=15, $fn=%d);\n"  # bearing seat, shoulder at z 7
               " translate([0,0,6]) cylinder(r=20, h=15, $fn=%d);\n"
               " rotate_extrude($fn=%d) translate([27,-3]) square([5,17]);\n"  # closed cored cavity
               " for (x=[-33,33], y=[-28,28]) translate([x,y,-8]) cylinder(r=4.5, h=30, $fn=%d); }"
               % (ctx.fn(fh), ctx.fn(fh), ctx.fn(64), ctx.fn(32)))
    parts = [Part("housing", housing), Part("outer_ring", outer), Part("inner_ring", inner),
             Part("shaft", cyl(10.0, 75.0, ctx.fn(fs), -30.0))]
    wo, wi = bearing_balls_check()
    assert wo <= 1e-9 and wi <= 1e-9, (wo, wi)
    groove_sag = ctx.sag(RG, 48)
    rels = [contact("outer_ring", "housing", "exact fit: ring OD r 23.5 ($fn %d) in the seat r 23.5 "
                    "($fn %d); its face on the shoulder (z 7)" % (ctx.fn(fr), ctx.fn(fh)),
                    ctx.sag(23.5, fh)),
            contact("inner_ring", "shaft", "exact fit: shaft r 10 ($fn %d) in the ring bore r 10 ($fn %d)"
                    % (ctx.fn(fs), ctx.fn(fr)), ctx.sag(10.0, fr)),
            clearance("shaft", "housing", 10.0, "shaft r 10 through the housing's r 20 hole",
                      ctx.sag(20.0, fh))]
    for k in range(8):
        b = "ball_%d" % (k + 1)
        a = 360.0 * k / 8 + 11.25
        parts.append(Part(b, "rotate([0,0,%r]) translate([%r,0,0]) sphere(r=%r, $fn=%d);"
                          % (a, RP, RB, ctx.fn(fb))))
        rels.append(contact(b, "outer_ring", "ball r 4 touches the groove r 4.16 at its deepest point "
                            "(sampled: ball within the groove's tube, max excess %.1e)" % wo,
                            groove_sag + ctx.sag(RP + RB, fr)))
        rels.append(contact(b, "inner_ring", "ball r 4 touches the groove r 4.16 at its deepest point "
                            "(sampled: max excess %.1e)" % wi, groove_sag + ctx.sag(RP - RB, fr)))
    return ("deep-groove ball bearing (8 balls) in a bored housing with a closed cored cavity, on a "
            "shaft", 0.05, parts, rels)


# --- bolted flange ----------------------------------------------------------------------------
# Two weld-neck flanges face to face (z 0), 6 M10 bolts on PCD 90 in 11 mm clearance holes: each
# bolt file holds two closed bodies (shank, head: face to face at z 12), each nut file a nut and
# its washer (face to face at z -14). Nut bore = shank radius (threads at nominal diameter).

def bolted_flange(ctx, name):
    fflange, fhole = 128, 32

    def flange(mirror):
        prof = [(25, 0), (60, 0), (60, 12), (33, 12), (30, 40), (25, 40)]
        return ("mirror([0,0,%d]) difference(){ rotate_extrude($fn=%d) polygon(%s);\n"
                " for (a=[0:60:359]) rotate([0,0,a]) translate([45,0,-1]) cylinder(r=5.5, h=14, $fn=%d); }"
                % (1 if mirror else 0, ctx.fn(fflange), json.dumps(prof), ctx.fn(fhole)))
    parts = [Part("flange_top", flange(False)), Part("flange_bottom", flange(True))]
    rels = [contact("flange_top", "flange_bottom", "flange faces on each other (z 0)")]
    hex_r = 16.0 / math.sqrt(3.0)
    for k in range(6):
        fb = 32 if k % 2 == 0 else 96  # coarse and fine bolts side by side
        place = "rotate([0,0,%d]) translate([45,0,0]) " % (60 * k)
        shank = place + cyl(5.0, 37.0, ctx.fn(fb), -25.0)
        head = (place + "intersection(){ translate([0,0,12]) cylinder(r=%r, h=6.4, $fn=6);"
                " translate([0,0,12]) cylinder(r1=%r, r2=%r, h=6.4, $fn=%d); }" % (hex_r, hex_r + 4.0, 7.9,
                                                                                   ctx.fn(fb)))
        wash = place + "difference(){ %s %s }" % (cyl(10.0, 2.0, ctx.fn(fb), -14.0),
                                                  cyl(5.3, 4.0, ctx.fn(fb), -15.0))
        nut = place + ("difference(){ translate([0,0,-22]) cylinder(r=%r, h=8, $fn=6); %s }"
                       % (hex_r, cyl(5.0, 10.0, ctx.fn(48), -23.0)))
        b, n = "bolt_%d" % (k + 1), "nut_%d" % (k + 1)
        parts += [Part(b, shank, head), Part(n, nut, wash)]
        rels += [contact(b, "flange_top", "two-body bolt (shank r 5, $fn %d, + hex head): head face on "
                         "the flange face (z 12); shank in an r 5.5 hole" % ctx.fn(fb)),
                 clearance(b, "flange_bottom", 0.5, "shank r 5 in the r 5.5 clearance hole",
                           ctx.sag(5.5, fhole)),
                 contact(n, "flange_bottom", "two-body nut + washer: washer face on the flange face (z -12)"),
                 contact(n, b, "nut bore r 5 ($fn %d) on the shank r 5; washer bore r 5.3" % ctx.fn(48),
                         ctx.sag(5.0, 48))]
    return "two weld-neck flanges, 6 two-body bolts (coarse/fine), 6 nut+washer files", 0.05, parts, rels


# --- L-bracket with a block in its inner corner -----------------------------------------------

def l_bracket(ctx, name):
    push = 0.5 if name == "l_bracket_pushed" else 0.0
    bracket = ("difference(){ rotate([90,0,0]) translate([0,0,-60]) linear_extrude(height=60)"
               " difference(){ union(){ square([80,6]); square([6,80]); translate([6,6]) square([3,3]); }"
               " translate([9,9]) circle(r=3, $fn=%d); }\n"
               " for (x=[50,70], y=[12,48]) translate([x,y,-1]) cylinder(r=3.3, h=8, $fn=%d);\n"
               " for (z=[50,70], y=[15,45]) translate([-1,y,z]) rotate([0,90,0]) cylinder(r=3.3, h=8, $fn=%d);\n"
               " hull(){ for (y=[20,40]) translate([-1,y,60]) rotate([0,90,0]) cylinder(r=2.5, h=8, $fn=%d); } }"
               % (ctx.fn(64), ctx.fn(48), ctx.fn(48), ctx.fn(32)))
    # block 30 x 40 x 25 in the corner (x 6, z 6), its edge there chamfered 4 mm (clears the fillet
    # r 3: the fillet reaches x + z <= 15, the chamfer starts at x + z = 16), a bore r 5 along z
    block = ("translate([%r,0,0]) difference(){ translate([6,10,6]) cube([30,40,25]);\n"
             " translate([0,9,0]) rotate([90,0,0]) translate([0,0,-42]) linear_extrude(height=42)"
             " polygon([[5,5],[11,5],[5,11]]);\n"
             " translate([21,30,0]) cylinder(r=5, h=40, $fn=%d); }" % (-push, ctx.fn(48)))
    parts = [Part("bracket", bracket), Part("block", block)]
    if push:
        rels = [interference("block", "bracket", push, "block pushed 0.5 mm into the upright leg: a slab "
                             "0.5 thick (40 x 25 face); its bottom still rests on the base leg")]
        desc = "L-bracket with a block pushed 0.5 mm into its upright leg"
    else:
        rels = [contact("block", "bracket", "block resting in the inner corner: bottom face on the base "
                        "leg, side face on the upright leg; chamfer clears the fillet by 0.7")]
        desc = "L-bracket with a block resting in its inner corner (two face contacts)"
    return desc, 0.1, parts, rels


# --- through-hole connectors on a drilled board -----------------------------------------------
# A 2x8 header (housing and 0.64 mm square pins as one body) and a 1x12 header written as 13
# closed bodies (housing, round pins r 0.4 passing through it: overlapping shells), both resting
# on a 1.6 mm board with r 0.5 holes (2.54 mm pitch) and 4 mounting holes.

def connector_board(ctx, name):
    fh = 32
    pins_a = [(5.0 + 1.27 + 2.54 * i, 8.0 + 1.27 + 2.54 * j) for i in range(8) for j in range(2)]
    pins_b = [(5.0 + 1.27 + 2.54 * i, 25.0 + 1.27) for i in range(12)]
    holes = "".join("translate([%r,%r,-3]) cylinder(r=0.5, h=5, $fn=%d);" % (x, y, ctx.fn(fh))
                    for x, y in pins_a + pins_b)
    board = ("difference(){ translate([0,0,-1.6]) cube([60,40,1.6]); %s\n"
             " for (x=[3.5,56.5], y=[3.5,36.5]) translate([x,y,-3]) cylinder(r=1.6, h=5, $fn=%d); }"
             % (holes, ctx.fn(fh)))
    conn_a = ("union(){ difference(){ translate([5,8,0]) cube([20.32,5.08,8.5]);"
              " translate([13.5,12.58,4]) cube([3.32,1,5]); }\n %s }"
              % "".join("translate([%r,%r,0]) translate([-0.32,-0.32,-3.2]) cube([0.64,0.64,14.7]);" % p
                        for p in pins_a))
    housing_b = "translate([5,25,0]) cube([30.48,2.54,8.5]);"
    pins_b_src = ["translate([%r,%r,-3.2]) cylinder(r=0.4, h=14.7, $fn=%d);" % (x, y, ctx.fn(16))
                  for x, y in pins_b]
    parts = [Part("board", board), Part("header_2x8", conn_a), Part("header_1x12", housing_b, *pins_b_src)]
    hole = ctx.sag(0.5, fh)
    rels = [contact("header_2x8", "board", "housing face on the board (z 0); 16 square pins 0.64 in r 0.5 "
                    "holes (corner gap 0.047)", hole),
            contact("header_1x12", "board", "housing face on the board (z 0); 12 round pins r 0.4 in r 0.5 "
                    "holes (gap 0.1); 13 bodies, pins overlapping the housing body", hole)]
    return "2x8 and 1x12 through-hole headers on a drilled board", 0.05, parts, rels


# --- involute spur gears ----------------------------------------------------------------------

def gear_outline(m, z, backlash, flank, phase, tip=3, root=3, alpha=20.0):
    """CCW outline of a spur gear (centre at the origin): involute flanks from max(base, root)
    circle to the tip, a radial line below the base circle, tip and root arcs; the tooth
    thickness on the pitch circle is pi m / 2 - backlash / 2. Every vertex on the exact curve."""
    a = math.radians(alpha)
    r, rb, ra, rf = m * z / 2.0, m * z / 2.0 * math.cos(a), m * z / 2.0 + m, m * z / 2.0 - 1.25 * m
    inv = lambda phi: math.tan(phi) - phi
    psi = (math.pi * m / 2.0 - backlash / 2.0) / (2.0 * r)

    def half(rho):
        return psi + inv(a) - inv(math.acos(min(1.0, rb / rho)))
    r0 = max(rb, rf)
    t0, t1 = math.sqrt(max(r0 * r0 / (rb * rb) - 1.0, 0.0)), math.sqrt(ra * ra / (rb * rb) - 1.0)
    radii = [rb * math.sqrt(1.0 + (t0 + (t1 - t0) * k / (flank - 1)) ** 2) for k in range(flank)]
    radii[0], radii[-1] = r0, ra
    pol = lambda rho, th: (rho * math.cos(th), rho * math.sin(th))
    pts = []
    for k in range(z):
        c = phase + 2.0 * math.pi * k / z
        if rf < rb:
            pts.append(pol(rf, c - half(rb)))
        pts += [pol(rho, c - half(rho)) for rho in radii]
        ht = half(ra)
        pts += [pol(ra, c - ht + 2.0 * ht * j / tip) for j in range(1, tip)]
        pts += [pol(rho, c + half(rho)) for rho in reversed(radii)]
        if rf < rb:
            pts.append(pol(rf, c + half(rb)))
        s, e = c + half(r0), c + 2.0 * math.pi / z - half(r0)
        pts += [pol(rf, s + (e - s) * j / root) for j in range(1, root)]
    return pts


class StarPolygon:
    """A polygon star-shaped about its centre, vertices in angle order: inside test by angle."""

    def __init__(self, pts, centre):
        self.c = centre
        self.pts = pts
        ang = [math.atan2(y - centre[1], x - centre[0]) for x, y in pts]
        k = min(range(len(ang)), key=lambda i: ang[i])
        self.pts = pts[k:] + pts[:k]
        self.ang = ang[k:] + ang[:k]
        assert all(self.ang[i] <= self.ang[i + 1] + 1e-12 for i in range(len(self.ang) - 1)), "not star-shaped"

    def edge_at(self, th):
        i = bisect.bisect_right(self.ang, th) - 1
        return i % len(self.pts)

    def rel(self, p):
        return (p[0] - self.c[0], p[1] - self.c[1])

    def inside(self, p):
        q = self.rel(p)
        i = self.edge_at(math.atan2(q[1], q[0]))
        a, b = self.rel(self.pts[i]), self.rel(self.pts[(i + 1) % len(self.pts)])
        cross = lambda u, v: u[0] * v[1] - u[1] * v[0]
        return cross((b[0] - a[0], b[1] - a[1]), (q[0] - a[0], q[1] - a[1])) > 0.0  # left of CCW edge

    def dist(self, p, window):
        q = self.rel(p)
        i = self.edge_at(math.atan2(q[1], q[0]))
        n = len(self.pts)
        best = 1e30
        for k in range(i - window, i + window + 1):
            a, b = self.pts[k % n], self.pts[(k + 1) % n]
            best = min(best, seg_dist(p, a, b))
        return best


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)
    t = max(0.0, min(1.0, t))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def mesh_check(g1, g2, zone_c, zone_r, window):
    """(smallest gap, deepest vertex of one outline inside the other) near the pitch point."""
    gap, pen = 1e30, 0.0
    for src, dst in ((g1, g2), (g2, g1)):
        for p in src.pts:
            if math.hypot(p[0] - zone_c[0], p[1] - zone_c[1]) > zone_r:
                continue
            d = dst.dist(p, window)
            if dst.inside(p):
                pen = max(pen, d)
            else:
                gap = min(gap, d)
    return gap, pen


def gear_pair(ctx, name):
    m, z1, z2 = 2.0, 36, 48
    backlash = 0.2 if name == "gears_backlash" else 0.0
    a = m * (z1 + z2) / 2.0  # standard centre distance: the pitch circles roll on each other
    d1 = 0.3 * 2.0 * math.pi / z1  # a generic phase; gear 2 turned so that their teeth mesh
    ph1, ph2 = d1, math.pi + math.pi / z2 - d1 * z1 / z2
    f1, f2 = 8 if ctx.quick else 10, 6 if ctx.quick else 16  # coarse and fine flanks
    o1 = gear_outline(m, z1, backlash, f1, ph1)
    o2 = [(x + a, y) for x, y in gear_outline(m, z2, backlash, f2, ph2)]
    e1 = gear_outline(m, z1, backlash, 100, ph1, tip=20, root=20)
    e2 = [(x + a, y) for x, y in gear_outline(m, z2, backlash, 100, ph2, tip=20, root=20)]
    pitch = (m * z1 / 2.0, 0.0)
    g_exact, p_exact = mesh_check(StarPolygon(e1, (0, 0)), StarPolygon(e2, (a, 0)), pitch, 4.0 * m, 260)
    g_mesh, p_mesh = mesh_check(StarPolygon(o1, (0, 0)), StarPolygon(o2, (a, 0)), pitch, 4.0 * m, 50)
    assert p_exact < 1e-6 and p_mesh < 1e-6, (p_exact, p_mesh)
    if backlash:
        want = backlash * math.cos(math.radians(20.0)) / 2.0
        assert abs(g_exact - want) < 2e-3, (g_exact, want)
    else:
        assert g_exact < 1e-3, g_exact

    def body(outline, bore, zb, h, lighten):
        holes = "".join("rotate([0,0,%d]) translate([%r,0]) circle(r=%r, $fn=%d);" % (ang, lighten[0],
                        lighten[1], ctx.fn(48)) for ang in range(0, 360, 60)) if lighten else ""
        return ("translate([0,0,%r]) linear_extrude(height=%r) difference(){ polygon(%s);"
                " circle(r=%r, $fn=%d); %s }" % (zb, h, json.dumps([[round(x, 9), round(y, 9)]
                                                                     for x, y in outline]),
                                                 bore[0], ctx.fn(bore[1]), holes))
    gear1 = body(o1, (8.0, 48), 0.0, 20.0, None)
    gear2 = "translate([%r,0,0]) " % a + body([(x - a, y) for x, y in o2], (10.0, 64), 2.0, 16.0, (29.0, 7.0))
    parts = [Part("pinion", gear1), Part("gear", gear2),
             Part("shaft_1", cyl(8.0, 80.0, ctx.fn(64), -30.0)),
             Part("shaft_2", "translate([%r,0,0]) %s" % (a, cyl(10.0, 80.0, ctx.fn(96), -30.0)))]
    how = ("m 2, z 36/48, pressure angle 20, standard centre distance 84 (pitch circles roll); tooth "
           "thickness on the pitch circle pi m/2 - %g each; in the plane near the pitch point: exact "
           "involutes (100 points per flank) gap %.2e, overlap %.1e; rendered outlines (%d/%d points per "
           "flank) gap %.4f, overlap %.1e" % (backlash / 2.0, g_exact, p_exact, f1, f2, g_mesh, p_mesh))
    if backlash:
        rels = [clearance("pinion", "gear", round(backlash * math.cos(math.radians(20.0)) / 2.0, 4),
                          "backlash 0.2 on the pitch circle: flanks 0.094 apart on both sides along the "
                          "line of action; " + how)]
        desc = "involute spur gears in mesh with 0.2 mm backlash (clearance)"
    else:
        rels = [contact("pinion", "gear", "zero backlash: both flanks touch on the lines of action; " + how)]
        desc = "involute spur gears in mesh without backlash (teeth touching)"
    rels += [contact("shaft_1", "pinion", "exact fit: shaft r 8 in the bore r 8 ($fn %d)" % ctx.fn(48),
                     ctx.sag(8.0, 48)),
             contact("shaft_2", "gear", "exact fit: shaft r 10 in the bore r 10 ($fn %d)" % ctx.fn(64),
                     ctx.sag(10.0, 64))]
    return desc, 0.05, parts, rels


# --- closed housing with parts in its cavity --------------------------------------------------

def cavity_housing(ctx, name):
    fo = 96
    housing = ("difference(){ union(){ hull(){ for (x=[6,74], y=[6,54]) translate([x,y,0]) cylinder(r=6, h=50, $fn=%d); }\n"
               " for (x=[20,60]) translate([x,30,50]) cylinder(r=8, h=8, $fn=%d);\n"
               " for (x=[-6,86], y=[10,50]) translate([x,y,0]) cylinder(r=8, h=8, $fn=%d);\n"
               " translate([-6,2,0]) cube([92,56,8]); }\n"
               " hull(){ for (x=[7,73], y=[7,53]) translate([x,y,5]) cylinder(r=2, h=40, $fn=%d); }\n"
               " for (x=[20,60]) translate([x,30,52]) cylinder(r=3, h=10, $fn=%d);\n"
               " for (x=[-6,86], y=[10,50]) translate([x,y,-1]) cylinder(r=4.5, h=10, $fn=%d); }"
               % (ctx.fn(fo), ctx.fn(64), ctx.fn(64), ctx.fn(32), ctx.fn(48), ctx.fn(48)))
    bushing = ("translate([25,30,7]) difference(){ cylinder(r=10, h=20, $fn=%d);"
               " translate([0,0,-1]) cylinder(r=5, h=22, $fn=%d); translate([-12,-1.5,16]) cube([24,3,5]); }"
               % (ctx.fn(64), ctx.fn(48)))
    post = ("translate([58,30,0]) union(){ translate([0,0,10]) cylinder(r=6, h=36, $fn=%d);"
            " translate([0,0,10]) cylinder(r=9, h=3, $fn=%d); }" % (ctx.fn(64), ctx.fn(64)))
    parts = [Part("housing", housing), Part("insert", bushing), Part("post", post)]
    rels = [clearance("insert", "housing", 2.0, "bushing wholly inside the closed cavity, >= 2 mm all "
                      "round (floor z 5 vs its base z 7)"),
            interference("post", "housing", 1.0, "post r 6 inside the cavity, its top (z 46) 1 mm into the "
                         "top wall (inner face z 45): a disc r 6, 1 thick")]
    return "closed housing (two shells) with a bushing in its cavity and a post through its top wall", \
        0.1, parts, rels


ASSEMBLIES = [(n, hinge) for n in ("hinge_fit", "hinge_clearance", "hinge_thick_washer", "hinge_oversize_pin")] + [
    ("pulley_shaft", pulley_shaft), ("bearing_housing", bearing_housing), ("bolted_flange", bolted_flange),
    ("l_bracket", l_bracket), ("l_bracket_pushed", l_bracket), ("connector_board", connector_board),
    ("gears_zero_backlash", gear_pair), ("gears_backlash", gear_pair), ("cavity_housing", cavity_housing)]


# ---------------------------------------------------------------------------------------------
# Rendering (cached) and STL

def openscad_version(exe):
    p = subprocess.run([exe, "--version"], capture_output=True, text=True)
    return (p.stdout + p.stderr).strip()


def read_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    n = struct.unpack_from("<I", data, 80)[0]
    if len(data) != 84 + 50 * n:
        sys.exit("%s: not a binary STL of %d triangles" % (path, n))
    tris = []
    for i in range(n):
        v = struct.unpack_from("<9f", data, 84 + 50 * i + 12)
        tris.append(((v[0], v[1], v[2]), (v[3], v[4], v[5]), (v[6], v[7], v[8])))
    return tris


def render(src, cache, exe, version):
    tris = read_stl(render_path(src, cache, exe, version))
    if not tris:
        sys.exit("openscad rendered an empty body:\n" + src)
    return canonical(tris)


def render_path(src, cache, exe, version):
    """The cached binary STL of `src` (rendered when missing), in OpenSCAD's triangle order."""
    key = hashlib.sha256((version + "\n" + src).encode()).hexdigest()
    out = os.path.join(cache, key + ".stl")
    if not os.path.exists(out):
        with tempfile.TemporaryDirectory() as tmp:
            scad = os.path.join(tmp, "part.scad")
            with open(scad, "w") as f:
                f.write(src + "\n")
            stl = os.path.join(tmp, "part.stl")
            p = subprocess.run([exe, "-o", stl, "--export-format", "binstl", scad],
                               capture_output=True, text=True)
            if p.returncode != 0 or not os.path.exists(stl):
                sys.exit("openscad failed on:\n%s\n%s" % (src, p.stderr[-2000:]))
            shutil.move(stl, out + ".tmp")
            os.replace(out + ".tmp", out)
    return out


def canonical(tris):
    """OpenSCAD (CGAL) writes the same triangles in a different order from run to run: each
    triangle starts at its smallest vertex (orientation kept) and the list is sorted, so that
    the files, and pdcheck's content hashes of them, are the same on every machine."""
    out = []
    for t in tris:
        k = min(range(3), key=lambda i: t[i])
        out.append((t[k], t[(k + 1) % 3], t[(k + 2) % 3]))
    return sorted(out)


def write_stl(path, tris, header):
    with open(path, "wb") as f:
        f.write(header.encode()[:80].ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for a, b, c in tris:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            ln = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write(struct.pack("<3f", *(x / ln for x in n)))
            f.write(struct.pack("<9f", *a, *b, *c))
            f.write(b"\0\0")


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


# ---------------------------------------------------------------------------------------------
# Placements

def random_rotation(rng):
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    q = (math.sqrt(1 - u1) * math.sin(2 * math.pi * u2), math.sqrt(1 - u1) * math.cos(2 * math.pi * u2),
         math.sqrt(u1) * math.sin(2 * math.pi * u3), math.sqrt(u1) * math.cos(2 * math.pi * u3))
    x, y, z, w = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def far_offset(rng):
    return [rng.uniform(20000.0, 35000.0), rng.uniform(-6000.0, 6000.0), rng.uniform(-3000.0, 3000.0)]


def apply(R, t, p):
    return tuple(R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2] + t[i] for i in range(3))


def transpose(R):
    return [[R[j][i] for j in range(3)] for i in range(3)]


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


# ---------------------------------------------------------------------------------------------
# Checks of pairs the assembly does not state (rendered meshes, assembly coordinates)

def tri_box(t):
    return (min(p[0] for p in t), min(p[1] for p in t), min(p[2] for p in t),
            max(p[0] for p in t), max(p[1] for p in t), max(p[2] for p in t))


def box_of(boxes):
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), min(b[2] for b in boxes),
            max(b[3] for b in boxes), max(b[4] for b in boxes), max(b[5] for b in boxes))


def boxes_meet(a, b, grow):
    return all(a[i] - grow <= b[i + 3] and b[i] - grow <= a[i + 3] for i in range(3))


def surfaces_apart(ta, tb, margin):
    """True when no triangle box of A comes within `margin` of a triangle box of B."""
    ba = [tri_box(t) for t in ta]
    bb = [tri_box(t) for t in tb]
    region = box_of(ba)
    rb = box_of(bb)
    lo = [max(region[i], rb[i]) - margin for i in range(3)]
    hi = [min(region[i + 3], rb[i + 3]) + margin for i in range(3)]
    if any(lo[i] > hi[i] for i in range(3)):
        return True
    ba = [b for b in ba if boxes_meet(b, lo + hi, margin)]
    bb = [b for b in bb if boxes_meet(b, lo + hi, margin)]
    if not ba or not bb:
        return True
    cell = max(max(hi[i] - lo[i] for i in range(3)) / 48.0, 0.25)
    grid = {}
    for k, b in enumerate(bb):
        c0 = [int(math.floor((b[i] - margin - lo[i]) / cell)) for i in range(3)]
        c1 = [int(math.floor((b[i + 3] + margin - lo[i]) / cell)) for i in range(3)]
        for x in range(c0[0], c1[0] + 1):
            for y in range(c0[1], c1[1] + 1):
                for z in range(c0[2], c1[2] + 1):
                    grid.setdefault((x, y, z), []).append(k)
    for b in ba:
        c0 = [int(math.floor((b[i] - lo[i]) / cell)) for i in range(3)]
        c1 = [int(math.floor((b[i + 3] - lo[i]) / cell)) for i in range(3)]
        for x in range(c0[0], c1[0] + 1):
            for y in range(c0[1], c1[1] + 1):
                for z in range(c0[2], c1[2] + 1):
                    for k in grid.get((x, y, z), ()):
                        if boxes_meet(b, bb[k], margin):
                            return False
    return True


def inside(p, tris):
    """Ray parity (one closed body): is p inside?"""
    d = (0.5773502691896258, 0.5773502691896258 + 1.3e-4, 0.5773502691896258 - 2.9e-4)
    hits = 0
    for a, b, c in tris:
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - a[i] for i in range(3)]
        h = [d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]]
        det = sum(e1[i] * h[i] for i in range(3))
        if abs(det) < 1e-14:
            continue
        s = [p[i] - a[i] for i in range(3)]
        u = sum(s[i] * h[i] for i in range(3)) / det
        if u < 0 or u > 1:
            continue
        q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]]
        v = sum(d[i] * q[i] for i in range(3)) / det
        if v < 0 or u + v > 1:
            continue
        if sum(e2[i] * q[i] for i in range(3)) / det > 0:
            hits += 1
    return hits % 2 == 1


def provably_apart(bodies_a, bodies_b, margin=0.1):
    ta = [t for b in bodies_a for t in b]
    tb = [t for b in bodies_b for t in b]
    if not surfaces_apart(ta, tb, margin):
        return False
    for src, dst in ((bodies_a, bodies_b), (bodies_b, bodies_a)):
        for body in src:
            p = body[0][0]
            if any(inside(p, d) for d in dst):
                return False
    return True


# ---------------------------------------------------------------------------------------------

def check_relations(name, tol, rels):
    """Every stated relation keeps its class after tessellation and float32 (module docstring)."""
    for r in rels:
        worst = r["max_sag"] + F32_PAIR
        if r["expect"] == "contact":
            ok = worst <= 0.75 * tol
        elif r["expect"] == "clearance":
            ok = r["gap"] - worst >= 0.02
        else:
            ok = r["nominal_depth"] - worst >= 2.0 * tol
        if not ok:
            sys.exit("%s: %s/%s %s does not keep its class at tolerance %g (sag %g)"
                     % (name, r["a"], r["b"], r["expect"], tol, r["max_sag"]))


def build(name, builder, ctx, outdir, cache, exe, version):
    desc, tol, parts, rels = builder(ctx, name)
    check_relations(name, tol, rels)
    rng = random.Random("pdcheck-cad-" + name)
    R, t = random_rotation(rng), far_offset(rng)
    d = os.path.join(outdir, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    modes = ["transform" if rng.random() < 0.45 else "baked" for _ in parts]
    if len(parts) >= 2 and len(set(modes)) == 1:
        modes[rng.randrange(len(parts))] = "baked" if modes[0] == "transform" else "transform"
    local = {}
    scene_parts, info, world_boxes = [], {}, {}
    for part, mode in zip(parts, modes):
        bodies = [render(src, cache, exe, version) for src in part.bodies]
        local[part.id] = bodies
        tris = [tr for b in bodies for tr in b]
        fname = part.id + ".stl"
        entry = {"id": part.id, "mesh": fname}
        if mode == "baked":
            ftris = [tuple(tuple(f32(x) for x in apply(R, t, p)) for p in tr) for tr in tris]
            world = [p for tr in ftris for p in tr]
        else:
            Rf, tf = random_rotation(rng), far_offset(rng)
            ftris = [tuple(tuple(f32(x) for x in apply(Rf, tf, p)) for p in tr) for tr in tris]
            M = matmul(R, transpose(Rf))  # world = M (file - tf) + t
            mt = [t[i] - sum(M[i][k] * tf[k] for k in range(3)) for i in range(3)]
            entry["transform"] = [M[0] + [mt[0]], M[1] + [mt[1]], M[2] + [mt[2]], [0.0, 0.0, 0.0, 1.0]]
            world = [apply(M, mt, p) for tr in ftris for p in tr]
        write_stl(os.path.join(d, fname), ftris, "binary STL, make_cad_assemblies %s/%s" % (name, part.id))
        scene_parts.append(entry)
        world_boxes[part.id] = (min(p[0] for p in world), min(p[1] for p in world), min(p[2] for p in world),
                                max(p[0] for p in world), max(p[1] for p in world), max(p[2] for p in world))
        info[part.id] = {"file": fname, "triangles": len(tris), "bodies": len(bodies), "placement": mode}
    stated = {frozenset((r["a"], r["b"])) for r in rels}
    ids = [p.id for p in parts]
    for r in rels:
        assert r["a"] in info and r["b"] in info, r
    auto = []
    for i, a in enumerate(ids):
        for b in ids[i + 1:]:
            if frozenset((a, b)) in stated or not boxes_meet(world_boxes[a], world_boxes[b], tol):
                continue
            if not provably_apart(local[a], local[b]):
                sys.exit("%s: %s/%s: boxes meet and the meshes are not clearly apart: state the relation"
                         % (name, a, b))
            auto.append(clearance(a, b, 0.1, "apart by construction (checked on the rendered meshes: "
                                  "surfaces >= 0.1 apart, neither inside the other); boxes meet"))
    for r in rels:
        if not boxes_meet(world_boxes[r["a"]], world_boxes[r["b"]], tol):
            r["note"] += " [boxes apart: culled]"
    scene = {"version": 1, "units": "mm", "tolerance": tol, "parts": scene_parts}
    with open(os.path.join(d, "scene.json"), "w") as f:
        f.write(json.dumps(scene, indent=1).split('"parts"')[0] + '"parts": [\n  ' +
                ",\n  ".join(json.dumps(p) for p in scene_parts) + "\n ]\n}\n")
    exp = {"assembly": name, "description": desc, "tolerance": tol, "parts": info,
           "pairs": rels + auto}
    with open(os.path.join(d, "expected.json"), "w") as f:
        json.dump(exp, f, indent=1)
        f.write("\n")
    return exp


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?")
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--quick", action="store_true", help="%s at $fn <= %d" % (", ".join(QUICK), QUICK_FN))
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--openscad", default=shutil.which("openscad") or "openscad")
    a = ap.parse_args()
    names = [n for n, _ in ASSEMBLIES]
    if a.list:
        for n in names:
            print(n + (" (quick)" if n in QUICK else ""))
        return
    if not a.outdir:
        ap.error("OUTDIR is required")
    chosen = a.only or (list(QUICK) if a.quick else names)
    for n in chosen:
        if n not in names:
            ap.error("unknown assembly %r (--list)" % n)
    if not shutil.which(a.openscad):
        sys.exit("openscad not found (Debian package openscad)")
    version = openscad_version(a.openscad)
    ctx = Ctx(a.quick)
    cache = os.path.join(a.outdir, ".render-cache")
    os.makedirs(cache, exist_ok=True)
    index = []
    for n, builder in ASSEMBLIES:
        if n not in chosen:
            continue
        exp = build(n, builder, ctx, a.outdir, cache, a.openscad, version)
        tris = [p["triangles"] for p in exp["parts"].values()]
        counts = {}
        for r in exp["pairs"]:
            counts[r["expect"]] = counts.get(r["expect"], 0) + 1
        print("%-20s %2d parts, %5d-%5d triangles, relations: %s" % (
            n, len(tris), min(tris), max(tris), ", ".join("%d %s" % (v, k) for k, v in sorted(counts.items()))),
            file=sys.stderr)
        index.append({"name": n, "description": exp["description"], "parts": len(tris),
                      "triangles": sum(tris), "max_part_triangles": max(tris), "relations": counts})
    with open(os.path.join(a.outdir, "index.json"), "w") as f:
        json.dump({"quick": a.quick, "assemblies": index}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
