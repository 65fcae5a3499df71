// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Cell-complex PLY ("property topomesh", OpenAlea cellcomplex) files
// (docs/import.md): vertex, face, optional edge, and volume elements, each
// volume listing its faces.
//
// Every volume is classified from its own faces: a closed surface (no edge
// on only one of its faces, one piece, every vertex a single fan, Euler
// characteristic 2) or an open patch (one piece, one boundary loop, Euler
// characteristic 1). A file of closed volumes is a 3D tissue: each face is a
// wall (shared by the one or two volumes listing it), oriented per volume so
// that every cell is closed and its walls point outwards. A file of patches
// is one surface cut into cells (an L1 layer): the faces, labelled by their
// volume and oriented consistently, go to the labelled-surface core that
// also reads MorphoGraphX meshes. Anything else is an InputError naming the
// file, the element and its index, and the volume's label.

#include <algorithm>
#include <array>
#include <cmath>
#include <compare>
#include <exception>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "cell_complex_core.hpp"
#include "labelled_surface.hpp"
#include "ply_mesh_columns.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io {

namespace {

using detail::edgeKey;
using detail::Label;
using detail::UnionFind;
using detail::ComplexFile;

std::string range(std::size_t n, const char* what) {
  return "(the file has " + std::to_string(n) + " " + what + (n == 0 ? "" : ", 0.." + std::to_string(n - 1)) + ")";
}

const PlyColumn& integerList(const PlyFile& ply, const char* element, const char* property) {
  const PlyColumn& c = ply.list(element, property);
  if (c.type == PlyType::Float32 || c.type == PlyType::Float64)
    throw InputError("'" + ply.path() + "': " + element + " property '" + property + "' holds " +
                     plyTypeName(c.type) + " values, expected indices of an integer type");
  return c;
}

// A face given by its edges: chains them into a vertex loop.
std::vector<Index> loopFromEdges(const std::string& where, std::span<const double> edges,
                                 const std::vector<std::array<Index, 2>>& edge_vertices) {
  const std::size_t n = edges.size();
  std::vector<std::array<Index, 2>> todo;
  for (double e : edges) {
    if (e < 0 || e >= double(edge_vertices.size()))
      throw InputError(where + ": edge index " + std::to_string(static_cast<long long>(e)) + " is out of range " +
                       range(edge_vertices.size(), "edges"));
    todo.push_back(edge_vertices[static_cast<std::size_t>(e)]);
  }
  if (n < 3) throw InputError(where + ": has " + std::to_string(n) + " edges, a face needs at least 3");
  std::vector<Index> loop{todo[0][0], todo[0][1]};
  std::vector<char> used(n, 0);
  used[0] = 1;
  for (std::size_t step = 1; step < n; ++step) {
    const Index at = loop.back();
    std::size_t next = n;
    for (std::size_t k = 0; k < n && next == n; ++k)
      if (!used[k] && (todo[k][0] == at || todo[k][1] == at)) next = k;
    if (next == n)
      throw InputError(where + ": its edges do not form one closed loop (no unused edge of the face continues at "
                       "vertex " + std::to_string(at) + ")");
    used[next] = 1;
    loop.push_back(todo[next][0] == at ? todo[next][1] : todo[next][0]);
  }
  if (loop.back() != loop.front())
    throw InputError(where + ": its edges do not form one closed loop (the chain ends at vertex " +
                     std::to_string(loop.back()) + ", not at vertex " + std::to_string(loop.front()) + ")");
  loop.pop_back();
  return loop;
}

ComplexFile readComplex(const std::string& path) {
  const PlyFile ply = PlyFile::read(path);
  ComplexFile m;
  m.path = path;
  const std::size_t nv = ply.count("vertex");
  m.positions = detail::plyPositions(ply, path);
  // Edges: needed when faces list edges, checked whenever present.
  std::vector<std::array<Index, 2>> edge_vertices;
  if (ply.hasElement("edge")) {
    const PlyColumn& source = ply.integerScalar("edge", "source");
    const PlyColumn& target = ply.integerScalar("edge", "target");
    for (std::size_t e = 0; e < source.values.size(); ++e) {
      const double ends[2] = {source.values[e], target.values[e]};
      for (double v : ends)
        if (v < 0 || v >= double(nv))
          throw InputError("'" + path + "' edge " + std::to_string(e) + ": vertex index " +
                           std::to_string(static_cast<long long>(v)) + " is out of range " + range(nv, "vertices"));
      if (ends[0] == ends[1])
        throw InputError("'" + path + "' edge " + std::to_string(e) + ": joins vertex " +
                         std::to_string(static_cast<long long>(ends[0])) + " to itself");
      edge_vertices.push_back({static_cast<Index>(ends[0]), static_cast<Index>(ends[1])});
    }
  }
  const std::size_t nf = ply.count("face");
  const char* vertex_list = ply.hasProperty("face", "vertex_indices") ? "vertex_indices" : "vertex_index";
  m.face_offsets = {0};
  if (ply.hasProperty("face", vertex_list)) {
    const PlyColumn& fv = integerList(ply, "face", vertex_list);
    for (std::size_t f = 0; f < nf; ++f) {
      const std::string where = "'" + path + "' face " + std::to_string(f);
      const std::size_t n = fv.offsets[f + 1] - fv.offsets[f];
      if (n < 3) throw InputError(where + ": has " + std::to_string(n) + " vertices, a face needs at least 3");
      for (std::size_t k = fv.offsets[f]; k < fv.offsets[f + 1]; ++k) {
        const double v = fv.values[k];
        if (v < 0 || v >= double(nv))
          throw InputError(where + ": vertex index " + std::to_string(static_cast<long long>(v)) +
                           " is out of range " + range(nv, "vertices"));
        m.face_vertices.push_back(static_cast<Index>(v));
      }
      m.face_offsets.push_back(m.face_vertices.size());
    }
  } else if (ply.hasProperty("face", "edge_index")) {
    if (!ply.hasElement("edge"))
      throw InputError("'" + path + "': faces list edges (property 'edge_index') but the file has no 'edge' element");
    m.faces_from_edges = true;
    const PlyColumn& fe = integerList(ply, "face", "edge_index");
    for (std::size_t f = 0; f < nf; ++f) {
      const std::span<const double> edges(fe.values.data() + fe.offsets[f], fe.offsets[f + 1] - fe.offsets[f]);
      for (Index v : loopFromEdges("'" + path + "' face " + std::to_string(f), edges, edge_vertices))
        m.face_vertices.push_back(v);
      m.face_offsets.push_back(m.face_vertices.size());
    }
  } else {
    throw InputError("'" + path + "': element 'face' has neither a vertex list ('vertex_index' or "
                     "'vertex_indices') nor an edge list ('edge_index')");
  }
  std::vector<Index> sorted;  // reused from face to face
  for (std::size_t f = 0; f < nf; ++f) {
    sorted.assign(m.face(f).begin(), m.face(f).end());
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end())
      throw InputError("'" + path + "' face " + std::to_string(f) + ": uses vertex " + std::to_string(*twice) +
                       " twice (a degenerate face)");
  }

  const std::size_t nvol = ply.count("volume");
  const PlyColumn& vf = integerList(ply, "volume", "face_index");
  m.volume_label.resize(nvol);
  if (ply.hasProperty("volume", "label")) {
    const PlyColumn& labels = ply.integerScalar("volume", "label");
    std::copy(labels.values.begin(), labels.values.end(), m.volume_label.begin());
  } else {
    for (std::size_t v = 0; v < nvol; ++v) m.volume_label[v] = static_cast<Label>(v);
  }
  // OpenAlea writes face_index 0-based (save_ply_property_topomesh) or, with
  // orientations, as +-(face + 1) (save_ply_cellcomplex_topomesh): a negative
  // index or one equal to the face count can only be the latter.
  for (double i : vf.values) m.signed_one_based = m.signed_one_based || i < 0 || i == double(nf);
  m.volume_offsets = {0};
  for (std::size_t v = 0; v < nvol; ++v) {
    const std::size_t n = vf.offsets[v + 1] - vf.offsets[v];
    if (n == 0) throw InputError(m.volumeName(v) + ": lists no face");
    for (std::size_t k = vf.offsets[v]; k < vf.offsets[v + 1]; ++k) {
      const double raw = vf.values[k];
      const double f = m.signed_one_based ? std::abs(raw) - 1 : raw;
      if (f < 0 || f >= double(nf))
        throw InputError(m.volumeName(v) + ": face index " + std::to_string(static_cast<long long>(raw)) +
                         " is out of range " + range(nf, "faces") +
                         (m.signed_one_based ? " (read as signed 1-based: +-(face + 1))" : ""));
      m.volume_faces.push_back(static_cast<Index>(f));
    }
    m.volume_offsets.push_back(m.volume_faces.size());
    sorted.assign(m.volume(v).begin(), m.volume(v).end());
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end())
      throw InputError(m.volumeName(v) + ": lists face " + std::to_string(*twice) + " twice");
  }
  // A label used twice: reported as a scan in volume order would, the
  // second use that comes first, with the first volume of its label.
  std::vector<std::pair<Label, Index>> by_label(nvol);
  for (std::size_t v = 0; v < nvol; ++v) by_label[v] = {m.volume_label[v], static_cast<Index>(v)};
  std::sort(by_label.begin(), by_label.end());
  Index first = kInvalidIndex, second = kInvalidIndex;
  for (std::size_t i = 1, start = 0; i < nvol; ++i) {
    if (by_label[i].first != by_label[start].first) start = i;
    else if (i == start + 1 && by_label[i].second < second) first = by_label[start].second, second = by_label[i].second;
  }
  if (first != kInvalidIndex)
    throw InputError("'" + path + "' volumes " + std::to_string(first) + " and " + std::to_string(second) +
                     ": label " + std::to_string(m.volume_label[first]) + " appears twice");
  return m;
}

}  // namespace

namespace detail {

// Two faces on the same vertices: one wall listed twice instead of shared.
void checkDuplicateFaces(const ComplexFile& m) {
  // Each face's vertices sorted, in one flat array; faces sorted by those
  // keys: equal keys are neighbours. Reported, as a scan in face order would:
  // the pair whose second face comes first, with the first face of its key.
  std::vector<Index> keys(m.face_vertices);
  for (std::size_t f = 0; f < m.numFaces(); ++f)
    std::sort(keys.begin() + static_cast<std::ptrdiff_t>(m.face_offsets[f]),
              keys.begin() + static_cast<std::ptrdiff_t>(m.face_offsets[f + 1]));
  auto key = [&](Index f) {
    return std::span<const Index>(keys.data() + m.face_offsets[f], m.face_offsets[f + 1] - m.face_offsets[f]);
  };
  std::vector<Index> order(m.numFaces());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    const auto ka = key(a), kb = key(b);
    if (ka.size() != kb.size()) return ka.size() < kb.size();
    const auto c = std::lexicographical_compare_three_way(ka.begin(), ka.end(), kb.begin(), kb.end());
    return c != 0 ? c < 0 : a < b;
  });
  Index first = kInvalidIndex, second = kInvalidIndex;
  for (std::size_t i = 1, start = 0; i < order.size(); ++i) {
    const auto ka = key(order[start]), kb = key(order[i]);
    if (!std::equal(ka.begin(), ka.end(), kb.begin(), kb.end())) {
      start = i;
    } else if (i == start + 1 && order[i] < second) {
      first = order[start], second = order[i];
    }
  }
  if (first != kInvalidIndex)
    throw InputError("'" + m.path + "' faces " + std::to_string(first) + " and " + std::to_string(second) +
                     " have the same vertices: a wall is listed once, by both the volumes it separates");
}

namespace {

// One edge of one face of a volume: its vertices in loop order and where.
struct FaceEdge {
  std::uint64_t key;  // undirected
  Index tail, head;
  Index face;          // position in the volume's face list
  Index tail_corner;   // position of the tail in the volume's corner list
  Index head_corner;
};

}  // namespace

VolumeSurface analyseVolume(const ComplexFile& m, std::size_t v) {
  const auto faces = m.volume(v);
  auto name = [&] { return m.volumeName(v); };  // built only for an error
  // Scratch reused from volume to volume (a file has many small volumes).
  thread_local std::vector<FaceEdge> scratch_edges;
  thread_local std::vector<Index> scratch_corners, scratch_verts;
  auto& edges = scratch_edges;
  auto& corner_vertex = scratch_corners;
  auto& verts = scratch_verts;
  edges.clear(), corner_vertex.clear();
  for (Index q = 0; q < faces.size(); ++q) {
    const auto loop = m.face(faces[q]);
    const Index first = static_cast<Index>(corner_vertex.size());
    for (std::size_t k = 0; k < loop.size(); ++k) {
      corner_vertex.push_back(loop[k]);
      const Index u = loop[k], w = loop[(k + 1) % loop.size()];
      const Index cu = first + static_cast<Index>(k), cw = first + static_cast<Index>((k + 1) % loop.size());
      edges.push_back({edgeKey(std::min(u, w), std::max(u, w)), u, w, q, cu, cw});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const FaceEdge& a, const FaceEdge& b) {
    return a.key != b.key ? a.key < b.key : a.face < b.face;
  });
  thread_local UnionFind pieces(0), corners(0);
  pieces.reset(faces.size()), corners.reset(corner_vertex.size());
  thread_local std::vector<std::pair<Index, Index>> boundary;
  boundary.clear();
  std::size_t num_edges = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    ++num_edges;
    if (j - i > 2) {
      std::string listed;
      for (std::size_t k = i; k < j; ++k) listed += (k > i ? ", " : "") + m.faceName(faces[edges[k].face]);
      throw InputError(name() + ": edge " + std::to_string(edges[i].tail) + "-" + std::to_string(edges[i].head) +
                       " is in " + std::to_string(j - i) + " of its faces (" + listed +
                       "): the cell is not a manifold surface");
    }
    if (j - i == 1) {
      boundary.emplace_back(edges[i].tail, edges[i].head);
    } else {
      const FaceEdge &a = edges[i], &b = edges[i + 1];
      pieces.unite(a.face, b.face);
      const bool same_way = a.tail == b.tail;
      corners.unite(a.tail_corner, same_way ? b.tail_corner : b.head_corner);
      corners.unite(a.head_corner, same_way ? b.head_corner : b.tail_corner);
    }
    i = j;
  }
  std::vector<Index> piece_first;  // first face of each piece
  for (Index q = 0; q < faces.size(); ++q)
    if (pieces.find(q) == q) piece_first.push_back(q);
  if (piece_first.size() > 1)
    throw InputError(name() + ": its faces form " + std::to_string(piece_first.size()) +
                     " disconnected pieces (" + m.faceName(faces[0]) + " is in one, " +
                     m.faceName(faces[piece_first[0] == pieces.find(0) ? piece_first[1] : piece_first[0]]) +
                     " in another): a cell is one piece");
  verts.assign(corner_vertex.begin(), corner_vertex.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  const long long euler = static_cast<long long>(verts.size()) - static_cast<long long>(num_edges) +
                          static_cast<long long>(faces.size());

  VolumeSurface out;
  if (!boundary.empty()) {
    // An open patch: one boundary loop (each boundary vertex on two boundary edges) and a disk.
    std::unordered_map<Index, int> degree;
    std::unordered_map<Index, Index> local;
    for (auto [a, b] : boundary) {
      ++degree[a], ++degree[b];
      local.emplace(a, static_cast<Index>(local.size()));
      local.emplace(b, static_cast<Index>(local.size()));
    }
    for (auto [vertex, d] : degree)
      if (d != 2)
        throw InputError(name() + ": neither a closed surface nor a patch of one: " + std::to_string(d) +
                         " edges of its boundary meet at vertex " + std::to_string(vertex) + " (a pinched boundary)");
    UnionFind loops(local.size());
    for (auto [a, b] : boundary) loops.unite(local[a], local[b]);
    std::size_t num_loops = 0;
    for (Index i = 0; i < local.size(); ++i) num_loops += loops.find(i) == i;
    if (num_loops != 1 || euler != 1)
      throw InputError(name() + ": neither a closed surface nor a patch of one: " + std::to_string(boundary.size()) +
                       " of its edges are on one face only, forming " + std::to_string(num_loops) +
                       " boundary loop(s), Euler characteristic V-E+F = " + std::to_string(euler) +
                       " (a closed cell has no such edge, a patch one loop and characteristic 1)");
    out.shape = Shape::Patch;
    return out;
  }
  // Closed: every vertex one fan of faces (not pinched), a sphere.
  {
    // (vertex, fan) of every corner, sorted: a vertex in two fans is pinched.
    // Reported: the vertex of the first corner (in listing order) whose fan
    // differs from that of the vertex's first corner.
    thread_local std::vector<std::array<Index, 3>> fans;  // vertex, corner, fan
    fans.resize(corner_vertex.size());
    for (Index c = 0; c < corner_vertex.size(); ++c) fans[c] = {corner_vertex[c], c, corners.find(c)};
    std::sort(fans.begin(), fans.end());
    Index pinched_corner = kInvalidIndex;
    for (std::size_t i = 1, first = 0; i < fans.size(); ++i) {
      if (fans[i][0] != fans[first][0]) first = i;
      else if (fans[i][2] != fans[first][2] && fans[i][1] < pinched_corner) pinched_corner = fans[i][1];
    }
    if (pinched_corner != kInvalidIndex)
      throw InputError(name() + ": its faces meet at vertex " + std::to_string(corner_vertex[pinched_corner]) +
                       " only by a corner (a pinched, non-manifold vertex): the cell is not a closed manifold");
  }
  if (euler != 2)
    throw InputError(name() + ": its closed surface has Euler characteristic V-E+F = " + std::to_string(euler) +
                     ", expected 2 (a sphere; a cell with a handle or a tunnel is refused)");
  // Orient the faces consistently: across a shared edge, two faces run opposite ways.
  out.orientation.assign(faces.size(), 0);
  // The edges of each face (positions in `edges`), grouped by face (counting sort).
  thread_local std::vector<Index> face_edge_start, face_edge_list, fill, stack;
  face_edge_start.assign(faces.size() + 1, 0), face_edge_list.resize(edges.size());
  for (const FaceEdge& e : edges) ++face_edge_start[e.face + 1];
  for (std::size_t q = 0; q < faces.size(); ++q) face_edge_start[q + 1] += face_edge_start[q];
  fill.assign(face_edge_start.begin(), face_edge_start.end() - 1);
  for (Index i = 0; i < edges.size(); ++i) face_edge_list[fill[edges[i].face]++] = i;
  stack.assign(1, 0);
  out.orientation[0] = 1;
  while (!stack.empty()) {
    const Index q = stack.back();
    stack.pop_back();
    for (Index k = face_edge_start[q]; k < face_edge_start[q + 1]; ++k) {
      const Index i = face_edge_list[k];
      // The other face along this edge: the neighbour in sorted order.
      const Index j = (i + 1 < edges.size() && edges[i + 1].key == edges[i].key) ? i + 1 : i - 1;
      const FaceEdge &a = edges[i], &b = edges[j];
      const int wanted = a.tail == b.tail ? -out.orientation[q] : out.orientation[q];
      if (out.orientation[b.face] == 0) {
        out.orientation[b.face] = wanted;
        stack.push_back(b.face);
      } else if (out.orientation[b.face] != wanted) {
        throw InputError(name() + ": its faces cannot be oriented consistently (" + m.faceName(faces[q]) + " and " +
                         m.faceName(faces[b.face]) + " along edge " + std::to_string(a.tail) + "-" +
                         std::to_string(a.head) + "): a non-orientable surface");
      }
    }
  }
  // Outward: the signed volume of the oriented surface is positive.
  const Vec3 origin = m.positions[corner_vertex[0]];
  double six_volume = 0, scale = 0;
  for (Index q = 0; q < faces.size(); ++q) {
    const auto loop = m.face(faces[q]);
    Vec3 centre = Vec3::Zero();
    for (Index u : loop) centre += m.positions[u] - origin;
    centre /= double(loop.size());
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 p = m.positions[loop[k]] - origin, r = m.positions[loop[(k + 1) % loop.size()]] - origin;
      six_volume += out.orientation[q] * centre.dot(p.cross(r));
      scale = std::max(scale, p.norm());
    }
  }
  if (!(std::abs(six_volume) > 1e-12 * scale * scale * scale))
    throw InputError(name() + ": its closed surface encloses no volume (" + formatNumber(six_volume / 6) + ")");
  if (six_volume < 0)
    for (int& o : out.orientation) o = -o;
  return out;
}

ImportResult importClosedVolumes(const ComplexFile& m, const std::vector<VolumeSurface>& surfaces,
                                 const ImportOptions& options, ImportReport& report) {
  if (options.simplify > 0)
    throw InputError("'" + m.path + "': simplify applies to the wall polylines of a curved sheet; this file is a "
                     "3D tissue (closed cells)");
  {  // welded: reuse the surface check, each face labelled by a volume listing it
    LabelledSurface s;
    s.path = m.path;
    s.positions = m.positions;
    s.face_offsets = {0};
    std::vector<Label> label_of(m.numFaces(), 0);
    std::vector<char> listed(m.numFaces(), 0);
    for (std::size_t v = 0; v < m.numVolumes(); ++v)
      for (Index f : m.volume(v)) label_of[f] = m.volume_label[v], listed[f] = 1;
    for (std::size_t f = 0; f < m.numFaces(); ++f) {
      if (!listed[f]) continue;
      s.face_vertices.insert(s.face_vertices.end(), m.face(f).begin(), m.face(f).end());
      s.face_offsets.push_back(s.face_vertices.size());
      s.face_label.push_back(label_of[f]);
      s.file_face.push_back(static_cast<Index>(f));
    }
    checkDuplicateVertices(s);
  }
  // Which volumes list each face, with the face's outward orientation in
  // each (grouped by face with a counting sort, volumes in order).
  std::vector<std::size_t> listed_start(m.numFaces() + 1, 0);
  for (Index f : m.volume_faces) ++listed_start[f + 1];
  for (std::size_t f = 0; f < m.numFaces(); ++f) listed_start[f + 1] += listed_start[f];
  std::vector<std::pair<Index, int>> listed_by(m.volume_faces.size());
  {
    std::vector<std::size_t> fill(listed_start.begin(), listed_start.end() - 1);
    for (std::size_t v = 0; v < m.numVolumes(); ++v) {
      const auto faces = m.volume(v);
      for (std::size_t q = 0; q < faces.size(); ++q)
        listed_by[fill[faces[q]]++] = {static_cast<Index>(v), surfaces[v].orientation[q]};
    }
  }
  std::vector<Index> face_index(m.numFaces(), kInvalidIndex);
  std::vector<Index> wall_offsets{0}, wall_vertices;  // the walls, flat
  std::size_t shared = 0, unlisted = 0;
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    const std::span<const std::pair<Index, int>> by(listed_by.data() + listed_start[f],
                                                    listed_start[f + 1] - listed_start[f]);
    if (by.empty()) {
      ++unlisted;
      continue;
    }
    if (by.size() > 2) {
      std::string labels;
      for (auto [v, o] : by) labels += (labels.empty() ? "" : ", ") + std::to_string(m.volume_label[v]);
      throw InputError("'" + m.path + "' " + m.faceName(f) + ": listed by " + std::to_string(by.size()) +
                       " volumes (labels " + labels + "), a wall separates at most two cells");
    }
    if (by.size() == 2 && by[0].second == by[1].second)
      throw InputError("'" + m.path + "' " + m.faceName(f) + ": volumes " + std::to_string(by[0].first) +
                       " and " + std::to_string(by[1].first) + " (labels " +
                       std::to_string(m.volume_label[by[0].first]) + " and " +
                       std::to_string(m.volume_label[by[1].first]) +
                       ") lie on the same side of it: the cells overlap");
    shared += by.size() == 2;
    face_index[f] = static_cast<Index>(wall_offsets.size() - 1);
    wall_vertices.insert(wall_vertices.end(), m.face(f).begin(), m.face(f).end());
    wall_offsets.push_back(static_cast<Index>(wall_vertices.size()));
  }
  const std::size_t num_walls = wall_offsets.size() - 1;
  // Vertices used by a wall, in file order.
  std::vector<Index> vertex_index(m.positions.size(), kInvalidIndex);
  for (Index u : wall_vertices) vertex_index[u] = 0;
  std::vector<Vec3> positions;
  for (Index u = 0; u < vertex_index.size(); ++u)
    if (vertex_index[u] == 0) {
      vertex_index[u] = static_cast<Index>(positions.size());
      positions.push_back(options.scale * m.positions[u]);
    }
  for (Index& u : wall_vertices) u = vertex_index[u];
  // Cells ordered by label, as for every other format.
  std::vector<Index> order(m.numVolumes());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return m.volume_label[a] < m.volume_label[b]; });
  std::vector<Index> cell_offsets{0};
  std::vector<CellFace> cell_faces;
  cell_faces.reserve(m.volume_faces.size());
  for (Index v : order) {
    const auto faces = m.volume(v);
    for (std::size_t q = 0; q < faces.size(); ++q)
      cell_faces.push_back(CellFace{face_index[faces[q]], surfaces[v].orientation[q] < 0});
    cell_offsets.push_back(static_cast<Index>(cell_faces.size()));
  }
  ImportResult result{Tissue(3, Embedding::Volume), {}};
  const std::size_t num_positions = positions.size();
  try {
    result.tissue = buildPolyhedralTissue(std::move(positions), wall_offsets, wall_vertices, cell_offsets, cell_faces);
  } catch (const Error& e) {
    throw InputError("'" + m.path + "': the volumes do not form a tissue: " + std::string(e.what()));
  }
  auto& label = result.tissue.cellProperties().add<std::int64_t>("label", 0);
  for (std::size_t c = 0; c < order.size(); ++c) label[CellId(static_cast<Index>(c))] = m.volume_label[order[c]];
  report.notes.push_back("layout: closed " + m.volume_noun + "s, a 3D tissue (" + std::to_string(num_walls) +
                         " walls, each " + (m.face_element.empty() ? m.face_origin : "a side of a tetrahedron") +
                         ": " + std::to_string(shared) + " between two cells, " +
                         std::to_string(num_walls - shared) + " on the boundary)");
  if (unlisted > 0)
    report.notes.push_back(std::to_string(unlisted) + " faces of the file are in no volume: ignored");
  if (const std::size_t unused = m.positions.size() - num_positions; unused > 0)
    report.notes.push_back(std::to_string(unused) + " vertices of the file are in no wall: ignored");
  return result;
}

}  // namespace detail

namespace {

using detail::Shape;
using detail::VolumeSurface;

// The patches as a labelled surface, every face oriented the way most faces
// of its connected part of the surface already run.
detail::LabelledSurface orientedPatches(const ComplexFile& m, ImportReport& report) {
  detail::LabelledSurface s;
  s.path = m.path;
  s.positions = m.positions;
  std::vector<Index> volume_of(m.numFaces(), kInvalidIndex);
  for (std::size_t v = 0; v < m.numVolumes(); ++v)
    for (Index f : m.volume(v)) {
      if (volume_of[f] != kInvalidIndex)
        throw InputError("'" + m.path + "' " + m.faceName(f) + ": listed by volumes " +
                         std::to_string(volume_of[f]) + " and " + std::to_string(v) + " (labels " +
                         std::to_string(m.volume_label[volume_of[f]]) + " and " + std::to_string(m.volume_label[v]) +
                         "), but the volumes are patches of one surface, which share no face");
      volume_of[f] = static_cast<Index>(v);
    }
  std::vector<Index> kept;
  for (Index f = 0; f < m.numFaces(); ++f)
    if (volume_of[f] != kInvalidIndex) kept.push_back(f);
  // Faces along each undirected edge of the surface.
  std::vector<std::tuple<std::uint64_t, Index, Index>> edges;  // key, tail, kept position
  for (Index q = 0; q < kept.size(); ++q) {
    const auto loop = m.face(kept[q]);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Index u = loop[k], w = loop[(k + 1) % loop.size()];
      edges.emplace_back(edgeKey(std::min(u, w), std::max(u, w)), u, q);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<std::pair<Index, bool>>> across(kept.size());  // neighbour, runs the same way
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i])) ++j;
    if (j - i > 2)
      throw InputError("'" + m.path + "' " + m.faceName(kept[std::get<2>(edges[i])]) + " (cell label " +
                       std::to_string(m.volume_label[volume_of[kept[std::get<2>(edges[i])]]]) + "): " +
                       std::to_string(j - i) + " faces meet at one edge: the surface is not a manifold");
    if (j - i == 2) {
      const auto &[ka, ta, qa] = edges[i];
      const auto &[kb, tb, qb] = edges[i + 1];
      across[qa].emplace_back(qb, ta == tb);
      across[qb].emplace_back(qa, ta == tb);
    }
    i = j;
  }
  std::vector<int> flip(kept.size(), -1);  // 0 keep, 1 reverse
  std::size_t reversed = 0;
  for (Index seed = 0; seed < kept.size(); ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<Index> part{seed}, stack{seed};
    flip[seed] = 0;
    while (!stack.empty()) {
      const Index q = stack.back();
      stack.pop_back();
      for (auto [r, same_way] : across[q]) {
        const int wanted = same_way ? 1 - flip[q] : flip[q];
        if (flip[r] < 0) {
          flip[r] = wanted;
          part.push_back(r);
          stack.push_back(r);
        } else if (flip[r] != wanted) {
          throw InputError("'" + m.path + "' " + m.faceName(kept[q]) + " and " + m.faceName(kept[r]) +
                           ": the surface of the patches cannot be oriented consistently (a non-orientable surface)");
        }
      }
    }
    std::size_t flipped = 0;
    for (Index q : part) flipped += flip[q];
    if (2 * flipped > part.size())  // keep the way most faces run
      for (Index q : part) flip[q] = 1 - flip[q];
  }
  s.face_offsets = {0};
  for (Index q = 0; q < kept.size(); ++q) {
    const auto loop = m.face(kept[q]);
    if (flip[q]) {
      ++reversed;
      s.face_vertices.insert(s.face_vertices.end(), loop.rbegin(), loop.rend());
    } else {
      s.face_vertices.insert(s.face_vertices.end(), loop.begin(), loop.end());
    }
    s.face_offsets.push_back(s.face_vertices.size());
    s.face_label.push_back(m.volume_label[volume_of[kept[q]]]);
    s.file_face.push_back(kept[q]);
  }
  report.notes.push_back("layout: open patches of one surface, a curved-sheet tissue (each cell the outline of its "
                         "volume's faces)");
  if (reversed > 0)
    report.notes.push_back(std::to_string(reversed) + " faces reversed to orient the surface consistently");
  if (kept.size() < m.numFaces())
    report.notes.push_back(std::to_string(m.numFaces() - kept.size()) + " faces of the file are in no volume: ignored");
  return s;
}

}  // namespace

bool isCellComplexPly(const std::string& path) {
  const PlyHeader h = readPlyHeader(path);
  const PlyElement* v = h.element("vertex");
  const PlyElement* f = h.element("face");
  const PlyElement* vol = h.element("volume");
  return v && f && vol && vol->property("face_index");
}

namespace detail {

ImportResult importComplex(const ComplexFile& m, const ImportOptions& options, ImportReport report) {
  if (m.numVolumes() == 0) throw InputError("'" + m.path + "' has no " + m.volume_noun + "s: no cell to import");
  checkDuplicateFaces(m);
  // Volumes are analysed independently, in parallel; of those that fail,
  // the first in file order is reported, as a serial scan would.
  std::vector<VolumeSurface> surfaces(m.numVolumes());
  std::size_t first_failed = std::numeric_limits<std::size_t>::max();
  std::exception_ptr failure;
  const auto num_volumes = static_cast<std::ptrdiff_t>(m.numVolumes());
#pragma omp parallel for schedule(dynamic, 64)
  for (std::ptrdiff_t v = 0; v < num_volumes; ++v) {
    try {
      surfaces[v] = analyseVolume(m, static_cast<std::size_t>(v));
    } catch (...) {
#pragma omp critical(import_complex_first_failure)
      if (static_cast<std::size_t>(v) < first_failed)
        first_failed = static_cast<std::size_t>(v), failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (std::size_t v = 1; v < m.numVolumes(); ++v)
    if (surfaces[v].shape != surfaces[0].shape) {
      const std::size_t closed = surfaces[0].shape == Shape::Closed ? 0 : v, open = closed == 0 ? v : 0;
      throw InputError(m.volumeName(open) + ": an open patch, but " + m.volumeRef(closed) +
                       " is a closed surface: a file holds either closed cells (a 3D tissue) or patches of one "
                       "surface (a sheet); a 3D cell must be closed");
    }
  ImportResult result{Tissue(2, Embedding::Surface), {}};
  if (surfaces[0].shape == Shape::Closed) {
    result = importClosedVolumes(m, surfaces, options, report);
  } else {
    LabelledSurface s = orientedPatches(m, report);
    LabelledSheet sheet = buildLabelledSheet(s, options, report);
    result.tissue = std::move(sheet.tissue);
    if (const std::size_t unused = unusedVertices(s); unused > 0)
      report.notes.push_back(std::to_string(unused) + " vertices of the file are in no face: ignored");
  }
  result.report = std::move(report);
  return result;
}

}  // namespace detail

ImportResult importCellComplex(const std::string& path, const ImportOptions& options) {
  detail::checkImportOptions(options);
  const ComplexFile m = readComplex(path);
  ImportReport report;
  report.path = path;
  report.format = "cell_complex";
  report.file_vertices = m.positions.size();
  report.file_faces = m.numFaces();
  ImportResult result = detail::importComplex(m, options, std::move(report));
  std::string conventions;
  if (m.faces_from_edges) conventions += "faces read from their edges (edge_index); ";
  if (m.signed_one_based) conventions += "volume face_index read as signed 1-based (+-(face + 1)); ";
  if (!conventions.empty()) result.report.notes.push_back(conventions.substr(0, conventions.size() - 2));
  result.report.notes.push_back("cell properties: label (the volume's label, or its index without a label property)");
  return result;
}

}  // namespace tessella::io
