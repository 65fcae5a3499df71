// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Dome tissues: the usual starting shape of shoot apical meristem models.

#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/dome_surface.hpp"

namespace tessella {

/// A curved-surface tissue for shoot apical meristem models: a 2D Voronoi
/// tissue of the dome's footprint disk, lifted onto the dome surface (every
/// vertex lies on the surface, Embedding::Surface). Only vertices are lifted:
/// walls are straight chords and cells slightly non-planar polygons.
/// footprint_seeds: positions in the footprint disk (their z is ignored);
/// the footprint is a 256-segment polygon as for Disk, and the rim vertices
/// (of edges with one cell) are then moved radially onto its circle, so the
/// whole rim lies on the base circle, in the base plane.
Tissue domeTissue(std::span<const Vec3> footprint_seeds, const Dome& dome,
                  const VoronoiOptions& options = {});

}  // namespace tessella
