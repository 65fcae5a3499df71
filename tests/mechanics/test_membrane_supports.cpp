// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Supports of membranes (docs/mechanics.md, "Supports of membranes"): symmetry
// planes and the one-point support of a closed body, against the closed form
// of a pressurised St Venant-Kirchhoff sphere and against each other (an
// eighth and a quarter of a sphere held by symmetry planes, the whole sphere
// held at one point: the same discretisation, so the same equilibrium up to a
// rigid motion); the point support does no work (its reactions vanish), and
// supports that leave a rigid motion free are refused, naming it.
#include <catch2/catch.hpp>

#include "tessella/mechanics/errors.hpp"
#include "tessella/mechanics/rigid_motions.hpp"
#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>

using namespace tessella;
using namespace tessella::mechanics;

namespace {

// The octants of a sphere of radius R, each the octahedron's face subdivided
// n times (grid point (i, j, k), i + j + k = n, on the ray of i e_x + j e_y +
// k e_z with the octant's signs); triangles counter-clockwise seen from
// outside. Grid points on the coordinate planes have that coordinate exactly 0.
struct OctantMesh {
  std::vector<Vec3> points;
  std::vector<std::vector<Index>> triangles;
  std::vector<std::array<int, 3>> grid;  // per point: its signed grid coordinates
};

OctantMesh octants(double R, int n, const std::vector<std::array<int, 3>>& signs) {
  OctantMesh m;
  std::map<std::array<int, 3>, Index> index;
  auto point = [&](std::array<int, 3> g) {
    for (int& c : g) c = c == 0 ? 0 : c;  // no -0 in the key
    const auto [it, fresh] = index.emplace(g, static_cast<Index>(m.points.size()));
    if (fresh) {
      const Vec3 b(g[0], g[1], g[2]);
      m.points.push_back(R * b.normalized());
      m.grid.push_back(g);
    }
    return it->second;
  };
  for (const auto& s : signs) {
    auto at = [&](int i, int j) { return point({s[0] * i, s[1] * j, s[2] * (n - i - j)}); };
    const bool mirrored =
        s[0] * s[1] * s[2] < 0;  // an odd number of reflections turns the loops round
    auto add = [&](Index a, Index b, Index c) {
      m.triangles.push_back(mirrored ? std::vector<Index>{a, c, b} : std::vector<Index>{a, b, c});
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + j <= n - 2) add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  return m;
}

std::vector<std::array<int, 3>> allOctants() {
  std::vector<std::array<int, 3>> s;
  for (int x : {1, -1})
    for (int y : {1, -1})
      for (int z : {1, -1}) s.push_back({x, y, z});
  return s;
}

// One 3D cell whose walls are the mesh's triangles (a closed sphere).
Tissue closedCell(const OctantMesh& m) {
  std::vector<std::vector<CellFace>> cells(1);
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    cells[0].push_back({static_cast<Index>(f), false});
  checkPolyhedra(m.points, m.triangles, cells, FaceOrientation::Given);
  return buildPolyhedralTissue(m.points, m.triangles, cells);
}

// The exact St Venant-Kirchhoff sphere: t E (lambda^2 - 1) / (1 - nu) = P R lambda, tension N = P
// lambda R / 2.
constexpr double kR = 1.0, kP = 1.0, kE = 1000.0, kT = 0.01, kNu = 0.3;
double exactStretch() {
  const double c = kP * kR * (1 - kNu) / (kT * kE);
  return 0.5 * (c + std::sqrt(c * c + 4.0));
}

MembraneGrowthParams sphereParams() {
  MembraneGrowthParams p;
  p.material = {.young = kE, .poisson = kNu, .thickness = kT};
  p.pressure = kP;
  p.solver.relative_tolerance = 1e-12;
  return p;
}

// Per cell (sheet) or wall (3D): the principal tensions N1, N2 of its membrane at x.
std::vector<std::array<double, 2>> tensions(const FanMembraneModel& model, const Eigen::VectorXd& x,
                                            std::size_t polygons) {
  std::vector<std::array<double, 2>> t;
  for (std::size_t i = 0; i < polygons; ++i) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(model.meanTension(x, i));
    t.push_back({eig.eigenvalues()[2], eig.eigenvalues()[1]});  // the third is 0 (normal)
  }
  return t;
}

struct Solved {
  std::vector<Vec3> positions;                 // by vertex slot
  std::vector<std::array<double, 2>> tension;  // by polygon (triangle of the mesh)
  double reaction = 0.0, force_scale = 0.0;    // |gradient at the fixed dofs|, the force scale
  std::size_t fixed_dofs = 0;
};

Solved solve(Tissue& tissue, const MembraneGrowthParams& params) {
  MembraneRestState state;
  const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
  const std::vector<std::uint8_t> fixed = membraneFixedDofs(tissue, params);
  requireNoRigidMotion(tissue, fixed, "test supports");
  Eigen::VectorXd x = spatialDofs(tissue);
  const EquilibriumReport report = solveEquilibrium(model, x, fixed, params.solver);
  setSpatialDofs(tissue, x);
  Solved s;
  for (VertexId v : tissue.vertices()) s.positions.push_back(tissue.position(v));
  s.tension = tensions(model, x, membraneFaces(tissue).size());
  Eigen::VectorXd g(x.size());
  model.gradient(x, g);
  double r2 = 0.0;
  for (VertexId v : tissue.vertices())
    for (int k = 0; k < 3; ++k)
      if (fixed[3 * v.index() + static_cast<std::size_t>(k)]) {
        r2 += g[3 * v.index() + k] * g[3 * v.index() + k];
        ++s.fixed_dofs;
      }
  s.reaction = std::sqrt(r2);
  s.force_scale = report.force_scale;
  return s;
}

// The RMS over the triangles (nearly equal in area) of N_i / N - 1 over both principal tensions,
// and the largest |r / (lambda R) - 1| over the vertices; returns the RMS.
double checkClosedForm(const Solved& s, const Vec3& centre, double rms_bound, double radius_bound) {
  const double lambda = exactStretch(), N = kP * lambda * kR / 2.0;
  double sum = 0.0;
  for (const auto& t : s.tension)
    sum += (std::pow(t[0] / N - 1.0, 2) + std::pow(t[1] / N - 1.0, 2)) / 2.0;
  const double rms = std::sqrt(sum / static_cast<double>(s.tension.size()));
  double radius = 0.0;
  for (const Vec3& p : s.positions)
    radius = std::max(radius, std::abs((p - centre).norm() / (lambda * kR) - 1.0));
  CAPTURE(rms, radius);
  CHECK(rms < rms_bound);
  CHECK(radius < radius_bound);
  return rms;
}

}  // namespace

TEST_CASE("symmetry planes: parsing names the bad item", "[mechanics]") {
  const auto planes = parseSymmetryPlanes("x = 0, y=-1.5 ,Z=2", "planes");
  REQUIRE(planes.size() == 3);
  CHECK(planes[0].axis == 0);
  CHECK(planes[0].offset == 0.0);
  CHECK(planes[1].axis == 1);
  CHECK(planes[1].offset == -1.5);
  CHECK(planes[2].axis == 2);
  CHECK(planes[2].offset == 2.0);
  CHECK(planes[1].text() == "y = -1.5");
  CHECK(parseSymmetryPlanes("", "planes").empty());
  CHECK(parseSymmetryPlanes(planes[1].text(), "planes")[0].offset == -1.5);
  CHECK_THROWS_WITH(parseSymmetryPlanes("w = 0", "planes"), Catch::Contains("planes: plane 'w=0'"));
  CHECK_THROWS_WITH(parseSymmetryPlanes("x = ", "planes"), Catch::Contains("'x='"));
  CHECK_THROWS_WITH(parseSymmetryPlanes("x = 1e999", "planes"), Catch::Contains("'x=1e999'"));
  CHECK_THROWS_WITH(parseSymmetryPlanes("x = 0,, y = 1", "planes"), Catch::Contains("empty plane"));
  CHECK_THROWS_WITH(parseSymmetryPlanes("x = 0, x=0", "planes"), Catch::Contains("given twice"));
}

// The whole sphere held at one point, an eighth held by the three coordinate
// planes and a quarter by two planes plus the point support (which then fixes
// only the z of its anchor): each matches the exact sphere (tension P r / 2,
// the stress P r / (2 t), radius lambda R) within the discretisation error,
// and the three agree with each other to the solver's tolerance (radii from
// the centre, principal tensions); the point support's reactions vanish.
TEST_CASE("supports: a pressurised sphere held at one point, by symmetry planes, or both",
          "[mechanics]") {
  std::vector<double> rms_full, rms_eighth;
  for (int n : {6, 12}) {
    CAPTURE(n);
    // Measured RMS tension errors 3.3 % (n = 6) and 0.81 % (n = 12): second order; radii within
    // 0.74 % and 0.26 %.
    const double rms_bound = n == 6 ? 0.04 : 0.01, radius_bound = n == 6 ? 0.01 : 0.003;
    // Whole sphere: one closed 3D cell, the point support.
    const OctantMesh whole = octants(kR, n, allOctants());
    Tissue sphere = closedCell(whole);
    MembraneGrowthParams point = sphereParams();
    point.support = MembraneGrowthParams::Support::Point;
    const Solved full = solve(sphere, point);
    CHECK(full.fixed_dofs == 6);  // 3 + 2 + 1
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : full.positions) centre += p;
    centre /= static_cast<double>(full.positions.size());
    CAPTURE(full.reaction, full.force_scale);
    // The support does no work: its reactions are the round-off of the balance (measured below
    // 1e-12 of the forces).
    CHECK(full.reaction < 1e-9 * full.force_scale);
    rms_full.push_back(checkClosedForm(full, centre, rms_bound, radius_bound));

    // Holding the second vertex fully as well (7 dofs) constrains the inflation: the reactions are
    // not zero.
    {
      Tissue over = closedCell(whole);
      MembraneRestState state;
      const FanMembraneModel model = buildTissueMembranes(over, point, state);
      std::vector<std::uint8_t> fixed = membraneFixedDofs(over, point);
      for (VertexId v : over.vertices()) {
        const std::size_t i = 3 * v.index();
        if (fixed[i] + fixed[i + 1] + fixed[i + 2] == 2) fixed[i] = fixed[i + 1] = fixed[i + 2] = 1;
      }
      Eigen::VectorXd x = spatialDofs(over);
      const EquilibriumReport report = solveEquilibrium(model, x, fixed, point.solver);
      Eigen::VectorXd g(x.size());
      model.gradient(x, g);
      double r2 = 0.0;
      for (Eigen::Index i = 0; i < x.size(); ++i)
        if (fixed[static_cast<std::size_t>(i)]) r2 += g[i] * g[i];  // every slot is live
      CHECK(std::sqrt(r2) > 1e-3 * report.force_scale);
    }

    // An eighth: a sheet held by the planes x = 0, y = 0, z = 0 alone (no lid: its rims lie in
    // them).
    const OctantMesh eighth_mesh = octants(kR, n, {{1, 1, 1}});
    Tissue eighth =
        buildPolygonTissue(eighth_mesh.points, eighth_mesh.triangles, Embedding::Surface);
    MembraneGrowthParams planes = sphereParams();
    planes.support = MembraneGrowthParams::Support::Symmetry;
    planes.planes = parseSymmetryPlanes("x = 0, y = 0, z = 0", "test");
    CHECK(membraneOrigin(eighth, planes) == Vec3::Zero());
    const Solved part = solve(eighth, planes);
    rms_eighth.push_back(checkClosedForm(part, Vec3::Zero(), rms_bound, radius_bound));

    // A quarter (x, y >= 0): the planes x = 0 and y = 0 leave the z translation, which the point
    // support takes.
    const OctantMesh quarter_mesh = octants(kR, n, {{1, 1, 1}, {1, 1, -1}});
    Tissue quarter =
        buildPolygonTissue(quarter_mesh.points, quarter_mesh.triangles, Embedding::Surface);
    MembraneGrowthParams both = sphereParams();
    both.support = MembraneGrowthParams::Support::Point;
    both.planes = parseSymmetryPlanes("x = 0, y = 0", "test");
    MembraneGrowthParams planes_only = both;
    planes_only.support = MembraneGrowthParams::Support::Symmetry;
    std::size_t plane_dofs = 0;
    for (std::uint8_t f : membraneFixedDofs(quarter, planes_only)) plane_dofs += f;
    const Solved half = solve(quarter, both);
    CHECK(half.fixed_dofs == plane_dofs + 1);  // the point support adds its anchor's z alone
    CAPTURE(half.reaction, half.force_scale);
    Vec3 quarter_centre =
        Vec3::Zero();  // on the z axis: the planes hold x and y; z by symmetry about z = const
    double zmin = 1e300, zmax = -1e300;
    for (const Vec3& p : half.positions) zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    quarter_centre.z() = 0.5 * (zmin + zmax);
    checkClosedForm(half, quarter_centre, rms_bound, radius_bound);

    // The same discretisation: radii from the centre and the principal tensions agree, vertex by
    // vertex and triangle by triangle (the meshes list the (+, +, +) octant first, in the same
    // order).
    const double lambda = exactStretch();
    double radius_gap = 0.0, tension_gap = 0.0;
    for (std::size_t i = 0; i < eighth_mesh.points.size(); ++i) {
      REQUIRE(whole.grid[i] == eighth_mesh.grid[i]);
      const double r_full = (full.positions[i] - centre).norm(),
                   r_eighth = part.positions[i].norm();
      const double r_quarter = (half.positions[i] - quarter_centre).norm();
      radius_gap =
          std::max({radius_gap, std::abs(r_full - r_eighth), std::abs(r_quarter - r_eighth)});
    }
    const double N = kP * lambda * kR / 2.0;
    for (std::size_t f = 0; f < eighth_mesh.triangles.size(); ++f)
      for (int k = 0; k < 2; ++k)
        tension_gap = std::max({tension_gap, std::abs(full.tension[f][k] - part.tension[f][k]) / N,
                                std::abs(half.tension[f][k] - part.tension[f][k]) / N});
    CAPTURE(radius_gap, tension_gap);
    std::cout << "supports: sphere n = " << n
              << ": eighth (planes) / quarter (planes + point) / whole (point) agree to "
              << radius_gap << " in radius, " << tension_gap
              << " in tension; point support reaction " << full.reaction / full.force_scale
              << " of the force scale\n";
    CHECK(radius_gap < 1e-8 * kR);
    CHECK(tension_gap < 1e-7);
  }
  // Second order under refinement (element size halved: a quarter of the error).
  CHECK(rms_full[1] < 0.3 * rms_full[0]);
  CHECK(rms_eighth[1] < 0.3 * rms_eighth[0]);
}

TEST_CASE("supports that leave a rigid motion free are refused, naming it", "[mechanics]") {
  const OctantMesh quarter_mesh = octants(kR, 3, {{1, 1, 1}, {1, 1, -1}});
  Tissue quarter =
      buildPolygonTissue(quarter_mesh.points, quarter_mesh.triangles, Embedding::Surface);
  MembraneGrowthParams params = sphereParams();
  params.support = MembraneGrowthParams::Support::Symmetry;
  params.planes = parseSymmetryPlanes("x = 0, y = 0", "test");
  params.solver.context = "mechanics, step 3, time 0.2";
  const std::vector<Vec3> before(quarter.positions().begin(), quarter.positions().end());
  MembraneRestState state;
  const auto free = freeRigidMotions(quarter, membraneFixedDofs(quarter, params));
  REQUIRE(free.size() == 1);
  CHECK(free[0].rotation == Vec3::Zero());
  CHECK(std::abs(free[0].translation.normalized().z()) == Approx(1.0).epsilon(1e-12));
  CHECK_THROWS_AS(membraneGrowthStep(quarter, params, state, 0.1), MechanicsError);
  CHECK_THROWS_WITH(membraneGrowthStep(quarter, params, state, 0.1),
                    Catch::Contains("step 3, time 0.2") && Catch::Contains("'symmetry'") &&
                        Catch::Contains("x = 0, y = 0") && Catch::Contains("1 rigid motion free") &&
                        Catch::Contains("translation along (0, 0, ") &&
                        Catch::Contains("singular"));
  CHECK(std::equal(before.begin(), before.end(), quarter.positions().begin()));  // nothing moved

  // A closed sphere on its base: the base is its lowest vertex alone, the three rotations about it
  // are free.
  Tissue sphere = closedCell(octants(kR, 3, allOctants()));
  MembraneGrowthParams base = sphereParams();
  const auto rotations = freeRigidMotions(sphere, membraneFixedDofs(sphere, base));
  REQUIRE(rotations.size() == 3);
  for (const RigidMotion& m : rotations) {
    CHECK(m.rotation.norm() > 0.0);
    // Each turns about an axis through the held south pole (0, 0, -1): it does not move it.
    const Vec3 pole(0, 0, -kR);
    CHECK((m.translation + m.rotation.cross(pole - m.centre)).norm() < 1e-9);
  }
  CHECK_THROWS_WITH(membraneGrowthStep(sphere, base, state, 0.1),
                    Catch::Contains("'base'") && Catch::Contains("3 rigid motions free") &&
                        Catch::Contains("rotation about the axis along") &&
                        Catch::Contains("singular"));
  // The symmetry support needs planes.
  MembraneGrowthParams none = sphereParams();
  none.support = MembraneGrowthParams::Support::Symmetry;
  CHECK_THROWS_WITH(none.check(), Catch::Contains("symmetry planes; none given"));
}
