// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// network_bench: cell-level networks (issue #17): network steps per second on
//   hexagonal grids of about 1e3, 1e4 and 1e5 cells with 3 species -- auxin
//   (production, decay, passive exchange and up-the-gradient PIN efflux, the
//   parameters of configs/auxin_network_2d.yaml), A (induced by auxin, a Hill
//   term, with passive exchange) and B (repressed by A, a Hill term) -- and
//   the cost split between the right-hand side, the Jacobian and the linear
//   solver's setups (KLU factorisations) and solves, from CVODE's counters and
//   timers around the callbacks.
//
//   A network step is one solve interval of the growth loop: the network
//   stage reads the tissue's graph, keeps its system and integrator when the
//   graph keeps its structure (here always; NetworkSystem::updateGraph) and
//   integrates over dt = 2 (the time.dt of configs/auxin_network_2d.yaml,
//   where the network solves every growth step). Each variant runs the same
//   steps from the same noisy start; the variants run in turns (the machine
//   is shared and noisy, the best turn is shown) and their final states are
//   compared with a run with tolerances 1e4 times tighter (1e3 cells) or with
//   the first variant's.
//   Variants: `today` (KLU, the `neighbours` Jacobian of
//   configs/auxin_network_2d.yaml, CVODE's defaults, as the stage does),
//   `setup_every_50` (KLU, fewer setups and Jacobians), `klu_kept` (KLU, one
//   graph, system and integrator for all the steps), `gmres_neighbours` /
//   `gmres_exact` (network.linear_solver: gmres), `gmres_rebuilt` (a new
//   graph, system and integrator every step, as the stage did before),
//   `gmres_kept` (GMRES, one graph, system and integrator),
//   `gmres_2_threads` (gmres_neighbours on two OpenMP threads:
//   IntegratorOptions::threads). CVODE starts afresh every step in all of
//   them (CVodeReInit). 1e5 cells: the GMRES variants only. Columns: network steps per
//   second of the steady clock and of the process' CPU time (all threads), CVODE steps, Newton
//   iterations, right-hand sides, Jacobians, linear setups, linear solves, GMRES
//   iterations (summed over the steps), then the share of the time in the
//   right-hand side, the Jacobian, the linear setups (KLU factorisations /
//   preconditioner blocks), the linear solves, the tissue's graph (networkGraph
//   with a new GeometryCache: the tissue's geometry on OpenMP's default
//   threads), the system and integrator (new or updated), and the rest
//   (CVODE's own vector operations).
// Usage: network_bench [--quick | --gmres | --profile]   --quick: 1e3 and 1e4 cells only; --gmres: the
//   GMRES variant on one and two threads only, at every size; --profile: 1e4 cells, 5 steps of
//   gmres_neighbours once, for perf record.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "tessella/generators/grids.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/tissue/geometry.hpp"
#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "process_usage.hpp"

using namespace tessella;
using namespace tessella::networks;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kInterval = 2.0;  // one network step: dt of configs/auxin_network_2d.yaml

NetworkModel benchModel() {
  NetworkModel m;
  m.parameters = {{"p", 0.5}, {"d", 0.05}, {"kA", 1.0}, {"KA", 10.0}, {"dA", 0.1},
                  {"kB", 1.0}, {"KB", 5.0}, {"dB", 0.1}};
  m.species.push_back({"auxin", "p - d * auxin", 0.05});
  m.species.push_back({"A", "kA * auxin^2 / (KA^2 + auxin^2) - dA * A", 0.01});
  m.species.push_back({"B", "kB / (1 + (A / KB)^2) - dB * B", 0.0});
  m.pin.species = "auxin";
  m.pin.function = PinFunction::Exponential;
  m.pin.base = 2.0;
  m.pin.rate = 1.0;
  m.pin.total = 1.0;
  return m;
}

// How a variant builds its system: `Stage`, as the stage does: the tissue's graph every step, the system
// and integrator once and then updated with the new graph (NetworkSystem::updateGraph: the tissue keeps its
// structure here); `Every`, a new graph, system and integrator every step (the stage before); `Once`, one
// graph, system and integrator for all the steps. CVODE starts afresh every step (CVodeReInit) in all three.
enum class Build { Stage, Every, Once };

struct Variant {
  const char* name;
  JacobianKind jacobian;
  IntegratorOptions options;
  Build build = Build::Stage;
};

std::vector<Variant> variants() {
  IntegratorOptions today;
  today.timers = true;
  std::vector<Variant> out{{"today", JacobianKind::Neighbours, today}};
  IntegratorOptions fewer = today;
  fewer.setup_frequency = 50;
  fewer.jacobian_frequency = 200;
  out.push_back({"setup_every_50", JacobianKind::Neighbours, fewer});
  out.push_back({"klu_kept", JacobianKind::Neighbours, today, Build::Once});
  IntegratorOptions gmres = today;
  gmres.linear_solver = LinearSolver::Gmres;
  out.push_back({"gmres_neighbours", JacobianKind::Neighbours, gmres});
  out.push_back({"gmres_exact", JacobianKind::Exact, gmres});
  out.push_back({"gmres_rebuilt", JacobianKind::Neighbours, gmres, Build::Every});
  out.push_back({"gmres_kept", JacobianKind::Neighbours, gmres, Build::Once});
  IntegratorOptions two = gmres;
  two.threads = 2;
  out.push_back({"gmres_2_threads", JacobianKind::Neighbours, two});
  return out;
}

struct Run {
  double seconds = 0;
  double cpu_seconds = 0;
  double graph_seconds = 0;  // the tissue's graph (networkGraph, with the tissue's geometry)
  double build_seconds = 0;  // the system and integrator (new or updated)
  IntegratorStatistics stats;
  std::vector<double> y;
};

// `steps` network steps: graph, system, integrator (as v.build says), advance.
Run runSteps(const Tissue& tissue, const NetworkModel& model, const Variant& v, std::vector<double> y, int steps) {
  Run run;
  const double cpu_start = bench::processCpuSeconds();
  if (v.build == Build::Once) {
    const auto a = Clock::now();
    GeometryCache geometry;
    NetworkGraph graph = networkGraph(tissue, geometry, {});
    const auto b = Clock::now();
    run.graph_seconds = std::chrono::duration<double>(b - a).count();
    NetworkSystem system(model, std::move(graph), v.jacobian);
    NetworkIntegrator integrator(system, v.options);
    run.build_seconds = std::chrono::duration<double>(Clock::now() - b).count();
    for (int k = 0; k < steps; ++k) integrator.advance(y, k * kInterval, (k + 1) * kInterval);
    run.seconds = std::chrono::duration<double>(Clock::now() - a).count();
    run.stats = integrator.statistics();
    run.y = std::move(y);
    run.cpu_seconds = bench::processCpuSeconds() - cpu_start;
    return run;
  }
  std::unique_ptr<NetworkSystem> system;
  std::unique_ptr<NetworkIntegrator> integrator;
  for (int k = 0; k < steps; ++k) {
    const auto a = Clock::now();
    GeometryCache geometry;
    NetworkGraph graph = networkGraph(tissue, geometry, {});
    const auto b = Clock::now();
    run.graph_seconds += std::chrono::duration<double>(b - a).count();
    if (v.build == Build::Stage && system && system->sameStructure(graph)) {
      system->updateGraph(std::move(graph));
    } else {
      integrator.reset();
      system = std::make_unique<NetworkSystem>(model, std::move(graph), v.jacobian);
      integrator = std::make_unique<NetworkIntegrator>(*system, v.options);
    }
    integrator->resetStatistics();
    run.build_seconds += std::chrono::duration<double>(Clock::now() - b).count();
    integrator->advance(y, k * kInterval, (k + 1) * kInterval);
    run.seconds += std::chrono::duration<double>(Clock::now() - a).count();
    run.stats += integrator->statistics();
  }
  run.y = std::move(y);
  run.cpu_seconds = bench::processCpuSeconds() - cpu_start;
  return run;
}

double maxRelativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double scale = 0, diff = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    scale = std::max(scale, std::abs(a[k]));
    diff = std::max(diff, std::abs(a[k] - b[k]));
  }
  return scale > 0 ? diff / scale : diff;
}

void benchSize(std::size_t side, int steps, int turns, bool klu, std::vector<std::string> only = {}) {
  const Tissue tissue = hexagonalGrid(side, side);
  const NetworkModel model = benchModel();
  GeometryCache geometry;
  const NetworkGraph graph = networkGraph(tissue, geometry, {});
  const std::size_t n = graph.numCells(), S = model.species.size();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> noise(0.0, 0.5);
  std::vector<double> y0(n * S);
  for (std::size_t c = 0; c < n; ++c) {
    y0[c * S + 0] = (10.0 + noise(rng)) * graph.measure[c];
    y0[c * S + 1] = 1.0 * graph.measure[c];
    y0[c * S + 2] = 1.0 * graph.measure[c];
  }
  std::printf("\n%zu cells (hexagonal grid %zu x %zu), %zu unknowns, %d steps of dt = %g, %d turns\n", n, side, side,
              n * S, steps, kInterval, turns);
  std::vector<Variant> vs = variants();
  if (!klu) {  // 1e5 cells: a KLU setup takes seconds (its fill-in grows faster than the cells)
    std::erase_if(vs, [](const Variant& v) { return v.options.linear_solver == LinearSolver::Klu; });
    std::printf("  (KLU variants left out at this size)\n");
  }
  if (!only.empty())
    std::erase_if(vs, [&](const Variant& v) { return std::find(only.begin(), only.end(), v.name) == only.end(); });
  // The accuracy reference: KLU with the exact Jacobian and tolerances 1e4 times tighter (small grids).
  std::vector<double> reference;
  if (n <= 2000 && only.empty()) {
    Variant tight{"reference", JacobianKind::Exact, {}};
    tight.options.relative_tolerance = 1e-10;
    tight.options.absolute_tolerance = 1e-13;
    reference = runSteps(tissue, model, tight, y0, steps).y;
  }
  std::vector<Run> best(vs.size());
  for (int t = 0; t < turns; ++t)
    for (std::size_t v = 0; v < vs.size(); ++v) {
      Run r = runSteps(tissue, model, vs[v], y0, steps);
      if (t == 0 || r.seconds < best[v].seconds) best[v] = std::move(r);
    }
  std::printf("  %-16s %9s %9s %7s %7s %7s %7s %7s %7s %7s %6s %6s %6s %6s %6s %6s %6s %9s\n", "variant",
              "steps/s", "cpu st/s", "cvsteps", "newton", "rhs", "jac", "setups", "solves", "lin.it", "rhs%", "jac%",
              "setup%", "solve%", "graph%", "build%", "other%", "max rel");
  const double base_rate = steps / best[0].seconds;
  const std::vector<double>& compared = reference.empty() ? best[0].y : reference;
  std::printf("  max rel: the largest difference from %s's final amounts over the largest amount\n",
              reference.empty() ? vs[0].name : "a run with tolerances 1e4 times tighter");
  for (std::size_t v = 0; v < vs.size(); ++v) {
    const Run& r = best[v];
    const IntegratorStatistics& s = r.stats;
    const double rate = steps / r.seconds;
    const double other = r.seconds - s.rhs_seconds - s.jacobian_seconds - s.setup_seconds - s.solve_seconds -
                         r.graph_seconds - r.build_seconds;
    auto pc = [&](double x) { return 100.0 * x / r.seconds; };
    std::printf("  %-16s %9.3g %9.3g %7ld %7ld %7ld %7ld %7ld %7ld %7ld %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f"
                " %9.2e\n",
                vs[v].name, rate, steps / r.cpu_seconds, s.steps, s.nonlinear_iterations, s.rhs_evaluations,
                s.jacobian_evaluations, s.linear_setups, s.linear_solves, s.linear_iterations, pc(s.rhs_seconds),
                pc(s.jacobian_seconds), pc(s.setup_seconds), pc(s.solve_seconds), pc(r.graph_seconds),
                pc(r.build_seconds), pc(other),
                maxRelativeDifference(compared, r.y));
    const std::string name = "network_steps_per_s_" + std::to_string(n) + "_" + vs[v].name;
    const double target = side == 100 ? 10.0 : bench::kNoTarget;  // issue #17: 1e4 cells >= 10 steps/s
    if (v == 0 || !klu)
      bench::printFigure(name, rate, "/s", target, bench::Better::Higher);
    else
      bench::printFigure(name, rate, "/s", base_rate, "today", bench::kNoTarget, bench::Better::Higher);
  }
  if (vs.size() > 1) {
    std::size_t fastest = 0;
    for (std::size_t v = 1; v < vs.size(); ++v)
      if (best[v].seconds < best[fastest].seconds) fastest = v;
    if (side == 100)
      bench::printFigure("network_steps_per_s_" + std::to_string(n) + "_fastest", steps / best[fastest].seconds,
                         "/s", 10.0, bench::Better::Higher);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string flag = bench::flagArgument(argc, argv, {"--quick", "--gmres", "--profile"},
                                               "network_bench [--quick | --gmres | --profile]");
  if (flag == "--profile") {
    benchSize(100, 5, 1, false, {"gmres_neighbours"});
    return 0;
  }
  if (flag == "--gmres") {
    for (auto [side, steps, turns] : {std::tuple{32, 10, 3}, std::tuple{100, 5, 2}, std::tuple{316, 2, 1}})
      benchSize(static_cast<std::size_t>(side), steps, turns, false, {"gmres_neighbours", "gmres_2_threads"});
    return 0;
  }
  const bool quick = flag == "--quick";
  benchSize(32, 10, 3, true);    // 1024 cells
  benchSize(100, 5, 2, true);    // 10^4 cells
  if (!quick) benchSize(316, 2, 1, false);  // 99856 cells
  return 0;
}
