#!/usr/bin/env bash
# Fuzzes one target for longer than the test suite does:
#   scripts/fuzz.sh TARGET SECONDS [libFuzzer flags...]
# TARGET: scene, stl, obj, ply, gltf, or all (each in turn, SECONDS each).
# Builds the libFuzzer + ASan + UBSan targets in build-asan/ (clang), keeps the
# corpus in build-asan/fuzz/TARGET/corpus and writes what it finds to
# build-asan/fuzz/TARGET/artifacts (a finding becomes a regression input:
# tests/fuzz/README.md). One core: targets run one after another.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ $# -ge 2 ] || { sed -n 2,8p "$0" >&2; exit 2; }
target=$1 seconds=$2
shift 2
command -v clang++ >/dev/null 2>&1 || { echo "fuzz: needs clang++ (scripts/setup.sh)" >&2; exit 2; }
BUILD="$ROOT/build-asan"
targets=("$target")
[ "$target" = all ] && targets=(scene stl obj ply gltf)
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only -DNDEBUG" \
  -DPDCHECK_SANITIZE=ON -DPDCHECK_FUZZ=ON >/dev/null
cmake --build "$BUILD" -j 2 --target "${targets[@]/#/fuzz_}" >&2
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$ROOT/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for t in "${targets[@]}"; do
  bash "$ROOT/tests/fuzz/run.sh" fuzz "$BUILD/bin/fuzz_$t" "$t" "$BUILD/fuzz/$t" "$seconds" 0 "$@" || status=1
done
exit $status
