// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 2D label images as planar tissues (docs/import.md, "Label images"): every
// label that is not background is a cell; walls run along the pixel edges
// between two labels; junctions are the pixel corners where three or more
// labels (the outside counting as one) meet. Each wall (a chain of pixel
// edges between junctions) is simplified by Douglas-Peucker with its ends
// fixed, both cells seeing the same polyline, and a wall whose simplification
// would cross another wall or flatten a cell is simplified again with half
// the tolerance until none does. The walls are traced on a graph of the
// corners where the boundary turns or branches, its edges straight stretches
// of pixel edges; the result is that of the graph of every pixel corner
// (see "Vertices and boundary edges" below and simplifyEdge).
//
// Pixel-diagonal contacts: at a pixel corner where two diagonal pixels carry
// one label and the other two pixels other labels (a pinch), the label of the
// diagonal pair bridges the corner: the corner becomes two vertices a quarter
// pixel off it, one on each side of the bridge. Where both diagonal pairs
// qualify (a checkerboard of two labels), a cell bridges over the outside,
// and of two cells the smaller label bridges.

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <thread>
#include <type_traits>
#include <variant>

#include <omp.h>

#include "label_image_2d.hpp"
#include "label_image_3d.hpp"
#include "labelled_surface.hpp"
#include "polyline_simplification.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/huge_pages.hpp"

namespace tessella::io {

namespace {

using tessella::detail::HugePageUninitializedVector;
using tessella::detail::HugePageVector;
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

// The positions of the graph's vertices, in pixels: pixel corner (ci, cj) (ci, cj >= 1) is at (ci - 1, cj - 1),
// the two vertices of a bridged corner a quarter pixel (kSplit) off it. Kept as unsigned quarter pixels from
// (-1, -1) (4 W + 1 < 2^32: W < 2^30 for any image a 2D import takes), a third of the memory of Vec3s, and read
// back as the same doubles (quarter pixels are exact).
struct CornerPositions {
  HugePageUninitializedVector<std::array<std::uint32_t, 2>> q;
  Vec3 operator[](std::size_t v) const {
    return Vec3((static_cast<double>(q[v][0]) - 4) * 0.25, (static_cast<double>(q[v][1]) - 4) * 0.25, 0);
  }
  std::size_t size() const { return q.size(); }
  void swap(CornerPositions& other) noexcept { q.swap(other.q); }
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
bool conflict(const Segment& s, const Segment& t, const CornerPositions& pos) {
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

// The walls, flat: wall w is the vertex chain chain[off[w] .. off[w + 1]), junction to junction (closed:
// first == last), simplified with tolerance tol[w] (< 0: keep every vertex); keep_one[w]: keep an inner vertex
// (another wall with the same two ends is a straight segment).
struct Walls {
  std::vector<std::int32_t> off{0};
  HugePageVector<std::int32_t> chain;
  std::vector<double> tol;
  std::vector<char> keep_one;
  std::size_t size() const { return tol.size(); }
};

// The pixel edges along a graph edge between two vertices (of a bridged corner: the corner's).
std::int32_t pixelLength(const Vec3& a, const Vec3& b) {
  return static_cast<std::int32_t>(std::abs(std::round(a.x()) - std::round(b.x())) +
                                   std::abs(std::round(a.y()) - std::round(b.y())));
}

// A pixel corner inside a graph edge kept by the simplification: the edge's ends a, b in the wall's order and
// the corner's distance from a in pixels.
struct InnerCorner {
  std::int32_t a, b, i;
};

// Douglas-Peucker (detail::douglasPeucker) on the pixel corners of the graph edge from a to b: a, the corners
// inside, b, as the graph of every pixel corner has them. Its inner corners lie on a segment and are kept
// only where the test's rounding says they lie off it (a corner inside [x, 0] to [0, 0] at a few ulp) or
// keep_one asks for one (a straight wall that must not become a segment).
void simplifyEdge(const CornerPositions& pos, std::int32_t a, std::int32_t b, double tol, bool keep_one,
                  std::vector<InnerCorner>& inner) {
  const Vec3 &pa = pos[a], &pb = pos[b];
  const int n = pixelLength(pa, pb);
  if (n < 2) return;
  const double ax = std::round(pa.x()), ay = std::round(pa.y());
  const double dx = (std::round(pb.x()) - ax) / n, dy = (std::round(pb.y()) - ay) / n;
  auto at = [&](int i) { return i == 0 ? pa : i == n ? pb : Vec3(ax + i * dx, ay + i * dy, 0); };
  auto dp = [&](auto&& self, int lo, int hi, bool one) -> void {
    if (hi <= lo + 1) return;
    const Vec3 p = at(lo), q = at(hi);
    double worst = -1;
    int arg = lo;
    for (int i = lo + 1; i < hi; ++i)
      if (const double d = detail::pointSegmentDistance(at(i), p, q); d > worst) worst = d, arg = i;
    if (worst <= tol && !one) return;
    inner.push_back({a, b, arg});
    self(self, lo, arg, false);
    self(self, arg, hi, false);
  };
  dp(dp, 0, n, keep_one);
}

// detail::douglasPeucker on the wall chain[lo..hi] of graph vertices, the same as on every pixel corner of it:
// along a straight stretch the distance to a segment is convex, so the farthest corner (the first of equals)
// is a vertex of the graph, or the chord is one edge, whose inner corners simplifyEdge visits.
void douglasPeuckerWall(const HugePageVector<std::int32_t>& ch, std::size_t lo, std::size_t hi,
                        const CornerPositions& pos, double tol, bool keep_one, HugePageVector<char>& keep,
                        std::vector<InnerCorner>& inner) {
  if (hi == lo + 1) return simplifyEdge(pos, ch[lo], ch[hi], tol, keep_one, inner);
  if (hi <= lo) return;
  if (tol == 0) {
    // Where every inner vertex turns (its edges not on one line), each range of two or more edges has one at a
    // positive distance from its chord, which the test finds positive (quarter-pixel coordinates, exact orient):
    // the recursion keeps every vertex and ends at every edge, left to right. The same result without it.
    bool turns = true;
    for (std::size_t i = lo + 1; i < hi && turns; ++i) turns = orient(pos[ch[i - 1]], pos[ch[i]], pos[ch[i + 1]]) != 0;
    if (turns) {
      for (std::size_t i = lo + 1; i < hi; ++i) keep[ch[i]] = 1;
      for (std::size_t i = lo; i < hi; ++i) simplifyEdge(pos, ch[i], ch[i + 1], tol, false, inner);
      return;
    }
  }
  double worst = -1;
  std::size_t at = lo;
  for (std::size_t i = lo + 1; i < hi; ++i)
    if (const double d = detail::pointSegmentDistance(pos[ch[i]], pos[ch[lo]], pos[ch[hi]]); d > worst)
      worst = d, at = i;
  if (worst <= tol && !keep_one) return;
  keep[ch[at]] = 1;
  douglasPeuckerWall(ch, lo, at, pos, tol, false, keep, inner);
  douglasPeuckerWall(ch, at, hi, pos, tol, false, keep, inner);
}

// Simplifies wall wi: sets `keep` of its inner vertices and lists the pixel corners kept inside its edges.
void simplifyWall(const Walls& ws, std::size_t wi, const CornerPositions& pos, HugePageVector<char>& keep,
                  std::vector<InnerCorner>& inner) {
  inner.clear();
  const auto& ch = ws.chain;
  const auto b = static_cast<std::size_t>(ws.off[wi]), last = static_cast<std::size_t>(ws.off[wi + 1]) - 1;
  const double tol = ws.tol[wi];
  for (std::size_t i = b + 1; i < last; ++i) keep[ch[i]] = tol < 0;  // tol < 0: keep every pixel corner
  if (tol < 0) {
    for (std::size_t i = b; i < last; ++i)
      for (std::int32_t k = 1, n = pixelLength(pos[ch[i]], pos[ch[i + 1]]); k < n; ++k)
        inner.push_back({ch[i], ch[i + 1], k});
    return;
  }
  if (ch[b] == ch[last]) {  // a loop: split at the vertex farthest from its start, keep one more on each side
    std::size_t far = b + 1;
    for (std::size_t i = b + 1; i < last; ++i)
      if ((pos[ch[i]] - pos[ch[b]]).squaredNorm() > (pos[ch[far]] - pos[ch[b]]).squaredNorm()) far = i;
    if (last < b + 2) return;
    keep[ch[far]] = 1;
    // keep_one: moot where no corner lies between the ends (as where it is false for every pixel corner)
    douglasPeuckerWall(ch, b, far, pos, tol, true, keep, inner);
    douglasPeuckerWall(ch, far, last, pos, tol, true, keep, inner);
    return;
  }
  douglasPeuckerWall(ch, b, last, pos, tol, ws.keep_one[wi] != 0, keep, inner);
}

// Compressed sparse rows: the items of row r are items[off[r] .. off[r + 1]).
template <typename T>
struct Csr {
  std::vector<std::int32_t> off;
  HugePageUninitializedVector<T> items;  // every item written after the resize
};

// The runs of equal labels along the rows of the padded image: row r's runs start at x[off[r]] (the first at 0),
// each ends where the next starts (the last at the padded width); label[k] is the run's label (kOutside for
// background, dropped labels and the padding, all joined into one run).
struct Runs {
  std::vector<std::int32_t> off;
  HugePageUninitializedVector<std::int32_t> x;  // every item written after a resize
  HugePageUninitializedVector<Label> label;
  std::int32_t end(std::size_t k, std::size_t row, std::int32_t width) const {
    return k + 1 < static_cast<std::size_t>(off[row + 1]) ? x[k + 1] : width;
  }
};

struct UnionFind32 {
  HugePageUninitializedVector<std::int32_t> parent;  // every item written by iota
  explicit UnionFind32(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

namespace {

// The labels are `pixels` (`count` of them: img.labels, or the file's pixels as stored); `release`, when given,
// frees them once the runs are made; `labels_3d`, when given, is img.labels for a 3D image, emptied once read.
ImportResult convertLabelImage(const LabelImage& img, detail::LabelPixels pixels, std::size_t count,
                               const ImportOptions& o, const std::function<void()>& release,
                               std::vector<std::int64_t>* labels_3d) {
  detail::checkImportOptions(o);
  const LabelImageOptions& io = o.image;
  const std::string file = "'" + img.name + "'";
  const auto [nx, ny, nz] = img.dims;
  if (nx < 1 || ny < 1 || nz < 1 ||
      count != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz))
    throw InputError(file + ": the image has dimensions " + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                     std::to_string(nz) + " but " + std::to_string(count) + " labels");
  if (nz != 1) return detail::tissueFromLabelImage3d(img, o, labels_3d);
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
  // The image padded with a ring of outside pixels: pixel (i, j) of the padded image is pixel (i - 1 + x0,
  // j - 1 + y0) of the file. Pixel corner (i, j) is the lower left corner of padded pixel (i, j).
  const std::int64_t W = w + 2, H = h + 2;
  if (W * H > std::numeric_limits<std::int32_t>::max())
    throw InputError(file + ": " + std::to_string(w) + " x " + std::to_string(h) +
                     " pixels are more than a 2D import handles (2^31); crop the image");
  const auto width = static_cast<std::int32_t>(W);
  auto pix = [&](std::int64_t i, std::int64_t j) { return static_cast<std::size_t>(j * W + i); };
  auto outsideLabel = [&](Label l) {
    return std::find(io.background.begin(), io.background.end(), l) != io.background.end() ||
           std::find(io.drop_labels.begin(), io.drop_labels.end(), l) != io.drop_labels.end();
  };

  // Labels, as runs along the rows: one pass over the pixels, in parallel over blocks of rows (a row's runs
  // depend on that row alone, so the result is the same for any number of threads).
  Runs runs;
  {
    const Label first = std::visit([&](auto* px) { return static_cast<Label>(px[y0 * nx + x0]); }, pixels);
    // Block 0 starts with the first padding row's run, and its arrays become the runs' (the others are copied
    // after it): it reserves room for the whole image's runs, the others for theirs.
    struct Block {
      std::vector<std::int32_t> count;
      HugePageUninitializedVector<std::int32_t> x;
      HugePageUninitializedVector<Label> label;
      bool several = false;
    };
    const int n_blocks = std::max(1, std::min<int>(omp_get_max_threads(), static_cast<int>(h)));
    std::vector<Block> blocks(static_cast<std::size_t>(n_blocks));
    // In the pixels' stored type (the read's, without a 64-bit copy): each pixel compared, a run's label widened.
    auto scan = [&](auto* px) {
#pragma omp parallel for schedule(static, 1) num_threads(n_blocks)
      for (int b = 0; b < n_blocks; ++b) {
        Block& blk = blocks[static_cast<std::size_t>(b)];
        const std::int64_t r0 = h * b / n_blocks, r1 = h * (b + 1) / n_blocks;
        bool several = false;
        if (b == 0) blk.x.push_back(0), blk.label.push_back(kOutside);
        for (std::int64_t r = r0; r < r1; ++r) {
          const auto* src = px + static_cast<std::size_t>((r + y0) * nx + x0);
          const std::size_t before = blk.x.size();
          blk.x.push_back(0), blk.label.push_back(kOutside);
          Label current = kOutside;
          for (std::int64_t i = 0; i < w;) {
            const Label l = src[i];
            several = several || l != first;
            const Label m = outsideLabel(l) ? kOutside : l;
            if (m != current) blk.x.push_back(static_cast<std::int32_t>(i + 1)), blk.label.push_back(m), current = m;
            for (++i; i < w && src[i] == l;) ++i;
          }
          if (current != kOutside) blk.x.push_back(static_cast<std::int32_t>(w + 1)), blk.label.push_back(kOutside);
          blk.count.push_back(static_cast<std::int32_t>(blk.x.size() - before));
          if (r == r0) {  // room at a quarter more than the first row's rate (growing by copies touches more memory),
            // and for a run per 4 pixels at most (a row far busier than the others)
            const auto rows = static_cast<std::size_t>(b == 0 ? H : r1 - r0), row_runs = blk.x.size() - before;
            const std::size_t guess = std::min(rows * (row_runs * 5 / 4 + 1), rows * static_cast<std::size_t>(W) / 4);
            blk.x.reserve(guess), blk.label.reserve(guess), blk.count.reserve(static_cast<std::size_t>(r1 - r0));
          }
        }
        blk.several = several;
      }
    };
    std::visit(scan, pixels);
    bool several = false;
    std::size_t n_runs = 1;  // and the last padding row's run
    for (const Block& blk : blocks) several = several || blk.several, n_runs += blk.x.size();
    if (!several)
      throw InputError(file + ": the image" + std::string(io.crop.empty() ? "" : " (cropped)") +
                       " holds one label only (" + std::to_string(first) + " in every pixel): no cells to tell apart");
    if (n_runs > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      throw InputError(file + ": too many label changes for a 2D import (2^31); crop the image");
    // Joined into the runs of the padded image: block 0's in place, the others copied after them.
    std::vector<std::size_t> block_start(static_cast<std::size_t>(n_blocks) + 1, 0);
    for (int b = 0; b < n_blocks; ++b)
      block_start[b + 1] = block_start[b] + blocks[static_cast<std::size_t>(b)].x.size();
    block_start[0] = 1;  // block 0's rows, after the padding row
    runs.off.resize(static_cast<std::size_t>(H + 1));
    runs.x.swap(blocks[0].x), runs.label.swap(blocks[0].label);
    runs.x.resize(n_runs), runs.label.resize(n_runs);
    runs.off[0] = 0;  // the padding rows: one outside run each
    runs.off[H - 1] = static_cast<std::int32_t>(n_runs - 1);
    runs.x[n_runs - 1] = 0, runs.label[n_runs - 1] = kOutside;
    runs.off[H] = static_cast<std::int32_t>(n_runs);
    for (int b = 0; b < n_blocks; ++b) {
      const Block& blk = blocks[static_cast<std::size_t>(b)];
      const std::size_t start = block_start[static_cast<std::size_t>(b)];
      std::copy(blk.x.begin(), blk.x.end(), runs.x.begin() + static_cast<std::ptrdiff_t>(start));
      std::copy(blk.label.begin(), blk.label.end(), runs.label.begin() + static_cast<std::ptrdiff_t>(start));
      std::size_t at = start, row = static_cast<std::size_t>(h * b / n_blocks) + 1;
      for (const std::int32_t n : blk.count)
        runs.off[row++] = static_cast<std::int32_t>(at), at += static_cast<std::size_t>(n);
    }
  }
  // The pixels are not read again: freed on a thread of their own, beside the steps below (unmapping a 4096^2
  // image's 64 MB took 10 ms of the serial path); joined when this returns or throws.
  std::jthread releasing;
  if (release) releasing = std::jthread(release);
  auto runEnd = [&](std::size_t k, std::size_t row) { return runs.end(k, row, width); };
  // Walks the runs of rows ra and rb side by side: f(ka, kb, s, e, a_ends, b_ends) for each stretch [s, e) of
  // the padded row over which run ka of row ra and run kb of row rb both lie (a_ends: run ka ends at e).
  auto sideBySide = [&](std::size_t ra, std::size_t rb, auto&& f) {
    auto ka = static_cast<std::size_t>(runs.off[ra]), kb = static_cast<std::size_t>(runs.off[rb]);
    for (std::int32_t s = 0; s < width;) {
      const std::int32_t ea = runEnd(ka, ra), eb = runEnd(kb, rb), e = std::min(ea, eb);
      f(ka, kb, s, e, ea == e, eb == e);
      ka += ea == e, kb += eb == e, s = e;
    }
  };

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
  // Small labels: dropped, or merged into the neighbour sharing the most pixel edges.
  if (io.min_cell_size > 0) {
    std::map<Label, std::int64_t> size;
    for (std::size_t r = 1; r + 1 < static_cast<std::size_t>(H); ++r)
      for (auto k = static_cast<std::size_t>(runs.off[r]); k < static_cast<std::size_t>(runs.off[r + 1]); ++k)
        if (runs.label[k] != kOutside) size[runs.label[k]] += runEnd(k, r) - runs.x[k];
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
      // Pixel edges shared by two labels: between consecutive runs of a row, and where runs of two
      // consecutive rows lie side by side.
      std::map<Label, std::map<Label, std::int64_t>> shared;
      for (std::size_t r = 1; r + 1 < static_cast<std::size_t>(H); ++r) {
        for (auto k = static_cast<std::size_t>(runs.off[r]) + 1; k < static_cast<std::size_t>(runs.off[r + 1]); ++k)
          if (const Label a = runs.label[k - 1], b = runs.label[k]; a != kOutside && b != kOutside)
            ++shared[a][b], ++shared[b][a];
        if (r + 2 < static_cast<std::size_t>(H))
          sideBySide(r, r + 1, [&](std::size_t ka, std::size_t kb, std::int32_t s, std::int32_t e, bool, bool) {
            const Label a = runs.label[ka], b = runs.label[kb];
            if (a != kOutside && b != kOutside && a != b) shared[a][b] += e - s, shared[b][a] += e - s;
          });
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
    if (!into.empty()) {  // relabel the runs, joining neighbours that now carry one label
      Runs joined;
      joined.off.reserve(runs.off.size()), joined.x.reserve(runs.x.size()), joined.label.reserve(runs.x.size());
      for (std::size_t r = 0; r + 1 < runs.off.size(); ++r) {
        joined.off.push_back(static_cast<std::int32_t>(joined.x.size()));
        for (auto k = static_cast<std::size_t>(runs.off[r]); k < static_cast<std::size_t>(runs.off[r + 1]); ++k) {
          const Label l = runs.label[k] != kOutside && into.count(runs.label[k]) ? find(runs.label[k]) : runs.label[k];
          if (k > static_cast<std::size_t>(runs.off[r]) && l == joined.label.back()) continue;
          joined.x.push_back(runs.x[k]), joined.label.push_back(l);
        }
      }
      joined.off.push_back(static_cast<std::int32_t>(joined.x.size()));
      runs = std::move(joined);
    }
  }
  for (std::size_t k = 0; k < small_notes.size() && k < kMaxNotes; ++k) report.notes.push_back(small_notes[k]);
  if (small_notes.size() > kMaxNotes)
    report.notes.push_back("and " + std::to_string(small_notes.size() - kMaxNotes) + " more small labels");

  // Pieces: runs of one label joined where they lie side by side in consecutive rows, or across a pinched
  // corner. A corner is pinched where both rows change label: which diagonal pair bridges it (1: bottom-left/
  // top-right, 2: bottom-right/top-left) is listed row by row.
  const std::size_t n_runs = runs.x.size();
  UnionFind32 uf(n_runs);
  // Per block of rows: the bridged corners, row by row; counted on the way, for the vertices and edges below:
  // the corners on a vertical edge, and the horizontal boundary edges and the corners inside their straight
  // stretches.
  struct Scan {
    std::vector<std::int32_t> bridge_row, bridge_x;
    std::vector<std::uint8_t> bridge_type;
    std::size_t checkerboards = 0, n_corners = 0, n_hedges = 0, n_hcorners = 0;
  };
  // Corner rows [r0, r1): the runs of rows r0 - 1 .. r1 - 1 are united (the sets' roots, their lowest runs, do
  // not depend on the order of the unions).
  auto scanRows = [&](Scan& sc, std::size_t r0, std::size_t r1) {
    for (std::size_t cj = r0; cj < r1; ++cj)
      sideBySide(cj - 1, cj, [&](std::size_t ka, std::size_t kb, std::int32_t s, std::int32_t e, bool a_ends,
                                 bool b_ends) {
        const Label below = runs.label[ka];
        if (below == runs.label[kb]) {
          if (below != kOutside) uf.unite(static_cast<std::int32_t>(ka), static_cast<std::int32_t>(kb));
        } else {  // a boundary (runs of one label side by side are one piece)
          sc.n_hedges += static_cast<std::size_t>(e - s), sc.n_hcorners += static_cast<std::size_t>(e - s - 1);
        }
        sc.n_corners += e < width;
        if (!a_ends || !b_ends || e == width) return;
        // Corner e: pixels a (below left), b (below right), c (above left), d (above right).
        const Label a = below, b = runs.label[ka + 1], c = runs.label[kb], d = runs.label[kb + 1];
        const bool ad = a == d && b != a && c != a, bc = b == c && a != b && d != b;
        if (!ad && !bc) return;
        bool use_ad = ad;
        if (ad && bc) {
          ++sc.checkerboards;
          use_ad = b == kOutside ? true : a == kOutside ? false : a < b;
        }
        sc.bridge_row.push_back(static_cast<std::int32_t>(cj)), sc.bridge_x.push_back(e);
        sc.bridge_type.push_back(use_ad ? 1 : 2);
        if (use_ad && d != kOutside) uf.unite(static_cast<std::int32_t>(ka), static_cast<std::int32_t>(kb + 1));
        if (!use_ad && b != kOutside) uf.unite(static_cast<std::int32_t>(ka + 1), static_cast<std::int32_t>(kb));
      });
  };
  // Two blocks of corner rows at once, [1, m) and [m + 1, H), whose unions touch the runs of rows below m and
  // from m on: none in common; then row m, which joins them.
  Scan scan;
  if (H >= 8) {
    const auto m = static_cast<std::size_t>(H / 2);
    Scan second, seam;
    std::exception_ptr failed[2];  // (an exception must not leave a section: out of memory, say)
#pragma omp parallel sections num_threads(std::min(2, omp_get_max_threads()))
    {
#pragma omp section
      try {
        scanRows(scan, 1, m);
      } catch (...) {
        failed[0] = std::current_exception();
      }
#pragma omp section
      try {
        scanRows(second, m + 1, static_cast<std::size_t>(H));
      } catch (...) {
        failed[1] = std::current_exception();
      }
    }
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
    scanRows(seam, m, m + 1);
    for (const Scan* part : {&seam, &second}) {
      scan.bridge_row.insert(scan.bridge_row.end(), part->bridge_row.begin(), part->bridge_row.end());
      scan.bridge_x.insert(scan.bridge_x.end(), part->bridge_x.begin(), part->bridge_x.end());
      scan.bridge_type.insert(scan.bridge_type.end(), part->bridge_type.begin(), part->bridge_type.end());
      scan.checkerboards += part->checkerboards, scan.n_corners += part->n_corners;
      scan.n_hedges += part->n_hedges, scan.n_hcorners += part->n_hcorners;
    }
  } else {
    scanRows(scan, 1, static_cast<std::size_t>(H));
  }
  std::vector<std::int32_t>& bridge_row = scan.bridge_row;
  std::vector<std::int32_t>& bridge_x = scan.bridge_x;
  std::vector<std::uint8_t>& bridge_type = scan.bridge_type;
  const std::size_t checkerboards = scan.checkerboards, n_corners = scan.n_corners, n_hedges = scan.n_hedges,
                    n_hcorners = scan.n_hcorners;
  if (checkerboards)
    report.notes.push_back(std::to_string(checkerboards) +
                           " pixel corner(s) where two labels touch diagonally (a checkerboard): the smaller "
                           "label, or the cell over the background, is joined across the corner");

  // Cells: pieces sorted by label, then by their first pixel (row by row from y0).
  struct Piece {
    Label label;
    std::size_t first, pixels = 0;
  };
  HugePageVector<std::int32_t> piece_of_run(n_runs, -1);  // by root run, then by run
  std::vector<Piece> pieces;
  for (std::size_t r = 1; r + 1 < static_cast<std::size_t>(H); ++r)
    for (auto k = static_cast<std::size_t>(runs.off[r]); k < static_cast<std::size_t>(runs.off[r + 1]); ++k) {
      if (runs.label[k] == kOutside) continue;
      std::int32_t& piece = piece_of_run[static_cast<std::size_t>(uf.find(static_cast<std::int32_t>(k)))];
      if (piece < 0) {
        piece = static_cast<std::int32_t>(pieces.size());
        pieces.push_back({runs.label[k], pix(runs.x[k], static_cast<std::int64_t>(r))});
      }
      pieces[static_cast<std::size_t>(piece)].pixels += static_cast<std::size_t>(runEnd(k, r) - runs.x[k]);
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
  std::vector<std::int32_t> cell_of_piece(pieces.size());
  for (std::size_t c = 0; c < order.size(); ++c) cell_of_piece[order[c]] = static_cast<std::int32_t>(c);
  const std::size_t n_cells = pieces.size();
  // The cell of each run (-1 outside), in place: a piece's root is its first run, converted before the others.
  auto& cell = piece_of_run;
  for (std::size_t k = 0; k < n_runs; ++k) {
    if (runs.label[k] == kOutside) {
      cell[k] = -1;
      continue;
    }
    const auto root = static_cast<std::size_t>(uf.find(static_cast<std::int32_t>(k)));
    cell[k] = root == k ? cell_of_piece[static_cast<std::size_t>(cell[k])] : cell[root];
  }
  decltype(uf.parent)().swap(uf.parent);
  auto cellName = [&](std::int32_t c) {
    return c < 0 ? std::string("the background") : "label " + std::to_string(pieces[order[c]].label);
  };

  // Vertices and boundary edges. The pixel corners on a boundary (two at a bridged corner) are numbered as a
  // scan of every pixel edge would create them: the corners on a vertical pixel edge row by row (each vertical
  // edge creating its lower corner, then its upper one), then those inside straight horizontal stretches (row by
  // row). The graph made here holds only the corners where the boundary turns or branches, the bridged ones,
  // and the corner next to a bridged one along a straight stretch (a kink); each of its edges is a straight
  // stretch of pixel edges between two cells (a stack of vertical pixel edges, or a run of horizontal ones),
  // its inner corners on the segment between its ends. Vertical edges are numbered before horizontal ones,
  // each by its first pixel edge in the scan's order, and every vertex keeps its scan order as `key`: the
  // walls, the outlines and the simplification then see the pixel corners' graph with its straight stretches
  // drawn as one edge (simplifyWall visits the corners inside them).
  const std::size_t n_verts = n_corners + bridge_row.size() + n_hcorners;  // the pixel corners on a boundary
  const std::size_t n_vedges = runs.x.size() - static_cast<std::size_t>(H);  // the pixel edges, vertical
  const std::int64_t h_key = 2 * W * (H + 1);  // the keys of the corners inside horizontal stretches start here
  // The edge that follows each edge around each of its two cells: follow[e][0] leaves v, the end of e, along the
  // left cell of e (which runs u -> v); follow[e][1] leaves u along the right cell (v -> u); -1 if there is none.
  // At a vertex of two edges, the other edge. Both walks below (walls, outlines) read it instead of chasing a
  // vertex's edges. Made in the sweep, as each corner row's vertices get all their edges (no incidence table).
  // Per vertex: its number of edges, whether it is a junction (more or fewer than two edges, or two between
  // different cells), and for a junction its lowest edge (a vertical one), from which its others are found.
  // In the sweep, horizontal edge i is numbered -2 - i (and -1 is none); once every vertical edge is made, they
  // follow them: n_vertical + i. Their order among themselves and after the vertical ones is kept.
  //
  // The sweep runs over two blocks of corner rows at once, [1, m) and [m, H), joined after into the graph one
  // sweep makes (the same numbers). The second block starts from the vertical edges of pixel row m - 1, which
  // the first one makes: it refers to the j-th of them, and to its upper vertex, as kPlaceholder + j, and keeps
  // its writes to them (their vertices' degree, junction and lowest edge, the edges' follow and upper end) for
  // the join. Whether such a stack goes on into row m depends on rows m - 1, m and the bridged corners only (a
  // stack never goes on through a bridged corner), so the second block knows it; the join checks it.
  struct EdgeEnd {  // an edge at a vertex, as the sweep knows it (without reading the edge)
    std::int32_t e = -1, left = -1, right = -1;  // its number (-1: none), its cells
    bool at_v = false;                           // whether the vertex is its end v (else its start u)
  };
  struct Up {
    std::int32_t x, vertex, edge;  // vertex -1: the stack of `edge` goes on into the row above
    std::int32_t left, right;      // the edge's cells
  };
  struct Sweep {
    CornerPositions pos;
    // Written by push_back only.
    HugePageUninitializedVector<std::int64_t> key;
    HugePageUninitializedVector<BoundaryEdge> edges, h_edges;
    HugePageUninitializedVector<std::array<std::int32_t, 2>> follow, h_follow;
    HugePageUninitializedVector<std::uint8_t> degree;
    HugePageUninitializedVector<char> junction;
    HugePageUninitializedVector<std::int32_t> first_edge;
    std::size_t pixel_edges = 0;  // in the edges made, checked against the counts above
    std::vector<Up> up;           // after the sweep: the upper ends of its last pixel row's vertical edges
    // A second block's writes to the first block's vertices and edges (placeholders), made at the join.
    std::vector<std::array<std::int32_t, 4>> settled;  // vertex, degree, junction, lowest edge
    std::vector<std::array<std::int32_t, 3>> follows;  // edge, side, the edge that follows it there
    std::vector<std::array<std::int32_t, 2>> ends;     // edge, its end v
  };
  constexpr std::int32_t kPlaceholder = std::int32_t{1} << 30;
  auto placeholder = [](std::int32_t id) { return id >= kPlaceholder; };
  // The scan's order of a corner met by a vertical pixel edge of pixel row `row`: its lower or upper end.
  auto vKey = [&](std::int32_t row, std::int32_t x, int upper) { return (row * W + x) * 2 + upper; };
  // The index in the bridge lists of the first bridged corner at or after (row, x).
  auto bridgeFrom = [&](std::int32_t row) {
    return static_cast<std::size_t>(std::lower_bound(bridge_row.begin(), bridge_row.end(), row) - bridge_row.begin());
  };
  auto bridgeAt = [&](std::size_t& bp, std::int32_t row, std::int32_t x) -> int {
    while (bp < bridge_row.size() && (bridge_row[bp] < row || (bridge_row[bp] == row && bridge_x[bp] < x))) ++bp;
    return bp < bridge_row.size() && bridge_row[bp] == row && bridge_x[bp] == x ? bridge_type[bp] : 0;
  };
  constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
  // Corner rows [r0, r1) into s, from `up`, the upper ends of pixel row r0 - 1's vertical edges.
  auto sweepRows = [&](Sweep& s, std::int32_t r0, std::int32_t r1, std::vector<Up> up, std::size_t n_vertex_guess,
                       std::size_t n_vedge_guess, std::size_t n_hedge_guess) {
    s.pos.q.reserve(n_vertex_guess), s.key.reserve(n_vertex_guess);
    s.degree.reserve(n_vertex_guess), s.junction.reserve(n_vertex_guess), s.first_edge.reserve(n_vertex_guess);
    s.edges.reserve(n_vedge_guess + n_hedge_guess), s.h_edges.reserve(n_hedge_guess);
    s.follow.reserve(n_vedge_guess + n_hedge_guess), s.h_follow.reserve(n_hedge_guess);
    auto setFollow = [&](std::int32_t e, int side, std::int32_t f) {
      if (placeholder(e)) s.follows.push_back({e, side, f});
      else (e >= 0 ? s.follow[e] : s.h_follow[-2 - e])[side] = f;
    };
    // The first block's edges before this block's, vertical edges before horizontal ones.
    auto edgeOrder = [&](std::int32_t e) {
      return placeholder(e) ? std::int64_t{-1} : e >= 0 ? std::int64_t{e} : (std::int64_t{1} << 40) - 2 - e;
    };
    // Vertex vx's edges are `at`, all made: its degree, junction, and the follow at vx of each.
    auto settle = [&](std::int32_t vx, std::array<EdgeEnd, 4> at) {
      int d = 0;
      for (const EdgeEnd& g : at)
        if (g.e != -1) at[d++] = g;
      for (int i = 1; i < d; ++i)  // increasing, as an incidence table made edge by edge lists them
        for (int j = i; j > 0 && edgeOrder(at[j].e) < edgeOrder(at[j - 1].e); --j) std::swap(at[j], at[j - 1]);
      const bool is_junction = d != 2 || std::minmax(at[0].left, at[0].right) != std::minmax(at[1].left, at[1].right);
      if (placeholder(vx)) {
        s.settled.push_back({vx, d, is_junction, at[0].e});
      } else {
        const auto v = static_cast<std::size_t>(vx);
        s.degree[v] = static_cast<std::uint8_t>(d), s.junction[v] = is_junction, s.first_edge[v] = at[0].e;
      }
      for (int i = 0; i < d; ++i) {
        const int side = at[i].at_v ? 0 : 1;
        const std::int32_t ci = side == 0 ? at[i].left : at[i].right;
        std::int32_t f = -1;
        if (d == 2) {
          f = at[1 - i].e;
        } else {
          for (int j = 0; j < d && f < 0; ++j)
            if ((at[j].left == ci && !at[j].at_v) || (at[j].right == ci && at[j].at_v)) f = at[j].e;
        }
        setFollow(at[i].e, side, f);
      }
    };
    std::size_t bp_this = bridgeFrom(r0), bp_next = bp_this, bp_above = bp_this;  // into the bridge lists
    // The vertex at corner (ci, cj): at a bridged corner, `second` is the one on the side of the edges leaving
    // it up or left (type 1) or up or right (type 2), a quarter pixel off the corner.
    auto newVertex = [&](std::int32_t ci, std::int32_t cj, int type, bool second, std::int64_t k) {
      constexpr std::uint32_t sp = 4 * kSplit;  // in quarter pixels
      const std::uint32_t x = 4 * static_cast<std::uint32_t>(ci), y = 4 * static_cast<std::uint32_t>(cj);
      if (type == 1) s.pos.q.push_back(second ? std::array{x - sp, y + sp} : std::array{x + sp, y - sp});
      else if (type == 2) s.pos.q.push_back(second ? std::array{x + sp, y + sp} : std::array{x - sp, y - sp});
      else s.pos.q.push_back({x, y});
      s.key.push_back(k);
      s.degree.push_back(0), s.junction.push_back(0), s.first_edge.push_back(-1);
      return static_cast<std::int32_t>(s.pos.size() - 1);
    };
    struct Corner {
      std::int32_t x, v0, v1;  // v1: the second vertex of a bridged corner; v0 -1: inside a vertical stack
      int type;
      EdgeEnd down{}, up{}, left{}, right{};  // its edges
    };
    std::vector<Corner> corners;  // of corner row cj: those on a vertical edge, by x
    std::vector<Up> next_up;      // `up` for the next row
    for (std::int32_t cj = r0; cj < r1; ++cj) {
      // The vertical edges of pixel row cj (none in the padding row H - 1).
      corners.clear(), next_up.clear();
      std::size_t p = 0, k = static_cast<std::size_t>(runs.off[cj]) + 1;
      const auto k_end = static_cast<std::size_t>(runs.off[cj + 1]);
      // Row cj + 1's label changes, to tell whether a stack goes on.
      std::size_t ka = 0, ka_end = 0;
      if (cj + 1 < static_cast<std::int32_t>(H))
        ka = static_cast<std::size_t>(runs.off[cj + 1]) + 1, ka_end = static_cast<std::size_t>(runs.off[cj + 2]);
      while (p < up.size() || k < k_end) {
        const std::int32_t xa = p < up.size() ? up[p].x : kNone, xb = k < k_end ? runs.x[k] : kNone;
        if (xa < xb) {
          corners.push_back({xa, up[p].vertex, -1, 0, {up[p].edge, up[p].left, up[p].right, true}});
          ++p;
          continue;
        }
        const std::int32_t left = cell[k - 1], right = cell[k];
        const int type = bridgeAt(bp_this, cj, xb);
        std::int32_t v0 = -1, v1 = -1, e;
        EdgeEnd down{};
        bool starts = true;
        if (xa == xb && up[p].vertex < 0) {  // the stack below goes on: its corner here is no vertex
          e = up[p++].edge, starts = false;
        } else {
          std::int32_t lower;
          if (xa == xb) {
            down = {up[p].edge, up[p].left, up[p].right, true}, v0 = up[p++].vertex;
            lower = type ? (v1 = newVertex(xb, cj, type, true, vKey(cj, xb, 0))) : v0;
          } else {
            lower = v0 = newVertex(xb, cj, 0, false, vKey(cj, xb, 0));
          }
          e = static_cast<std::int32_t>(s.edges.size());
          s.edges.push_back({lower, -1, left, right}), s.follow.push_back({-1, -1});
        }
        ++s.pixel_edges;
        // The stack goes on into row cj + 1 where that row has a vertical edge at xb between the same cells (no
        // corner between them is bridged), unless a bridged corner lies just below (a stack starting at one) or
        // two corners up: the corner next to a bridged one is a vertex.
        while (ka < ka_end && runs.x[ka] < xb) ++ka;
        const int type_up = bridgeAt(bp_next, cj + 1, xb);
        const bool goes_on = ka < ka_end && runs.x[ka] == xb && cell[ka - 1] == left && cell[ka] == right &&
                             !(starts && type) && !bridgeAt(bp_above, cj + 2, xb);
        if (goes_on) {
          next_up.push_back({xb, -1, e, left, right});
        } else {
          const std::int32_t upper = newVertex(xb, cj + 1, type_up, false, vKey(cj, xb, 1));
          if (placeholder(e)) s.ends.push_back({e, upper});
          else s.edges[static_cast<std::size_t>(e)].v = upper;
          next_up.push_back({xb, upper, e, left, right});
        }
        corners.push_back({xb, v0, v1, type, down, {starts ? e : -1, left, right, false}});
        ++k;
      }
      std::swap(up, next_up);
      // The horizontal edges along corner row cj, between pixel rows cj - 1 (below) and cj (above): each
      // stretch [s, e) starts and ends at a corner on a vertical edge, corners[q - 1] and corners[q]; a bridged
      // end makes the corner next to it a vertex (kink).
      std::size_t q = 0;
      sideBySide(static_cast<std::size_t>(cj) - 1, static_cast<std::size_t>(cj),
                 [&](std::size_t kb, std::size_t kc, std::int32_t xs, std::int32_t xe, bool, bool) {
                   const std::int32_t below = cell[kb], above = cell[kc];
                   if (below != above) {
                     Corner &cs = corners[q - 1], &ce = corners[q];
                     std::int32_t u = cs.type == 2 ? cs.v1 : cs.v0;  // leaving right: type 2's second vertex
                     const std::int32_t v = ce.type == 1 ? ce.v1 : ce.v0;  // leaving left: type 1's second vertex
                     std::int32_t last = -1;  // the stretch's edge made last
                     auto addEdge = [&](std::int32_t to) {
                       const std::int32_t id = -2 - static_cast<std::int32_t>(s.h_edges.size());
                       s.h_edges.push_back({u, to, above, below}), s.h_follow.push_back({-1, -1});
                       if (last == -1) cs.right = {id, above, below, false};
                       else setFollow(last, 0, id), setFollow(id, 1, last);  // at the kink between them
                       last = id;
                     };
                     auto kink = [&](std::int32_t ci) {
                       const std::int32_t kv = newVertex(ci, cj, 0, false, h_key + cj * W + ci);
                       s.degree[static_cast<std::size_t>(kv)] = 2;  // two edges between the same cells
                       addEdge(kv);
                       u = kv;
                     };
                     if (cs.type && xe - xs >= 2) kink(xs + 1);
                     if (ce.type && xe - xs >= 2 && !(cs.type && xe - xs == 2)) kink(xe - 1);
                     addEdge(v);
                     ce.left = {last, above, below, true};
                     s.pixel_edges += static_cast<std::size_t>(xe - xs);
                   }
                   q += xe < width;
                 });
      // The corners of row cj now have all their edges: at a bridged corner, the first vertex has the edges
      // leaving it down and right (type 1) or down and left (type 2), the second the others.
      for (const Corner& c : corners) {
        if (c.v0 < 0) continue;
        if (c.type == 0) settle(c.v0, {c.down, c.up, c.left, c.right});
        else if (c.type == 1) settle(c.v0, {c.down, c.right, {}, {}}), settle(c.v1, {c.up, c.left, {}, {}});
        else settle(c.v0, {c.down, c.left, {}, {}}), settle(c.v1, {c.up, c.right, {}, {}});
      }
    }
    s.up = std::move(up);
  };
  // The upper ends of pixel row r's vertical edges as placeholders: what the sweep of row r leaves for row r + 1.
  auto placeholdersAfter = [&](std::int32_t r) {
    std::vector<Up> out;
    std::size_t ka = static_cast<std::size_t>(runs.off[r + 1]) + 1;
    const auto ka_end = static_cast<std::size_t>(runs.off[r + 2]);
    std::size_t bp = bridgeFrom(r), bp_above = bridgeFrom(r + 2);
    for (auto k = static_cast<std::size_t>(runs.off[r]) + 1; k < static_cast<std::size_t>(runs.off[r + 1]); ++k) {
      const std::int32_t xb = runs.x[k], left = cell[k - 1], right = cell[k];
      while (ka < ka_end && runs.x[ka] < xb) ++ka;
      const bool goes_on = ka < ka_end && runs.x[ka] == xb && cell[ka - 1] == left && cell[ka] == right &&
                           !bridgeAt(bp, r, xb) && !bridgeAt(bp_above, r + 2, xb);
      const auto id = kPlaceholder + static_cast<std::int32_t>(out.size());
      out.push_back({xb, goes_on ? -1 : id, id, left, right});
    }
    return out;
  };
  Sweep graph;  // the first block's, then the whole graph
  const std::size_t n_vertex_guess = n_corners + 3 * bridge_row.size();
  // Two blocks of about as many runs each; one for a small image (and where the placeholders could not be told
  // from numbers).
  std::int32_t split = static_cast<std::int32_t>(H);
  if (H >= 8 && n_verts + n_vedges + n_hedges < static_cast<std::size_t>(kPlaceholder)) {
    const auto half = static_cast<std::int32_t>(runs.x.size() / 2);
    split = static_cast<std::int32_t>(std::upper_bound(runs.off.begin(), runs.off.end(), half) - runs.off.begin());
    split = std::clamp(split, std::int32_t{3}, static_cast<std::int32_t>(H) - 2);
  }
  if (split == static_cast<std::int32_t>(H)) {
    sweepRows(graph, 1, split, {}, n_vertex_guess, n_vedges, n_hedges);
  } else {
    Sweep second;
    // The second block's share of the graph, with room to spare (its arrays are copied after the first's).
    const double share = static_cast<double>(runs.x.size() - static_cast<std::size_t>(runs.off[split])) /
                         static_cast<double>(runs.x.size());
    auto part = [&](std::size_t n) { return static_cast<std::size_t>(static_cast<double>(n) * share * 1.25) + 64; };
    std::exception_ptr failed[2];  // (an exception must not leave a section: out of memory, say)
#pragma omp parallel sections num_threads(std::min(2, omp_get_max_threads()))
    {
#pragma omp section
      try {
        sweepRows(graph, 1, split, {}, n_vertex_guess, n_vedges, n_hedges);
      } catch (...) {
        failed[0] = std::current_exception();
      }
#pragma omp section
      try {
        sweepRows(second, split, static_cast<std::int32_t>(H), placeholdersAfter(split - 1), part(n_vertex_guess),
                  part(n_vedges), part(n_hedges));
      } catch (...) {
        failed[1] = std::current_exception();
      }
    }
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
    // The join: the second block's vertices and edges numbered after the first's, its placeholders replaced by
    // the first block's vertices and edges they stand for.
    const std::vector<Up>& ends = graph.up;
    const std::vector<Up> expected = placeholdersAfter(split - 1);
    bool same = ends.size() == expected.size();
    for (std::size_t j = 0; same && j < ends.size(); ++j)
      same = ends[j].x == expected[j].x && ends[j].left == expected[j].left && ends[j].right == expected[j].right &&
             (ends[j].vertex < 0) == (expected[j].vertex < 0);
    if (!same) throw InputError(file + ": the sweep's two blocks do not meet (an internal error)");
    const auto nv0 = static_cast<std::int32_t>(graph.pos.size()), ne0 = static_cast<std::int32_t>(graph.edges.size()),
               nh0 = static_cast<std::int32_t>(graph.h_edges.size());
    auto vertexOf = [&](std::int32_t v) { return v < 0 ? v : placeholder(v) ? ends[v - kPlaceholder].vertex : nv0 + v; };
    auto edgeOf = [&](std::int32_t e) {
      return e == -1 ? e : placeholder(e) ? ends[e - kPlaceholder].edge : e >= 0 ? ne0 + e : e - nh0;
    };
    // Copied after the first block's items, on one thread: 4 ms at 4096^2, where a parallel loop waited up to
    // 100 ms for its second thread on a loaded machine.
    for (std::size_t i = 0; i < second.pos.size(); ++i) {
      graph.pos.q.push_back(second.pos.q[i]), graph.key.push_back(second.key[i]);
      graph.degree.push_back(second.degree[i]), graph.junction.push_back(second.junction[i]);
      graph.first_edge.push_back(edgeOf(second.first_edge[i]));
    }
    for (std::size_t i = 0; i < second.edges.size(); ++i) {
      const BoundaryEdge& e = second.edges[i];
      graph.edges.push_back({vertexOf(e.u), vertexOf(e.v), e.left, e.right});
      graph.follow.push_back({edgeOf(second.follow[i][0]), edgeOf(second.follow[i][1])});
    }
    for (std::size_t i = 0; i < second.h_edges.size(); ++i) {
      const BoundaryEdge& e = second.h_edges[i];
      graph.h_edges.push_back({vertexOf(e.u), vertexOf(e.v), e.left, e.right});
      graph.h_follow.push_back({edgeOf(second.h_follow[i][0]), edgeOf(second.h_follow[i][1])});
    }
    for (const auto& [vx, d, is_junction, e] : second.settled) {
      const auto v = static_cast<std::size_t>(vertexOf(vx));
      graph.degree[v] = static_cast<std::uint8_t>(d), graph.junction[v] = static_cast<char>(is_junction);
      graph.first_edge[v] = edgeOf(e);
    }
    for (const auto& [e, side, f] : second.follows) graph.follow[static_cast<std::size_t>(edgeOf(e))][side] = edgeOf(f);
    for (const auto& [e, v] : second.ends) graph.edges[static_cast<std::size_t>(edgeOf(e))].v = vertexOf(v);
    graph.pixel_edges += second.pixel_edges;
  }
  CornerPositions& pos = graph.pos;
  auto& key = graph.key;
  auto& edges = graph.edges;
  auto& follow = graph.follow;
  auto& degree = graph.degree;
  auto& junction = graph.junction;
  auto& first_edge = graph.first_edge;
  const std::size_t pixel_edges = graph.pixel_edges;
  // The horizontal edges after the vertical ones, renumbered.
  const auto n_vertical = static_cast<std::int32_t>(edges.size());
  auto renumber = [&](const std::array<std::int32_t, 2>& f) {
    return std::array{f[0] < -1 ? n_vertical - 2 - f[0] : f[0], f[1] < -1 ? n_vertical - 2 - f[1] : f[1]};
  };
  for (auto& f : follow) f = renumber(f);
  for (const auto& f : graph.h_follow) follow.push_back(renumber(f));
  edges.insert(edges.end(), graph.h_edges.begin(), graph.h_edges.end());
  decltype(graph.h_edges)().swap(graph.h_edges);
  decltype(graph.h_follow)().swap(graph.h_follow);
  const std::size_t n_edges = edges.size(), nv = pos.size();
  if (pixel_edges != n_vedges + n_hedges || nv + pixel_edges - n_edges != n_verts)
    throw InputError(file + ": the pixel corners were miscounted (an internal error)");
  Runs().x.swap(runs.x);
  // Walls: chains of edges between junctions; a closed chain without one starts at its first vertex.
  // Outlines: per cell, its boundary edges chained the way the cell runs (counter-clockwise), from its first
  // edge (the edges of each cell in increasing order); the loop through a cell's first edge (each cell writes
  // its own outline); a cell whose loop misses some of its edges has several loops (a hole), reported below.
  // The two walks share no data: they run side by side, one thread each (the outlines' loop over blocks of cells
  // then runs on its section's thread; the result is the same for any number of threads).
  Walls walls;
  std::vector<std::array<std::int32_t, 2>> wall_cells;  // -1: none (the outside)
  // Per cell: the number of its edges (as offsets: cell c has cell_off[c + 1] - cell_off[c]) and its first one.
  std::vector<std::int32_t> cell_off, cell_first;
  Csr<std::int32_t> outlines;  // the vertices, in loop order
  std::vector<std::uint8_t> outline_fault(n_cells, 0);
  auto traceWalls = [&] {
    HugePageVector<std::int32_t> edge_wall(n_edges, -1);
    // At most one wall per edge, and a wall's chain holds its edges and one more vertex: room for all.
    walls.chain.reserve(2 * n_edges), walls.off.reserve(n_edges + 1), walls.tol.reserve(n_edges);
    walls.keep_one.reserve(n_edges), wall_cells.reserve(n_edges);
    auto walk = [&](std::int32_t start, std::int32_t e0) {
      const auto wi = static_cast<std::int32_t>(walls.size());
      walls.chain.push_back(start);
      std::int32_t v = start, e = e0;
      for (;;) {
        edge_wall[e] = wi;
        const bool forward = edges[e].u == v;  // arriving at v, the end of e: follow[e][0] is the other edge there
        v = forward ? edges[e].v : edges[e].u;
        walls.chain.push_back(v);
        if (junction[v]) break;
        e = follow[e][forward ? 0 : 1];
      }
      walls.off.push_back(static_cast<std::int32_t>(walls.chain.size()));
      walls.tol.push_back(o.simplify);
      walls.keep_one.push_back(0);
      wall_cells.push_back({edges[e0].left, edges[e0].right});
    };
    // From each junction, in order, along each of its edges in increasing order. Its edges are found from its
    // lowest one by turning around it: the edge that follows an edge at a vertex, around the cell on one side,
    // is the next one around the vertex, and its other cell leads on.
    for (std::size_t v = 0; v < nv; ++v) {
      if (!junction[v]) continue;
      const auto vx = static_cast<std::int32_t>(v);
      const int d = degree[v];
      std::array<std::int32_t, 4> at{first_edge[v], -1, -1, -1};
      for (int k = 1; k < d; ++k) {
        const std::int32_t g = at[k - 1];
        at[k] = follow[g][edges[g].v == vx ? 0 : 1];
        if (at[k] < 0 || std::find(at.begin(), at.begin() + k, at[k]) != at.begin() + k)
          throw InputError(file + ": the walls around a junction were misread (an internal error)");
      }
      for (int i = 1; i < d; ++i)
        for (int j = i; j > 0 && at[j] < at[j - 1]; --j) std::swap(at[j], at[j - 1]);
      for (int k = 0; k < d; ++k)
        if (edge_wall[at[k]] < 0) walk(vx, at[k]);
    }
    for (std::size_t e = 0; e < n_edges; ++e)
      if (edge_wall[e] < 0) {
        junction[edges[e].u] = 1;
        walk(edges[e].u, static_cast<std::int32_t>(e));
      }
    decltype(edge_wall)().swap(edge_wall);
  };
  auto traceOutlines = [&] {
    cell_off.assign(n_cells + 1, 0), cell_first.assign(n_cells, -1);
    for (std::size_t e = 0; e < n_edges; ++e)
      for (const std::int32_t c : {edges[e].left, edges[e].right})
        if (c >= 0) {
          const auto ci = static_cast<std::size_t>(c);
          ++cell_off[ci + 1];
          if (cell_first[ci] < 0) cell_first[ci] = static_cast<std::int32_t>(e);
        }
    std::partial_sum(cell_off.begin(), cell_off.end(), cell_off.begin());
    outlines.off = cell_off;
    outlines.items.resize(static_cast<std::size_t>(cell_off.back()));
    // Each step of a walk waits for a load from memory (the edges are far apart): a block of cells is walked
    // kLanes at a time, one step of each in turn, so that their loads overlap. Each cell's walk is its own.
    {
      constexpr std::size_t kBlock = 512;
      constexpr int kLanes = 8;
      const auto n_blocks = static_cast<std::ptrdiff_t>((n_cells + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(dynamic, 1)
      for (std::ptrdiff_t blk = 0; blk < n_blocks; ++blk) {
        struct Lane {
          std::int32_t c = -1, begin = 0, count = 0, e0 = 0, e = 0, k = 0;
        };
        std::array<Lane, kLanes> lanes;
        std::size_t c_next = static_cast<std::size_t>(blk) * kBlock;
        const std::size_t c_end = std::min(n_cells, c_next + kBlock);
        auto start = [&](Lane& l) {
          if (c_next == c_end) return false;
          const std::size_t c = c_next++;
          l.c = static_cast<std::int32_t>(c), l.begin = cell_off[c], l.count = cell_off[c + 1] - l.begin;
          l.e = l.e0 = cell_first[c], l.k = 0;
          return true;
        };
        int active = 0;
        for (Lane& l : lanes) active += start(l);
        while (active > 0)
          for (Lane& l : lanes) {
            if (l.c < 0) continue;
            // The cell's edge leaving each vertex: one at most, as pinched corners are bridged.
            const bool left = edges[l.e].left == l.c;
            outlines.items[static_cast<std::size_t>(l.begin + l.k++)] = left ? edges[l.e].u : edges[l.e].v;
            l.e = follow[l.e][left ? 0 : 1];
            if (l.e >= 0 && l.e != l.e0 && l.k < l.count) continue;
            outline_fault[static_cast<std::size_t>(l.c)] = l.e != l.e0 || l.k > l.count ? 2 : l.k < l.count ? 1 : 0;
            if (!start(l)) l.c = -1, --active;
          }
      }
    }
  };
  {
    std::exception_ptr failed[2];  // (an exception must not leave a section: out of memory, say)
#pragma omp parallel sections num_threads(std::min(2, omp_get_max_threads()))
    {
#pragma omp section
      try {
        traceWalls();
      } catch (...) {
        failed[0] = std::current_exception();
      }
#pragma omp section
      try {
        traceOutlines();
      } catch (...) {
        failed[1] = std::current_exception();
      }
    }
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
  }
  const std::size_t n_walls = walls.size();
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (!outline_fault[c]) continue;
    // Every loop of the cell, for the message.
    const auto ci = static_cast<std::int32_t>(c);
    // Every vertex's edges (the sweep keeps none): for the message only.
    std::vector<std::array<std::int32_t, 4>> incident(nv);
    std::fill(degree.begin(), degree.end(), 0);
    for (std::size_t e = 0; e < n_edges; ++e)
      for (const std::int32_t v : {edges[e].u, edges[e].v}) incident[v][degree[v]++] = static_cast<std::int32_t>(e);
    auto side = [&](std::int32_t e) -> std::uint8_t { return edges[e].left == ci ? 1 : 2; };
    auto from = [&](std::int32_t e) { return edges[e].left == ci ? edges[e].u : edges[e].v; };
    auto to = [&](std::int32_t e) { return edges[e].left == ci ? edges[e].v : edges[e].u; };
    auto out = [&](std::int32_t v) {
      for (int k = 0; k < degree[v]; ++k) {
        const std::int32_t e = incident[v][k];
        if ((edges[e].left == ci && edges[e].u == v) || (edges[e].right == ci && edges[e].v == v)) return e;
      }
      throw InputError(file + ": " + cellName(ci) + ": its outline is not closed (an internal error)");
    };
    std::map<std::int32_t, std::uint8_t> edge_used;  // 1: walked by its left cell, 2: by its right one
    std::vector<std::vector<std::int32_t>> loops;
    for (std::size_t k = 0; k < n_edges; ++k) {  // the cell's edges, in increasing order
      const auto e0 = static_cast<std::int32_t>(k);
      if (edges[k].left != ci && edges[k].right != ci) continue;
      if (edge_used[e0] & side(e0)) continue;
      loops.emplace_back();
      for (std::int32_t e = e0; !(edge_used[e] & side(e)); e = out(to(e))) {
        edge_used[e] |= side(e);
        loops.back().push_back(e);
      }
    }
    if (loops.size() < 2)
      throw InputError(file + ": " + cellName(ci) + ": its outline is not closed (an internal error)");
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
  // A cell's outline starts, as in the graph of every pixel corner, at the upper end of its first pixel edge
  // (the lowest of its left side). Where the cell's first edge is a longer stack, that corner lies inside it,
  // just above the stack's lower end, which the walk met second: the outline then starts at the lower end, and
  // the corner is the last inside its closing edge (`rotated`).
  std::vector<char> rotated(n_cells, 0);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t cc = 0; cc < static_cast<std::ptrdiff_t>(n_cells); ++cc) {
    const auto c = static_cast<std::size_t>(cc);
    const auto& first = edges[static_cast<std::size_t>(cell_first[c])];
    if (pixelLength(pos[first.u], pos[first.v]) < 2) continue;
    rotated[c] = 1;
    const auto begin = outlines.items.begin();
    std::rotate(begin + cell_off[c], begin + cell_off[c] + 1, begin + cell_off[c + 1]);
  }
  std::vector<std::int32_t>().swap(cell_first);
  decltype(graph.follow)().swap(follow);

  // Simplify, then make sure no two walls cross and no cell flattens.
  HugePageVector<char> keep(junction.begin(), junction.end());
  // Not read from here on: freed now, so that the arrays made below can take their memory.
  auto drop = [](auto& v) { std::remove_cvref_t<decltype(v)>().swap(v); };
  drop(edges), drop(first_edge), drop(degree), drop(junction), drop(piece_of_run);
  drop(runs.off), drop(runs.label), drop(bridge_row), drop(bridge_x), drop(bridge_type);
  drop(cell_off);
  // The pixel corners kept inside edges, by wall (few or none: see simplifyEdge); has_inner[w]: wall w has some.
  std::map<std::int32_t, std::vector<InnerCorner>> wall_inner;
  std::vector<char> has_inner(n_walls, 0);
  auto simplify = [&](std::size_t wi, std::vector<InnerCorner>& inner) {
    simplifyWall(walls, wi, pos, keep, inner);
    if (inner.empty() && !has_inner[wi]) return;
#pragma omp critical(label_image_2d_inner)
    {
      if (inner.empty()) wall_inner.erase(static_cast<std::int32_t>(wi));
      else wall_inner[static_cast<std::int32_t>(wi)] = inner;
    }
    has_inner[wi] = !inner.empty();
  };
  // In parallel: a wall sets `keep` of its inner vertices only, and its own entry of has_inner.
#pragma omp parallel
  {
    std::vector<InnerCorner> inner;
#pragma omp for schedule(dynamic, 1024)
    for (std::ptrdiff_t wi = 0; wi < static_cast<std::ptrdiff_t>(n_walls); ++wi)
      simplify(static_cast<std::size_t>(wi), inner);
  }
  {
    // Of the walls with the same two ends, one at most may become a straight segment (they would collapse):
    // the first of them, in wall order.
    std::vector<std::pair<std::uint64_t, std::int32_t>> straight;  // ends, wall
    for (std::size_t wi = 0; wi < n_walls; ++wi) {
      const auto b = static_cast<std::size_t>(walls.off[wi]), last = static_cast<std::size_t>(walls.off[wi + 1]) - 1;
      if (walls.chain[b] == walls.chain[last] ||
          (last - b < 2 && pixelLength(pos[walls.chain[b]], pos[walls.chain[last]]) < 2))
        continue;  // a loop, or a single pixel edge
      bool inner = has_inner[wi] != 0;
      for (std::size_t k = b + 1; k < last && !inner; ++k) inner = keep[walls.chain[k]];
      if (inner) continue;
      const auto [lo, hi] = std::minmax(walls.chain[b], walls.chain[last]);
      straight.emplace_back((static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint32_t>(hi),
                            static_cast<std::int32_t>(wi));
    }
    std::sort(straight.begin(), straight.end());
    std::vector<InnerCorner> inner;
    for (std::size_t k = 1; k < straight.size(); ++k)
      if (straight[k].first == straight[k - 1].first) {
        const auto wi = static_cast<std::size_t>(straight[k].second);
        walls.keep_one[wi] = 1;
        simplify(wi, inner);
      }
  }
  // With simplify 0 every wall is its pixel staircase but for the corners it passes straight through: the
  // walls neither cross nor touch, and no cell flattens (tests/io compares both ways on random images).
  if (o.simplify > 0) {
    Csr<std::int32_t> cell_walls;
    cell_walls.off.assign(n_cells + 1, 0);
    for (const auto& cs : wall_cells)
      for (const std::int32_t c : cs)
        if (c >= 0) ++cell_walls.off[static_cast<std::size_t>(c) + 1];
    std::partial_sum(cell_walls.off.begin(), cell_walls.off.end(), cell_walls.off.begin());
    cell_walls.items.resize(static_cast<std::size_t>(cell_walls.off.back()));
    {
      std::vector<std::int32_t> fill(cell_walls.off.begin(), cell_walls.off.end() - 1);
      for (std::size_t wi = 0; wi < n_walls; ++wi)
        for (const std::int32_t c : wall_cells[wi])
          if (c >= 0) cell_walls.items[fill[c]++] = static_cast<std::int32_t>(wi);
    }
    // The crossing test: every pair of segments in one bucket of a grid of kBucket x kBucket pixels whose
    // bounding boxes meet is tested, unless neither wall changed since the last round (a pair that did not
    // conflict then does not now; a wall that conflicted was redone). Two segments that conflict share a point,
    // so a bucket and their boxes hold it: the size of the buckets changes what is tested, not the result.
    // Cells are checked again when one of their walls changed.
    constexpr std::int64_t kBucket = 8;
    const auto nbx = static_cast<std::size_t>(w / kBucket + 2), nby = static_cast<std::size_t>(h / kBucket + 2);
    struct Box {
      float x0, y0, x1, y1;  // quarter pixels: exact
    };
    std::vector<Box> boxes;
    std::vector<char> dirty(n_walls, 1), redo(n_walls, 0);
    std::vector<Segment> segs;
    std::vector<std::int32_t> bucket_off, bucket_segs;
    std::vector<char> active;  // after the first round: the buckets to test
    for (int round = 0;; ++round) {
      std::fill(redo.begin(), redo.end(), 0);
      segs.clear();
      for (std::size_t wi = 0; wi < n_walls; ++wi) {
        const auto b = static_cast<std::size_t>(walls.off[wi]), e = static_cast<std::size_t>(walls.off[wi + 1]);
        std::int32_t prev = walls.chain[b];
        for (std::size_t k = b + 1; k < e; ++k) {
          const std::int32_t v = walls.chain[k];
          if (!keep[v]) continue;
          segs.push_back({prev, v, static_cast<std::int32_t>(wi)});
          prev = v;
        }
      }
      boxes.resize(segs.size());
      for (std::size_t k = 0; k < segs.size(); ++k) {
        const Vec3 &p = pos[segs[k].a], &q = pos[segs[k].b];
        boxes[k] = {static_cast<float>(std::min(p.x(), q.x())), static_cast<float>(std::min(p.y(), q.y())),
                    static_cast<float>(std::max(p.x(), q.x())), static_cast<float>(std::max(p.y(), q.y()))};
      }
      // The buckets a segment's bounding box meets (x + 1 > 0: the cast is the floor).
      auto forBuckets = [&](std::size_t k, auto&& f) {
        const Box& bx = boxes[k];
        constexpr float size = kBucket;
        const auto bx0 = static_cast<std::size_t>((bx.x0 + 1) / size);
        const auto bx1 = static_cast<std::size_t>((bx.x1 + 1) / size);
        const auto by0 = static_cast<std::size_t>((bx.y0 + 1) / size);
        const auto by1 = static_cast<std::size_t>((bx.y1 + 1) / size);
        for (std::size_t by = by0; by <= by1; ++by)
          for (std::size_t x = bx0; x <= bx1; ++x) f(by * nbx + x);
      };
      // Only the buckets a changed wall's segment passes through are tested (a pair of unchanged walls is
      // skipped anyway); in the first round every wall has changed.
      if (round > 0) {
        active.assign(nbx * nby, 0);
        for (std::size_t k = 0; k < segs.size(); ++k)
          if (dirty[segs[k].wall]) forBuckets(k, [&](std::size_t b) { active[b] = 1; });
      }
      auto used = [&](std::size_t b) { return round == 0 || active[b]; };
      bucket_off.assign(nbx * nby + 1, 0);
      for (std::size_t k = 0; k < segs.size(); ++k) forBuckets(k, [&](std::size_t b) { bucket_off[b + 1] += used(b); });
      std::partial_sum(bucket_off.begin(), bucket_off.end(), bucket_off.begin());
      bucket_segs.resize(static_cast<std::size_t>(bucket_off.back()));
      {
        std::vector<std::int32_t> fill(bucket_off.begin(), bucket_off.end() - 1);
        for (std::size_t k = 0; k < segs.size(); ++k)
          forBuckets(k, [&](std::size_t b) {
            if (used(b)) bucket_segs[static_cast<std::size_t>(fill[b]++)] = static_cast<std::int32_t>(k);
          });
      }
      // Buckets and cells in parallel: `redo` only ever becomes 1.
      auto setRedo = [&](std::int32_t wi) {
        std::atomic_ref<char>(redo[static_cast<std::size_t>(wi)]).store(1, std::memory_order_relaxed);
      };
#pragma omp parallel for schedule(dynamic, 4096)
      for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t>(nbx * nby); ++b)
        for (auto i = bucket_off[b]; i < bucket_off[b + 1]; ++i)
          for (auto j = i + 1; j < bucket_off[b + 1]; ++j) {
            const Box &bs = boxes[bucket_segs[i]], &bt = boxes[bucket_segs[j]];
            if (bs.x0 > bt.x1 || bt.x0 > bs.x1 || bs.y0 > bt.y1 || bt.y0 > bs.y1) continue;
            const Segment &s = segs[bucket_segs[i]], &t = segs[bucket_segs[j]];
            if ((dirty[s.wall] || dirty[t.wall]) && conflict(s, t, pos)) setRedo(s.wall), setRedo(t.wall);
          }
#pragma omp parallel for schedule(dynamic, 1024)
      for (std::ptrdiff_t cc = 0; cc < static_cast<std::ptrdiff_t>(n_cells); ++cc) {
        const auto c = static_cast<std::size_t>(cc);
        bool changed = false;
        for (auto k = cell_walls.off[c]; k < cell_walls.off[c + 1] && !changed; ++k)
          changed = dirty[cell_walls.items[k]];
        if (!changed) continue;
        double area = 0;
        std::size_t corners_kept = 0;
        std::int32_t first = -1, prev = -1;
        for (auto k = outlines.off[c]; k < outlines.off[c + 1]; ++k) {
          const std::int32_t v = outlines.items[k];
          if (!keep[v]) continue;
          ++corners_kept;
          if (first < 0) first = v;
          else area += pos[prev].x() * pos[v].y() - pos[v].x() * pos[prev].y();
          prev = v;
        }
        area += pos[prev].x() * pos[first].y() - pos[first].x() * pos[prev].y();
        if (corners_kept < 3 || area <= 0)
          for (auto k = cell_walls.off[c]; k < cell_walls.off[c + 1]; ++k) setRedo(cell_walls.items[k]);
      }
      if (std::find(redo.begin(), redo.end(), 1) == redo.end()) break;
#pragma omp parallel
      {
        std::vector<InnerCorner> inner;
#pragma omp for schedule(dynamic, 1024)
        for (std::ptrdiff_t wi = 0; wi < static_cast<std::ptrdiff_t>(n_walls); ++wi) {
          if (!redo[wi] || walls.tol[wi] < 0) continue;
          walls.tol[wi] = walls.tol[wi] > 1.0 / 64 ? walls.tol[wi] / 2 : -1;
          simplify(static_cast<std::size_t>(wi), inner);
        }
      }
      dirty.swap(redo);
      if (round > 64) throw InputError(file + ": simplifying the walls did not converge (an internal error)");
    }
  }
  drop(walls.chain), drop(walls.off), drop(walls.tol), drop(walls.keep_one), drop(wall_cells);
  drop(has_inner);
  // Positions: corner (x, y) in pixels is the edge of pixel x, at origin + (x - 1/2) * spacing, in the scan's
  // order of the pixel corners (`key`): the kept vertices met by a vertical pixel edge, in the graph's order,
  // then those inside horizontal stretches, and the kept corners inside edges (few or none) merged in by key.
  // In parallel over fixed blocks of vertices, then of cells (the same result for any number of threads).
  auto place = [&](const Vec3& p) {
    const double x = img.origin[0] + (p.x() + static_cast<double>(x0) - 0.5) * sx;
    const double y = img.origin[1] + (p.y() + static_cast<double>(y0) - 0.5) * sy;
    return Vec3(o.scale * x, o.scale * y, 0.0);
  };
  HugePageUninitializedVector<std::int32_t> new_index(nv);  // written and read for kept vertices only
  std::vector<Vec3> positions;
  std::vector<Index> polygon_off(n_cells + 1, 0);
  HugePageUninitializedVector<Index> polygon_vertices;
  if (wall_inner.empty()) {
    constexpr std::ptrdiff_t kBlocks = 64;
    std::vector<std::size_t> start_v(kBlocks + 1, 0), start_h(kBlocks + 1, 0);
    auto blockOf = [&](std::ptrdiff_t b) { return static_cast<std::size_t>(b) * nv / kBlocks; };
    // One parallel region (each worker's wait between regions costs CPU): counts, their sums, then the lists.
#pragma omp parallel
    {
#pragma omp for schedule(static) nowait
      for (std::ptrdiff_t b = 0; b < kBlocks; ++b) {
        std::size_t n_v = 0, n_h = 0;
        for (std::size_t v = blockOf(b); v < blockOf(b + 1); ++v)
          if (keep[v]) ++(key[v] < h_key ? n_v : n_h);
        start_v[static_cast<std::size_t>(b) + 1] = n_v, start_h[static_cast<std::size_t>(b) + 1] = n_h;
      }
#pragma omp for schedule(static)
      for (std::ptrdiff_t cc = 0; cc < static_cast<std::ptrdiff_t>(n_cells); ++cc) {
        const auto c = static_cast<std::size_t>(cc);
        Index n = 0;
        for (auto k = outlines.off[c]; k < outlines.off[c + 1]; ++k) n += keep[outlines.items[k]] != 0;
        polygon_off[c + 1] = n;
      }
#pragma omp single
      {
        std::partial_sum(start_v.begin(), start_v.end(), start_v.begin());
        start_h[0] = start_v.back();
        std::partial_sum(start_h.begin(), start_h.end(), start_h.begin());
        positions.resize(start_h.back());  // Vec3's default constructor writes nothing
        tessella::detail::adviseHugePages(positions.data(), positions.size() * sizeof(Vec3));
        std::partial_sum(polygon_off.begin(), polygon_off.end(), polygon_off.begin());
        polygon_vertices.resize(polygon_off.back());
      }
#pragma omp for schedule(static)
      for (std::ptrdiff_t b = 0; b < kBlocks; ++b) {
        std::size_t next_v = start_v[static_cast<std::size_t>(b)], next_h = start_h[static_cast<std::size_t>(b)];
        for (std::size_t v = blockOf(b); v < blockOf(b + 1); ++v)
          if (keep[v]) {
            std::size_t& next = key[v] < h_key ? next_v : next_h;
            new_index[v] = static_cast<std::int32_t>(next);
            positions[next++] = place(pos[v]);
          }
      }
#pragma omp for schedule(static)
      for (std::ptrdiff_t cc = 0; cc < static_cast<std::ptrdiff_t>(n_cells); ++cc) {
        const auto c = static_cast<std::size_t>(cc);
        Index next = polygon_off[c];
        for (auto k = outlines.off[c]; k < outlines.off[c + 1]; ++k)
          if (const std::int32_t v = outlines.items[k]; keep[v])
            polygon_vertices[next++] = static_cast<Index>(new_index[v]);
      }
    }
  } else {
    // Kept corners inside edges: ordered with the vertices by key, listed by edge for the outlines.
    std::vector<InnerCorner> inner;
    for (const auto& entry : wall_inner) inner.insert(inner.end(), entry.second.begin(), entry.second.end());
    auto innerPos = [&](const InnerCorner& ic) {
      const Vec3 &pa = pos[ic.a], &pb = pos[ic.b];
      const int n = pixelLength(pa, pb);
      const double ax = std::round(pa.x()), ay = std::round(pa.y());
      return Vec3(ax + ic.i * ((std::round(pb.x()) - ax) / n), ay + ic.i * ((std::round(pb.y()) - ay) / n), 0);
    };
    std::vector<std::pair<std::int64_t, std::int64_t>> by_key;  // key, vertex or -1 - the corner's index
    for (std::size_t v = 0; v < nv; ++v)
      if (keep[v]) by_key.emplace_back(key[v], static_cast<std::int64_t>(v));
    for (std::size_t k = 0; k < inner.size(); ++k) {
      const Vec3 p = innerPos(inner[k]);
      const auto ci = static_cast<std::int32_t>(std::lround(p.x())) + 1;
      const auto cj = static_cast<std::int32_t>(std::lround(p.y())) + 1;
      const bool vertical = std::round(pos[inner[k].a].x()) == std::round(pos[inner[k].b].x());
      by_key.emplace_back(vertical ? vKey(cj - 1, ci, 1) : h_key + cj * W + ci, -1 - static_cast<std::int64_t>(k));
    }
    std::sort(by_key.begin(), by_key.end());
    // (lower vertex, higher vertex) of an edge -> (pixels from the lower one, position index) of its kept corners
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::int32_t, std::int32_t>>> edge_inner;
    positions.resize(by_key.size());
    for (std::size_t n = 0; n < by_key.size(); ++n) {
      const std::int64_t ref = by_key[n].second;
      if (ref >= 0) {
        new_index[static_cast<std::size_t>(ref)] = static_cast<std::int32_t>(n);
        positions[n] = place(pos[static_cast<std::size_t>(ref)]);
        continue;
      }
      const InnerCorner& ic = inner[static_cast<std::size_t>(-1 - ref)];
      positions[n] = place(innerPos(ic));
      const std::int32_t len = pixelLength(pos[ic.a], pos[ic.b]);
      edge_inner[std::minmax(ic.a, ic.b)].emplace_back(ic.a < ic.b ? ic.i : len - ic.i, static_cast<std::int32_t>(n));
    }
    for (auto& entry : edge_inner) std::sort(entry.second.begin(), entry.second.end());
    for (std::size_t c = 0; c < n_cells; ++c) {
      const auto b = static_cast<std::size_t>(outlines.off[c]), m = static_cast<std::size_t>(outlines.off[c + 1]) - b;
      const std::size_t start = polygon_vertices.size();
      std::int64_t front = -1;  // of a rotated outline: the corner it starts at, inside its closing edge
      for (std::size_t k = 0; k < m; ++k) {
        const std::int32_t v = outlines.items[b + k], to = outlines.items[b + (k + 1) % m];
        if (keep[v]) polygon_vertices.push_back(static_cast<Index>(new_index[v]));
        const auto it = edge_inner.find(std::minmax(v, to));
        if (it == edge_inner.end()) continue;
        const std::int32_t len = pixelLength(pos[v], pos[to]);
        auto add = [&](const std::pair<std::int32_t, std::int32_t>& corner) {
          const std::int32_t from_to = v < to ? len - corner.first : corner.first;
          if (rotated[c] && k + 1 == m && from_to == 1) front = corner.second;
          else polygon_vertices.push_back(static_cast<Index>(corner.second));
        };
        if (v < to) std::for_each(it->second.begin(), it->second.end(), add);
        else std::for_each(it->second.rbegin(), it->second.rend(), add);
      }
      if (front >= 0)
        polygon_vertices.insert(polygon_vertices.begin() + static_cast<std::ptrdiff_t>(start),
                                static_cast<Index>(front));
      polygon_off[c + 1] = static_cast<Index>(polygon_vertices.size());
    }
  }
  drop(pos), drop(key), drop(new_index), drop(keep), drop(outlines.off), drop(outlines.items);
  const std::size_t n_positions = positions.size();
  report.file_vertices = 0;
  report.simplified_vertices = n_verts - n_positions;
  try {
    result.tissue = buildPolygonTissue(std::move(positions), polygon_off, polygon_vertices, Embedding::Planar);
  } catch (const Error& e) {
    throw InputError(file + ": the cells do not form a tissue: " + std::string(e.what()));
  }
  auto& label = result.tissue.cellProperties().add<std::int64_t>("label", 0);
  for (std::size_t c = 0; c < n_cells; ++c) label[CellId(static_cast<Index>(c))] = pieces[order[c]].label;
  report.notes.push_back(std::to_string(n_cells) + " cells, " + std::to_string(n_walls) + " walls; " +
                         std::to_string(n_positions) + " of " + std::to_string(n_verts) +
                         " boundary pixel corners kept (simplify " + formatNumber(o.simplify) + " px)");
  return result;
}

}  // namespace

ImportResult tissueFromLabelImage(const LabelImage& image, const ImportOptions& options) {
  return convertLabelImage(image, image.labels.data(), image.labels.size(), options, {}, nullptr);
}

ImportResult tissueFromLabelImage(LabelImage&& image, const ImportOptions& options) {
  return convertLabelImage(image, image.labels.data(), image.labels.size(), options,
                           [&] { std::vector<std::int64_t>().swap(image.labels); }, &image.labels);
}

namespace detail {

ImportResult tissueFromLabelPixels2d(const LabelImage& image, LabelPixels pixels, std::size_t count,
                                     const ImportOptions& options, const std::function<void()>& release) {
  if (image.dims[2] != 1)
    throw InputError("'" + image.name + "': a 3D image has no 2D import (an internal error)");
  return convertLabelImage(image, pixels, count, options, release, nullptr);
}

}  // namespace detail

}  // namespace tessella::io
