#include "tessella/mesh/mesh_tissue.hpp"

namespace tessella {

FeMesh meshTissue(const Tissue& tissue, const MeshOptions& options) {
  switch (tissue.embedding()) {
    case Embedding::Planar: return meshPlanarTissue(tissue, options);
    case Embedding::Surface: return meshSurfaceTissue(tissue, options);
    case Embedding::Volume: return meshVolumeTissue(tissue, options);
  }
  return meshVolumeTissue(tissue, options);  // unreachable: every embedding is handled above
}

}  // namespace tessella
