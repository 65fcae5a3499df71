// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// checkConformity(): the structural guarantees of a tissue mesh, checked on
// the plain arrays (used by the tests; cheap enough to run after every mesh).
//
//   - every element has a cell index >= 0 and non-degenerate, positively
//     oriented corners (tetrahedra; triangles have no orientation test);
//   - no hanging nodes: every element facet is shared by at most two
//     elements, and a facet with one element lies on a wall facet;
//   - every wall facet is an element facet: of one element on the tissue
//     boundary, of two elements of two different cells inside;
//   - every element facet between two different cells is a wall facet.

#include <string>

#include "tessella/mesh/fe_mesh.hpp"

namespace tessella::mesh {

struct ConformityReport {
  bool ok = true;
  std::string message;  ///< the first violation, naming node/element/facet ids
  long interior_facets = 0;   ///< element facets shared by two elements
  long boundary_facets = 0;   ///< element facets of one element
  explicit operator bool() const { return ok; }
};

ConformityReport checkConformity(const FeMesh& mesh);

}  // namespace tessella::mesh
