#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite; then the
# sanitizer build's run (scripts/sanitize.sh; PDCHECK_SKIP_SANITIZERS=1 skips it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
# Test-only (not for demo.sh): the SARIF multitool (npm; a self-contained .NET binary) reads the tests' SARIF back. Optional: when
# npm or the registry is missing, that one test is skipped and says so.
MT="$ROOT/build/tools/sarif-multitool"
if [ ! -x "$MT/node_modules/@microsoft/sarif-multitool-linux/Sarif.Multitool" ] && command -v npm >/dev/null; then
  echo "pdcheck setup: installing the SARIF multitool (npm) into build/tools" >&2
  npm install --prefix "$MT" --no-audit --no-fund --loglevel=error --fetch-timeout=60000 --fetch-retries=1 \
      @microsoft/sarif-multitool-linux@5.7.0 >&2 ||
    echo "pdcheck setup: the SARIF multitool could not be installed; its test will be skipped" >&2
fi

JOBS="$(nproc 2>/dev/null || echo 2)"
cd "$ROOT/build"
ctest --output-on-failure -j "$JOBS" "$@"
[ "${PDCHECK_SKIP_SANITIZERS:-0}" = 1 ] || "$ROOT/scripts/sanitize.sh"
