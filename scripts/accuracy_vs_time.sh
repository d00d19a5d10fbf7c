#!/usr/bin/env bash
# Accuracy vs time: runs every method and setting over the generated corpus and
# writes docs/accuracy-vs-time.md and docs/accuracy-vs-time.png (matplotlib).
# Takes ~10 minutes: slow methods stop after --budget seconds per cell.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
EXTRA_PACKAGES="python3-matplotlib" "$ROOT/scripts/setup.sh"
OUT="$ROOT/build/accuracy"
# Debian's python3 has Debian's matplotlib (a python3 earlier on PATH may not).
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3
mkdir -p "$OUT"
PAIRS="${PAIRS:-20}"
echo "accuracy_vs_time: corpus of $PAIRS pairs per set (stderr shows progress)" >&2
"$ROOT/build/bin/pdbench" --pairs "$PAIRS" --budget "${BUDGET:-20}" --json "$OUT/corpus.json" >&2
"$ROOT/build/bin/pdbench" --paper-tables --json "$OUT/paper.json" >&2
"$PY" "$ROOT/scripts/accuracy_vs_time.py" "$OUT/corpus.json" "$OUT/paper.json" "$ROOT/docs" \
  "$PAIRS" "${BUDGET:-20}"
echo "wrote docs/accuracy-vs-time.md and docs/accuracy-vs-time.png" >&2
