#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Writes the small label images of the example configs, as a segmentation
tool would:

- configs/label_images/cells_2d.tif (configs/from_label_image_2d.yaml): a 200 x
  150 pixel image (16-bit labels) of about 60 cells, the discrete Voronoi regions
  of jittered seeds inside an ellipse, background 0 outside it and label 1 in a
  band along the image's top edge (both background by default, as in PlantSeg
  and MARS), deflate-compressed, and three specks of 1 to 3 pixels with labels of
  their own inside cells (segmentation noise, merged away by
  import.min_cell_size);
- configs/label_images/cells_3d.mha (configs/from_label_image_3d.yaml): a 40 x
  40 x 24 voxel stack (16-bit labels; a zlib-compressed MetaImage carrying its
  voxel size, 0.5 x 0.5 x 1 micrometres, as confocal stacks are coarser in z) of
  18 cells, the discrete Voronoi regions of jittered seeds on a 3 x 3 x 2 grid
  inside a flat dome (an ellipsoid standing on the stack's bottom layer, which
  cuts the top corners), background 0 above it, and two specks of 1 and 2 voxels
  with labels of their own inside cells.

    python3 scripts/make_label_image.py [OUT.tif]       # the 2D image (both images without arguments)
    python3 scripts/make_label_image.py --3d [OUT.mha]  # the 3D image

Needs NumPy (and Pillow for the 2D image). The output is the same byte for
byte on every run.
"""
import pathlib
import sys
import zlib

import numpy as np


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


def label_image_3d():
    nx, ny, nz = 40, 40, 24
    rng = np.random.default_rng(7)
    gz, gy, gx = np.mgrid[0:2, 0:3, 0:3]
    seeds = np.stack([(gx + 0.5) * nx / 3, (gy + 0.5) * ny / 3, (gz + 0.5) * (nz - 2) / 2], axis=-1).reshape(-1, 3)
    seeds += rng.uniform(-2.0, 2.0, size=seeds.shape)
    z, y, x = np.mgrid[0:nz, 0:ny, 0:nx] + 0.5
    d = sum((c[..., None] - seeds[:, k]) ** 2 for k, c in enumerate((x, y, z)))
    labels = (np.argmin(d, axis=3) + 2).astype(np.uint16)
    inside = ((x - 20) / 30) ** 2 + ((y - 20) / 30) ** 2 + (z / 30) ** 2 <= 1
    labels[~inside] = 0
    # Specks: 1 and 2 voxels with new labels inside cells.
    labels[4, 20, 20] = 500
    labels[12, 10, 9:11] = 501
    return labels


def write_metaimage(out, labels, spacing):
    """A MetaImage (.mha): the text header, then the voxels (x fastest, 16-bit little endian), zlib-compressed."""
    nz, ny, nx = labels.shape
    data = zlib.compress(labels.astype("<u2").tobytes(), 9)
    header = ("ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
              f"CompressedData = True\nCompressedDataSize = {len(data)}\nOffset = 0 0 0\n"
              f"ElementSpacing = {spacing[0]} {spacing[1]} {spacing[2]}\nDimSize = {nx} {ny} {nz}\n"
              "ElementType = MET_USHORT\nElementDataFile = LOCAL\n")
    out.write_bytes(header.encode("ascii") + data)


def main():
    folder = pathlib.Path(__file__).resolve().parents[1] / "configs" / "label_images"
    args = sys.argv[1:]
    if args[:1] != ["--3d"]:
        from PIL import Image
        out = pathlib.Path(args[0]) if args else folder / "cells_2d.tif"
        Image.fromarray(label_image()).save(out, compression="tiff_adobe_deflate")
        print(f"wrote {out}")
    if not args or args[0] == "--3d":
        out = pathlib.Path(args[1]) if len(args) > 1 else folder / "cells_3d.mha"
        write_metaimage(out, label_image_3d(), (0.5, 0.5, 1.0))
        print(f"wrote {out}")


if __name__ == "__main__":
    main()
