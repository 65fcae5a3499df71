// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Segmented label images (one integer label per pixel) as Tessella tissues:
// the image itself (read from TIFF, NRRD, MetaImage or VTK image files, or
// given as an array from Python) and the conversion, 2D or 3D (docs/import.md,
// "Label images", "3D label images").

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tessella/io/import.hpp"

namespace tessella::io {

/// A label image: labels[i + nx * (j + ny * k)] is the label of pixel (i, j, k),
/// whose centre lies at origin + (i, j, k) * spacing (VTK's convention).
struct LabelImage {
  std::string name;  ///< the file, or what the image is called in messages
  std::array<std::int64_t, 3> dims{0, 0, 0};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
  std::vector<std::int64_t> labels;
};

/// Reads a label image through VTK (.tif/.tiff, .nrrd/.nhdr, .mha/.mhd, .vti).
/// InputError naming the file for an unreadable file, a scalar type that is
/// not an integer, more than one component per pixel.
LabelImage readLabelImage(const std::string& path);

/// The planar tissue of a 2D label image (dims[2] == 1), or the 3D tissue of
/// a 3D one (dims[2] > 1: voxel_size then has 3 numbers, crop 6; simplify
/// smooths and simplifies the junction lines). options.image holds
/// the background labels, labels to drop, the minimum cell size, the crop box
/// and voxel_size (overriding image.spacing); options.simplify is a tolerance
/// in pixels; options.scale multiplies positions. InputError naming
/// image.name, the label and the value for each defect; nothing is built.
ImportResult tissueFromLabelImage(const LabelImage& image, const ImportOptions& options);

/// The same, releasing image.labels as soon as they are read (the first pass
/// over the pixels), which lowers the peak memory of a large import by the
/// image's size: what the Python module does with an image it reads, and
/// importTissue with a 3D file (a 2D file's pixels it reads as stored, without
/// the 64-bit copy, and releases after the same pass).
ImportResult tissueFromLabelImage(LabelImage&& image, const ImportOptions& options);

}  // namespace tessella::io
