#!/usr/bin/env python3
"""Prints a contact table from pdbench's JSON (one run; docs/performance.md, "Contacts"):
exact and the default mlsl side by side on the same pairs, wall and CPU time.

usage: contact_table.py build/accuracy/corpus.json [mlsl method name]
"""
import json
import sys


def main():
    rows = json.load(open(sys.argv[1]))
    mlsl = sys.argv[2] if len(sys.argv) > 2 else "mlsl tau=0.9"
    by = {(r["set"], r["method"]): r for r in rows}
    print("| set | pairs | exact median ms | mlsl median ms | mlsl / exact | mlsl p99 ms "
          "| mlsl p99 CPU ms | max rel. err | median α evals | fallbacks | stop reasons |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for s in dict.fromkeys(r["set"] for r in rows):
        e, m = by.get((s, "exact")), by.get((s, mlsl))
        if not e or not m:
            continue
        stops = ", ".join(f"{k} {v}" for k, v in sorted(m.get("stop_reasons", {}).items()))
        print(f"| {s} | {m['pairs']} | {e['median_ms']:.3g} | {m['median_ms']:.3g} | "
              f"{m['median_ms'] / e['median_ms']:.2g} | {m['p99_ms']:.3g} | "
              f"{m.get('p99_cpu_ms', float('nan')):.3g} | {m['max_rel_err']:.1e} | "
              f"{m['median_alpha_evals']:.0f} | {m['fallbacks']} | {stops} |")


if __name__ == "__main__":
    main()
