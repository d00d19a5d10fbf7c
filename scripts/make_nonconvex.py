#!/usr/bin/env python3
"""Writes a nonconvex CAD-like assembly whose nominal relations are known by construction.

usage: make_nonconvex.py OUT_DIR [--segments 32] [--copies 1] [--tolerance 0.05] [--bench]

Float32 binary STL parts far from the origin (x ~ 20,000 mm) as CAD tools export them,
a scene OUT_DIR/scene.json and a sidecar OUT_DIR/expected.json with the nominal relation
of every pair meant to be a candidate:
  interference  a genuine overlap deeper than the tolerance  -> status interference
  contact       faces on faces (an exact fit, a part seated)  -> separated or false_positive
  clearance     apart by more than the tolerance              -> separated
Groups (each --copies times, 100 mm apart in y so groups never meet):
  plate with two bolt holes and bolts: exact fit, clearance fit (0.2 mm), interference fit (0.5 mm)
  block with a through bore and a pin in it (clearance fit)
  L-bracket with a block in its corner: touching both legs; a second with a 0.3 mm gap
  drilled board with a component seated on it, its two leads through holes (clearance)
  hollow housing (closed, two shells) with a part in its cavity
  thick L-block with a part buried in its material (containment, no surfaces meet)
  open tray (no lid: an open mesh) with a part resting inside with clearance, and a rod
  through its wall (interference)
  a 0.05 mm foil 3 mm deep into an L-bracket's leg (interference: thin, yet a clash)
--bench writes, per copy, only the groups whose parts grow with --segments (a plate with
an exact-fit and a clearance bolt, a plate with an interference-fit bolt, a two-bore block
with a pin, a drilled board with a component): 4 nonconvex parts of ~1,000-4,000 triangles
each at --segments 96 (scripts/bench_nonconvex.py).
Every pair not listed has boxes apart (not a candidate). Per part, expected.json also
gives its triangle count and whether it is convex by construction.
"""
import argparse
import json
import math
import os
import struct

X0 = 20000.0


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


class Mesh:
    def __init__(self):
        self.tris = []

    def tri(self, a, b, c):
        self.tris.append((a, b, c))

    def quad(self, a, b, c, d):  # counter-clockwise seen from outside
        self.tri(a, b, c)
        self.tri(a, c, d)

    def add(self, other):
        self.tris += other.tris
        return self

    def reversed(self):
        m = Mesh()
        m.tris = [(a, c, b) for a, b, c in self.tris]
        return m

    def moved(self, dx, dy, dz):
        m = Mesh()
        m.tris = [tuple((p[0] + dx, p[1] + dy, p[2] + dz) for p in t) for t in self.tris]
        return m

    def write(self, path):
        with open(path, "wb") as f:
            f.write(b"pdcheck make_nonconvex".ljust(80, b" "))
            f.write(struct.pack("<I", len(self.tris)))
            for t in self.tris:
                f.write(struct.pack("<3f", 0, 0, 0))
                for p in t:
                    f.write(struct.pack("<3f", *p))
                f.write(b"\0\0")


def box(lo, hi, top=True):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    m = Mesh()
    m.quad(v[0], v[2], v[3], v[1])  # bottom (-z)
    if top:
        m.quad(v[4], v[5], v[7], v[6])
    m.quad(v[0], v[1], v[5], v[4])  # -y
    m.quad(v[2], v[6], v[7], v[3])  # +y
    m.quad(v[0], v[4], v[6], v[2])  # -x
    m.quad(v[1], v[3], v[7], v[5])  # +x
    return m


def ring(cx, cy, r, n):
    return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def prism(cx, cy, r, n, z0, z1):
    """A cylinder tessellated as an n-gon prism (closed, outward)."""
    p = ring(cx, cy, r, n)
    m = Mesh()
    for k in range(n):
        a, b = p[k], p[(k + 1) % n]
        m.quad((a[0], a[1], z0), (b[0], b[1], z0), (b[0], b[1], z1), (a[0], a[1], z1))
        m.tri((cx, cy, z0), (b[0], b[1], z0), (a[0], a[1], z0))
        m.tri((cx, cy, z1), (a[0], a[1], z1), (b[0], b[1], z1))
    return m


def square_point(cx, cy, s, t):
    """Where the ray from the cell centre at angle t meets the cell's square (side s)."""
    c, d = math.cos(t), math.sin(t)
    k = (s / 2) / max(abs(c), abs(d))
    x, y = cx + k * c, cy + k * d
    # Snap the coordinate on the square exactly, so neighbouring cells share points.
    if abs(c) >= abs(d):
        x = cx + math.copysign(s / 2, c)
    if abs(d) >= abs(c):
        y = cy + math.copysign(s / 2, d)
    # Neighbouring cells compute a shared point from mirrored angles: round off the
    # last-ulp difference so the plate closes.
    return (round(x, 9), round(y, 9))


def plate_with_holes(x0, y0, s, cells, hole_r, n, z0, z1):
    """A plate of `cells` square cells (side s) in a row along x, a through hole
    (an n-gon, n divisible by 8) in the middle of each: closed, outward."""
    assert n % 8 == 0
    m = Mesh()
    xs, xe, ys, ye = x0, x0 + s * cells, y0, y0 + s
    for i in range(cells):
        cx, cy = x0 + s * (i + 0.5), y0 + s / 2
        hole = ring(cx, cy, hole_r, n)
        outer = [square_point(cx, cy, s, 2 * math.pi * k / n) for k in range(n)]
        for k in range(n):
            h0, h1 = hole[k], hole[(k + 1) % n]
            o0, o1 = outer[k], outer[(k + 1) % n]
            # top (+z) and bottom (-z) annulus
            m.quad((h0[0], h0[1], z1), (o0[0], o0[1], z1), (o1[0], o1[1], z1), (h1[0], h1[1], z1))
            m.quad((h0[0], h0[1], z0), (h1[0], h1[1], z0), (o1[0], o1[1], z0), (o0[0], o0[1], z0))
            # hole wall, facing the hole's axis
            m.quad((h0[0], h0[1], z0), (h0[0], h0[1], z1), (h1[0], h1[1], z1), (h1[0], h1[1], z0))
            # outer wall where the cell edge is the plate's edge
            on_edge = any(
                (abs(o0[j] - e) < 1e-9 and abs(o1[j] - e) < 1e-9)
                for j, e in ((0, xs), (0, xe), (1, ys), (1, ye)))
            if on_edge:
                m.quad((o0[0], o0[1], z0), (o1[0], o1[1], z0), (o1[0], o1[1], z1),
                       (o0[0], o0[1], z1))
    return m


def l_bracket(x0, y0, z0, w, h, t, depth):
    """An L profile in xz (legs along +x and +z, thickness t) extruded along y."""
    p = [(0, 0), (w, 0), (w, t), (t, t), (t, h), (0, h)]
    p = [(x0 + a, z0 + b) for a, b in p]
    y1 = y0 + depth
    m = Mesh()
    fan = [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5)]
    for a, b, c in fan:  # y0 face looks -y: clockwise in xz seen from -y
        m.tri((p[a][0], y0, p[a][1]), (p[b][0], y0, p[b][1]), (p[c][0], y0, p[c][1]))
        m.tri((p[a][0], y1, p[a][1]), (p[c][0], y1, p[c][1]), (p[b][0], y1, p[b][1]))
    for k in range(6):
        a, b = p[k], p[(k + 1) % 6]
        m.quad((a[0], y0, a[1]), (a[0], y1, a[1]), (b[0], y1, b[1]), (b[0], y0, b[1]))
    return m


def f32_mesh(m):
    out = Mesh()
    out.tris = [tuple(tuple(f32(X0 + c if i == 0 else c) for i, c in enumerate(p)) for p in t)
                for t in m.tris]
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("--segments", type=int, default=32, help="n of every n-gon (a multiple of 8)")
    ap.add_argument("--copies", type=int, default=1)
    ap.add_argument("--tolerance", type=float, default=0.05)
    ap.add_argument("--bench", action="store_true", help="only the groups that scale (see above)")
    a = ap.parse_args()
    n = a.segments
    os.makedirs(a.out_dir, exist_ok=True)
    parts, pairs, info = [], [], {}

    def part(name, mesh, convex):
        m = f32_mesh(mesh)
        m.write(os.path.join(a.out_dir, name + ".stl"))
        parts.append({"id": name, "mesh": name + ".stl"})
        info[name] = {"triangles": len(m.tris), "convex": convex}

    def rel(x, y, what, why):
        pairs.append({"a": x, "b": y, "expect": what, "why": why})

    # Groups both assemblies hold; `holes` is how many holes the second plate and
    # the block have (the bench's parts are larger). Each returns the next row's y.
    def bolted_plates(g, y, holes):
        # plate with two holes (r 5): exact-fit bolt, clearance bolt; a second
        # plate with an interference-fit bolt.
        part(g + "plate", plate_with_holes(0, y, 20, 2, 5.0, n, 0, 4), False)
        part(g + "bolt_exact", prism(10, y + 10, 5.0, n, -6, 10), True)
        part(g + "bolt_clear", prism(30, y + 10, 4.8, n, -6, 10), True)
        rel(g + "plate", g + "bolt_exact", "contact", "exact fit: bolt faces on the hole's")
        rel(g + "plate", g + "bolt_clear", "clearance", "0.2 mm radial clearance")
        y += 100
        part(g + "plate2", plate_with_holes(0, y, 20, holes, 5.0, n, 0, 4), False)
        part(g + "bolt_tight", prism(10, y + 10, 5.5, n, -6, 10), True)
        rel(g + "plate2", g + "bolt_tight", "interference", "0.5 mm interference fit")
        return y + 100

    def pin_in_block(g, y, holes):
        # block with a through bore and a pin (0.1 mm clearance).
        part(g + "block", plate_with_holes(0, y, 16, holes, 3.0, n, 0, 20), False)
        part(g + "pin", prism(8, y + 8, 2.9, n, 2, 30), True)
        rel(g + "block", g + "pin", "clearance", "pin in bore, 0.1 mm radial clearance")
        return y + 100

    def drilled_board(g, y):
        # drilled board, a component on it, its two leads through holes.
        part(g + "board", plate_with_holes(0, y, 10, 3, 1.0, n, 0, 1.6), False)
        part(g + "component", box((4, y + 3, 1.6), (26, y + 7, 5)), True)
        rel(g + "board", g + "component", "contact", "seated on the board")
        for k, lx in enumerate((5, 25)):
            part(g + "lead%d" % k, prism(lx, y + 5, 0.6, 8, -3, 1.6), True)
            rel(g + "board", g + "lead%d" % k, "clearance", "lead through a 1 mm hole")
            rel(g + "component", g + "lead%d" % k, "contact", "lead under the component")
        return y + 100

    for c in range(a.copies if a.bench else 0):
        g = "c%d_" % c
        y = bolted_plates(g, 100.0 * c * 5, 2)
        y = pin_in_block(g, y, 2)
        drilled_board(g, y)

    for c in range(0 if a.bench else a.copies):
        g = "c%d_" % c
        # 1. bolted plates; 2. a pin in a block.
        y = bolted_plates(g, 100.0 * c * 8, 1)
        y = pin_in_block(g, y, 1)
        # 3. L-brackets: a block touching both legs; a block 0.3 mm off both.
        part(g + "bracket", l_bracket(0, y, 0, 30, 30, 4, 10), False)
        part(g + "corner", box((4, y + 2, 4), (14, y + 8, 14)), True)
        rel(g + "bracket", g + "corner", "contact", "block seated in the L's corner")
        part(g + "bracket2", l_bracket(50, y, 0, 30, 30, 4, 10), False)
        part(g + "corner2", box((54.3, y + 2, 4.3), (64, y + 8, 14)), True)
        rel(g + "bracket2", g + "corner2", "clearance", "0.3 mm off both legs")
        y += 100
        # 4. drilled board, a component on it, its two leads through holes.
        y = drilled_board(g, y)
        # 5. hollow housing (outer shell, inner shell reversed) with a part in the cavity.
        housing = box((0, y, 0), (30, y + 30, 30)).add(box((3, y + 3, 3), (27, y + 27, 27)).reversed())
        part(g + "housing", housing, False)
        part(g + "inner", box((8, y + 8, 8), (20, y + 20, 20)), True)
        rel(g + "housing", g + "inner", "clearance", "in the housing's cavity")
        y += 100
        # 6. containment: a part buried in a thick L's material, no surfaces meet.
        part(g + "solid", l_bracket(0, y, 0, 40, 40, 20, 30), False)
        part(g + "buried", box((6, y + 10, 6), (12, y + 16, 12)), True)
        rel(g + "solid", g + "buried", "interference", "buried in the thick L (containment)")
        y += 100
        # 7. open tray (no lid) with a part inside; a rod through its wall.
        tray = box((0, y, 0), (30, y + 30, 15), top=False)
        tray.add(box((1, y + 1, 1), (29, y + 29, 15), top=False).reversed())
        part(g + "tray", tray, False)
        part(g + "in_tray", box((5, y + 5, 1.5), (20, y + 20, 10)), True)
        rel(g + "tray", g + "in_tray", "clearance", "resting 0.5 mm above the open tray's floor")
        part(g + "rod", prism(29.5, y + 25, 1.0, n, 6, 9), True)
        rel(g + "tray", g + "rod", "interference", "a rod through the open tray's wall")
        y += 100
        # 8. a 0.05 mm foil pushed 3 mm into an L-bracket's leg: a thin overlap,
        # a genuine clash (its surface lies deep inside the bracket).
        part(g + "bracket3", l_bracket(0, y, 0, 30, 30, 4, 10), False)
        part(g + "foil", box((10, y + 2, 1), (10.05, y + 8, 12)), True)
        rel(g + "bracket3", g + "foil", "interference", "0.05 mm foil 3 mm into the leg")

    scene = {"version": 1, "units": "mm",
             "tolerance": a.tolerance, "parts": parts}
    with open(os.path.join(a.out_dir, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    with open(os.path.join(a.out_dir, "expected.json"), "w") as f:
        json.dump({"pairs": pairs, "parts": info}, f, indent=1)


if __name__ == "__main__":
    main()
