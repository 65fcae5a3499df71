// growth_bench: cost of growth and division.
//   growth step = move vertices (Euler or Heun) + recompute geometry + check
//   thresholds (the integrator's step, then SizeThreshold::cellsDue), on 2D
//   grids of 1e4, 1e5, 1e6 cells and a 3D grid of 1e4 cells, with 1 and 2
//   OpenMP threads; then the cost of one division (rule + splitCell) per rule.
// Usage: growth_bench [--quick]   (--quick skips the 1e6-cell tissue)

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "tessella/growth/division_rule_factory.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/grids.hpp"
#include "tessella/tissue/voronoi.hpp"

using namespace tessella;
using namespace tessella::growth;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Milliseconds per growth step (best of `repeats` runs of `steps` steps).
double growthStepMs(const Tissue& start, IntegrationScheme scheme, int threads, int steps, int repeats) {
  omp_set_num_threads(threads);
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    Tissue t = start;
    GrowthIntegrator g(std::make_shared<LinearField>(uniformExpansion(0.01)), GrowthOptions{.scheme = scheme});
    const SizeThreshold threshold = SizeThreshold::fixed(1e9);  // checked, never reached
    Rng rng(1);
    std::size_t due = 0;
    const auto a = Clock::now();
    for (int s = 0; s < steps; ++s) {
      g.step(t, 0.01);
      due += threshold.cellsDue(t, g.geometry(), rng).size();
    }
    const auto b = Clock::now();
    if (due != 0) std::printf("unexpected divisions\n");
    best = std::min(best, 1e3 * seconds(a, b) / steps);
  }
  return best;
}

// Growth and division together: steps per second while cells divide.
void growthWithDivision(const char* label, const Tissue& start, int threads, int steps) {
  omp_set_num_threads(threads);
  Tissue t = start;
  const double mean = totalMeasure(t) / static_cast<double>(t.numCells());
  GrowthIntegrator g(std::make_shared<LinearField>(uniformExpansion(0.2)));
  DivisionScheduler d(SizeThreshold::noisy(1.5 * mean, 0.1 * mean), makeDivisionRule("main_axis"));
  std::size_t divisions = 0;
  const auto a = Clock::now();
  for (int s = 0; s < steps; ++s) {
    g.step(t, 0.05);
    divisions += d.step(t, const_cast<GeometryCache&>(g.geometry())).divided.size();
  }
  const double sec = seconds(a, Clock::now());
  std::printf("  %-28s %d thr: %7.2f steps/s, %zu divisions (%zu -> %zu cells)\n", label, threads,
              steps / sec, divisions, start.numCells(), t.numCells());
}

// Microseconds per division (rule plane + splitCell) over every cell once.
void divisionCost(const char* label, const Tissue& start, const std::string& rule_name) {
  omp_set_num_threads(1);
  Tissue t = start;
  auto rule = makeDivisionRule(rule_name);
  Rng rng(3);
  std::vector<CellId> cells;
  for (CellId c : t.cells()) cells.push_back(c);
  std::size_t failed = 0;
  double plane_s = 0;
  const auto a = Clock::now();
  for (CellId c : cells) {
    const auto p0 = Clock::now();
    const Plane p = rule->plane(t, c, rng);
    plane_s += seconds(p0, Clock::now());
    try {
      t.splitCell(c, p);
    } catch (const GeometryError&) {
      ++failed;
    }
  }
  const double total = seconds(a, Clock::now());
  std::printf("  %-4s %-30s %8.2f us/division (rule %7.2f us, split %6.2f us)%s\n", label,
              rule_name.c_str(), 1e6 * total / cells.size(), 1e6 * plane_s / cells.size(),
              1e6 * (total - plane_s) / cells.size(), failed ? " [some cuts refused]" : "");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::printf("growth_bench (OpenMP max threads %d)\n\n", omp_get_max_threads());

  std::printf("Growth step: move vertices + recompute geometry + check thresholds\n");
  struct Case { const char* name; Tissue tissue; double target_ms_2thr; };
  std::vector<Case> cases;
  cases.push_back({"2D 1e4 cells (100x100)", rectangularGrid(100, 100), -1});
  cases.push_back({"2D 1e5 cells (316x316)", rectangularGrid(316, 316), 10.0});
  if (!quick) cases.push_back({"2D 1e6 cells (1000x1000)", rectangularGrid(1000, 1000), 60.0});
  cases.push_back({"3D 1e4 cells (22x22x21)", boxGrid(22, 22, 21), -1});
  for (const Case& c : cases) {
    const int steps = c.tissue.numCells() >= 1000000 ? 5 : 20;
    for (IntegrationScheme scheme : {IntegrationScheme::Euler, IntegrationScheme::Heun}) {
      const double one = growthStepMs(c.tissue, scheme, 1, steps, 3);
      const double two = growthStepMs(c.tissue, scheme, 2, steps, 3);
      std::printf("  %-26s %-5s 1 thr %8.2f ms  2 thr %8.2f ms", c.name, schemeName(scheme), one, two);
      if (c.target_ms_2thr > 0)
        std::printf("   (target < %.0f ms with 2 threads: %s)", c.target_ms_2thr,
                    two < c.target_ms_2thr ? "met" : "NOT met");
      std::printf("\n");
    }
  }

  std::printf("\nGrowth + division (uniform expansion, main axis, noisy threshold)\n");
  for (int threads : {1, 2}) {
    growthWithDivision("2D 1e4 cells", rectangularGrid(100, 100), threads, 20);
    growthWithDivision("2D 1e5 cells", rectangularGrid(316, 316), threads, 10);
    growthWithDivision("3D 1e4 cells", boxGrid(22, 22, 21), threads, 10);
  }

  std::printf("\nOne division (rule + Tissue::splitCell), 1 thread; target < 10 us in 2D\n");
  const Rectangle domain{Vec3(0, 0, 0), Vec3(100, 100, 0)};
  const Tissue voronoi = voronoiTissue(randomSeeds(domain, 10000, 1), domain);
  const Tissue box = boxGrid(10, 10, 10);
  for (const std::string& rule : divisionRuleNames()) divisionCost("2D", voronoi, rule);
  for (const std::string& rule : divisionRuleNames()) divisionCost("3D", box, rule);
  return 0;
}
