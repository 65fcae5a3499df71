#pragma once
// Geometry derived from borders: only vertices have positions.
//
// Polygons (2D cells, 3D walls) are measured as a fan of triangles from the
// mean of their loop vertices, each triangle signed against the polygon's
// mean normal (the normalised vector area). For a planar loop this is exact
// for any simple polygon, convex or not; for a non-planar loop on a curved
// tissue it is the area of that fan surface, well defined and independent of
// the loop's starting vertex. Reversing a loop flips the normal only.
// Polyhedra use the divergence theorem over the same fans with each wall's
// outward sign, so neighbouring cells share exactly the same wall surface and
// their volumes add up to the tissue's.

#include <span>
#include <vector>

#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella {

struct PolygonMeasures {
  double area = 0.0;
  Vec3 centroid = Vec3::Zero();
  /// Unit normal, right-handed with the loop direction.
  Vec3 normal = Vec3::Zero();
  /// Second moment of area about the centroid: integral of (x-c)(x-c)^T dA.
  Mat3 second_moment = Mat3::Zero();
};

struct PolyhedronMeasures {
  double volume = 0.0;
  double surface_area = 0.0;
  Vec3 centroid = Vec3::Zero();
  /// Second moment of volume about the centroid: integral of (x-c)(x-c)^T dV.
  Mat3 second_moment = Mat3::Zero();
};

/// Principal axes of a second-moment tensor, by decreasing extent: axes.col(0)
/// is the longest axis ("main axis"), values(0) its second moment.
struct PrincipalAxes {
  Vec3 values = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
};

PrincipalAxes principalAxes(const Mat3& second_moment);
/// Inertia tensor (unit density) from a second-moment tensor: tr(S) I - S.
Mat3 inertiaTensor(const Mat3& second_moment);

// --- per element, straight from the borders ----------------------------------
double edgeLength(const Tissue& t, EdgeId e);
Vec3 edgeMidpoint(const Tissue& t, EdgeId e);
PolygonMeasures polygonMeasures(const Tissue& t, FaceId f);
PolygonMeasures polygonMeasures(std::span<const Vec3> loop);
PolyhedronMeasures polyhedronMeasures(const Tissue& t, VolumeId c);

/// Length (2D) or area (3D) of a wall.
double wallMeasure(const Tissue& t, WallId w);
/// Area (2D) or volume (3D) of a cell.
double cellMeasure(const Tissue& t, CellId c);
Vec3 cellCentroid(const Tissue& t, CellId c);
/// Second moment of the cell about its centroid (area in 2D, volume in 3D).
Mat3 cellSecondMoment(const Tissue& t, CellId c);
/// Principal axes of the cell; axes.col(0) is its main (longest) axis.
PrincipalAxes cellPrincipalAxes(const Tissue& t, CellId c);
/// Sum of cell measures: the tissue's total area (2D) or volume (3D).
double totalMeasure(const Tissue& t);

// --- batched -------------------------------------------------------------------
/// All measures of a tissue, struct-of-arrays indexed by element slot
/// (tombstone slots hold zeros). Filled by recomputeGeometry().
struct GeometryCache {
  std::vector<double> edge_length;
  std::vector<double> face_area;
  std::vector<Vec3> face_centroid;
  std::vector<Vec3> face_normal;
  std::vector<Sym3> face_second_moment;
  std::vector<double> volume;           // 3D only
  std::vector<double> volume_surface;   // 3D only
  std::vector<Vec3> volume_centroid;    // 3D only
  std::vector<Sym3> volume_second_moment;  // 3D only
  std::uint64_t topology_version = ~0ull;
  std::uint64_t geometry_version = ~0ull;

  bool fresh(const Tissue& t) const {
    return topology_version == t.topologyVersion() && geometry_version == t.geometryVersion();
  }
  double cellMeasure(const Tissue& t, CellId c) const {
    return t.dim() == 2 ? face_area[c.index()] : volume[c.index()];
  }
  const Vec3& cellCentroid(const Tissue& t, CellId c) const {
    return t.dim() == 2 ? face_centroid[c.index()] : volume_centroid[c.index()];
  }
};

struct GeometryOptions {
  bool edges = true;
  bool second_moments = true;
};

/// Recomputes every measure, in parallel with OpenMP. Each element is computed
/// independently by the same arithmetic, so the result is bit-identical for
/// any number of threads.
void recomputeGeometry(const Tissue& t, GeometryCache& cache, const GeometryOptions& options = {});

}  // namespace tessella
