# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Render every step of a Tessella time series to PNG files.

Run with ParaView's batch interpreter (it needs a display; under a headless
server wrap it in xvfb-run):

    xvfb-run -a pvbatch paraview/render_series.py out/tissue.pvd --property auxin

Cells are drawn with their walls as edges and coloured by the chosen cell
property (or vertex property), with one colour range over the whole series so
that the frames can be compared. --summary writes a JSON file recording what
ParaView itself read at each step (cells, points, arrays), which the test in
tests/paraview/ compares against what was written.
"""

import argparse
import json
import os
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar, PVDReader, ResetCamera,
                             SaveScreenshot, Show)


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("pvd", help="the series' .pvd file")
    parser.add_argument("--property", default="area",
                        help="cell (or vertex) array to colour by (default: area; use volume for 3D tissues)")
    parser.add_argument("--output-dir", help="where the PNGs go (default: <pvd dir>/png)")
    parser.add_argument("--size", default="800x600", help="image size WIDTHxHEIGHT (default 800x600)")
    parser.add_argument("--summary", help="write a JSON summary of what ParaView read")
    parser.add_argument("--no-edges", action="store_true", help="do not draw the cell walls")
    return parser.parse_args(argv)


def fail(message):
    print("render_series.py: error: " + message, file=sys.stderr)
    sys.exit(2)


def time_steps(reader):
    values = reader.TimestepValues
    if values is None:
        return [0.0]
    try:
        return list(values)
    except TypeError:  # a single step comes back as a bare number
        return [float(values)]


def array_names(arrays):
    return sorted(arrays.keys())


def main(argv):
    args = parse_args(argv)
    if not os.path.isfile(args.pvd):
        fail("no such series file: " + args.pvd)
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        fail("--size must look like 800x600, got " + args.size)
    output_dir = args.output_dir or os.path.join(os.path.dirname(os.path.abspath(args.pvd)), "png")
    os.makedirs(output_dir, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.pvd))[0]

    reader = PVDReader(FileName=args.pvd)
    times = time_steps(reader)

    # First pass: what is in each step, and the colour range over all steps.
    steps = []
    low, high = float("inf"), float("-inf")
    association = None
    for t in times:
        reader.UpdatePipeline(t)
        info = reader.GetDataInformation()
        cell_arrays = array_names(reader.CellData)
        point_arrays = array_names(reader.PointData)
        if args.property in cell_arrays:
            association, arrays = "CELLS", reader.CellData
        elif args.property in point_arrays:
            association, arrays = "POINTS", reader.PointData
        else:
            fail("step at time %g has no array '%s'; cell arrays: %s; point arrays: %s"
                 % (t, args.property, ", ".join(cell_arrays), ", ".join(point_arrays)))
        component = -1 if arrays[args.property].GetNumberOfComponents() > 1 else 0  # -1: magnitude
        lo, hi = arrays[args.property].GetRange(component)
        low, high = min(low, lo), max(high, hi)
        steps.append({"time": t, "cells": info.GetNumberOfCells(), "points": info.GetNumberOfPoints(),
                      "cell_arrays": cell_arrays, "point_arrays": point_arrays,
                      "bounds": list(info.GetBounds())})
    if high <= low:
        high = low + 1.0  # a uniform property still gets a valid colour map

    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    if hasattr(view, "UseColorPaletteForBackground"):  # ParaView >= 5.10 ignores Background otherwise
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    display = Show(reader, view)
    display.SetRepresentationType("Surface" if args.no_edges else "Surface With Edges")
    ColorBy(display, (association, args.property))
    lut = GetColorTransferFunction(args.property)
    lut.RescaleTransferFunction(low, high)
    lut.AutomaticRescaleRangeMode = "Never"
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.TitleColor = [0.0, 0.0, 0.0]  # dark text: the background is white
    bar.LabelColor = [0.0, 0.0, 0.0]

    # The camera frames the last (largest, for a growing tissue) step and stays.
    view.ViewTime = times[-1]
    ResetCamera(view)
    if steps[-1]["bounds"][5] - steps[-1]["bounds"][4] > 1e-12 * max(1.0, abs(steps[-1]["bounds"][5])):
        camera = view.GetActiveCamera()  # 3D or curved tissue: look from above and aside
        camera.Elevation(35)
        camera.Azimuth(30)
        ResetCamera(view)

    for index, (t, step) in enumerate(zip(times, steps)):
        view.ViewTime = t
        png = os.path.join(output_dir, "%s_%06d.png" % (stem, index))
        SaveScreenshot(png, view, ImageResolution=[width, height])
        step["png"] = png
        print("step %d  time %g  cells %d  points %d  -> %s" % (index, t, step["cells"], step["points"], png))

    if args.summary:
        with open(args.summary, "w") as out:
            json.dump({"pvd": os.path.abspath(args.pvd), "property": args.property, "association": association,
                       "range": [low, high], "steps": steps}, out, indent=2)


if __name__ == "__main__":
    main(sys.argv[1:])
