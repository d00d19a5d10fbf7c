#!/usr/bin/env bash
# Shared set-up for demo.sh and test.sh: install what is missing, configure, build (Release).
#   scripts/setup.sh demo   the build's dependencies only, and only the pdcheck binary
#   scripts/setup.sh        (test.sh) everything the tests need too, and every target
# Idempotent: a second run installs nothing and rebuilds incrementally.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODE="${1:-all}"
case "$MODE" in
  demo | all) ;;
  *) echo "usage: scripts/setup.sh [demo|all]" >&2; exit 2 ;;
esac

# What building pdcheck needs (and --html: three.js, inlined into the page).
PACKAGES=(cmake g++ make ninja-build pkg-config libeigen3-dev coinor-libipopt-dev libcli11-dev
          nlohmann-json3-dev libassimp-dev libqhull-dev libthread-pool-dev libxxhash-dev
          libcgal-dev libgmp-dev libmpfr-dev
          libocct-data-exchange-dev libtbb-dev  # STEP and .brep input (Open CASCADE 7.6)
          libzip-dev  # --bcf writes a zip
          libjs-three)  # --html inlines three.js
if [ "$MODE" = all ]; then
  PACKAGES+=(libgtest-dev python3 python3-jsonschema libxml2-utils parallel
             unzip  # the --bcf tests list and unpack its zip
             clang libclang-rt-14-dev llvm-14  # scripts/sanitize.sh: ASan, UBSan, libFuzzer, symbolizer
             chromium  # the HTML report's browser test
             openscad  # scripts/make_cad_assemblies.py: CAD test assemblies (and their ctest)
             occt-misc)  # Open CASCADE's sample parts: B-rep files nobody shaped for pdcheck
fi
# Callers may need more (accuracy_vs_time.sh: python3-matplotlib for its plot).
read -r -a EXTRA <<<"${EXTRA_PACKAGES:-}"
PACKAGES+=("${EXTRA[@]}")
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "pdcheck setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
# Ninja for a new build directory: it compiles a library's sources while the libraries below it
# still build, where make waits for them (a clean sanitizer build: 589 s with make, 475 s with
# Ninja, 2 cores). A directory configured before keeps its generator.
GEN=()
[ -f "$ROOT/build/CMakeCache.txt" ] || ! command -v ninja >/dev/null || GEN=(-G Ninja)
if [ "$MODE" = demo ]; then
  # A build directory configured before (by test.sh) keeps its tests; a new one
  # is configured without them (GoogleTest is not installed for the demo).
  TESTING=()
  [ -f "$ROOT/build/CMakeCache.txt" ] || TESTING=(-DBUILD_TESTING=OFF)
  cmake "${GEN[@]}" -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release "${TESTING[@]}" >/dev/null
  cmake --build "$ROOT/build" -j "$JOBS" --target pdcheck >&2
else
  cmake "${GEN[@]}" -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON >/dev/null
  cmake --build "$ROOT/build" -j "$JOBS" >&2
fi
