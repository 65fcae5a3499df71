// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Membranes built from a tissue's polygons (fan from the loop's vertex mean, or
// for a folded polygon the fan from its kernel centroid with fixed weights or
// its ear-clipped triangles): the triangulations against closed forms,
// derivatives against finite differences (the apex chain rule included), the
// fan volumes against the tissue's own cell volumes, a single 3D cell and a
// dome sheet under pressure reaching equilibrium, short growth runs with a
// division (validate() after every step), thread counts 1 and 2.
#include <catch2/catch.hpp>

#include "tessella/generators/dome.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/mechanics/errors.hpp"
#include "tessella/mechanics/membrane_triangulation.hpp"
#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

#include <Eigen/Eigenvalues>
#include <omp.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace tessella;
using namespace tessella::mechanics;

namespace {

Tissue domeSheet(std::size_t cells, std::uint64_t seed) {
  Dome dome;
  dome.base_radius = 5.0;
  dome.height = 2.5;
  const Disk footprint{Vec3::Zero(), 5.0};
  return domeTissue(randomSeeds(footprint, cells, seed), dome, VoronoiOptions{.lloyd_iterations = 2});
}

Tissue voronoiBox(std::size_t cells, std::uint64_t seed) {
  const Box box{Vec3(0, 0, 0), Vec3(3, 3, 3)};
  return voronoiTissue(randomSeeds(box, cells, seed), box, VoronoiOptions{.lloyd_iterations = 1});
}

double totalVolume(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

// Central differences of E against g, and of g against the Hessian (columns).
void checkDerivatives(const FanMembraneModel& model, const Eigen::VectorXd& x) {
  Eigen::VectorXd g;
  model.gradient(x, g);
  std::vector<Triplet> entries;
  model.hessian(x, entries);
  Eigen::SparseMatrix<double> K(model.size(), model.size());
  K.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  CHECK((Kd - Kd.transpose()).norm() <= 1e-12 * Kd.norm());
  const double h = 1e-6;
  Eigen::VectorXd fd(model.size());
  Eigen::MatrixXd fdK(model.size(), model.size());
  for (Eigen::Index i = 0; i < model.size(); ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp(i) += h;
    xm(i) -= h;
    fd(i) = (model.energy(xp) - model.energy(xm)) / (2 * h);
    Eigen::VectorXd gp, gm;
    model.gradient(xp, gp);
    model.gradient(xm, gm);
    fdK.col(i) = (gp - gm) / (2 * h);
  }
  CHECK((fd - g).norm() <= 1e-7 * g.norm());
  CHECK((fdK - Kd).norm() <= 1e-6 * Kd.norm());
  CHECK(g.norm() > 0.0);
}

// A curved two-cell sheet whose fans from the vertex means fold: a U cell (no
// kernel: ear-clipped) and an L cell beside it (kernel [3, 4] x [0, 1]: the fan
// from its centroid (3.5, 0.5)), sharing the wall x = 3, lifted onto the bowl
// z = bowl (x^2 + y^2).
Tissue foldedSheet(double bowl) {
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 3, 0), Vec3(2, 3, 0), Vec3(2, 1, 0), Vec3(1, 1, 0),
                         Vec3(1, 3, 0), Vec3(0, 3, 0), Vec3(6, 0, 0), Vec3(6, 1, 0), Vec3(4, 1, 0), Vec3(4, 3, 0)};
  for (Vec3& q : p) q.z() = bowl * (q.x() * q.x() + q.y() * q.y());
  return buildPolygonTissue(p, {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 8, 9, 10, 11, 2}}, Embedding::Surface);
}

}  // namespace

TEST_CASE("membrane triangulation: the mean fan, the kernel fan with mean value coordinates, the ears",
          "[mechanics]") {
  using Kind = MembraneTriangulation::Kind;
  // A convex loop keeps the fan from its vertex mean.
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.2), Vec3(0, 1, 0)};
  CHECK(membraneTriangulation(square).kind == Kind::MeanFan);
  // The L: its vertex mean (4/3, 4/3) lies in the notch; its kernel is the unit
  // square [0, 1]^2, centroid (1/2, 1/2). The apex weights are positive, sum to
  // 1 and reproduce that centroid (linear precision), whatever the plane.
  const std::vector<std::array<double, 2>> l2 = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> l3;
  for (const auto& q : l2) l3.push_back(rotation * Vec3(q[0], q[1], 0) + Vec3(5, -2, 1));
  const MembraneTriangulation l = membraneTriangulation(l3);
  REQUIRE(l.kind == Kind::KernelFan);
  REQUIRE(l.apex_weights.size() == 6);
  double sum = 0.0;
  Vec3 apex = Vec3::Zero();
  for (std::size_t k = 0; k < 6; ++k) {
    CHECK(l.apex_weights[k] > 0.0);
    sum += l.apex_weights[k];
    apex += l.apex_weights[k] * l3[k];
  }
  CHECK(sum == Approx(1.0).epsilon(1e-14));
  CHECK((apex - (rotation * Vec3(0.5, 0.5, 0) + Vec3(5, -2, 1))).norm() <= 1e-12);
  CHECK(l.size(6) == 6);
  CHECK(l.triangle(5, 6) == std::array<int, 3>{MembraneTriangulation::kApex, 5, 0});
  // A regular polygon's centre: every weight 1/n (symmetry).
  std::vector<std::array<double, 2>> hexagon;
  for (int k = 0; k < 6; ++k) hexagon.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  for (double w : meanValueCoordinates(hexagon, {0.0, 0.0})) CHECK(w == Approx(1.0 / 6.0).epsilon(1e-14));
  // Outside the kernel (the L's notch): no coordinates.
  CHECK(meanValueCoordinates(l2, {2.0, 2.0}).empty());
  // The U has no kernel: its n - 2 ear triangles, counter-clockwise, cover its area 7.
  const std::vector<Vec3> u = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 3, 0), Vec3(2, 3, 0),
                               Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 3, 0), Vec3(0, 3, 0)};
  const MembraneTriangulation ears = membraneTriangulation(u);
  REQUIRE(ears.kind == Kind::Ears);
  REQUIRE(ears.size(8) == 6);
  CHECK_FALSE(ears.hasApex());
  double area = 0.0;
  for (std::size_t i = 0; i < 6; ++i) {
    const auto t = ears.triangle(i, 8);
    const double a = 0.5 * (u[t[1]] - u[t[0]]).cross(u[t[2]] - u[t[0]]).z();
    CHECK(a > 0.0);
    area += a;
  }
  CHECK(area == Approx(7.0).epsilon(1e-14));
  // Triangulations that do not fit their loop are refused, naming it.
  MembraneTriangulation bad = l;
  bad.apex_weights[0] += 0.1;
  CHECK_THROWS_WITH(bad.check(6, "polygon 3"), Catch::Contains("polygon 3") && Catch::Contains("sum"));
  CHECK_THROWS_WITH(l.check(7, "polygon 3"), Catch::Contains("7 vertices"));
  bad = ears;
  bad.ears[2][1] = 8;
  CHECK_THROWS_WITH(bad.check(8, "polygon 4"), Catch::Contains("polygon 4") && Catch::Contains("corner 8"));
}

TEST_CASE("tissue membranes: derivatives of folded polygons (kernel fan, ears) against finite differences",
          "[mechanics]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Tissue tissue = foldedSheet(0.03);
  REQUIRE(polygonTriangulation(std::vector<Vec3>{tissue.position(VertexId(0)), tissue.position(VertexId(1)),
                                                 tissue.position(VertexId(2)), tissue.position(VertexId(3)),
                                                 tissue.position(VertexId(4)), tissue.position(VertexId(5)),
                                                 tissue.position(VertexId(6)), tissue.position(VertexId(7))})
              .folded);
  MembraneGrowthParams params;
  params.material.young = 50.0;
  params.material.thickness = 0.1;
  params.material.fibre_ratio = 4.0;
  params.fibres.kind = FibreRule::Kind::Fixed;
  params.fibres.vector = Vec3(1, 2, 0.5);
  auto& pressure = cellOutput(tissue, kTurgorPressureName, 0.0);
  pressure[CellId(0)] = 0.7;
  pressure[CellId(1)] = 0.4;
  cellOutput(tissue, kYoungScaleName, 1.0)[CellId(1)] = 1.6;
  MembraneRestState state;
  const FanMembraneModel at_rest = buildTissueMembranes(tissue, params, state);
  CHECK(state.triangulations[0].kind == MembraneTriangulation::Kind::Ears);
  CHECK(state.triangulations[1].kind == MembraneTriangulation::Kind::KernelFan);
  CHECK(at_rest.numTriangles(0) == 6);
  CHECK(at_rest.numTriangles(1) == 6);
  // The kernel apex projects on the tissue's apex, the kernel centroid placed
  // in the L's best-fit plane (it differs only across that plane).
  const Eigen::VectorXd x0 = spatialDofs(tissue);
  std::vector<Vec3> l_loop;
  for (Index v : state.loops[1]) l_loop.push_back(tissue.position(VertexId(v)));
  const PolygonTriangulation l_tri = polygonTriangulation(l_loop);
  Vec3 apex = Vec3::Zero();
  for (std::size_t k = 0; k < 6; ++k) apex += state.triangulations[1].apex_weights[k] * l_loop[k];
  const Vec3 off = apex - l_tri.center;
  CHECK((off - off.dot(l_tri.normal) * l_tri.normal).norm() <= 1e-12);
  // At rest: no elastic energy.
  double pv = 0.0;
  for (std::size_t f = 0; f < at_rest.numPolygons(); ++f)
    pv += at_rest.polygon(f).pressure * at_rest.coneVolume(x0, f);
  CHECK(at_rest.energy(x0) == Approx(-pv).epsilon(1e-12));
  // Flat, both tile their cells: the rest areas are the U's 7 and the L's 5.
  Tissue flat = foldedSheet(0.0);
  MembraneRestState flat_state;
  const FanMembraneModel flat_model = buildTissueMembranes(flat, MembraneGrowthParams{}, flat_state);
  CHECK(flat_model.restArea(0) == Approx(7.0).epsilon(1e-14));
  CHECK(flat_model.restArea(1) == Approx(5.0).epsilon(1e-14));
  CHECK(flat_model.fanArea(spatialDofs(flat), 1) == Approx(5.0).epsilon(1e-14));
  // Their cones from a point 2 below the (counter-clockwise) loops: area times 2 / 3, positive.
  const FanMembraneModel below(spatialDofs(flat), {flat_model.polygon(0), flat_model.polygon(1)}, MembraneMaterial{},
                               Vec3(0.3, 0.4, -2.0));
  CHECK(below.coneVolume(spatialDofs(flat), 0) == Approx(7.0 * 2.0 / 3.0).epsilon(1e-14));
  CHECK(below.coneVolume(spatialDofs(flat), 1) == Approx(5.0 * 2.0 / 3.0).epsilon(1e-14));
  // Strained and sheared: rest shapes 0.9 of the current ones, random moves.
  for (auto& r : state.rest)
    for (RestMetric& m : r) m *= 0.81;
  Eigen::VectorXd x = x0;
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.05 * u(rng);
  const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
  CHECK(model.polygon(1).triangulation == state.triangulations[1]);
  checkDerivatives(model, x);
}

TEST_CASE("tissue membranes: a divided folded cell is triangulated anew; its neighbour keeps its rest state",
          "[mechanics]") {
  Tissue tissue = foldedSheet(0.0);
  MembraneRestState state;
  buildTissueMembranes(tissue, MembraneGrowthParams{}, state);
  const MembraneTriangulation l_tri = state.triangulations[1];
  auto& l_rest = state.rest[1];
  for (RestMetric& m : l_rest) m *= 0.7;  // the L strained: its rest state must survive
  const std::vector<RestMetric> l_before = l_rest;
  // The U at 0.9 of its area at rest: both parts start so (membrane_rest_ratio, copied on division).
  tissue.properties(2).get<double>(kMembraneRestRatioName)[FaceId(0)] = 0.9;
  // Cut off its left arm's outer half: a rectangle [0, 0.5] x [0, 3] and a U still without kernel.
  const CellSplit split = tissue.splitCell(CellId(0), Plane{Vec3(0.5, 1.5, 0), Vec3(1, 0, 0)});
  REQUIRE(tissue.numCells() == 3);
  std::size_t reset = 0;
  const FanMembraneModel model = buildTissueMembranes(tissue, MembraneGrowthParams{}, state, &reset);
  CHECK(reset == 2);
  CHECK(state.triangulations[1] == l_tri);
  CHECK(state.rest[1] == l_before);
  int fans = 0, ears = 0;
  for (CellId c : {CellId(0), split.daughter}) {
    const MembraneTriangulation& t = state.triangulations[c.index()];
    fans += t.kind == MembraneTriangulation::Kind::MeanFan ? 1 : 0;
    ears += t.kind == MembraneTriangulation::Kind::Ears ? 1 : 0;
    CHECK(model.restArea(c.index()) == Approx(0.9 * cellMeasure(tissue, c)).epsilon(1e-13));
  }
  CHECK(fans == 1);
  CHECK(ears == 1);
  CHECK(cellMeasure(tissue, CellId(0)) + cellMeasure(tissue, split.daughter) == Approx(7.0).epsilon(1e-14));
}

TEST_CASE("tissue membranes: derivatives of a dome sheet and a 3D tissue against finite differences",
          "[mechanics]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MembraneGrowthParams params;
  params.material.young = 50.0;
  params.material.poisson = 0.3;
  params.material.thickness = 0.1;
  params.material.fibre_ratio = 5.0;
  params.fibres.kind = FibreRule::Kind::Circumferential;
  for (int dim : {2, 3}) {
    CAPTURE(dim);
    Tissue tissue = dim == 2 ? domeSheet(12, 3) : voronoiBox(6, 4);
    auto& pressure = cellOutput(tissue, kTurgorPressureName, 0.0);
    auto& young = cellOutput(tissue, kYoungScaleName, 1.0);
    for (CellId c : tissue.cells()) {
      pressure[c] = 0.5 + 0.3 * u(rng);  // uneven: interior walls carry a net pressure
      young[c] = 1.0 + 0.5 * u(rng);
    }
    MembraneRestState state;
    FanMembraneModel at_rest = buildTissueMembranes(tissue, params, state);
    // Rest shapes 0.9 of the current ones, then a random perturbation: strained, sheared.
    for (auto& r : state.rest)
      for (RestMetric& m : r) m *= 0.81;
    Eigen::VectorXd x = spatialDofs(tissue);
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.02 * u(rng);
    const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
    checkDerivatives(model, x);
    // At rest in its shape the elastic energy is zero: E = -sum p_f V_f.
    const Eigen::VectorXd x0 = spatialDofs(tissue);
    double pv = 0.0;
    for (std::size_t f = 0; f < at_rest.numPolygons(); ++f)
      pv += at_rest.polygon(f).pressure * at_rest.coneVolume(x0, f);
    CHECK(at_rest.energy(x0) == Approx(-pv).epsilon(1e-12));
  }
}

TEST_CASE("tissue membranes: fan volumes of a 3D tissue are the tissue's cell volumes", "[mechanics]") {
  Tissue tissue = voronoiBox(20, 9);
  MembraneRestState state;
  const FanMembraneModel model = buildTissueMembranes(tissue, MembraneGrowthParams{}, state);
  const std::vector<double> v = membraneCellVolumes(tissue, model, spatialDofs(tissue));
  for (CellId c : tissue.cells()) CHECK(v[c.index()] == Approx(cellMeasure(tissue, c)).epsilon(1e-10));
  CHECK(totalVolume(v) == Approx(27.0).epsilon(1e-10));
}

TEST_CASE("tissue membranes: a single box cell under pressure reaches equilibrium", "[mechanics]") {
  Tissue tissue = boxGrid(1, 1, 1);
  MembraneGrowthParams params;
  params.material.young = 100.0;
  params.material.thickness = 0.05;
  params.pressure = 0.5;
  params.solver.relative_tolerance = 1e-12;
  MembraneRestState state;
  const double v0 = totalMeasure(tissue);
  const MembraneStepReport r = membraneGrowthStep(tissue, params, state, 0.0);
  CHECK(r.fixed_vertices == 4);  // the bottom face
  CHECK(r.equilibrium.iterations >= 2);
  for (std::size_t k = 1; k < r.equilibrium.energies.size(); ++k)  // up to round-off of E
    CHECK(r.equilibrium.energies[k] <=
          r.equilibrium.energies[k - 1] + 1e-13 * std::abs(r.equilibrium.energies[k - 1]));
  CHECK(r.equilibrium.residual <= r.equilibrium.tolerance);
  // The box inflates: volume larger, still positive; the top rises above 1.
  CHECK(totalMeasure(tissue) > v0);
  double top = 0.0;
  for (VertexId v : tissue.vertices()) top = std::max(top, tissue.position(v).z());
  CHECK(top > 1.0);
  CHECK_NOTHROW(validateOrThrow(tissue));
  // Energy balance at equilibrium (Clapeyron does not hold at large strain, but
  // the gradient vanishes): moving every free vertex by a small rigid shift of
  // the top changes E only to second order.
  MembraneRestState again = state;
  const FanMembraneModel model = buildTissueMembranes(tissue, params, again);
  Eigen::VectorXd x = spatialDofs(tissue), g;
  model.gradient(x, g);
  for (VertexId v : tissue.vertices())
    if (tissue.position(v).z() > 1e-9) CHECK(g.segment<3>(3 * v.index()).norm() <= 1e-9 * r.equilibrium.force_scale);
}

TEST_CASE("tissue membranes: the base support holds the base plane it is given, not the lowest vertex",
          "[mechanics]") {
  Tissue tissue = domeSheet(40, 5);
  MembraneGrowthParams params;
  const std::vector<std::uint8_t> base = membraneSupport(tissue, params);  // the plane z = lowest vertex
  double z0 = std::numeric_limits<double>::infinity();
  for (VertexId v : tissue.vertices()) z0 = std::min(z0, tissue.position(v).z());
  // A free vertex sinks below the base (as a rim vertex a little above the
  // plane can under turgor): without a base height it alone would be "the base".
  VertexId sunk;
  for (VertexId v : tissue.vertices())
    if (!base[v.index()]) {
      sunk = v;
      break;
    }
  REQUIRE(sunk.valid());
  tissue.setPosition(sunk, Vec3(tissue.position(sunk).x(), tissue.position(sunk).y(), z0 - 0.01));
  const std::vector<std::uint8_t> found_again = membraneSupport(tissue, params);
  CHECK(std::count(found_again.begin(), found_again.end(), 1) == 1);
  params.base_height = z0;
  const std::vector<std::uint8_t> kept = membraneSupport(tissue, params);
  for (VertexId v : tissue.vertices()) {
    INFO("vertex " << v.index());
    CHECK(kept[v.index()] == (base[v.index()] || v == sunk ? 1 : 0));
  }
}

TEST_CASE("tissue membranes: a dome sheet with a fixed base converges quadratically", "[mechanics]") {
  Tissue tissue = domeSheet(40, 5);
  MembraneGrowthParams params;
  params.material.young = 20.0;
  params.material.thickness = 0.1;
  params.pressure = 0.2;
  params.solver.relative_tolerance = 1e-13;
  MembraneRestState state;
  const double h0 = [&] {
    double h = 0.0;
    for (VertexId v : tissue.vertices()) h = std::max(h, tissue.position(v).z());
    return h;
  }();
  const MembraneStepReport rep = membraneGrowthStep(tissue, params, state, 0.0);
  const EquilibriumReport& r = rep.equilibrium;
  const double s = r.force_scale;
  for (std::size_t k = 0; k < r.residuals.size(); ++k)
    UNSCOPED_INFO("relative residual " << k << ": " << r.residuals[k] / s);
  int near = 0;
  for (std::size_t k = 0; k + 1 < r.residuals.size(); ++k) {
    const double rk = r.residuals[k] / s, rn = r.residuals[k + 1] / s;
    if (rk < 1e-3) {  // measured: r_{k+1} / r_k^2 = 41..55 over the last three steps
      ++near;
      CAPTURE(k, rk, rn);
      CHECK(rn <= 100.0 * rk * rk + 1e-14);
    }
  }
  CHECK(near >= 2);
  for (std::size_t k = 1; k < r.energies.size(); ++k)  // up to round-off of E
    CHECK(r.energies[k] <= r.energies[k - 1] + 1e-13 * std::abs(r.energies[k - 1]));
  double h = 0.0;
  for (VertexId v : tissue.vertices()) h = std::max(h, tissue.position(v).z());
  CHECK(h > h0);  // the dome inflates
  CHECK(rep.fixed_vertices > 0);
  CHECK_NOTHROW(validateOrThrow(tissue));
}

TEST_CASE("tissue membranes: growth runs with divisions stay valid; threads 1 and 2 bit-identical",
          "[mechanics]") {
  auto run = [](int dim, int threads) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    Tissue tissue = dim == 2 ? domeSheet(30, 8) : voronoiBox(12, 8);
    MembraneGrowthParams params;
    params.material.young = 20.0;
    params.material.thickness = 0.1;
    params.pressure = 0.2;
    params.growth.extensibility = 2.0;
    params.growth.threshold = 0.005;
    params.fibres.kind = FibreRule::Kind::Circumferential;
    params.material.fibre_ratio = 3.0;
    MembraneRestState state;
    std::vector<double> volumes;
    for (int step = 0; step < 4; ++step) {
      const MembraneStepReport r = membraneGrowthStep(tissue, params, state, 0.2);
      CHECK(r.max_growth_rate > 0.0);
      CHECK_NOTHROW(validateOrThrow(tissue));
      const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
      const std::vector<double> v = membraneCellVolumes(tissue, model, spatialDofs(tissue));
      for (CellId c : tissue.cells()) CHECK(v[c.index()] > 0.0);
      volumes.push_back(totalVolume(v));
      if (step == 1) {  // divide the largest cell through its centroid
        CellId big;
        double best = 0.0;
        for (CellId c : tissue.cells())
          if (cellMeasure(tissue, c) > best) {
            best = cellMeasure(tissue, c);
            big = c;
          }
        const Vec3 axis = dim == 2 ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
        tissue.splitCell(big, Plane{cellCentroid(tissue, big), axis});
        CHECK_NOTHROW(validateOrThrow(tissue));
      }
    }
    for (std::size_t k = 1; k < volumes.size(); ++k) CHECK(volumes[k] > volumes[k - 1]);  // it grows
    omp_set_num_threads(saved);
    return std::vector<Vec3>(tissue.positions().begin(), tissue.positions().end());
  };
  for (int dim : {2, 3}) {
    CAPTURE(dim);
    CHECK(run(dim, 1) == run(dim, 2));
  }
}

TEST_CASE("tissue membranes: refused tissues and bad state", "[mechanics]") {
  Tissue planar = rectangularGrid(2, 2);
  MembraneRestState state;
  CHECK_THROWS_WITH(buildTissueMembranes(planar, MembraneGrowthParams{}, state), Catch::Contains("planar"));
  // The boundary support needs a sheet with a rim.
  MembraneGrowthParams boundary;
  boundary.support = MembraneGrowthParams::Support::Boundary;
  Tissue box = voronoiBox(4, 1);
  CHECK_THROWS_WITH(membraneSupport(box, boundary), Catch::Contains("3D tissue"));
  Tissue folded = foldedSheet(0.0);
  const auto rim = membraneSupport(folded, boundary);
  CHECK(std::count(rim.begin(), rim.end(), 1) == 12);  // every vertex of the two cells is on the rim
  // The rest state reads back exactly from its text; a short text is refused.
  Tissue tissue = voronoiBox(5, 2);
  MembraneGrowthParams params;
  params.pressure = 0.3;
  membraneGrowthStep(tissue, params, state, 0.0);
  for (auto& r : state.rest)
    for (RestMetric& m : r) m *= 1.0 / 3.0;  // not a short decimal
  MembraneRestState back;
  back.fromText(tissue, state.toText(tissue), "snapshot s");
  for (FaceId f : tissue.faces()) {
    CHECK(back.rest[f.index()] == state.rest[f.index()]);
    CHECK(back.loops[f.index()] == state.loops[f.index()]);
  }
  CHECK_THROWS_WITH(back.fromText(tissue, "3 1 0 1", "snapshot s"), Catch::Contains("snapshot s"));
  // Folded polygons: the triangulations (kernel weights, ear corners) read back too.
  MembraneRestState bent;
  buildTissueMembranes(folded, MembraneGrowthParams{}, bent);
  for (auto& r : bent.rest)
    for (RestMetric& m : r) m *= 1.0 / 3.0;
  const std::string text = bent.toText(folded);
  CHECK(text.find("ears 6") != std::string::npos);
  CHECK(text.find("apex 6") != std::string::npos);
  MembraneRestState bent_back;
  bent_back.fromText(folded, text, "snapshot t");
  for (FaceId f : folded.faces()) {
    CHECK(bent_back.rest[f.index()] == bent.rest[f.index()]);
    CHECK(bent_back.triangulations[f.index()] == bent.triangulations[f.index()]);
  }
  CHECK(bent_back.toText(folded) == text);
  std::string wrong = text;
  wrong.replace(wrong.find("ears 6"), 6, "ears 5");
  CHECK_THROWS_WITH(bent_back.fromText(folded, wrong, "snapshot t"),
                    Catch::Contains("snapshot t") && Catch::Contains("ear triangles"));
}

TEST_CASE("stress feedback: the fibre angle to a uniaxial stress decays exponentially at the given rate",
          "[mechanics]") {
  // One flat square membrane at rest, stretched by 1.2 along x: the maximal
  // principal tension is along x; an isotropic material keeps it there.
  const std::vector<Index> loop = {0, 1, 2, 3};
  Eigen::VectorXd x0(12);
  x0 << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  MembranePolygon poly;
  poly.loop = loop;
  poly.rest = FanMembraneModel::currentMetrics(x0, loop);
  const FanMembraneModel model(x0, {poly}, MembraneMaterial{}, Vec3::Zero());
  Eigen::VectorXd x = x0;
  for (int i = 0; i < 4; ++i) x(3 * i) *= 1.2;
  Vec3 n;
  const Eigen::Matrix3d T = model.meanTension(x, 0, &n);
  CHECK(std::abs(n.z()) == Approx(1.0));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(T);
  const Vec3 s = eig.eigenvectors().col(2);
  CHECK(std::abs(s.x()) == Approx(1.0).epsilon(1e-12));
  const double rate = 2.0, dt = 0.05, theta0 = 1.2;
  Vec3 f(std::cos(theta0), std::sin(theta0), 0.0);
  for (int k = 1; k <= 20; ++k) {
    f = turnFibre(f, s, n, rate, dt);
    CHECK(f.norm() == Approx(1.0).epsilon(1e-14));
    const double expected = theta0 * std::exp(-rate * dt * k);
    CHECK(std::abs(axisAngle(f, Vec3(1, 0, 0), Vec3(0, 0, 1))) == Approx(expected).epsilon(1e-12));
  }
  // Axes: a fibre at 170 degrees is 10 degrees from the stress axis.
  CHECK(axisAngle(Vec3(std::cos(3.0), std::sin(3.0), 0), Vec3(1, 0, 0), Vec3(0, 0, 1)) ==
        Approx(3.0 - std::acos(-1.0)).epsilon(1e-14));
}

TEST_CASE("stress feedback in a growth step: a cylinder's fibres turn toward the hoop stress at the rate given",
          "[mechanics]") {
  // An isotropic pressurised cylinder (the fibres do not change its stress):
  // away from its ends the maximal tension is the hoop one (P r against about
  // P r / 3 along), so each fibre's angle to the hoop direction decays as
  // theta0 exp(-rate t).
  Tissue tissue = cylinderGrid(16, 12, 1.0, 6.0);
  MembraneGrowthParams params;
  params.material.young = 10.0;
  params.material.thickness = 0.1;
  params.pressure = 0.02;
  params.fibres.kind = FibreRule::Kind::Fixed;
  const double theta0 = 1.0;  // from the hoop direction, toward the axis
  params.fibres.vector = Vec3(0, 0, 1);
  params.feedback.rate = 1.5;
  MembraneRestState state;
  // Start: each polygon's fibre at theta0 from its hoop direction.
  buildTissueMembranes(tissue, params, state);
  for (CellId c : tissue.cells()) {
    const Vec3 p = cellCentroid(tissue, c);
    const Vec3 hoop = Vec3(-p.y(), p.x(), 0).normalized();
    state.fibres[c.index()] = std::cos(theta0) * hoop + std::sin(theta0) * Vec3(0, 0, 1);
  }
  const double dt = 0.2;
  for (int step = 1; step <= 5; ++step) {
    membraneGrowthStep(tissue, params, state, dt);
    for (CellId c : tissue.cells()) {
      const Vec3 p = cellCentroid(tissue, c);
      if (p.z() < 2.0 || p.z() > 4.0) continue;  // the middle third
      const Vec3 hoop = Vec3(-p.y(), p.x(), 0).normalized();
      const Vec3 normal = Vec3(p.x(), p.y(), 0).normalized();
      CAPTURE(step, c.index());
      CHECK(axisAngle(state.fibres[c.index()], hoop, normal) ==
            Approx(theta0 * std::exp(-params.feedback.rate * dt * step)).epsilon(1e-6));
    }
  }
}

TEST_CASE("tissue membranes: derivatives with neo-Hookean walls and per-polygon fibre ratios (sheet, 3D)",
          "[mechanics][neo-hookean]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (MembraneLaw law : {MembraneLaw::NeoHookean, MembraneLaw::StVenantKirchhoff}) {
    MembraneGrowthParams params;
    params.material.law = law;
    params.material.young = 50.0;
    params.material.thickness = 0.1;
    params.material.fibre_ratio = 2.0;
    params.fibres.kind = FibreRule::Kind::Circumferential;
    for (int dim : {2, 3}) {
      CAPTURE(static_cast<int>(law), dim);
      Tissue tissue = dim == 2 ? domeSheet(12, 3) : voronoiBox(6, 4);
      auto& pressure = cellOutput(tissue, kTurgorPressureName, 0.0);
      for (CellId c : tissue.cells()) pressure[c] = 0.5 + 0.3 * u(rng);
      // The ratio per sheet cell / per 3D wall: one face store serves both.
      auto& ratio = tissue.properties(2).add<double>(kFibreRatioName, 1.0, DivisionPolicy::Copy);
      for (FaceId f : membraneFaces(tissue)) ratio[f] = 4.5 + 3.5 * u(rng);
      MembraneRestState state;
      buildTissueMembranes(tissue, params, state);
      for (auto& r : state.rest)
        for (RestMetric& m : r) m *= 0.81;
      Eigen::VectorXd x = spatialDofs(tissue);
      for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.02 * u(rng);
      const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
      const std::vector<FaceId> faces = membraneFaces(tissue);
      for (std::size_t i = 0; i < faces.size(); ++i) CHECK(model.polygon(i).fibre_ratio == ratio[faces[i]]);
      checkDerivatives(model, x);
    }
  }
}

TEST_CASE("tissue membranes: each polygon's fibre ratio gives the closed-form energy of a stretch along and across "
          "its fibres",
          "[mechanics][neo-hookean]") {
  // Three flat unit squares with fibres along x, ratios: the material's (3), 1 and 10. Stretched by lambda along
  // x (or y) every fan triangle has C = diag(lambda^2, 1) (or diag(1, lambda^2)) in its fibre frame.
  std::vector<Vec3> points;
  std::vector<MembranePolygon> polygons(3);
  for (int k = 0; k < 3; ++k) {
    const Vec3 o(2.0 * k, 0, 0);
    for (const Vec3& q : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) points.push_back(o + q);
    polygons[k].loop = {Index(4 * k), Index(4 * k + 1), Index(4 * k + 2), Index(4 * k + 3)};
    polygons[k].fibre = Vec3(1, 0, 0);
  }
  polygons[1].fibre_ratio = 1.0;
  polygons[2].fibre_ratio = 10.0;
  Eigen::VectorXd x0(3 * static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) x0.segment<3>(3 * static_cast<Eigen::Index>(i)) = points[i];
  for (MembranePolygon& p : polygons) p.rest = FanMembraneModel::currentMetrics(x0, p.loop);
  for (MembraneLaw law : {MembraneLaw::StVenantKirchhoff, MembraneLaw::NeoHookean}) {
    MembraneMaterial material;
    material.law = law;
    material.young = 6.0;
    material.thickness = 0.1;
    material.fibre_ratio = 3.0;
    const FanMembraneModel model(x0, polygons, material, Vec3::Zero());
    for (int axis : {0, 1}) {
      const double lambda = 1.3;
      Eigen::VectorXd x = x0;
      for (Eigen::Index i = 0; i < x.size(); i += 3) x(i + axis) *= lambda;
      double expected = 0.0;
      for (double r : {3.0, 1.0, 10.0}) {
        MembraneMaterial m = material;
        m.fibre_ratio = r;
        const double e = 0.5 * (lambda * lambda - 1);  // the Green strain along the stretch
        double w = 0.0;
        if (law == MembraneLaw::StVenantKirchhoff) {
          w = 0.5 * m.planeStressMatrix()(axis, axis) * e * e;
        } else {
          w = 0.5 * m.shearModulus() * (lambda * lambda + 1 / (lambda * lambda) - 2);
          if (axis == 0) w += m.fibreStiffness() / 8 * (lambda * lambda - 1) * (lambda * lambda - 1);
        }
        expected += material.thickness * 1.0 * w;  // t A0 W, A0 = 1
      }
      CAPTURE(static_cast<int>(law), axis);
      CHECK(model.energy(x) == Approx(expected).epsilon(1e-12));
    }
  }
  polygons[2].fibre_ratio = 0.5;
  MembraneMaterial nh;
  nh.law = MembraneLaw::NeoHookean;
  CHECK_THROWS_WITH(FanMembraneModel(x0, polygons, nh, Vec3::Zero()),
                    Catch::Contains("membrane polygon 2") && Catch::Contains("fibre_ratio 0.5"));
}

TEST_CASE("tissue membranes: a cylinder whose halves have fibre ratios 1 and 10 strains as each half's law says",
          "[mechanics][neo-hookean]") {
  // Hoop fibres; away from the ends and the junction the tensions are the
  // statically determinate hoop P r and axial P r / 2 in both halves, so the
  // Green strains are the compliance D^-1 (of each half's small-strain law)
  // times (P r / t, P r / (2 t)): the stiff half swells a tenth (SVK) or
  // less as much and elongates more.
  for (MembraneLaw law : {MembraneLaw::StVenantKirchhoff, MembraneLaw::NeoHookean}) {
    CAPTURE(static_cast<int>(law));
    const double R = 1.0, L = 8.0, P = 0.01;
    Tissue tissue = cylinderGrid(32, 32, R, L);
    MembraneGrowthParams params;
    params.material.law = law;
    params.material.young = 10.0;
    params.material.thickness = 0.1;
    params.pressure = P;
    params.fibres.kind = FibreRule::Kind::Circumferential;
    params.solver.relative_tolerance = 1e-12;
    auto& ratio = tissue.cellProperties().add<double>(kFibreRatioName, 1.0, DivisionPolicy::Copy);
    for (CellId c : tissue.cells()) ratio[c] = cellCentroid(tissue, c).z() > L / 2 ? 10.0 : 1.0;
    const std::vector<Vec3> before(tissue.positions().begin(), tissue.positions().end());
    MembraneRestState state;
    membraneGrowthStep(tissue, params, state, 0.0);
    for (int half : {0, 1}) {
      // The rings at a quarter of the half's length from its middle, and the middle ring.
      const double z_mid = L / 4 + half * L / 2, dz = L / 8;
      double hoop = 0.0, z_lo = 0.0, z_hi = 0.0;
      int rings = 0, lo = 0, hi = 0;
      for (VertexId v : tissue.vertices()) {
        const Vec3 &X = before[v.index()], &x = tissue.position(v);
        if (std::abs(X.z() - z_mid) < 1e-9) hoop += std::hypot(x.x(), x.y()) / R, ++rings;
        if (std::abs(X.z() - (z_mid - dz)) < 1e-9) z_lo += x.z(), ++lo;
        if (std::abs(X.z() - (z_mid + dz)) < 1e-9) z_hi += x.z(), ++hi;
      }
      REQUIRE(rings > 0);
      REQUIRE(lo > 0);
      REQUIRE(hi > 0);
      const double hoop_stretch = hoop / rings, axial_stretch = (z_hi / hi - z_lo / lo) / (2 * dz);
      MembraneMaterial m = params.material;
      m.fibre_ratio = half == 0 ? 1.0 : 10.0;
      const double r = hoop_stretch * R, t = m.thickness;
      const Eigen::Vector3d predicted =
          m.smallStrainMatrix().inverse() * Eigen::Vector3d(P * r / t, P * r / (2 * t), 0);
      const double hoop_green = 0.5 * (hoop_stretch * hoop_stretch - 1);
      const double axial_green = 0.5 * (axial_stretch * axial_stretch - 1);
      std::cout << "cylinder halves (" << (law == MembraneLaw::NeoHookean ? "neo-Hookean" : "SVK") << "), ratio "
                << m.fibre_ratio << ": hoop strain " << hoop_green << " (predicted " << predicted[0]
                << "), axial strain " << axial_green << " (predicted " << predicted[1] << ")\n";
      CAPTURE(half, hoop_green, predicted[0], axial_green, predicted[1]);
      // Within 5 % of the larger strain (the isotropic neo-Hookean half, nu = 1/2, has no axial strain).
      const double scale = std::max(std::abs(predicted[0]), std::abs(predicted[1]));
      CHECK(std::abs(hoop_green - predicted[0]) < 0.05 * scale);
      CHECK(std::abs(axial_green - predicted[1]) < 0.05 * scale);
    }
  }
}

TEST_CASE("tissue membranes: a divided cell's parts keep its fibre ratio; a bad ratio names the cell",
          "[mechanics][neo-hookean]") {
  Tissue tissue = domeSheet(12, 3);
  auto& ratio = tissue.cellProperties().add<double>(kFibreRatioName, 2.0, DivisionPolicy::Copy);
  const CellId c = *tissue.cells().begin();
  ratio[c] = 7.5;
  const Vec3 centre = cellCentroid(tissue, c);
  const CellSplit split = tissue.splitCell(c, Plane{centre, Vec3(1, 0, 0)});
  MembraneGrowthParams params;
  params.material.law = MembraneLaw::NeoHookean;
  MembraneRestState state;
  const FanMembraneModel model = buildTissueMembranes(tissue, params, state);
  const std::vector<FaceId> faces = membraneFaces(tissue);
  int parts = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const bool part = faces[i].index() == c.index() || faces[i].index() == split.daughter.index();
    parts += part;
    CHECK(model.polygon(i).fibre_ratio == (part ? 7.5 : 2.0));
  }
  CHECK(parts == 2);
  tissue.cellProperties().get<double>(kFibreRatioName)[split.daughter] = 0.5;
  CHECK_THROWS_WITH(buildTissueMembranes(tissue, params, state),
                    Catch::Contains("cell " + std::to_string(split.daughter.index())) &&
                        Catch::Contains("fibre_ratio 0.5") && Catch::Contains("neo_hookean"));
}
