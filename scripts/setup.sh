#!/usr/bin/env bash
# Shared set-up for demo.sh and test.sh: install what is missing, configure, build (Release).
# Idempotent: a second run installs nothing and rebuilds incrementally.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

PACKAGES=(cmake g++ make pkg-config libeigen3-dev coinor-libipopt-dev libcli11-dev
          nlohmann-json3-dev libassimp-dev libqhull-dev libthread-pool-dev libxxhash-dev libgtest-dev
          libcgal-dev libgmp-dev libmpfr-dev python3 python3-jsonschema libxml2-utils parallel
          libocct-data-exchange-dev libtbb-dev  # STEP and .brep input (Open CASCADE 7.6)
          libzip-dev unzip  # --bcf writes a zip (libzip); its tests list and unpack it
          clang libclang-rt-14-dev llvm-14  # scripts/sanitize.sh: ASan, UBSan, libFuzzer, symbolizer
          libjs-three chromium  # the HTML report: three.js inlined in it; its browser test
          openscad)  # scripts/make_cad_assemblies.py: CAD test assemblies (and their ctest)
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
cmake -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$ROOT/build" -j "$JOBS" >&2
