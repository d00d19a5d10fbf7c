#!/usr/bin/env bash
# Runs one fuzz target (tests/fuzz/README.md).
#   run.sh replay BIN TARGET          every seed and regression input, once
#   run.sh fuzz BIN TARGET WORK SECONDS [RUNS] [extra libFuzzer flags...]
#        fuzz for SECONDS (or RUNS executions, whichever ends first) on the
#        corpus WORK/corpus (seeded from the seeds and regressions), crashes
#        and hangs to WORK/artifacts; prints the executions done.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
mode=$1 bin=$2 target=$3
shift 3

# The seeds: testdata of the format, small generated files, and every
# regression input found so far.
seeds=()
case "$target" in
  scene) seeds+=("$ROOT"/testdata/demo/scene.json "$ROOT"/testdata/examples/*.json) ;;
  stl | obj | ply | gltf) seeds+=("$ROOT"/testdata/*/*."$target") ;;
  *) echo "run.sh: unknown target $target (scene, stl, obj, ply, gltf)" >&2; exit 2 ;;
esac
for dir in "$HERE/seeds/$target" "$HERE/regressions/$target"; do
  [ -d "$dir" ] && for f in "$dir"/*; do [ -f "$f" ] && seeds+=("$f"); done
done
# glb files are glTF too.
[ "$target" = gltf ] && for f in "$ROOT"/testdata/*/*.glb; do [ -f "$f" ] && seeds+=("$f"); done

case "$mode" in
  replay)
    exec "$bin" "${seeds[@]}"
    ;;
  fuzz)
    work=$1 seconds=$2 runs=${3:-0}
    shift 3 || shift $#
    mkdir -p "$work/corpus" "$work/artifacts"
    cp -n "${seeds[@]}" "$work/corpus/" 2>/dev/null || true
    dict=()
    [ -f "$HERE/dict/$target.dict" ] && dict=(-dict="$HERE/dict/$target.dict")
    log="$work/fuzz.log"
    set +e
    "$bin" "${dict[@]}" -max_total_time="$seconds" -runs="$( [ "$runs" -gt 0 ] && echo "$runs" || echo -1)" \
      -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$work/artifacts/" "$@" "$work/corpus" >"$log" 2>&1
    rc=$?
    set -e
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    # -fork=N prints no final stats: its last status line counts every job's executions.
    [ -n "$execs" ] || execs=$(grep -o "#[0-9]*: cov:" "$log" | tr -dc "0-9\n" | sort -n | tail -n 1)
    crashes=$(ls "$work/artifacts" | wc -l)
    echo "fuzz $target: ${execs:-?} executions in ${seconds}s max, exit $rc, $crashes files in $work/artifacts; log $log"
    if [ $rc -ne 0 ]; then
      grep -E "ERROR|SUMMARY|oracle failed|Test unit written|timeout" "$log" | head -n 20 >&2
      exit 1
    fi
    ;;
  *) echo "run.sh: mode is replay or fuzz" >&2; exit 2 ;;
esac
