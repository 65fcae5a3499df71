#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Installs the Debian packages Tessella builds, tests and runs with.
# Idempotent: packages already present are skipped; safe to run again.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libtet1.5-dev
  libvtk9-dev zlib1g-dev libyaml-cpp-dev libcli11-dev libfmt-dev libmuparser-dev
  catch2
  # libopenblas0-serial: an optimised single-threaded BLAS (the system's libblas.so.3) for CHOLMOD's
  # supernodal factorisation, ~6x the reference BLAS on 3D membrane tangents (docs/mechanics.md, "Cost")
  libsuitesparse-dev libhypre-dev libopenblas0-serial
  python3-dev pybind11-dev python3-numpy python3-pytest python3-pil
  libcairo2-dev snakemake python3-matplotlib chromium libdeflate-dev
  libsundials-dev python3-scipy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
