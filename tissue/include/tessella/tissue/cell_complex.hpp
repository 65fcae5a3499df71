// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// CellComplex: the pure combinatorics of a tissue (no positions, no
// properties): elements of degree 0..D with oriented borders and regions.
//
//   borders                              regions (kept in sync by every edit)
//   edge   -> 2 vertices (from, to)      vertex -> edges
//   face   -> closed oriented edge loop  edge   -> faces
//   volume -> faces with signs           face   -> volumes (at most 2)
//
// A face loop is stored twice, as oriented edges and as vertices (vertex i
// is where edge i starts), so geometry sweeps read only the vertex loop.
// A volume's face signs make every face normal point out of the volume.
// Removal leaves a tombstone; compact() renumbers. Users normally reach the
// complex through Tissue, which adds positions, properties and lineage.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/ragged_array.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"
#include "tessella/tissue/version_stamp.hpp"

namespace tessella {

/// Old-to-new index maps returned by compact(), one per degree
/// (kInvalidIndex for removed elements).
struct Renumbering {
  std::array<std::vector<Index>, 4> old_to_new;
  Index operator()(int degree, Index old) const { return old_to_new[degree][old]; }
  template <typename Tag>
  Handle<Tag> operator()(int degree, Handle<Tag> h) const {
    return Handle<Tag>(old_to_new[degree][h.index()]);
  }
};

/// A complex as flat lists, with everything that makes two complexes the
/// same and not merely alike: the numbering of every element, the direction
/// of every edge, where every face loop starts and which way it runs, and
/// the order of every border and region list (sums over them, and hence the
/// last bits of a simulation, follow that order). Live elements are numbered
/// in slot order, as compact() would. Lists are CSR: list k is
/// items[offsets[k] .. offsets[k+1]). Oriented items are packed as
/// 2 * index + (reversed ? 1 : 0). A 3D snapshot stores one, so that a
/// restart continues on the very complex the run had.
struct ComplexLayout {
  int dim = 2;
  std::size_t num_vertices = 0;
  std::vector<Index> edge_vertices;  ///< from, to of every edge
  std::vector<Index> face_edge_offsets, face_edges;
  std::vector<Index> volume_face_offsets, volume_faces;  ///< empty lists in 2D
  std::vector<Index> vertex_edge_offsets, vertex_edges;
  std::vector<Index> edge_face_offsets, edge_faces;
  std::vector<Index> face_volume_offsets, face_volumes;  ///< empty lists in 2D

  /// Every member equal: the same complex with the same numbering and order.
  bool operator==(const ComplexLayout&) const = default;
};

/// One end of a chord of CellComplex::splitFaces: an existing vertex of the
/// face's loop, a new vertex on one of its loop edges, or the new vertex an
/// earlier chord of the batch makes on that edge.
struct ChordEnd {
  VertexId vertex;  ///< the existing vertex; invalid otherwise
  EdgeId edge;      ///< the loop edge the new vertex splits (also for `same_as`)
  /// Where the new vertex lies along `edge`, from its first vertex (0) to its
  /// second (1): orders two new vertices on one edge.
  double t = 0.5;
  /// 2 j + k: the vertex is the one end k of the earlier chord j makes on `edge`.
  std::int32_t same_as = -1;
  bool isNew() const { return !vertex && same_as < 0; }
};

/// A face split by a chord between two points of its loop (CellComplex::splitFaces).
struct FaceChord {
  FaceId face;
  ChordEnd ends[2];
  /// Which part of the loop the new face gets: from end 0 to end 1, or from end 1 to end 0.
  bool new_face_from_0_to_1 = false;
};

/// What CellComplex::splitFaces made for one chord.
struct ChordSplit {
  VertexId vertex[2];  ///< the chord's ends
  /// For an end that made a new vertex: the edge it split, which ran from
  /// split_from to split_to at that moment and now ends at the vertex, and
  /// the new edge from the vertex to split_to. Invalid for other ends.
  EdgeId split_edge[2], new_edge[2];
  VertexId split_from[2], split_to[2];
  /// The end (2 j + k) that split the same edge after this one, or -1.
  std::int32_t next_on_edge[2] = {-1, -1};
  bool first_on_edge[2] = {false, false};  ///< a new vertex, the first on its edge
  EdgeId chord;  ///< the new edge between the ends
  FaceId face;   ///< the new face
};

class CellComplex {
 public:
  /// dim = 2 (vertices, edges, faces) or 3 (and volumes).
  explicit CellComplex(int dim);

  int dim() const { return dim_; }
  /// Number of slots of a degree, tombstones included (the bound for indices).
  std::size_t slots(int degree) const { return alive_[degree].size(); }
  /// Number of live elements of a degree.
  std::size_t count(int degree) const { return live_count_[degree]; }
  bool alive(int degree, Index i) const { return i < alive_[degree].size() && alive_[degree][i]; }
  bool alive(VertexId v) const { return alive(0, v.index()); }
  bool alive(EdgeId e) const { return alive(1, e.index()); }
  bool alive(FaceId f) const { return alive(2, f.index()); }
  bool alive(VolumeId c) const { return alive(3, c.index()); }

  // --- borders --------------------------------------------------------------
  VertexId edgeFrom(EdgeId e) const { return edge_vertices_[e.index()][0]; }
  VertexId edgeTo(EdgeId e) const { return edge_vertices_[e.index()][1]; }
  std::array<VertexId, 2> edgeVertices(EdgeId e) const { return edge_vertices_[e.index()]; }
  /// Start vertex of an oriented edge.
  VertexId tail(OrientedEdge oe) const {
    return oe.reversed() ? edgeTo(oe.handle()) : edgeFrom(oe.handle());
  }
  VertexId head(OrientedEdge oe) const {
    return oe.reversed() ? edgeFrom(oe.handle()) : edgeTo(oe.handle());
  }
  std::span<const OrientedEdge> faceEdges(FaceId f) const { return face_edges_[f.index()]; }
  std::span<const VertexId> faceVertices(FaceId f) const { return face_vertices_[f.index()]; }
  std::span<const OrientedFace> volumeFaces(VolumeId c) const { return volume_faces_[c.index()]; }

  // --- regions --------------------------------------------------------------
  std::span<const EdgeId> vertexEdges(VertexId v) const { return vertex_edges_[v.index()]; }
  std::span<const FaceId> edgeFaces(EdgeId e) const { return edge_faces_[e.index()]; }
  std::span<const VolumeId> faceVolumes(FaceId f) const { return face_volumes_[f.index()]; }

  /// The edge joining a and b, or an invalid handle.
  EdgeId findEdge(VertexId a, VertexId b) const;
  /// Position of edge e in f's loop, or -1.
  int loopPosition(FaceId f, EdgeId e) const;
  /// Position of vertex v in f's vertex loop, or -1.
  int loopPosition(FaceId f, VertexId v) const;
  /// Orientation of face f in volume c (+1, -1, 0 if f does not bound c).
  int faceSign(VolumeId c, FaceId f) const;

  // --- construction (checked; throw TopologyError, leaving the complex unchanged)
  VertexId addVertex();
  EdgeId addEdge(VertexId from, VertexId to);
  /// A face from a closed loop of oriented edges (each edge's head is the
  /// next edge's tail; no vertex repeats).
  FaceId addFace(std::span<const OrientedEdge> loop);
  /// A volume from faces with orientation signs; the surface must be closed
  /// and consistently oriented (each edge used once in each direction).
  VolumeId addVolume(std::span<const OrientedFace> faces);

  // --- bulk construction (generators, readers) --------------------------------
  /// A complex of `num_vertices` vertices and one face per vertex loop, given
  /// in CSR form: face k is loop_vertices[loop_offsets[k] .. loop_offsets[k+1]).
  /// Edges are created at their first use, in loop order: the result (ids and
  /// the order of every region list) is the one addVertex x n then one
  /// polygon per loop would give, without a search per edge. Throws
  /// TopologyError naming face k for a loop of fewer than 3 vertices, a vertex
  /// out of range or repeated in the loop, or (2D) an edge bounding a third face.
  ///
  /// `face_ids`, when given (a permutation of the faces), says the loops are
  /// listed in build order: loop q (loop_offsets[q] .. loop_offsets[q+1]) is
  /// face face_ids[q], and edges are numbered by first use in that order.
  /// Listing nearby faces one after the other (e.g. along a spatial sort)
  /// keeps the build streaming through memory when face ids are scattered.
  static CellComplex fromLoops(int dim, std::size_t num_vertices,
                               std::span<const Index> loop_offsets,
                               std::span<const Index> loop_vertices,
                               std::span<const Index> face_ids = {});
  /// The complex as a ComplexLayout (live elements only, renumbered in order).
  ComplexLayout layout() const;
  /// The complex a layout describes, every element numbered and every list
  /// ordered as listed. Checked like the element-by-element construction
  /// (closed loops, closed and consistently oriented volumes, no duplicate
  /// edge), and every region list must hold exactly the elements its borders
  /// imply; throws TopologyError naming the element otherwise.
  static CellComplex fromLayout(const ComplexLayout& layout);
  /// Appends volumes in bulk (3D): volume k is faces[offsets[k] .. offsets[k+1]).
  /// Same checks as addVolume (run in parallel, the first bad volume is
  /// reported); on error nothing is added.
  ///
  /// `closed_by_construction` (empty, or one flag per new volume): a volume
  /// flagged non-zero is taken as closed and consistently oriented without
  /// the per-edge count of its surface, because the caller's construction
  /// guarantees it (the Voronoi generator flags a cell read off the Delaunay
  /// triangulation whose Voronoi vertices are all distinct: its surface is
  /// the dual of its seed's link, a triangulated sphere, so each of its
  /// edges -- a Delaunay triangle -- is used once each way). Everything else
  /// is still checked for every volume (at least 4 faces, live and distinct,
  /// a face in at most two volumes); builds without NDEBUG or with
  /// TESSELLA_PARANOID ignore the flags and check every surface, and
  /// validate() checks the result in tests.
  void addVolumes(std::span<const Index> offsets, std::span<const OrientedFace> faces,
                  std::span<const std::uint8_t> closed_by_construction = {});

  /// Removes an element that bounds nothing (its regions are empty); its
  /// borders lose it from their regions.
  void remove(int degree, Index i);

  // --- topological edits used by Tissue's editing primitives ------------------
  /// Splits e = (a, b) into e = (a, v) and a new edge (v, b) with a new vertex
  /// v; every face through e gets v and the new edge in its loop.
  std::pair<VertexId, EdgeId> splitEdge(EdgeId e);
  /// Splits face f along a new edge between loop vertices a and b (not
  /// adjacent). f keeps the part of its loop from a to b (a -> ... -> b, then
  /// the new edge b -> a); the new face gets b -> ... -> a plus a -> b. Both
  /// keep f's orientation, and every volume bounded by f is bounded by both.
  std::pair<EdgeId, FaceId> splitFace(FaceId f, VertexId a, VertexId b);
  /// Splits volume c: the faces in `moving` go to a new volume, and a new
  /// face with the given loop is added, bounding c with sign `cut_sign` and
  /// the new volume with the opposite sign.
  std::pair<FaceId, VolumeId> splitVolume(VolumeId c, std::span<const FaceId> moving,
                                          std::span<const OrientedEdge> cut_loop, int cut_sign);

  /// Many face splits of a 2D complex at once, in parallel (OpenMP). The
  /// result (element numbering, every list and its order) is the one of
  /// taking the chords in order and, for each, splitting the edges of its new
  /// ends (the piece of the edge holding `t` when an earlier chord split it
  /// already) with splitEdge, then the face with splitFace(face, from, to),
  /// the new face getting the part from `from` to `to`. Faces are distinct;
  /// the two ends of a chord are on different, non-adjacent places of its
  /// loop. Checked before anything changes (TopologyError naming the face).
  /// The numbering is the same for any number of threads (prefix sums).
  UninitializedVector<ChordSplit> splitFaces(std::span<const FaceChord> chords);

  /// Drops tombstones and renumbers every degree, preserving order.
  Renumbering compact();

  /// Bumped by every topological change: caches compare it to know when to rebuild.
  std::uint64_t version() const { return version_.value(); }
  const std::vector<std::uint8_t>& aliveFlags(int degree) const { return alive_[degree]; }
  std::size_t bytes() const;

 private:
  Index newSlot(int degree);
  void checkLoop(std::span<const OrientedEdge> loop) const;

  int dim_;
  std::array<std::vector<std::uint8_t>, 4> alive_;
  std::array<std::size_t, 4> live_count_{};
  UninitializedVector<std::array<VertexId, 2>> edge_vertices_;  // grows unwritten (splitFaces)
  RaggedArray<OrientedEdge> face_edges_;
  RaggedArray<VertexId> face_vertices_;
  RaggedArray<OrientedFace> volume_faces_;
  RaggedArray<EdgeId> vertex_edges_;
  RaggedArray<FaceId> edge_faces_;
  RaggedArray<VolumeId> face_volumes_;
  VersionStamp version_;
};

}  // namespace tessella
