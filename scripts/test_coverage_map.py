#!/usr/bin/env python3
"""Which modules under src/ have a test file named after them (issue 26: tests
mirror the sources, one tests/test_<module>.cpp per module it tests).

    scripts/test_coverage_map.py [ROOT] [--all] [--quiet]

A module is a stem under src/ (foo.h and foo.cpp are one module, src/report/foo
is "report/foo"); it is covered when tests/test_<foo>.cpp exists (tests/ is
flat, so two modules of one name would share a test file: listed as a
collision). A few modules are exempt, each with its reason below (pure
declarations, test fixtures). Prints the modules without a test file (with
--all every module and its test), the test files named after no module: the
story files listed in STORY with their reason (through the binary, or across
modules; printed with --all), and any other (listed always), then the figures:
"N of M modules without a test file (E exempt)" and "S story file(s), U
unlisted". Exit 0 (a map, not a gate).
"""
import collections
import os
import sys

# Modules that need no test file of their own, and why. Keep this short: a
# module with behaviour is no exemption.
EXEMPT = {
    "tolerances": "constants only; each one's meaning and test are in docs/numerics.md",
    "geometry/types": "type aliases only",
    "geometry/mesh": "a struct declaration only",
    "batch/run_result": "struct declarations only (what a run found)",
    "results/part_result": "struct declarations only (a report's part entry)",
    "scene/rules": "struct declarations only (the rules, resolved by rules_json)",
    "user_error": "an exception type holding an exit code, no logic",
    "output_error": "an exception type (user_error.h), no logic",
    "report/input_error": "an exception type (user_error.h), no logic",
    "corpus/cad_shapes": "test and benchmark fixtures, not the product",
    "corpus/contacts": "test and benchmark fixtures, not the product",
    "corpus/generators": "test and benchmark fixtures, not the product",
}

# Test files named after no module, and why they stay as they are: each tells
# a story through the binary, or across several modules, that no one module's
# file could hold. A file that tests one module belongs in that module's file.
STORY = {
    "checks": "clearance and motion checks through run_scene and the report",
    "ci_cli": "the nightly CI loop through the binary (baseline, suppressions, JUnit, SARIF)",
    "cli": "the binary end to end: exit codes, messages, reports",
    "cli_mesh_input": "the binary on bad mesh input (hangs, crashes, damaged files)",
    "convex_float32": "convex float32 parts far from the origin through the binary, against the "
    "exact reference (parts' convexity, hull stage, report)",
    "cli_numbers": "the binary at the edges of double precision and on malformed text",
    "exact_depth": "the default method against the exact reference (methods, epa, exact step)",
    "exports": "--csv and --bcf through the binary, against the JSON report and BCF schemas",
    "hard_cases": "known-hard geometry through the whole pair check (hulls, solve, status)",
    "html": "the HTML report through the binary (--html, pdcheck html)",
    "nonconvex": "a generated nonconvex assembly end to end, cold and cached",
    "output": "where the binary writes its report (-o, stdout, bad options)",
    "report_outputs": "the binary's report against its schema and the fields CI keys on",
    "run_control": "the binary under signals, a closed reader and process limits",
    "settings_hashes": "every setting against every hash (content_hashes, refine_cache, report)",
    "step_assemblies": "STEP assemblies through the binary: reading, meshing, the exact check",
    "brep_module": "Open CASCADE on demand through the binary: its module, a copy without it",
    "memory_budget": "memory that follows the work: the byte-bounded cache, the mesh store, and "
    "the largest process under --memory",
    "real_brep_files": "Debian's real B-rep files (occt-misc) against Open CASCADE's own reference",
    "main": "the tests' own main (a scratch directory per process, the linked Open CASCADE code)",
}


def modules(root):
    """Module name (path under src/ without extension) -> its basename."""
    found = {}
    for d, _, files in os.walk(os.path.join(root, "src")):
        for f in files:
            stem, ext = os.path.splitext(f)
            if ext not in (".h", ".cpp"):
                continue
            rel = os.path.relpath(os.path.join(d, stem), os.path.join(root, "src"))
            found[rel.replace(os.sep, "/")] = stem
    return dict(sorted(found.items()))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    show_all, quiet = "--all" in sys.argv, "--quiet" in sys.argv
    mods = modules(root)
    tests_dir = os.path.join(root, "tests")
    tests = {f[len("test_"):-len(".cpp")] for f in os.listdir(tests_dir)
             if f.startswith("test_") and f.endswith(".cpp")}
    by_stem = collections.defaultdict(list)
    for m, stem in mods.items():
        by_stem[stem].append(m)

    missing = [m for m, stem in mods.items() if stem not in tests and m not in EXEMPT]
    stale = sorted(set(EXEMPT) - set(mods))
    if not quiet:
        for m, stem in mods.items():
            if m in EXEMPT:
                if show_all:
                    print(f"  exempt   {m}: {EXEMPT[m]}")
            elif stem in tests:
                if show_all:
                    print(f"  tested   {m}: tests/test_{stem}.cpp")
            else:
                print(f"  missing  {m}: no tests/test_{stem}.cpp")
        for t in sorted(t for t in tests if t not in by_stem):
            if t not in STORY:
                print(f"  unlisted test_{t}.cpp: named after no module, not in STORY")
            elif show_all:
                print(f"  story    test_{t}.cpp: {STORY[t]}")
        for stem, ms in sorted(by_stem.items()):
            if len(ms) > 1:
                print(f"collision: {', '.join(ms)} share tests/test_{stem}.cpp")
    for m in stale:
        print(f"exempt but not found: {m} (remove it from EXEMPT)")
    for t in sorted(set(STORY) - tests):
        print(f"story but not found: test_{t}.cpp (remove it from STORY)")
    for t in sorted(set(STORY) & set(by_stem)):
        print(f"story but named after a module: test_{t}.cpp (remove it from STORY)")
    story = [t for t in tests if t not in by_stem]
    unlisted = [t for t in story if t not in STORY]
    print(f"{len(missing)} of {len(mods)} modules without a test file ({len(EXEMPT)} exempt)")
    print(f"{len(story)} story file(s), {len(unlisted)} unlisted")
    return 0


if __name__ == "__main__":
    sys.exit(main())
