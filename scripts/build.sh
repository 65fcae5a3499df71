#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Installs dependencies (if missing) and builds Tessella into ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="${TESSELLA_BUILD_TYPE:-Release}" ${TESSELLA_CMAKE_ARGS:-}
cmake --build build --parallel "${TESSELLA_JOBS:-$(nproc)}"

# `import tessella` for the interpreter the Python module is built for
# (/usr/bin/python3): a tessella.pth file in its user site-packages naming
# build/python. TESSELLA_PYTHON_PTH=0 skips it (then set PYTHONPATH=build/python).
python=$(sed -n 's/^TESSELLA_PYTHON_EXECUTABLE:INTERNAL=//p' build/CMakeCache.txt)
if [ "${TESSELLA_PYTHON_PTH:-1}" != 0 ] && [ -n "$python" ] && compgen -G "build/python/tessella*.so" > /dev/null; then
  if "$python" -c 'import site, sys; sys.exit(0 if site.ENABLE_USER_SITE else 1)'; then
    site_dir=$("$python" -m site --user-site)
    mkdir -p "$site_dir"
    echo "$(pwd)/build/python" > "$site_dir/tessella.pth"
    echo "build: import tessella works in $python ($site_dir/tessella.pth -> $(pwd)/build/python)"
  else
    echo "build: $python has no user site-packages; use PYTHONPATH=$(pwd)/build/python to import tessella"
  fi
fi
