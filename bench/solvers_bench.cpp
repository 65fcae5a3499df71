// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// solvers_bench: assembly rate and time to solution of the P1 solvers on
// structured meshes (2D triangles, 3D Kuhn tetrahedra) of ~10^4, 10^5 and 10^6
// unknowns, for every linear-solver back-end built in.
//
// Usage: solvers_bench [--quick] [--full] [--write-meshes DIR] [--backends LIST]
//   default      ~10^4 and 10^5 nodes in 2D and 3D
//   --quick      ~10^4 nodes only
//   --full       adds ~10^6 nodes in 2D and 3D (minutes and several GB: keep it
//                for an idle machine)
//   --write-meshes DIR  also writes each mesh as raw little-endian arrays
//                (DIR/<name>.nodes: float64 N x 3, DIR/<name>.cells: int64
//                M x (d+1)) for bench/dolfinx_compare.py
//   --backends   comma list of direct,cholmod,cg,amg (default: all built)
// Problems: steady -lap u = 1 with u = 0 on x = 0 and zero flux elsewhere, and
// one implicit-Euler diffusion step (dt = 1e-3) from u = 0 of the same problem.
// Each measurement is one line; lines starting with RESULT are key=value for
// scripts. No assertions (the tests check correctness).

#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/assembly_pattern.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/facets.hpp"
#include "tessella/solvers/linear_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "bench_args.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Unit square or cube, n cells per side; the x = 0 side is wall 0 (its facets
// are the only wall facets: enough for a Dirichlet condition).
FeMesh structured(int dim, int n) {
  FeMesh m;
  m.dim = dim;
  const int np = n + 1;
  const int nodes = dim == 2 ? np * np : np * np * np;
  m.nodes.resize(nodes, 3);
  auto id = [np](int i, int j, int k) { return (k * np + j) * np + i; };
  for (int k = 0; k < (dim == 3 ? np : 1); ++k)
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) m.nodes.row(id(i, j, k)) << double(i) / n, double(j) / n, double(k) / n;
  std::vector<int> facet_nodes;
  if (dim == 2) {
    m.elements.resize(2 * n * n, 3);
    int e = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        m.elements.row(e++) << id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0);
        m.elements.row(e++) << id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0);
      }
    for (int j = 0; j < n; ++j) facet_nodes.insert(facet_nodes.end(), {id(0, j, 0), id(0, j + 1, 0)});
  } else {
    // Kuhn subdivision (6 tetrahedra per cube along the 000-111 diagonal).
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    m.elements.resize(6 * n * n * n, 4);
    int e = 0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          for (const auto& p : perms) {
            int c[3] = {i, j, k};
            int t[4];
            t[0] = id(c[0], c[1], c[2]);
            for (int s = 0; s < 3; ++s) {
              ++c[p[s]];
              t[s + 1] = id(c[0], c[1], c[2]);
            }
            // Odd permutations are negatively oriented: swap two nodes.
            const bool odd = (p[0] == 0 && p[1] == 2) || (p[0] == 1 && p[1] == 0) || (p[0] == 2 && p[1] == 1);
            if (odd) std::swap(t[2], t[3]);
            m.elements.row(e++) << t[0], t[1], t[2], t[3];
          }
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        facet_nodes.insert(facet_nodes.end(), {id(0, j, k), id(0, j + 1, k), id(0, j + 1, k + 1), id(0, j, k),
                                               id(0, j + 1, k + 1), id(0, j, k + 1)});
  }
  m.element_cell = Eigen::VectorXi::Zero(m.numElements());
  const int nf = static_cast<int>(facet_nodes.size()) / dim;
  m.wall_facets.resize(nf, dim);
  for (int f = 0; f < nf; ++f)
    for (int a = 0; a < dim; ++a) m.wall_facets(f, a) = facet_nodes[static_cast<std::size_t>(f * dim + a)];
  m.facet_wall = Eigen::VectorXi::Zero(nf);
  m.facet_on_boundary = Eigen::Matrix<bool, Eigen::Dynamic, 1>::Constant(nf, true);
  m.node_vertex = Eigen::VectorXi::Constant(m.numNodes(), -1);
  return m;
}

struct Config {
  std::vector<SolverMethod> backends;
  std::string mesh_dir;
};

const char* key(SolverMethod m) {
  switch (m) {
    case SolverMethod::Direct: return "direct";
    case SolverMethod::Cholmod: return "cholmod";
    case SolverMethod::ConjugateGradient: return "cg";
    case SolverMethod::AmgCG: return "amg";
    default: return "auto";
  }
}

void writeMesh(const FeMesh& m, const std::string& dir, const std::string& name) {
  const std::string base = dir + "/" + name;
  std::FILE* f = std::fopen((base + ".nodes").c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + base + ".nodes");
  std::fwrite(m.nodes.data(), sizeof(double), static_cast<std::size_t>(m.nodes.size()), f);
  std::fclose(f);
  const Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> cells =
      m.elements.cast<std::int64_t>();
  f = std::fopen((base + ".cells").c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + base + ".cells");
  std::fwrite(cells.data(), sizeof(std::int64_t), static_cast<std::size_t>(cells.size()), f);
  std::fclose(f);
}

void run(int dim, int n, const Config& cfg) {
  const FeMesh m = structured(dim, n);
  const std::string name = std::to_string(dim) + "d_" + std::to_string(n);
  std::printf("mesh %s  dim %d  n %d  nodes %d  elements %d\n", name.c_str(), dim, n, m.numNodes(), m.numElements());
  if (!cfg.mesh_dir.empty()) writeMesh(m, cfg.mesh_dir, name);
  const int max_threads = omp_get_max_threads();
  for (int threads : {1, max_threads}) {
    omp_set_num_threads(threads);
    // One-off assembly (assembleStiffness: builds a pattern for the call)...
    auto t0 = std::chrono::steady_clock::now();
    const long nnz = static_cast<long>(assembleStiffness(m).nonZeros());
    const double t_once = seconds(t0);
    // ...and the cached pattern: its build, then re-assembly into the same
    // matrix (best of 3, as in a time loop that re-assembles every step).
    t0 = std::chrono::steady_clock::now();
    const AssemblyPattern pattern(m);
    const double t_pattern = seconds(t0);
    SparseMatrix K;
    pattern.stiffness(m, {}, K);
    double t = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
      t0 = std::chrono::steady_clock::now();
      pattern.stiffness(m, {}, K);
      t = std::min(t, seconds(t0));
    }
    std::printf("  stiffness  threads %d  one-off assembly %.3f s (%.3g elements/s)  pattern build %.3f s (%d colours)"
                "  re-assembly %.3f s  %.3g elements/s  nnz %ld\n",
                threads, t_once, m.numElements() / t_once, t_pattern, pattern.numColours(), t,
                m.numElements() / t, nnz);
    std::printf("RESULT mesh=%s dim=%d nodes=%d elements=%d what=assembly threads=%d seconds=%.6g once=%.6g "
                "pattern=%.6g\n",
                name.c_str(), dim, m.numNodes(), m.numElements(), threads, t, t_once, t_pattern);
    if (threads == max_threads) break;
  }
  omp_set_num_threads(max_threads);

  Species s;
  s.production = Eigen::VectorXd::Ones(1);
  s.dirichlet.push_back({boundaryFacets(m), 0.0, {}});
  for (SolverMethod method : cfg.backends) {
    const bool direct = method == SolverMethod::Direct || method == SolverMethod::Cholmod;
    // 3D direct fill-in grows like n^(4/3) and the work like n^2: measured here
    // ~2 s for 10^4 nodes, so 10^5 would take minutes. 2D is fine up to 10^6.
    const int direct_limit = dim == 2 ? 1100000 : 50000;
    if (direct && m.numNodes() > direct_limit) {
      std::printf("  %-40s skipped (direct fill-in too large for this machine)\n", toString(method).c_str());
      continue;
    }
    // Eigen's Jacobi CG needs O(n^(1/d)) iterations; skip the 10^6 runs (minutes each).
    if (method == SolverMethod::ConjugateGradient && m.numNodes() > 300000) {
      std::printf("  %-40s skipped (Jacobi CG: too many iterations at this size)\n", toString(method).c_str());
      continue;
    }
    DiffusionOptions opt;
    opt.linear.method = method;
    opt.linear.preconditioner = Preconditioner::Jacobi;
    opt.linear.tolerance = 1e-8;
    opt.linear.amg_strong_threshold = dim == 2 ? 0.25 : 0.5;
    opt.scheme = TimeScheme::ImplicitEuler;
    for (const char* problem : {"steady", "step"}) {
      auto t0 = std::chrono::steady_clock::now();
      DiffusionReaction solver(m, {s}, opt);
      const double t_setup = seconds(t0);  // matrices and boundary data
      t0 = std::chrono::steady_clock::now();
      if (std::strcmp(problem, "steady") == 0)
        solver.solveSteady();
      else
        solver.step(1e-3);
      const double t_solve = seconds(t0);  // factorisation or preconditioner setup + solve
      const SolveReport& r = solver.lastReport();
      std::printf("  %-6s %-40s setup %.3f s  solve %.3f s  unknowns %d  iterations %d  residual %.2e  max u %.6f\n",
                  problem, toString(method).c_str(), t_setup, t_solve, r.unknowns, r.iterations,
                  r.relative_residual, solver.state().maxCoeff());
      std::printf("RESULT mesh=%s dim=%d nodes=%d elements=%d what=%s backend=%s setup=%.6g seconds=%.6g "
                  "iterations=%d residual=%.3g maxu=%.9g\n",
                  name.c_str(), dim, m.numNodes(), m.numElements(), problem, key(method), t_setup, t_solve,
                  r.iterations, r.relative_residual, solver.state().maxCoeff());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines appear as measured, even if the run is cut short
  bool quick = false, full = false;
  Config cfg;
  std::string backends = "direct,cholmod,cg,amg";
  const char* usage = "solvers_bench [--quick] [--full] [--write-meshes DIR] [--backends direct,cholmod,cg,amg]";
  if (tessella::bench::helpRequested(argc, argv, usage)) return 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if (a == "--full" || a == "--large") {
      full = true;
    } else if (a == "--write-meshes" && i + 1 < argc) {
      cfg.mesh_dir = argv[++i];
    } else if (a == "--backends" && i + 1 < argc) {
      backends = argv[++i];
    } else {
      std::fprintf(stderr, "solvers_bench: unknown argument '%s'\nusage: %s\n", a.c_str(), usage);
      return 2;
    }
  }
  std::stringstream list(backends);
  for (std::string item; std::getline(list, item, ',');) {
    SolverMethod m;
    if (item == "direct") m = SolverMethod::Direct;
    else if (item == "cholmod") m = SolverMethod::Cholmod;
    else if (item == "cg") m = SolverMethod::ConjugateGradient;
    else if (item == "amg") m = SolverMethod::AmgCG;
    else {
      std::fprintf(stderr, "solvers_bench: unknown back-end '%s' (direct, cholmod, cg, amg)\n", item.c_str());
      return 2;
    }
    if (solverAvailable(m))
      cfg.backends.push_back(m);
    else
      std::printf("solvers_bench: back-end %s not built, skipped\n", item.c_str());
  }
  std::printf("solvers_bench: OpenMP max threads %d\n", omp_get_max_threads());
  // hypre's first use initialises MPI (a fraction of a second): not part of any figure.
  if (solverAvailable(SolverMethod::AmgCG)) {
    LinearSolverOptions warm;
    warm.method = SolverMethod::AmgCG;
    solveLinear(SparseMatrix(Eigen::VectorXd::Ones(4).asDiagonal()), Eigen::VectorXd::Ones(4), warm);
  }
  std::vector<std::pair<int, int>> runs = {{2, 100}, {3, 21}};  // ~10^4 nodes
  if (!quick) runs.insert(runs.end(), {{2, 316}, {3, 46}});      // ~10^5
  if (full) runs.insert(runs.end(), {{2, 1000}, {3, 99}});       // ~10^6
  for (const auto& [dim, n] : runs) run(dim, n, cfg);
  return 0;
}
