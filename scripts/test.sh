#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# The README's test command: installs dependencies, builds, runs every test.
# Tests tagged [slow] are skipped unless TESSELLA_SLOW_TESTS=1.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
cd build
ctest --output-on-failure --parallel "${TESSELLA_JOBS:-$(nproc)}"
