// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal to io/: the 2D path of tissueFromLabelImage (label_image_2d.cpp) reading the pixels as the file
// stores them, so that importing a file does not first copy them into 64-bit labels.

#include <cstddef>
#include <functional>
#include <variant>

#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"

namespace tessella::io::detail {

/// The pixels of an image in their stored type: an integer type whose every value is a label (an
/// std::int64_t); unsigned 64-bit images go through LabelImage::labels, which refuses labels above 2^63.
using LabelPixels = std::variant<const char*, const signed char*, const unsigned char*, const short*,
                                 const unsigned short*, const int*, const unsigned int*, const long*,
                                 const long long*>;

/// tissueFromLabelImage of a 2D image (image.dims[2] == 1) whose labels are `pixels` (`count` of them, pixel
/// (i, j) at i + dims[0] * j) instead of image.labels. `release`, when given, is called once the pixels are
/// read (the first pass), to free them early (lower peak memory).
ImportResult tissueFromLabelPixels2d(const LabelImage& image, LabelPixels pixels, std::size_t count,
                                     const ImportOptions& options, const std::function<void()>& release = {});

}  // namespace tessella::io::detail
