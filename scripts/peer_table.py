#!/usr/bin/env python3
"""Prints docs/performance.md's side-by-side table of issue 29 from pdbench's JSON
(one run): the default method against exact, the default without its EPA bracket
("mlsl sampling only", the method before issue 29) and the peers compiled into
pdbench (FCL, Bullet), medians per pair on the same pairs, and each one's largest
error against exact.

usage: peer_table.py corpus.json [default method name]
"""
import json
import sys


def table_lines(rows, mlsl="mlsl tau=0.9", before="mlsl sampling only"):
    """The table's markdown lines (no peers in the run: exact and default only)."""
    out = []
    by = {(r["set"], r["method"]): r for r in rows}
    old = {r["set"]: r for r in rows if r["method"] == before}
    peers = [p for p in ("fcl", "bullet") if any(r["method"] == p for r in rows)]
    head = "| set | pairs | exact µs |" + (" sampling only µs |" if old else "") + " default µs |"
    head += "".join(f" {p} µs |" for p in peers) + " default / exact |"
    head += "".join(f" default / {p} |" for p in peers) + " max rel. err: default |"
    head += "".join(f" {p} |" for p in peers) + " default stop reasons |"
    out.append(head)
    out.append("|---|" + "---:|" * (head.count("|") - 3) + "---|")
    for s in dict.fromkeys(r["set"] for r in rows):
        e, m = by.get((s, "exact")), by.get((s, mlsl))
        if not e or not m:
            continue
        us = lambda r: f"{1000 * r['median_ms']:.3g}" if r else "–"  # noqa: E731
        line = f"| {s} | {m['pairs']} | {us(e)} |" + (f" {us(old.get(s))} |" if old else "")
        line += f" {us(m)} |" + "".join(f" {us(by.get((s, p)))} |" for p in peers)
        line += f" {m['median_ms'] / e['median_ms']:.2g} |"
        for p in peers:
            r = by.get((s, p))
            line += f" {m['median_ms'] / r['median_ms']:.2g} |" if r else " – |"
        line += f" {m['max_rel_err']:.1e} |"
        for p in peers:
            r = by.get((s, p))
            fails = f" ({r['fallbacks']} failed)" if r and r["fallbacks"] else ""
            line += f" {r['max_rel_err']:.1e}{fails} |" if r else " – |"
        stops = ", ".join(f"{k} {v}" for k, v in sorted(m.get("stop_reasons", {}).items()))
        out.append(line + f" {stops} |")
    return out


def main():
    rows = json.load(open(sys.argv[1]))
    mlsl = sys.argv[2] if len(sys.argv) > 2 else "mlsl tau=0.9"
    print("\n".join(table_lines(rows, mlsl)))


if __name__ == "__main__":
    main()
