"""The exact interference check a FreeCAD user would script, for scripts/bench_step_assemblies.py.

usage: PDCHECK_FC_SCENE=scene.json PDCHECK_FC_OUT=result.json freecadcmd freecad_exact_check.py

Runs inside freecadcmd (FreeCAD 0.20's Python and Part API). Reads a pdcheck scene of STEP parts
(units mm; `mesh` relative to the scene; an optional 4x4 `transform`), loads every file with
Import.insert (useLinkGroup=False: the default link-group import crashes FreeCAD 0.20 headless on
assembly files), takes each leaf Part::Feature at its global placement (one part per leaf: the
scene id, and for an assembly file the scene id / the leaf's label), then for every pair whose
bounding boxes, grown by the scene's tolerance, meet: `distToShape`, and `common().Volume` when
the distance is 0 (<= 1e-7 mm, Open CASCADE's confusion tolerance). The shapes are used as loaded
(a multi-solid product is a compound). Writes PDCHECK_FC_OUT: {"load_seconds", "check_seconds",
"parts", "pairs": [{"a", "b", "distance", "volume"?, "seconds", "error"?}]}; check_seconds times
the pair loop only (boxes, distances, Booleans), load_seconds the reading.
"""
import json
import os
import time
import traceback

TOUCH = 1e-7


def load(scene_path):
    import FreeCAD as App
    import Import
    scene = json.load(open(scene_path))
    base = os.path.dirname(os.path.abspath(scene_path))
    parts = []
    for k, spec in enumerate(scene["parts"]):
        doc = App.newDocument("load%d" % k)
        Import.insert(os.path.join(base, spec["mesh"]), doc.Name, useLinkGroup=False)
        leaves = [o for o in doc.Objects if o.TypeId == "Part::Feature" and o.Shape.Solids]
        M = None
        if "transform" in spec:
            t = spec["transform"]
            M = App.Placement(App.Matrix(*[x for row in t for x in row]))
        for o in leaves:
            s = o.Shape.copy()
            s.Placement = o.getGlobalPlacement()
            if M is not None:
                s.Placement = M.multiply(s.Placement)
            pid = spec["id"] if len(leaves) == 1 else spec["id"] + "/" + o.Label
            parts.append((pid, s))
    return scene, parts


def check(parts, tol):
    import FreeCAD as App
    boxes = []
    for _, s in parts:
        b = App.BoundBox(s.BoundBox)
        b.enlarge(tol)
        boxes.append(b)
    out = []
    for i in range(len(parts)):
        for j in range(i + 1, len(parts)):
            if not boxes[i].intersect(parts[j][1].BoundBox):
                continue
            t0 = time.perf_counter()
            r = {"a": parts[i][0], "b": parts[j][0]}
            try:
                d = parts[i][1].distToShape(parts[j][1])[0]
                r["distance"] = d
                if d <= TOUCH:
                    r["volume"] = parts[i][1].common(parts[j][1]).Volume
            except Exception as e:  # a user's script would note it and go on
                r["error"] = "%s: %s" % (type(e).__name__, e)
            r["seconds"] = time.perf_counter() - t0
            out.append(r)
    return out


def main():
    t0 = time.perf_counter()
    scene, parts = load(os.environ["PDCHECK_FC_SCENE"])
    t1 = time.perf_counter()
    pairs = check(parts, scene["tolerance"])
    t2 = time.perf_counter()
    with open(os.environ["PDCHECK_FC_OUT"], "w") as f:
        json.dump({"load_seconds": t1 - t0, "check_seconds": t2 - t1, "parts": [p for p, _ in parts],
                   "pairs": pairs}, f, indent=1)


try:
    main()
except BaseException:
    traceback.print_exc()
    os._exit(1)
os._exit(0)
