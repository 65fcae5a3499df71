// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// meshVolumeTissue: checks the 3D tissue, then hands it to the volume method
// the options name (volume_methods.hpp).

#include "tessella/mesh/mesh_tissue.hpp"

#include <string>

#include "tessella/tissue/errors.hpp"
#include "volume_methods.hpp"

namespace tessella::mesh {

FeMesh meshVolumeTissue(const Tissue& t, const MeshOptions& options) {
  validateMeshOptions(options);
  if (t.dim() != 3)
    throw InputError("meshVolumeTissue needs a 3D tissue, got one of dimension " + std::to_string(t.dim()));
  detail::WallTriangulation walls;
  if (const auto report = detail::checkVolumeGeometry(t, options, walls); !report)
    throw GeometryError("cannot mesh the tissue: " + report.message, report.element);
  checkElementLimit(t, options);
  return options.volume_method == VolumeMethod::WholeTissue ? detail::meshWholeTissue(t, options, walls)
                                                            : detail::meshCellByCell(t, options, walls);
}

}  // namespace tessella::mesh
