// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal to io/: the 3D path of tissueFromLabelImage (label_image_3d.cpp).

#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"

namespace tessella::io::detail {

/// The 3D tissue of a label image with more than one z layer
/// (docs/import.md, "3D label images"); `options` already checked by
/// checkImportOptions. `release`, when given, is image.labels, emptied once
/// read (lower peak memory).
ImportResult tissueFromLabelImage3d(const LabelImage& image, const ImportOptions& options,
                                    std::vector<std::int64_t>* release = nullptr);

}  // namespace tessella::io::detail
