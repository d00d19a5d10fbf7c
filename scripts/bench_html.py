#!/usr/bin/env python3
"""Size and load time of the HTML report of a 10,000-part assembly in headless Chromium.

usage: python3 scripts/bench_html.py [--parts 10000] [--runs 3] [--all-overlapping]

Writes the assembly (scripts/make_assembly.py) under build/, runs
`pdcheck --html` on it, then opens the page RUNS times, each in a fresh
headless Chromium, and prints the page's size, what it holds, and the medians
of: the load event, the page ready (table, histogram and the first finding's
3D view drawn), and selecting the last finding (its 3D view drawn). The
machine's load shows in these numbers: quote them with the load average.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "browser"))
import cdp  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--parts", type=int, default=10000)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--all-overlapping", action="store_true")
    a = ap.parse_args()
    build = os.path.join(ROOT, "build")
    name = "html-bench-%d%s" % (a.parts, "-overlapping" if a.all_overlapping else "")
    scene = os.path.join(build, name + ".json")
    page = os.path.join(build, name + ".html")
    cmd = [sys.executable, os.path.join(ROOT, "scripts", "make_assembly.py"), scene,
           "--parts", str(a.parts)] + (["--all-overlapping"] if a.all_overlapping else [])
    subprocess.run(cmd, check=True)
    t0 = time.monotonic()
    run = subprocess.run([os.path.join(build, "bin", "pdcheck"), scene, "-q", "-o",
                          os.path.join(build, name + "-report.json"), "--html", page])
    wall = time.monotonic() - t0
    if run.returncode not in (0, 1):
        sys.exit("pdcheck exit %d" % run.returncode)
    text = open(page, encoding="utf-8").read()
    data = json.loads(re.search(r'<script id="pdcheck-data" type="application/json">(.*?)</script>',
                                text, re.S).group(1))
    triangles = sum(m["triangles"] for m in data["meshes"])
    with_view = sum(1 for f in data["findings"] if f.get("view"))
    print("scene: %d parts%s; pdcheck with --html: %.2f s" % (
        a.parts, " (all overlapping)" if a.all_overlapping else "", wall))
    print("page: %.2f MB (%d bytes): %d findings, %d with a 3D view, %d meshes, %d triangles"
          % (os.path.getsize(page) / 1e6, os.path.getsize(page), len(data["findings"]), with_view,
             len(data["meshes"]), triangles))
    url = "file://" + page
    load, ready, select = [], [], []
    for _ in range(a.runs):
        with cdp.Browser(timeout=120) as b:
            b.open_page()
            b.navigate(url, timeout=120)
            b.wait_for("window.pdcheck && window.pdcheck.ready", timeout=120)
            nav = b.evaluate("performance.getEntriesByType('navigation')[0].toJSON()")
            load.append(nav["loadEventEnd"] / 1000)
            ready.append(b.evaluate("pdcheck.readyMs") / 1000)
            print("  page script phases (ms since its start, which was at %s ms): %s" % (
                b.evaluate("pdcheck.ms.script_start"), b.evaluate("JSON.stringify(pdcheck.ms)")))
            last = data["findings"][-1]["fingerprint"]
            ms = b.evaluate("(() => { const t = performance.now(); location.hash = '#pair=%s'; "
                            "window.dispatchEvent(new HashChangeEvent('hashchange')); "
                            "return performance.now() - t; })()" % last)
            select.append(ms / 1000)
            if b.console_errors:
                sys.exit("console errors: %s" % b.console_errors)
    print("load event: median %.2f s (%s)" % (statistics.median(load), ", ".join("%.2f" % x for x in load)))
    print("ready (table, histogram, first 3D view): median %.2f s (%s)"
          % (statistics.median(ready), ", ".join("%.2f" % x for x in ready)))
    print("select the last finding: median %.3f s (%s)"
          % (statistics.median(select), ", ".join("%.3f" % x for x in select)))
    print("load average: %s" % open("/proc/loadavg").read().split()[:3])


if __name__ == "__main__":
    main()
