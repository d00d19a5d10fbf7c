#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite; then the
# sanitizer build's run (scripts/sanitize.sh; PDCHECK_SKIP_SANITIZERS=1 skips it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
JOBS="$(nproc 2>/dev/null || echo 2)"
cd "$ROOT/build"
ctest --output-on-failure -j "$JOBS" "$@"
[ "${PDCHECK_SKIP_SANITIZERS:-0}" = 1 ] || "$ROOT/scripts/sanitize.sh"
