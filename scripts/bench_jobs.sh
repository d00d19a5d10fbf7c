#!/usr/bin/env bash
# Work-queue benchmark: the 10,000-part assembly and a 2,000-pair scene of
# 100-vertex pairs, each with --jobs 1 and --jobs 2 (REPEAT runs each, default 3;
# medians). Prints the table of docs/performance.md.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
OUT="$ROOT/build/bench-jobs"
mkdir -p "$OUT"
python3 "$ROOT/scripts/make_assembly.py" "$OUT/assembly-10k.json"
python3 "$ROOT/scripts/make_assembly.py" "$OUT/pairs-2000.json" --parts 4000 --vertices 100:100 \
  --all-overlapping
python3 "$ROOT/scripts/bench_jobs.py" "$ROOT/build/bin/pdcheck" "$OUT" "${REPEAT:-3}" \
  "$OUT/assembly-10k.json" "$OUT/pairs-2000.json"
