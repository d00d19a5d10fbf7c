#!/usr/bin/python3
"""A CAD assembly at the scale users have: many distinct, finely tessellated binary STL files.

usage: /usr/bin/python3 scripts/make_scale_assembly.py OUTDIR --triangles N [--fine K]
           [--mechanisms bearing_housing,bolted_flange,hinge_oversize_pin] [--render-cache DIR] [--openscad PATH]

Needs numpy (Debian's python3-numpy: run it with /usr/bin/python3; a pyenv `python3` may lack
it). Issue 45: the benchmark of scripts/bench_scale.py.

The mechanisms of scripts/make_cad_assemblies.py (default: the bearing in its housing, the
bolted flange and the hinge with its oversize pin, for interferences), rendered by OpenSCAD with
every $fn multiplied by K (--fine, default 8: the bearing's rings 201,216 triangles each, its
balls 65,532, the whole bearing 941,564; the flange 101,624; the hinge 45,104; the first render
at K = 8 takes ~ 3 minutes, cached), are written again and again until the assembly has at least
N triangles:
copy i is mechanism i mod M under a rotation of its own (uniform on SO(3), seeded with i) and a
place of its own on a cubic lattice, baked into the float32 coordinates of its files, so no two
files are equal byte for byte and pdcheck cannot share a mesh between copies.

OUTDIR/cNNNN/PART.stl  one binary STL per part (float32, the 80-byte header not starting with
                       "solid", normals of the exact rotation), part id "cNNNN/PART"
OUTDIR/scene.json      version 1, units mm, the tolerance, parts with `mesh` relative to it
OUTDIR/expected.json   as make_cad_assemblies.py writes it: {"assembly", "description",
                       "tolerance", "parts": {id: {triangles, bodies, placement, file, mechanism,
                       copy}}, "pairs": [{"a", "b", "expect", "nominal_depth"?, "gap"?, "max_sag",
                       "note"}]}, plus "copies", "fine", "triangles", "float32_pair_error"
The renders are cached (default OUTDIR/.render-cache; --render-cache shares them between
scenes); triangles are put in make_cad_assemblies' canonical order, so the files are the same on
every run.

Nominal relations: each copy carries its mechanism's stated relations (make_cad_assemblies.py),
their sags taken at the finer $fn (its Ctx), each checked to keep its class at the scene's
tolerance after tessellation and float32 (check_relations). A pair the mechanism does not state
whose parts could come within the tolerance in some rotation (centres closer than sqrt(3) times
the sum of the radii and the tolerance) is checked apart here on the fine meshes (no triangle
box within 0.1 mm of the other's, neither part inside the other) and listed as a clearance in a
copy where its world boxes meet; the script stops when it cannot check such a pair apart.

Copies do not interact: the lattice pitch is the largest mechanism diameter + 10 mm, and each
copy moves by at most 2 mm per axis from its lattice point, so boxes of different copies stay >= 6 mm
apart (above any tolerance). Coordinates: x from about 20,000 mm, |x|, |y|, |z| < 60,000 mm
(checked); below 65,536 mm float32 spacing is at most 2^-8 mm, so the float32 error budget is
make_cad_assemblies' F32_PAIR (0.0068 mm between the two parts of a pair).
"""
import argparse
import importlib.util
import json
import math
import os
import random
import re
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("make_cad_assemblies", os.path.join(HERE, "make_cad_assemblies.py"))
cad = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cad)

try:
    import numpy as np
except ImportError:
    np = None

LIMIT = 60000.0     # every coordinate below this in magnitude (float32 spacing <= 2^-8 mm)
X0 = 20000.0        # the lattice starts here along x
JITTER = 2.0        # each copy moves by up to this from its lattice point, per axis
GAP = 10.0          # pitch = largest mechanism diameter + GAP (copies >= GAP - 2 JITTER apart)
CHECK_MARGIN = 0.1  # unstated pairs: no triangle box within this of the other's (as make_cad_assemblies)


def record_dtype():
    rec = np.dtype([("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    assert rec.itemsize == 50
    return rec


def read_stl_np(path):
    rec = record_dtype()
    with open(path, "rb") as f:
        f.seek(80)
        n = int(np.frombuffer(f.read(4), "<u4")[0])
        data = np.fromfile(f, rec, count=n)
    if len(data) != n or os.path.getsize(path) != 84 + 50 * n:
        sys.exit("%s: not a binary STL of %d triangles" % (path, n))
    return data["v"].astype(np.float64)


def lex_less(a, b):
    return (a[:, 0] < b[:, 0]) | ((a[:, 0] == b[:, 0]) & ((a[:, 1] < b[:, 1]) |
                                                          ((a[:, 1] == b[:, 1]) & (a[:, 2] < b[:, 2]))))


def canonical_np(t):
    """make_cad_assemblies.canonical in numpy: each triangle from its smallest vertex, sorted."""
    k = np.zeros(len(t), dtype=np.int64)
    best = t[:, 0]
    for i in (1, 2):
        m = lex_less(t[:, i], best)
        best = np.where(m[:, None], t[:, i], best)
        k[m] = i
    idx = (k[:, None] + np.arange(3)[None, :]) % 3
    t = t[np.arange(len(t))[:, None], idx]
    order = np.lexsort([t[:, i // 3, i % 3] for i in reversed(range(9))])
    return t[order]


def unit_normals(t):
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    ln = np.linalg.norm(n, axis=1)
    ln[ln == 0.0] = 1.0
    return n / ln[:, None]


# --- checks of unstated pairs on the fine meshes (make_cad_assemblies.provably_apart, vectorized)

def cells_of(boxes, lo, hi, cell):
    """(box index, cell key) for every cell of a grid on [lo, hi] that each box covers."""
    top = np.floor((hi - lo) / cell).astype(np.int64)
    c0 = np.clip(np.floor((boxes[:, :3] - lo) / cell).astype(np.int64), 0, top)
    c1 = np.clip(np.floor((boxes[:, 3:] - lo) / cell).astype(np.int64), 0, top)
    dims = c1 - c0 + 1
    count = dims.prod(1)
    box = np.repeat(np.arange(len(boxes)), count)
    start = np.repeat(np.cumsum(count) - count, count)
    j = np.arange(count.sum()) - start
    d = dims[box]
    ix = j // (d[:, 1] * d[:, 2])
    iy = (j // d[:, 2]) % d[:, 1]
    iz = j % d[:, 2]
    c = c0[box]
    return box, ((c[:, 0] + ix) * 1000003 + (c[:, 1] + iy)) * 1000003 + (c[:, 2] + iz)


def surfaces_apart_np(ta, tb, margin):
    ba = np.concatenate([ta.min(1), ta.max(1)], 1)
    bb = np.concatenate([tb.min(1), tb.max(1)], 1)
    lo = np.maximum(ba[:, :3].min(0), bb[:, :3].min(0)) - margin
    hi = np.minimum(ba[:, 3:].max(0), bb[:, 3:].max(0)) + margin
    if (lo > hi).any():
        return True

    def near(b):
        return ((b[:, :3] - margin <= hi) & (b[:, 3:] + margin >= lo)).all(1)
    ba, bb = ba[near(ba)], bb[near(bb)]
    if not len(ba) or not len(bb):
        return True
    cell = max(float((hi - lo).max()) / 64.0, 0.25)
    grown = bb + np.array([-margin] * 3 + [margin] * 3)
    kb_box, kb = cells_of(grown, lo - 2 * margin, hi + 2 * margin, cell)
    ka_box, ka = cells_of(ba, lo - 2 * margin, hi + 2 * margin, cell)
    order = np.argsort(kb, kind="stable")
    kb, kb_box = kb[order], kb_box[order]
    left = np.searchsorted(kb, ka, "left")
    right = np.searchsorted(kb, ka, "right")
    hits = right - left
    sel = hits > 0
    ka_box, left, hits = ka_box[sel], left[sel], hits[sel]
    step = 4000000
    ends = np.cumsum(hits)
    s = 0
    while s < len(hits):
        e = int(np.searchsorted(ends, (ends[s - 1] if s else 0) + step, "right"))
        e = max(e, s + 1)
        h = hits[s:e]
        ia = np.repeat(ka_box[s:e], h)
        off = np.arange(h.sum()) - np.repeat(np.cumsum(h) - h, h)
        ib = kb_box[np.repeat(left[s:e], h) + off]
        A, B = ba[ia], bb[ib]
        if ((A[:, :3] - margin <= B[:, 3:]) & (B[:, :3] - margin <= A[:, 3:])).all(1).any():
            return False
        s = e
    return True


def inside_np(p, tris):
    """Ray parity (one closed body), as make_cad_assemblies.inside."""
    d = np.array([0.5773502691896258, 0.5773502691896258 + 1.3e-4, 0.5773502691896258 - 2.9e-4])
    a, e1, e2 = tris[:, 0], tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]
    h = np.cross(d, e2)
    det = (e1 * h).sum(1)
    ok = np.abs(det) >= 1e-14
    det = np.where(ok, det, 1.0)
    s = p - a
    u = (s * h).sum(1) / det
    q = np.cross(s, e1)
    v = (q * d).sum(1) / det
    t = (e2 * q).sum(1) / det
    return int((ok & (u >= 0) & (u <= 1) & (v >= 0) & (u + v <= 1) & (t > 0)).sum()) % 2 == 1


def provably_apart_np(bodies_a, bodies_b):
    if not surfaces_apart_np(np.concatenate(bodies_a), np.concatenate(bodies_b), CHECK_MARGIN):
        return False
    for src, dst in ((bodies_a, bodies_b), (bodies_b, bodies_a)):
        for body in src:
            if any(inside_np(body[0][0], d) for d in dst):
                return False
    return True


# --- mechanisms ------------------------------------------------------------------------------

class Mechanism:
    pass


def prepare(name, fine, tol, cache, exe, version):
    builders = dict(cad.ASSEMBLIES)
    desc, own_tol, parts, rels = builders[name](cad.Ctx(False, fine), name)
    tol = own_tol if tol is None else tol
    cad.check_relations(name, tol, rels)
    m = Mechanism()
    m.name, m.desc, m.tol, m.rels = name, desc, tol, rels
    m.ids = [p.id for p in parts]
    m.bodies = {}
    t0 = time.monotonic()
    for p in parts:
        m.bodies[p.id] = [canonical_np(read_stl_np(cad.render_path(src, cache, exe, version)))
                          for src in p.bodies]
        if any(len(b) == 0 for b in m.bodies[p.id]):
            sys.exit("%s/%s: openscad rendered an empty body" % (name, p.id))
    m.tris = {pid: np.concatenate(b) for pid, b in m.bodies.items()}
    m.normals = {pid: unit_normals(t) for pid, t in m.tris.items()}
    allv = np.concatenate([t.reshape(-1, 3) for t in m.tris.values()])
    m.centre = (allv.min(0) + allv.max(0)) / 2.0
    m.radius = float(np.linalg.norm(allv - m.centre, axis=1).max()) + 1.0
    m.triangles = sum(len(t) for t in m.tris.values())
    # parts' own spheres: which unstated pairs could have meeting world boxes in some rotation
    sph = {}
    for pid, t in m.tris.items():
        v = t.reshape(-1, 3)
        c = (v.min(0) + v.max(0)) / 2.0
        sph[pid] = (c, float(np.linalg.norm(v - c, axis=1).max()) + 1.0)
    stated = {frozenset((r["a"], r["b"])) for r in rels}
    m.apart = []
    for i, a in enumerate(m.ids):
        for b in m.ids[i + 1:]:
            if frozenset((a, b)) in stated:
                continue
            (ca, ra), (cb, rb) = sph[a], sph[b]
            if np.linalg.norm(ca - cb) > math.sqrt(3.0) * (ra + rb + tol):
                continue
            if not provably_apart_np(m.bodies[a], m.bodies[b]):
                sys.exit("%s: %s/%s: the fine meshes are not clearly apart: state the relation" % (name, a, b))
            m.apart.append((a, b))
    print("%s at $fn x %d: %d parts, %d triangles (largest part %d), %d stated relations, %d unstated pairs "
          "checked apart (%.1f s)" % (name, fine, len(m.ids), m.triangles, max(len(t) for t in m.tris.values()),
                                      len(rels), len(m.apart), time.monotonic() - t0), file=sys.stderr)
    return m


def write_stl_np(path, world, normals, header):
    rec = np.empty(len(world), dtype=record_dtype())
    rec["n"] = normals
    rec["v"] = world
    rec["attr"] = 0
    with open(path, "wb") as f:
        f.write(header.encode()[:80].ljust(80, b" "))
        f.write(np.array([len(world)], "<u4").tobytes())
        rec.tofile(f)


def boxes_meet(a, b, grow):
    return bool(np.all(a[:3] - grow <= b[3:]) and np.all(b[:3] - grow <= a[3:]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--triangles", type=float, required=True, help="at least this many triangles (1e8 is fine)")
    ap.add_argument("--fine", type=int, default=8, help="$fn multiplier of the renders (default 8)")
    ap.add_argument("--mechanisms", default="bearing_housing,bolted_flange,hinge_oversize_pin",
                    help="comma-separated assemblies of make_cad_assemblies.py (--list there)")
    ap.add_argument("--render-cache", help="OpenSCAD render cache (default OUTDIR/.render-cache)")
    ap.add_argument("--openscad", default=shutil.which("openscad") or "openscad")
    a = ap.parse_args()
    if np is None:
        sys.exit("make_scale_assembly.py needs numpy: run it with /usr/bin/python3 (Debian: apt-get install "
                 "python3-numpy); %s has none" % sys.executable)
    if a.fine < 1 or a.triangles < 1:
        ap.error("--fine and --triangles must be >= 1")
    names = [n for n in a.mechanisms.split(",") if n]
    known = [n for n, _ in cad.ASSEMBLIES]
    for n in names:
        if n not in known:
            ap.error("unknown mechanism %r (one of %s)" % (n, ", ".join(known)))
    if not shutil.which(a.openscad):
        sys.exit("openscad not found (Debian package openscad)")
    version = cad.openscad_version(a.openscad)
    cache = a.render_cache or os.path.join(a.outdir, ".render-cache")
    os.makedirs(cache, exist_ok=True)
    mechs, tol = [], None
    for n in names:
        m = prepare(n, a.fine, tol, cache, a.openscad, version)
        tol = m.tol  # the first mechanism's tolerance is the scene's (the others checked at it)
        mechs.append(m)

    copies, total = 0, 0
    while total < a.triangles:
        total += mechs[copies % len(mechs)].triangles
        copies += 1
    pitch = 2.0 * max(m.radius for m in mechs) + GAP
    side = max(1, math.ceil(copies ** (1.0 / 3.0) - 1e-9))
    half = (side - 1) * pitch / 2.0
    if X0 + pitch * side + pitch > LIMIT:
        sys.exit("%d copies do not fit below %g mm" % (copies, LIMIT))

    os.makedirs(a.outdir, exist_ok=True)
    for e in os.listdir(a.outdir):
        if re.fullmatch(r"c\d{4,}", e):
            shutil.rmtree(os.path.join(a.outdir, e))
    scene_parts, info, pairs = [], {}, []
    t0 = time.monotonic()
    written = 0
    for i in range(copies):
        m = mechs[i % len(mechs)]
        cid = "c%04d" % i
        rng = random.Random("pdcheck-scale-%d-%s" % (i, m.name))
        R = np.array(cad.random_rotation(rng))
        ix, iy, iz = i % side, (i // side) % side, i // (side * side)
        t = np.array([X0 + pitch / 2.0 + ix * pitch, -half + iy * pitch, -half + iz * pitch])
        t += np.array([rng.uniform(-JITTER, JITTER) for _ in range(3)])
        os.makedirs(os.path.join(a.outdir, cid), exist_ok=True)
        boxes = {}
        for pid in m.ids:
            world = (m.tris[pid] - m.centre) @ R.T + t
            world = world.astype(np.float32)
            if float(np.abs(world).max()) >= LIMIT:
                sys.exit("%s/%s: a coordinate beyond %g mm" % (cid, pid, LIMIT))
            fname = "%s/%s.stl" % (cid, pid)
            write_stl_np(os.path.join(a.outdir, fname), world, (m.normals[pid] @ R.T).astype(np.float32),
                         "binary STL, make_scale_assembly %s/%s (%s)" % (cid, pid, m.name))
            w = world.reshape(-1, 3).astype(np.float64)
            boxes[pid] = np.concatenate([w.min(0), w.max(0)])
            full = "%s/%s" % (cid, pid)
            scene_parts.append({"id": full, "mesh": fname})
            info[full] = {"file": fname, "triangles": len(world), "bodies": len(m.bodies[pid]),
                          "placement": "baked", "mechanism": m.name, "copy": i}
            written += len(world)
        for r in m.rels:
            q = dict(r, a="%s/%s" % (cid, r["a"]), b="%s/%s" % (cid, r["b"]))
            if not boxes_meet(boxes[r["a"]], boxes[r["b"]], tol):
                q["note"] = r["note"] + " [boxes apart: culled]"
            pairs.append(q)
        for pa, pb in m.apart:
            if boxes_meet(boxes[pa], boxes[pb], tol):
                pairs.append(cad.clearance("%s/%s" % (cid, pa), "%s/%s" % (cid, pb), 0.1,
                                           "apart by construction (checked on the fine meshes: surfaces "
                                           ">= 0.1 apart, neither inside the other); boxes meet"))
        if (i + 1) % max(1, copies // 20) == 0 or i + 1 == copies:
            dt = time.monotonic() - t0
            print("copy %d/%d: %d triangles written, %.0f s (%.1f M triangles/s)" % (
                i + 1, copies, written, dt, written / 1e6 / max(dt, 1e-9)), file=sys.stderr)
    scene = {"version": 1, "units": "mm", "tolerance": tol, "parts": scene_parts}
    with open(os.path.join(a.outdir, "scene.json"), "w") as f:
        f.write(json.dumps(scene, indent=1).split('"parts"')[0] + '"parts": [\n  ' +
                ",\n  ".join(json.dumps(p) for p in scene_parts) + "\n ]\n}\n")
    counts = {}
    for r in pairs:
        counts[r["expect"]] = counts.get(r["expect"], 0) + 1
    desc = ("%d copies of %s at $fn x %d, each under its own rotation on a lattice (pitch %.0f mm), baked "
            "into float32" % (copies, " and ".join(m.name for m in mechs), a.fine, pitch))
    exp = {"assembly": "scale", "description": desc, "tolerance": tol, "copies": copies, "fine": a.fine,
           "mechanisms": names, "triangles": written, "float32_pair_error": cad.F32_PAIR,
           "parts": info, "pairs": pairs}
    with open(os.path.join(a.outdir, "expected.json"), "w") as f:
        json.dump(exp, f, indent=1)
        f.write("\n")
    print("%s: %d parts in %d copies, %d triangles (%.2f GB), relations: %s" % (
        a.outdir, len(scene_parts), copies, written, (84 * len(scene_parts) + 50 * written) / 1e9,
        ", ".join("%d %s" % (v, k) for k, v in sorted(counts.items()))), file=sys.stderr)


if __name__ == "__main__":
    main()
