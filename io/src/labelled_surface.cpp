// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The part of importing shared by the formats whose cells are labelled
// patches of one polygon surface (MorphoGraphX cell meshes, cell-complex PLY
// files of an L1 layer): each label's faces must form a disk, whose outline
// (the boundary of their union, followed the way the faces run, so two
// neighbours traverse their shared wall in opposite directions, as validate()
// requires) becomes a cell of a curved-sheet tissue. Checked: one connected
// piece per label (faces joined by edges), every edge in at most two of its
// faces and used once each way, one boundary loop, no pinched vertex, Euler
// characteristic 1.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <unordered_map>

#include "labelled_surface.hpp"
#include "polyline_simplification.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io::detail {

std::string fmtPoint(const Vec3& p) { return formatPoint(p, 9); }

void checkImportOptions(const ImportOptions& o) {
  if (!(std::isfinite(o.scale) && o.scale > 0))
    throw InputError("import scale must be a positive finite number, got " + formatNumber(o.scale));
  if (!(std::isfinite(o.simplify) && o.simplify >= 0))
    throw InputError("import simplify tolerance must be >= 0 (0 = off), got " + formatNumber(o.simplify));
}

// Two used vertices at the same position: the mesh is not welded.
void checkDuplicateVertices(const LabelledSurface& m) {
  std::vector<Index> first_face(m.positions.size(), kInvalidIndex);
  for (std::size_t f = 0; f < m.numFaces(); ++f)
    for (Index v : m.face(f))
      if (first_face[v] == kInvalidIndex) first_face[v] = static_cast<Index>(f);
  // A flat open-addressing table of positions (linear probing), filled in
  // index order: a vertex finding its position taken is a duplicate. Of all
  // duplicates, the one reported is at the smallest position (x, then y, z)
  // and the two smallest indices there, whatever the table's order.
  std::size_t size = 16;
  while (size < 2 * m.positions.size()) size *= 2;
  const std::size_t mask = size - 1;
  std::vector<Index> table(size, kInvalidIndex);
  auto hash = [](const Vec3& p) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int k = 0; k < 3; ++k) {
      const double c = p[k] + 0.0;  // -0 and +0 compare equal: hash them alike
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return h;
  };
  auto lexLess = [](const Vec3& p, const Vec3& q) {
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    return p.z() < q.z();
  };
  Index dup_a = kInvalidIndex, dup_b = kInvalidIndex;
  for (Index v = 0; v < m.positions.size(); ++v) {
    if (first_face[v] == kInvalidIndex) continue;
    const Vec3& p = m.positions[v];
    for (std::size_t i = hash(p) & mask;; i = (i + 1) & mask) {
      const Index w = table[i];
      if (w == kInvalidIndex) {
        table[i] = v;
        break;
      }
      if (m.positions[w] == p) {  // w < v is the first vertex here; keep the second one only
        if (dup_a == kInvalidIndex || lexLess(p, m.positions[dup_a]) ||
            (m.positions[dup_a] == p && v < dup_b))
          dup_a = w, dup_b = v;
        break;
      }
    }
  }
  if (dup_a != kInvalidIndex) {
    const Index a = dup_a, b = dup_b;
    throw InputError("'" + m.path + "' vertices " + std::to_string(a) + " and " + std::to_string(b) +
                     " are duplicates at " + fmtPoint(m.positions[a]) + " (used by face " + m.faceId(first_face[a]) +
                     " of cell label " + std::to_string(m.face_label[first_face[a]]) + " and face " +
                     m.faceId(first_face[b]) + " of cell label " + std::to_string(m.face_label[first_face[b]]) +
                     "): the mesh is not welded, neighbours would not share their walls");
  }
}

namespace {

// The cells of a mesh: faces grouped by label (sorted by label), each
// checked to be a disk, with its oriented outline.

// The directed edges of the faces, grouped by tail vertex (a counting sort,
// linear): the face running along u->v is found by scanning u's few edges.
// Sorted vectors instead of a hash map of edges: building this and the
// lookups were most of an import's time.
struct DirectedEdges {
  struct Entry {
    Index head, face, corner;  // corner: position of the tail in the face's loop
  };
  std::vector<std::size_t> start;  // per tail vertex, into entries (size vertices + 1)
  std::vector<Entry> entries;      // per tail, sorted by (head, face)

  /// The face running along u->v, or kInvalidIndex.
  Index face(Index u, Index v) const {
    for (std::size_t i = start[u]; i < start[u + 1]; ++i)
      if (entries[i].head == v) return entries[i].face;
    return kInvalidIndex;
  }
};

// Builds the directed edges; throws on an edge used twice the same way (the
// first such face in file order, as a sequential scan would find it).
void buildDirectedEdges(const LabelledSurface& m, DirectedEdges& out) {
  out.start.assign(m.positions.size() + 1, 0);
  for (Index u : m.face_vertices) ++out.start[u + 1];
  for (std::size_t i = 1; i < out.start.size(); ++i) out.start[i] += out.start[i - 1];
  out.entries.resize(m.face_vertices.size());
  std::vector<std::size_t> fill(out.start.begin(), out.start.end() - 1);
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const auto loop = m.face(f);
    for (std::size_t k = 0; k < loop.size(); ++k)
      out.entries[fill[loop[k]]++] = {loop[(k + 1) % loop.size()], static_cast<Index>(f), static_cast<Index>(k)};
  }
  // Per tail: sort by (head, face); equal heads are an edge used twice.
  struct Clash {
    Index face = kInvalidIndex, corner = 0, earlier = 0, tail = 0, head = 0;
  } clash;
  for (std::size_t u = 0; u + 1 < out.start.size(); ++u) {
    const auto first = out.entries.begin() + static_cast<std::ptrdiff_t>(out.start[u]);
    const auto last = out.entries.begin() + static_cast<std::ptrdiff_t>(out.start[u + 1]);
    auto less = [](const DirectedEdges::Entry& a, const DirectedEdges::Entry& b) {
      return a.head != b.head ? a.head < b.head : a.face < b.face;
    };
    if (last - first > 16) {
      std::sort(first, last, less);
    } else {  // a vertex has a few edges: insertion sort
      for (auto it = first + (first != last); it < last; ++it)
        for (auto j = it; j != first && less(*j, *(j - 1)); --j) std::iter_swap(j, j - 1);
    }
    for (auto it = first; it + 1 < last; ++it)
      if (it->head == (it + 1)->head) {
        const auto& later = *(it + 1);
        if (later.face < clash.face || (later.face == clash.face && later.corner < clash.corner))
          clash = {later.face, later.corner, it->face, static_cast<Index>(u), it->head};
      }
  }
  if (clash.face == kInvalidIndex) return;
  const Index f = clash.face, g = clash.earlier, u = clash.tail, v = clash.head;
  if (m.face_label[g] == m.face_label[f])
    throw InputError("'" + m.path + "' face " + m.faceId(f) + " (cell label " + std::to_string(m.face_label[f]) +
                     "): it and face " + m.faceId(g) + " both run along edge " + std::to_string(u) + "->" +
                     std::to_string(v) +
                     ": the cell's triangles are not a disk (more than two meet at an edge, or they are "
                     "oriented inconsistently)");
  throw InputError("'" + m.path + "' face " + m.faceId(f) + " (cell label " + std::to_string(m.face_label[f]) +
                   ") and face " + m.faceId(g) + " (cell label " + std::to_string(m.face_label[g]) +
                   ") both run along edge " + std::to_string(u) + "->" + std::to_string(v) +
                   ": the two cells are oriented opposite ways, or more than two triangles meet at that edge");
}

// Per cell, the connected pieces of its faces (faces joined by an edge), in
// the order of their first face; none listed when the cell is one piece.
// Fills `edges`.
std::vector<std::vector<std::vector<Index>>> pieces(const LabelledSurface& m, const std::vector<Label>& labels,
                                                    const std::vector<std::vector<Index>>& faces,
                                                    DirectedEdges& edges) {
  buildDirectedEdges(m, edges);
  UnionFind uf(m.numFaces());
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const auto loop = m.face(f);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Index g = edges.face(loop[(k + 1) % loop.size()], loop[k]);
      if (g != kInvalidIndex && m.face_label[g] == m.face_label[f]) uf.unite(static_cast<Index>(f), g);
    }
  }
  std::vector<std::vector<std::vector<Index>>> out(labels.size());
  std::vector<std::pair<Index, Index>> roots;  // (root, position in the cell's face list)
  for (std::size_t c = 0; c < labels.size(); ++c) {
    const auto& fs = faces[c];
    const Index root0 = uf.find(fs.front());
    bool one = true;
    for (Index f : fs) one = one && uf.find(f) == root0;
    if (one) continue;  // no list: one piece, the cell's faces
    // Several pieces: group by root, pieces ordered by their first face.
    roots.clear();
    for (Index q = 0; q < fs.size(); ++q) roots.emplace_back(uf.find(fs[q]), q);
    std::sort(roots.begin(), roots.end());
    std::vector<std::pair<Index, std::vector<Index>>> grouped;  // (first position, faces)
    for (std::size_t i = 0; i < roots.size(); ++i) {
      if (i == 0 || roots[i].first != roots[i - 1].first) grouped.emplace_back(roots[i].second, std::vector<Index>{});
      grouped.back().second.push_back(roots[i].second);
    }
    std::sort(grouped.begin(), grouped.end());
    for (auto& [pos, members] : grouped) {
      std::sort(members.begin(), members.end());
      for (Index& q : members) q = fs[q];
      out[c].push_back(std::move(members));
    }
  }
  return out;
}

void groupByLabel(const LabelledSurface& m, std::vector<Label>& labels, std::vector<std::vector<Index>>& faces) {
  labels.assign(m.face_label.begin(), m.face_label.end());
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  faces.assign(labels.size(), {});
  {
    std::vector<Index> count(labels.size(), 0);
    std::size_t c = 0;
    for (std::size_t f = 0; f < m.numFaces(); ++f) {
      if (labels[c] != m.face_label[f])
        c = static_cast<std::size_t>(std::lower_bound(labels.begin(), labels.end(), m.face_label[f]) - labels.begin());
      ++count[c];
    }
    for (std::size_t k = 0; k < labels.size(); ++k) faces[k].reserve(count[k]);
  }
  std::size_t c = 0;  // files list a cell's faces together: try the previous face's cell first
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    if (labels[c] != m.face_label[f])
      c = static_cast<std::size_t>(std::lower_bound(labels.begin(), labels.end(), m.face_label[f]) - labels.begin());
    faces[c].push_back(static_cast<Index>(f));
  }
}

// Repairs one-triangle slivers: a single triangle of a cell lying apart from
// the rest of it moves to the neighbour it shares most edges with (dropped if
// it shares none). Returns whether anything changed.
bool repairSlivers(LabelledSurface& m, const std::vector<Label>& labels,
                   const std::vector<std::vector<std::vector<Index>>>& parts,
                   const DirectedEdges& edges, std::vector<std::string>& repairs,
                   std::vector<char>& dropped) {
  bool changed = false;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    if (parts[c].size() < 2) continue;
    std::size_t big = 0;
    for (const auto& p : parts[c]) big += p.size() > 1;
    if (big != 1) continue;  // two real pieces: not a sliver, reported as an error
    for (const auto& p : parts[c]) {
      if (p.size() != 1) continue;
      const Index f = p[0];
      std::unordered_map<Label, int> shared;
      const auto loop = m.face(f);
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Index g = edges.face(loop[(k + 1) % loop.size()], loop[k]);
        if (g != kInvalidIndex && m.face_label[g] != labels[c]) ++shared[m.face_label[g]];
      }
      Label best = 0;
      int most = 0;
      for (const auto& [label, n] : shared)
        if (n > most || (n == most && label < best)) best = label, most = n;
      if (most > 0) {
        repairs.push_back("face " + m.faceId(f) + ", a one-triangle sliver of cell label " +
                          std::to_string(labels[c]) + " apart from the rest of that cell, moved to cell label " +
                          std::to_string(best) + " (it shares " + std::to_string(most) + " edge(s) with it)");
        m.face_label[f] = best;
      } else {
        repairs.push_back("face " + m.faceId(f) + ", a one-triangle sliver of cell label " +
                          std::to_string(labels[c]) + " apart from the rest of that cell, dropped (it shares no "
                          "edge with another cell)");
        dropped[f] = 1;
      }
      changed = true;
    }
  }
  if (!changed) return false;
  // Remove dropped faces for good.
  LabelledSurface kept = m;
  kept.face_offsets = {0};
  kept.face_vertices.clear();
  kept.face_label.clear();
  kept.file_face.clear();
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    if (dropped[f]) continue;
    for (Index v : m.face(f)) kept.face_vertices.push_back(v);
    kept.face_offsets.push_back(kept.face_vertices.size());
    kept.face_label.push_back(m.face_label[f]);
    kept.file_face.push_back(m.file_face.empty() ? static_cast<Index>(f) : m.file_face[f]);
  }
  m = std::move(kept);
  std::fill(dropped.begin(), dropped.end(), 0);
  dropped.resize(m.numFaces(), 0);
  return true;
}

SheetCells findCells(LabelledSurface& m, bool repair, ImportReport& report) {
  SheetCells cells;
  DirectedEdges owner;
  std::vector<std::vector<std::vector<Index>>> parts;
  std::vector<char> dropped(m.numFaces(), 0);
  for (int round = 0;; ++round) {
    groupByLabel(m, cells.labels, cells.faces);
    parts = pieces(m, cells.labels, cells.faces, owner);
    if (!repair || round > 0 || !repairSlivers(m, cells.labels, parts, owner, report.repairs, dropped)) break;
  }
  const std::size_t n = cells.labels.size();
  // One piece per cell.
  for (std::size_t c = 0; c < n; ++c) {
    if (parts[c].size() < 2) continue;
    const Label label = cells.labels[c];
    // A piece holding a vertex labelled like the cell is a fan around its own
    // centre: two such pieces are two cells that got the same label.
    std::vector<Index> with_centre;
    for (const auto& p : parts[c]) {
      bool centre = false;
      for (Index f : p)
        for (Index v : m.face(f)) centre = centre || (!m.vertex_label.empty() && m.vertex_label[v] == label);
      if (centre) with_centre.push_back(p.front());
    }
    std::string sizes;
    for (const auto& p : parts[c]) sizes += (sizes.empty() ? "" : ", ") + std::to_string(p.size());
    if (with_centre.size() >= 2)
      throw InputError("'" + m.path + "' faces " + m.faceId(with_centre[0]) + " and " +
                       m.faceId(with_centre[1]) + ": label " + std::to_string(label) +
                       " appears twice as separate cells (" + std::to_string(parts[c].size()) +
                       " pieces of " + sizes + " triangles, each around its own centre vertex)");
    throw InputError("'" + m.path + "' face " + m.faceId(parts[c][1].front()) + " (cell label " +
                     std::to_string(label) + "): the cell is made of " + std::to_string(parts[c].size()) +
                     " disconnected pieces (of " + sizes + " triangles; face " +
                     m.faceId(parts[c][0].front()) + " is in the first)" +
                     (repair ? "" : "; repair: true moves a one-triangle sliver to its neighbour"));
  }
  // The outline of each cell: its boundary edges, one loop. Per-vertex
  // arrays stamped with the cell's index (no clearing, no sorting): whether
  // a vertex is in the cell, its boundary successor, whether the walk passed it.
  cells.outlines.resize(n);
  std::vector<Index> in_cell(m.positions.size(), kInvalidIndex), has_next(m.positions.size(), kInvalidIndex),
      walked(m.positions.size(), kInvalidIndex), next_of(m.positions.size(), kInvalidIndex);
  std::vector<Index> tails;
  std::vector<std::vector<Index>> loops;
  for (std::size_t c = 0; c < n; ++c) {
    const Label label = cells.labels[c];
    const Index f0 = cells.faces[c].front();
    const Index stamp = static_cast<Index>(c);
    auto fail = [&](const std::string& what) {
      return InputError("'" + m.path + "' face " + m.faceId(f0) + " (cell label " + std::to_string(label) +
                        "): " + what);
    };
    tails.clear();
    std::size_t num_verts = 0, edges_twice = 0, edges_once = 0;
    for (Index f : cells.faces[c]) {
      const auto loop = m.face(f);
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Index u = loop[k], v = loop[(k + 1) % loop.size()];
        if (in_cell[u] != stamp) in_cell[u] = stamp, ++num_verts;
        const Index g = owner.face(v, u);
        if (g != kInvalidIndex && m.face_label[g] == label) {
          ++edges_twice;
          continue;
        }
        ++edges_once;
        if (has_next[u] == stamp)  // a second boundary edge leaves u
          throw fail("the cell's triangles meet at vertex " + std::to_string(u) +
                     " only by a corner (a pinched, non-manifold vertex): the cell is not a disk");
        has_next[u] = stamp, next_of[u] = v;
        tails.push_back(u);
      }
    }
    const long long euler = static_cast<long long>(num_verts) -
                            static_cast<long long>(edges_twice / 2 + edges_once) +
                            static_cast<long long>(cells.faces[c].size());
    // Walk the loops, each from its smallest vertex, in that order.
    std::sort(tails.begin(), tails.end());
    loops.clear();
    for (Index s0 : tails) {
      if (walked[s0] == stamp) continue;
      loops.emplace_back();
      for (Index u = s0; walked[u] != stamp;) {
        walked[u] = stamp;
        loops.back().push_back(u);
        if (has_next[u] != stamp) throw fail("its boundary is not closed at vertex " + std::to_string(u));
        u = next_of[u];
      }
    }
    if (loops.size() != 1)
      throw fail("the cell has a hole: the boundary of its triangles is " + std::to_string(loops.size()) +
                 " loops (through vertices " + std::to_string(loops[0][0]) + " and " +
                 std::to_string(loops[1][0]) + "), not one");
    if (euler != 1)
      throw fail("the cell's triangles are not a disk (Euler characteristic V-E+F = " + std::to_string(euler) +
                 ", expected 1)");
    if (loops[0].size() < 3)
      throw fail("the cell's outline has only " + std::to_string(loops[0].size()) + " vertices");
    cells.outlines[c] = std::move(loops[0]);
  }
  return cells;
}

// --- simplification of wall polylines ---------------------------------------

// Simplifies every wall (a chain of outline edges between junctions, shared
// by the same cells) with tolerance `tol`; both sides of a wall see the same
// result, so the tissue stays conforming. Returns the vertices removed.
std::size_t simplifyWalls(std::vector<std::vector<Index>>& outlines, const std::vector<Vec3>& pos, double tol) {
  // Undirected outline edges -> the cells along them.
  std::unordered_map<std::uint64_t, std::vector<Index>> edge_cells;
  std::unordered_map<Index, std::vector<Index>> around;  // vertex -> neighbour vertices
  for (Index c = 0; c < outlines.size(); ++c) {
    const auto& loop = outlines[c];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Index u = loop[k], v = loop[(k + 1) % loop.size()];
      auto& cs = edge_cells[edgeKey(std::min(u, v), std::max(u, v))];
      if (cs.empty()) around[u].push_back(v), around[v].push_back(u);
      cs.push_back(c);
    }
  }
  auto cellsOf = [&](Index u, Index v) {
    auto cs = edge_cells.at(edgeKey(std::min(u, v), std::max(u, v)));
    std::sort(cs.begin(), cs.end());
    return cs;
  };
  std::vector<char> keep(pos.size(), 0), junction(pos.size(), 0);
  for (const auto& [v, nb] : around)
    if (nb.size() != 2 || cellsOf(v, nb[0]) != cellsOf(v, nb[1])) junction[v] = keep[v] = 1;
  // Walk the walls from each junction; then the closed walls with none.
  std::unordered_map<std::uint64_t, char> walked;
  std::vector<std::vector<Index>> chains;
  auto walk = [&](Index start, Index second) {
    std::vector<Index> chain{start};
    Index prev = start, cur = second;
    walked[edgeKey(std::min(prev, cur), std::max(prev, cur))] = 1;
    while (!junction[cur] && cur != start) {
      chain.push_back(cur);
      const auto& nb = around.at(cur);
      const Index nxt = nb[0] == prev ? nb[1] : nb[0];
      prev = cur, cur = nxt;
      walked[edgeKey(std::min(prev, cur), std::max(prev, cur))] = 1;
    }
    chain.push_back(cur);
    chains.push_back(std::move(chain));
  };
  std::vector<Index> verts;
  for (const auto& [v, nb] : around) verts.push_back(v);
  std::sort(verts.begin(), verts.end());
  for (Index v : verts)
    if (junction[v])
      for (Index w : around.at(v))
        if (!walked.count(edgeKey(std::min(v, w), std::max(v, w)))) walk(v, w);
  for (Index v : verts)
    for (Index w : around.at(v))
      if (!walked.count(edgeKey(std::min(v, w), std::max(v, w)))) {
        junction[v] = keep[v] = 1;  // a closed wall without junction: start it here
        walk(v, w);
      }
  // Walls with the same two ends must keep an inner vertex each, or they
  // would collapse onto one edge (and a cell between them onto two vertices).
  std::unordered_map<std::uint64_t, int> ends;
  for (const auto& ch : chains) ++ends[edgeKey(std::min(ch.front(), ch.back()), std::max(ch.front(), ch.back()))];
  for (const auto& ch : chains) {
    const std::size_t last = ch.size() - 1;
    if (ch.front() == ch.back()) {  // closed: split at the vertex farthest from its start
      std::size_t far = 1;
      for (std::size_t i = 1; i < last; ++i)
        if ((pos[ch[i]] - pos[ch[0]]).norm() > (pos[ch[far]] - pos[ch[0]]).norm()) far = i;
      if (last < 2) continue;
      keep[ch[far]] = 1;
      douglasPeucker(ch, 0, far, pos, tol, far > 1, keep);
      douglasPeucker(ch, far, last, pos, tol, last - far > 1, keep);
      continue;
    }
    const bool twin = ends[edgeKey(std::min(ch.front(), ch.back()), std::max(ch.front(), ch.back()))] > 1;
    douglasPeucker(ch, 0, last, pos, tol, twin, keep);
  }
  std::size_t removed = 0;
  for (const auto& [v, nb] : around) removed += !keep[v];
  for (auto& loop : outlines) std::erase_if(loop, [&](Index v) { return !keep[v]; });
  return removed;
}

}  // namespace

LabelledSheet buildLabelledSheet(LabelledSurface& m, const ImportOptions& options, ImportReport& report) {
  if (m.numFaces() == 0) throw InputError("'" + m.path + "' has no faces: no cell to import");
  checkDuplicateVertices(m);
  LabelledSheet sheet{Tissue(2, Embedding::Surface), findCells(m, options.repair, report)};
  SheetCells& cells = sheet.cells;

  if (options.simplify > 0) {  // the tolerance is in scaled units
    std::vector<Vec3> scaled(m.positions.size());
    for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = options.scale * m.positions[i];
    report.simplified_vertices = simplifyWalls(cells.outlines, scaled, options.simplify);
  }

  // Keep the outline vertices only, numbered in file order.
  std::vector<Index> new_index(m.positions.size(), kInvalidIndex);
  for (const auto& loop : cells.outlines)
    for (Index v : loop) new_index[v] = 0;
  std::vector<Vec3> positions;
  for (Index v = 0; v < new_index.size(); ++v)
    if (new_index[v] == 0) {
      new_index[v] = static_cast<Index>(positions.size());
      positions.push_back(options.scale * m.positions[v]);
    }
  // The polygons as one flat list (offsets, vertices), as the builder takes them.
  std::vector<Index> offsets{0}, items;
  offsets.reserve(cells.outlines.size() + 1);
  for (std::size_t c = 0; c < cells.outlines.size(); ++c) {
    if (cells.outlines[c].size() < 3)
      throw InputError("'" + m.path + "' cell label " + std::to_string(cells.labels[c]) + ": simplify = " +
                       formatNumber(options.simplify) + " leaves its outline " +
                       std::to_string(cells.outlines[c].size()) + " vertices");
    for (Index v : cells.outlines[c]) items.push_back(new_index[v]);
    offsets.push_back(static_cast<Index>(items.size()));
  }
  try {
    sheet.tissue = buildPolygonTissue(std::move(positions), offsets, items, Embedding::Surface);
  } catch (const Error& e) {
    throw InputError("'" + m.path + "': the cells do not form a tissue: " + std::string(e.what()));
  }
  auto& label = sheet.tissue.cellProperties().add<std::int64_t>("label", 0);
  for (std::size_t c = 0; c < cells.labels.size(); ++c) label[CellId(static_cast<Index>(c))] = cells.labels[c];
  return sheet;
}

std::size_t unusedVertices(const LabelledSurface& m) {
  std::vector<char> used(m.positions.size(), 0);
  for (Index v : m.face_vertices) used[v] = 1;
  return m.positions.size() - static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
}
}  // namespace tessella::io::detail
