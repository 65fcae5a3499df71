// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The wall-spring/turgor energy's gradient and Hessian against central finite
// differences, on a Voronoi tissue with random rest lengths (walls stretched
// and compressed, so the Hessian is indefinite) and random pressures.
#include <catch2/catch.hpp>

#include "tessella/generators/voronoi.hpp"
#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/mechanics/wall_spring_model.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

#include <Eigen/Eigenvalues>

#include <random>

using namespace tessella;
using namespace tessella::mechanics;

namespace {

struct Fixture {
  Tissue tissue;
  WallSpringModel model;
  Eigen::VectorXd x;
};

Fixture makeFixture() {
  Rectangle domain{Vec3(0, 0, 0), Vec3(4, 3, 0)};
  Tissue t = voronoiTissue(randomSeeds(domain, 12, 7), domain);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> rest(t.slots(1), 0.0), stiff(t.slots(1), 0.0), pressure(t.cellSlots(), 0.0);
  for (EdgeId e : t.edges()) {
    rest[e.index()] = edgeLength(t, e) * (0.7 + 0.6 * u(rng));  // some compressed, some stretched
    stiff[e.index()] = 0.5 + u(rng);
  }
  for (CellId c : t.cells()) pressure[c.index()] = 0.05 + 0.2 * u(rng);
  WallSpringModel model = WallSpringModel::fromTissue(t, rest, stiff, pressure);
  Eigen::VectorXd x = planarDofs(t);
  return {std::move(t), std::move(model), std::move(x)};
}

}  // namespace

TEST_CASE("wall-spring energy: gradient equals central finite differences of the energy", "[mechanics]") {
  const Fixture f = makeFixture();
  Eigen::VectorXd g;
  f.model.gradient(f.x, g);
  const double h = 1e-6;
  double worst = 0.0;
  for (VertexId v : f.tissue.vertices())
    for (int k = 0; k < 2; ++k) {
      const Eigen::Index i = 2 * v.index() + k;
      Eigen::VectorXd xp = f.x, xm = f.x;
      xp[i] += h;
      xm[i] -= h;
      const double fd = (f.model.energy(xp) - f.model.energy(xm)) / (2 * h);
      worst = std::max(worst, std::abs(fd - g[i]));
    }
  // Central differences: O(h^2) truncation plus round-off eps E / h ~ 1e-10.
  CHECK(worst < 1e-7 * std::max(1.0, g.lpNorm<Eigen::Infinity>()));
  CHECK(g.norm() > 1e-2);  // the check is not vacuous
}

TEST_CASE("wall-spring energy: Hessian equals central finite differences of the gradient", "[mechanics]") {
  const Fixture f = makeFixture();
  std::vector<Triplet> entries;
  f.model.hessian(f.x, entries);
  Eigen::SparseMatrix<double> H(f.model.size(), f.model.size());
  H.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd dense = H;
  CHECK((dense - dense.transpose()).lpNorm<Eigen::Infinity>() < 1e-14 * dense.lpNorm<Eigen::Infinity>());
  const double h = 1e-6;
  double worst = 0.0;
  Eigen::VectorXd gp, gm;
  for (VertexId v : f.tissue.vertices())
    for (int k = 0; k < 2; ++k) {
      const Eigen::Index i = 2 * v.index() + k;
      Eigen::VectorXd xp = f.x, xm = f.x;
      xp[i] += h;
      xm[i] -= h;
      f.model.gradient(xp, gp);
      f.model.gradient(xm, gm);
      const Eigen::VectorXd fd = (gp - gm) / (2 * h);
      worst = std::max(worst, (fd - dense.col(i)).lpNorm<Eigen::Infinity>());
    }
  CHECK(worst < 1e-6 * dense.lpNorm<Eigen::Infinity>());
  // Some walls are compressed: the tangent is indefinite somewhere.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense);
  CHECK(eig.eigenvalues().minCoeff() < -1e-6);
}

TEST_CASE("wall-spring energy: the area and spring terms match their formulas", "[mechanics]") {
  const Fixture f = makeFixture();
  std::size_t j = 0;
  for (FaceId face : f.tissue.faces()) {
    CHECK(f.model.area(f.x, j) == Approx(polygonMeasures(f.tissue, face).area).epsilon(1e-12));
    ++j;
  }
  for (std::size_t i = 0; i < f.model.springs().size(); ++i) {
    const WallSpring& s = f.model.springs()[i];
    const double L = edgeLength(f.tissue, EdgeId(f.model.springElement()[i]));
    CHECK(f.model.length(f.x, i) == Approx(L).epsilon(1e-14));
    CHECK(f.model.tension(f.x, i) == Approx(s.stiffness * (L - s.rest_length) / s.rest_length).epsilon(1e-12));
  }
}

TEST_CASE("wall-spring model: bad input is refused with the element named", "[mechanics]") {
  CHECK_THROWS_WITH(WallSpringModel(3, {{0, 1, 0.0, 1.0}}, {}), Catch::Contains("wall spring 0") &&
                                                                  Catch::Contains("rest length 0"));
  CHECK_THROWS_WITH(WallSpringModel(3, {{0, 5, 1.0, 1.0}}, {}), Catch::Contains("wall spring 0"));
  CHECK_THROWS_WITH(WallSpringModel(3, {}, {{{0, 1}, 0.1}}), Catch::Contains("pressurised cell 0"));
  Tissue t3(3, Embedding::Volume);
  CHECK_THROWS_AS(WallSpringModel::fromTissue(t3, {}, {}, {}), InputError);
}
