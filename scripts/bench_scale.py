#!/usr/bin/python3
"""pdcheck at the scale users have: time, peak memory of all its processes, relations right.

usage: /usr/bin/python3 scripts/bench_scale.py SCENE_DIR [SCENE_DIR ...] [--out OUT]
           [--pdcheck build/bin/pdcheck] [--jobs 2] [--runs 1] [--modes cold,hull,numpy]
           [--mode NAME=ARGS ...] [--timeout 3600] [--max-memory 19000] [--interval 0.05]
           [-- PDCHECK_ARGS ...]

Issue 45. Each SCENE_DIR is written by scripts/make_scale_assembly.py (scene.json, expected.json,
binary STL files). Run it with /usr/bin/python3: the numpy baseline needs numpy and scipy
(Debian's python3-numpy and python3-scipy); without them that mode is reported as skipped.

Modes (--modes, comma-separated, in this order per scene and run):
  cold     the default (pieces auto) with an empty --cache directory
  nocache  the default with --no-cache
  hull     --pieces hull --no-cache
  shard4   4 shards one after another (`--shard K/4 --no-cache`, as on 4 machines without a
           shared cache), then `pdcheck merge`; the merged report is scored, the peak is the
           largest shard's, each shard's peak is listed
  numpy    the floor a user could write in a few lines, in one process: read every STL with
           numpy.fromfile on the binary STL record dtype, weld nothing, scipy.spatial.ConvexHull
           (qhull) of the float64 points
  --mode NAME=ARGS adds a mode running `pdcheck SCENE --jobs J ARGS` (e.g. --mode
           "mem512=--no-cache --memory 512M"). Arguments after `--` go to every pdcheck run
           (not to the merge).

Measured per run: wall seconds; CPU seconds (user + system of the process and the children it
waited for, wait4); the peak over time of the SUM over pdcheck's process tree (the main process,
its worker and loader processes: /proc/PID/task/*/children walked from the pdcheck pid every
--interval seconds) of RSS and of PSS (/proc/PID/smaps_rollup; PSS counts a page shared by k
processes 1/k in each, so its sum is the honest "together" figure for forked workers); the
report's stage_seconds; nominal relations right against expected.json (scripts/
bench_cad_assemblies.py's scoring: contact = separated or false_positive, clearance =
separated, interference = interference, a pair culled counts as separated) and the undecided
pairs. The samples are labelled with the stage in progress (from the report's stage_seconds laid
end to end from the start, and the last progress line pdcheck printed); the peak PSS per stage is
printed, and the series (every 0.5 s) kept in OUT/results.json.

Progress on stderr (pdcheck's own progress lines with the elapsed time and the current PSS sum);
a markdown table on stdout; OUT/results.json. A run past --timeout, or whose PSS sum passes
--max-memory MB (or the machine's MemAvailable falls below 1 GB), is killed (its process group)
and reported as such.
"""
import argparse
import importlib.util
import json
import os
import re
import shlex
import shutil
import signal
import statistics
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("bench_cad_assemblies", os.path.join(HERE, "bench_cad_assemblies.py"))
bca = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bca)

STAGES = ("load", "parts", "broad_phase", "solve", "refine", "exact")
BUILTIN = ("cold", "nocache", "hull", "shard4", "numpy")
PAGE = os.sysconf("SC_PAGE_SIZE")


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# --- process-tree memory --------------------------------------------------------------------

def tree(root):
    pids, todo = [], [root]
    while todo:
        pid = todo.pop()
        pids.append(pid)
        try:
            for tid in os.listdir("/proc/%d/task" % pid):
                with open("/proc/%d/task/%s/children" % (pid, tid)) as f:
                    todo += [int(x) for x in f.read().split()]
        except (FileNotFoundError, ProcessLookupError, PermissionError):
            pass
    return pids


def rss_pss(pid):
    """(RSS, PSS) in bytes from /proc/PID/smaps_rollup; (0, 0) when it is gone."""
    rss = pss = 0
    try:
        with open("/proc/%d/smaps_rollup" % pid) as f:
            for line in f:
                if line.startswith("Rss:"):
                    rss = int(line.split()[1]) * 1024
                elif line.startswith("Pss:"):
                    pss = int(line.split()[1]) * 1024
    except (FileNotFoundError, ProcessLookupError, PermissionError):
        pass
    return rss, pss


def mem_available_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) / 1024.0
    return float("inf")


def run_measured(cmd, a, label):
    """Runs cmd in a session of its own, sampling its process tree. Returns a dict."""
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    state = {"what": "start", "lines": []}
    samples = []
    out_chunks = []

    def read_err():
        for raw in proc.stderr:
            line = raw.decode(errors="replace").rstrip()
            t = time.monotonic() - t0
            state["lines"].append((t, line))
            m = re.match(r"pdcheck: \d+/\d+ (.+?) \(\d+%\)", line)
            if m:
                state["what"] = m.group(1)
            if re.match(r"pdcheck: (fails --fail-on|group |\u2026 and )", line):
                continue
            pss = samples[-1][2] / 1e6 if samples else 0.0
            log("  [%s %6.1f s, PSS %6.0f MB] %s" % (label, t, pss, line))

    def read_out():
        out_chunks.append(proc.stdout.read())
    threads = [threading.Thread(target=read_err, daemon=True), threading.Thread(target=read_out, daemon=True)]
    for th in threads:
        th.start()
    killed = None
    status = usage = None
    while True:
        pid, st, ru = os.wait4(proc.pid, os.WNOHANG)
        if pid == proc.pid:
            status, usage = st, ru
            break
        t = time.monotonic() - t0
        rss = pss = 0
        pids = tree(proc.pid)
        for p in pids:
            r, s = rss_pss(p)
            rss += r
            pss += s
        samples.append((t, rss, pss, len(pids), state["what"]))
        if killed is None:
            if t > a.timeout:
                killed = "timed out after %g s" % a.timeout
            elif pss / 1e6 > a.max_memory:
                killed = "killed: PSS sum %.0f MB > --max-memory %g MB" % (pss / 1e6, a.max_memory)
            elif mem_available_mb() < 1024:
                killed = "killed: the machine's MemAvailable fell below 1 GB (PSS sum %.0f MB)" % (pss / 1e6)
            if killed:
                log("  [%s] %s" % (label, killed))
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
        time.sleep(a.interval)
    wall = time.monotonic() - t0
    for th in threads:
        th.join(timeout=10)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return {"cmd": cmd, "wall": wall, "cpu": usage.ru_utime + usage.ru_stime, "code": proc.returncode,
            "killed": killed, "peak_rss_mb": max((s[1] for s in samples), default=0) / 1e6,
            "peak_pss_mb": max((s[2] for s in samples), default=0) / 1e6,
            "max_procs": max((s[3] for s in samples), default=0), "samples": samples,
            "stderr": state["lines"], "stdout": b"".join(x for x in out_chunks if x)}


def stage_of(t, stage_seconds):
    acc = 0.0
    for k, v in stage_seconds.items():
        acc += v
        if t <= acc:
            return k
    return "after stages"


def memory_by_stage(res, stage_seconds):
    """Peak PSS sum (MB) and its time per stage (stage_seconds laid end to end from the start)."""
    out = {}
    for t, rss, pss, n, what in res["samples"]:
        k = stage_of(t, stage_seconds) if stage_seconds else what
        if k not in out or pss / 1e6 > out[k]["peak_pss_mb"]:
            out[k] = {"peak_pss_mb": pss / 1e6, "peak_rss_mb": rss / 1e6, "at_s": t, "procs": n,
                      "progress": what}
    return out


def series(res, stage_seconds, every=0.5):
    pts, nxt = [], 0.0
    for t, rss, pss, n, what in res["samples"]:
        if t >= nxt:
            pts.append([round(t, 2), round(pss / 1e6, 1), round(rss / 1e6, 1), n,
                        stage_of(t, stage_seconds) if stage_seconds else "", what])
            nxt = t + every
    return pts


# --- the numpy + qhull floor -----------------------------------------------------------------

def numpy_baseline(scene_path):
    import numpy as np
    from scipy.spatial import ConvexHull
    rec = np.dtype([("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    scene = json.load(open(scene_path))
    base = os.path.dirname(os.path.abspath(scene_path))
    t0 = time.perf_counter()
    read = hull = 0.0
    tris = verts = 0
    for p in scene["parts"]:
        t1 = time.perf_counter()
        data = np.fromfile(os.path.join(base, p["mesh"]), dtype=rec, offset=84)
        pts = data["v"].reshape(-1, 3).astype(np.float64)
        if "transform" in p:
            M = np.array(p["transform"], dtype=np.float64)
            pts = pts @ M[:3, :3].T + M[:3, 3]
        t2 = time.perf_counter()
        h = ConvexHull(pts)
        t3 = time.perf_counter()
        read += t2 - t1
        hull += t3 - t2
        tris += len(data)
        verts += len(h.vertices)
    print(json.dumps({"seconds": time.perf_counter() - t0, "read_s": read, "hull_s": hull, "parts": len(scene["parts"]),
                      "triangles": tris, "hull_vertices": verts}))


# --- modes -----------------------------------------------------------------------------------

def pdcheck_run(a, scene, name, args, report, label):
    cmd = [a.pdcheck, scene, "--jobs", str(a.jobs), "-o", report] + args + a.passthrough
    if os.path.exists(report):
        os.remove(report)
    res = run_measured(cmd, a, label)
    res["report"] = None
    if res["killed"] is None and res["code"] in (0, 1, 3) and os.path.exists(report):
        try:
            res["report"] = json.load(open(report))
        except ValueError as e:
            res["error"] = "report does not parse (%s)" % e
    elif res["killed"] is None:
        res["error"] = "exit %d: %s" % (res["code"], " | ".join(l for _, l in res["stderr"][-3:]))
    else:
        res["error"] = res["killed"]
    return res


def score(report, expected):
    ok, wrong, unlisted = bca.score(report, expected)
    undecided = sum(1 for p in report["pairs"] if p["status"] == "undecided")
    return {"right": ok, "total": len(expected["pairs"]), "undecided": undecided,
            "unlisted_flagged": len(unlisted),
            "wrong": [bca.describe(*w) for w in wrong[:20]], "wrong_count": len(wrong)}


def run_mode(a, sdir, mode, extra, r):
    scene = os.path.join(sdir, "scene.json")
    tag = "%s-%s-%d" % (os.path.basename(os.path.normpath(sdir)), mode, r)
    work = os.path.join(a.out, "runs", tag)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    label = "%s %s" % (os.path.basename(os.path.normpath(sdir)), mode)
    if mode == "numpy":
        res = run_measured([sys.executable, os.path.abspath(__file__), "--numpy-baseline", scene], a, label)
        res["report"] = None
        if res["code"] != 0 or res["killed"]:
            res["error"] = res["killed"] or "exit %d: %s" % (res["code"], " | ".join(l for _, l in res["stderr"][-3:]))
        else:
            res["numpy"] = json.loads(res["stdout"].decode())
        return res
    if mode == "shard4":
        shards, paths = [], []
        for k in range(1, 5):
            p = os.path.join(work, "shard-%d.json" % k)
            s = pdcheck_run(a, scene, mode, ["--shard", "%d/4" % k, "--no-cache", "-q"], p, "%s %d/4" % (label, k))
            shards.append(s)
            paths.append(p)
            if s.get("error"):
                return {"wall": sum(x["wall"] for x in shards), "error": "shard %d: %s" % (k, s["error"]),
                        "shards": shards, "report": None}
        merged = os.path.join(work, "merged.json")
        m = run_measured([a.pdcheck, "merge"] + paths + ["-q", "-o", merged], a, label + " merge")
        res = {"wall": sum(x["wall"] for x in shards) + m["wall"], "cpu": sum(x["cpu"] for x in shards) + m["cpu"],
               "peak_pss_mb": max(x["peak_pss_mb"] for x in shards), "peak_rss_mb": max(x["peak_rss_mb"] for x in shards),
               "shards": shards, "merge": m, "report": None, "killed": None, "samples": []}
        if m["code"] in (0, 1, 3) and os.path.exists(merged):
            res["report"] = json.load(open(merged))
            st = {}
            for x in shards:
                for k2, v in x["report"].get("stage_seconds", {}).items():
                    st[k2] = st.get(k2, 0.0) + v
            res["report"]["stage_seconds"] = st
        else:
            res["error"] = "merge exit %d" % m["code"]
        return res
    if mode == "cold":
        cache = os.path.join(work, "cache")
        os.makedirs(cache)
        args = ["--cache", cache]
    elif mode == "nocache":
        args = ["--no-cache"]
    elif mode == "hull":
        args = ["--pieces", "hull", "--no-cache"]
    else:
        args = shlex.split(extra)
    res = pdcheck_run(a, scene, mode, args, os.path.join(work, "report.json"), label)
    if mode == "cold":
        shutil.rmtree(os.path.join(work, "cache"), ignore_errors=True)
    return res


def slim(res, stage_seconds):
    out = {k: v for k, v in res.items() if k not in ("samples", "stderr", "stdout", "report", "shards", "merge")}
    if res.get("samples"):
        out["memory_by_stage"] = memory_by_stage(res, stage_seconds)
        out["series"] = series(res, stage_seconds)
    out["stderr_tail"] = [l for _, l in res.get("stderr", [])[-5:]]
    if "shards" in res:
        out["shards"] = [slim(s, (s.get("report") or {}).get("stage_seconds")) for s in res["shards"]]
        out["merge"] = slim(res["merge"], None) if "merge" in res else None
    return out


def fmt(x, f="%.2f"):
    return "-" if x is None else f % x


def main():
    argv = sys.argv[1:]
    if argv[:1] == ["--numpy-baseline"]:
        numpy_baseline(argv[1])
        return
    passthrough = []
    if "--" in argv:
        k = argv.index("--")
        argv, passthrough = argv[:k], argv[k + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="+", metavar="SCENE_DIR")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "build", "bench_scale"))
    ap.add_argument("--pdcheck", default=os.path.join(HERE, "..", "build", "bin", "pdcheck"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--modes", default="cold,hull,numpy", help="comma-separated, of %s" % ",".join(BUILTIN))
    ap.add_argument("--mode", action="append", default=[], metavar="NAME=ARGS",
                    help="a mode of your own: pdcheck SCENE --jobs J ARGS")
    ap.add_argument("--timeout", type=float, default=3600.0, help="seconds per process")
    ap.add_argument("--max-memory", type=float, default=19000.0, help="MB of PSS sum at which a run is killed")
    ap.add_argument("--interval", type=float, default=0.05, help="seconds between /proc samples")
    a = ap.parse_args(argv)
    a.passthrough = passthrough
    a.pdcheck = os.path.abspath(a.pdcheck)
    if not (os.path.isfile(a.pdcheck) and os.access(a.pdcheck, os.X_OK)):
        ap.error("no pdcheck executable at %s" % a.pdcheck)
    modes = [(m, None) for m in a.modes.split(",") if m]
    for m, _ in modes:
        if m not in BUILTIN:
            ap.error("unknown mode %r (%s, or --mode NAME=ARGS)" % (m, ", ".join(BUILTIN)))
    for spec_ in a.mode:
        if "=" not in spec_:
            ap.error("--mode takes NAME=ARGS")
        n, args = spec_.split("=", 1)
        modes.append((n, args))
    if any(m == "numpy" for m, _ in modes):
        try:
            import numpy  # noqa: F401
            import scipy.spatial  # noqa: F401
        except ImportError:
            log("numpy or scipy missing for %s (run with /usr/bin/python3; Debian python3-numpy python3-scipy): "
                "the numpy mode is skipped" % sys.executable)
            modes = [m for m in modes if m[0] != "numpy"]
    os.makedirs(a.out, exist_ok=True)
    a.version = subprocess.run([a.pdcheck, "--version"], capture_output=True, text=True).stdout.strip()
    rows = []
    for sdir in a.scenes:
        expected = json.load(open(os.path.join(sdir, "expected.json")))
        tris = sum(p["triangles"] for p in expected["parts"].values())
        nparts = len(expected["parts"])
        sname = os.path.basename(os.path.normpath(sdir))
        log("%s: %d parts, %d triangles, %d relations" % (sname, nparts, tris, len(expected["pairs"])))
        for mode, extra in modes:
            runs = []
            for r in range(a.runs):
                log("%s %s, run %d/%d" % (sname, mode, r + 1, a.runs))
                res = run_mode(a, sdir, mode, extra, r)
                runs.append(res)
                rep = res.get("report")
                st = rep.get("stage_seconds") if rep else None
                log("%s %s, run %d: wall %.1f s, peak PSS %.0f MB, peak RSS %.0f MB%s" % (
                    sname, mode, r + 1, res["wall"], res.get("peak_pss_mb", 0), res.get("peak_rss_mb", 0),
                    ", " + res["error"] if res.get("error") else ""))
                if res.get("samples") and mode != "shard4":
                    for k, v in memory_by_stage(res, st).items():
                        log("    peak PSS during %-12s %7.0f MB at %6.1f s (%d processes; progress: %s)" % (
                            k, v["peak_pss_mb"], v["at_s"], v["procs"], v["progress"]))
                for k, s in enumerate(res.get("shards", [])):
                    log("    shard %d/4: wall %.1f s, peak PSS %.0f MB, peak RSS %.0f MB" % (
                        k + 1, s["wall"], s["peak_pss_mb"], s["peak_rss_mb"]))
            last = runs[-1]
            rep = last.get("report")
            row = {"scene": sname, "dir": os.path.abspath(sdir), "triangles": tris, "parts": nparts, "mode": mode,
                   "args": extra, "runs": [slim(x, (x.get("report") or {}).get("stage_seconds")) for x in runs],
                   "wall": statistics.median(x["wall"] for x in runs),
                   "cpu": statistics.median(x.get("cpu", 0.0) for x in runs),
                   "peak_pss_mb": max(x.get("peak_pss_mb", 0.0) for x in runs),
                   "peak_rss_mb": max(x.get("peak_rss_mb", 0.0) for x in runs),
                   "error": last.get("error"), "stage_seconds": rep.get("stage_seconds") if rep else None,
                   "score": score(rep, expected) if rep else None}
            if mode == "numpy" and last.get("numpy"):
                row["numpy"] = last["numpy"]
            if row["score"] and row["score"]["wrong"]:
                show = 3 if mode == "hull" else 20  # a hull's depth only bounds a nonconvex part's
                for w in row["score"]["wrong"][:show]:
                    log("    wrong: " + w)
                if row["score"]["wrong_count"] > show:
                    log("    ... %d wrong in all" % row["score"]["wrong_count"])
            rows.append(row)
            with open(os.path.join(a.out, "results.json"), "w") as f:
                json.dump({"pdcheck": a.pdcheck, "version": a.version, "jobs": a.jobs, "runs": a.runs, "passthrough": passthrough,
                           "rows": rows}, f, indent=1)

    def wall_of(scene, mode):
        for r in rows:
            if r["scene"] == scene and r["mode"] == mode and not r["error"]:
                return r["wall"]
        return None
    print("| scene | triangles | parts | mode | wall s | CPU s | peak PSS MB | peak RSS MB | stages (s) | relations right "
          "| undecided | default/hull | hull/numpy |")
    print("|---|---:|---:|---|---:|---:|---:|---:|---|---:|---:|---:|---:|")
    for r in rows:
        hull, npy = wall_of(r["scene"], "hull"), wall_of(r["scene"], "numpy")
        dh = r["wall"] / hull if hull and r["mode"] in ("cold", "nocache") and not r["error"] else None
        hn = r["wall"] / npy if npy and r["mode"] == "hull" and not r["error"] else None
        st = r["stage_seconds"]
        if r["mode"] == "numpy" and r.get("numpy"):
            stages = "read %.1f, hull %.1f" % (r["numpy"]["read_s"], r["numpy"]["hull_s"])
        else:
            stages = ", ".join("%s %.1f" % (k, v) for k, v in st.items() if v >= 0.05) if st else "-"
        sc = r["score"]
        name = r["mode"] + (" (%s)" % r["args"] if r["args"] else "")
        if r["error"]:
            name += " **%s**" % r["error"][:60]
        print("| %s | %d | %d | %s | %.1f | %.1f | %.0f | %.0f | %s | %s | %s | %s | %s |" % (
            r["scene"], r["triangles"], r["parts"], name, r["wall"], r["cpu"], r["peak_pss_mb"], r["peak_rss_mb"],
            stages, "%d/%d" % (sc["right"], sc["total"]) if sc else "-", sc["undecided"] if sc else "-",
            fmt(dh, "%.2fx"), fmt(hn, "%.2fx")))
        if r["mode"] == "shard4" and r["runs"][-1].get("shards"):
            print("|  |  |  | shards: " + "; ".join("%d/4 %.1f s %.0f MB PSS" % (k + 1, s["wall"], s["peak_pss_mb"])
                                                  for k, s in enumerate(r["runs"][-1]["shards"])) +
                  " | | | | | | | | | |")
    print("\n--jobs %d, %s of %d run(s); peaks: the largest sum over the process tree, sampled every %g s; "
          "%s%s" % (a.jobs, "median wall" if a.runs > 1 else "one", a.runs, a.interval, a.version,
                    (", with " + " ".join(passthrough)) if passthrough else ""))


if __name__ == "__main__":
    main()
