// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// P1 assembly: exact integrals of constants and linear functions on flat,
// curved and 3D meshes; symmetry, zero row sums; bit-identical with 1 or 2
// OpenMP threads.
#include <catch2/catch.hpp>

#include "structured_meshes.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/assembly_pattern.hpp"
#include "tessella/solvers/element_geometry.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <omp.h>

#include <cmath>
#include <cstring>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;
using tessella::test::boxMesh;
using tessella::test::cylinderStrip;
using tessella::test::rectangleMesh;

namespace {

Eigen::VectorXd nodal(const FeMesh& m, const Eigen::Vector3d& a) { return m.nodes * a; }

bool bitIdentical(const SparseMatrix& A, const SparseMatrix& B) {
  if (A.rows() != B.rows() || A.cols() != B.cols() || A.nonZeros() != B.nonZeros()) return false;
  const auto nnz = static_cast<std::size_t>(A.nonZeros());
  return std::memcmp(A.valuePtr(), B.valuePtr(), nnz * sizeof(double)) == 0 &&
         std::memcmp(A.innerIndexPtr(), B.innerIndexPtr(), nnz * sizeof(int)) == 0 &&
         std::memcmp(A.outerIndexPtr(), B.outerIndexPtr(), static_cast<std::size_t>(A.outerSize() + 1) * sizeof(int)) == 0;
}

}  // namespace

TEST_CASE("Mass matrices integrate constants; stiffness is exact on linear fields", "[solvers][assembly]") {
  const double pi = std::acos(-1.0);
  const int n_theta = 12;
  const double R = 2.0, angle = pi / 2, H = 3.0;
  struct Case {
    const char* name;
    FeMesh mesh;
    double measure;
  };
  // The cylinder strip is a polyhedral sheet of planar rectangles of width
  // 2 R sin(dtheta / 2): its exact area is known.
  const Case cases[] = {{"rectangle", rectangleMesh(5, 3, 2.0, 1.5), 3.0},
                        {"box", boxMesh(3, 2, 4, 1.0, 2.0, 0.5), 1.0},
                        {"cylinder strip", cylinderStrip(n_theta, 4, R, angle, H),
                         n_theta * 2 * R * std::sin(angle / n_theta / 2) * H}};
  for (const Case& c : cases) {
    INFO(c.name);
    const SparseMatrix M = assembleMass(c.mesh, MassType::Consistent);
    const SparseMatrix ML = assembleMass(c.mesh, MassType::Lumped);
    const Eigen::VectorXd one = Eigen::VectorXd::Ones(c.mesh.numNodes());
    CHECK(one.dot(M * one) == Approx(c.measure).epsilon(1e-13));
    CHECK(one.dot(ML * one) == Approx(c.measure).epsilon(1e-13));
    CHECK(assembleLoad(c.mesh, Eigen::VectorXd::Constant(c.mesh.numElements(), 2.0)).sum() ==
          Approx(2.0 * c.measure).epsilon(1e-13));
    CHECK((ML - SparseMatrix(ML.diagonal().asDiagonal())).norm() == 0.0);
    CHECK((SparseMatrix(M.transpose()) - M).norm() == 0.0);

    const SparseMatrix K = assembleStiffness(c.mesh);
    CHECK((SparseMatrix(K.transpose()) - K).norm() <= 1e-14 * K.norm());
    CHECK((K * one).cwiseAbs().maxCoeff() <= 1e-12 * K.coeffs().cwiseAbs().maxCoeff());
    // int |grad u|^2 for u = z (on the cylinder z is along every planar
    // rectangle, so its tangential gradient is e_z) or u = a.x in flat meshes.
    const Eigen::Vector3d a = c.mesh.dim == 3 ? Eigen::Vector3d(1.0, -2.0, 0.5)
                              : std::string(c.name) == "rectangle" ? Eigen::Vector3d(1.0, -2.0, 0.0)
                                                                   : Eigen::Vector3d(0.0, 0.0, 1.0);
    const Eigen::VectorXd u = nodal(c.mesh, a);
    CHECK(u.dot(K * u) == Approx(a.squaredNorm() * c.measure).epsilon(1e-12));
  }
}

TEST_CASE("Per-element coefficients and facet integrals", "[solvers][assembly]") {
  const FeMesh m = boxMesh(4, 2, 2, 2.0, 1.0, 1.0, /*two_cells=*/true);
  const Eigen::Vector2d per_cell(3.0, 5.0);
  const Eigen::VectorXd c = cellToElement(m, per_cell, "coefficient");
  const Eigen::VectorXd u = nodal(m, Eigen::Vector3d(1.0, 0.0, 0.0));
  // Cells are the halves x < 1 and x > 1, each of volume 1.
  CHECK(u.dot(assembleStiffness(m, c) * u) == Approx(3.0 + 5.0).epsilon(1e-12));
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(m.numNodes());
  CHECK(one.dot(assembleMass(m, MassType::Consistent, c) * one) == Approx(8.0).epsilon(1e-13));

  // Facets: boundary area of the 2 x 1 x 1 box is 10; the interior wall (id 6) has area 1.
  const std::vector<int> boundary = boundaryFacets(m);
  CHECK(one.dot(assembleFacetMass(m, boundary) * one) == Approx(10.0).epsilon(1e-13));
  const std::vector<int> inner = facetsOfWalls(m, {6});
  CHECK(facetsOfWalls(m, {6}, /*boundary_only=*/true).empty());
  CHECK(assembleFacetLoad(m, inner, Eigen::VectorXd::Constant(static_cast<Eigen::Index>(inner.size()), 4.0)).sum() ==
        Approx(4.0).epsilon(1e-13));
  // int_{x=2} x ds = 2: the facet mass reproduces linear integrands.
  const std::vector<int> right = facetsOfWalls(m, {1});
  CHECK(one.dot(assembleFacetMass(m, right) * u) == Approx(2.0).epsilon(1e-13));

  // Outward normals of the boundary facets point away from the box centre.
  const std::vector<FacetSide> sides = facetSides(m, boundary);
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const Eigen::Vector3d n = outwardNormal(m, boundary[i], sides[i]);
    const Eigen::Vector3d x = m.nodes.row(m.wall_facets(boundary[i], 0)).transpose();
    CHECK(n.norm() == Approx(1.0));
    CHECK(n.dot(x - Eigen::Vector3d(1.0, 0.5, 0.5)) > 0.0);
  }
}

TEST_CASE("Assembly rejects bad input", "[solvers][assembly]") {
  FeMesh m = rectangleMesh(2, 2);
  CHECK_THROWS_AS(cellToElement(m, Eigen::VectorXd::Constant(1, -1.0), "D", true), InvalidProblemError);
  CHECK_THROWS_AS(assembleStiffness(m, Eigen::VectorXd::Ones(3)), InvalidProblemError);
  CHECK_THROWS_AS(assembleFacetMass(m, {m.numWallFacets()}), InvalidProblemError);
  m.nodes.row(m.elements(0, 2)) = m.nodes.row(m.elements(0, 0));  // collapse element 0
  CHECK_THROWS_AS(assembleStiffness(m), InvalidProblemError);
  FeMesh bad = rectangleMesh(2, 2);
  bad.elements(1, 1) = bad.numNodes();
  CHECK_THROWS_AS(assembleMass(bad, MassType::Lumped), InvalidProblemError);
}

TEST_CASE("Assembly is bit-identical with 1 and 2 OpenMP threads", "[solvers][assembly][determinism]") {
  FeMesh box = boxMesh(8, 7, 6, 1.0, 1.0, 1.0, true);
  test::perturbInterior(box, 1.0 / 8, 0.2);  // irregular values, not just a few distinct ones
  const FeMesh sheet = cylinderStrip(40, 30, 1.0, 2.0, 1.0);
  const int saved = omp_get_max_threads();
  auto assembleAll = [&](int threads) {
    omp_set_num_threads(threads);
    const Eigen::VectorXd c = cellToElement(box, Eigen::Vector2d(1.5, 0.25), "c");
    std::vector<SparseMatrix> out{assembleStiffness(box, c), assembleMass(box, MassType::Consistent, c),
                                  assembleStiffness(sheet), assembleFacetMass(box, boundaryFacets(box))};
    ElasticityProblem p;
    p.displacement.push_back({facetsOfWalls(box, {0}), {}, {true, true, true}, Eigen::Vector3d::Zero()});
    p.traction.push_back({facetsOfWalls(box, {1}), Eigen::Vector3d(0.1, 0.2, 0.0)});
    p.linear.method = SolverMethod::Direct;
    const ElasticityResult r = solveElasticity(box, p);
    return std::make_pair(out, r);
  };
  const auto one = assembleAll(1);
  const auto two = assembleAll(2);
  omp_set_num_threads(saved);
  for (std::size_t k = 0; k < one.first.size(); ++k) {
    INFO("matrix " << k);
    CHECK(bitIdentical(one.first[k], two.first[k]));
  }
  CHECK(std::memcmp(one.second.displacement.data(), two.second.displacement.data(),
                    static_cast<std::size_t>(one.second.displacement.size()) * sizeof(double)) == 0);
  CHECK(std::memcmp(one.second.stress.data(), two.second.stress.data(),
                    static_cast<std::size_t>(one.second.stress.size()) * sizeof(double)) == 0);
}

namespace {

// Independent reference: element matrices from elementGeometry summed as
// triplets (Eigen's setFromTriplets), the textbook assembly.
SparseMatrix tripletReference(const FeMesh& m, bool stiffness, const Eigen::VectorXd& c) {
  const int nn = m.dim + 1;
  std::vector<Eigen::Triplet<double>> t;
  for (int e = 0; e < m.numElements(); ++e) {
    const ElementGeometry g = elementGeometry(m, e);
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b) {
        const double v = stiffness ? g.measure * g.gradients.row(a).dot(g.gradients.row(b))
                                   : g.measure * (a == b ? 2.0 : 1.0) / (nn * (nn + 1));
        t.emplace_back(m.elements(e, a), m.elements(e, b), c[e] * v);
      }
  }
  SparseMatrix A(m.numNodes(), m.numNodes());
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

TEST_CASE("AssemblyPattern re-assembly equals triplet assembly; invariants; thread-independent",
          "[solvers][assembly][pattern]") {
  // Large enough for many chunks of AssemblyPattern::kChunk elements per colour.
  FeMesh box = boxMesh(12, 10, 8, 1.0, 2.0, 0.5, true);
  test::perturbInterior(box, 0.5 / 8, 0.2);
  FeMesh square = rectangleMesh(40, 30, 2.0, 1.5, true);
  test::perturbInterior(square, 1.5 / 30, 0.2);
  const double pi = std::acos(-1.0);
  struct Case {
    const char* name;
    FeMesh mesh;
    double measure;
  };
  const Case cases[] = {{"3D box", box, 1.0},
                        {"2D rectangle", square, 3.0},
                        {"curved strip", cylinderStrip(40, 30, 2.0, pi / 2, 3.0),
                         40 * 2 * 2.0 * std::sin(pi / 2 / 40 / 2) * 3.0}};
  const int saved = omp_get_max_threads();
  for (const Case& k : cases) {
    INFO(k.name);
    const FeMesh& m = k.mesh;
    // Per-element coefficients with many distinct values.
    Eigen::VectorXd c(m.numElements());
    for (int e = 0; e < m.numElements(); ++e) c[e] = 0.5 + std::fmod(0.37 * e, 1.3);
    const AssemblyPattern p(m);
    CHECK(p.numColours() >= 2);             // neighbouring chunks need distinct colours
    CHECK(p.numChunks() >= 4 * p.numColours());  // several chunks per colour: real parallel adds
    const SparseMatrix K = p.stiffness(m, c);
    const SparseMatrix M = p.mass(m, MassType::Consistent, c);
    const SparseMatrix Kref = tripletReference(m, true, c);
    const SparseMatrix Mref = tripletReference(m, false, c);
    CHECK(K.nonZeros() == Kref.nonZeros());
    const double kscale = Kref.coeffs().cwiseAbs().maxCoeff();
    CHECK(SparseMatrix(K - Kref).coeffs().cwiseAbs().maxCoeff() <= 1e-13 * kscale);
    const double mscale = Mref.coeffs().cwiseAbs().maxCoeff();
    CHECK(SparseMatrix(M - Mref).coeffs().cwiseAbs().maxCoeff() <= 1e-14 * mscale);

    // Invariants with c = 1: stiffness rows sum to zero, mass sums to the measure.
    const Eigen::VectorXd one = Eigen::VectorXd::Ones(m.numNodes());
    CHECK((p.stiffness(m) * one).cwiseAbs().maxCoeff() <= 1e-12 * kscale);
    CHECK(one.dot(p.mass(m, MassType::Consistent) * one) == Approx(k.measure).epsilon(1e-13));
    const SparseMatrix ML = p.mass(m, MassType::Lumped);
    CHECK(one.dot(ML * one) == Approx(k.measure).epsilon(1e-13));
    double off_diagonal = 0.0;
    for (int j = 0; j < ML.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(ML, j); it; ++it)
        if (it.row() != it.col()) off_diagonal = std::max(off_diagonal, std::abs(it.value()));
    CHECK(off_diagonal == 0.0);

    // Re-assembly into an existing matrix keeps its storage and gives the same values.
    SparseMatrix into = p.mass(m, MassType::Lumped);
    const double* storage = into.valuePtr();
    p.stiffness(m, c, into);
    CHECK(into.valuePtr() == storage);
    CHECK(bitIdentical(into, K));

    // Bit-identical with 1 and 2 threads.
    omp_set_num_threads(1);
    const SparseMatrix K1 = p.stiffness(m, c), M1 = p.mass(m, MassType::Consistent, c);
    omp_set_num_threads(2);
    const SparseMatrix K2 = p.stiffness(m, c), M2 = p.mass(m, MassType::Consistent, c);
    omp_set_num_threads(saved);
    CHECK(bitIdentical(K1, K2));
    CHECK(bitIdentical(M1, M2));
  }
}

TEST_CASE("AssemblyPattern rejects a different mesh, bad coefficients and degenerate elements",
          "[solvers][assembly][pattern]") {
  FeMesh m = boxMesh(2, 2, 2);
  const AssemblyPattern p(m);
  CHECK_THROWS_AS(p.stiffness(boxMesh(3, 2, 2)), InvalidProblemError);
  CHECK_THROWS_AS(p.mass(m, MassType::Consistent, Eigen::VectorXd::Ones(3)), InvalidProblemError);
  m.nodes.row(m.elements(5, 3)) = m.nodes.row(m.elements(5, 0));  // collapse element 5
  CHECK_THROWS_WITH(p.stiffness(m), Catch::Contains("degenerate"));
  CHECK_THROWS_WITH(p.mass(m, MassType::Lumped), Catch::Contains("degenerate"));
}
