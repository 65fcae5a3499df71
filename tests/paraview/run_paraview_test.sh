#!/bin/bash
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# End-to-end check that ParaView opens Tessella series: writes a small series,
# renders it with paraview/render_series.py under pvbatch, and compares what
# ParaView read with what was written.
#
#   run_paraview_test.sh WRITE_EXAMPLE_SERIES RENDER_SERIES_PY CHECK_RENDER_PY WORK_DIR
#
# Exit code 77 (CTest: skipped) when ParaView cannot be installed here.
set -euo pipefail
writer=$1 script=$2 checker=$3 work=$4

# ParaView and a virtual X server, installed once (dpkg check first: reruns are fast).
if ! dpkg -s paraview xvfb xauth >/dev/null 2>&1; then
  echo "installing paraview and xvfb (first run only)"
  if ! (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends paraview xvfb xauth) >"$work.apt.log" 2>&1; then
    echo "SKIP: could not install paraview/xvfb (see $work.apt.log)"; exit 77
  fi
fi

# pvbatch needs ParaView's Python modules (package python3-paraview). That
# package conflicts with python3-vtk9, on which libvtk9-dev (our build
# dependency) depends, so installing it would uninstall VTK's headers. Its
# files are unpacked into a private directory instead, found via PYTHONPATH.
pvpython_dir=
if ! dpkg -s python3-paraview >/dev/null 2>&1; then
  cache=$(dirname "$work")/python3-paraview
  pvpython_dir=$cache/root/usr/lib/python3/dist-packages
  if [ ! -f "$pvpython_dir/paraview/simple.py" ]; then
    rm -rf "$cache" && mkdir -p "$cache"
    if ! (cd "$cache" && apt-get download python3-paraview && dpkg-deb -x python3-paraview_*.deb root) >"$cache.log" 2>&1; then
      echo "SKIP: could not fetch python3-paraview (see $cache.log)"; exit 77
    fi
  fi
fi

rm -rf "$work" && mkdir -p "$work"
"$writer" "$work/series" "$work/expected.json"
# Xvfb can lose a race for its display number on a busy shared machine
# ("bad X server connection"): try up to three times.
for attempt in 1 2 3; do
  rm -rf "$work/png" "$work/summary.json"
  if PYTHONPATH=${pvpython_dir}${PYTHONPATH:+:$PYTHONPATH} \
     xvfb-run -a -s "-screen 0 1280x1024x24" \
     pvbatch "$script" "$work/series/tissue.pvd" --property auxin --size 640x480 \
     --output-dir "$work/png" --summary "$work/summary.json"; then
    break
  fi
  echo "pvbatch attempt $attempt failed"
  [ "$attempt" = 3 ] && exit 1
  sleep 2
done
python3 "$checker" "$work/expected.json" "$work/summary.json"
