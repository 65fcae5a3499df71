// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: what the two TetGen-based volume meshers share — the switch
// string, running TetGen with its integer exit codes in words, and filling a
// facet.

#include <algorithm>
#include <string>
#include <vector>

#include <tetgen.h>

#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::mesh::detail {

/// What TetGen's integer exit codes mean (tetgen.h, terminatetetgen()).
inline std::string tetgenErrorMeaning(int code) {
  switch (code) {
    case 1: return "out of memory";
    case 2: return "internal error in TetGen";
    case 3: return "input facets intersect each other (self-intersecting walls)";
    case 4: return "an input feature is too small for TetGen's tolerance (near-degenerate wall or edge)";
    case 5: return "two input facets are too close to each other (nearly overlapping walls)";
    case 10: return "TetGen rejected the input complex";
    default: return "unknown TetGen error";
  }
}

/// `base` followed by the quality and volume bounds: q<ratio>[/<dihedral>][a<volume>].
inline std::string tetgenSwitches(const std::string& base, const MeshOptions& o) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) about "q" + std::string&&.
  std::string s = base;
  s += 'q';
  s += formatNumber(o.radius_edge_ratio);
  if (o.min_dihedral_degrees > 0.0) {
    s += '/';
    s += formatNumber(o.min_dihedral_degrees);
  }
  if (o.max_volume > 0.0) {
    s += 'a';
    s += formatNumber(o.max_volume);
  }
  return s;
}

/// tetrahedralize(), with TetGen's integer throws turned into a GeometryError
/// that says what `what` was ("meshing cell 12") and which switches ran.
inline void runTetgen(const std::string& switches, tetgenio& in, tetgenio& out, const std::string& what) {
  std::string sw = switches;  // TetGen wants a mutable string
  try {
    tetrahedralize(sw.data(), &in, &out);
  } catch (int code) {
    throw GeometryError("TetGen failed with code " + std::to_string(code) + " (" + tetgenErrorMeaning(code) + ") " +
                        what + " with switches \"" + switches + "\"");
  }
}

/// Makes `f` one polygon through `corners` (indices into the point list).
inline void setPolygon(tetgenio::facet& f, const std::vector<int>& corners) {
  f.numberofpolygons = 1;
  f.polygonlist = new tetgenio::polygon[1];
  f.numberofholes = 0;
  f.holelist = nullptr;
  f.polygonlist[0].numberofvertices = static_cast<int>(corners.size());
  f.polygonlist[0].vertexlist = new int[corners.size()];
  std::copy(corners.begin(), corners.end(), f.polygonlist[0].vertexlist);
}

}  // namespace tessella::mesh::detail
