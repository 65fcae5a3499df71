// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// CellComplex::splitFaces: many chords of a 2D complex at once. Ids are handed
// out by prefix sums over the chords (the numbering the one-by-one
// splitEdge / splitFace sequence gives; parallelPrefixSum, the same for any
// number of threads), room for every list is made (where each goes by prefix
// sums too), then the lists are written in parallel, each by one thread: the
// edges cut by the chords (one thread per cut edge), then the face loops (one
// per face).

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <span>
#include <string>

#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/parallel_prefix_sum.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"
#include "parallel_claims.hpp"

namespace tessella {

namespace {

constexpr std::ptrdiff_t kParallelMin = 1024;  // fewer chords: one thread (a team costs more)
// The changed faces are the split ones (more work each), then their neighbours:
// passes over them deal chunks round-robin so that each thread gets a share of both.
constexpr int kBalancedChunk = 1024;

// Up to two new vertices on one edge, ordered along it: the pieces the edge
// becomes (from its first vertex to its second) and the vertices between them.
struct EdgeChain {
  int cuts = 0;
  EdgeId piece[3];
  VertexId inner[2];
};

}  // namespace

UninitializedVector<ChordSplit> CellComplex::splitFaces(std::span<const FaceChord> chords) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(chords.size());
  UninitializedVector<ChordSplit> out(chords.size());  // each written whole by the numbering pass
  if (n == 0) return out;
  if (dim_ != 2) throw TopologyError("splitFaces: the complex is 3D (chords split the faces of 2D complexes)", {});
  const Index f0 = static_cast<Index>(slots(2));

  // Face -> chord; faces of the batch are distinct and alive. Claimed in
  // parallel; on a dead face or a face claimed twice the serial loop runs
  // again to name the first defect in chord order.
  UninitializedVector<std::int32_t> chord_of = filledInParallel<std::int32_t>(slots(2), -1);
  if (!detail::claimInParallel(
          n, chord_of, [&](std::ptrdiff_t i) { return chords[i].face; }, [&](FaceId f) { return alive(f); },
          kParallelMin)) {
    std::fill(chord_of.begin(), chord_of.end(), -1);
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const FaceId f = chords[i].face;
      if (!alive(f)) throw TopologyError("splitFaces: chord " + std::to_string(i) + ": face " +
                                             std::to_string(f.index()) + " is not alive", {2, f.index()});
      if (chord_of[f.index()] >= 0)
        throw TopologyError("splitFaces: face " + std::to_string(f.index()) + " is split by chords " +
                                std::to_string(chord_of[f.index()]) + " and " + std::to_string(i),
                            {2, f.index()});
      chord_of[f.index()] = static_cast<std::int32_t>(i);
    }
  }
  // The chord splitting a face (or the new face a chord made), -1 for none.
  // Edge-face lists are read with atomic loads: pass B rewrites other items of them.
  auto chordOfFace = [&](FaceId g) -> std::int32_t {
    if (g.index() >= f0) return static_cast<std::int32_t>(g.index() - f0);
    return chord_of[g.index()];
  };
  auto facesOf = [&](EdgeId e, FaceId* faces) {
    auto list = edge_faces_.mutableList(e.index());
    int m = 0;
    for (FaceId& g : list.first(std::min<std::size_t>(list.size(), 2)))
      faces[m++] = std::atomic_ref<FaceId>(g).load(std::memory_order_relaxed);
    return m;
  };

  // Checks, before anything changes.
  auto problem = [&](std::ptrdiff_t i) -> std::string {
    const FaceChord& ch = chords[i];
    const FaceId f = ch.face;
    auto who = [&] {  // spelled out only for an error
      return "splitFaces: chord " + std::to_string(i) + " of face " + std::to_string(f.index());
    };
    for (int k = 0; k < 2; ++k) {
      const ChordEnd& end = ch.ends[k];
      if (end.vertex) {
        if (loopPosition(f, end.vertex) < 0)
          return who() + ": vertex " + std::to_string(end.vertex.index()) + " is not on its loop";
      } else {
        if (!end.edge || loopPosition(f, end.edge) < 0)
          return who() + ": edge " + std::to_string(end.edge.index()) + " is not on its loop";
        if (end.same_as >= 0) {
          const std::int32_t j = end.same_as / 2;
          if (j >= i || !chords[j].ends[end.same_as % 2].isNew() || chords[j].ends[end.same_as % 2].edge != end.edge)
            return who() + ": end " + std::to_string(k) + " reuses end " + std::to_string(end.same_as) +
                   ", which makes no vertex on edge " + std::to_string(end.edge.index()) + " before it";
        }
      }
    }
    const ChordEnd &a = ch.ends[0], &b = ch.ends[1];
    if (a.vertex && b.vertex) {
      const int n_loop = static_cast<int>(face_vertices_[f.index()].size());
      const int ia = loopPosition(f, a.vertex), ib = loopPosition(f, b.vertex);
      if (ia == ib || (ia + 1) % n_loop == ib || (ib + 1) % n_loop == ia)
        return who() + ": vertices " + std::to_string(a.vertex.index()) + " and " + std::to_string(b.vertex.index()) +
               " are equal or adjacent on its loop";
      if (findEdge(a.vertex, b.vertex))
        return who() + ": vertices " + std::to_string(a.vertex.index()) + " and " + std::to_string(b.vertex.index()) +
               " are already joined by an edge";
    } else if (!a.vertex && !b.vertex) {
      if (a.edge == b.edge) return who() + ": both ends on edge " + std::to_string(a.edge.index());
    } else {
      const VertexId v = a.vertex ? a.vertex : b.vertex;
      const EdgeId e = a.vertex ? b.edge : a.edge;
      if (edgeFrom(e) == v || edgeTo(e) == v)
        return who() + ": vertex " + std::to_string(v.index()) + " is an end of the cut edge " +
               std::to_string(e.index());
    }
    return {};
  };
  // The per-chord scratch arrays are UninitializedVectors written whole by the
  // parallel passes (no serial zeroing and first touch of tens of MB).
  UninitializedVector<std::uint8_t> bad(chords.size());
  bool any_bad = false;
#pragma omp parallel for schedule(static) reduction(|| : any_bad) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    bad[i] = !problem(i).empty();
    any_bad = any_bad || bad[i];
  }
  if (any_bad)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (bad[i]) throw TopologyError(problem(i), {2, chords[i].face.index()});

  // The other new end on the same edge (a face's chord cuts an edge once; an
  // edge of a 2D complex bounds at most two faces).
  auto partnerOf = [&](std::ptrdiff_t i, int k) -> std::int32_t {
    const EdgeId e = chords[i].ends[k].edge;
    FaceId faces[2];
    const int m = facesOf(e, faces);
    for (int q = 0; q < m; ++q) {
      const std::int32_t j = chordOfFace(faces[q]);
      if (j < 0 || j == i) continue;
      for (int kk = 0; kk < 2; ++kk)
        if (chords[j].ends[kk].isNew() && chords[j].ends[kk].edge == e) return 2 * j + kk;
    }
    return -1;
  };
  // Also per new end: how many faces its edge bounds, and the neighbour across it.
  UninitializedVector<std::int32_t> partner(2 * chords.size()), reused_by(2 * chords.size());
  UninitializedVector<std::uint32_t> edge_face_count(2 * chords.size());
  UninitializedVector<Index> across(2 * chords.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      partner[2 * i + k] = -1;
      reused_by[2 * i + k] = -1;  // the later end that reuses this end's vertex (numbering, below)
      edge_face_count[2 * i + k] = 0;
      across[2 * i + k] = kInvalidIndex;
      if (!chords[i].ends[k].isNew()) continue;
      partner[2 * i + k] = partnerOf(i, k);
      const auto faces = edge_faces_[chords[i].ends[k].edge.index()];
      edge_face_count[2 * i + k] = static_cast<std::uint32_t>(faces.size());
      for (FaceId g : faces)
        if (chord_of[g.index()] < 0) across[2 * i + k] = g.index();
    }

  // Numbering, in the order of the one-by-one sequence: per chord the vertex
  // and edge of end 0, of end 1, then the chord's edge and the new face. So
  // chord i's first new vertex is v0 + (new ends of the chords before it),
  // its first new edge e0 + that + i: one prefix sum over the chords.
  const Index v0 = static_cast<Index>(slots(0)), e0 = static_cast<Index>(slots(1));
  UninitializedVector<Index> new_before(chords.size());
  const Index nv = parallelPrefixSum<Index>(
      n, [&](std::ptrdiff_t i) { return Index{chords[i].ends[0].isNew()} + Index{chords[i].ends[1].isNew()}; },
      [&](std::ptrdiff_t i, Index before) { new_before[i] = before; });
  const Index ne = nv + static_cast<Index>(n);
  // Faces per new edge (the pieces of cut edges, the chords), edges per new vertex.
  UninitializedVector<std::uint32_t> edge_face_sizes(ne), vertex_edge_sizes(nv);
#pragma omp parallel if (n >= kParallelMin)
  {
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      ChordSplit& s = out[i];
      s = ChordSplit{};
      Index at = new_before[i];  // this chord's next new vertex, minus v0
      for (int k = 0; k < 2; ++k) {
        const ChordEnd& end = chords[i].ends[k];
        if (end.vertex) {
          s.vertex[k] = end.vertex;
        } else if (end.same_as < 0) {
          s.vertex[k] = VertexId(v0 + at);
          s.new_edge[k] = EdgeId(e0 + at + static_cast<Index>(i));
          edge_face_sizes[at + i] = edge_face_count[2 * i + k];
          vertex_edge_sizes[at] = 3;
          ++at;
          const std::int32_t p = partner[2 * i + k];
          s.first_on_edge[k] = p < 0 || p > 2 * i + k;
          if (s.first_on_edge[k] && p >= 0) s.next_on_edge[k] = p;
        }
      }
      s.chord = EdgeId(e0 + at + static_cast<Index>(i));
      edge_face_sizes[at + i] = 2;
      s.face = FaceId(f0 + static_cast<Index>(i));
    }
    // Ends reusing an earlier end's vertex (a new end, numbered above): one
    // more edge at it, and the reusing end (the last one, as the serial
    // loop's last write, should two ends reuse one).
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k) {
        const std::int32_t same_as = chords[i].ends[k].same_as;
        if (chords[i].ends[k].vertex || same_as < 0) continue;
        const VertexId v = out[same_as / 2].vertex[same_as % 2];
        out[i].vertex[k] = v;
        std::atomic_ref<std::uint32_t>(vertex_edge_sizes[v.index() - v0]).fetch_add(1, std::memory_order_relaxed);
        std::atomic_ref<std::int32_t> reuser(reused_by[same_as]);
        const std::int32_t mine = static_cast<std::int32_t>(2 * i + k);
        std::int32_t seen = reuser.load(std::memory_order_relaxed);
        while (seen < mine && !reuser.compare_exchange_weak(seen, mine, std::memory_order_relaxed)) {
        }
      }
  }

  // The pieces of a cut edge, from the chords that cut it (one or two).
  auto chainOf = [&](std::int32_t first_end) {
    const std::ptrdiff_t i = first_end / 2;
    const int k = first_end % 2;
    const ChordSplit& s = out[i];
    EdgeChain c;
    c.piece[0] = chords[i].ends[k].edge;
    const std::int32_t next = s.next_on_edge[k];
    if (next < 0) {
      c.cuts = 1;
      c.piece[1] = s.new_edge[k];
      c.inner[0] = s.vertex[k];
      return c;
    }
    c.cuts = 2;
    const ChordSplit& s2 = out[next / 2];
    const int k2 = next % 2;
    if (chords[next / 2].ends[k2].t > chords[i].ends[k].t) {
      c.piece[1] = s.new_edge[k];
      c.piece[2] = s2.new_edge[k2];
      c.inner[0] = s.vertex[k];
      c.inner[1] = s2.vertex[k2];
    } else {
      c.piece[1] = s2.new_edge[k2];
      c.piece[2] = s.new_edge[k];
      c.inner[0] = s2.vertex[k2];
      c.inner[1] = s.vertex[k];
    }
    return c;
  };
  // The first end cutting each edge that existed before the batch, or -1
  // (one end per edge is first on it, so each entry is written once).
  UninitializedVector<std::int32_t> first_cut = filledInParallel<std::int32_t>(e0, -1);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k)
      if (out[i].first_on_edge[k]) first_cut[chords[i].ends[k].edge.index()] = static_cast<std::int32_t>(2 * i + k);
  auto firstCutOn = [&](EdgeId e) -> std::int32_t { return e.index() < e0 ? first_cut[e.index()] : -1; };

  // The faces whose loops change: the split faces, then the neighbours across cut edges.
  // Each neighbour once, where it first appears (in chord order): claimed in
  // parallel by the smallest position (chord_of holds -2 - position), then
  // gathered in order.
  const std::ptrdiff_t n2 = 2 * n;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t p = 0; p < n2; ++p) {
    if (across[p] == kInvalidIndex) continue;
    std::atomic_ref<std::int32_t> owner(chord_of[across[p]]);
    const std::int32_t mine = static_cast<std::int32_t>(-2 - p);
    std::int32_t seen = owner.load(std::memory_order_relaxed);
    while ((seen == -1 || seen < mine) && !owner.compare_exchange_weak(seen, mine, std::memory_order_relaxed)) {
    }
  }
  UninitializedVector<Index> affected(3 * chords.size());  // cut to its size below
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) affected[i] = chords[i].face.index();
  auto claimedAt = [&](std::ptrdiff_t p) { return across[p] != kInvalidIndex && chord_of[across[p]] == -2 - p; };
  const std::ptrdiff_t na =
      n + parallelPrefixSum<std::ptrdiff_t>(
              n2, [&](std::ptrdiff_t p) { return std::ptrdiff_t{claimedAt(p)}; },
              [&](std::ptrdiff_t p, std::ptrdiff_t before) {
                if (claimedAt(p)) affected[n + before] = across[p];
              });
  affected.resize(static_cast<std::size_t>(na));
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t q = n; q < na; ++q) chord_of[affected[q]] = -1;

  // A face's loop with every cut edge replaced by its pieces (and new
  // vertices), appended to edges and verts.
  auto expandedLoop = [&](FaceId f, std::vector<OrientedEdge>& edges, std::vector<VertexId>& verts) {
    const std::size_t size = face_edges_.listSize(f.index());
    const OrientedEdge* loop_e = face_edges_.mutableList(f.index()).data();
    const VertexId* loop_v = face_vertices_.mutableList(f.index()).data();
    for (std::size_t r = 0; r < size; ++r) {
      const OrientedEdge oe = loop_e[r];
      const std::int32_t first = firstCutOn(oe.handle());
      if (first < 0) {
        edges.push_back(oe);
        verts.push_back(loop_v[r]);
        continue;
      }
      const EdgeChain c = chainOf(first);
      if (!oe.reversed()) {
        edges.push_back(oe);
        verts.push_back(loop_v[r]);
        for (int q = 0; q < c.cuts; ++q) {
          edges.emplace_back(c.piece[q + 1], false);
          verts.push_back(c.inner[q]);
        }
      } else {
        edges.emplace_back(c.piece[c.cuts], true);
        verts.push_back(loop_v[r]);
        for (int q = c.cuts - 1; q >= 0; --q) {
          edges.emplace_back(c.piece[q], true);
          verts.push_back(c.inner[q]);
        }
      }
    }
  };
  auto fromTo = [&](std::ptrdiff_t i) {
    const bool swap = chords[i].new_face_from_0_to_1;
    return std::pair<VertexId, VertexId>(out[i].vertex[swap ? 1 : 0], out[i].vertex[swap ? 0 : 1]);
  };
  auto position = [](std::span<const VertexId> verts, VertexId v) {
    for (std::size_t r = 0; r < verts.size(); ++r)
      if (verts[r] == v) return static_cast<std::ptrdiff_t>(r);
    return std::ptrdiff_t{-1};
  };

  // The expanded loops, built once: each thread appends those of its faces
  // to its own pool (where each lies is kept for pass B).
  struct Outlines {
    std::vector<OrientedEdge> edges;
    std::vector<VertexId> verts;
  };
  struct OutlineAt {
    std::uint32_t pool = 0, at = 0, size = 0;
  };
  std::vector<Outlines> pools;
  UninitializedVector<OutlineAt> outline(affected.size());
  auto outlineEdges = [&](std::ptrdiff_t q) {
    const OutlineAt& o = outline[q];
    return std::span<const OrientedEdge>(pools[o.pool].edges.data() + o.at, o.size);
  };
  auto outlineVerts = [&](std::ptrdiff_t q) {
    const OutlineAt& o = outline[q];
    return std::span<const VertexId>(pools[o.pool].verts.data() + o.at, o.size);
  };

  // Sizes of the new loops: a split face keeps from..to plus the chord, its
  // new face gets to..from plus the chord.
  UninitializedVector<std::uint32_t> loop_sizes(affected.size()), new_face_sizes(chords.size());
#pragma omp parallel if (n >= kParallelMin)
  {
#pragma omp single
    pools.resize(static_cast<std::size_t>(omp_get_num_threads()));
    const int tid = omp_get_thread_num();
    Outlines& mine = pools[static_cast<std::size_t>(tid)];
    const std::size_t share = static_cast<std::size_t>(na) / pools.size() + 1;
    mine.edges.reserve(8 * share);
    mine.verts.reserve(8 * share);
#pragma omp for schedule(static, kBalancedChunk)
    for (std::ptrdiff_t q = 0; q < na; ++q) {
      const std::size_t at = mine.edges.size();
      expandedLoop(FaceId(affected[q]), mine.edges, mine.verts);
      const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(mine.edges.size() - at);
      outline[q] = {static_cast<std::uint32_t>(tid), static_cast<std::uint32_t>(at), static_cast<std::uint32_t>(m)};
      if (q >= n) {
        loop_sizes[q] = static_cast<std::uint32_t>(m);
        continue;
      }
      const auto [from, to] = fromTo(q);
      const std::span<const VertexId> verts(mine.verts.data() + at, static_cast<std::size_t>(m));
      const std::ptrdiff_t ia = position(verts, from), ib = position(verts, to);
      const std::ptrdiff_t keep = (ib - ia + m) % m;
      loop_sizes[q] = static_cast<std::uint32_t>(keep + 1);
      new_face_sizes[q] = static_cast<std::uint32_t>(m - keep + 1);
    }
  }

  // Room for everything, serially.
  for (auto [degree, count] : {std::pair{0, nv}, std::pair{1, ne}, std::pair{2, static_cast<Index>(n)}}) {
    alive_[degree].resize(alive_[degree].size() + count, 1);
    live_count_[degree] += count;
  }
  ++version_;
  growInParallel(edge_vertices_, slots(1));  // every new edge is written by pass A
  vertex_edges_.appendLists(vertex_edge_sizes);
  edge_faces_.appendLists(edge_face_sizes);
  face_edges_.resizeLists(affected, loop_sizes);
  face_vertices_.resizeLists(affected, loop_sizes);
  face_edges_.appendLists(new_face_sizes);
  face_vertices_.appendLists(new_face_sizes);
  face_volumes_.appendLists(filledInParallel<std::uint32_t>(chords.size(), 0));

  // Pass A: the cut edges (by the thread of the first chord cutting each) and the chords' edges.
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    ChordSplit& s = out[i];
    for (int k = 0; k < 2; ++k) {
      if (!s.first_on_edge[k]) continue;
      const EdgeId e = chords[i].ends[k].edge;
      const VertexId a = edgeFrom(e), b = edgeTo(e);
      const EdgeChain c = chainOf(static_cast<std::int32_t>(2 * i + k));
      VertexId along[4] = {a};
      for (int q = 0; q < c.cuts; ++q) along[q + 1] = c.inner[q];
      along[c.cuts + 1] = b;
      const auto faces = edge_faces_[e.index()];
      for (int q = 0; q <= c.cuts; ++q) {
        edge_vertices_[c.piece[q].index()] = {along[q], along[q + 1]};
        if (q > 0) std::copy(faces.begin(), faces.end(), edge_faces_.mutableList(c.piece[q].index()).begin());
      }
      for (int q = 0; q < c.cuts; ++q) {
        // A new vertex: its two pieces, its chord, and the chord of a later end reusing it.
        const VertexId v = c.inner[q];
        const bool mine = v == s.vertex[k];
        const std::int32_t end = mine ? static_cast<std::int32_t>(2 * i + k) : s.next_on_edge[k];
        auto list = vertex_edges_.mutableList(v.index());
        list[0] = c.piece[q];
        list[1] = c.piece[q + 1];
        list[2] = out[end / 2].chord;
        if (reused_by[end] >= 0) list[3] = out[reused_by[end] / 2].chord;
      }
      vertex_edges_.replaceValueShared(b.index(), e, c.piece[c.cuts]);
      // The one-by-one sequence's edge splits: which edge each end split, and its ends then.
      s.split_edge[k] = e;
      s.split_from[k] = a;
      s.split_to[k] = b;
      if (c.cuts == 2) {
        ChordSplit& s2 = out[s.next_on_edge[k] / 2];
        const int k2 = s.next_on_edge[k] % 2;
        const bool after = c.inner[1] == s2.vertex[k2];
        s2.split_edge[k2] = after ? s.new_edge[k] : e;
        s2.split_from[k2] = after ? s.vertex[k] : a;
        s2.split_to[k2] = after ? b : s.vertex[k];
      }
    }
    const auto [from, to] = fromTo(i);
    edge_vertices_[s.chord.index()] = {from, to};
    auto list = edge_faces_.mutableList(s.chord.index());
    list[0] = chords[i].face;
    list[1] = s.face;
  }

  // Pass B: the loops of the affected faces; a split face hands its part from
  // `to` to `from` (and the edges in it) to its new face.
#pragma omp parallel for schedule(static, kBalancedChunk) if (n >= kParallelMin)
  for (std::ptrdiff_t q = 0; q < na; ++q) {
    const FaceId f(affected[q]);
    const std::span<const OrientedEdge> edges = outlineEdges(q);
    const std::span<const VertexId> verts = outlineVerts(q);
    if (q >= n) {
      std::copy(edges.begin(), edges.end(), face_edges_.mutableList(f.index()).begin());
      std::copy(verts.begin(), verts.end(), face_vertices_.mutableList(f.index()).begin());
      continue;
    }
    const ChordSplit& s = out[q];
    const auto [from, to] = fromTo(q);
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(edges.size());
    const std::ptrdiff_t ia = position(verts, from), ib = position(verts, to);
    auto keep_e = face_edges_.mutableList(f.index());
    auto keep_v = face_vertices_.mutableList(f.index());
    std::size_t w = 0;
    for (std::ptrdiff_t r = ia; r != ib; r = (r + 1) % m, ++w) {
      keep_e[w] = edges[r];
      keep_v[w] = verts[r];
    }
    keep_e[w] = OrientedEdge(s.chord, true);  // to -> from
    keep_v[w] = to;
    auto move_e = face_edges_.mutableList(s.face.index());
    auto move_v = face_vertices_.mutableList(s.face.index());
    w = 0;
    for (std::ptrdiff_t r = ib; r != ia; r = (r + 1) % m, ++w) {
      move_e[w] = edges[r];
      move_v[w] = verts[r];
      edge_faces_.replaceValueShared(edges[r].handle().index(), f, s.face);
    }
    move_e[w] = OrientedEdge(s.chord, false);  // from -> to
    move_v[w] = from;
  }

  // Pass C: existing vertices join the chords at them, serially and in chord
  // order (a list that grows moves to the end of the pool); the chords with
  // an end at an existing vertex (few) are found in parallel first.
  auto oldEnds = [&](std::ptrdiff_t i) {
    const auto [from, to] = fromTo(i);
    return std::ptrdiff_t{from.index() < v0} + std::ptrdiff_t{to.index() < v0};
  };
  UninitializedVector<std::int32_t> joining(chords.size());  // written up to its count
  const std::ptrdiff_t n_joining = parallelPrefixSum<std::ptrdiff_t>(
      n, [&](std::ptrdiff_t i) { return std::ptrdiff_t{oldEnds(i) > 0}; },
      [&](std::ptrdiff_t i, std::ptrdiff_t before) {
        if (oldEnds(i) > 0) joining[before] = static_cast<std::int32_t>(i);
      });
  for (std::ptrdiff_t q = 0; q < n_joining; ++q) {
    const std::ptrdiff_t i = joining[q];
    const auto [from, to] = fromTo(i);
    for (VertexId v : {from, to})
      if (v.index() < v0) vertex_edges_.pushBack(v.index(), out[i].chord);
  }
  return out;
}

}  // namespace tessella
