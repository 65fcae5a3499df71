#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Writes configs/label_images/cells_2d.tif, the small label image of
configs/from_label_image_2d.yaml, as a segmentation tool would: a 200 x 150
pixel image (16-bit labels) of about 60 cells, the discrete Voronoi regions of
jittered seeds inside an ellipse, background 0 outside it and label 1 in a
band along the image's top edge (both background by default, as in PlantSeg and
MARS), deflate-compressed, and three specks of 1 to 3 pixels with labels of their own inside
cells (segmentation noise, merged away by import.min_cell_size).

    python3 scripts/make_label_image.py [OUT.tif]

Needs NumPy and Pillow. The output is the same byte for byte on every run.
"""
import pathlib
import sys

import numpy as np
from PIL import Image


def label_image():
    width, height = 200, 150
    rng = np.random.default_rng(2026)
    gy, gx = np.mgrid[0:9, 0:12]
    seeds = np.stack([(gx + 0.5) * width / 12, (gy + 0.5) * height / 9], axis=-1).reshape(-1, 2)
    seeds += rng.uniform(-5.0, 5.0, size=seeds.shape)
    y, x = np.mgrid[0:height, 0:width] + 0.5
    d = (x[..., None] - seeds[:, 0]) ** 2 + (y[..., None] - seeds[:, 1]) ** 2
    labels = (np.argmin(d, axis=2) + 2).astype(np.uint16)
    inside = ((x - 100) / 92) ** 2 + ((y - 78) / 66) ** 2 <= 1
    labels[~inside] = 0
    labels[0:4, :] = 1
    # Specks: 1, 2 and 3 pixels with new labels inside cells.
    labels[75, 100] = 500
    labels[40, 60:62] = 501
    labels[110:113, 140] = 502
    return labels


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else \
        pathlib.Path(__file__).resolve().parents[1] / "configs" / "label_images" / "cells_2d.tif"
    Image.fromarray(label_image()).save(out, compression="tiff_adobe_deflate")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
