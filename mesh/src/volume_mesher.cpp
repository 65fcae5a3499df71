// meshVolumeTissue: checks the 3D tissue, then hands it to the volume method
// the options name (volume_methods.hpp).

#include <string>

#include "interior_point.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "volume_methods.hpp"

namespace tessella {

namespace mesh_detail {

Vec3 cellSeed(const Tissue& t, const WallTriangulation& walls, CellId c) {
  std::vector<Triangle> outward;
  for (OrientedFace of : t.topology().volumeFaces(handle_cast<VolumeId>(c)))
    for (const auto& tri : walls.wall_triangles[of.handle().index()]) {
      const Vec3 &a = walls.points[static_cast<std::size_t>(tri[0])], &b = walls.points[static_cast<std::size_t>(tri[1])],
                 &d = walls.points[static_cast<std::size_t>(tri[2])];
      outward.push_back(of.reversed() ? Triangle{a, d, b} : Triangle{a, b, d});
    }
  const double size = std::cbrt(cellMeasure(t, c));
  const auto seed = interiorPoint(outward, cellCentroid(t, c), 1e-6 * size);
  if (!seed)
    throw GeometryError("volume mesher: found no point strictly inside cell " + std::to_string(c.index()) +
                            " to seed its region (the cell is too thin or not closed)",
                        ElementId{3, c.index()});
  return *seed;
}

}  // namespace mesh_detail

FeMesh meshVolumeTissue(const Tissue& t, const MeshOptions& options) {
  validateMeshOptions(options);
  if (t.dim() != 3)
    throw InputError("meshVolumeTissue needs a 3D tissue, got one of dimension " + std::to_string(t.dim()));
  mesh_detail::WallTriangulation walls;
  if (const auto report = mesh_detail::checkVolumeGeometry(t, options, walls); !report)
    throw GeometryError("cannot mesh the tissue: " + report.message, report.element);
  checkElementLimit(t, options);
  return options.volume_method == VolumeMethod::WholeTissue ? mesh_detail::meshWholeTissue(t, options, walls)
                                                            : mesh_detail::meshCellByCell(t, options, walls);
}

}  // namespace tessella
