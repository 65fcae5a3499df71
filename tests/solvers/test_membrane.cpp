// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Membrane elasticity on triangle meshes in R^3: a flat sheet turned arbitrarily
// in space gives the plane-stress answer turned with it, and a pressurised
// sphere carries the Laplace membrane stress p R / (2 t).
#include <catch2/catch.hpp>

#include "structured_meshes.hpp"
#include "tessella/solvers/elasticity.hpp"
#include "tessella/solvers/errors.hpp"
#include "tessella/solvers/facets.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <utility>

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::solvers;
using tessella::test::rectangleMesh;

namespace {

const double kPi = std::acos(-1.0);

// Unit octahedron refined `levels` times (each triangle into 4), nodes pushed
// onto the sphere of radius R; triangles counter-clockwise seen from outside,
// every triangle its own cell. Nodes at +-R on each axis.
FeMesh octaSphere(int levels, double R) {
  std::vector<Eigen::Vector3d> x = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<int, 3>> tri = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                         {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      x.push_back((x[static_cast<std::size_t>(a)] + x[static_cast<std::size_t>(b)]).normalized());
      return mid[key] = static_cast<int>(x.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : tri) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    tri = std::move(next);
  }
  FeMesh m;
  m.dim = 2;
  m.nodes.resize(static_cast<Eigen::Index>(x.size()), 3);
  for (std::size_t i = 0; i < x.size(); ++i) m.nodes.row(static_cast<Eigen::Index>(i)) = R * x[i].transpose();
  m.elements.resize(static_cast<Eigen::Index>(tri.size()), 3);
  m.element_cell.resize(static_cast<Eigen::Index>(tri.size()));
  for (std::size_t e = 0; e < tri.size(); ++e) {
    for (int a = 0; a < 3; ++a) m.elements(static_cast<Eigen::Index>(e), a) = tri[e][static_cast<std::size_t>(a)];
    m.element_cell[static_cast<Eigen::Index>(e)] = static_cast<int>(e);
  }
  m.wall_facets.resize(0, 2);
  m.node_vertex = Eigen::VectorXi::Constant(m.numNodes(), -1);
  return m;
}

int nodeAt(const FeMesh& m, const Eigen::Vector3d& p) {
  for (int i = 0; i < m.numNodes(); ++i)
    if ((m.nodes.row(i).transpose() - p).norm() < 1e-12) return i;
  FAIL("no node at " << p.transpose());
  return -1;
}

DisplacementCondition fixNode(int node, std::array<bool, 3> comps) {
  DisplacementCondition d;
  d.nodes = {node};
  d.fixed = comps;
  return d;
}

}  // namespace

TEST_CASE("A flat membrane turned in space gives the rotated plane-stress solution", "[solvers][elasticity][membrane]") {
  // Cantilever of two materials, clamped at x = 0, with an oblique end traction
  // and a body force: a non-uniform state with shear.
  const FeMesh flat = rectangleMesh(12, 5, 2.0, 1.0, /*two_cells=*/true);
  ElasticityProblem p;
  p.model = ElasticModel::PlaneStress;
  p.young = Eigen::Vector2d(100.0, 300.0);
  p.poisson = Eigen::Vector2d(0.3, 0.2);
  p.thickness = 0.1;
  p.linear.method = SolverMethod::Direct;
  DisplacementCondition clamp;
  clamp.facets = facetsOfWalls(flat, {0});
  p.displacement.push_back(clamp);
  const Eigen::Vector3d traction(1.0, 0.4, 0.0), body(0.3, -0.5, 0.0);
  p.traction.push_back({facetsOfWalls(flat, {1}), traction});
  p.body_force = body;
  const ElasticityResult ref = solveElasticity(flat, p);

  // Turn in-plane by 30 degrees, then tilt the sheet upright (normal -> -y):
  // its in-plane axes are mixtures of x and z.
  const Eigen::Matrix3d rot = (Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(kPi / 6, Eigen::Vector3d::UnitZ()))
                                  .toRotationMatrix();
  FeMesh turned = flat;
  turned.nodes = (flat.nodes * rot.transpose()).eval();
  ElasticityProblem q = p;
  q.model = ElasticModel::Membrane;
  q.traction[0].traction = rot * traction;
  q.body_force = rot * body;
  DisplacementCondition normal;  // a flat membrane has no stiffness along its normal (global y here)
  for (int i = 0; i < turned.numNodes(); ++i) normal.nodes.push_back(i);
  normal.fixed = {false, true, false};
  q.displacement.push_back(normal);
  const ElasticityResult r = solveElasticity(turned, q);

  const double umax = ref.displacement.cwiseAbs().maxCoeff();
  REQUIRE(umax > 1e-3);
  for (int i = 0; i < turned.numNodes(); ++i)
    CHECK((r.displacement.row(i).transpose() - rot * ref.displacement.row(i).transpose()).norm() < 1e-10 * umax);
  const double smax = ref.stress.cwiseAbs().maxCoeff();
  for (int e = 0; e < turned.numElements(); ++e) {
    const Eigen::Matrix3d s_ref = rot * voigtToTensor(ref.stress.row(e)) * rot.transpose();
    CHECK((voigtToTensor(r.stress.row(e)) - s_ref).cwiseAbs().maxCoeff() < 1e-10 * smax);
    // Strain: Voigt with engineering shears; compare as tensors.
    auto strainTensor = [](const Eigen::Matrix<double, 1, 6>& v) {
      Eigen::Matrix<double, 1, 6> h = v;
      h.tail<3>() /= 2.0;
      return voigtToTensor(h);
    };
    const Eigen::Matrix3d e_ref = rot * strainTensor(ref.strain.row(e)) * rot.transpose();
    CHECK((strainTensor(r.strain.row(e)) - e_ref).cwiseAbs().maxCoeff() < 1e-10 * smax / 100.0);
  }
  // Per-cell principal stresses do not depend on the orientation.
  for (int c = 0; c < 2; ++c)
    CHECK((r.principal_stress.row(c) - ref.principal_stress.row(c)).cwiseAbs().maxCoeff() < 1e-10 * smax);
}

TEST_CASE("A pressurised spherical membrane carries p R / (2 t) and expands by (1 - nu) p R^2 / (2 E t)",
          "[solvers][elasticity][membrane]") {
  const double R = 2.0, t = 0.01, E = 1000.0, nu = 0.3, pressure = 0.05;
  const double sigma = pressure * R / (2 * t), ur = (1 - nu) * pressure * R * R / (2 * E * t);
  double previous_error = 1e300, previous_rms = 1e300;
  for (int levels : {3, 4}) {
    const FeMesh m = octaSphere(levels, R);
    ElasticityProblem p;
    p.model = ElasticModel::Membrane;
    p.young = Eigen::VectorXd::Constant(1, E);
    p.poisson = Eigen::VectorXd::Constant(1, nu);
    p.thickness = t;
    p.membrane_pressure = pressure;
    p.linear.method = SolverMethod::Direct;
    // Six components that stop rigid motion and agree with a radial expansion.
    p.displacement.push_back(fixNode(nodeAt(m, {0, 0, R}), {true, true, false}));
    p.displacement.push_back(fixNode(nodeAt(m, {R, 0, 0}), {false, true, true}));
    p.displacement.push_back(fixNode(nodeAt(m, {0, R, 0}), {true, false, true}));
    const ElasticityResult r = solveElasticity(m, p);

    double area = 0.0, mean_stress = 0.0, worst_normal = 0.0, rms_stress = 0.0;
    for (int e = 0; e < m.numElements(); ++e) {
      const Eigen::Vector3d x0 = m.nodes.row(m.elements(e, 0)).transpose();
      const Eigen::Vector3d x1 = m.nodes.row(m.elements(e, 1)).transpose();
      const Eigen::Vector3d x2 = m.nodes.row(m.elements(e, 2)).transpose();
      const Eigen::Vector3d n = (x1 - x0).cross(x2 - x0);
      const double a = 0.5 * n.norm();
      const Eigen::Matrix3d s = voigtToTensor(r.stress.row(e));
      worst_normal = std::max(worst_normal, std::abs(n.normalized().dot(s * n.normalized())));
      mean_stress += a * s.trace() / 2;  // mean in-plane normal stress
      area += a;
      // Per cell: principal values 0 (normal) and two in-plane ones near sigma.
      // (Near the octahedron's 6 valence-4 vertices single facets deviate by up
      // to 1/3 at every level: faceting, not convergence; hence an RMS measure.)
      rms_stress += a * (std::pow(r.principal_stress(e, 1) - sigma, 2) + std::pow(r.principal_stress(e, 2) - sigma, 2));
      CHECK(std::abs(r.principal_stress(e, 0)) < 1e-9 * sigma);
    }
    mean_stress /= area;
    rms_stress = std::sqrt(rms_stress / (2 * area)) / sigma;
    double mean_ur = 0.0;
    for (int i = 0; i < m.numNodes(); ++i)
      mean_ur += r.displacement.row(i).dot(m.nodes.row(i).normalized()) / m.numNodes();
    INFO("levels " << levels << ": mean stress " << mean_stress << " (exact " << sigma << "), relative RMS of principal stresses "
                   << rms_stress << ", mean u_r " << mean_ur << " (exact " << ur << ")");
    CHECK(worst_normal < 1e-9 * sigma);
    const double error = std::abs(mean_stress - sigma) / sigma;
    CHECK(error < 0.02);
    CHECK(std::abs(mean_ur - ur) / ur < 0.05);
    CHECK(rms_stress < 0.1);
    CHECK(error < previous_error);  // converges under refinement
    CHECK(rms_stress < previous_rms);
    previous_error = error;
    previous_rms = rms_stress;
  }
}

TEST_CASE("Membrane input errors name the problem", "[solvers][elasticity][membrane]") {
  const FeMesh flat = rectangleMesh(4, 4);
  ElasticityProblem p;
  p.model = ElasticModel::Membrane;
  DisplacementCondition clamp;
  clamp.facets = facetsOfWalls(flat, {0, 1});  // no rigid motion left...
  p.displacement.push_back(clamp);
  p.linear.method = SolverMethod::Direct;
  p.traction.push_back({facetsOfWalls(flat, {2}), Eigen::Vector3d(0, -1, 0)});
  // ...but a flat sheet with a free normal direction can still bulge out of plane.
  try {
    solveElasticity(flat, p);
    FAIL("expected InvalidProblemError");
  } catch (const InvalidProblemError& e) {
    CHECK(std::string(e.what()).find("no bending stiffness") != std::string::npos);
  }
  ElasticityProblem q;
  q.model = ElasticModel::PlaneStress;
  q.membrane_pressure = 1.0;
  q.displacement.push_back(clamp);
  CHECK_THROWS_WITH(solveElasticity(flat, q), Catch::Contains("membrane_pressure needs the Membrane model"));
}
