#!/usr/bin/env python3
"""The documents a user reads first, checked against the product.

usage: test_docs.py PDCHECK SOURCE_DIR BINARY_DIR

- README's first screen: the job in a sentence or two, then the two commands
  (bash scripts/demo.sh, bash scripts/test.sh) before anything else, then a
  scene for your own parts and the command that checks it: the scene is read
  by pdcheck (and valid against docs/scene.schema.json when python3-jsonschema
  is installed) on stand-in meshes, and the command writes its HTML page.
- Every relative link in README.md and docs/*.md names a file that exists and,
  for a Markdown file, a heading it has (GitHub's anchors).
"""
import json
import os
import re
import shutil
import subprocess
import sys

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def fenced_blocks(text):
    """(language, body, line of the opening fence) of each fenced block."""
    out = []
    for m in re.finditer(r"^```(\w*)\n(.*?)^```", text, re.S | re.M):
        out.append((m.group(1), m.group(2), text.count("\n", 0, m.start()) + 1))
    return out


def anchor(heading):
    h = heading.strip().lower()
    h = re.sub(r"[^\w\- ]", "", h)
    return h.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        found, seen, in_code = set(), {}, False
        for line in open(path, encoding="utf-8"):
            if line.startswith("```"):
                in_code = not in_code
            m = None if in_code else re.match(r"^#+\s+(.*)", line)
            if m:
                a = anchor(m.group(1))
                n = seen.get(a, 0)
                seen[a] = n + 1
                found.add(a if n == 0 else "%s-%d" % (a, n))
        cache[path] = found
    return cache[path]


def check_links(source):
    docs = os.path.join(source, "docs")
    files = [os.path.join(source, "README.md")] + sorted(
        os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    bad = []
    for path in files:
        text = open(path, encoding="utf-8").read()
        for m in re.finditer(r"\]\(([^)\s]+)\)", text):
            link = m.group(1)
            if re.match(r"^[a-z]+:", link):
                continue
            target, _, fragment = link.partition("#")
            full = os.path.normpath(os.path.join(os.path.dirname(path), target)) if target else path
            where = "%s: %s" % (os.path.relpath(path, source), link)
            if not os.path.exists(full):
                bad.append(where + " (no such file)")
            elif fragment and full.endswith(".md") and fragment not in anchors(full):
                bad.append(where + " (no such heading)")
    check(not bad, "every link in README.md and docs/*.md leads somewhere: %s" % bad)


def check_first_screen(pdcheck, source, binary):
    text = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    blocks = fenced_blocks(text)
    check(len(blocks) >= 3, "README has code blocks")
    if len(blocks) < 3:
        return
    lang, body, line = blocks[0]
    commands = [l.split("#")[0].strip() for l in body.splitlines() if l.split("#")[0].strip()]
    check(commands == ["bash scripts/demo.sh", "bash scripts/test.sh"] and line <= 12,
          "the first commands are the demo and the tests, on the first screen: %s (line %d)"
          % (commands, line))
    scene_blocks = [(b, n) for lang, b, n in blocks if lang == "json"]
    check(scene_blocks and scene_blocks[0][1] <= 40,
          "a scene for your own parts on the first screen (line %s)"
          % (scene_blocks[0][1] if scene_blocks else None))
    if not scene_blocks:
        return
    scene_text, scene_line = scene_blocks[0]
    after = [b for lang, b, n in blocks if n > scene_line and lang == "sh"]
    run = next((l.split("#")[0].strip() for b in after[:1] for l in b.splitlines()
                if l.startswith("build/bin/pdcheck ")), None)
    check(run is not None and "--html" in run,
          "the command after the scene checks it and writes the page: %s" % run)
    if run is None:
        return
    scene = json.loads(scene_text)
    try:
        import jsonschema
        with open(os.path.join(source, "docs/scene.schema.json")) as f:
            jsonschema.validate(scene, json.load(f))
        check(True, "the README's scene is valid against docs/scene.schema.json")
    except ImportError:
        print("skipped: the schema check (python3-jsonschema is not installed)")
    except Exception as e:  # jsonschema.ValidationError
        check(False, "the README's scene is valid against docs/scene.schema.json: %s" % e)
    # The scene on stand-in meshes (the demo's, by format), run as the README says.
    work = os.path.join(binary, "docs-test")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    stand_in = {".stl": "base.stl", ".obj": "cover.obj", ".ply": "pin.ply", ".gltf": "bracket.gltf"}
    for part in scene["parts"]:
        if "mesh" in part:
            ext = os.path.splitext(part["mesh"])[1].lower()
            shutil.copy(os.path.join(source, "testdata/demo", stand_in[ext]),
                        os.path.join(work, part["mesh"]))
    name = run.split()[1]
    with open(os.path.join(work, name), "w") as f:
        f.write(scene_text)
    args = [os.path.abspath(pdcheck)] + run.split()[2:]
    done = subprocess.run(args[:1] + [name] + args[1:], cwd=work, capture_output=True, text=True)
    page = run.split("--html")[1].split()[0]
    check(done.returncode in (0, 1) and os.path.exists(os.path.join(work, page)),
          "the README's command checks its scene and writes the page: exit %d %s"
          % (done.returncode, done.stderr.strip()[-300:]))


def main():
    pdcheck, source, binary = sys.argv[1:4]
    check_first_screen(pdcheck, source, binary)
    check_links(source)
    print("%d checks failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
