#!/usr/bin/env python3
"""The HTML report in a real headless Chromium (issue: see clashes in 3D).

usage: test_html_report.py PDCHECK SOURCE_DIR BINARY_DIR

Writes the demo scene's page with `pdcheck --html`, opens it from disk and
checks: no console errors and no request but the page itself; one table row
per finding of the JSON report, interference first; the 3D view draws the
overlap (pixels read back from the canvas) with both parts wholly in view; the
verdict banner (fail on the demo, incomplete on a run that could not read a
part); clicking a row, the arrow keys and a #pair= permalink select findings and
update the permalink; sorting and filtering; and, where WebGL is missing, the
table and details alone. Leaves the demo
screenshot in BINARY_DIR/html-report-demo.png. Exits 77 (skipped) only when
no chromium is installed.
"""
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cdp  # noqa: E402

SKIP = 77
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


# Pixels of the 3D canvas, read back through a 2D canvas: how many differ from
# the background, and how many are the overlap's red.
CANVAS_STATS = """(() => {
  const c = document.querySelector('#canvas-box canvas');
  if (!c || c.style.visibility === 'hidden') return null;
  const d = document.createElement('canvas');
  d.width = c.width; d.height = c.height;
  const x = d.getContext('2d');
  x.drawImage(c, 0, 0);
  const px = x.getImageData(0, 0, d.width, d.height).data;
  let drawn = 0, red = 0;
  for (let i = 0; i < px.length; i += 4) {
    const r = px[i], g = px[i + 1], b = px[i + 2];
    if (Math.abs(r - 251) + Math.abs(g - 252) + Math.abs(b - 253) > 24) drawn++;
    if (r > 170 && g < 90 && b < 120) red++;
  }
  return {total: px.length / 4, drawn: drawn, red: red};
})()"""

ROWS = "[...document.querySelectorAll('#findings tbody tr')]"


def visible_rows(b):
    return b.evaluate(ROWS + ".filter(r => !r.hidden).map(r => [r.cells[0].textContent, "
                      "r.cells[1].textContent, r.cells[6].title])")


def click(b, selector):
    box = b.evaluate("(() => { const r = document.querySelector(%s).getBoundingClientRect(); "
                     "return [r.x + r.width / 2, r.y + r.height / 2]; })()" % json.dumps(selector))
    for kind in ("mousePressed", "mouseReleased"):
        b.call("Input.dispatchMouseEvent", {"type": kind, "x": box[0], "y": box[1],
                                            "button": "left", "clickCount": 1})


def main():
    pdcheck, source, binary = sys.argv[1:4]
    if not cdp.find_chromium():
        print("SKIPPED: chromium is not installed (Debian package chromium; scripts/setup.sh "
              "installs it): the HTML report was not tested in a browser")
        return SKIP
    out = os.path.join(binary, "html-report-test")
    os.makedirs(out, exist_ok=True)
    page = os.path.abspath(os.path.join(out, "demo.html"))
    report = os.path.abspath(os.path.join(out, "demo.json"))
    # From the source tree: the page (and the screenshot) names the scene as
    # testdata/demo/scene.json, no path of the machine it ran on.
    run = subprocess.run([os.path.abspath(pdcheck), "testdata/demo/scene.json", "-q",
                          "-o", report, "--html", page], capture_output=True, text=True, cwd=source)
    check(run.returncode == 1, "pdcheck --html on the demo exits 1 (its interference): %d %s"
          % (run.returncode, run.stderr.strip()))
    with open(report) as f:
        pairs = json.load(f)["pairs"]
    findings = [p for p in pairs if p["status"] != "separated"]
    check(len(findings) >= 2, "the demo has findings to show (%d)" % len(findings))
    url = "file://" + os.path.abspath(page)

    t0 = time.monotonic()
    with cdp.Browser(timeout=60) as b:
        b.open_page()
        b.navigate(url, timeout=60)
        b.wait_for("window.pdcheck && window.pdcheck.ready", timeout=30)
        print("page loaded in %.2f s (browser start included)" % (time.monotonic() - t0))
        rows = visible_rows(b)
        check(len(rows) == len(findings),
              "one table row per finding: %d rows, %d findings" % (len(rows), len(findings)))
        check(sorted(r[2] for r in rows) == sorted(p["fingerprint"] for p in findings),
              "the rows are the report's findings (by fingerprint)")
        check(rows and rows[0][0] == "interference", "interference first: %s" % (rows[:1],))
        check(b.evaluate("pdcheck.webgl") is True, "WebGL is available in headless chromium")
        b.wait_for("pdcheck.renders > 0", timeout=10)
        stats = b.evaluate(CANVAS_STATS)
        print("canvas after load:", stats)
        check(stats is not None and stats["drawn"] > 0.01 * stats["total"],
              "the 3D view of the first finding is not blank")
        check(stats is not None and stats["red"] > 50,
              "the interference's overlap is drawn (red pixels: %s)" % (stats and stats["red"]))
        # Both parts wholly on the canvas (-1..1 in device coordinates).
        reach = b.evaluate("pdcheck.partsOnScreen")
        check(reach is not None and 0.3 < reach <= 1.0,
              "the first view frames both parts whole: they reach %s of the canvas" % reach)
        # The verdict, first thing on the page.
        banner = b.evaluate("(() => { const v = document.getElementById('verdict'); "
                            "const r = v.getBoundingClientRect(); "
                            "return [v.className, v.textContent, r.top, r.height]; })()")
        check(banner[0] == "fail" and b.evaluate("pdcheck.verdict") == "fail",
              "the banner says fail: %s" % banner[:2])
        check(banner[1].startswith("FAIL: 1 interference (exit code 1)") and
              ("%d false positive" % sum(p["status"] == "false_positive" for p in findings)) in banner[1],
              "the banner gives the verdict and the counts: %s" % banner[1])
        check(banner[2] < 120 and banner[3] > 10, "the banner is at the top of the page: %s" % banner[2:])
        b.screenshot(os.path.join(binary, "html-report-demo.png"))
        # Where: the first finding's `at` is marked and the view centred on it.
        first = next(p for p in findings if p["fingerprint"] == rows[0][2])
        target = b.evaluate("pdcheck.target")
        check("at" in first and b.evaluate("pdcheck.marker") is True,
              "the first finding's `at` is marked: %s" % first.get("at"))
        check(target is not None and "at" in first and
              max(abs(t - a) for t, a in zip(target, first["at"])) <= 1e-6 * (1 + max(map(abs, first["at"]))),
              "the view is centred on `at`: %s vs %s" % (target, first.get("at")))
        # Groups: one line each, every grouped finding's row names its group.
        with open(report) as f:
            groups = json.load(f)["groups"]
        check(len(groups) >= 1 and b.evaluate("document.querySelectorAll('#group-list li').length") == len(groups),
              "the page lists the report's %d groups" % len(groups))
        labels = b.evaluate(ROWS + ".map(r => [r.cells[6].title, r.cells[7].title])")
        check(all((p.get("group") or "") == dict(labels)[p["fingerprint"]] for p in findings),
              "each row names its finding's group")
        bars = b.evaluate("document.querySelectorAll('#histogram-plot rect.bar').length")
        over = b.evaluate("document.querySelectorAll('#histogram-plot rect.bar.over').length")
        n_over = sum(p["status"] == "interference" for p in findings)
        check(bars >= 2 and over >= 1 and b.evaluate("!!document.querySelector('#histogram-plot line.tol')"),
              "the histogram has bars on both sides of its tolerance line (%d bars, %d above)" % (bars, over))
        check(("%d above it" % n_over) in b.evaluate("document.getElementById('histogram-text').textContent"),
              "the histogram's text counts the %d depths above the tolerance" % n_over)

        # A click on the last row selects it and puts it in the permalink.
        last = rows[-1][2]
        before = b.evaluate("pdcheck.renders")
        click(b, "#findings tbody tr:last-child td:nth-child(4)")
        b.wait_for("pdcheck.selected === %s" % json.dumps(last), timeout=10)
        check(b.evaluate("location.hash") == "#pair=" + last,
              "a click updates the permalink: %s" % b.evaluate("location.hash"))
        check(b.evaluate("pdcheck.renders") > before, "a click redraws the 3D view")
        stats = b.evaluate(CANVAS_STATS)
        check(stats is not None and stats["drawn"] > 0.01 * stats["total"],
              "the clicked finding's 3D view is not blank: %s" % (stats,))
        reach = b.evaluate("pdcheck.partsOnScreen")
        check(reach is not None and reach <= 1.0, "the clicked finding's parts are whole in view: %s" % reach)

        # The keyboard: Home, then ArrowDown, moves the selection.
        b.key("Home", key_code=36)
        b.wait_for("pdcheck.selected === %s" % json.dumps(rows[0][2]), timeout=10)
        b.key("ArrowDown", key_code=40)
        b.wait_for("pdcheck.selected === %s" % json.dumps(rows[1][2]), timeout=10)
        check(b.evaluate("location.hash") == "#pair=" + rows[1][2],
              "ArrowDown selects the next row and updates the permalink")
        check(b.evaluate("document.activeElement.getAttribute('aria-selected')") == "true",
              "the selected row has the focus")

        # Sorting and filtering.
        click(b, "#findings th[data-key=depth] button")
        depths = [float(r[1]) for r in visible_rows(b) if r[1] != "—"]
        check(depths == sorted(depths, reverse=True), "the depth header sorts: %s" % depths)
        b.evaluate("(() => { const s = document.getElementById('status-filter'); "
                   "s.value = 'false_positive'; s.dispatchEvent(new Event('input')); })()")
        n_fp = sum(p["status"] == "false_positive" for p in findings)
        check(len(visible_rows(b)) == n_fp, "the status filter keeps the %d false positives" % n_fp)
        b.evaluate("(() => { const s = document.getElementById('status-filter'); s.value = ''; "
                   "s.dispatchEvent(new Event('input')); const q = document.getElementById('search'); "
                   "q.value = %s; q.dispatchEvent(new Event('input')); })()"
                   % json.dumps(findings[0]["b"]))
        part = findings[0]["b"]
        want = sorted(p["fingerprint"] for p in findings if part in p["a"] or part in p["b"])
        shown = sorted(r[2] for r in visible_rows(b))
        check(shown == want and len(want) < len(findings),
              "the search keeps the %d rows of part %s: %d" % (len(want), part, len(shown)))

        # A permalink opens its finding.
        b.navigate("about:blank")  # else the same page with a new hash does not reload
        b.navigate(url + "#pair=" + rows[-1][2], timeout=60)
        b.wait_for("window.pdcheck && window.pdcheck.ready", timeout=30)
        check(b.evaluate("pdcheck.selected") == rows[-1][2], "a #pair= permalink selects its finding")

        check(not b.console_errors, "no console errors: %s" % b.console_errors)
        others = [u for u in b.requests if u.split("#")[0] not in (url, "about:blank")]
        check(not others, "no request but the page itself: %s" % others)

        # Without WebGL (blocked, or no GPU path): getContext('webgl') gives
        # null, as such a browser does. The table still works and the view says why.
        b.call("Page.addScriptToEvaluateOnNewDocument", {"source": """
            const real = HTMLCanvasElement.prototype.getContext;
            HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
              return /webgl/.test(kind) ? null : real.call(this, kind, ...rest);
            };"""})
        b.navigate("about:blank")
        b.navigate(url, timeout=60)
        b.wait_for("window.pdcheck && window.pdcheck.ready", timeout=30)
        check(b.evaluate("pdcheck.webgl") is False, "without WebGL: the page knows")
        check(len(visible_rows(b)) == len(findings), "without WebGL: the table has every finding")
        check("WebGL" in b.evaluate("document.getElementById('no-view').textContent"),
              "without WebGL: the page says the 3D view needs it")
        click(b, "#findings tbody tr:last-child td:nth-child(4)")
        b.wait_for("pdcheck.selected === %s" % json.dumps(rows[-1][2]), timeout=10)
        check(b.evaluate("document.getElementById('view-info').textContent").find("depth") >= 0,
              "without WebGL: a selected finding's details are shown")
        check(not b.console_errors, "without WebGL: no console errors: %s" % b.console_errors)

    # A run that could not read a part (exit 3): incomplete, never a pass.
    with open(os.path.join(source, "testdata/demo/scene.json")) as f:
        scene = json.load(f)
    for part in scene["parts"]:
        if "mesh" in part:
            part["mesh"] = os.path.abspath(os.path.join(source, "testdata/demo", part["mesh"]))
    scene["parts"].append({"id": "lost", "mesh": os.path.abspath(os.path.join(out, "no-such-part.stl"))})
    with open(os.path.join(out, "incomplete.json"), "w") as f:
        json.dump(scene, f)
    incomplete = os.path.join(out, "incomplete.html")
    run = subprocess.run([pdcheck, os.path.join(out, "incomplete.json"), "-q", "-o",
                          os.path.join(out, "incomplete-report.json"), "--html", incomplete],
                         capture_output=True, text=True)
    check(run.returncode == 3, "a run with an unreadable part exits 3: %d %s" % (run.returncode, run.stderr.strip()))
    with cdp.Browser(timeout=60) as b:
        b.open_page()
        b.navigate("file://" + os.path.abspath(incomplete), timeout=60)
        b.wait_for("window.pdcheck && window.pdcheck.ready", timeout=30)
        banner = b.evaluate("[document.getElementById('verdict').className, "
                            "document.getElementById('verdict').textContent]")
        check(banner[0] == "incomplete" and banner[1].startswith("INCOMPLETE") and "PASS" not in banner[1]
              and "1 unusable part" in banner[1],
              "an exit-3 run's banner says incomplete: %s" % banner)
        check(not b.console_errors, "incomplete page: no console errors: %s" % b.console_errors)
    print("%d checks failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
