#!/usr/bin/env python3
"""Counts the include edges between pdcheck's layers and fails on any that runs
back up them (docs/contributing.md, "Layout"; the build enforces the same order with one
library and one include view per layer, CMakeLists.txt).

    utilities -> geometry -> solve -> scene -> batch -> report -> apps/pdcheck
                             solve -> results -> batch
                 geometry -> brep -> scene, batch

A file may include headers of its own layer and of the layers below it, except
that src/geometry and src/solve see only each other (solve above geometry) and
src/tolerances.h, src/results (what a run found, between batch and report) sees
the utilities, geometry and solve but not src/scene, and src/corpus (test and benchmark fixtures) only geometry,
solve and src/tolerances.h. Nothing in the product includes src/corpus. src/brep
(STEP and .brep files, the exact solids) sees the utilities and geometry, and is
the only place that includes Open CASCADE (a header named *.hxx): any other
file under src or apps that includes one is flagged too.

Usage: scripts/check_layers.py [SOURCE_ROOT] [--quiet]
Prints the edge counts per pair of layers, then every edge that runs back up;
exit 0 when there is none, 1 otherwise.
"""
import collections
import os
import re
import sys

ORDER = ["utilities", "geometry", "solve", "brep", "results", "scene", "batch", "report", "app"]
# The layers whose headers each layer may include, besides its own.
ALLOWED = {
    "utilities": {"tolerances"},
    "geometry": {"tolerances"},
    "solve": {"tolerances", "geometry"},
    "results": {"tolerances", "utilities", "geometry", "solve"},
    "brep": {"tolerances", "utilities", "geometry"},
    "scene": {"tolerances", "utilities", "geometry", "solve", "brep"},
    "corpus": {"tolerances", "geometry", "solve"},
    "bench": set(ORDER) | {"tolerances", "corpus"},
}
ALLOWED["batch"] = ALLOWED["scene"] | {"results", "scene"}  # brep through scene's set
ALLOWED["report"] = ALLOWED["batch"] | {"batch"}
ALLOWED["app"] = ALLOWED["report"] | {"report"}
SUBDIRS = {"geometry", "solve", "brep", "results", "scene", "batch", "report", "corpus"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
# Open CASCADE's headers: <Name.hxx>, allowed in src/brep alone.
OCCT_INCLUDE = re.compile(r'^\s*#\s*include\s+<([^>]+\.hxx)>', re.M)


def layer_of(rel):
    """The layer of a path relative to the source root, or None (not checked)."""
    parts = rel.split("/")
    if parts[0] == "apps":
        return "app" if parts[1] == "pdcheck" else "bench"
    if parts[0] != "src":
        return None
    if len(parts) == 2:
        return "tolerances" if parts[1] == "tolerances.h" else "utilities"
    return parts[1] if parts[1] in SUBDIRS else None


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quiet = "--quiet" in sys.argv
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    edges = collections.Counter()
    back = []
    unresolved = []
    for top in ["src", "apps"]:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if not f.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(dirpath, f)
                rel = os.path.relpath(path, root).replace(os.sep, "/")
                src_layer = layer_of(rel)
                if src_layer is None:
                    continue
                if src_layer == "tolerances":
                    src_layer = "utilities"
                with open(path, encoding="utf-8") as text:
                    body = text.read()
                includes = INCLUDE.findall(body)
                if src_layer != "brep":
                    for occt in OCCT_INCLUDE.findall(body):
                        back.append(f"{rel}: #include <{occt}> (Open CASCADE outside src/brep)")
                for inc in includes:
                    # As the compiler looks: beside the file, then under src/;
                    # report/html_assets.h is generated into the report layer.
                    beside = os.path.relpath(os.path.join(dirpath, inc), root).replace(os.sep, "/")
                    if os.path.exists(os.path.join(root, beside)):
                        target = beside
                    elif os.path.exists(os.path.join(root, "src", inc)) or inc == "report/html_assets.h":
                        target = "src/" + inc
                    else:
                        unresolved.append(f"{rel}: #include \"{inc}\"")
                        continue
                    to_layer = layer_of(target)
                    if to_layer is None:
                        continue
                    if to_layer != src_layer:
                        edges[(src_layer, to_layer)] += 1
                    if to_layer != src_layer and to_layer not in ALLOWED[src_layer]:
                        back.append(f"{rel}: #include \"{inc}\" ({src_layer} -> {to_layer})")
    if not quiet:
        print("include edges between layers (from -> to: count):")
        for (a, b), n in sorted(edges.items()):
            print(f"  {a} -> {b}: {n}")
    for line in unresolved:
        print("unresolved: " + line)
    print(f"{len(back)} include edge(s) running back up the layers")
    for line in back:
        print("  " + line)
    return 1 if back or unresolved else 0


if __name__ == "__main__":
    sys.exit(main())
