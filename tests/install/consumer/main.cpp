// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Checks an installed Tessella from the outside: a hexagonal tissue, a
// property divided with its policy, division along the main axis, validation
// and (when the growth module is installed) growth by a velocity field and
// scheduled division. Every check compares against a value known
// independently (conservation, cell counts, the exact solution of a linear
// field); the exit status is the number of failed checks.
#include <cmath>
#include <cstdio>
#include <vector>

#include <tessella/generators.hpp>
#include <tessella/tissue.hpp>
#ifdef CONSUMER_WITH_GROWTH
#include <tessella/growth/growth.hpp>
#endif

using namespace tessella;

namespace {

int failures = 0;

void check(bool ok, const char* what, double got = NAN, double expected = NAN) {
  std::printf("%s %s", ok ? "ok  " : "FAIL", what);
  if (!std::isnan(got)) std::printf(" (got %.12g, expected %.12g)", got, expected);
  std::printf("\n");
  if (!ok) ++failures;
}

bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }

double sum(const Tissue& t, const PropertyColumn<double>& p) {
  double s = 0;
  for (CellId c : t.cells()) s += p[c];
  return s;
}

}  // namespace

int main() {
  try {
    Tissue t = hexagonalGrid(6, 5, 1.0);
    const std::size_t n0 = t.numCells();
    const double area0 = totalMeasure(t);
    // A regular hexagon of circumradius 1 has area 3 sqrt(3) / 2.
    check(n0 == 30, "hexagonal grid has 6 x 5 cells", double(n0), 30);
    check(close(area0, 30 * 1.5 * std::sqrt(3.0), 1e-12), "grid area", area0, 30 * 1.5 * std::sqrt(3.0));

    // An amount of substance (split by area) and an identity (copied).
    auto& amount = t.cellProperties().add<double>("amount", 0.0, DivisionPolicy::SplitByMeasure);
    auto& identity = t.cellProperties().add<int>("identity", 0, DivisionPolicy::Copy);
    for (CellId c : t.cells()) {
      amount[c] = 1.0 + 0.1 * c.index();
      identity[c] = static_cast<int>(c.index() % 3);
    }
    const double amount0 = sum(t, amount);

    // Divide every cell across its longest principal axis.
    std::vector<CellId> mothers(t.cells().begin(), t.cells().end());
    int lineage_ok = 0, identity_ok = 0;
    for (CellId c : mothers) {
      const Vec3 axis = cellPrincipalAxes(t, c).axes.col(0);
      const std::int64_t mother_lineage = t.lineageId(c);
      const int mother_identity = identity[c];
      CellSplit s = t.splitCell(c, Plane{cellCentroid(t, c), axis});
      lineage_ok += t.parentId(s.daughter) == mother_lineage;
      identity_ok += identity[s.daughter] == mother_identity && identity[c] == mother_identity;
    }
    check(t.numCells() == 2 * n0, "every cell divided once", double(t.numCells()), double(2 * n0));
    check(lineage_ok == int(n0), "daughters record their mother's lineage id");
    check(identity_ok == int(n0), "Copy policy: both parts keep the identity");
    check(close(totalMeasure(t), area0, 1e-12), "division conserves area", totalMeasure(t), area0);
    check(close(sum(t, amount), amount0, 1e-12), "SplitByMeasure conserves the amount", sum(t, amount), amount0);
    ValidationReport report = validate(t);
    check(report.ok, "validate() after division");
    if (!report.ok) std::printf("     %s\n", report.message.c_str());

#ifdef CONSUMER_WITH_GROWTH
    // Uniform expansion v = r x: every length scales by exp(r T), so the area
    // by exp(2 r T). Heun is second order: 20 steps of 0.05 are well within 1e-4.
    const double rate = 0.2, dt = 0.05;
    const int steps = 20;
    auto field = std::make_shared<growth::LinearField>(growth::uniformExpansion(rate));
    growth::GrowthIntegrator integrator(field);
    for (int i = 0; i < steps; ++i) integrator.step(t, dt);
    const double expected = area0 * std::exp(2 * rate * steps * dt);
    check(close(t.time(), steps * dt, 1e-12), "integrator advanced the clock", t.time(), steps * dt);
    check(close(totalMeasure(t), expected, 1e-4), "area after uniform expansion", totalMeasure(t), expected);

    // Cells now have about 1.3 x 1.49 x the half-hexagon area: a threshold of
    // the mean cell area divides roughly half of them, each along its main axis.
    const std::size_t before = t.numCells();
    const double area_before = totalMeasure(t);
    const double amount_before = sum(t, amount);
    growth::DivisionScheduler scheduler(growth::SizeThreshold::fixed(area_before / double(before)),
                                        std::make_shared<growth::MainAxisRule>());
    GeometryCache geometry;
    recomputeGeometry(t, geometry);
    growth::DivisionReport divisions = scheduler.step(t, geometry);
    std::printf("     scheduler: %zu divided, %zu skipped\n", divisions.divided.size(),
                divisions.skipped.size());
    check(!divisions.divided.empty(), "scheduler divided cells over the threshold");
    check(t.numCells() == before + divisions.divided.size(), "one new cell per division",
          double(t.numCells()), double(before + divisions.divided.size()));
    check(close(totalMeasure(t), area_before, 1e-12), "scheduled division conserves area", totalMeasure(t),
          area_before);
    check(close(sum(t, amount), amount_before, 1e-12), "scheduled division conserves the amount",
          sum(t, amount), amount_before);
    report = validate(t);
    check(report.ok, "validate() after growth and division");
    if (!report.ok) std::printf("     %s\n", report.message.c_str());
#else
    std::printf("skip growth checks: the growth module is not installed\n");
#endif
  } catch (const std::exception& e) {
    std::printf("FAIL exception: %s\n", e.what());
    return 100;
  }
  std::printf("%d failed check(s)\n", failures);
  return failures;
}
