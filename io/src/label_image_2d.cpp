// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 2D label images as planar tissues (docs/import.md, "Label images"): every
// label that is not background is a cell; walls run along the pixel edges
// between two labels; junctions are the pixel corners where three or more
// labels (the outside counting as one) meet. Each wall (a chain of pixel
// edges between junctions) is simplified by Douglas-Peucker with its ends
// fixed, both cells seeing the same polyline, and a wall whose simplification
// would cross another wall or flatten a cell is simplified again with half
// the tolerance until none does.
//
// Pixel-diagonal contacts: at a pixel corner where two diagonal pixels carry
// one label and the other two pixels other labels (a pinch), the label of the
// diagonal pair bridges the corner: the corner becomes two vertices a quarter
// pixel off it, one on each side of the bridge. Where both diagonal pairs
// qualify (a checkerboard of two labels), a cell bridges over the outside,
// and of two cells the smaller label bridges.

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "label_image_3d.hpp"
#include "labelled_surface.hpp"
#include "polyline_simplification.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io {

namespace {

using detail::douglasPeucker;
using detail::Label;
constexpr Label kOutside = std::numeric_limits<Label>::min();
constexpr double kSplit = 0.25;  // offset of the two vertices of a bridged corner, in pixels
constexpr std::size_t kMaxNotes = 20;

std::string labelList(const std::vector<Label>& labels) {
  std::string out;
  for (std::size_t i = 0; i < labels.size(); ++i) out += (i ? ", " : "") + std::to_string(labels[i]);
  return out;
}

struct BoundaryEdge {
  std::int32_t u, v;         // vertices; `left` runs u -> v in its outline, `right` v -> u
  std::int32_t left, right;  // cells, -1 for the outside
};

struct Segment {
  std::int32_t a, b, wall;
};

// Exact for the quarter-pixel coordinates used here.
double orient(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
bool onSegment(const Vec3& a, const Vec3& b, const Vec3& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
         p.y() <= std::max(a.y(), b.y());
}
// Whether two segments of the simplified walls conflict: they cross or touch
// away from a shared end, overlap along a line, or join the same two vertices.
bool conflict(const Segment& s, const Segment& t, const std::vector<Vec3>& pos) {
  const int shared = (s.a == t.a) + (s.a == t.b) + (s.b == t.a) + (s.b == t.b);
  const Vec3 &p1 = pos[s.a], &p2 = pos[s.b], &q1 = pos[t.a], &q2 = pos[t.b];
  if (shared == 2) return true;
  if (shared == 1) {
    const std::int32_t common = (s.a == t.a || s.a == t.b) ? s.a : s.b;
    const Vec3& o = pos[common];
    const Vec3& x = pos[s.a == common ? s.b : s.a];
    const Vec3& y = pos[t.a == common ? t.b : t.a];
    return orient(o, x, y) == 0 && (x - o).dot(y - o) > 0;
  }
  const double d1 = orient(q1, q2, p1), d2 = orient(q1, q2, p2), d3 = orient(p1, p2, q1), d4 = orient(p1, p2, q2);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
         (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

struct Wall {
  std::vector<std::int32_t> chain;  // vertices, junction to junction (closed: first == last)
  double tol;
  bool keep_one = false;  // keep an inner vertex: another wall with the same two ends is a straight segment
};

void simplifyWall(const Wall& w, const std::vector<Vec3>& pos, std::vector<char>& keep) {
  const auto& ch = w.chain;
  const std::size_t last = ch.size() - 1;
  for (std::size_t i = 1; i < last; ++i) keep[ch[i]] = w.tol < 0;  // tol < 0: keep every vertex
  if (w.tol < 0) return;
  if (ch.front() == ch.back()) {  // a loop: split at the vertex farthest from its start, keep one more on each side
    std::size_t far = 1;
    for (std::size_t i = 1; i < last; ++i)
      if ((pos[ch[i]] - pos[ch[0]]).squaredNorm() > (pos[ch[far]] - pos[ch[0]]).squaredNorm()) far = i;
    if (last < 2) return;
    keep[ch[far]] = 1;
    douglasPeucker(ch, 0, far, pos, w.tol, far > 1, keep);
    douglasPeucker(ch, far, last, pos, w.tol, last - far > 1, keep);
    return;
  }
  douglasPeucker(ch, 0, last, pos, w.tol, w.keep_one, keep);
}

}  // namespace

ImportResult tissueFromLabelImage(const LabelImage& img, const ImportOptions& o) {
  detail::checkImportOptions(o);
  const LabelImageOptions& io = o.image;
  const std::string file = "'" + img.name + "'";
  const auto [nx, ny, nz] = img.dims;
  if (nx < 1 || ny < 1 || nz < 1 ||
      img.labels.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz))
    throw InputError(file + ": the image has dimensions " + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                     std::to_string(nz) + " but " + std::to_string(img.labels.size()) + " labels");
  if (nz != 1) return detail::tissueFromLabelImage3d(img, o);
  // Pixel size.
  double sx = img.spacing[0], sy = img.spacing[1];
  if (!io.voxel_size.empty()) {
    if (io.voxel_size.size() != 2 && io.voxel_size.size() != 3)
      throw InputError(file + ": voxel_size needs 2 or 3 numbers (x, y[, z]), got " +
                       std::to_string(io.voxel_size.size()));
    for (std::size_t k = 0; k < io.voxel_size.size(); ++k)
      if (!(std::isfinite(io.voxel_size[k]) && io.voxel_size[k] > 0))
        throw InputError(file + ": voxel_size " + std::string("xyz").substr(k, 1) + " = " +
                         formatNumber(io.voxel_size[k]) + " must be a positive finite number");
    sx = io.voxel_size[0], sy = io.voxel_size[1];
  } else {
    for (int k = 0; k < 2; ++k)
      if (!(std::isfinite(img.spacing[k]) && img.spacing[k] > 0))
        throw InputError(file + ": the file's pixel size in " + std::string("xy").substr(k, 1) + " is " +
                         formatNumber(img.spacing[k]) + ", not a positive number; give voxel_size (--voxel-size)");
  }
  if (io.min_cell_size < 0)
    throw InputError(file + ": min_cell_size must be >= 0, got " + std::to_string(io.min_cell_size));
  if (io.small_cells != "drop" && io.small_cells != "merge")
    throw InputError(file + ": small_cells must be drop or merge, got '" + io.small_cells + "'");
  // Crop box.
  std::int64_t x0 = 0, y0 = 0, x1 = nx, y1 = ny;
  if (!io.crop.empty()) {
    if (io.crop.size() != 4)
      throw InputError(file + ": crop needs 4 numbers x0, y0, x1, y1, got " + std::to_string(io.crop.size()));
    x0 = io.crop[0], y0 = io.crop[1], x1 = io.crop[2], y1 = io.crop[3];
    if (!(0 <= x0 && x0 < x1 && x1 <= nx && 0 <= y0 && y0 < y1 && y1 <= ny))
      throw InputError(file + ": crop " + labelList(io.crop) + " is not a box 0 <= x0 < x1 <= " + std::to_string(nx) +
                       ", 0 <= y0 < y1 <= " + std::to_string(ny) + " inside the image");
  }
  const std::int64_t w = x1 - x0, h = y1 - y0;
  const std::int64_t W = w + 2, H = h + 2;  // padded with a ring of outside pixels
  auto pix = [&](std::int64_t i, std::int64_t j) { return static_cast<std::size_t>(j * W + i); };
  std::vector<Label> lab(static_cast<std::size_t>(W * H), kOutside);
  {
    Label first = img.labels[static_cast<std::size_t>(y0 * nx + x0)];
    bool several = false;
    for (std::int64_t j = 0; j < h; ++j)
      for (std::int64_t i = 0; i < w; ++i) {
        const Label l = img.labels[static_cast<std::size_t>((j + y0) * nx + i + x0)];
        several = several || l != first;
        lab[pix(i + 1, j + 1)] = l;
      }
    if (!several)
      throw InputError(file + ": the image" + std::string(io.crop.empty() ? "" : " (cropped)") +
                       " holds one label only (" + std::to_string(first) + " in every pixel): no cells to tell apart");
  }
  ImportResult result{Tissue(2, Embedding::Planar), {}};
  ImportReport& report = result.report;
  report.path = img.name;
  report.file_faces = static_cast<std::size_t>(nx * ny);
  report.file_faces_noun = "pixels";
  report.notes.push_back("image " + std::to_string(nx) + " x " + std::to_string(ny) + " pixels" +
                         (io.crop.empty() ? std::string()
                                          : ", cropped to x " + std::to_string(x0) + ".." + std::to_string(x1 - 1) +
                                                ", y " + std::to_string(y0) + ".." + std::to_string(y1 - 1)) +
                         ", pixel size " + formatNumber(sx) + " x " + formatNumber(sy) +
                         (io.voxel_size.empty() ? " (from the file)" : " (given)"));
  std::vector<std::string> small_notes;
  for (Label& l : lab) {
    if (l == kOutside) continue;
    if (std::find(io.background.begin(), io.background.end(), l) != io.background.end() ||
        std::find(io.drop_labels.begin(), io.drop_labels.end(), l) != io.drop_labels.end())
      l = kOutside;
  }
  // Small labels: dropped, or merged into the neighbour sharing the most pixel edges.
  if (io.min_cell_size > 0) {
    std::map<Label, std::int64_t> size;
    for (Label l : lab)
      if (l != kOutside) ++size[l];
    std::vector<std::pair<std::int64_t, Label>> small;
    for (const auto& [l, n] : size)
      if (n < io.min_cell_size) small.emplace_back(n, l);
    std::sort(small.begin(), small.end());
    std::map<Label, Label> into;  // merged label -> the label it went to (kOutside: dropped)
    auto find = [&](Label l) {
      for (auto it = into.find(l); it != into.end(); it = into.find(l)) l = it->second;
      return l;
    };
    if (io.small_cells == "merge" && !small.empty()) {
      std::map<Label, std::map<Label, std::int64_t>> shared;
      for (std::int64_t j = 1; j < H - 1; ++j)
        for (std::int64_t i = 1; i < W - 1; ++i) {
          const Label a = lab[pix(i, j)];
          if (a == kOutside) continue;
          for (const Label b : {lab[pix(i + 1, j)], lab[pix(i, j + 1)]})
            if (b != kOutside && b != a) ++shared[a][b], ++shared[b][a];
        }
      for (const auto& [n0, l] : small) {
        if (find(l) != l || size[l] >= io.min_cell_size) continue;
        std::map<Label, std::int64_t> by_root;
        for (const auto& [b, n] : shared[l])
          if (const Label r = find(b); r != l && r != kOutside) by_root[r] += n;
        Label best = kOutside;
        std::int64_t most = 0;
        for (const auto& [r, n] : by_root)
          if (n > most) best = r, most = n;  // ties: the smaller label (map order)
        into[l] = best;
        if (best == kOutside) {
          small_notes.push_back("label " + std::to_string(l) + " (" + std::to_string(size[l]) +
                                " pixels < min_cell_size) dropped: it touches no other cell");
          continue;
        }
        small_notes.push_back("label " + std::to_string(l) + " (" + std::to_string(size[l]) +
                              " pixels < min_cell_size) merged into label " + std::to_string(best) + " (they share " +
                              std::to_string(most) + " pixel edges)");
        size[best] += size[l];
        for (const auto& [b, n] : shared[l]) shared[best][b] += n;
      }
    } else {
      for (const auto& [n, l] : small) {
        into[l] = kOutside;
        small_notes.push_back("label " + std::to_string(l) + " (" + std::to_string(n) +
                              " pixels < min_cell_size) dropped");
      }
    }
    if (!into.empty())
      for (Label& l : lab)
        if (l != kOutside && into.count(l)) l = find(l);
  }
  for (std::size_t k = 0; k < small_notes.size() && k < kMaxNotes; ++k) report.notes.push_back(small_notes[k]);
  if (small_notes.size() > kMaxNotes)
    report.notes.push_back("and " + std::to_string(small_notes.size() - kMaxNotes) + " more small labels");

  // Pinched corners: which diagonal pair bridges (1: bottom-left/top-right, 2: bottom-right/top-left).
  std::vector<std::uint8_t> bridge(static_cast<std::size_t>(W * H), 0);
  std::size_t checkerboards = 0;
  for (std::int64_t cj = 1; cj < H; ++cj)
    for (std::int64_t ci = 1; ci < W; ++ci) {
      const Label a = lab[pix(ci - 1, cj - 1)], b = lab[pix(ci, cj - 1)], c = lab[pix(ci - 1, cj)],
                  d = lab[pix(ci, cj)];
      const bool ad = a == d && b != a && c != a, bc = b == c && a != b && d != b;
      if (!ad && !bc) continue;
      bool use_ad = ad;
      if (ad && bc) {
        ++checkerboards;
        use_ad = b == kOutside ? true : a == kOutside ? false : a < b;
      }
      bridge[pix(ci, cj)] = use_ad ? 1 : 2;
    }
  if (checkerboards)
    report.notes.push_back(std::to_string(checkerboards) +
                           " pixel corner(s) where two labels touch diagonally (a checkerboard): the smaller "
                           "label, or the cell over the background, is joined across the corner");

  // Pieces: pixels of one label joined by an edge or a bridged corner.
  detail::UnionFind uf(lab.size());
  for (std::int64_t j = 1; j < H - 1; ++j)
    for (std::int64_t i = 1; i < W - 1; ++i) {
      const Label a = lab[pix(i, j)];
      if (a == kOutside) continue;
      if (lab[pix(i + 1, j)] == a) uf.unite(static_cast<Index>(pix(i, j)), static_cast<Index>(pix(i + 1, j)));
      if (lab[pix(i, j + 1)] == a) uf.unite(static_cast<Index>(pix(i, j)), static_cast<Index>(pix(i, j + 1)));
    }
  for (std::int64_t cj = 1; cj < H; ++cj)
    for (std::int64_t ci = 1; ci < W; ++ci) {
      const auto type = bridge[pix(ci, cj)];
      if (type == 1 && lab[pix(ci, cj)] != kOutside)
        uf.unite(static_cast<Index>(pix(ci - 1, cj - 1)), static_cast<Index>(pix(ci, cj)));
      if (type == 2 && lab[pix(ci, cj - 1)] != kOutside)
        uf.unite(static_cast<Index>(pix(ci, cj - 1)), static_cast<Index>(pix(ci - 1, cj)));
    }
  // Cells: pieces sorted by label, then by their first pixel (row by row from y0).
  struct Piece {
    Label label;
    std::size_t first, pixels = 0;
  };
  std::vector<std::int32_t> piece_of_root(lab.size(), -1);  // by root pixel
  std::vector<Piece> pieces;
  for (std::int64_t j = 1; j < H - 1; ++j)
    for (std::int64_t i = 1; i < W - 1; ++i) {
      const Label a = lab[pix(i, j)];
      if (a == kOutside) continue;
      std::int32_t& piece = piece_of_root[uf.find(static_cast<Index>(pix(i, j)))];
      if (piece < 0) {
        piece = static_cast<std::int32_t>(pieces.size());
        pieces.push_back({a, pix(i, j)});
      }
      ++pieces[static_cast<std::size_t>(piece)].pixels;
    }
  if (pieces.empty())
    throw InputError(file + ": no cells: every pixel is background (" + labelList(io.background) + ")" +
                     (io.drop_labels.empty() && io.min_cell_size == 0 ? ""
                                                                      : ", dropped or smaller than min_cell_size"));
  std::vector<std::size_t> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    return pieces[p].label != pieces[q].label ? pieces[p].label < pieces[q].label : pieces[p].first < pieces[q].first;
  });
  auto pixelName = [&](std::size_t p) {
    return "(" + std::to_string(static_cast<std::int64_t>(p) % W - 1 + x0) + ", " +
           std::to_string(static_cast<std::int64_t>(p) / W - 1 + y0) + ")";
  };
  std::size_t split_labels = 0;
  for (std::size_t k = 0; k < order.size();) {
    std::size_t e = k;
    while (e < order.size() && pieces[order[e]].label == pieces[order[k]].label) ++e;
    if (e - k > 1) ++split_labels;
    k = e;
  }
  if (split_labels && !io.keep_pieces) {
    for (std::size_t k = 0; k < order.size();) {
      std::size_t e = k;
      while (e < order.size() && pieces[order[e]].label == pieces[order[k]].label) ++e;
      if (e - k > 1) {
        std::string sizes, where;
        for (std::size_t q = k; q < e && q < k + 5; ++q) {
          sizes += (q > k ? ", " : "") + std::to_string(pieces[order[q]].pixels);
          where += (q > k ? ", " : "") + pixelName(pieces[order[q]].first);
        }
        if (e - k > 5) sizes += ", ...", where += ", ...";
        throw InputError(file + ": label " + std::to_string(pieces[order[k]].label) + " is made of " +
                         std::to_string(e - k) + " disconnected pieces (of " + sizes + " pixels; a pixel of each: " +
                         where + ")" +
                         (split_labels > 1 ? "; " + std::to_string(split_labels - 1) + " other label(s) are split too"
                                           : "") +
                         "; keep_pieces: true (--keep-pieces) makes each piece a cell");
      }
      k = e;
    }
  }
  if (split_labels)
    report.notes.push_back(std::to_string(split_labels) +
                           " label(s) in several disconnected pieces, each piece a cell (keep_pieces)");
  std::vector<std::size_t> cell_of_piece(pieces.size());
  for (std::size_t c = 0; c < order.size(); ++c) cell_of_piece[order[c]] = c;
  const std::size_t n_cells = pieces.size();
  std::vector<std::int32_t> cell(lab.size(), -1);
  for (std::int64_t j = 1; j < H - 1; ++j)
    for (std::int64_t i = 1; i < W - 1; ++i)
      if (lab[pix(i, j)] != kOutside)
        cell[pix(i, j)] = static_cast<std::int32_t>(
            cell_of_piece[static_cast<std::size_t>(piece_of_root[uf.find(static_cast<Index>(pix(i, j)))])]);
  auto cellName = [&](std::int32_t c) {
    return c < 0 ? std::string("the background") : "label " + std::to_string(pieces[order[c]].label);
  };

  // Vertices: the pixel corners on a boundary (two at a bridged corner), in pixel units.
  std::vector<std::int32_t> vert0(lab.size(), -1), vert1(lab.size(), -1);
  std::vector<Vec3> pos;
  // The vertex at corner (ci, cj) for the pixel edge leaving it along axis 0 down, 1 right, 2 up, 3 left.
  auto vertexAt = [&](std::int64_t ci, std::int64_t cj, int axis) {
    const std::size_t k = pix(ci, cj);
    const double x = static_cast<double>(ci - 1), y = static_cast<double>(cj - 1);
    const auto type = bridge[k];
    bool second = false;
    Vec3 p(x, y, 0);
    if (type == 1) {  // a-d bridge: down/right on b's side (+,-), up/left on c's side (-,+)
      second = axis == 2 || axis == 3;
      p = second ? Vec3(x - kSplit, y + kSplit, 0) : Vec3(x + kSplit, y - kSplit, 0);
    } else if (type == 2) {  // b-c bridge: down/left on a's side (-,-), up/right on d's side (+,+)
      second = axis == 1 || axis == 2;
      p = second ? Vec3(x + kSplit, y + kSplit, 0) : Vec3(x - kSplit, y - kSplit, 0);
    }
    std::int32_t& id = second ? vert1[k] : vert0[k];
    if (id < 0) {
      id = static_cast<std::int32_t>(pos.size());
      pos.push_back(p);
    }
    return id;
  };
  std::vector<BoundaryEdge> edges;
  for (std::int64_t j = 1; j < H - 1; ++j)
    for (std::int64_t i = 1; i < W; ++i) {  // vertical edge between pixels (i-1, j) and (i, j)
      const std::int32_t l = cell[pix(i - 1, j)], r = cell[pix(i, j)];
      if (l != r) edges.push_back({vertexAt(i, j, 2), vertexAt(i, j + 1, 0), l, r});
    }
  for (std::int64_t j = 1; j < H; ++j)
    for (std::int64_t i = 1; i < W - 1; ++i) {  // horizontal edge between pixels (i, j-1) below and (i, j) above
      const std::int32_t below = cell[pix(i, j - 1)], above = cell[pix(i, j)];
      if (below != above) edges.push_back({vertexAt(i, j, 1), vertexAt(i + 1, j, 3), above, below});
    }
  std::vector<std::int32_t>().swap(vert0);
  std::vector<std::int32_t>().swap(vert1);
  const std::size_t n_verts = pos.size();
  std::vector<std::array<std::int32_t, 4>> incident(n_verts);
  std::vector<std::uint8_t> degree(n_verts, 0);
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (const std::int32_t v : {edges[e].u, edges[e].v}) incident[v][degree[v]++] = static_cast<std::int32_t>(e);
  auto pairOf = [&](std::size_t e) {
    return std::minmax(edges[e].left, edges[e].right);
  };
  std::vector<char> junction(n_verts, 0);
  for (std::size_t v = 0; v < n_verts; ++v)
    junction[v] = degree[v] != 2 || pairOf(incident[v][0]) != pairOf(incident[v][1]);

  // Walls: chains of edges between junctions; a closed chain without one starts at its first vertex.
  std::vector<Wall> walls;
  std::vector<std::int32_t> edge_wall(edges.size(), -1);
  auto walk = [&](std::int32_t start, std::int32_t e0) {
    Wall wall{{start}, o.simplify};
    std::int32_t v = start, e = e0;
    for (;;) {
      edge_wall[e] = static_cast<std::int32_t>(walls.size());
      v = edges[e].u == v ? edges[e].v : edges[e].u;
      wall.chain.push_back(v);
      if (junction[v]) break;
      e = incident[v][0] == e ? incident[v][1] : incident[v][0];
    }
    walls.push_back(std::move(wall));
  };
  for (std::size_t v = 0; v < n_verts; ++v)
    if (junction[v])
      for (int k = 0; k < degree[v]; ++k)
        if (edge_wall[incident[v][k]] < 0) walk(static_cast<std::int32_t>(v), incident[v][k]);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edge_wall[e] < 0) {
      junction[edges[e].u] = 1;
      walk(edges[e].u, static_cast<std::int32_t>(e));
    }

  // Outlines: per cell, its boundary edges chained the way the cell runs (counter-clockwise).
  std::vector<std::vector<std::int32_t>> cell_edges(n_cells);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].left >= 0) cell_edges[edges[e].left].push_back(static_cast<std::int32_t>(e));
    if (edges[e].right >= 0) cell_edges[edges[e].right].push_back(static_cast<std::int32_t>(e));
  }
  std::vector<std::uint8_t> edge_used(edges.size(), 0);  // 1: walked by its left cell, 2: by its right one
  std::vector<std::vector<std::int32_t>> outline_edges(n_cells);  // the edges in loop order
  std::vector<std::vector<std::int32_t>> outlines(n_cells);       // the vertices
  for (std::size_t c = 0; c < n_cells; ++c) {
    const auto ci = static_cast<std::int32_t>(c);
    auto from = [&](std::int32_t e) { return edges[e].left == ci ? edges[e].u : edges[e].v; };
    auto to = [&](std::int32_t e) { return edges[e].left == ci ? edges[e].v : edges[e].u; };
    // The cell's edge leaving vertex v: one at most, as pinched corners are bridged.
    auto out = [&](std::int32_t v) {
      for (int k = 0; k < degree[v]; ++k) {
        const std::int32_t e = incident[v][k];
        if ((edges[e].left == ci && edges[e].u == v) || (edges[e].right == ci && edges[e].v == v)) return e;
      }
      throw InputError(file + ": " + cellName(ci) + ": its outline is not closed (an internal error)");
    };
    std::vector<std::vector<std::int32_t>> loops;
    for (const std::int32_t e0 : cell_edges[c]) {  // in increasing order
      if (edge_used[e0] & (edges[e0].left == ci ? 1 : 2)) continue;
      loops.emplace_back();
      for (std::int32_t e = e0; !(edge_used[e] & (edges[e].left == ci ? 1 : 2)); e = out(to(e))) {
        edge_used[e] |= edges[e].left == ci ? 1 : 2;
        loops.back().push_back(e);
      }
    }
    if (loops.size() > 1) {
      // The outer loop turns counter-clockwise (positive area); the others bound holes.
      std::vector<Label> inside;
      bool background = false;
      for (const auto& loop : loops) {
        double area = 0;
        for (const std::int32_t e : loop) {
          const Vec3 &p = pos[from(e)], &q = pos[to(e)];
          area += p.x() * q.y() - q.x() * p.y();
        }
        if (area > 0) continue;
        for (const std::int32_t e : loop) {
          const std::int32_t other = edges[e].left == ci ? edges[e].right : edges[e].left;
          if (other < 0) background = true;
          else inside.push_back(pieces[order[other]].label);
        }
      }
      std::sort(inside.begin(), inside.end());
      inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
      std::string what = inside.empty() ? std::string() : "label(s) " + labelList(inside);
      if (background) what += (what.empty() ? "" : " and ") + std::string("background pixels");
      throw InputError(file + ": " + cellName(ci) + " (a pixel of it at " + pixelName(pieces[order[c]].first) +
                       ") has a hole: it surrounds " + what +
                       ". A cell is one polygon without holes; drop the inner labels (drop_labels), merge them "
                       "(min_cell_size with small_cells: merge), or make the hole part of the cell");
    }
    outline_edges[c] = std::move(loops[0]);
    for (const std::int32_t e : outline_edges[c]) outlines[c].push_back(from(e));
  }

  // Simplify, then make sure no two walls cross and no cell flattens.
  std::vector<char> keep(n_verts, 0);
  for (std::size_t v = 0; v < n_verts; ++v) keep[v] = junction[v];
  for (const Wall& wl : walls) simplifyWall(wl, pos, keep);
  {
    // Of the walls with the same two ends, one at most may become a straight segment (they would collapse).
    std::map<std::pair<std::int32_t, std::int32_t>, int> straight;
    for (Wall& wl : walls) {
      if (wl.chain.front() == wl.chain.back() || wl.chain.size() < 3) continue;
      bool inner = false;
      for (std::size_t k = 1; k + 1 < wl.chain.size(); ++k) inner = inner || keep[wl.chain[k]];
      if (inner) continue;
      if (straight[std::minmax(wl.chain.front(), wl.chain.back())]++ == 0) continue;
      wl.keep_one = true;
      simplifyWall(wl, pos, keep);
    }
  }
  std::vector<std::vector<std::int32_t>> wall_cells(walls.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    auto& cs = wall_cells[edge_wall[e]];
    if (cs.empty()) {
      if (edges[e].left >= 0) cs.push_back(edges[e].left);
      if (edges[e].right >= 0) cs.push_back(edges[e].right);
    }
  }
  std::vector<std::vector<std::int32_t>> cell_walls(n_cells);
  for (std::size_t wi = 0; wi < walls.size(); ++wi)
    for (const std::int32_t c : wall_cells[wi]) cell_walls[c].push_back(static_cast<std::int32_t>(wi));
  const double bucket = 4;
  for (int round = 0;; ++round) {
    std::vector<char> redo(walls.size(), 0);
    std::vector<Segment> segs;
    for (std::size_t wi = 0; wi < walls.size(); ++wi) {
      std::int32_t prev = walls[wi].chain.front();
      for (std::size_t k = 1; k < walls[wi].chain.size(); ++k) {
        const std::int32_t v = walls[wi].chain[k];
        if (!keep[v]) continue;
        segs.push_back({prev, v, static_cast<std::int32_t>(wi)});
        prev = v;
      }
    }
    std::unordered_map<std::uint64_t, std::vector<std::int32_t>> grid;
    for (std::size_t s = 0; s < segs.size(); ++s) {
      const Vec3 &p = pos[segs[s].a], &q = pos[segs[s].b];
      const auto bx0 = static_cast<std::int64_t>(std::floor((std::min(p.x(), q.x()) + 1) / bucket));
      const auto bx1 = static_cast<std::int64_t>(std::floor((std::max(p.x(), q.x()) + 1) / bucket));
      const auto by0 = static_cast<std::int64_t>(std::floor((std::min(p.y(), q.y()) + 1) / bucket));
      const auto by1 = static_cast<std::int64_t>(std::floor((std::max(p.y(), q.y()) + 1) / bucket));
      for (std::int64_t by = by0; by <= by1; ++by)
        for (std::int64_t bx = bx0; bx <= bx1; ++bx)
          grid[(static_cast<std::uint64_t>(by) << 32) | static_cast<std::uint64_t>(bx)].push_back(
              static_cast<std::int32_t>(s));
    }
    for (const auto& [key, list] : grid)
      for (std::size_t a = 0; a < list.size(); ++a)
        for (std::size_t b = a + 1; b < list.size(); ++b) {
          const Segment &s = segs[list[a]], &t = segs[list[b]];
          if (conflict(s, t, pos)) redo[s.wall] = redo[t.wall] = 1;
        }
    for (std::size_t c = 0; c < n_cells; ++c) {
      double area = 0;
      std::size_t corners = 0;
      std::int32_t first = -1, prev = -1;
      for (const std::int32_t v : outlines[c]) {
        if (!keep[v]) continue;
        ++corners;
        if (first < 0) first = v;
        else area += pos[prev].x() * pos[v].y() - pos[v].x() * pos[prev].y();
        prev = v;
      }
      area += pos[prev].x() * pos[first].y() - pos[first].x() * pos[prev].y();
      if (corners < 3 || area <= 0)
        for (const std::int32_t wi : cell_walls[c]) redo[wi] = 1;
    }
    if (std::find(redo.begin(), redo.end(), 1) == redo.end()) break;
    for (std::size_t wi = 0; wi < walls.size(); ++wi) {
      if (!redo[wi]) continue;
      Wall& wl = walls[wi];
      if (wl.tol < 0) continue;
      wl.tol = wl.tol > 1.0 / 64 ? wl.tol / 2 : -1;
      simplifyWall(wl, pos, keep);
    }
    if (round > 64) throw InputError(file + ": simplifying the walls did not converge (an internal error)");
  }

  // Positions: corner (x, y) in pixels is the edge of pixel x, at origin + (x - 1/2) * spacing.
  std::vector<std::int32_t> new_index(n_verts, -1);
  std::vector<Vec3> positions;
  for (std::size_t v = 0; v < n_verts; ++v)
    if (keep[v]) {
      new_index[v] = static_cast<std::int32_t>(positions.size());
      const double x = img.origin[0] + (pos[v].x() + static_cast<double>(x0) - 0.5) * sx;
      const double y = img.origin[1] + (pos[v].y() + static_cast<double>(y0) - 0.5) * sy;
      positions.emplace_back(o.scale * x, o.scale * y, 0.0);
    }
  report.file_vertices = 0;
  report.simplified_vertices = n_verts - positions.size();
  std::vector<std::vector<Index>> polygons(n_cells);
  for (std::size_t c = 0; c < n_cells; ++c)
    for (const std::int32_t v : outlines[c])
      if (keep[v]) polygons[c].push_back(static_cast<Index>(new_index[v]));
  try {
    result.tissue = buildPolygonTissue(positions, polygons, Embedding::Planar);
  } catch (const Error& e) {
    throw InputError(file + ": the cells do not form a tissue: " + std::string(e.what()));
  }
  auto& label = result.tissue.cellProperties().add<std::int64_t>("label", 0);
  for (std::size_t c = 0; c < n_cells; ++c) label[CellId(static_cast<Index>(c))] = pieces[order[c]].label;
  report.notes.push_back(std::to_string(n_cells) + " cells, " + std::to_string(walls.size()) + " walls; " +
                         std::to_string(positions.size()) + " of " + std::to_string(n_verts) +
                         " boundary pixel corners kept (simplify " + formatNumber(o.simplify) + " px)");
  return result;
}

}  // namespace tessella::io
