// solvers_bench: assembly throughput and linear-solve times of the P1 solvers
// on structured meshes (2D triangles, 3D tetrahedra) of 10^4 .. 10^6 unknowns.
// Usage: solvers_bench [--quick | --large]   (--quick: up to ~10^5 nodes; --large adds a
// 10^6-node tetrahedral mesh)
// Prints one line per measurement; no assertions (the tests check correctness).

#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"
#include "tessella/solvers/facets.hpp"
#include "tessella/solvers/linear_solver.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

using namespace tessella;

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

void run(int dim, int n) {
  const FeMesh m = structured(dim, n);
  std::printf("dim %d  n %d  nodes %d  elements %d\n", dim, n, m.numNodes(), m.numElements());
  const int max_threads = omp_get_max_threads();
  for (int threads : {1, max_threads}) {
    omp_set_num_threads(threads);
    auto t0 = std::chrono::steady_clock::now();
    const SparseMatrix K = assembleStiffness(m);
    const double t = seconds(t0);
    std::printf("  stiffness assembly  threads %d  %.3f s  %.3g elements/s  nnz %ld\n", threads, t,
                m.numElements() / t, static_cast<long>(K.nonZeros()));
    if (threads == max_threads) break;
  }
  omp_set_num_threads(max_threads);
  // Steady -lap u = 1 with u = 0 on x = 0, zero flux elsewhere.
  for (SolverMethod method : {SolverMethod::Direct, SolverMethod::ConjugateGradient}) {
    if (method == SolverMethod::Direct && m.numNodes() > (dim == 2 ? 1100000 : 150000)) {
      std::printf("  solve %-22s skipped (fill-in too large for this machine)\n", toString(method).c_str());
      continue;
    }
    Species s;
    s.production = Eigen::VectorXd::Ones(1);
    s.dirichlet.push_back({boundaryFacets(m), 0.0, {}});
    DiffusionOptions opt;
    opt.linear.method = method;
    opt.linear.tolerance = 1e-8;
    auto t0 = std::chrono::steady_clock::now();
    DiffusionReaction solver(m, {s}, opt);
    const double t_setup = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    solver.solveSteady();
    const double t_solve = seconds(t0);
    const SolveReport& r = solver.lastReport();
    std::printf("  solve %-22s setup %.3f s  factorise+solve %.3f s  unknowns %d  iterations %d  residual %.2e  max u %.6f\n",
                toString(method).c_str(), t_setup, t_solve, r.unknowns, r.iterations, r.relative_residual,
                solver.state().maxCoeff());
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool large = argc > 1 && std::strcmp(argv[1], "--large") == 0;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // lines appear as measured, even if the run is cut short
  std::printf("solvers_bench: OpenMP max threads %d\n", omp_get_max_threads());
  if (quick) {  // ~10^4 and 10^5 nodes only
    run(2, 100);
    run(2, 316);
    run(3, 21);
    return 0;
  }
  for (int n : {100, 316, 1000}) run(2, n);  // ~10^4, 10^5, 10^6 nodes
  for (int n : {21, 46}) run(3, n);           // ~10^4, 10^5 nodes
  if (large) run(3, 99);                      // ~10^6 nodes
  return 0;
}
