// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/assembly_pattern.hpp"

#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/errors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <sstream>
#include <string>

namespace tessella::solvers {

namespace {

// Measure and hat-function gradients of element e, no allocation. Tetrahedra
// by cofactors (grad lambda_k = (e_{k+1} x e_{k+2}) / det); triangles (flat or
// curved, in R^3) through elementGeometry. Same degeneracy test as
// elementGeometry, which is called to raise its error.
inline double geometry(const mesh::FeMesh& mesh, int e, double g[4][3]) {
  if (mesh.dim == 3) {
    const double* x0 = &mesh.nodes(mesh.elements(e, 0), 0);
    double v[3][3];
    double hmax2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double* x = &mesh.nodes(mesh.elements(e, k + 1), 0);
      for (int c = 0; c < 3; ++c) v[k][c] = x[c] - x0[c];
      hmax2 = std::max(hmax2, v[k][0] * v[k][0] + v[k][1] * v[k][1] + v[k][2] * v[k][2]);
    }
    for (int k = 0; k < 3; ++k) {
      const double* a = v[(k + 1) % 3];
      const double* b = v[(k + 2) % 3];
      g[k + 1][0] = a[1] * b[2] - a[2] * b[1];
      g[k + 1][1] = a[2] * b[0] - a[0] * b[2];
      g[k + 1][2] = a[0] * b[1] - a[1] * b[0];
    }
    const double det = v[0][0] * g[1][0] + v[0][1] * g[1][1] + v[0][2] * g[1][2];
    const double measure = std::abs(det) / 6.0;
    if (!(measure > 1e-13 * hmax2 * std::sqrt(hmax2))) {
      const ElementGeometry eg = elementGeometry(mesh, e);  // throws for a degenerate element
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) g[a][c] = eg.gradients(a, c);
      return eg.measure;
    }
    const double inv = 1.0 / det;
    for (int c = 0; c < 3; ++c) {
      for (int k = 1; k < 4; ++k) g[k][c] *= inv;
      g[0][c] = -(g[1][c] + g[2][c] + g[3][c]);
    }
    return measure;
  }
  const ElementGeometry eg = elementGeometry(mesh, e);
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) g[a][c] = eg.gradients(a, c);
  return eg.measure;
}

}  // namespace

AssemblyPattern::AssemblyPattern(const mesh::FeMesh& mesh) : dim_(mesh.dim), num_elements_(mesh.numElements()) {
  checkMesh(mesh);
  const int n = mesh.numNodes();
  const int ne = num_elements_;
  const int nn = dim_ + 1;

  // Node -> incident elements (in element order).
  std::vector<int> node_ptr(static_cast<std::size_t>(n) + 1, 0);
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < nn; ++a) ++node_ptr[static_cast<std::size_t>(mesh.elements(e, a)) + 1];
  for (int i = 0; i < n; ++i) node_ptr[static_cast<std::size_t>(i) + 1] += node_ptr[static_cast<std::size_t>(i)];
  std::vector<int> node_elems(static_cast<std::size_t>(node_ptr.back()));
  {
    std::vector<int> fill(node_ptr.begin(), node_ptr.end() - 1);
    for (int e = 0; e < ne; ++e)
      for (int a = 0; a < nn; ++a) node_elems[static_cast<std::size_t>(fill[static_cast<std::size_t>(mesh.elements(e, a))]++)] = e;
  }

  // Column j holds the nodes sharing an element with j (sorted): count, then
  // fill. A per-thread marker (last column that saw node i) drops duplicates
  // before the sort.
  auto neighbours = [&](int j, std::vector<int>& buf, std::vector<int>& seen) {
    buf.clear();
    for (int p = node_ptr[static_cast<std::size_t>(j)]; p < node_ptr[static_cast<std::size_t>(j) + 1]; ++p)
      for (int a = 0; a < nn; ++a) {
        const int i = mesh.elements(node_elems[static_cast<std::size_t>(p)], a);
        if (seen[static_cast<std::size_t>(i)] != j) {
          seen[static_cast<std::size_t>(i)] = j;
          buf.push_back(i);
        }
      }
    std::sort(buf.begin(), buf.end());
  };
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
#pragma omp parallel
  {
    std::vector<int> buf, seen(static_cast<std::size_t>(n), -1);
#pragma omp for schedule(static)
    for (int j = 0; j < n; ++j) {
      neighbours(j, buf, seen);
      outer[static_cast<std::size_t>(j) + 1] = static_cast<int>(buf.size());
    }
  }
  std::int64_t total = 0;
  for (int j = 0; j < n; ++j) {
    total += outer[static_cast<std::size_t>(j) + 1];
    if (total > std::numeric_limits<int>::max())
      throw InvalidProblemError("AssemblyPattern: more than 2^31 nonzeros; the mesh is too large for int indices");
    outer[static_cast<std::size_t>(j) + 1] = static_cast<int>(total);
  }
  structure_.resize(n, n);
  structure_.resizeNonZeros(static_cast<Eigen::Index>(total));
  std::copy(outer.begin(), outer.end(), structure_.outerIndexPtr());
  int* inner = structure_.innerIndexPtr();
#pragma omp parallel
  {
    std::vector<int> buf, seen(static_cast<std::size_t>(n), -1);
#pragma omp for schedule(static)
    for (int j = 0; j < n; ++j) {
      neighbours(j, buf, seen);
      std::copy(buf.begin(), buf.end(), inner + outer[static_cast<std::size_t>(j)]);
    }
  }
  std::fill(structure_.valuePtr(), structure_.valuePtr() + total, 0.0);

  // Chunks: runs of kChunk elements in order of their smallest node (elements
  // near in the node numbering are near in memory: the chunk's writes stay in
  // cache). Greedy colouring of the chunks in that order: the smallest colour
  // unused at all the chunk's nodes (per-node bit masks, widened on demand).
  std::vector<int> base(static_cast<std::size_t>(ne));
  {
    std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
    auto minNode = [&](int e) {
      int m = mesh.elements(e, 0);
      for (int a = 1; a < nn; ++a) m = std::min(m, mesh.elements(e, a));
      return m;
    };
    for (int e = 0; e < ne; ++e) ++start[static_cast<std::size_t>(minNode(e)) + 1];
    for (int i = 0; i < n; ++i) start[static_cast<std::size_t>(i) + 1] += start[static_cast<std::size_t>(i)];
    for (int e = 0; e < ne; ++e) base[static_cast<std::size_t>(start[static_cast<std::size_t>(minNode(e))]++)] = e;
  }
  const int num_chunks = (ne + kChunk - 1) / kChunk;
  int words = 1;
  std::vector<std::uint64_t> used(static_cast<std::size_t>(n), 0);
  std::vector<int> chunk_colour(static_cast<std::size_t>(num_chunks));
  std::vector<int> chunk_nodes;
  int num_colours = 0;
  for (int q = 0; q < num_chunks; ++q) {
    chunk_nodes.clear();
    for (int p = q * kChunk; p < std::min(ne, (q + 1) * kChunk); ++p)
      for (int a = 0; a < nn; ++a) chunk_nodes.push_back(mesh.elements(base[static_cast<std::size_t>(p)], a));
    int c = -1;
    for (int w = 0; w < words && c < 0; ++w) {
      std::uint64_t taken = 0;
      for (int i : chunk_nodes) taken |= used[static_cast<std::size_t>(i) * words + w];
      if (~taken) c = 64 * w + std::countr_one(taken);
    }
    if (c < 0) {  // all colours taken: one more word per node
      std::vector<std::uint64_t> wider(static_cast<std::size_t>(n) * (words + 1), 0);
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i)
        std::copy_n(&used[i * words], words, &wider[i * (words + 1)]);
      used.swap(wider);
      c = 64 * words;
      ++words;
    }
    for (int i : chunk_nodes) used[static_cast<std::size_t>(i) * words + c / 64] |= std::uint64_t{1} << (c % 64);
    chunk_colour[static_cast<std::size_t>(q)] = c;
    num_colours = std::max(num_colours, c + 1);
  }
  // Group the chunks by colour (stable), and the elements with their chunk.
  colour_ptr_.assign(static_cast<std::size_t>(num_colours) + 1, 0);
  for (int c : chunk_colour) ++colour_ptr_[static_cast<std::size_t>(c) + 1];
  for (int k = 0; k < num_colours; ++k) colour_ptr_[static_cast<std::size_t>(k) + 1] += colour_ptr_[static_cast<std::size_t>(k)];
  std::vector<int> chunk_order(static_cast<std::size_t>(num_chunks));
  {
    std::vector<int> fill(colour_ptr_.begin(), colour_ptr_.end() - 1);
    for (int q = 0; q < num_chunks; ++q) chunk_order[static_cast<std::size_t>(fill[static_cast<std::size_t>(chunk_colour[static_cast<std::size_t>(q)])]++)] = q;
  }
  order_.clear();
  order_.reserve(static_cast<std::size_t>(ne));
  chunk_ptr_.assign(1, 0);
  for (int q : chunk_order) {
    for (int p = q * kChunk; p < std::min(ne, (q + 1) * kChunk); ++p) order_.push_back(base[static_cast<std::size_t>(p)]);
    chunk_ptr_.push_back(static_cast<int>(order_.size()));
  }

  // Slot of entry (a, b) of the element at position p: row node a within column node b.
  const std::size_t block = static_cast<std::size_t>(nn) * static_cast<std::size_t>(nn);
  slots_.resize(static_cast<std::size_t>(ne) * block);
#pragma omp parallel for schedule(static)
  for (int p = 0; p < ne; ++p) {
    const int e = order_[static_cast<std::size_t>(p)];
    int* s = &slots_[static_cast<std::size_t>(p) * block];
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b) {
        const int col = mesh.elements(e, b);
        const int* first = inner + outer[static_cast<std::size_t>(col)];
        const int* last = inner + outer[static_cast<std::size_t>(col) + 1];
        s[a * nn + b] = static_cast<int>(std::lower_bound(first, last, mesh.elements(e, a)) - inner);
      }
  }
}

void AssemblyPattern::prepare(const mesh::FeMesh& mesh, const Eigen::VectorXd& c, const char* what, SparseMatrix& out) const {
  if (mesh.dim != dim_ || mesh.numNodes() != numNodes() || mesh.numElements() != num_elements_) {
    std::ostringstream msg;
    msg << what << ": mesh (dim " << mesh.dim << ", " << mesh.numNodes() << " nodes, " << mesh.numElements()
        << " elements) is not the one the pattern was built from (dim " << dim_ << ", " << numNodes() << " nodes, "
        << num_elements_ << " elements)";
    throw InvalidProblemError(msg.str());
  }
  if (c.size() != 0 && c.size() != num_elements_) {
    std::ostringstream msg;
    msg << what << ": " << c.size() << " coefficients for " << num_elements_ << " items";
    throw InvalidProblemError(msg.str());
  }
  const auto nnz = static_cast<std::size_t>(structure_.nonZeros());
  const bool same = out.rows() == structure_.rows() && out.cols() == structure_.cols() && out.isCompressed() &&
                    static_cast<std::size_t>(out.nonZeros()) == nnz &&
                    std::memcmp(out.outerIndexPtr(), structure_.outerIndexPtr(),
                                (static_cast<std::size_t>(structure_.outerSize()) + 1) * sizeof(int)) == 0 &&
                    std::memcmp(out.innerIndexPtr(), structure_.innerIndexPtr(), nnz * sizeof(int)) == 0;
  if (same)
    std::fill(out.valuePtr(), out.valuePtr() + nnz, 0.0);
  else
    out = structure_;
}

void AssemblyPattern::assemble(const mesh::FeMesh& mesh, Kind kind, const Eigen::VectorXd& c, SparseMatrix& out) const {
  const int nn = dim_ + 1;
  const std::size_t block = static_cast<std::size_t>(nn) * static_cast<std::size_t>(nn);
  double* values = out.valuePtr();
  const double* coef = c.size() ? c.data() : nullptr;
  // Consistent P1 mass of a simplex with nn nodes: |e| / (nn (nn + 1)) * (1 + delta_ab).
  const double mass_off = 1.0 / (nn * (nn + 1));
  for (std::size_t k = 0; k + 1 < colour_ptr_.size(); ++k) {
    std::exception_ptr error;
    int error_element = std::numeric_limits<int>::max();
    // No two chunks of one colour share a node, hence no slot: race-free adds.
#pragma omp parallel for schedule(static)
    for (int q = colour_ptr_[k]; q < colour_ptr_[k + 1]; ++q) {
      for (int p = chunk_ptr_[static_cast<std::size_t>(q)]; p < chunk_ptr_[static_cast<std::size_t>(q) + 1]; ++p) {
        const int e = order_[static_cast<std::size_t>(p)];
        try {
          const int* s = &slots_[static_cast<std::size_t>(p) * block];
          const double w = coef ? coef[e] : 1.0;
          if (kind == Kind::Stiffness) {
            double g[4][3];
            const double wm = w * geometry(mesh, e, g);
            for (int a = 0; a < nn; ++a)
              for (int b = a; b < nn; ++b) {
                const double v = wm * (g[a][0] * g[b][0] + g[a][1] * g[b][1] + g[a][2] * g[b][2]);
                values[s[a * nn + b]] += v;
                if (b != a) values[s[b * nn + a]] += v;
              }
          } else {
            double g[4][3];
            const double wm = w * geometry(mesh, e, g);  // checks degeneracy like the stiffness
            if (kind == Kind::LumpedMass) {
              for (int a = 0; a < nn; ++a) values[s[a * nn + a]] += wm / nn;
            } else {
              const double off = wm * mass_off;
              for (int a = 0; a < nn; ++a)
                for (int b = 0; b < nn; ++b) values[s[a * nn + b]] += a == b ? 2.0 * off : off;
            }
          }
        } catch (...) {
#pragma omp critical(tessella_pattern_error)
          if (e < error_element) {
            error_element = e;
            error = std::current_exception();
          }
        }
      }
    }
    if (error) std::rethrow_exception(error);
  }
}

void AssemblyPattern::stiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& c, SparseMatrix& out) const {
  prepare(mesh, c, "AssemblyPattern::stiffness", out);
  assemble(mesh, Kind::Stiffness, c, out);
}

void AssemblyPattern::mass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& c, SparseMatrix& out) const {
  prepare(mesh, c, "AssemblyPattern::mass", out);
  assemble(mesh, type == MassType::Consistent ? Kind::ConsistentMass : Kind::LumpedMass, c, out);
}

SparseMatrix AssemblyPattern::stiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& c) const {
  SparseMatrix out;
  stiffness(mesh, c, out);
  return out;
}

SparseMatrix AssemblyPattern::mass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& c) const {
  SparseMatrix out;
  mass(mesh, type, c, out);
  return out;
}

}  // namespace tessella::solvers
