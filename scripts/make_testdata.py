#!/usr/bin/env python3
"""Generates the bundled meshes: the demo assembly and the format fixtures.

Run from anywhere: python3 scripts/make_testdata.py. Standard library only.
Every file under testdata/demo and testdata/formats is written by this script.

The demo assembly (units: mm, tolerance 0.1 mm):
  base      a 200 x 100 x 10 plate (binary STL)
  cover     a 200 x 100 x 8 plate resting on it; its exported bottom face sits
            0.02 mm low, as a tessellator's rounding leaves it (OBJ)
  slot      a block with a 10 mm slot, two convex pieces in one OBJ
  pin       a 10 mm pin, a 24-gon circumscribing the circle: in the slot it
            overlaps each wall by r(1/cos(pi/24) - 1) = 0.043 mm (ASCII PLY)
  bracket   an angle bracket placed by glTF node transforms; a design error
            pushes it 2 mm into the cover (a genuine interference)
  spacer    an inline vertex list touching the base exactly (face contact)
"""
import base64
import json
import math
import os
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "testdata")


def box(x0, y0, z0, x1, y1, z1):
    v = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    # Faces of the cube on v indices (x major, then y, then z), outward winding.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = []
    for a, b, c, d in quads:
        tris += [(a, b, c), (a, c, d)]
    return v, tris


def cylinder(cx, cy, z0, z1, r, n):
    # A circumscribed n-gon prism: its faces touch the true circle, its
    # vertices (one on each axis) stand out by r(1/cos(pi/n) - 1).
    R = r / math.cos(math.pi / n)
    v = []
    for z in (z0, z1):
        for k in range(n):
            t = 2 * math.pi * k / n
            v.append((cx + R * math.cos(t), cy + R * math.sin(t), z))
    tris = []
    for k in range(n):
        a, b = k, (k + 1) % n
        tris += [(a, b, n + b), (a, n + b, n + a)]
    for k in range(1, n - 1):
        tris += [(0, k + 1, k), (n, n + k, n + k + 1)]
    return v, tris


def normal(v, t):
    a, b, c = (v[i] for i in t)
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    s = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / s for x in n]


def write_stl_binary(path, v, tris):
    with open(path, "wb") as f:
        f.write(b"pdcheck testdata".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", *normal(v, t)))
            for i in t:
                f.write(struct.pack("<3f", *v[i]))
            f.write(b"\0\0")


def write_stl_ascii(path, v, tris):
    with open(path, "w") as f:
        f.write("solid pdcheck\n")
        for t in tris:
            f.write("  facet normal %g %g %g\n    outer loop\n" % tuple(normal(v, t)))
            for i in t:
                f.write("      vertex %.9g %.9g %.9g\n" % v[i])
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid pdcheck\n")


def write_obj(path, objects):
    with open(path, "w") as f:
        base = 1
        for name, (v, tris) in objects:
            f.write("o %s\n" % name)
            for p in v:
                f.write("v %.9g %.9g %.9g\n" % p)
            for t in tris:
                f.write("f %d %d %d\n" % tuple(base + i for i in t))
            base += len(v)


def write_ply_ascii(path, v, tris):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % len(v))
        f.write("property float x\nproperty float y\nproperty float z\n")
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(tris))
        for p in v:
            f.write("%.9g %.9g %.9g\n" % p)
        for t in tris:
            f.write("3 %d %d %d\n" % t)


def write_ply_binary(path, v, tris):
    with open(path, "wb") as f:
        head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % len(v) +
                "property float x\nproperty float y\nproperty float z\n" +
                "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(tris))
        f.write(head.encode())
        for p in v:
            f.write(struct.pack("<3f", *p))
        for t in tris:
            f.write(struct.pack("<B3i", 3, *t))


def write_gltf(path, v, tris, nodes):
    """One mesh, instanced by `nodes` (glTF node dicts; "mesh": 0 marks instances)."""
    pos = b"".join(struct.pack("<3f", *p) for p in v)
    idx = b"".join(struct.pack("<3H", *t) for t in tris)
    pad = (4 - len(pos) % 4) % 4
    buf = pos + b"\0" * pad + idx
    lo = [min(p[i] for p in v) for i in range(3)]
    hi = [max(p[i] for p in v) for i in range(3)]
    doc = {
        "asset": {"version": "2.0", "generator": "pdcheck make_testdata.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos) + pad, "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3",
                       "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5123, "count": 3 * len(tris), "type": "SCALAR"}],
    }
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def demo():
    d = os.path.join(ROOT, "demo")
    os.makedirs(d, exist_ok=True)
    write_stl_binary(os.path.join(d, "base.stl"), *box(0, 0, 0, 200, 100, 10))
    write_obj(os.path.join(d, "cover.obj"), [("cover", box(0, 0, 9.98, 200, 100, 18))])
    # The slot block on the base, x in [20, 60], with a 10 mm slot at x = 40.
    write_obj(os.path.join(d, "slot.obj"), [("left", box(20, 10, -30, 35, 40, 0)),
                                            ("right", box(45, 10, -30, 60, 40, 0))])
    write_ply_ascii(os.path.join(d, "pin.ply"), *cylinder(40, 25, -30, 0, 5, 24))
    # The bracket mesh is a unit-free L profile's two legs as one convex block;
    # nodes place it: a parent translation and a child rotation about z.
    bv, bt = box(0, 0, 0, 20, 30, 12)
    write_gltf(os.path.join(d, "bracket.gltf"), bv, bt, [
        {"name": "assembly", "translation": [150, 10, 0], "children": [1]},
        # 90 degrees about z: (x, y) -> (-y, x); the block then spans x in
        # [120, 150], y in [10, 30], z in [16, 28]: 2 mm into the cover (top 18).
        {"name": "bracket", "rotation": [0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)],
         "translation": [0, 0, 16], "mesh": 0},
    ])
    scene = {
        "$schema": "../../docs/scene.schema.json",
        "version": 1,
        "units": "mm",
        "tolerance": 0.1,
        "parts": [
            {"id": "base", "mesh": "base.stl"},
            {"id": "cover", "mesh": "cover.obj"},
            {"id": "slot", "mesh": "slot.obj", "pieces": "meshes",
             "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]},
            {"id": "pin", "mesh": "pin.ply"},
            # Authored in mm; glTF 2.0 fixes metres, so the part says mm.
            {"id": "bracket", "mesh": "bracket.gltf", "units": "mm"},
            {"id": "spacer", "units": "cm",
             "vertices": [[8, 6, 0], [9, 6, 0], [8, 7, 0], [9, 7, 0],
                          [8, 6, -1], [9, 6, -1], [8, 7, -1], [9, 7, -1]]},
        ],
    }
    with open(os.path.join(d, "scene.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")


def formats():
    d = os.path.join(ROOT, "formats")
    os.makedirs(d, exist_ok=True)
    v, t = box(-1, -2, -3, 1, 2, 3)  # a 2 x 4 x 6 box centred at the origin
    write_stl_ascii(os.path.join(d, "box_ascii.stl"), v, t)
    write_stl_binary(os.path.join(d, "box_binary.stl"), v, t)
    write_obj(os.path.join(d, "box.obj"), [("box", (v, t))])
    write_ply_ascii(os.path.join(d, "box_ascii.ply"), v, t)
    write_ply_binary(os.path.join(d, "box_binary.ply"), v, t)
    # Two instances: a translated one, and a child scaled by 2 then rotated 90
    # degrees about x under a translated parent (world = parent * child * v).
    s = math.sin(math.pi / 4)
    write_gltf(os.path.join(d, "box_nodes.gltf"), v, t, [
        {"name": "root", "children": [1, 2]},
        {"name": "moved", "translation": [10, 0, 0], "mesh": 0},
        {"name": "parent", "translation": [0, 20, 0], "children": [3]},
        {"name": "child", "rotation": [s, 0, 0, s], "scale": [2, 2, 2], "mesh": 0},
    ])
    with open(os.path.join(d, "empty.obj"), "w") as f:
        f.write("# an OBJ file with no geometry\n")
    with open(os.path.join(d, "garbage.stl"), "w") as f:
        f.write("this is not a mesh\n")
    with open(os.path.join(d, "nan.obj"), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 1\nf 1 2 3\nf 1 2 4\n")


if __name__ == "__main__":
    demo()
    formats()
