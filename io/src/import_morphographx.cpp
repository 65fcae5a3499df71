// MorphoGraphX PLY cell meshes and cell graphs (docs/import.md).
//
// A cell is the set of triangles carrying its label. Its outline is the
// boundary of their union, followed the way the triangles run (so two
// neighbours traverse their shared wall in opposite directions, as
// validate() requires). The importer checks that every cell is a disk: one
// connected piece (triangles joined by edges), every edge in at most two of
// its triangles and used once each way, one boundary loop, no pinched
// vertex, Euler characteristic 1.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io {

namespace {

using Label = std::int64_t;

std::uint64_t edgeKey(Index u, Index v) { return (std::uint64_t(u) << 32) | v; }

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index{0}); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

// A vertex of the file, nine digits: enough to find it in the file and tell it from its neighbours.
std::string fmtPoint(const Vec3& p) { return formatPoint(p, 9); }

void checkOptions(const ImportOptions& o) {
  if (!(std::isfinite(o.scale) && o.scale > 0))
    throw InputError("import scale must be a positive finite number, got " + formatNumber(o.scale));
  if (!(std::isfinite(o.simplify) && o.simplify >= 0))
    throw InputError("import simplify tolerance must be >= 0 (0 = off), got " + formatNumber(o.simplify));
}

// The file, read into plain arrays.
struct MgxMesh {
  std::string path;
  std::vector<Vec3> positions;
  std::vector<Label> vertex_label;
  std::vector<Label> vertex_parent;  // empty without a parent property
  std::vector<std::size_t> face_offsets;
  std::vector<Index> face_vertices;
  std::vector<Label> face_label;
  std::size_t numFaces() const { return face_label.size(); }
  std::span<const Index> face(std::size_t f) const {
    return {face_vertices.data() + face_offsets[f], face_offsets[f + 1] - face_offsets[f]};
  }
};

MgxMesh readMesh(const std::string& path) {
  const PlyFile ply = PlyFile::read(path);
  MgxMesh m;
  m.path = path;
  const PlyColumn& x = ply.scalar("vertex", "x");
  const PlyColumn& y = ply.scalar("vertex", "y");
  const PlyColumn& z = ply.scalar("vertex", "z");
  const PlyColumn& vl = ply.integerScalar("vertex", "label");
  const std::size_t nv = ply.count("vertex");
  m.positions.resize(nv);
  m.vertex_label.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    m.positions[i] = Vec3(x.values[i], y.values[i], z.values[i]);
    if (!m.positions[i].allFinite())
      throw InputError("'" + path + "' vertex " + std::to_string(i) + ": position " + fmtPoint(m.positions[i]) +
                       " is not finite");
    m.vertex_label[i] = static_cast<Label>(vl.values[i]);
  }
  if (ply.hasProperty("vertex", "parent")) {
    const PlyColumn& vp = ply.integerScalar("vertex", "parent");
    m.vertex_parent.assign(vp.values.begin(), vp.values.end());
  }
  const char* list_name = ply.hasProperty("face", "vertex_indices") ? "vertex_indices" : "vertex_index";
  if (!ply.hasProperty("face", list_name))
    throw InputError("'" + path + "': element 'face' has no vertex list (property 'vertex_indices' or "
                     "'vertex_index')");
  const PlyColumn& fv = ply.list("face", list_name);
  if (fv.type == PlyType::Float32 || fv.type == PlyType::Float64)
    throw InputError("'" + path + "': face property '" + list_name + "' holds " + plyTypeName(fv.type) +
                     " values, expected vertex indices of an integer type");
  const PlyColumn& fl = ply.integerScalar("face", "label");
  const std::size_t nf = ply.count("face");
  m.face_offsets = fv.offsets;
  m.face_vertices.resize(fv.values.size());
  m.face_label.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    m.face_label[f] = static_cast<Label>(fl.values[f]);
    const std::string where = "'" + path + "' face " + std::to_string(f) + " (cell label " +
                              std::to_string(m.face_label[f]) + ")";
    const std::size_t n = m.face_offsets[f + 1] - m.face_offsets[f];
    if (n < 3) throw InputError(where + ": has " + std::to_string(n) + " vertices, a face needs at least 3");
    for (std::size_t k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
      const double v = fv.values[k];
      if (v < 0 || v >= double(nv))
        throw InputError(where + ": vertex index " + std::to_string(static_cast<long long>(v)) +
                         " is out of range (the file has " + std::to_string(nv) + " vertices, 0.." +
                         std::to_string(nv == 0 ? 0 : nv - 1) + ")");
      m.face_vertices[k] = static_cast<Index>(v);
    }
    for (std::size_t a = m.face_offsets[f]; a < m.face_offsets[f + 1]; ++a)
      for (std::size_t b = a + 1; b < m.face_offsets[f + 1]; ++b)
        if (m.face_vertices[a] == m.face_vertices[b])
          throw InputError(where + ": uses vertex " + std::to_string(m.face_vertices[a]) +
                           " twice (a degenerate face)");
    if (m.face_label[f] <= 0)
      throw InputError(where + ": label " + std::to_string(m.face_label[f]) +
                       " is no cell (MorphoGraphX cell labels are positive)");
  }
  return m;
}

// Two used vertices at the same position: the mesh is not welded.
void checkDuplicateVertices(const MgxMesh& m) {
  std::vector<Index> first_face(m.positions.size(), kInvalidIndex);
  for (std::size_t f = 0; f < m.numFaces(); ++f)
    for (Index v : m.face(f))
      if (first_face[v] == kInvalidIndex) first_face[v] = static_cast<Index>(f);
  std::vector<Index> used;
  for (Index v = 0; v < m.positions.size(); ++v)
    if (first_face[v] != kInvalidIndex) used.push_back(v);
  auto less = [&](Index a, Index b) {
    const Vec3 &p = m.positions[a], &q = m.positions[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(used.begin(), used.end(), less);
  for (std::size_t i = 1; i < used.size(); ++i) {
    const Index a = used[i - 1], b = used[i];
    if (m.positions[a] == m.positions[b])
      throw InputError("'" + m.path + "' vertices " + std::to_string(a) + " and " + std::to_string(b) +
                       " are duplicates at " + fmtPoint(m.positions[a]) + " (used by face " +
                       std::to_string(first_face[a]) + " of cell label " +
                       std::to_string(m.face_label[first_face[a]]) + " and face " + std::to_string(first_face[b]) +
                       " of cell label " + std::to_string(m.face_label[first_face[b]]) +
                       "): the mesh is not welded, neighbours would not share their walls");
  }
}

// The cells of a mesh: faces grouped by label (sorted by label), each
// checked to be a disk, with its oriented outline.
struct Cells {
  std::vector<Label> labels;
  std::vector<std::vector<Index>> faces;     // per cell
  std::vector<std::vector<Index>> outlines;  // per cell, file vertex indices
};

// Per cell, the connected pieces of its faces (faces joined by an edge).
// Fills `owner` (directed edge -> face) and throws on an edge used twice the
// same way.
std::vector<std::vector<std::vector<Index>>> pieces(const MgxMesh& m, const std::vector<Label>& labels,
                                                    const std::vector<std::vector<Index>>& faces,
                                                    std::unordered_map<std::uint64_t, Index>& owner) {
  owner.clear();
  owner.reserve(m.face_vertices.size() * 2);
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const auto loop = m.face(f);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Index u = loop[k], v = loop[(k + 1) % loop.size()];
      const auto [it, fresh] = owner.emplace(edgeKey(u, v), static_cast<Index>(f));
      if (fresh) continue;
      const Index g = it->second;
      if (m.face_label[g] == m.face_label[f])
        throw InputError("'" + m.path + "' face " + std::to_string(f) + " (cell label " +
                         std::to_string(m.face_label[f]) + "): it and face " + std::to_string(g) +
                         " both run along edge " + std::to_string(u) + "->" + std::to_string(v) +
                         ": the cell's triangles are not a disk (more than two meet at an edge, or they are "
                         "oriented inconsistently)");
      throw InputError("'" + m.path + "' face " + std::to_string(f) + " (cell label " +
                       std::to_string(m.face_label[f]) + ") and face " + std::to_string(g) + " (cell label " +
                       std::to_string(m.face_label[g]) + ") both run along edge " + std::to_string(u) + "->" +
                       std::to_string(v) +
                       ": the two cells are oriented opposite ways, or more than two triangles meet at that edge");
    }
  }
  UnionFind uf(m.numFaces());
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const auto loop = m.face(f);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto it = owner.find(edgeKey(loop[(k + 1) % loop.size()], loop[k]));
      if (it != owner.end() && m.face_label[it->second] == m.face_label[f]) uf.unite(static_cast<Index>(f), it->second);
    }
  }
  std::vector<std::vector<std::vector<Index>>> out(labels.size());
  for (std::size_t c = 0; c < labels.size(); ++c) {
    std::unordered_map<Index, std::size_t> piece_of;
    for (Index f : faces[c]) {
      const auto [it, fresh] = piece_of.emplace(uf.find(f), out[c].size());
      if (fresh) out[c].emplace_back();
      out[c][it->second].push_back(f);
    }
  }
  return out;
}

void groupByLabel(const MgxMesh& m, std::vector<Label>& labels, std::vector<std::vector<Index>>& faces) {
  labels.assign(m.face_label.begin(), m.face_label.end());
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  faces.assign(labels.size(), {});
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const auto c = std::lower_bound(labels.begin(), labels.end(), m.face_label[f]) - labels.begin();
    faces[c].push_back(static_cast<Index>(f));
  }
}

// Repairs one-triangle slivers: a single triangle of a cell lying apart from
// the rest of it moves to the neighbour it shares most edges with (dropped if
// it shares none). Returns whether anything changed.
bool repairSlivers(MgxMesh& m, const std::vector<Label>& labels,
                   const std::vector<std::vector<std::vector<Index>>>& parts,
                   const std::unordered_map<std::uint64_t, Index>& owner, std::vector<std::string>& repairs,
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
        const auto it = owner.find(edgeKey(loop[(k + 1) % loop.size()], loop[k]));
        if (it != owner.end() && m.face_label[it->second] != labels[c]) ++shared[m.face_label[it->second]];
      }
      Label best = 0;
      int most = 0;
      for (const auto& [label, n] : shared)
        if (n > most || (n == most && label < best)) best = label, most = n;
      if (most > 0) {
        repairs.push_back("face " + std::to_string(f) + ", a one-triangle sliver of cell label " +
                          std::to_string(labels[c]) + " apart from the rest of that cell, moved to cell label " +
                          std::to_string(best) + " (it shares " + std::to_string(most) + " edge(s) with it)");
        m.face_label[f] = best;
      } else {
        repairs.push_back("face " + std::to_string(f) + ", a one-triangle sliver of cell label " +
                          std::to_string(labels[c]) + " apart from the rest of that cell, dropped (it shares no "
                          "edge with another cell)");
        dropped[f] = 1;
      }
      changed = true;
    }
  }
  if (!changed) return false;
  // Remove dropped faces for good.
  MgxMesh kept = m;
  kept.face_offsets = {0};
  kept.face_vertices.clear();
  kept.face_label.clear();
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    if (dropped[f]) continue;
    for (Index v : m.face(f)) kept.face_vertices.push_back(v);
    kept.face_offsets.push_back(kept.face_vertices.size());
    kept.face_label.push_back(m.face_label[f]);
  }
  m = std::move(kept);
  std::fill(dropped.begin(), dropped.end(), 0);
  dropped.resize(m.numFaces(), 0);
  return true;
}

Cells findCells(MgxMesh& m, bool repair, ImportReport& report) {
  Cells cells;
  std::unordered_map<std::uint64_t, Index> owner;
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
        for (Index v : m.face(f)) centre = centre || m.vertex_label[v] == label;
      if (centre) with_centre.push_back(p.front());
    }
    std::string sizes;
    for (const auto& p : parts[c]) sizes += (sizes.empty() ? "" : ", ") + std::to_string(p.size());
    if (with_centre.size() >= 2)
      throw InputError("'" + m.path + "' faces " + std::to_string(with_centre[0]) + " and " +
                       std::to_string(with_centre[1]) + ": label " + std::to_string(label) +
                       " appears twice as separate cells (" + std::to_string(parts[c].size()) +
                       " pieces of " + sizes + " triangles, each around its own centre vertex)");
    throw InputError("'" + m.path + "' face " + std::to_string(parts[c][1].front()) + " (cell label " +
                     std::to_string(label) + "): the cell is made of " + std::to_string(parts[c].size()) +
                     " disconnected pieces (of " + sizes + " triangles; face " +
                     std::to_string(parts[c][0].front()) + " is in the first)" +
                     (repair ? "" : "; repair: true moves a one-triangle sliver to its neighbour"));
  }
  // The outline of each cell: its boundary edges, one loop.
  cells.outlines.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    const Label label = cells.labels[c];
    const Index f0 = cells.faces[c].front();
    auto fail = [&](const std::string& what) {
      return InputError("'" + m.path + "' face " + std::to_string(f0) + " (cell label " + std::to_string(label) +
                        "): " + what);
    };
    std::unordered_map<Index, Index> next;  // boundary: vertex -> next vertex
    std::vector<Index> verts;
    std::size_t edges_twice = 0, edges_once = 0;
    for (Index f : cells.faces[c]) {
      const auto loop = m.face(f);
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Index u = loop[k], v = loop[(k + 1) % loop.size()];
        verts.push_back(u);
        const auto it = owner.find(edgeKey(v, u));
        if (it != owner.end() && m.face_label[it->second] == label) {
          ++edges_twice;
          continue;
        }
        ++edges_once;
        if (!next.emplace(u, v).second)
          throw fail("the cell's triangles meet at vertex " + std::to_string(u) +
                     " only by a corner (a pinched, non-manifold vertex): the cell is not a disk");
      }
    }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    const long long euler = static_cast<long long>(verts.size()) -
                            static_cast<long long>(edges_twice / 2 + edges_once) +
                            static_cast<long long>(cells.faces[c].size());
    // Walk the loops, starting each at its smallest vertex.
    std::vector<Index> starts;
    for (const auto& [u, v] : next) starts.push_back(u);
    std::sort(starts.begin(), starts.end());
    std::unordered_map<Index, char> seen;
    std::vector<std::vector<Index>> loops;
    for (Index s : starts) {
      if (seen.count(s)) continue;
      loops.emplace_back();
      for (Index u = s; !seen.count(u);) {
        seen[u] = 1;
        loops.back().push_back(u);
        const auto it = next.find(u);
        if (it == next.end()) throw fail("its boundary is not closed at vertex " + std::to_string(u));
        u = it->second;
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

double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Douglas-Peucker on chain[lo..hi] (ends kept), marking kept vertices.
void douglasPeucker(const std::vector<Index>& chain, std::size_t lo, std::size_t hi, const std::vector<Vec3>& pos,
                    double tol, bool keep_one, std::vector<char>& keep) {
  if (hi <= lo + 1) return;
  double worst = -1;
  std::size_t at = lo;
  for (std::size_t i = lo + 1; i < hi; ++i) {
    const double d = pointSegmentDistance(pos[chain[i]], pos[chain[lo]], pos[chain[hi]]);
    if (d > worst) worst = d, at = i;
  }
  if (worst <= tol && !keep_one) return;
  keep[chain[at]] = 1;
  douglasPeucker(chain, lo, at, pos, tol, false, keep);
  douglasPeucker(chain, at, hi, pos, tol, false, keep);
}

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

bool isMorphoGraphXMesh(const std::string& path) {
  const PlyHeader h = readPlyHeader(path);
  const PlyElement* v = h.element("vertex");
  const PlyElement* f = h.element("face");
  return v && f && v->property("label") && f->property("label");
}

ImportResult importMorphoGraphX(const std::string& path, const ImportOptions& options) {
  checkOptions(options);
  MgxMesh m = readMesh(path);
  ImportResult result{Tissue(2, Embedding::Surface), {}};
  ImportReport& report = result.report;
  report.path = path;
  report.format = "morphographx";
  report.file_vertices = m.positions.size();
  report.file_faces = m.numFaces();
  if (m.numFaces() == 0) throw InputError("'" + path + "' has no faces: no cell to import");
  checkDuplicateVertices(m);
  Cells cells = findCells(m, options.repair, report);

  std::vector<Vec3> scaled(m.positions.size());
  for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = options.scale * m.positions[i];
  if (options.simplify > 0) report.simplified_vertices = simplifyWalls(cells.outlines, scaled, options.simplify);

  // Keep the outline vertices only, numbered in file order.
  std::vector<Index> new_index(m.positions.size(), kInvalidIndex);
  for (const auto& loop : cells.outlines)
    for (Index v : loop) new_index[v] = 0;
  std::vector<Vec3> positions;
  for (Index v = 0; v < new_index.size(); ++v)
    if (new_index[v] == 0) {
      new_index[v] = static_cast<Index>(positions.size());
      positions.push_back(scaled[v]);
    }
  std::vector<std::vector<Index>> polygons(cells.outlines.size());
  for (std::size_t c = 0; c < polygons.size(); ++c)
    for (Index v : cells.outlines[c]) polygons[c].push_back(new_index[v]);
  for (std::size_t c = 0; c < polygons.size(); ++c)
    if (polygons[c].size() < 3)
      throw InputError("'" + path + "' cell label " + std::to_string(cells.labels[c]) + ": simplify = " +
                       std::to_string(options.simplify) + " leaves its outline " +
                       std::to_string(polygons[c].size()) + " vertices");
  try {
    result.tissue = buildPolygonTissue(positions, polygons, Embedding::Surface);
  } catch (const Error& e) {
    throw InputError("'" + path + "': the cells do not form a tissue: " + std::string(e.what()));
  }

  auto& label = result.tissue.cellProperties().add<std::int64_t>("label", 0);
  const bool has_parent = !m.vertex_parent.empty();
  PropertyColumn<std::int64_t>* parent =
      has_parent ? &result.tissue.cellProperties().add<std::int64_t>("parent", 0) : nullptr;
  std::size_t without_centre = 0;
  for (std::size_t c = 0; c < cells.labels.size(); ++c) {
    const CellId cell(static_cast<Index>(c));
    label[cell] = cells.labels[c];
    if (!parent) continue;
    Index centre = kInvalidIndex;
    for (Index f : cells.faces[c])
      for (Index v : m.face(f))
        if (centre == kInvalidIndex && m.vertex_label[v] == cells.labels[c]) centre = v;
    if (centre == kInvalidIndex) {
      ++without_centre;
      continue;
    }
    (*parent)[cell] = m.vertex_parent[centre];
  }
  std::size_t unused = m.positions.size();
  {
    std::vector<char> used(m.positions.size(), 0);
    for (Index v : m.face_vertices) used[v] = 1;
    unused -= static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  }
  report.notes.push_back("cell properties: label" + std::string(has_parent ? ", parent" : "") +
                         " (from the file's vertex and face labels)");
  if (without_centre > 0)
    report.notes.push_back(std::to_string(without_centre) +
                           " cells have no centre vertex carrying their label: parent 0 (unknown)");
  if (unused > 0) report.notes.push_back(std::to_string(unused) + " vertices of the file are in no face: ignored");
  return result;
}

std::vector<std::pair<std::int64_t, std::int64_t>> MorphoGraphXCellGraph::neighbourPairs() const {
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (auto [a, b] : edges) pairs.emplace_back(std::min(a, b), std::max(a, b));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

MorphoGraphXCellGraph readMorphoGraphXCellGraph(const std::string& path) {
  const PlyFile ply = PlyFile::read(path);
  MorphoGraphXCellGraph g;
  const PlyColumn& labels = ply.integerScalar("vertex", "label");
  g.labels.assign(labels.values.begin(), labels.values.end());
  if (ply.hasProperty("vertex", "Geometry/Area")) g.areas = ply.scalar("vertex", "Geometry/Area").values;
  std::vector<std::int64_t> sorted = g.labels;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] == sorted[i - 1]) {
      const auto first = std::find(g.labels.begin(), g.labels.end(), sorted[i]) - g.labels.begin();
      const auto second = std::find(g.labels.begin() + first + 1, g.labels.end(), sorted[i]) - g.labels.begin();
      throw InputError("'" + path + "' vertices " + std::to_string(first) + " and " + std::to_string(second) +
                       ": label " + std::to_string(sorted[i]) + " is listed twice");
    }
  const PlyColumn& source = ply.integerScalar("edge", "source");
  const PlyColumn& target = ply.integerScalar("edge", "target");
  for (std::size_t e = 0; e < source.values.size(); ++e) {
    const auto a = static_cast<std::int64_t>(source.values[e]), b = static_cast<std::int64_t>(target.values[e]);
    for (std::int64_t l : {a, b})
      if (!std::binary_search(sorted.begin(), sorted.end(), l))
        throw InputError("'" + path + "' edge " + std::to_string(e) + ": " + std::to_string(l) +
                         " is not the label of a listed cell");
    if (a == b)
      throw InputError("'" + path + "' edge " + std::to_string(e) + ": cell label " + std::to_string(a) +
                       " is its own neighbour");
    g.edges.emplace_back(a, b);
  }
  return g;
}

}  // namespace tessella::io
