// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Tissue: the t-scene-graph. A CellComplex augmented with geometry (vertex
// positions only: every other measure is derived from borders), property
// columns per degree, cell lineage and a clock.
//
//   dim 2, Embedding::Planar  cells are polygons in the z = 0 plane
//   dim 2, Embedding::Surface cells are (possibly non-planar) polygons on a
//                             curved sheet; positions are 3D
//   dim 3, Embedding::Volume  cells are polyhedra bounded by polygonal walls
//
// Handles stay valid through every edit except removal of their element and
// compact(). Spans returned by accessors are invalidated by any edit.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/properties.hpp"
#include "tessella/tissue/vec3.hpp"
#include "tessella/tissue/version_stamp.hpp"

namespace tessella {

enum class Embedding { Planar, Surface, Volume };

const char* embeddingName(Embedding e);

/// Iterates the live indices of one degree, as handles of type H.
template <typename H>
class LiveRange {
 public:
  LiveRange(const std::vector<std::uint8_t>* alive) : alive_(alive) {}
  class iterator {
   public:
    using value_type = H;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(const std::vector<std::uint8_t>* a, Index i) : a_(a), i_(i) { skip(); }
    H operator*() const { return H(i_); }
    iterator& operator++() {
      ++i_;
      skip();
      return *this;
    }
    iterator operator++(int) {
      iterator t = *this;
      ++*this;
      return t;
    }
    bool operator==(const iterator& o) const { return i_ == o.i_; }

   private:
    void skip() {
      while (i_ < a_->size() && !(*a_)[i_]) ++i_;
    }
    const std::vector<std::uint8_t>* a_ = nullptr;
    Index i_ = 0;
  };
  iterator begin() const { return {alive_, 0}; }
  iterator end() const { return {alive_, static_cast<Index>(alive_->size())}; }

 private:
  const std::vector<std::uint8_t>* alive_;
};

/// What an editing primitive created. Old handles stay valid unless stated.
struct EdgeSplit {
  VertexId vertex;  ///< the new vertex
  EdgeId edge;      ///< the new edge (vertex -> old head); the old edge now ends at `vertex`
};
struct FaceSplit {
  EdgeId edge;  ///< the new edge between the two loop vertices
  FaceId face;  ///< the new face; the old face keeps the rest of its loop
};
struct CellSplit {
  CellId daughter;                    ///< the new cell, on the plane normal's positive side
  WallId wall;                        ///< the new wall between mother and daughter
  std::vector<VertexId> new_vertices; ///< vertices created on cut edges (shared with neighbours)
};

/// Largest SplitOptions::snap_tolerance accepted (a tenth of the cell size).
inline constexpr double kMaxSnapTolerance = 0.1;

/// splitCell() refuses options out of range (negative, NaN, too large) with
/// an InputError naming the option and its value.
struct SplitOptions {
  /// Vertices closer to the plane than snap_tolerance * (cell size) are taken
  /// as lying on it, so a plane through a vertex reuses it instead of making
  /// a zero-length edge. Cell size: sqrt(area) in 2D, cbrt(volume) in 3D.
  /// In [0, kMaxSnapTolerance].
  double snap_tolerance = 1e-9;
  /// A split leaving either part with less than this fraction of the cell's
  /// measure is refused (GeometryError) instead of making a sliver. In [0, 0.5).
  double min_fraction = 1e-6;
};

// The plans splitCell makes and applies (cell_split_plan.hpp).
struct CellSplitPlan2D;
struct CellSplitPlan3D;

class Tissue {
 public:
  Tissue(int dim, Embedding embedding);
  /// A tissue around a complete complex (bulk-built with
  /// CellComplex::fromLoops / addVolumes) and one position per vertex; every
  /// cell is a founder cell (fresh lineage id, parent -1, birth time 0).
  /// Throws InputError for a count mismatch or a non-finite position.
  Tissue(CellComplex complex, std::vector<Vec3> positions, Embedding embedding);

  // --- kind -----------------------------------------------------------------
  int dim() const { return complex_.dim(); }
  Embedding embedding() const { return embedding_; }
  /// Degree of the cells (dim) and of the walls (dim - 1).
  int cellDegree() const { return dim(); }
  int wallDegree() const { return dim() - 1; }

  /// The combinatorics (read-only; edit through Tissue so that properties,
  /// lineage and counters follow).
  const CellComplex& topology() const { return complex_; }

  // --- counts and iteration -------------------------------------------------
  std::size_t numVertices() const { return complex_.count(0); }
  std::size_t numEdges() const { return complex_.count(1); }
  std::size_t numFaces() const { return complex_.count(2); }
  std::size_t numVolumes() const { return dim() == 3 ? complex_.count(3) : 0; }
  std::size_t numCells() const { return complex_.count(dim()); }
  std::size_t numWalls() const { return complex_.count(dim() - 1); }
  std::size_t slots(int degree) const { return complex_.slots(degree); }
  std::size_t cellSlots() const { return complex_.slots(dim()); }

  LiveRange<VertexId> vertices() const { return {&aliveFlags(0)}; }
  LiveRange<EdgeId> edges() const { return {&aliveFlags(1)}; }
  LiveRange<FaceId> faces() const { return {&aliveFlags(2)}; }
  LiveRange<VolumeId> volumes() const { return {&aliveFlags(3)}; }
  LiveRange<CellId> cells() const { return {&aliveFlags(dim())}; }
  LiveRange<WallId> walls() const { return {&aliveFlags(dim() - 1)}; }

  bool alive(CellId c) const { return complex_.alive(dim(), c.index()); }
  bool alive(WallId w) const { return complex_.alive(dim() - 1, w.index()); }
  template <typename Tag>
  bool alive(Handle<Tag> h) const { return complex_.alive(h); }

  // --- cells and walls, dimension-independent -------------------------------
  /// The walls bounding a cell (edges of a 2D cell's loop, faces of a 3D cell).
  std::vector<WallId> cellWalls(CellId c) const;
  /// The cells a wall bounds (1 on the boundary, 2 inside).
  std::vector<CellId> wallCells(WallId w) const;
  /// Cells sharing a wall with c.
  std::vector<CellId> cellNeighbors(CellId c) const;
  /// Distinct vertices of a cell.
  std::vector<VertexId> cellVertices(CellId c) const;
  bool isBoundaryWall(WallId w) const;
  FaceId cellFace(CellId c) const;      ///< 2D only
  VolumeId cellVolume(CellId c) const;  ///< 3D only

  // --- positions (the only stored geometry) ---------------------------------
  const Vec3& position(VertexId v) const { return positions_[v.index()]; }
  void setPosition(VertexId v, const Vec3& p);
  std::span<const Vec3> positions() const { return positions_; }
  /// Mutable view of all positions; counts as a geometry change.
  std::span<Vec3> mutablePositions();

  // --- properties -----------------------------------------------------------
  PropertyStore& properties(int degree) { return properties_[degree]; }
  const PropertyStore& properties(int degree) const { return properties_[degree]; }
  PropertyStore& cellProperties() { return properties_[dim()]; }
  const PropertyStore& cellProperties() const { return properties_[dim()]; }
  PropertyStore& wallProperties() { return properties_[dim() - 1]; }
  const PropertyStore& wallProperties() const { return properties_[dim() - 1]; }

  // --- lineage (built-in cell properties) -----------------------------------
  /// Unique over the tissue's whole history, never reused (even after compact).
  std::int64_t lineageId(CellId c) const { return (*lineage_)[c]; }
  /// Lineage id of the mother, or -1 for a founder cell.
  std::int64_t parentId(CellId c) const { return (*parent_)[c]; }
  double birthTime(CellId c) const { return (*birth_)[c]; }
  std::int64_t nextLineageId() const { return next_lineage_; }
  /// Restores lineage read back from a file (restart). Ids stay unique: the
  /// next new id is larger than every restored one.
  void restoreLineage(CellId c, std::int64_t lineage, std::int64_t parent, double birth_time);
  /// Makes the next new lineage id at least `next` (a restart whose saved
  /// history used ids of cells no longer alive). Never lowers it.
  void reserveLineageIds(std::int64_t next);
  static constexpr const char* kLineageName = "lineage_id";
  static constexpr const char* kParentName = "parent_id";
  static constexpr const char* kBirthTimeName = "birth_time";

  // --- clock ------------------------------------------------------------------
  double time() const { return time_; }
  void setTime(double t) { time_ = t; }

  // --- change counters --------------------------------------------------------
  // Values unique in the process (VersionStamp): equal versions mean the same
  // topology / geometry, whichever tissue (or copy) they are read from.
  std::uint64_t topologyVersion() const { return complex_.version(); }
  /// Bumped by every position change and every topological change.
  std::uint64_t geometryVersion() const { return geometry_version_.value(); }
  void markGeometryChanged() { ++geometry_version_; }

  // --- building -------------------------------------------------------------
  VertexId addVertex(const Vec3& p);
  EdgeId addEdge(VertexId from, VertexId to);
  /// Face from a closed oriented edge loop.
  FaceId addFace(std::span<const OrientedEdge> loop);
  /// Face from a vertex loop, reusing existing edges (created where missing).
  FaceId addPolygon(std::span<const VertexId> loop);
  FaceId addPolygon(std::initializer_list<VertexId> loop) {
    return addPolygon(std::span<const VertexId>(loop.begin(), loop.size()));
  }
  VolumeId addVolume(std::span<const OrientedFace> faces);
  /// In 2D a new face is a cell and in 3D a new volume is: new cells get a
  /// fresh lineage id, parent -1 and the current time as birth time.

  // --- editing primitives (never leave the complex corrupted) --------------
  /// Splits an edge at `point` (normally on the segment). Edge properties
  /// divide by length fraction. Returns the new vertex and edge; e keeps its
  /// tail and now ends at the new vertex. Faces through e get both.
  EdgeSplit splitEdge(EdgeId e, const Vec3& point);
  /// Splits face f by a new edge between two non-adjacent vertices of its
  /// loop. Face properties divide by area fraction; in 2D this divides a
  /// cell (lineage updated). The new face is the loop part from b to a.
  FaceSplit splitFace(FaceId f, VertexId a, VertexId b);
  /// Splits face f by a segment from point pa on edge ea to point pb on edge
  /// eb (both edges of f's loop): splits both edges, then the face.
  FaceSplit splitFace(FaceId f, EdgeId ea, const Vec3& pa, EdgeId eb, const Vec3& pb);
  /// Divides a cell by a plane (2D: the plane's trace on the cell is the cut
  /// line; 3D: the plane cuts the polyhedron). Crossed edges and walls are
  /// split, shared with the neighbours, and a new wall separates the mother
  /// (negative side, keeps its handle) from the daughter (positive side).
  /// Throws GeometryError (complex unchanged) when the plane misses the cell,
  /// runs along an existing wall, leaves a part below
  /// options.min_fraction, or cuts a non-convex cell into more than two
  /// pieces where the choice is ambiguous (see docs/ARCHITECTURE.md).
  CellSplit splitCell(CellId c, const Plane& plane, const SplitOptions& options = {});
  /// Divides plan.cell by a plan made on this tissue as it is now
  /// (planCellSplit2D / planCellSplit3D, cell_split_plan.hpp): splitCell
  /// without planning again, with the same result. Only the plan's recorded
  /// topology and geometry versions are checked, against the tissue's (equal
  /// versions mean the same complex and positions: the tissue it was made on,
  /// unchanged, or a copy of it); a plan of another state is a
  /// std::logic_error naming the cell and the versions. Properties and
  /// lineage do not enter a plan and may change in between.
  CellSplit splitCell(const CellSplitPlan2D& plan);
  CellSplit splitCell(const CellSplitPlan3D& plan);
  /// Divides many cells of a 2D tissue at once, in parallel (OpenMP), by plans
  /// made on the tissue as it is (planCellSplit2D, one per cell, each cell
  /// once). The result, bit for bit and whatever the number of threads, is
  /// the one of applying the plans one after the other in their order: each
  /// new chord end splits (splitEdge) the piece of its edge that holds its
  /// point, unless an earlier plan of the batch made a vertex on that edge
  /// within the plan's snap distance of its plane, which it then reuses;
  /// then the cell is split between the chord's ends (the daughter gets the
  /// plan's side), its properties divided by the plan's mother_fraction, and
  /// it gets its lineage ids (mother, then daughter, plan after plan).
  /// Element numbering and every list order are those of that sequence
  /// (docs/growth.md, "Division in parallel"). Results in plan order.
  std::vector<CellSplit> splitCells(std::span<const CellSplitPlan2D> plans);

  // --- removal and compaction -------------------------------------------------
  /// Removes a cell, then every wall, edge and vertex left bounding nothing.
  void removeCell(CellId c);
  /// Drops tombstones; returns the renumbering of every degree. Properties
  /// follow; lineage ids do not change.
  Renumbering compact();

  /// Heap bytes used by topology, positions and properties.
  std::size_t bytes() const;

 private:
  const std::vector<std::uint8_t>& aliveFlags(int degree) const;
  void grew(int degree);  // keep property columns sized after an insertion
  void newCell(Index cell);
  void dividedCell(Index mother, Index daughter, double fraction);
  void paranoidCheck(const char* where) const;
  // splitFace's edit once its checks passed: the complex's split, and `kept` of the measures to f.
  FaceSplit commitFaceSplit(FaceId f, VertexId a, VertexId b, double kept);
  // splitCell's edits: apply a plan made for this tissue as it is.
  CellSplit applyCellSplit(const CellSplitPlan2D& plan);
  CellSplit applyCellSplit(const CellSplitPlan3D& plan);
  // Throws std::logic_error unless a plan's versions are the tissue's.
  void checkPlanVersions(CellId c, std::uint64_t topology_version, std::uint64_t geometry_version) const;
  double measureFraction(int degree, Index kept, Index part) const;

  CellComplex complex_;
  Embedding embedding_;
  std::vector<Vec3> positions_;
  std::array<PropertyStore, 4> properties_;
  PropertyColumn<std::int64_t>* lineage_ = nullptr;
  PropertyColumn<std::int64_t>* parent_ = nullptr;
  PropertyColumn<double>* birth_ = nullptr;
  std::int64_t next_lineage_ = 0;
  double time_ = 0.0;
  VersionStamp geometry_version_;
  std::vector<std::uint8_t> no_elements_;  // alive flags of an absent degree (volumes in 2D)

 public:
  Tissue(const Tissue& other);
  Tissue& operator=(const Tissue& other);
  Tissue(Tissue&& other) noexcept;
  Tissue& operator=(Tissue&& other) noexcept;
  ~Tissue();
};

}  // namespace tessella
