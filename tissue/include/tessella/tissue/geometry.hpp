// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Geometry derived from borders: only vertices have positions.
//
// Polygons (2D cells, 3D walls) are measured as a fan of triangles from the
// mean of their loop vertices, each triangle signed against the polygon's
// mean normal (the normalised vector area), wherever that fan does not fold:
// every fan triangle's signed area is above 1e-12 of the fan's area (the
// polygon is star-shaped from its vertex mean). For a planar loop the signed
// fan is exact for any simple polygon; for a non-planar loop on a curved
// tissue it is the area of that fan surface, well defined and independent of
// the loop's starting vertex.
//
// Where the fan folds (a non-convex cell not star-shaped from its vertex
// mean, common in real tissues), the loop is projected onto the plane through
// its vertex mean normal to its vector area (its best-fit plane). If the
// projected polygon is star-shaped from somewhere (its kernel has area), the
// polygon is measured on the fan from the kernel's centroid, placed in that
// plane: the same kind of surface as the ordinary fan, only from an apex that
// sees the whole outline. Otherwise it is measured on a triangulation of its
// own outline: the projected polygon is triangulated by ear clipping
// (best-shaped ear first, so the result does not depend on the start vertex
// or direction) and the triangles are lifted back to the 3D vertex positions.
// See polygonTriangulation(). Both are exact for a simple planar polygon.
// Planar 2D tissues keep their shoelace formula, exact for any simple polygon.
// Reversing a loop flips the normal only.
//
// Polyhedra use the divergence theorem over the same surfaces (fans or folded
// walls' triangles) with each wall's outward sign, so neighbouring cells share
// exactly the same wall surface and their volumes add up to the tissue's.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
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

/// The surface a polygon loop is measured (and meshed) on: the fan from
/// `center` when `triangles` is empty, else those triangles (loop positions,
/// counter-clockwise about `normal`, lifted to the loop's points). `center`
/// is the vertex mean unless the fan from it folds (`folded`); then it is
/// the centroid of the kernel of the loop's projection (in the plane through
/// the vertex mean), or, when that kernel is empty, `triangles` is the loop's
/// ear-clipped triangulation. `normal` is the unit vector-area normal (zero
/// for a loop without vector area, which is then measured on its fan).
struct PolygonTriangulation {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
  bool folded = false;
  std::vector<std::array<int, 3>> triangles;
  bool fan() const { return triangles.empty(); }
};
PolygonTriangulation polygonTriangulation(std::span<const Vec3> loop);

/// What makes a loop other than a simple closed curve in its best-fit plane
/// (the plane normal to its vector area): two non-adjacent vertices within
/// 1e-12 of the loop's size (bounding-box diagonal) of each other (pinched),
/// or two edges that cross or touch, or an edge folding back onto the next
/// one (self-intersecting). `first`, `second`: loop positions of the two
/// vertices, or of the first vertices of the two edges.
struct PolygonDefect {
  enum Kind { None, Pinched, SelfIntersecting, NoArea };
  Kind kind = None;
  int first = -1;
  int second = -1;
  explicit operator bool() const { return kind != None; }
};
PolygonDefect polygonDefect(std::span<const Vec3> loop);
/// "pinched: vertices 3 and 7 coincide ..." naming the loop's vertex ids.
std::string polygonDefectText(const PolygonDefect& d, std::span<const VertexId> vertices,
                              std::span<const Vec3> loop);

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

// --- batched: one shared, versioned cache -----------------------------------------
/// The quantities a GeometryCache holds. Each is computed, stamped with the
/// tissue's versions and counted on its own.
enum class GeometryQuantity : std::uint8_t {
  EdgeLengths,          ///< edge_length
  FaceMeasures,         ///< face_area, face_centroid, face_normal (2D cells, 3D walls)
  FaceSecondMoments,    ///< face_second_moment
  VolumeMeasures,       ///< volume, volume_surface, volume_centroid (3D; reads face_area)
  VolumeSecondMoments,  ///< volume_second_moment (3D)
};
inline constexpr std::size_t kGeometryQuantityCount = 5;
/// "edge_lengths", "face_measures", ... (for messages and statistics).
const char* geometryQuantityName(GeometryQuantity q);

/// A set of GeometryQuantity: `FaceMeasures | FaceSecondMoments`.
class GeometryQuantities {
 public:
  constexpr GeometryQuantities() = default;
  constexpr GeometryQuantities(GeometryQuantity q) : bits_(bit(q)) {}  // NOLINT: a quantity is a set of one
  constexpr bool contains(GeometryQuantity q) const { return (bits_ & bit(q)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr GeometryQuantities operator|(GeometryQuantities other) const { return of(bits_ | other.bits_); }
  constexpr GeometryQuantities without(GeometryQuantities other) const { return of(bits_ & ~other.bits_); }
  constexpr bool operator==(const GeometryQuantities&) const = default;

 private:
  static constexpr unsigned bit(GeometryQuantity q) { return 1u << static_cast<unsigned>(q); }
  static constexpr GeometryQuantities of(unsigned bits) {
    GeometryQuantities s;
    s.bits_ = bits;
    return s;
  }
  unsigned bits_ = 0;
};
constexpr GeometryQuantities operator|(GeometryQuantity a, GeometryQuantity b) {
  return GeometryQuantities(a) | GeometryQuantities(b);
}

/// Cell areas (2D) or volumes (3D) with their centroids, and face normals:
/// what growth, division, compartments and output read.
inline constexpr GeometryQuantities kCellMeasures = GeometryQuantity::FaceMeasures | GeometryQuantity::VolumeMeasures;
/// Every quantity.
inline constexpr GeometryQuantities kAllGeometry = GeometryQuantity::EdgeLengths | GeometryQuantity::FaceMeasures |
                                                   GeometryQuantity::FaceSecondMoments |
                                                   GeometryQuantity::VolumeMeasures |
                                                   GeometryQuantity::VolumeSecondMoments;

/// The measures of a tissue, struct-of-arrays indexed by element slot
/// (tombstone slots hold zeros), shared by whoever reads the same tissue
/// (a Simulation's stages and outputs share one through the step context).
///
/// A consumer asks for the quantities it reads, `cache.require(t, kCellMeasures)`,
/// then reads their arrays. The cache remembers, per quantity, the tissue's
/// topology and geometry versions it was computed at, and computes only the
/// quantities that are missing or stale: asking again without a change to the
/// tissue computes nothing; asking for second moments after areas computes
/// the second moments only. An array is valid while fresh(t, quantity).
struct GeometryCache {
  std::vector<double> edge_length;
  std::vector<double> face_area;
  std::vector<Vec3> face_centroid;
  std::vector<Vec3> face_normal;
  std::vector<Sym3> face_second_moment;
  std::vector<double> volume;              // 3D only
  std::vector<double> volume_surface;      // 3D only
  std::vector<Vec3> volume_centroid;       // 3D only
  std::vector<Sym3> volume_second_moment;  // 3D only

  /// Makes `quantities` fresh for t, computing those missing or stale (and
  /// face measures where volume measures need them) and nothing else.
  /// Volume quantities of a 2D tissue are nothing to compute. In parallel
  /// with OpenMP, bit-identical for any number of threads.
  const GeometryCache& require(const Tissue& t, GeometryQuantities quantities);
  /// Computes `quantities` whether fresh or not (recomputeGeometry).
  void recompute(const Tissue& t, GeometryQuantities quantities);
  /// Marks every quantity stale (the arrays keep their values).
  void forget();

  /// Computed at t's current topology and geometry versions (a volume
  /// quantity of a 2D tissue always is).
  bool fresh(const Tissue& t, GeometryQuantities quantities) const;
  /// Every quantity the tissue has is fresh (all five in 3D, three in 2D).
  bool fresh(const Tissue& t) const { return fresh(t, kAllGeometry); }

  /// Statistics: how many times `q` has been computed into this cache.
  std::uint64_t computations(GeometryQuantity q) const { return computations_[static_cast<std::size_t>(q)]; }

  double cellMeasure(const Tissue& t, CellId c) const {
    return t.dim() == 2 ? face_area[c.index()] : volume[c.index()];
  }
  const Vec3& cellCentroid(const Tissue& t, CellId c) const {
    return t.dim() == 2 ? face_centroid[c.index()] : volume_centroid[c.index()];
  }

 private:
  struct Versions {
    std::uint64_t topology = ~0ull;
    std::uint64_t geometry = ~0ull;
  };
  void compute(const Tissue& t, GeometryQuantities quantities);
  std::array<Versions, kGeometryQuantityCount> versions_{};
  std::array<std::uint64_t, kGeometryQuantityCount> computations_{};
};

/// Which quantities recomputeGeometry computes: face and volume measures
/// always, edge lengths and second moments as asked.
struct GeometryOptions {
  bool edges = true;
  bool second_moments = true;
};
GeometryQuantities geometryQuantities(const GeometryOptions& options);

/// Recomputes the quantities `options` names whether fresh or not
/// (cache.recompute): each element is computed independently by the same
/// arithmetic, so the result is bit-identical for any number of threads.
void recomputeGeometry(const Tissue& t, GeometryCache& cache, const GeometryOptions& options = {});

}  // namespace tessella
