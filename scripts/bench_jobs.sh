#!/usr/bin/env bash
# Work-queue benchmark: the 10,000-part assembly and a 2,000-pair scene of
# 100-vertex pairs, each with --jobs 1 and --jobs 2; wall time, pairs/s,
# speedup and peak memory (GNU time when present).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
OUT="$ROOT/build/bench-jobs"
mkdir -p "$OUT"
python3 "$ROOT/scripts/make_assembly.py" "$OUT/assembly-10k.json"
python3 "$ROOT/scripts/make_assembly.py" "$OUT/pairs-2000.json" --parts 4000 --vertices 100:100 \
  --all-overlapping
echo "| scene | jobs | wall s | pairs | pairs/s | peak RSS MB (main process) |"
echo "|---|---:|---:|---:|---:|---:|"
for scene in assembly-10k pairs-2000; do
  declare -A wall
  for jobs in 1 2; do
    start=$(date +%s.%N)
    if [ -x /usr/bin/time ]; then
      /usr/bin/time -f "%M" -o "$OUT/rss" "$ROOT/build/bin/pdcheck" "$OUT/$scene.json" -q \
        --jobs "$jobs" -o "$OUT/$scene-j$jobs.json" || true
      rss=$(( $(tail -n 1 "$OUT/rss") / 1024 ))  # GNU time notes a non-zero exit first
    else
      "$ROOT/build/bin/pdcheck" "$OUT/$scene.json" -q --jobs "$jobs" -o "$OUT/$scene-j$jobs.json" || true
      rss="?"
    fi
    end=$(date +%s.%N)
    w=$(python3 -c "print(f'{$end - $start:.2f}')")
    wall[$jobs]=$w
    pairs=$(python3 -c "import json; print(json.load(open('$OUT/$scene-j$jobs.json'))['summary']['candidate_pairs'])")
    echo "| $scene | $jobs | $w | $pairs | $(python3 -c "print(round($pairs / $w))") | $rss |"
  done
  echo "| $scene | speedup | $(python3 -c "print(f'{${wall[1]} / ${wall[2]}:.2f}x')") | | | |"
done
