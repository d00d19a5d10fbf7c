#!/usr/bin/env python3
"""Lengths of the functions under src/ and apps/ (issue 26's figure: none over
100 lines; run_cli and main() at most 60).

    scripts/function_lengths.py [--over N] [ROOT]

With Universal Ctags installed (ctags --version says "Universal Ctags"), a
function's length is its last line minus its first plus one, as
`ctags --output-format=json --fields=+ne --kinds-C++=f` gives them; without
it, a brace counter over each file (a line at depth 0 ending in `) {` starts a
function, which ends where the depth returns to 0). Prints the functions over
N lines (default 100), longest first, then their count; exit 0.
"""
import json
import os
import re
import shutil
import subprocess
import sys


def sources(root):
    for top in ("src", "apps"):
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith((".cpp", ".h")):
                    yield os.path.join(d, f)


def with_ctags(paths):
    out = subprocess.run(["ctags", "--output-format=json", "--fields=+ne", "--kinds-C++=f",
                          "--languages=C++", "--language-force=C++", "-f", "-"] + paths,
                         capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        tag = json.loads(line)
        if "end" in tag:
            yield tag["path"], tag["name"], tag["line"], tag["end"] - tag["line"] + 1


HEAD = re.compile(r"^[A-Za-z].*\)\s*(const)?\s*(noexcept)?\s*(->\s*[\w:<>, ]+)?\s*\{\s*$")


def with_braces(paths):
    for path in paths:
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
        depth, start, name = 0, None, None
        for k, line in enumerate(lines):
            code = re.sub(r'"(\\.|[^"\\])*"|//.*', "", line)
            if depth == 0 and start is None and HEAD.match(code) and not code.startswith(
                    ("namespace", "struct", "class", "enum", "union")):
                start, name = k, re.sub(r"\(.*", "", code).split()[-1]
            depth += code.count("{") - code.count("}")
            if start is not None and depth == 0:
                yield path, name, start + 1, k - start + 1
                start = None


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    over = 100
    if "--over" in sys.argv:
        over = int(sys.argv[sys.argv.index("--over") + 1])
        args = [a for a in args if a != str(over)]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    paths = list(sources(root))
    ctags = shutil.which("ctags")
    universal = ctags and "Universal Ctags" in subprocess.run(
        [ctags, "--version"], capture_output=True, text=True).stdout
    rows = list(with_ctags(paths) if universal else with_braces(paths))
    print(f"{len(rows)} functions measured ({'Universal Ctags' if universal else 'brace counter'})")
    long_ones = sorted((r for r in rows if r[3] > over), key=lambda r: -r[3])
    for path, name, line, n in long_ones:
        print(f"  {n:4d}  {name}  {os.path.relpath(path, root)}:{line}")
    print(f"{len(long_ones)} function(s) over {over} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
