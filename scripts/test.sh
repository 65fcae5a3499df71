#!/usr/bin/env bash
# The README's test command: installs dependencies, builds, runs every test.
# Tests tagged [slow] are skipped unless TESSELLA_SLOW_TESTS=1.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
cd build
ctest --output-on-failure --parallel "${TESSELLA_JOBS:-$(nproc)}"
