#!/usr/bin/env bash
# Fuzzes one target for longer than the test suite does:
#   scripts/fuzz.sh [--fast] TARGET SECONDS [libFuzzer flags...]
# TARGET: scene, stl, obj, ply, gltf, or all (each in turn, SECONDS each).
# Default: libFuzzer + ASan + UBSan targets in build-asan/ (clang).
# --fast: libFuzzer + UBSan only, -O2, in build-fuzz/ (several times the
# executions per second), then every input of the corpus it grew is replayed
# once under ASan + UBSan (build-asan/), so memory errors are still looked for
# on everything the fast run reached.
# The corpus stays in BUILD/fuzz/TARGET/corpus, findings go to
# BUILD/fuzz/TARGET/artifacts (a finding becomes a regression input:
# tests/fuzz/README.md). One core: targets run one after another.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
fast=0
[ "${1:-}" = --fast ] && { fast=1; shift; }
[ $# -ge 2 ] || { sed -n 2,13p "$0" >&2; exit 2; }
target=$1 seconds=$2
shift 2
command -v clang++ >/dev/null 2>&1 || { echo "fuzz: needs clang++ (scripts/setup.sh)" >&2; exit 2; }
targets=("$target")
[ "$target" = all ] && targets=(scene stl obj ply gltf)

configure() {  # BUILD SANITIZERS OPT
  local gen=()  # Ninja for a new directory (scripts/setup.sh says why)
  [ -f "$1/CMakeCache.txt" ] || ! command -v ninja >/dev/null || gen=(-G Ninja)
  cmake "${gen[@]}" -S "$ROOT" -B "$1" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="$3 -gline-tables-only -DNDEBUG" \
    -DPDCHECK_SANITIZE=ON -DPDCHECK_SANITIZERS="$2" -DPDCHECK_FUZZ=ON >/dev/null
  cmake --build "$1" -j 2 --target "${targets[@]/#/fuzz_}" >&2
}
ASAN="$ROOT/build-asan"
FAST="$ROOT/build-fuzz"
configure "$ASAN" address,undefined -O1
[ $fast = 1 ] && configure "$FAST" undefined -O2
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$ROOT/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for t in "${targets[@]}"; do
  if [ $fast = 1 ]; then
    bash "$ROOT/tests/fuzz/run.sh" fuzz "$FAST/bin/fuzz_$t" "$t" "$FAST/fuzz/$t" "$seconds" 0 "$@" || status=1
    n=$(ls "$FAST/fuzz/$t/corpus" | wc -l)
    mkdir -p "$FAST/fuzz/$t/asan-artifacts"
    if "$ASAN/bin/fuzz_$t" -runs=0 -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$FAST/fuzz/$t/asan-artifacts/" "$FAST/fuzz/$t/corpus" \
      >"$FAST/fuzz/$t/asan-replay.log" 2>&1; then
      echo "asan replay $t: all $n corpus inputs clean"
    else
      echo "asan replay $t: FAILED, see $FAST/fuzz/$t/asan-replay.log" >&2
      status=1
    fi
  else
    bash "$ROOT/tests/fuzz/run.sh" fuzz "$ASAN/bin/fuzz_$t" "$t" "$ASAN/fuzz/$t" "$seconds" 0 "$@" || status=1
  fi
done
exit $status
