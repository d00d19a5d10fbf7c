#!/usr/bin/env bash
# The test suite under AddressSanitizer + UBSan (halting on the first error),
# with the fuzz targets built for libFuzzer and run briefly: a clang build in
# build-asan/ (docs/reliability.md, "Sanitizers"). Called by scripts/test.sh;
# arguments go to ctest (e.g. -R fuzz_ for the fuzz tests only).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if ! command -v clang++ >/dev/null 2>&1; then
  echo "sanitize: SKIPPED: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
  exit 0
fi
start=$(date +%s)
JOBS="$(nproc 2>/dev/null || echo 2)"
BUILD="$ROOT/build-asan"
# -O1 compiles faster than -O3 and keeps ASan's reports exact; line tables
# give the reports file:line.
GEN=()  # Ninja for a new directory (scripts/setup.sh says why)
[ -f "$BUILD/CMakeCache.txt" ] || ! command -v ninja >/dev/null || GEN=(-G Ninja)
cmake "${GEN[@]}" -S "$ROOT" -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only -DNDEBUG" \
  -DPDCHECK_SANITIZE=ON -DPDCHECK_FUZZ=ON >/dev/null
cmake --build "$BUILD" -j "$JOBS" >&2
built=$(date +%s)
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$ROOT/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# The solver accuracy sweeps (hundreds of Ipopt and qhull solves each) take 1-5
# minutes apiece under ASan; their code runs, on fewer cases, in the faster
# solver, scene and CLI tests that do run here. PDCHECK_SANITIZE_ALL=1 runs all.
# Also left out: tests whose outcome depends on wall time (time-boxed decompositions: under ASan's
# 3-10x slowdown they hit their time box and give other pieces), the contact-family test (clang -O1
# rounds a 7e-15 contact depth differently from the release build), and the HTML report's browser
# test (its pdcheck code runs under ASan in the HtmlCli tests; a browser start costs seconds), and
# the mixed-tessellation assembly (seven whole pdcheck runs with refinement, a minute each under
# ASan; its code runs under ASan in the AutoTolerance tests), and two sweeps of many generated
# cases whose code runs under ASan in their suites' other tests (the sag of 8-256 segment
# surfaces: 217 s under ASan; convex pairs against the Chebyshev centre: 78 s; a pin turned half a
# step in 16-, 32- and 64-facet bores, each also decided the strict way: 44 s, its code run by the
# shouldered pin and the exact-fit pin), and the STEP assembly stories (whole pdcheck runs with the
# exact stage on every finding, 40-75 s each under ASan; the same code runs under ASan in the
# BrepFile, BrepConfirm, ShapeMesh and RealBrepFiles tests), and four more sweeps of 17-27 s each
# under ASan whose code their suites' other tests run here (every face of a STEP file sampled densely
# against its sag bound, the sharded report merged and compared pair by pair, the contact sampling
# rules' stop reasons, the plane models' optimum on a pin in its bore). All of them run in the
# release build's suite.
# The test programs (ctest names) and GoogleTest patterns (GTEST_FILTER's syntax: the sanitizer
# build runs the tests in shards, tests/CMakeLists.txt) left to the release build:
SLOW_PROGRAMS="^(html_report_browser|auto_tolerance_mixed_assembly|step_assemblies_quick)$"
SLOW_TESTS=(TessellationSag.WithinTenPercentOfTheTrueDeviation
  OverlapThickness.ConvexPairsBracketTheChebyshevCentreAndDecideBothWays
  OverlapThickness.PinHalfAStepTurnedInItsBoreIsThinAndBracketed 'Decompose.*' 'Nonconvex.*'
  Contacts.EveryFamilyGivesTheExactDepth Exact.BoundedByDenseDirectionSampling
  Cli.JobsDoNotChangeALargerReport Checks.WarmStartGivesTheColdValues
  Checks.IpoptDistanceMatchesTheExactDistance Methods.EveryMethodIsAnUpperBoundOnExact
  Mlsl.PaperLikePairsMatchExact HardCases.TwoThousandVerticesPerPart
  StepAssemblies.OneFilePerPartAndAPartList StepAssemblies.OneAssemblyFileEveryRelationConfirmed
  BrepFile.EveryFaceLiesWithinTheSagBoundOfTheMesh Shard.MergedShardsEqualTheUnshardedReport
  Contacts.StopReasonsOfTheSamplingRules MaxMinAffine.EqualsTheExactOptimumOnAPinInItsBore)
exclude=(-E "$SLOW_PROGRAMS")
export GTEST_FILTER="-$(IFS=:; echo "${SLOW_TESTS[*]}")"
if [ "${PDCHECK_SANITIZE_ALL:-0}" = 1 ]; then
  exclude=()
  unset GTEST_FILTER
fi
# A shard's output: only the failures (and the tests' own output).
export GTEST_BRIEF=1
(cd "$BUILD" && ctest --output-on-failure -j "$JOBS" "${exclude[@]}" "$@")
end=$(date +%s)
echo "sanitize: build $((built - start)) s, tests $((end - built)) s" >&2
