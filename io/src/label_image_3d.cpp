// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D label images as 3D tissues (docs/import.md, "3D label images"). On the
// voxel grid, padded by one layer of outside voxels: interfaces are the voxel
// faces between two labels, at least one of them a cell; junction lines are
// the voxel edges around which three or more labels meet; vertices are the
// voxel corners on a junction line where four or more labels meet or where
// junction lines branch. The background inside the image is one outside
// label, and the padding beyond each of the six image faces another, so a
// cell cut by the image border gets one flat wall per side it touches.
//
// First the labels are made well-composed (every label's voxels bound a
// 2-manifold surface): where one label's voxels touch only along an edge or
// at a corner, a neighbouring voxel takes that label, until none does. Then
// each wall (a patch of interface faces between one pair of labels, connected
// across voxel edges that are no junction) becomes one face whose boundary
// loop is its chain of junction polylines, each simplified by Douglas-Peucker
// with its ends fixed (shared by every wall along it). Walls whose polygons
// cross or fail the mesher's checks get their junction lines simplified less
// and smoothed more; a wall still failing is made of the triangles of its
// voxel interface (several faces between the same two cells), its lines put
// back on their voxel corners if even that fails. The cells go to the
// cell-complex core (cell_complex_core.hpp), which orients and checks them.

#include "label_image_3d.hpp"

#include <algorithm>
#include <atomic>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include <omp.h>

#include "cell_complex_core.hpp"
#include "labelled_surface.hpp"
#include "polyline_simplification.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::io::detail {

namespace {

constexpr std::int32_t kBackground = -1;  // outside inside the image; -2 - side beyond image side 0..5
constexpr std::size_t kMaxNotes = 20;
constexpr int kExtraSmoothing = 4;  // rounds of further smoothing for walls still crossing with every corner kept
// The staircase (simplify 0): passes of smoothing along every junction line, rounds of further smoothing of the
// lines of walls that fail the checks, then the largest Douglas-Peucker tolerance (voxels) tried on them.
constexpr int kStaircasePasses = 2;
constexpr int kStaircaseExtraSmoothing = 16;
constexpr double kStaircaseMaxTolerance = 2;
// Walls of several faces: the smallest corner of a face (degrees), and the sharpest fold between two faces
// (the cosine of the angle between their normals).
constexpr double kMinFaceAngle = 5;
constexpr double kMinFoldCosine = -0.5;
// A wall of one polygon with a corner under this (degrees; the two edges at the corner nearly along each other,
// a sliver or a spike) fails like a crossing one: the wall mesher's angle bound does not finish on it (corners of
// 0.0017 and 0.0007 degrees seen; one of 0.22 degrees in the 40-cell test tissue at 48^3, simplify 1, meshes).
constexpr double kMinPolygonAngle = 0.1;

bool isPadding(std::int32_t l) { return l < kBackground; }

std::string numberList(const std::vector<std::int64_t>& v) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + std::to_string(v[i]);
  return out;
}

// The padded voxel grid: voxel (i, j, k), 0 <= i < n[0] ..., at i + n[0] * (j + n[1] * k);
// corner (i, j, k) is the corner shared by voxels i - 1 and i along each axis, indexed the same way.
struct Grid {
  std::array<std::int64_t, 3> n;
  std::array<std::size_t, 3> stride;
  std::vector<std::int32_t> cell;
  Grid(std::int64_t w, std::int64_t h, std::int64_t d)
      : n{w, h, d}, stride{1, static_cast<std::size_t>(w), static_cast<std::size_t>(w * h)} {}
  std::size_t size() const { return stride[2] * static_cast<std::size_t>(n[2]); }
  std::size_t at(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>(i) + stride[1] * static_cast<std::size_t>(j) +
           stride[2] * static_cast<std::size_t>(k);
  }
  std::array<std::int64_t, 3> coords(std::size_t v) const {
    return {static_cast<std::int64_t>(v % stride[1]), static_cast<std::int64_t>((v / stride[1]) % n[1]),
            static_cast<std::int64_t>(v / stride[2])};
  }
  // The 8 voxels around corner c (bit 0: +x, 1: +y, 2: +z).
  std::size_t blockVoxel(std::size_t c, int bit) const {
    return c - stride[0] - stride[1] - stride[2] + ((bit & 1) ? stride[0] : 0) + ((bit & 2) ? stride[1] : 0) +
           ((bit & 4) ? stride[2] : 0);
  }
  bool interiorCorner(std::size_t c) const {
    const auto p = coords(c);
    for (int a = 0; a < 3; ++a)
      if (p[a] < 1 || p[a] > n[a] - 1) return false;
    return true;
  }
};

// The defects of the 8 voxels around a corner (bit 0: +x, 1: +y, 2: +z)
// that keep a label's voxels from bounding a 2-manifold: each half of the
// block (the four voxels around an edge from the corner) where one label
// holds two diagonal voxels and not the other two; each label, and each
// label's complement, in several face-connected parts of the block.
int blockDefects(const std::array<std::int32_t, 8>& l) {
  int defects = 0;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b1 = 1 << ((a + 1) % 3), b2 = 1 << ((a + 2) % 3), s = side << a;
      const int q[4] = {s, s | b1, s | b1 | b2, s | b2};
      for (int r = 0; r < 2; ++r)
        defects += l[q[r]] == l[q[r + 2]] && l[q[r + 1]] != l[q[r]] && l[q[(r + 3) % 4]] != l[q[r]];
    }
  for (int b = 0; b < 8; ++b) {
    bool seen_before = false;
    for (int e = 0; e < b; ++e) seen_before = seen_before || l[e] == l[b];
    if (seen_before) continue;
    for (int complement = 0; complement < 2; ++complement) {
      unsigned mask = 0;
      for (int e = 0; e < 8; ++e)
        if ((l[e] == l[b]) != (complement == 1)) mask |= 1u << e;
      if (mask == 0) continue;
      unsigned part = mask & (~mask + 1), grown = 0;
      while (grown != part) {
        grown = part;
        for (int e = 0; e < 8; ++e)
          if (part & (1u << e))
            for (const int nb : {e ^ 1, e ^ 2, e ^ 4})
              if (mask & (1u << nb)) part |= 1u << nb;
      }
      defects += part != mask;
    }
  }
  return defects;
}

// Makes every label's voxels well-composed (no block defect anywhere): at a
// defect, of all the changes of one voxel of the block (never a padding
// voxel) to another label of the block, the one that removes the most
// defects from the 8 blocks around that voxel is made, so the total number
// of defects falls with every change. Returns the voxels changed; an
// InputError naming a voxel where no change helps.
std::size_t makeWellComposed(Grid& g, const std::string& name, const std::function<std::string(std::size_t)>& where,
                             const std::function<std::string(std::int32_t)>& labelName) {
  auto block = [&](std::size_t c) {
    std::array<std::int32_t, 8> l;
    for (int b = 0; b < 8; ++b) l[b] = g.cell[g.blockVoxel(c, b)];
    return l;
  };
  auto cornerOf = [&](std::size_t v, int b) {  // the corner of voxel v at the block bit b away
    return v + ((b & 1) ? g.stride[0] : 0) + ((b & 2) ? g.stride[1] : 0) + ((b & 4) ? g.stride[2] : 0);
  };
  // Defects in the blocks around voxel v (every corner of an interior voxel is an interior corner).
  auto around = [&](std::size_t v) {
    int n = 0;
    for (int b = 0; b < 8; ++b) n += blockDefects(block(cornerOf(v, b)));
    return n;
  };
  // The corners with a defect, in parallel over z layers, then in corner order.
  std::vector<std::vector<std::size_t>> layer_work(static_cast<std::size_t>(g.n[2]));
#pragma omp parallel for schedule(dynamic, 4)
  for (std::int64_t k = 1; k < g.n[2]; ++k)
    for (std::int64_t j = 1; j < g.n[1]; ++j)
      for (std::int64_t i = 1; i < g.n[0]; ++i) {
        const std::size_t c = g.at(i, j, k);
        const std::int32_t first = g.cell[g.blockVoxel(c, 0)];
        bool mixed = false;
        for (int b = 1; b < 8 && !mixed; ++b) mixed = g.cell[g.blockVoxel(c, b)] != first;
        if (mixed && blockDefects(block(c)) > 0) layer_work[static_cast<std::size_t>(k)].push_back(c);
      }
  std::vector<std::size_t> work;
  for (const auto& lw : layer_work) work.insert(work.end(), lw.begin(), lw.end());
  std::reverse(work.begin(), work.end());  // worked from the back: the first corner first
  std::size_t changed = 0;
  while (!work.empty()) {
    const std::size_t c = work.back();
    work.pop_back();
    const auto l = block(c);
    if (blockDefects(l) == 0) continue;
    // The change that removes the most defects; of equal ones, the voxel whose six face neighbours
    // most favour the new label over its old one (so no speck of a label is made).
    int best_gain = 0, best_agreement = 0;
    std::size_t best_voxel = 0;
    std::int32_t best_label = 0;
    for (int b = 0; b < 8; ++b) {
      const std::size_t v = g.blockVoxel(c, b);
      const std::int32_t old = l[b];
      if (isPadding(old)) continue;
      const int before = around(v);
      for (int e = 0; e < 8; ++e) {
        if (isPadding(l[e]) || l[e] == old) continue;
        bool tried = false;
        for (int f = 0; f < e; ++f) tried = tried || l[f] == l[e];
        if (tried) continue;
        g.cell[v] = l[e];
        const int gain = before - around(v);
        g.cell[v] = old;
        int agreement = 0;
        for (int a = 0; a < 3; ++a)
          for (const std::size_t nb : {v - g.stride[a], v + g.stride[a]})
            agreement += (g.cell[nb] == l[e]) - (g.cell[nb] == old);
        if (gain > best_gain || (gain == best_gain && gain > 0 && agreement > best_agreement))
          best_gain = gain, best_agreement = agreement, best_voxel = v, best_label = l[e];
      }
    }
    if (best_gain <= 0) {
      std::string labels;
      for (int b = 0; b < 8; ++b) {
        bool listed = false;
        for (int e = 0; e < b; ++e) listed = listed || l[e] == l[b];
        if (!listed) labels += (labels.empty() ? "" : ", ") + labelName(l[b]);
      }
      throw InputError("'" + name + "': the voxels around the corner of voxel " + where(g.blockVoxel(c, 7)) +
                       " (" + labels + ") touch only along an edge or at a corner, and no change of one voxel's "
                       "label makes them bound manifold surfaces; drop or merge one of the labels");
    }
    g.cell[best_voxel] = best_label;
    ++changed;
    for (int b = 0; b < 8; ++b) work.push_back(cornerOf(best_voxel, b));
  }
  return changed;
}

// A set of indices below n with the position of each among them in O(1).
struct RankedSet {
  std::vector<std::uint64_t> bits;
  std::vector<std::uint32_t> before;  // members in the words before, after finish()
  explicit RankedSet(std::size_t n) : bits((n + 63) / 64, 0) {}
  void insert(std::uint64_t i) { bits[i >> 6] |= std::uint64_t{1} << (i & 63); }
  bool contains(std::uint64_t i) const { return (bits[i >> 6] >> (i & 63)) & 1; }
  void finish() {
    before.resize(bits.size());
    std::uint32_t n = 0;
    for (std::size_t k = 0; k < bits.size(); ++k)
      before[k] = n, n += static_cast<std::uint32_t>(std::popcount(bits[k]));
  }
  std::uint32_t rank(std::uint64_t i) const {
    return before[i >> 6] +
           static_cast<std::uint32_t>(std::popcount(bits[i >> 6] & ((std::uint64_t{1} << (i & 63)) - 1)));
  }
};

struct WallTriangle {
  std::array<std::int32_t, 3> v;  // point ids: corners, fan centres, a wall's interior vertices
  std::int32_t wall;
  std::int32_t face = 0;  // of a wall made of several faces (each a wall of the tissue), which one
};

// Whether segment pq, lying in the plane of triangle abc, meets it (touching
// included, within `eps` of the triangle's size): in the coordinate plane
// most nearly parallel to the triangle, an end inside or an edge crossed.
bool coplanarSegmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                                  const Vec3& normal, double eps) {
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) > std::abs(normal[drop])) drop = k;
  const int x = (drop + 1) % 3, y = (drop + 2) % 3;
  auto cross2 = [&](const Vec3& o, const Vec3& u, const Vec3& w) {
    return (u[x] - o[x]) * (w[y] - o[y]) - (u[y] - o[y]) * (w[x] - o[x]);
  };
  const double size = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
  const double tol = eps * size * size;  // on twice the signed areas
  const double orient = cross2(a, b, c) > 0 ? 1 : -1;
  auto inside = [&](const Vec3& r) {
    return orient * cross2(a, b, r) >= -tol && orient * cross2(b, c, r) >= -tol && orient * cross2(c, a, r) >= -tol;
  };
  if (inside(p) || inside(q)) return true;
  const double seg_tol = eps * size * std::max(size, (q - p).norm());
  auto segmentsMeet = [&](const Vec3& u, const Vec3& w) {
    const double d1 = cross2(p, q, u), d2 = cross2(p, q, w), d3 = cross2(u, w, p), d4 = cross2(u, w, q);
    if (std::abs(d1) <= seg_tol && std::abs(d2) <= seg_tol) {  // on one line: do they overlap along it?
      const int z =
          std::abs(q[x] - p[x]) + std::abs(w[x] - u[x]) >= std::abs(q[y] - p[y]) + std::abs(w[y] - u[y]) ? x : y;
      const double slack = eps * size;
      return std::max(std::min(p[z], q[z]), std::min(u[z], w[z])) <=
             std::min(std::max(p[z], q[z]), std::max(u[z], w[z])) + slack;
    }
    return ((d1 >= -seg_tol && d2 <= seg_tol) || (d1 <= seg_tol && d2 >= -seg_tol)) &&
           ((d3 >= -seg_tol && d4 <= seg_tol) || (d3 <= seg_tol && d4 >= -seg_tol));
  };
  return segmentsMeet(a, b) || segmentsMeet(b, c) || segmentsMeet(c, a);
}

// Whether segment pq meets triangle abc, touching included (within a relative
// 1e-9), also when it lies in the triangle's plane.
bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  constexpr double eps = 1e-9;
  const Vec3 d = q - p, e1 = b - a, e2 = c - a, h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) <= 1e-12 * d.norm() * e1.norm() * e2.norm()) {  // parallel to the plane: in it?
    const Vec3 n = e1.cross(e2);
    const double nn = n.norm(), size = std::max({e1.norm(), e2.norm(), d.norm()});
    if (!(nn > 0)) return false;  // a degenerate triangle (the core's checks report it)
    if (std::abs((p - a).dot(n)) > eps * size * nn || std::abs((q - a).dot(n)) > eps * size * nn) return false;
    return coplanarSegmentMeetsTriangle(p, q, a, b, c, n, eps);
  }
  const Vec3 w = p - a;
  const double u = w.dot(h) / det;
  if (u < -eps || u > 1 + eps) return false;
  const Vec3 r = w.cross(e1);
  const double v = d.dot(r) / det;
  if (v < -eps || u + v > 1 + eps) return false;
  const double t = e2.dot(r) / det;
  return t >= -eps && t <= 1 + eps;
}

// Whether two triangles (corner ids into points) meet other than at what they
// share, as the mesher's check counts it (mesh/src/geometry_check.cpp): two
// sharing an edge do when they fold flat onto each other (in one plane, on
// one side of the edge); two sharing a corner do when the edge of either
// opposite that corner meets the other; others when any edge meets the other.
bool trianglesCross(const std::array<std::int32_t, 3>& A, const std::array<std::int32_t, 3>& B,
                    const std::vector<Vec3>& points) {
  std::int32_t common = -1;
  int shared = 0;
  for (const std::int32_t a : A)
    if (a == B[0] || a == B[1] || a == B[2]) ++shared, common = a;
  if (shared == 3) return true;
  if (shared <= 1) {
    // A quick no: one triangle's corners (but the shared one) all on one side of the other's plane, by more
    // than a millionth of the larger triangle's size (far beyond the tests' 1e-9), and, with a shared corner,
    // the other way round too: then no edge of either meets the other.
    auto apart = [&](const std::array<std::int32_t, 3>& S, const std::array<std::int32_t, 3>& T) {
      const Vec3 &a = points[T[0]], &b = points[T[1]], &c = points[T[2]];
      const Vec3 n = (b - a).cross(c - a);
      double size2 = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
      for (int k = 0; k < 3; ++k) size2 = std::max(size2, (points[S[k]] - points[S[(k + 1) % 3]]).squaredNorm());
      const double margin = 1e-6 * std::sqrt(size2) * n.norm();
      int above = 0, below = 0;
      for (const std::int32_t u : S) {
        if (u == common && shared == 1) continue;
        const double d = (points[u] - a).dot(n);
        above += d > margin, below += d < -margin;
      }
      const int others = shared == 1 ? 2 : 3;
      return margin > 0 && (above == others || below == others);
    };
    if (shared == 0 ? apart(A, B) || apart(B, A) : apart(A, B) && apart(B, A)) return false;
  }
  if (shared == 2) {
    std::int32_t r = -1, t = -1, e0 = -1, e1 = -1;
    for (const std::int32_t a : A) {
      if (a != B[0] && a != B[1] && a != B[2]) r = a;
      else (e0 < 0 ? e0 : e1) = a;
    }
    for (const std::int32_t b : B)
      if (b != A[0] && b != A[1] && b != A[2]) t = b;
    const Vec3 &x0 = points[e0], &x1 = points[e1];
    const Vec3 axis = x1 - x0, vr = points[r] - x0, vt = points[t] - x0;
    const Vec3 n = axis.cross(vr);
    const double size = std::max({axis.norm(), vr.norm(), vt.norm()});
    if (std::abs(vt.dot(n)) > 1e-9 * size * n.norm()) return false;  // not in one plane
    const double len2 = axis.squaredNorm();  // r and t beside the edge, on one side of it?
    const Vec3 ar = vr - axis * (vr.dot(axis) / len2), at = vt - axis * (vt.dot(axis) / len2);
    return ar.dot(at) > 0;
  }
  auto edgesMeet = [&](const std::array<std::int32_t, 3>& S, const std::array<std::int32_t, 3>& T) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t u = S[k], w = S[(k + 1) % 3];
      if (shared == 1 && (u == common || w == common)) continue;
      if (segmentMeetsTriangle(points[u], points[w], points[T[0]], points[T[1]], points[T[2]])) return true;
    }
    return false;
  };
  return edgesMeet(A, B) || edgesMeet(B, A);
}

struct Face {
  std::int32_t first, second;  // first: a cell (the larger id); the loop is oriented out of it
  bool forward;                // the loop as the +axis normal (first is the lower voxel)
};

struct Polyline {
  std::vector<std::int32_t> chain;  // corners (compact ids), vertex to vertex (closed: first == last)
  double tol;
  bool keep_one = false;
};

void simplifyPolyline(const Polyline& p, const std::vector<Vec3>& pos, std::vector<char>& keep) {
  const auto& ch = p.chain;
  const std::size_t last = ch.size() - 1;
  for (std::size_t i = 1; i < last; ++i) keep[ch[i]] = p.tol < 0;
  if (p.tol < 0) return;
  if (ch.front() == ch.back()) {  // a loop: split at the corner farthest from its start, one more on each side
    std::size_t far = 1;
    for (std::size_t i = 1; i < last; ++i)
      if ((pos[ch[i]] - pos[ch[0]]).squaredNorm() > (pos[ch[far]] - pos[ch[0]]).squaredNorm()) far = i;
    if (last < 2) return;
    keep[ch[far]] = 1;
    douglasPeucker(ch, 0, far, pos, p.tol, far > 1, keep);
    douglasPeucker(ch, far, last, pos, p.tol, last - far > 1, keep);
    return;
  }
  douglasPeucker(ch, 0, last, pos, p.tol, p.keep_one, keep);
}

}  // namespace

ImportResult tissueFromLabelImage3d(const LabelImage& img, const ImportOptions& o,
                                    std::vector<std::int64_t>* release) {
  const LabelImageOptions& io = o.image;
  const std::string file = "'" + img.name + "'";
  const auto [nx, ny, nz] = img.dims;
  const std::string dims_text = std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz);
  // Voxel size.
  std::array<double, 3> s = img.spacing;
  if (!io.voxel_size.empty()) {
    if (io.voxel_size.size() != 3)
      throw InputError(file + ": a 3D image of " + dims_text + " voxels needs voxel_size of 3 numbers (x, y, z), got " +
                       std::to_string(io.voxel_size.size()));
    for (std::size_t k = 0; k < 3; ++k) {
      if (!(std::isfinite(io.voxel_size[k]) && io.voxel_size[k] > 0))
        throw InputError(file + ": voxel_size " + std::string("xyz").substr(k, 1) + " = " +
                         formatNumber(io.voxel_size[k]) + " must be a positive finite number");
      s[k] = io.voxel_size[k];
    }
  } else {
    for (int k = 0; k < 3; ++k)
      if (!(std::isfinite(img.spacing[k]) && img.spacing[k] > 0))
        throw InputError(file + ": the file's voxel size in " + std::string("xyz").substr(k, 1) + " is " +
                         formatNumber(img.spacing[k]) + ", not a positive number; give voxel_size (--voxel-size)");
  }
  if (io.min_cell_size < 0)
    throw InputError(file + ": min_cell_size must be >= 0, got " + std::to_string(io.min_cell_size));
  if (io.small_cells != "drop" && io.small_cells != "merge")
    throw InputError(file + ": small_cells must be drop or merge, got '" + io.small_cells + "'");
  std::array<std::int64_t, 3> lo{0, 0, 0}, hi{nx, ny, nz};
  if (!io.crop.empty()) {
    if (io.crop.size() != 6)
      throw InputError(file + ": a 3D image of " + dims_text + " voxels needs crop of 6 numbers x0, y0, z0, x1, y1, "
                       "z1, got " + std::to_string(io.crop.size()));
    for (int a = 0; a < 3; ++a) lo[a] = io.crop[a], hi[a] = io.crop[a + 3];
    for (int a = 0; a < 3; ++a)
      if (!(0 <= lo[a] && lo[a] < hi[a] && hi[a] <= img.dims[a]))
        throw InputError(file + ": crop " + numberList(io.crop) + " is not a box 0 <= x0 < x1 <= " +
                         std::to_string(nx) + ", 0 <= y0 < y1 <= " + std::to_string(ny) + ", 0 <= z0 < z1 <= " +
                         std::to_string(nz) + " inside the image");
  }
  const std::int64_t w = hi[0] - lo[0], h = hi[1] - lo[1], d = hi[2] - lo[2];
  Grid g(w + 2, h + 2, d + 2);
  auto voxelName = [&](std::size_t v) {
    const auto p = g.coords(v);
    return "(" + std::to_string(p[0] - 1 + lo[0]) + ", " + std::to_string(p[1] - 1 + lo[1]) + ", " +
           std::to_string(p[2] - 1 + lo[2]) + ")";
  };

  ImportResult result{Tissue(3, Embedding::Volume), {}};
  ImportReport report;
  report.path = img.name;
  report.file_faces = img.labels.size();
  report.file_faces_noun = "voxels";
  report.notes.push_back("image " + dims_text + " voxels" +
                         (io.crop.empty() ? std::string()
                                          : ", cropped to x " + std::to_string(lo[0]) + ".." +
                                                std::to_string(hi[0] - 1) + ", y " + std::to_string(lo[1]) + ".." +
                                                std::to_string(hi[1] - 1) + ", z " + std::to_string(lo[2]) + ".." +
                                                std::to_string(hi[2] - 1)) +
                         ", voxel size " + formatNumber(s[0]) + " x " + formatNumber(s[1]) + " x " +
                         formatNumber(s[2]) + (io.voxel_size.empty() ? " (from the file)" : " (given)"));

  // Labels to compact ids (background and dropped labels: kBackground), padding by side.
  std::vector<Label> id_label;
  {
    auto source = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
      return img.labels[static_cast<std::size_t>((i + lo[0]) + nx * ((j + lo[1]) + ny * (k + lo[2])))];
    };
    std::unordered_map<Label, std::int32_t> id;
    auto excluded = [&](Label l) {
      return std::find(io.background.begin(), io.background.end(), l) != io.background.end() ||
             std::find(io.drop_labels.begin(), io.drop_labels.end(), l) != io.drop_labels.end();
    };
    const Label first = source(0, 0, 0);
    bool several = false;
    // The labels present, in parallel over z layers (merged as a set: the same for any number of threads).
#pragma omp parallel reduction(|| : several)
    {
      std::unordered_set<Label> present;
#pragma omp for schedule(static)
      for (std::int64_t k = 0; k < d; ++k) {
        Label last = first;
        bool last_in = false;
        for (std::int64_t j = 0; j < h; ++j)
          for (std::int64_t i = 0; i < w; ++i) {
            const Label l = source(i, j, k);
            if (l == last && last_in) continue;
            several = several || l != first;
            last = l;
            last_in = true;
            if (!excluded(l)) present.insert(l);
          }
      }
#pragma omp critical
      for (const Label l : present) id.emplace(l, 0);
    }
    if (!several)
      throw InputError(file + ": the image" + std::string(io.crop.empty() ? "" : " (cropped)") +
                       " holds one label only (" + std::to_string(first) + " in every voxel): no cells to tell apart");
    for (const auto& [l, unused] : id) id_label.push_back(l);
    std::sort(id_label.begin(), id_label.end());
    for (std::size_t k = 0; k < id_label.size(); ++k) id[id_label[k]] = static_cast<std::int32_t>(k);
    g.cell.resize(g.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < g.n[2]; ++k)
      for (std::int64_t j = 0; j < g.n[1]; ++j) {
        Label last = 0;
        std::int32_t last_id = kBackground;
        bool have = false;
        for (std::int64_t i = 0; i < g.n[0]; ++i) {
          std::int32_t& c = g.cell[g.at(i, j, k)];
          if (i == 0) c = -2;
          else if (i == g.n[0] - 1) c = -3;
          else if (j == 0) c = -4;
          else if (j == g.n[1] - 1) c = -5;
          else if (k == 0) c = -6;
          else if (k == g.n[2] - 1) c = -7;
          else {
            const Label l = source(i - 1, j - 1, k - 1);
            if (!have || l != last) {
              const auto it = id.find(l);
              last_id = it == id.end() ? kBackground : it->second;
              last = l, have = true;
            }
            c = last_id;
          }
        }
      }
  }
  if (release) std::vector<std::int64_t>().swap(*release);  // img.labels: read for the last time above
  std::vector<std::int64_t> size(id_label.size(), 0);
  auto countSizes = [&] {  // voxels per label, summed over per-thread counts
    std::fill(size.begin(), size.end(), 0);
#pragma omp parallel
    {
      std::vector<std::int64_t> mine(size.size(), 0);
#pragma omp for schedule(static)
      for (std::ptrdiff_t v = 0; v < static_cast<std::ptrdiff_t>(g.size()); ++v)
        if (const std::int32_t c = g.cell[static_cast<std::size_t>(v)]; c >= 0) ++mine[static_cast<std::size_t>(c)];
#pragma omp critical
      for (std::size_t l = 0; l < size.size(); ++l) size[l] += mine[l];
    }
  };
  countSizes();

  // Small labels: dropped, or merged into the neighbour sharing the most voxel faces.
  std::vector<std::string> small_notes;
  if (io.min_cell_size > 0) {
    std::vector<std::pair<std::int64_t, std::int32_t>> small;
    for (std::size_t l = 0; l < size.size(); ++l)
      if (size[l] < io.min_cell_size) small.emplace_back(size[l], static_cast<std::int32_t>(l));
    std::sort(small.begin(), small.end());
    std::vector<std::int32_t> into(size.size());
    std::iota(into.begin(), into.end(), 0);
    auto find = [&](std::int32_t l) {
      while (l >= 0 && into[static_cast<std::size_t>(l)] != l) l = into[static_cast<std::size_t>(l)];
      return l;
    };
    std::vector<char> is_small(size.size(), 0);
    for (const auto& [n, l] : small) is_small[static_cast<std::size_t>(l)] = 1;
    if (io.small_cells == "merge" && !small.empty()) {
      std::map<std::int32_t, std::map<std::int32_t, std::int64_t>> shared;
      for (std::size_t v = 0; v < g.size(); ++v) {
        const std::int32_t a = g.cell[v];
        if (a < 0) continue;
        for (int ax = 0; ax < 3; ++ax) {
          const std::int32_t b = g.cell[v + g.stride[ax]];  // a cell is never in the last padding layer
          if (b < 0 || b == a || !(is_small[static_cast<std::size_t>(a)] || is_small[static_cast<std::size_t>(b)]))
            continue;
          ++shared[a][b], ++shared[b][a];
        }
      }
      for (const auto& [n0, l] : small) {
        if (find(l) != l || size[static_cast<std::size_t>(l)] >= io.min_cell_size) continue;
        std::map<std::int32_t, std::int64_t> by_root;
        for (const auto& [b, n] : shared[l])
          if (const std::int32_t r = find(b); r != l && r >= 0) by_root[r] += n;
        std::int32_t best = kBackground;
        std::int64_t most = 0;
        for (const auto& [r, n] : by_root)
          if (n > most) best = r, most = n;  // ties: the smaller label
        into[static_cast<std::size_t>(l)] = best;
        const std::string what = "label " + std::to_string(id_label[static_cast<std::size_t>(l)]) + " (" +
                                 std::to_string(size[static_cast<std::size_t>(l)]) + " voxels < min_cell_size)";
        if (best < 0) {
          small_notes.push_back(what + " dropped: it touches no other cell");
          continue;
        }
        small_notes.push_back(what + " merged into label " + std::to_string(id_label[static_cast<std::size_t>(best)]) +
                              " (they share " + std::to_string(most) + " voxel faces)");
        size[static_cast<std::size_t>(best)] += size[static_cast<std::size_t>(l)];
        for (const auto& [b, n] : shared[l]) shared[best][b] += n;
      }
    } else {
      for (const auto& [n, l] : small) {
        into[static_cast<std::size_t>(l)] = kBackground;
        small_notes.push_back("label " + std::to_string(id_label[static_cast<std::size_t>(l)]) + " (" +
                              std::to_string(n) + " voxels < min_cell_size) dropped");
      }
    }
    if (!small.empty()) {
      for (std::int32_t& c : g.cell)
        if (c >= 0 && into[static_cast<std::size_t>(c)] != c) c = find(c);
      countSizes();
    }
  }
  for (std::size_t k = 0; k < small_notes.size() && k < kMaxNotes; ++k) report.notes.push_back(small_notes[k]);
  if (small_notes.size() > kMaxNotes)
    report.notes.push_back("and " + std::to_string(small_notes.size() - kMaxNotes) + " more small labels");

  {
    auto name = [&](std::int32_t c) {
      if (c == kBackground) return std::string("the background");
      if (c < kBackground) return std::string("the image border");
      return "label " + std::to_string(id_label[static_cast<std::size_t>(c)]);
    };
    if (const std::size_t changed = makeWellComposed(g, img.name, voxelName, name); changed > 0)
      report.notes.push_back(std::to_string(changed) +
                             " voxel(s) relabelled where voxels of one label touched only along an edge or at a "
                             "corner (each took the label of a voxel beside it)");
  }
  // Pieces: voxels of one label joined through faces; cells are pieces sorted by label, then first voxel.
  struct Piece {
    std::int32_t id;  // compact label id
    std::size_t first, voxels = 0;
  };
  std::vector<Piece> pieces;
  {
    std::vector<std::uint64_t> visited((g.size() + 63) / 64, 0);
    auto seen = [&](std::size_t v) { return (visited[v >> 6] >> (v & 63)) & 1; };
    auto mark = [&](std::size_t v) { visited[v >> 6] |= std::uint64_t{1} << (v & 63); };
    std::vector<std::size_t> stack;
    for (std::size_t v0 = 0; v0 < g.size(); ++v0) {
      const std::int32_t l = g.cell[v0];
      if (l < 0 || seen(v0)) continue;
      const auto p = static_cast<std::int32_t>(pieces.size());
      pieces.push_back({l, v0});
      stack.assign(1, v0);
      mark(v0);
      while (!stack.empty()) {
        const std::size_t v = stack.back();
        stack.pop_back();
        ++pieces.back().voxels;
        g.cell[v] = p;  // piece ids for now
        for (int ax = 0; ax < 3; ++ax)
          for (const std::size_t nb : {v - g.stride[ax], v + g.stride[ax]})
            if (!seen(nb) && g.cell[nb] == l) {
              // g.cell[nb] == l only for not-yet-visited voxels of the label (visited ones hold piece ids,
              // which may equal l: hence the visited bit first).
              mark(nb);
              stack.push_back(nb);
            }
      }
    }
  }
  if (pieces.empty())
    throw InputError(file + ": no cells: every voxel is background (" + numberList(io.background) + ")" +
                     (io.drop_labels.empty() && io.min_cell_size == 0 ? ""
                                                                      : ", dropped or smaller than min_cell_size"));
  std::vector<std::size_t> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    return pieces[p].id != pieces[q].id ? pieces[p].id < pieces[q].id : pieces[p].first < pieces[q].first;
  });
  std::size_t split_labels = 0;
  for (std::size_t k = 0; k < order.size();) {
    std::size_t e = k;
    while (e < order.size() && pieces[order[e]].id == pieces[order[k]].id) ++e;
    if (e - k > 1 && !io.keep_pieces && split_labels == 0) {
      std::string sizes, where;
      for (std::size_t q = k; q < e && q < k + 5; ++q) {
        sizes += (q > k ? ", " : "") + std::to_string(pieces[order[q]].voxels);
        where += (q > k ? ", " : "") + voxelName(pieces[order[q]].first);
      }
      if (e - k > 5) sizes += ", ...", where += ", ...";
      std::size_t others = 0;
      for (std::size_t r = e, f = e; r < order.size(); r = f) {
        f = r;
        while (f < order.size() && pieces[order[f]].id == pieces[order[r]].id) ++f;
        others += f - r > 1;
      }
      throw InputError(file + ": label " + std::to_string(id_label[static_cast<std::size_t>(pieces[order[k]].id)]) +
                       " is made of " + std::to_string(e - k) + " disconnected pieces (of " + sizes +
                       " voxels; a voxel of each: " + where + ")" +
                       (others > 0 ? "; " + std::to_string(others) + " other label(s) are split too" : "") +
                       "; keep_pieces: true (--keep-pieces) makes each piece a cell");
    }
    if (e - k > 1) ++split_labels;
    k = e;
  }
  if (split_labels)
    report.notes.push_back(std::to_string(split_labels) +
                           " label(s) in several disconnected pieces, each piece a cell (keep_pieces)");
  const std::size_t n_cells = pieces.size();
  std::vector<Label> cell_label(n_cells);
  {
    std::vector<std::int32_t> cell_of_piece(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c) {
      cell_of_piece[order[c]] = static_cast<std::int32_t>(c);
      cell_label[c] = id_label[static_cast<std::size_t>(pieces[order[c]].id)];
    }
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t v = 0; v < static_cast<std::ptrdiff_t>(g.size()); ++v)
      if (std::int32_t& c = g.cell[static_cast<std::size_t>(v)]; c >= 0) c = cell_of_piece[static_cast<std::size_t>(c)];
  }
  auto labelName = [&](std::int32_t c) {
    static const char* sides[6] = {"x = 0", "x = max", "y = 0", "y = max", "z = 0", "z = max"};
    if (c == kBackground) return std::string("the background");
    if (c < kBackground) return "the image border (" + std::string(sides[-2 - c]) + " side)";
    return "label " + std::to_string(cell_label[static_cast<std::size_t>(c)]);
  };

  // Interface faces: key voxel * 3 + axis for the face between voxel and voxel + axis (ascending).
  // In parallel over blocks of voxels, joined in voxel order.
  std::vector<std::uint64_t> face_key;
  std::vector<Face> faces;
  RankedSet face_set(3 * g.size());
  {
    constexpr std::ptrdiff_t kBlocks = 64;
    const std::size_t n_voxels = g.size() - g.stride[2];
    std::vector<std::vector<std::uint64_t>> block_keys(kBlocks);
    std::vector<std::vector<Face>> block_faces(kBlocks);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t blk = 0; blk < kBlocks; ++blk) {
      auto& keys = block_keys[static_cast<std::size_t>(blk)];
      auto& fs = block_faces[static_cast<std::size_t>(blk)];
      const std::size_t v0 = n_voxels * static_cast<std::size_t>(blk) / kBlocks,
                        v1 = n_voxels * static_cast<std::size_t>(blk + 1) / kBlocks;
      for (std::size_t v = v0; v < v1; ++v) {
        const std::int32_t a = g.cell[v];
        for (int ax = 0; ax < 3; ++ax) {
          const std::int32_t b = g.cell[v + g.stride[ax]];
          if (a == b || (a < 0 && b < 0)) continue;
          keys.push_back(v * 3 + static_cast<std::uint64_t>(ax));
          fs.push_back(a > b ? Face{a, b, true} : Face{b, a, false});
        }
      }
    }
    for (std::size_t blk = 0; blk < kBlocks; ++blk) {
      for (const std::uint64_t key : block_keys[blk]) face_set.insert(key);
      face_key.insert(face_key.end(), block_keys[blk].begin(), block_keys[blk].end());
      faces.insert(faces.end(), block_faces[blk].begin(), block_faces[blk].end());
      std::vector<std::uint64_t>().swap(block_keys[blk]);
      std::vector<Face>().swap(block_faces[blk]);
    }
  }
  face_set.finish();
  auto faceIndex = [&](std::uint64_t key) { return static_cast<Index>(face_set.rank(key)); };

  // Voxel edges: junctions (three or more labels around) or a joint of two faces of one wall.
  // In parallel over z layers: each lists its junction edges and the face pairs to join, taken in layer order.
  UnionFind patches(faces.size());
  std::vector<std::uint64_t> junction_edges;  // corner * 3 + axis: from the corner along the axis
  RankedSet junction_set(3 * g.size());
  {
    struct Layer {
      std::vector<std::uint64_t> junctions;
      std::vector<std::array<Index, 2>> joins;
      std::string error;
    };
    std::vector<Layer> layers(static_cast<std::size_t>(g.n[2]));
#pragma omp parallel for schedule(dynamic, 4)
    for (std::int64_t k = 1; k < g.n[2]; ++k) {
      Layer& layer = layers[static_cast<std::size_t>(k)];
      for (std::int64_t j = 1; j < g.n[1] && layer.error.empty(); ++j)
        for (std::int64_t i = 1; i < g.n[0] && layer.error.empty(); ++i) {
          const std::size_t c = g.at(i, j, k);
          const std::array<std::int64_t, 3> p{i, j, k};
          for (int ax = 0; ax < 3; ++ax) {
            if (p[ax] > g.n[ax] - 2) continue;  // the edge would run in the last padding layer
            const int b = (ax + 1) % 3, cc = (ax + 2) % 3;
            // The four voxels around the edge, in turn: q0 (-b, -c), q1 (+b, -c), q2 (+b, +c), q3 (-b, +c).
            const std::size_t q1 = c - g.stride[cc], q3 = c - g.stride[b], q0 = q1 - g.stride[b], q2 = c;
            const std::int32_t l0 = g.cell[q0], l1 = g.cell[q1], l2 = g.cell[q2], l3 = g.cell[q3];
            if (l0 == l1 && l1 == l2 && l2 == l3) continue;
            auto iface = [](std::int32_t x, std::int32_t y) { return x != y && (x >= 0 || y >= 0); };
            const bool f01 = iface(l0, l1), f12 = iface(l1, l2), f32 = iface(l3, l2), f03 = iface(l0, l3);
            const int n_faces = f01 + f12 + f32 + f03;
            if (n_faces == 0) continue;
            int distinct = 1 + (l1 != l0) + (l2 != l0 && l2 != l1) + (l3 != l0 && l3 != l1 && l3 != l2);
            if (distinct >= 3) {
              layer.junctions.push_back(c * 3 + static_cast<std::uint64_t>(ax));
              continue;
            }
            if (n_faces != 2) {
              layer.error = file + ": voxels " + voxelName(q0) + " and " + voxelName(q2) +
                            " touch along an edge only (an internal error: they should have been joined)";
              break;
            }
            std::array<Index, 2> two{};
            int m = 0;
            if (f01) two[m++] = faceIndex(q0 * 3 + static_cast<std::uint64_t>(b));
            if (f12) two[m++] = faceIndex(q1 * 3 + static_cast<std::uint64_t>(cc));
            if (f32) two[m++] = faceIndex(q3 * 3 + static_cast<std::uint64_t>(b));
            if (f03) two[m++] = faceIndex(q0 * 3 + static_cast<std::uint64_t>(cc));
            layer.joins.push_back(two);
          }
        }
    }
    for (Layer& layer : layers) {
      if (!layer.error.empty()) throw InputError(layer.error);
      for (const auto& two : layer.joins) patches.unite(two[0], two[1]);
      for (const std::uint64_t e : layer.junctions) junction_set.insert(e), junction_edges.push_back(e);
      Layer().joins.swap(layer.joins);
      Layer().junctions.swap(layer.junctions);
    }
  }
  // Corners on junction lines (compact ids, ascending corner index), their degree and whether they are vertices.
  junction_set.finish();
  std::vector<std::uint64_t> corners;
  RankedSet corner_set(g.size());
  for (std::uint64_t e : junction_edges) {
    corner_set.insert(e / 3);
    corner_set.insert(e / 3 + g.stride[e % 3]);
  }
  corner_set.finish();
  for (std::size_t wi = 0; wi < corner_set.bits.size(); ++wi)
    for (std::uint64_t word = corner_set.bits[wi]; word != 0; word &= word - 1)
      corners.push_back(wi * 64 + static_cast<std::uint64_t>(std::countr_zero(word)));
  auto cornerId = [&](std::uint64_t c) { return static_cast<std::int32_t>(corner_set.rank(c)); };
  const std::size_t n_corners = corners.size();
  std::vector<std::array<std::int32_t, 6>> incident(n_corners);  // junction edges at each corner
  std::vector<std::uint8_t> degree(n_corners, 0);
  std::vector<std::array<std::int32_t, 2>> edge_ends(junction_edges.size());
  for (std::size_t e = 0; e < junction_edges.size(); ++e) {
    const std::size_t c = junction_edges[e] / 3;
    edge_ends[e] = {cornerId(c), cornerId(c + g.stride[junction_edges[e] % 3])};
    for (const std::int32_t u : edge_ends[e]) incident[u][degree[u]++] = static_cast<std::int32_t>(e);
  }
  std::vector<char> is_vertex(n_corners, 0);
  std::vector<Vec3> pos(n_corners);  // in voxels, padded corner coordinates
  for (std::size_t u = 0; u < n_corners; ++u) {
    const auto p = g.coords(corners[u]);
    pos[u] = Vec3(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
    if (degree[u] != 2) {
      is_vertex[u] = 1;
      continue;
    }
    std::array<std::int32_t, 8> l;
    for (int b = 0; b < 8; ++b) l[b] = g.cell[g.blockVoxel(corners[u], b)];
    std::sort(l.begin(), l.end());
    is_vertex[u] = std::unique(l.begin(), l.end()) - l.begin() >= 4;
  }

  // Junction polylines: chains of junction edges between vertices; a closed one without a vertex starts anywhere.
  std::vector<Polyline> polylines;
  std::vector<std::int32_t> edge_polyline(junction_edges.size(), -1);
  auto walk = [&](std::int32_t start, std::int32_t e0) {
    Polyline pl{{start}, o.simplify};
    std::int32_t u = start, e = e0;
    for (;;) {
      edge_polyline[e] = static_cast<std::int32_t>(polylines.size());
      u = edge_ends[e][0] == u ? edge_ends[e][1] : edge_ends[e][0];
      pl.chain.push_back(u);
      if (is_vertex[u]) break;
      e = incident[u][0] == e ? incident[u][1] : incident[u][0];
    }
    polylines.push_back(std::move(pl));
  };
  for (std::size_t u = 0; u < n_corners; ++u)
    if (is_vertex[u])
      for (int k = 0; k < degree[u]; ++k)
        if (edge_polyline[incident[u][k]] < 0) walk(static_cast<std::int32_t>(u), incident[u][k]);
  for (std::size_t e = 0; e < junction_edges.size(); ++e)
    if (edge_polyline[e] < 0) {
      is_vertex[edge_ends[e][0]] = 1;
      walk(edge_ends[e][0], static_cast<std::int32_t>(e));
    }

  // Walls: the patches; each one's boundary (its faces' junction edges, run out of its first cell) as one loop.
  std::vector<Index> patch_of_face(faces.size());
  std::vector<Index> patch_face;  // a face of each patch
  {
    std::vector<Index> id_of_root(faces.size(), kInvalidIndex);
    for (Index f = 0; f < faces.size(); ++f) {
      Index& id = id_of_root[patches.find(f)];
      if (id == kInvalidIndex) {
        id = static_cast<Index>(patch_face.size());
        patch_face.push_back(f);
      }
      patch_of_face[f] = id;
    }
  }
  const std::size_t n_walls = patch_face.size();
  struct Boundary {
    Index patch;
    std::int32_t tail, head, edge;
    bool operator<(const Boundary& b) const { return patch != b.patch ? patch < b.patch : tail < b.tail; }
  };
  std::vector<Boundary> boundary;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::size_t v = face_key[f] / 3;
    const int ax = static_cast<int>(face_key[f] % 3), b = (ax + 1) % 3, cc = (ax + 2) % 3;
    const std::size_t c0 = v + g.stride[0] + g.stride[1] + g.stride[2] - g.stride[b] - g.stride[cc];
    // corners in turn about +axis: c0, c0 + b, c0 + b + c, c0 + c; edges: from the corner along the axis.
    const std::size_t cs[4] = {c0, c0 + g.stride[b], c0 + g.stride[b] + g.stride[cc], c0 + g.stride[cc]};
    const std::uint64_t es[4] = {c0 * 3 + static_cast<std::uint64_t>(b), cs[1] * 3 + static_cast<std::uint64_t>(cc),
                                 cs[3] * 3 + static_cast<std::uint64_t>(b), c0 * 3 + static_cast<std::uint64_t>(cc)};
    for (int k = 0; k < 4; ++k) {
      if (!junction_set.contains(es[k])) continue;
      std::int32_t tail = cornerId(cs[k]), head = cornerId(cs[(k + 1) % 4]);
      if (!faces[f].forward) std::swap(tail, head);
      boundary.push_back({patch_of_face[f], tail, head, static_cast<std::int32_t>(junction_set.rank(es[k]))});
    }
  }
  std::sort(boundary.begin(), boundary.end());
  std::vector<std::size_t> boundary_start(n_walls + 1, 0);
  for (const Boundary& bd : boundary) ++boundary_start[bd.patch + 1];
  for (std::size_t p = 0; p < n_walls; ++p) boundary_start[p + 1] += boundary_start[p];
  std::vector<std::vector<std::int32_t>> loops(n_walls);          // corners, in turn
  std::vector<std::vector<std::int32_t>> wall_polylines(n_walls);  // the polylines along each loop
  for (std::size_t p = 0; p < n_walls; ++p) {
    const Face& f = faces[patch_face[p]];
    const std::string pair = labelName(f.first) + " and " + labelName(f.second);
    const std::string at = " (at voxel " + voxelName(face_key[patch_face[p]] / 3) + ")";
    const std::size_t b0 = boundary_start[p], b1 = boundary_start[p + 1];
    if (b0 == b1)
      throw InputError(file + ": the interface between " + pair + at +
                       " is a closed surface, met by no third label (one cell enclosed by the other): a wall needs a "
                       "boundary of junction lines; drop or merge the inner label");
    for (std::size_t k = b0 + 1; k < b1; ++k)
      if (boundary[k].tail == boundary[k - 1].tail)
        throw InputError(file + ": the wall between " + pair + at + " is pinched: its boundary passes twice through "
                         "the voxel corner " + fmtPoint(pos[boundary[k].tail]) +
                         " (padded voxel coordinates); a wall is a disc");
    std::size_t walked = 0;
    std::int32_t u = boundary[b0].tail;
    std::vector<char> used(b1 - b0, 0);
    do {
      const auto it = std::lower_bound(boundary.begin() + static_cast<std::ptrdiff_t>(b0),
                                       boundary.begin() + static_cast<std::ptrdiff_t>(b1),
                                       Boundary{static_cast<Index>(p), u, 0, 0});
      const auto at_k = static_cast<std::size_t>(it - boundary.begin());
      if (at_k >= b1 || it->tail != u || used[at_k - b0])
        throw InputError(file + ": the boundary of the wall between " + pair + at +
                         " is not a closed loop (an internal error)");
      used[at_k - b0] = 1;
      loops[p].push_back(u);
      const std::int32_t pl = edge_polyline[it->edge];
      if (wall_polylines[p].empty() || wall_polylines[p].back() != pl) wall_polylines[p].push_back(pl);
      u = it->head;
      ++walked;
    } while (u != boundary[b0].tail);
    if (walked != b1 - b0)
      throw InputError(file + ": the interface between " + pair + at + " is not a disc: its boundary is " +
                       "several loops of junction lines (an annulus, e.g. one cell wrapped around another); " +
                       "merge or drop one of the labels");
    std::sort(wall_polylines[p].begin(), wall_polylines[p].end());
    wall_polylines[p].erase(std::unique(wall_polylines[p].begin(), wall_polylines[p].end()), wall_polylines[p].end());
  }
  std::vector<std::vector<Index>> cell_walls(n_cells);
  for (std::size_t p = 0; p < n_walls; ++p) {
    const Face& f = faces[patch_face[p]];
    cell_walls[static_cast<std::size_t>(f.first)].push_back(static_cast<Index>(p));
    if (f.second >= 0) cell_walls[static_cast<std::size_t>(f.second)].push_back(static_cast<Index>(p));
  }

  // Smooth each junction polyline first (its ends fixed): repeated [1/4, 1/2, 1/4] averaging along it,
  // ceil(8 * simplify) times (up to 32; kStaircasePasses times at simplify 0), takes the voxel staircase to a
  // curve near the junction it samples, whose best-fit-plane projection no longer zigzags.
  const int passes =
      o.simplify > 0 ? static_cast<int>(std::min(32.0, std::ceil(8 * o.simplify))) : kStaircasePasses;
  auto smoothLine = [&](const std::vector<std::int32_t>& ch) {
    std::vector<Vec3> next(ch.size());
    for (int pass = 0; pass < passes; ++pass) {
      for (std::size_t i = 1; i + 1 < ch.size(); ++i)
        next[i] = 0.25 * pos[ch[i - 1]] + 0.5 * pos[ch[i]] + 0.25 * pos[ch[i + 1]];
      for (std::size_t i = 1; i + 1 < ch.size(); ++i) pos[ch[i]] = next[i];
    }
  };
  std::map<std::pair<std::int32_t, std::int32_t>, int> same_ends;  // open junction lines by their two ends
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> first_with_ends;  // and the first of them
  for (std::size_t k = 0; k < polylines.size(); ++k) {
    const auto& ch = polylines[k].chain;
    if (ch.front() == ch.back()) continue;
    ++same_ends[std::minmax(ch.front(), ch.back())];
    first_with_ends.emplace(std::minmax(ch.front(), ch.back()), static_cast<std::int32_t>(k));
  }
  auto smoothedLine = [&](std::size_t k) {  // a closed line, or the first line with its two ends
    const auto& ch = polylines[k].chain;
    return ch.front() == ch.back() ||
           first_with_ends.at(std::minmax(ch.front(), ch.back())) == static_cast<std::int32_t>(k);
  };
  const std::vector<Vec3> voxel_pos = pos;  // the corners before smoothing (below)
  if (o.simplify > 0)
    for (const Polyline& pl : polylines)
      if (pl.chain.size() >= 3) smoothLine(pl.chain);
  // Simplify, then make sure every wall keeps three corners and no cell loses much of its volume.
  std::vector<char> keep(n_corners, 0);
  for (std::size_t u = 0; u < n_corners; ++u) keep[u] = is_vertex[u];
  for (const Polyline& pl : polylines) simplifyPolyline(pl, pos, keep);
  {
    std::map<std::pair<std::int32_t, std::int32_t>, int> straight;
    for (Polyline& pl : polylines) {
      if (pl.chain.front() == pl.chain.back() || pl.chain.size() < 3) continue;
      bool inner = false;
      for (std::size_t k = 1; k + 1 < pl.chain.size(); ++k) inner = inner || keep[pl.chain[k]];
      if (inner) continue;
      if (straight[std::minmax(pl.chain.front(), pl.chain.back())]++ == 0) continue;
      pl.keep_one = true;
      // Smoothing takes every line towards the chord between its ends, so two lines with the same ends meet
      // there, and the wall between them (often a voxel face or two where two cells barely touch) would be a
      // sliver through the corner kept here: on configs/label_images/cells_3d.mha at simplify 1, a one-face wall
      // became a triangle with corners of 0.22, 0.22 and 179.6 degrees (1/500 of the face's area; at simplify 4
      // the two lines met: duplicate vertices), which the mesher's angle bound refined into 3000 triangles and
      // TetGen took tens of seconds over. So this line's corners go back to the voxel corners they were.
      if (o.simplify > 0)
        for (std::size_t k = 1; k + 1 < pl.chain.size(); ++k) pos[pl.chain[k]] = voxel_pos[pl.chain[k]];
      simplifyPolyline(pl, pos, keep);
    }
  }
  // The staircase (simplify 0) keeps the corners where it turns (above), then smoothed.
  if (o.simplify == 0)
    for (const Polyline& pl : polylines)
      if (pl.chain.size() >= 3) smoothLine(pl.chain);
  std::vector<double> six_volume(n_cells, 0);  // of each cell's wall polygons, in voxels
  // Walls changed since the last crossing test (two unchanged walls that did not meet still do not).
  std::vector<char> wall_changed(n_walls, 1);
  std::vector<std::vector<std::int32_t>> polyline_walls(polylines.size());
  for (std::size_t p = 0; p < n_walls; ++p)
    for (const std::int32_t pl : wall_polylines[p]) polyline_walls[static_cast<std::size_t>(pl)].push_back(
        static_cast<std::int32_t>(p));
  const double voxel_volume = s[0] * s[1] * s[2], max_voxel = std::max({s[0], s[1], s[2]});
  // Per wall, kept between rounds for the walls that did not change: 2 fewer than three corners, 1 a defect
  // the mesher refuses (pinched, or crossing itself where that folds its fan), 0 fine; the volume its surface
  // adds to its first cell; its triangles.
  std::vector<char> wall_state(n_walls, 0);
  std::vector<double> wall_volume(n_walls, 0);
  std::vector<std::vector<WallTriangle>> wall_tris_of(n_walls);
  std::vector<std::array<Vec3, 2>> wall_box(n_walls);  // of its triangles' points (changed walls only move them)
  // The crossing test's points: every junction-line corner, then the walls' fan centres (n_corners + wall).
  std::vector<Vec3> points(n_corners + n_walls);
  for (std::size_t u = 0; u < n_corners; ++u) points[u] = Vec3(pos[u].x() * s[0], pos[u].y() * s[1], pos[u].z() * s[2]);
  // The tissue's position of a point, bit for bit as written below (a junction-line corner from its grid position, a
  // point inside a wall of faces from its crossing-test position), and back. The polygon checks run on these: the
  // mesher runs the same ones on the tissue, and whether a loop's projection touches itself can depend on the last
  // bit of a coordinate (a wall of voxel corners passed here in the crossing test's frame, shifted by 1.5 voxels,
  // and was refused by the mesher).
  auto worldOf = [&](std::size_t u) {
    Vec3 x;
    if (u < n_corners)
      for (int a = 0; a < 3; ++a) x[a] = img.origin[a] + (pos[u][a] - 1.0 + static_cast<double>(lo[a]) - 0.5) * s[a];
    else
      for (int a = 0; a < 3; ++a)
        x[a] = img.origin[a] + (points[u][a] / s[a] - 1.0 + static_cast<double>(lo[a]) - 0.5) * s[a];
    return x;
  };
  auto fromWorld = [&](const Vec3& x) {
    Vec3 y;
    for (int a = 0; a < 3; ++a) y[a] = ((x[a] - img.origin[a]) / s[a] + 1.0 - static_cast<double>(lo[a]) + 0.5) * s[a];
    return y;
  };
  std::vector<char> refined(n_walls, 0);    // walls along a junction line simplified less than asked (or smoothed)
  std::vector<char> coarsened(n_walls, 0);  // simplify 0: walls along a junction line simplified after all
  std::vector<std::size_t> failing;  // walls still failing every repair
  int extra_smoothing = 0;  // rounds of it, below: at most kExtraSmoothing (kStaircaseExtraSmoothing at simplify 0)
  const int max_extra_smoothing = o.simplify > 0 ? kExtraSmoothing : kStaircaseExtraSmoothing;
  std::vector<char> unresolved(n_walls, 0);
  // The last repair (docs/import.md, step 6, "Walls of several faces"): a wall still failing once its junction
  // lines are as the repairs above left them is made of the triangles of its voxel interface, its boundary
  // those junction lines unchanged (so no other wall changes): every voxel face of the patch two triangles,
  // its corners off the junction lines moved by the harmonic extension of how far the repairs moved the
  // corners of the boundary, the corners the junction lines dropped merged into the nearest kept one along
  // the boundary. Each triangle is a wall of the tissue between the same two cells.
  std::vector<std::vector<std::array<std::int32_t, 3>>> wall_faces(n_walls);  // point ids, loop orientation
  std::vector<std::vector<std::int32_t>> face_centre(n_walls);                // each face's fan centre slot
  std::vector<char> interior_tried(n_walls, 0);
  std::vector<char> line_restored(polylines.size(), 0), restored_wall(n_walls, 0);
  bool interiors = false;  // in the phase of walls of several faces
  // Whether kept corners a and b are in turn along a junction line (an edge of the tissue).
  auto isTissueEdge = [&](std::int32_t a, std::int32_t b) {
    for (int k = 0; k < degree[a]; ++k) {
      const auto& ch = polylines[static_cast<std::size_t>(edge_polyline[incident[a][k]])].chain;
      for (std::size_t i = 0; i < ch.size(); ++i) {
        if (ch[i] != a) continue;
        std::size_t j = i + 1;
        while (j < ch.size() && !keep[ch[j]]) ++j;
        if (j < ch.size() && ch[j] == b) return true;
        j = i;
        while (j > 0 && !keep[ch[j - 1]]) --j;
        if (j > 0 && ch[j - 1] == b) return true;
      }
    }
    return false;
  };
  std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> chord_owner;  // such edges, by wall
  std::vector<std::vector<std::pair<std::int32_t, std::int32_t>>> wall_chords(n_walls);
  // Each wall's voxel faces (ascending): patch_faces[patch_faces_start[p] .. patch_faces_start[p + 1]), made on
  // the first call (a counting sort).
  std::vector<Index> patch_faces;
  std::vector<std::size_t> patch_faces_start;
  auto makeInteriors = [&](const std::vector<std::size_t>& todo) {
    if (patch_faces_start.empty()) {
      patch_faces_start.assign(n_walls + 1, 0);
      for (Index f = 0; f < faces.size(); ++f) ++patch_faces_start[patch_of_face[f] + 1];
      for (std::size_t p = 0; p < n_walls; ++p) patch_faces_start[p + 1] += patch_faces_start[p];
      patch_faces.resize(faces.size());
      std::vector<std::size_t> fill(patch_faces_start.begin(), patch_faces_start.end() - 1);
      for (Index f = 0; f < faces.size(); ++f) patch_faces[fill[patch_of_face[f]]++] = f;
    }
    for (const std::size_t p : todo) interior_tried[p] = 1;
    std::size_t made = 0;
    for (const std::size_t p : todo) {
      // The boundary corners in loop order, and for each the kept corner it merges into.
      const auto& loop = loops[p];
      const std::size_t n = loop.size();
      std::vector<std::size_t> kept_at;
      for (std::size_t i = 0; i < n; ++i)
        if (keep[loop[i]]) kept_at.push_back(i);
      if (kept_at.size() < 3) continue;
      std::unordered_map<std::int32_t, std::int32_t> merge_into;  // boundary corner -> kept corner
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t back = 0, ahead = 0;
        while (!keep[loop[(i + n - back) % n]]) ++back;
        while (!keep[loop[(i + ahead) % n]]) ++ahead;
        merge_into[loop[i]] = back <= ahead ? loop[(i + n - back) % n] : loop[(i + ahead) % n];
      }
      // The patch's voxel corners: on the boundary (corner ids) or interior (local ids, from n_corners up).
      std::unordered_map<std::size_t, std::int32_t> local;  // grid corner -> interior index
      std::vector<std::size_t> inner;                        // grid corner of each interior index
      std::vector<std::array<std::int32_t, 4>> quads;        // boundary corner id, or -1 - interior index
      bool ok = true;
      for (std::size_t fi = patch_faces_start[p]; fi < patch_faces_start[p + 1]; ++fi) {
        const Index f = patch_faces[fi];
        const std::size_t v = face_key[f] / 3;
        const int ax = static_cast<int>(face_key[f] % 3), b = (ax + 1) % 3, cc = (ax + 2) % 3;
        const std::size_t c0 = v + g.stride[0] + g.stride[1] + g.stride[2] - g.stride[b] - g.stride[cc];
        const std::size_t cs[4] = {c0, c0 + g.stride[b], c0 + g.stride[b] + g.stride[cc], c0 + g.stride[cc]};
        std::array<std::int32_t, 4> q;
        for (int k = 0; k < 4; ++k) {
          if (corner_set.contains(cs[k])) {
            q[k] = cornerId(cs[k]);
            ok = ok && merge_into.count(q[k]);  // a junction corner inside the patch: not a disc of corners
            continue;
          }
          const auto [it, added] = local.emplace(cs[k], static_cast<std::int32_t>(inner.size()));
          if (added) inner.push_back(cs[k]);
          q[k] = -1 - it->second;
        }
        if (!faces[f].forward) std::swap(q[1], q[3]);
        quads.push_back(q);
      }
      if (!ok) continue;
      // The interior corners' displacement: the mean of their neighbours' (Gauss-Seidel), the boundary's given.
      const std::size_t m = inner.size();
      std::vector<std::vector<std::int32_t>> nbrs(m);
      for (const auto& q : quads)
        for (int k = 0; k < 4; ++k) {
          const std::int32_t a = q[k], c = q[(k + 1) % 4];
          if (a < 0) nbrs[static_cast<std::size_t>(-1 - a)].push_back(c);
          if (c < 0) nbrs[static_cast<std::size_t>(-1 - c)].push_back(a);
        }
      for (auto& nb : nbrs) {
        std::sort(nb.begin(), nb.end());
        nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
      }
      auto gridPos = [&](std::size_t c) {
        const auto x = g.coords(c);
        return Vec3(static_cast<double>(x[0]), static_cast<double>(x[1]), static_cast<double>(x[2]));
      };
      std::vector<Vec3> disp(m, Vec3::Zero());
      for (int it = 0; it < 4000; ++it) {
        double change = 0;
        for (std::size_t i = 0; i < m; ++i) {
          Vec3 sum = Vec3::Zero();
          for (const std::int32_t u : nbrs[i])
            sum += u >= 0 ? Vec3(pos[u] - voxel_pos[u]) : disp[static_cast<std::size_t>(-1 - u)];
          const Vec3 next = sum / static_cast<double>(nbrs[i].size());
          change = std::max(change, (next - disp[i]).cwiseAbs().maxCoeff());
          disp[i] = next;
        }
        if (change < 1e-6) break;
      }
      // The triangles, the dropped boundary corners merged; then the boundary must be the kept loop.
      const auto base = static_cast<std::int32_t>(points.size());
      std::vector<std::array<std::int32_t, 3>> tris;
      for (const auto& q : quads) {
        std::array<std::int32_t, 4> id;
        for (int k = 0; k < 4; ++k) id[k] = q[k] >= 0 ? merge_into.at(q[k]) : base - 1 - q[k];
        // The diagonal from an interior corner where one is: no triangle of three junction-line corners,
        // nearly in a line once the line is smoothed.
        const int r = q[0] < 0 || q[2] < 0 || !(q[1] < 0 || q[3] < 0) ? 0 : 1;
        for (const auto& t : {std::array<std::int32_t, 3>{id[r], id[r + 1], id[r + 2]},
                              {id[r], id[r + 2], id[(r + 3) % 4]}})
          if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) tris.push_back(t);
      }
      std::map<std::pair<std::int32_t, std::int32_t>, int> directed;
      for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
      std::size_t boundary_edges = 0;
      for (const auto& [e, count] : directed) {
        const int back = directed.count({e.second, e.first}) ? directed.at({e.second, e.first}) : 0;
        ok = ok && count == 1 && back <= 1;
        boundary_edges += back == 0;
      }
      for (std::size_t i = 0; i < kept_at.size() && ok; ++i) {
        const std::int32_t a = loop[kept_at[i]], b = loop[kept_at[(i + 1) % kept_at.size()]];
        ok = directed.count({a, b}) && !directed.count({b, a});
      }
      ok = ok && boundary_edges == kept_at.size();
      // A triangle edge inside the wall between two junction-line corners must not be an edge of the tissue
      // already (two kept corners in turn along a junction line, or such an edge inside another wall of faces):
      // that edge would bound more faces of a cell.
      std::vector<std::pair<std::int32_t, std::int32_t>> chords;
      for (const auto& [e, count] : directed)
        if (ok && e.first < e.second && static_cast<std::size_t>(e.second) < n_corners &&
            directed.count({e.second, e.first})) {
          const auto owner = chord_owner.find(e);
          ok = !isTissueEdge(e.first, e.second) && (owner == chord_owner.end() || owner->second == p);
          chords.push_back(e);
        }
      if (!ok) continue;
      for (const auto& e : chords) chord_owner[e] = p;
      wall_chords[p] = std::move(chords);
      for (std::size_t i = 0; i < m; ++i) {
        const Vec3 x = gridPos(inner[i]) + disp[i];
        points.emplace_back(x.x() * s[0], x.y() * s[1], x.z() * s[2]);
      }
      wall_faces[p] = std::move(tris);
      face_centre[p].resize(wall_faces[p].size());
      for (auto& c : face_centre[p]) c = static_cast<std::int32_t>(points.size()), points.emplace_back(Vec3::Zero());
      wall_changed[p] = 1;
      ++made;
    }
    return made;
  };
  for (;;) {
    std::vector<char> redo(polylines.size(), 0), flagged(n_walls, 0);
    bool any = false;
    auto redoWall = [&](std::size_t p) {
      flagged[p] = 1, any = true;
      for (const std::int32_t pl : wall_polylines[p]) redo[static_cast<std::size_t>(pl)] = 1;
    };
    auto redoWallShared = [&](std::size_t p) {  // from several threads: the flags only ever become 1
      std::atomic_ref<char>(flagged[p]).store(1, std::memory_order_relaxed);
      for (const std::int32_t pl : wall_polylines[p])
        std::atomic_ref<char>(redo[static_cast<std::size_t>(pl)]).store(1, std::memory_order_relaxed);
    };
    // A wall flagged before and not changed since still is (its pairs with unchanged walls are not tested again).
    for (std::size_t p = 0; p < n_walls; ++p)
      if (unresolved[p]) redoWall(p);
    std::fill(six_volume.begin(), six_volume.end(), 0.0);
    // Each changed wall's surface: its check, volume and triangles, in parallel (a wall writes its own
    // entries and fan centre), then gathered in wall order (the volumes summed in that order).
#pragma omp parallel for schedule(dynamic, 64)
    for (std::ptrdiff_t pp = 0; pp < static_cast<std::ptrdiff_t>(n_walls); ++pp) {
      const auto p = static_cast<std::size_t>(pp);
      if (!wall_changed[p]) continue;
      wall_tris_of[p].clear();
      if (!wall_faces[p].empty()) {  // a wall of several faces: each one's fan (tissue/geometry.hpp)
        double vol = 0;
        wall_state[p] = 0;
        for (std::size_t j = 0; j < wall_faces[p].size(); ++j) {
          const auto& ids = wall_faces[p][j];
          const std::array<Vec3, 3> tp{points[ids[0]], points[ids[1]], points[ids[2]]};
          const PolygonDefect defect = polygonDefect(std::array<Vec3, 3>{
              worldOf(static_cast<std::size_t>(ids[0])), worldOf(static_cast<std::size_t>(ids[1])),
              worldOf(static_cast<std::size_t>(ids[2]))});  // as the tissue will hold it
          // A sliver (mean width 2 area / perimeter, as the mesher measures it) is a defect too.
          const double width = (tp[1] - tp[0]).cross(tp[2] - tp[0]).norm() /
                               ((tp[1] - tp[0]).norm() + (tp[2] - tp[1]).norm() + (tp[0] - tp[2]).norm());
          if (defect.kind != PolygonDefect::None || !(width > 1e-6 * max_voxel)) wall_state[p] = 1;
          // And a corner under kMinFaceAngle degrees (the wall mesher's angle bound fills it with points).
          for (int i = 0; i < 3; ++i) {
            const Vec3 a = tp[(i + 1) % 3] - tp[i], b = tp[(i + 2) % 3] - tp[i];
            if (!(a.cross(b).norm() > std::sin(kMinFaceAngle * std::numbers::pi / 180) * a.norm() * b.norm() ||
                  a.dot(b) < 0))
              wall_state[p] = 1;
          }
          if (defect.kind == PolygonDefect::NoArea || defect.kind == PolygonDefect::Pinched) continue;
          const PolygonTriangulation tri = polygonTriangulation(tp);
          const auto face = static_cast<std::int32_t>(j + 1);
          if (tri.fan()) {
            const std::int32_t centre = face_centre[p][j];
            points[static_cast<std::size_t>(centre)] = tri.center;
            for (int i = 0; i < 3; ++i) {
              vol += tri.center.dot(tp[i].cross(tp[(i + 1) % 3]));
              wall_tris_of[p].push_back({{centre, ids[i], ids[(i + 1) % 3]}, static_cast<std::int32_t>(p), face});
            }
          } else {
            for (const auto& t : tri.triangles) {
              vol += tp[t[0]].dot(tp[t[1]].cross(tp[t[2]]));
              wall_tris_of[p].push_back({{ids[t[0]], ids[t[1]], ids[t[2]]}, static_cast<std::int32_t>(p), face});
            }
          }
        }
        wall_volume[p] = vol / voxel_volume;
        // Two of its triangles sharing an edge must not fold onto each other (normals more than 120 degrees
        // apart): nearly overlapping faces, which the mesher's exact test passes and TetGen fails on.
        std::map<std::pair<std::int32_t, std::int32_t>, Vec3> edge_normal;
        double worst = 1;
        for (const auto& t : wall_faces[p]) {
          const Vec3 nrm = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).normalized();
          for (int k = 0; k < 3; ++k) {
            const auto key = std::minmax(t[k], t[(k + 1) % 3]);
            const auto [it, added] = edge_normal.emplace(key, nrm);
            if (!added) worst = std::min(worst, it->second.dot(nrm));
          }
        }
        if (!(worst > kMinFoldCosine)) wall_state[p] = 1;
        continue;
      }
      std::vector<Vec3> loop_points, loop_world;
      std::vector<std::int32_t> ids;
      for (const std::int32_t u : loops[p])
        if (keep[u]) loop_points.push_back(points[u]), loop_world.push_back(worldOf(u)), ids.push_back(u);
      if (loop_points.size() < 3) {
        wall_state[p] = 2;
        continue;
      }
      // The cells' volumes as the tissue will measure them (tissue/geometry.hpp), from the loop as the tissue will
      // hold it (its positions and order: the wall's vertices are written in this order).
      // Where the crossing test's frame makes the same triangles (nearly always), its own fan centre is kept.
      PolygonTriangulation tri = polygonTriangulation(loop_points);
      PolygonTriangulation in_tissue = polygonTriangulation(loop_world);
      const bool folded = in_tissue.folded;
      if (in_tissue.triangles != tri.triangles || in_tissue.folded != tri.folded) {
        tri = std::move(in_tissue);
        if (tri.fan()) tri.center = fromWorld(tri.center);
      }
      // A loop the mesher and validate() refuse (tissue/validate.cpp): simplify it less.
      const PolygonDefect defect = polygonDefect(loop_world);
      wall_state[p] = defect.kind == PolygonDefect::Pinched ||
                      (defect.kind == PolygonDefect::SelfIntersecting && folded);
      // A corner under kMinPolygonAngle degrees (a sliver, or a spike), which the wall mesher's angle bound fills
      // with points without end (a 0.0007-degree corner of a 4-corner wall at simplify 2 in docs/import.md).
      const double sin_min = std::sin(kMinPolygonAngle * std::numbers::pi / 180);
      for (std::size_t i = 0, n_loop = loop_points.size(); i < n_loop && !wall_state[p]; ++i) {
        const Vec3 a = loop_points[(i + 1) % n_loop] - loop_points[i],
                   b = loop_points[(i + n_loop - 1) % n_loop] - loop_points[i];
        wall_state[p] = !(a.cross(b).norm() > sin_min * a.norm() * b.norm() || a.dot(b) < 0);
      }
      double vol = 0;
      const std::size_t k = loop_points.size();
      if (tri.fan())
        for (std::size_t i = 0; i < k; ++i) vol += tri.center.dot(loop_points[i].cross(loop_points[(i + 1) % k]));
      else
        for (const auto& t : tri.triangles)
          vol += loop_points[t[0]].dot(loop_points[t[1]].cross(loop_points[t[2]]));
      wall_volume[p] = vol / voxel_volume;
      // The wall's triangles, as the tissue and the mesher make them.
      if (tri.fan()) {
        const auto centre = static_cast<std::int32_t>(n_corners + p);
        points[static_cast<std::size_t>(centre)] = tri.center;
        for (std::size_t i = 0; i < k; ++i)
          wall_tris_of[p].push_back({{centre, ids[i], ids[(i + 1) % k]}, static_cast<std::int32_t>(p)});
      } else {
        for (const auto& t : tri.triangles)
          wall_tris_of[p].push_back({{ids[t[0]], ids[t[1]], ids[t[2]]}, static_cast<std::int32_t>(p)});
      }
    }
    // Each changed wall's box (the corners of an unchanged wall and its fan centres do not move).
#pragma omp parallel for schedule(dynamic, 256)
    for (std::ptrdiff_t pp = 0; pp < static_cast<std::ptrdiff_t>(n_walls); ++pp) {
      const auto p = static_cast<std::size_t>(pp);
      if (!wall_changed[p] || wall_tris_of[p].empty()) continue;
      std::array<Vec3, 2> bx{points[wall_tris_of[p][0].v[0]], points[wall_tris_of[p][0].v[0]]};
      for (const WallTriangle& tr : wall_tris_of[p])
        for (const std::int32_t u : tr.v) bx[0] = bx[0].cwiseMin(points[u]), bx[1] = bx[1].cwiseMax(points[u]);
      wall_box[p] = bx;
    }
    const bool all_changed = std::find(wall_changed.begin(), wall_changed.end(), 0) == wall_changed.end();
    for (std::size_t p = 0; p < n_walls; ++p) {
      if (wall_state[p] == 2) {
        redoWall(p);
        continue;
      }
      if (wall_state[p] == 1) redoWall(p);
      const Face& f = faces[patch_face[p]];
      six_volume[static_cast<std::size_t>(f.first)] += wall_volume[p];
      if (f.second >= 0) six_volume[static_cast<std::size_t>(f.second)] -= wall_volume[p];
    }
    {
      // Triangles of two walls that cross (away from shared corners and edges): both walls are simplified less.
      // Pairs found through a grid of buckets; a pair is tested in the bucket holding the low corner
      // of the overlap of their bounding boxes only.
      std::vector<std::pair<std::uint64_t, std::int32_t>> buckets;
      const double bucket = 4 * std::max({s[0], s[1], s[2]});
      auto cellOf = [&](const Vec3& x) {
        std::array<std::int64_t, 3> b;
        for (int a = 0; a < 3; ++a) b[a] = static_cast<std::int64_t>(std::floor(x[a] / bucket));
        return b;
      };
      auto key = [](const std::array<std::int64_t, 3>& b) {
        return (static_cast<std::uint64_t>(b[2] & 0x1FFFFF) << 42) |
               (static_cast<std::uint64_t>(b[1] & 0x1FFFFF) << 21) | static_cast<std::uint64_t>(b[0] & 0x1FFFFF);
      };
      auto boxOf = [&](const auto& ids) {
        std::array<Vec3, 2> b{points[ids[0]], points[ids[0]]};
        for (const std::int32_t u : ids) b[0] = b[0].cwiseMin(points[u]), b[1] = b[1].cwiseMax(points[u]);
        return b;
      };
      auto forBucketsOf = [&](const std::array<Vec3, 2>& bx, const auto& f) {
        const auto b0 = cellOf(bx[0]), b1 = cellOf(bx[1]);
        for (std::int64_t z = b0[2]; z <= b1[2]; ++z)
          for (std::int64_t y = b0[1]; y <= b1[1]; ++y)
            for (std::int64_t x = b0[0]; x <= b1[0]; ++x) f(key({x, y, z}));
      };
      // Only buckets holding a changed wall's triangle can hold a pair to test: the unchanged walls' triangles
      // go into those only (after the first round, most walls are unchanged), and only the walls whose box
      // (of its corners and fan centre) meets one of those buckets are looked at, in wall order.
      std::vector<std::uint64_t> hot;  // the buckets of the changed walls' triangles
      std::vector<char> near(n_walls, 0);
      for (std::size_t p = 0; p < n_walls; ++p) near[p] = wall_state[p] != 2 && (all_changed || wall_changed[p]);
      if (!all_changed) {
        for (std::size_t p = 0; p < n_walls; ++p)
          if (near[p])
            for (const WallTriangle& tr : wall_tris_of[p]) forBucketsOf(boxOf(tr.v), [&](std::uint64_t k) {
              hot.push_back(k);
            });
        std::sort(hot.begin(), hot.end());
        hot.erase(std::unique(hot.begin(), hot.end()), hot.end());
        // Whether a wall's box meets a hot bucket: a count of the hot buckets in a box of buckets, from the
        // prefix sums of a dense grid of them over the hot buckets' range (bucket coordinates taken back from
        // the keys: 21 bits each, two's complement).
        auto coord = [](std::uint64_t k, int a) {
          const auto c = static_cast<std::int64_t>((k >> (21 * a)) & 0x1FFFFF);
          return c >= (std::int64_t{1} << 20) ? c - (std::int64_t{1} << 21) : c;
        };
        std::array<std::int64_t, 3> hlo{0, 0, 0}, hhi{-1, -1, -1};
        for (std::size_t i = 0; i < hot.size(); ++i)
          for (int a = 0; a < 3; ++a) {
            const std::int64_t c = coord(hot[i], a);
            hlo[a] = i == 0 ? c : std::min(hlo[a], c), hhi[a] = i == 0 ? c : std::max(hhi[a], c);
          }
        std::array<std::size_t, 3> hd{};
        for (int a = 0; a < 3; ++a) hd[a] = static_cast<std::size_t>(hhi[a] - hlo[a] + 2);  // one more: sums
        std::vector<std::int32_t> hot_sum(hot.empty() ? 0 : hd[0] * hd[1] * hd[2], 0);
        auto at = [&](std::size_t x, std::size_t y, std::size_t z) -> std::int32_t& {
          return hot_sum[x + hd[0] * (y + hd[1] * z)];
        };
        for (const std::uint64_t k : hot)
          at(static_cast<std::size_t>(coord(k, 0) - hlo[0]) + 1, static_cast<std::size_t>(coord(k, 1) - hlo[1]) + 1,
             static_cast<std::size_t>(coord(k, 2) - hlo[2]) + 1) = 1;
        for (std::size_t z = 1; z < hd[2] && !hot.empty(); ++z)
          for (std::size_t y = 1; y < hd[1]; ++y)
            for (std::size_t x = 1; x < hd[0]; ++x)
              at(x, y, z) += at(x - 1, y, z) + at(x, y - 1, z) + at(x, y, z - 1) - at(x - 1, y - 1, z) -
                             at(x - 1, y, z - 1) - at(x, y - 1, z - 1) + at(x - 1, y - 1, z - 1);
        auto meetsHot = [&](const std::array<Vec3, 2>& bx) {
          auto b0 = cellOf(bx[0]), b1 = cellOf(bx[1]);
          std::array<std::size_t, 3> bl{}, bh{};
          for (int a = 0; a < 3; ++a) {
            b0[a] = std::max(b0[a], hlo[a]), b1[a] = std::min(b1[a], hhi[a]);
            if (b0[a] > b1[a]) return false;
            bl[a] = static_cast<std::size_t>(b0[a] - hlo[a]), bh[a] = static_cast<std::size_t>(b1[a] - hlo[a]) + 1;
          }
          return at(bh[0], bh[1], bh[2]) - at(bl[0], bh[1], bh[2]) - at(bh[0], bl[1], bh[2]) -
                     at(bh[0], bh[1], bl[2]) + at(bl[0], bl[1], bh[2]) + at(bl[0], bh[1], bl[2]) +
                     at(bh[0], bl[1], bl[2]) - at(bl[0], bl[1], bl[2]) >
                 0;
        };
        for (std::size_t p = 0; p < n_walls && !hot.empty(); ++p) {
          if (near[p] || wall_state[p] == 2 || wall_tris_of[p].empty()) continue;
          near[p] = meetsHot(wall_box[p]);
        }
      }
      std::vector<WallTriangle> wall_tris;  // of the walls near a changed one, in wall order
      for (std::size_t p = 0; p < n_walls; ++p)
        if (near[p]) wall_tris.insert(wall_tris.end(), wall_tris_of[p].begin(), wall_tris_of[p].end());
      std::vector<std::array<Vec3, 2>> box(wall_tris.size());
      for (std::size_t t = 0; t < wall_tris.size(); ++t) box[t] = boxOf(wall_tris[t].v);
      auto forBuckets = [&](std::size_t t, const auto& f) { forBucketsOf(box[t], f); };
      // The buckets' runs of triangles, each in triangle (so wall) order: entry_tri[group_start[g] ..
      // group_start[g + 1]) in the bucket group_key[g], the buckets in key order ((z, y, x) lexicographic).
      std::vector<std::int32_t> entry_tri;
      std::vector<std::size_t> group_start;
      std::vector<std::uint64_t> group_key;
      bool in_grid = true;  // every bucket coordinate >= 0 (true: corners and centres lie in the padded grid)
      for (std::size_t t = 0; t < box.size() && in_grid; ++t) in_grid = (box[t][0].array() >= 0).all();
      if (all_changed && in_grid) {
        // Every triangle: a counting sort over the dense grid of buckets (no list of (bucket, triangle) pairs
        // to sort: at 512^3 with every staircase corner kept it holds 3e7 of them).
        std::array<std::int64_t, 3> nb{1, 1, 1};
        for (std::size_t t = 0; t < wall_tris.size(); ++t) {
          const auto b1 = cellOf(box[t][1]);
          for (int a = 0; a < 3; ++a) nb[a] = std::max(nb[a], b1[a] + 1);
        }
        const auto bucket_nx = static_cast<std::size_t>(nb[0]), bucket_ny = static_cast<std::size_t>(nb[1]);
        auto dense = [&](std::uint64_t k) {
          return static_cast<std::size_t>(k & 0x1FFFFF) +
                 bucket_nx * (static_cast<std::size_t>((k >> 21) & 0x1FFFFF) +
                              bucket_ny * static_cast<std::size_t>(k >> 42));
        };
        const std::size_t n_buckets = static_cast<std::size_t>(nb[0] * nb[1] * nb[2]);
        std::vector<std::size_t> start(n_buckets + 1, 0);
        for (std::size_t t = 0; t < wall_tris.size(); ++t)
          forBuckets(t, [&](std::uint64_t k) { ++start[dense(k) + 1]; });
        for (std::size_t b = 0; b < n_buckets; ++b) start[b + 1] += start[b];
        entry_tri.resize(start[n_buckets]);
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (std::size_t t = 0; t < wall_tris.size(); ++t)
          forBuckets(t, [&](std::uint64_t k) { entry_tri[fill[dense(k)]++] = static_cast<std::int32_t>(t); });
        std::vector<std::size_t>().swap(fill);
        for (std::size_t b = 0; b < n_buckets; ++b)
          if (start[b + 1] > start[b]) {
            group_start.push_back(start[b]);
            const std::uint64_t x = b % bucket_nx, y = (b / bucket_nx) % bucket_ny, z = b / (bucket_nx * bucket_ny);
            group_key.push_back((z << 42) | (y << 21) | x);
          }
        group_start.push_back(entry_tri.size());
      } else {  // (bucket, triangle) pairs, sorted
        for (std::size_t t = 0; t < wall_tris.size(); ++t)
          if (wall_changed[wall_tris[t].wall])
            forBuckets(t, [&](std::uint64_t k) { buckets.emplace_back(k, static_cast<std::int32_t>(t)); });
        for (std::size_t t = 0; t < wall_tris.size() && !hot.empty() && !all_changed; ++t)
          if (!wall_changed[wall_tris[t].wall])
            forBuckets(t, [&](std::uint64_t k) {
              if (std::binary_search(hot.begin(), hot.end(), k)) buckets.emplace_back(k, static_cast<std::int32_t>(t));
            });
        std::sort(buckets.begin(), buckets.end());
        for (std::size_t i = 0; i < buckets.size(); ++i) {
          if (i == 0 || buckets[i].first != buckets[i - 1].first)
            group_start.push_back(i), group_key.push_back(buckets[i].first);
          entry_tri.push_back(buckets[i].second);
        }
        group_start.push_back(buckets.size());
      }
      const double slack = 1e-9 * bucket;
#pragma omp parallel for schedule(dynamic, 256)
      for (std::ptrdiff_t gi = 0; gi < static_cast<std::ptrdiff_t>(group_start.size()) - 1; ++gi) {
        const std::size_t i = group_start[static_cast<std::size_t>(gi)],
                          j = group_start[static_cast<std::size_t>(gi) + 1];
        // A bucket's triangles are in wall (and face) order: each is tested against those of the faces after its
        // own (a wall made of several faces: each is a wall of the tissue, tested against the others).
        std::size_t next_wall = i;
        for (std::size_t a = i; a < j; ++a) {
          const std::int32_t x = entry_tri[a];
          const WallTriangle& ta = wall_tris[x];
          if (next_wall <= a)
            for (next_wall = a + 1; next_wall < j && wall_tris[entry_tri[next_wall]].wall == ta.wall &&
                                    wall_tris[entry_tri[next_wall]].face == ta.face;)
              ++next_wall;
          for (std::size_t b = next_wall; b < j; ++b) {
            const std::int32_t y = entry_tri[b];
            const WallTriangle& tb = wall_tris[y];
            if (!(wall_changed[ta.wall] || wall_changed[tb.wall])) continue;
            const Vec3 lo_o = box[x][0].cwiseMax(box[y][0]), hi_o = box[x][1].cwiseMin(box[y][1]);
            if ((lo_o.array() > hi_o.array() + slack).any()) continue;
            if (key(cellOf(lo_o)) != group_key[static_cast<std::size_t>(gi)]) continue;
            if (trianglesCross(ta.v, tb.v, points)) redoWallShared(ta.wall), redoWallShared(tb.wall);
          }
        }
      }
      any = any || std::find(flagged.begin(), flagged.end(), 1) != flagged.end();
    }
    for (std::size_t c = 0; c < n_cells; ++c)
      if (six_volume[c] < 3.0 * static_cast<double>(pieces[order[c]].voxels))  // lost more than half its volume
        for (const Index p : cell_walls[c]) redoWall(p);
    if (!any) break;
    // The junction lines as the repairs left them, walls still failing: each made of several faces, once.
    // The flagged walls are all tested again (a wall flagged with one made of faces now may pass).
    auto interiorRound = [&] {
      // A wall made of faces (or that could not be) and still failing gets its junction lines back on their
      // voxel corners, every corner kept; the walls of faces along them are made again on the new boundary.
      std::fill(wall_changed.begin(), wall_changed.end(), 0);
      std::vector<char> todo_mark(n_walls, 0);
      std::size_t progress = 0;
      auto restore = [&](std::size_t p) {
        for (const std::int32_t pl : wall_polylines[p]) {
          if (line_restored[static_cast<std::size_t>(pl)]) continue;
          line_restored[static_cast<std::size_t>(pl)] = 1;
          ++progress;
          Polyline& line = polylines[static_cast<std::size_t>(pl)];
          line.tol = -1;
          simplifyPolyline(line, pos, keep);
          for (const std::int32_t u : line.chain) {
            pos[u] = voxel_pos[u];
            points[u] = Vec3(pos[u].x() * s[0], pos[u].y() * s[1], pos[u].z() * s[2]);
          }
          for (const std::int32_t wl : polyline_walls[static_cast<std::size_t>(pl)]) {
            const auto ww = static_cast<std::size_t>(wl);
            wall_changed[ww] = 1;
            restored_wall[ww] = 1;
            interior_tried[ww] = 0;
            if (!wall_faces[ww].empty() || ww == p) {
              wall_faces[ww].clear(), todo_mark[ww] = 1;
              for (const auto& e : wall_chords[ww]) chord_owner.erase(e);
              wall_chords[ww].clear();
            }
          }
        }
      };
      for (std::size_t p = 0; p < n_walls; ++p) {
        if (!flagged[p]) continue;
        if (interior_tried[p]) restore(p);
        else todo_mark[p] = 1;
      }
      for (;;) {
        std::vector<std::size_t> todo;
        for (std::size_t p = 0; p < n_walls; ++p)
          if (todo_mark[p]) todo.push_back(p), todo_mark[p] = 0;
        if (todo.empty()) break;
        progress += makeInteriors(todo);
        for (const std::size_t p : todo)
          if (wall_faces[p].empty()) restore(p);  // could not be made of faces on this boundary
      }
      if (progress == 0) return false;
      for (std::size_t p = 0; p < n_walls; ++p) {
        if (flagged[p]) wall_changed[p] = 1;
        unresolved[p] = 0;
      }
      return true;
    };
    if (interiors) {
      if (interiorRound()) continue;
      for (std::size_t p = 0; p < n_walls; ++p)
        if (flagged[p]) failing.push_back(p);
      break;
    }
    // Simplify less along the flagged walls' junction lines: half the tolerance, down to 1/64 voxel, then every
    // corner (simplify > 0); then smooth them further; at simplify 0, then simplify them after all (below).
    bool changed = false;
    std::fill(wall_changed.begin(), wall_changed.end(), 0);
    for (std::size_t k = 0; k < polylines.size() && o.simplify > 0; ++k) {
      if (!redo[k] || polylines[k].tol < 0) continue;
      polylines[k].tol = polylines[k].tol > 1.0 / 64 ? polylines[k].tol / 2 : -1;
      simplifyPolyline(polylines[k], pos, keep);
      changed = true;
      for (const std::int32_t p : polyline_walls[k]) wall_changed[static_cast<std::size_t>(p)] = 1, refined[p] = 1;
    }
    auto smoothAgain = [&](std::size_t k) {
      const auto& ch = polylines[k].chain;
      if (ch.size() < 3) return;
      // At simplify 0, of the lines with the same two ends only the first is smoothed further: smoothed on, two
      // such lines tend to the same chord and their corners meet (a pinched wall).
      if (o.simplify == 0 && !smoothedLine(k)) return;
      smoothLine(ch);
      for (const std::int32_t u : ch) points[u] = Vec3(pos[u].x() * s[0], pos[u].y() * s[1], pos[u].z() * s[2]);
      changed = true;
      for (const std::int32_t p : polyline_walls[k]) wall_changed[static_cast<std::size_t>(p)] = 1, refined[p] = 1;
    };
    if (!changed && extra_smoothing < max_extra_smoothing) {
      // Every corner kept: smooth the flagged walls' junction lines further (as above, as many passes again).
      ++extra_smoothing;
      for (std::size_t k = 0; k < polylines.size(); ++k)
        if (redo[k]) smoothAgain(k);
    } else if (!changed && o.simplify == 0) {
      // The staircase still failing once smoothed: its junction lines are smoothed once more and simplified
      // with 1/4 voxel, then twice that, up to kStaircaseMaxTolerance (fewer, longer segments: the fans
      // through them follow the voxel interface less closely, which is what separates some thin cells').
      for (std::size_t k = 0; k < polylines.size(); ++k) {
        Polyline& pl = polylines[k];
        if (!redo[k] || pl.tol >= kStaircaseMaxTolerance) continue;
        pl.tol = pl.tol <= 0 ? 0.25 : 2 * pl.tol;
        // A line sharing both ends with another keeps an inner corner (two straight ones would be one edge).
        pl.keep_one = pl.keep_one || (pl.chain.front() != pl.chain.back() &&
                                      same_ends[std::minmax(pl.chain.front(), pl.chain.back())] > 1);
        smoothAgain(k);
        simplifyPolyline(pl, pos, keep);
        changed = true;
        for (const std::int32_t p : polyline_walls[k])
          wall_changed[static_cast<std::size_t>(p)] = 1, refined[p] = 1, coarsened[p] = 1;
      }
    }
    for (std::size_t p = 0; p < n_walls; ++p) unresolved[p] = flagged[p] && !wall_changed[p];
    if (!changed) {  // every repair of the junction lines tried: walls of several faces (above), else reported
      interiors = true;
      if (interiorRound()) continue;
      for (std::size_t p = 0; p < n_walls; ++p)
        if (flagged[p]) failing.push_back(p);
      break;
    }
  }
  // A wall is one polygon through its boundary loop: walls that bend around a small cell can flatten it.
  for (std::size_t c = 0; c < n_cells; ++c)
    if (six_volume[c] < 1.5 * static_cast<double>(pieces[order[c]].voxels))
      throw InputError(file + ": " + labelName(static_cast<std::int32_t>(c)) + " (" +
                       std::to_string(pieces[order[c]].voxels) + " voxels, one at " +
                       voxelName(pieces[order[c]].first) +
                       "): the polygons through its walls' boundary loops enclose " + formatNumber(six_volume[c] / 6) +
                       " voxels, under a quarter of its own (its walls bend around it: a wall is one polygon "
                       "through its junction lines); drop or merge it (min_cell_size, small_cells)");

  // The complex: kept corners in world coordinates, walls as loops, cells as wall lists.
  ComplexFile m;
  m.path = img.name;
  m.volume_noun = "cell";
  m.face_noun = "wall";
  m.face_origin = "the interface of two labels";
  std::vector<Index> new_index(n_corners, kInvalidIndex);
  for (std::size_t u = 0; u < n_corners; ++u)
    if (keep[u]) {
      new_index[u] = static_cast<Index>(m.positions.size());
      Vec3 x;
      for (int a = 0; a < 3; ++a) x[a] = img.origin[a] + (pos[u][a] - 1.0 + static_cast<double>(lo[a]) - 0.5) * s[a];
      m.positions.push_back(x);
    }
  // The interior vertices of walls of several faces, those their triangles use, after the corners.
  std::unordered_map<std::int32_t, Index> interior_index;
  std::size_t n_faces_walls = 0, n_faces_made = 0;
  for (std::size_t p = 0; p < n_walls; ++p) {
    n_faces_walls += !wall_faces[p].empty();
    n_faces_made += wall_faces[p].size();
    for (const auto& t : wall_faces[p])
      for (const std::int32_t u : t)
        if (static_cast<std::size_t>(u) >= n_corners && !interior_index.count(u)) {
          interior_index[u] = static_cast<Index>(m.positions.size());
          const Vec3& x = points[static_cast<std::size_t>(u)];
          Vec3 y;
          for (int a = 0; a < 3; ++a)
            y[a] = img.origin[a] + (x[a] / s[a] - 1.0 + static_cast<double>(lo[a]) - 0.5) * s[a];
          m.positions.push_back(y);
        }
  }
  m.face_offsets = {0};
  std::vector<Index> first_face(n_walls + 1, 0);  // the faces of wall p: first_face[p] .. first_face[p + 1]
  for (std::size_t p = 0; p < n_walls; ++p) {
    if (wall_faces[p].empty()) {
      for (const std::int32_t u : loops[p])
        if (keep[u]) m.face_vertices.push_back(new_index[u]);
      m.face_offsets.push_back(m.face_vertices.size());
    } else {
      for (const auto& t : wall_faces[p]) {
        for (const std::int32_t u : t)
          m.face_vertices.push_back(static_cast<std::size_t>(u) < n_corners ? new_index[static_cast<std::size_t>(u)]
                                                                            : interior_index.at(u));
        m.face_offsets.push_back(m.face_vertices.size());
      }
    }
    first_face[p + 1] = static_cast<Index>(m.face_offsets.size() - 1);
  }
  m.volume_offsets = {0};
  for (std::size_t c = 0; c < n_cells; ++c) {
    for (const Index p : cell_walls[c])
      for (Index f = first_face[p]; f < first_face[p + 1]; ++f) m.volume_faces.push_back(f);
    m.volume_offsets.push_back(m.volume_faces.size());
    m.volume_label.push_back(cell_label[c]);
  }
  report.file_vertices = 0;
  const std::size_t n_kept = m.positions.size() - interior_index.size();
  report.simplified_vertices = n_corners - n_kept;
  report.notes.push_back(std::to_string(n_cells) + " cells, " + std::to_string(n_walls) + " walls, " +
                         std::to_string(polylines.size()) + " junction lines; " + std::to_string(n_kept) +
                         " of " + std::to_string(n_corners) + " junction-line voxel corners kept (simplify " +
                         formatNumber(o.simplify) + " voxels)");
  if (const auto n_refined = std::count(refined.begin(), refined.end(), 1); n_refined > 0)
    report.notes.push_back(
        std::to_string(n_refined) +
        (o.simplify > 0 ? " wall(s) simplified less than asked along some of their junction lines (down to every "
                          "corner, then smoothed further) so that no two walls cross"
                        : " wall(s) smoothed further along some of their junction lines (" +
                              std::to_string(std::count(coarsened.begin(), coarsened.end(), 1)) +
                              " of them then simplified, up to " + formatNumber(kStaircaseMaxTolerance) +
                              " voxels) so that no two walls cross"));
  if (n_faces_walls > 0) {
    const auto n_lines = std::count(line_restored.begin(), line_restored.end(), 1);
    const auto n_along = std::count(restored_wall.begin(), restored_wall.end(), 1);
    report.notes.push_back(std::to_string(n_faces_walls) + " wall(s) made of the triangles of their voxel interface "
                           "(" + std::to_string(n_faces_made) + " faces, " + std::to_string(interior_index.size()) +
                           " vertices inside them) so that no two walls cross" +
                           (n_lines > 0 ? "; " + std::to_string(n_lines) + " junction line(s) of " +
                                              std::to_string(n_along) + " wall(s) put back on their voxel corners"
                                        : std::string()));
  }
  if (!failing.empty()) {
    std::string pairs;
    for (std::size_t k = 0; k < failing.size() && k < 5; ++k) {
      const Face& f = faces[patch_face[failing[k]]];
      pairs += (k ? "; " : "") + labelName(f.first) + " and " + labelName(f.second);
    }
    report.notes.push_back(std::to_string(failing.size()) +
                           " wall(s) still cross another wall or fail the polygon checks with every repair tried "
                           "(voxel-scale features), between " + pairs + (failing.size() > 5 ? "; ..." : "") +
                           ": the mesher will refuse the tissue; merge or drop one of the labels");
  }
  ImportOptions core = o;
  core.simplify = 0;  // done above, in voxels
  result = importComplex(m, core, std::move(report));
  return result;
}

}  // namespace tessella::io::detail
