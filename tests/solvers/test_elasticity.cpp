// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Linear elasticity: uniaxial tension (3D, plane stress, plane strain, two
// materials), hydrostatic pressure, patch tests on distorted meshes, and
// refusal of under-constrained bodies.
#include <catch2/catch.hpp>

#include "structured_meshes.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <cmath>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;
using tessella::test::boxMesh;
using tessella::test::rectangleMesh;

namespace {

using Voigt = Eigen::Matrix<double, 1, 6>;

DisplacementCondition fix(const std::vector<int>& facets, int component) {
  DisplacementCondition d;
  d.facets = facets;
  d.fixed = {component == 0, component == 1, component == 2};
  return d;
}

// Symmetry planes x = 0, y = 0 (and z = 0 in 3D): no rigid motion, no over-constraint.
ElasticityProblem symmetricBar(const FeMesh& m, ElasticModel model) {
  ElasticityProblem p;
  p.model = model;
  p.displacement.push_back(fix(facetsOfWalls(m, {0}), 0));
  p.displacement.push_back(fix(facetsOfWalls(m, {2}), 1));
  if (m.dim == 3) p.displacement.push_back(fix(facetsOfWalls(m, {4}), 2));
  p.linear.method = SolverMethod::Direct;
  return p;
}

double maxRowError(const Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>& rows, const Voigt& expected) {
  return (rows.rowwise() - expected).cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("Uniaxial tension of a 3D bar: sigma_xx = E eps, lateral contraction -nu eps", "[solvers][elasticity]") {
  const double E = 200.0, nu = 0.3, sigma = 1.5;
  const FeMesh m = boxMesh(4, 2, 2, 2.0, 1.0, 1.0);
  ElasticityProblem p = symmetricBar(m, ElasticModel::Solid);
  p.young = Eigen::VectorXd::Constant(1, E);
  p.poisson = Eigen::VectorXd::Constant(1, nu);
  p.traction.push_back({facetsOfWalls(m, {1}), Eigen::Vector3d(sigma, 0, 0)});
  const ElasticityResult r = solveElasticity(m, p);
  const double eps = sigma / E;
  CHECK(maxRowError(r.stress, Voigt(sigma, 0, 0, 0, 0, 0)) < 1e-10 * sigma);
  CHECK(maxRowError(r.strain, Voigt(eps, -nu * eps, -nu * eps, 0, 0, 0)) < 1e-10 * eps);
  for (int i = 0; i < m.numNodes(); ++i) {
    const Eigen::Vector3d x = m.nodes.row(i).transpose();
    const Eigen::Vector3d u = r.displacement.row(i).transpose();
    CHECK((u - Eigen::Vector3d(eps * x.x(), -nu * eps * x.y(), -nu * eps * x.z())).norm() < 1e-12);
  }
  REQUIRE(r.cell_stress.rows() == 1);
  CHECK(r.principal_stress(0, 2) == Approx(sigma).epsilon(1e-10));
  CHECK(std::abs(r.principal_stress(0, 0)) < 1e-10);
  CHECK(std::abs(r.principal_directions[0].col(2).x()) == Approx(1.0).epsilon(1e-10));
  CHECK(r.report.method == SolverMethod::Direct);
  CHECK(r.report.relative_residual < 1e-12);
}

TEST_CASE("Uniaxial tension in plane stress and plane strain", "[solvers][elasticity]") {
  const double E = 10.0, nu = 0.25, sigma = 0.4;
  const FeMesh m = rectangleMesh(6, 3, 2.0, 1.0);
  for (ElasticModel model : {ElasticModel::PlaneStress, ElasticModel::PlaneStrain}) {
    ElasticityProblem p = symmetricBar(m, model);
    p.young = Eigen::VectorXd::Constant(1, E);
    p.poisson = Eigen::VectorXd::Constant(1, nu);
    p.thickness = 0.1;  // scales forces and stiffness alike: stresses do not change
    p.traction.push_back({facetsOfWalls(m, {1}), Eigen::Vector3d(sigma, 0, 0)});
    const ElasticityResult r = solveElasticity(m, p);
    if (model == ElasticModel::PlaneStress) {
      const double eps = sigma / E;
      CHECK(maxRowError(r.stress, Voigt(sigma, 0, 0, 0, 0, 0)) < 1e-10 * sigma);
      CHECK(maxRowError(r.strain, Voigt(eps, -nu * eps, -nu * eps, 0, 0, 0)) < 1e-10 * eps);
    } else {
      // eps_zz = 0 => sigma_zz = nu sigma; eps_xx = (1 - nu^2) sigma / E, eps_yy = -nu (1 + nu) sigma / E.
      CHECK(maxRowError(r.stress, Voigt(sigma, 0, nu * sigma, 0, 0, 0)) < 1e-10 * sigma);
      CHECK(maxRowError(r.strain, Voigt((1 - nu * nu) * sigma / E, -nu * (1 + nu) * sigma / E, 0, 0, 0, 0)) <
            1e-10 * sigma / E);
    }
    CHECK(r.displacement.col(2).isZero(0.0));
  }
}

TEST_CASE("Two materials in series: same stress, strain E-weighted", "[solvers][elasticity]") {
  // nu = 0: no lateral contraction, so the two bars stay compatible at their
  // interface and the uniaxial stress state is the exact solution.
  const FeMesh m = boxMesh(4, 2, 2, 2.0, 1.0, 1.0, /*two_cells=*/true);
  ElasticityProblem p = symmetricBar(m, ElasticModel::Solid);
  p.young = Eigen::Vector2d(1.0, 4.0);
  p.poisson = Eigen::Vector2d(0.0, 0.0);
  p.traction.push_back({facetsOfWalls(m, {1}), Eigen::Vector3d(0.5, 0, 0)});
  const ElasticityResult r = solveElasticity(m, p);
  CHECK(maxRowError(r.stress, Voigt(0.5, 0, 0, 0, 0, 0)) < 1e-10);
  for (int e = 0; e < m.numElements(); ++e) {
    const double E = m.element_cell[e] == 0 ? 1.0 : 4.0;
    CHECK(r.strain(e, 0) == Approx(0.5 / E).epsilon(1e-10));
  }
  // End displacement: 1 * (0.5 / 1) + 1 * (0.5 / 4).
  CHECK(r.displacement.col(0).maxCoeff() == Approx(0.625).epsilon(1e-10));
  CHECK(r.cell_stress(0, 0) == Approx(0.5).epsilon(1e-10));
  CHECK(r.cell_stress(1, 0) == Approx(0.5).epsilon(1e-10));
}

TEST_CASE("Pressure on the outer faces gives hydrostatic stress -p I", "[solvers][elasticity]") {
  const FeMesh m = boxMesh(3, 3, 2, 1.0, 1.0, 0.5);
  ElasticityProblem p = symmetricBar(m, ElasticModel::Solid);
  p.young = Eigen::VectorXd::Constant(1, 3.0);
  p.poisson = Eigen::VectorXd::Constant(1, 0.35);
  p.pressure.push_back({facetsOfWalls(m, {1, 3, 5}), 0.2});
  const ElasticityResult r = solveElasticity(m, p);
  CHECK(maxRowError(r.stress, Voigt(-0.2, -0.2, -0.2, 0, 0, 0)) < 1e-10);
  // Volumetric strain of hydrostatic compression: -3 p (1 - 2 nu) / E per axis sum.
  CHECK(r.strain.row(0).head<3>().sum() == Approx(-3 * 0.2 * (1 - 2 * 0.35) / 3.0).epsilon(1e-10));
  ElasticityProblem interior = p;
  const FeMesh two = boxMesh(2, 2, 2, 1.0, 1.0, 1.0, true);
  interior.pressure = {{facetsOfWalls(two, {6}), 1.0}};
  interior.displacement = symmetricBar(two, ElasticModel::Solid).displacement;
  CHECK_THROWS_AS(solveElasticity(two, interior), InvalidProblemError);
}

TEST_CASE("Patch test: a linear displacement field is reproduced exactly on distorted meshes", "[solvers][elasticity]") {
  Eigen::Matrix3d G;  // u = G x + c
  G << 0.010, -0.004, 0.002, 0.003, -0.006, 0.001, -0.002, 0.005, 0.008;
  const Eigen::Vector3d c(0.1, -0.2, 0.05);
  for (int dim : {2, 3}) {
    INFO("dim " << dim);
    FeMesh m = dim == 3 ? boxMesh(4, 4, 4, 1.0, 1.0, 1.0, true) : rectangleMesh(6, 6, 1.0, 1.0, true);
    test::perturbInterior(m, dim == 3 ? 0.25 : 1.0 / 6, 0.25);
    ElasticityProblem p;
    p.model = dim == 3 ? ElasticModel::Solid : ElasticModel::PlaneStress;
    // Homogeneous material (given per cell): only then is a linear field in equilibrium.
    p.young = Eigen::Vector2d(7.0, 7.0);
    p.poisson = Eigen::Vector2d(0.4, 0.4);
    p.linear.method = SolverMethod::ConjugateGradient;  // the iterative path, to a tight tolerance
    p.linear.tolerance = 1e-14;
    const std::vector<int> boundary = boundaryFacets(m);
    for (int i : facetNodes(m, boundary)) {
      DisplacementCondition d;
      d.nodes = {i};
      d.value = G * m.nodes.row(i).transpose() + c;
      p.displacement.push_back(d);
    }
    const ElasticityResult r = solveElasticity(m, p);
    double err = 0.0;
    for (int i = 0; i < m.numNodes(); ++i) {
      Eigen::Vector3d u = G * m.nodes.row(i).transpose() + c;
      if (dim == 2) u.z() = 0.0;
      const Eigen::Vector3d got = r.displacement.row(i).transpose();
      for (int k = 0; k < dim; ++k) err = std::max(err, std::abs(got[k] - u[k]));
    }
    CHECK(err < 1e-10);
    const Eigen::Matrix3d S = 0.5 * (G + G.transpose());
    for (int e = 0; e < m.numElements(); ++e) {
      CHECK(r.strain(e, 0) == Approx(S(0, 0)).margin(1e-10));
      CHECK(r.strain(e, 1) == Approx(S(1, 1)).margin(1e-10));
      CHECK(r.strain(e, 5) == Approx(2 * S(0, 1)).margin(1e-10));
      if (dim == 3) {
        CHECK(r.strain(e, 2) == Approx(S(2, 2)).margin(1e-10));
        CHECK(r.strain(e, 3) == Approx(2 * S(1, 2)).margin(1e-10));
        CHECK(r.strain(e, 4) == Approx(2 * S(0, 2)).margin(1e-10));
      }
    }
  }
}

TEST_CASE("Under-constrained elastic bodies are refused before solving", "[solvers][elasticity][errors]") {
  const FeMesh m = boxMesh(2, 2, 2);
  ElasticityProblem p;
  p.traction.push_back({facetsOfWalls(m, {1}), Eigen::Vector3d(1, 0, 0)});
  p.traction.push_back({facetsOfWalls(m, {0}), Eigen::Vector3d(-1, 0, 0)});
  auto message = [&](const ElasticityProblem& q) {
    try {
      solveElasticity(m, q);
    } catch (const InvalidProblemError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message(p).find("no displacement constraints") != std::string::npos);

  ElasticityProblem one_node = p;  // a pinned node still lets the body rotate about it
  one_node.displacement.push_back({{}, {0}, {true, true, true}, Eigen::Vector3d::Zero()});
  CHECK(message(one_node).find("3 of the 6 rigid-body modes") != std::string::npos);

  ElasticityProblem face_x = p;  // u_x = 0 on a face: free to slide in y, z and spin about x
  face_x.displacement.push_back(fix(facetsOfWalls(m, {0}), 0));
  CHECK(message(face_x).find("3 of the 6 rigid-body modes") != std::string::npos);

  ElasticityProblem enough = face_x;  // add the other two symmetry planes: well posed
  enough.displacement.push_back(fix(facetsOfWalls(m, {2}), 1));
  enough.displacement.push_back(fix(facetsOfWalls(m, {4}), 2));
  CHECK_NOTHROW(solveElasticity(m, enough));

  const FeMesh flat = rectangleMesh(2, 2);
  ElasticityProblem plane;
  plane.model = ElasticModel::PlaneStress;
  plane.displacement.push_back(fix(facetsOfWalls(flat, {0}), 0));  // rigid y-translation left
  try {
    solveElasticity(flat, plane);
    FAIL("expected InvalidProblemError");
  } catch (const InvalidProblemError& e) {
    CHECK(std::string(e.what()).find("1 of the 3 rigid-body modes") != std::string::npos);
  }
}

TEST_CASE("Elasticity input validation", "[solvers][elasticity][errors]") {
  const FeMesh box = boxMesh(1, 1, 1);
  ElasticityProblem p = symmetricBar(box, ElasticModel::Solid);
  p.poisson = Eigen::VectorXd::Constant(1, 0.5);
  CHECK_THROWS_AS(solveElasticity(box, p), InvalidProblemError);
  p.poisson = Eigen::VectorXd::Constant(1, 0.3);
  p.young = Eigen::VectorXd::Constant(1, 0.0);
  CHECK_THROWS_AS(solveElasticity(box, p), InvalidProblemError);
  p.young = Eigen::VectorXd::Constant(1, 1.0);
  p.model = ElasticModel::PlaneStress;
  CHECK_THROWS_AS(solveElasticity(box, p), InvalidProblemError);  // plane model on tetrahedra
  const FeMesh sheet = test::cylinderStrip(4, 2, 1.0, 1.0, 1.0);
  ElasticityProblem curved;
  curved.model = ElasticModel::PlaneStress;
  curved.displacement.push_back({facetsOfWalls(sheet, {0}), {}, {true, true, true}, Eigen::Vector3d::Zero()});
  CHECK_THROWS_AS(solveElasticity(sheet, curved), InvalidProblemError);  // plane stress on a curved sheet
}
