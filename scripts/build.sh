#!/usr/bin/env bash
# Installs dependencies (if missing) and builds Tessella into ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="${TESSELLA_BUILD_TYPE:-Release}" ${TESSELLA_CMAKE_ARGS:-}
cmake --build build --parallel "${TESSELLA_JOBS:-$(nproc)}"
