// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Stopping a run early (Ctrl-C in `tessella run`): a stop flag ends run() and
// PreparedRun::execute() between steps, with every file written complete.

#include <catch2/catch.hpp>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tessella/sim/run/run.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/generators/grids.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;

namespace {

std::vector<std::string> entriesOf(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::size_t pvdEntries(const fs::path& pvd) {
  std::ifstream f(pvd);
  std::ostringstream s;
  s << f.rdbuf();
  const std::string text = s.str();
  std::size_t n = 0;
  for (auto at = text.find("<DataSet"); at != std::string::npos; at = text.find("<DataSet", at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("a stop flag ends run() and runUntil() between steps", "[sim][stop]") {
  Simulation sim(rectangularGrid(2, 2), {.time = {0, 10, 1}});
  std::atomic<bool> stop{false};
  sim.setStopFlag(&stop);
  sim.onStep([&](const Simulation& s) {
    if (s.stepsDone() == 3) stop = true;
  });
  sim.run();
  CHECK(sim.stepsDone() == 3);
  CHECK(sim.stopRequested());
  CHECK_FALSE(sim.finished());
  sim.runUntil(8.0);
  CHECK(sim.stepsDone() == 3);
  stop = false;  // cleared: the run goes on to the end
  sim.run();
  CHECK(sim.finished());
  sim.setStopFlag(nullptr);
  CHECK_FALSE(sim.stopRequested());
}

TEST_CASE("a stopped PreparedRun leaves complete snapshots listed in the .pvd", "[sim][stop]") {
  ScratchDir scratch;
  const std::string out = scratch / "out";
  PreparedRun run = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/hex_grid_2d.yaml"), {"time.end=20", "output.every=1"}),
      RunOptions{out, false});
  std::atomic<bool> stop{false};
  run.simulation().setStopFlag(&stop);
  run.simulation().onStep([&](const Simulation& s) {
    if (s.stepsDone() == 4) stop = true;
  });
  run.execute();
  CHECK(run.interrupted());
  CHECK(run.simulation().stepsDone() == 4);
  CHECK(run.snapshots() == 5);  // steps 0..4
  CHECK(run.seriesPath() == (fs::path(out) / "tissue.pvd").string());
  CHECK(pvdEntries(run.seriesPath()) == 5);
  CHECK(entriesOf(out) == std::vector<std::string>{"run.yaml", "stats.csv", "tissue.pvd", "tissue_000000.vtu", "tissue_000001.vtu",
                                                   "tissue_000002.vtu", "tissue_000003.vtu", "tissue_000004.vtu"});
}

TEST_CASE("a PreparedRun stopped before execute() writes nothing", "[sim][stop]") {
  ScratchDir scratch;
  const std::string out = scratch / "out";
  PreparedRun run =
      PreparedRun::prepare(loadSimulationConfigFile(sourcePath("configs/hex_grid_2d.yaml")), RunOptions{out, false});
  std::atomic<bool> stop{true};
  run.simulation().setStopFlag(&stop);
  run.execute();
  CHECK(run.interrupted());
  CHECK(run.snapshots() == 0);
  CHECK(run.seriesPath().empty());
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("overwriting a run also removes the temporaries an interrupted one left", "[sim][stop][run]") {
  ScratchDir scratch;
  const std::string out = scratch / "out";
  const std::string config = sourcePath("configs/hex_grid_2d.yaml");
  PreparedRun::prepare(loadSimulationConfigFile(config, {"time.end=1"}), RunOptions{out, false}).execute();
  for (const char* stale : {"tissue_000009.vtu.tmp-4242-0", "tissue.pvd.tmp-4242-1", "run.yaml.tmp",
                            "run.yaml.tmp-4242-2", "fields_000001.vtu.tmp-4242-3"})
    std::ofstream(fs::path(out) / stale);
  std::ofstream(fs::path(out) / "notes.tmp-1-2");  // not a file of the run: kept
  PreparedRun::prepare(loadSimulationConfigFile(config, {"time.end=1"}), RunOptions{out, true}).execute();
  CHECK(entriesOf(out) ==
        std::vector<std::string>{"notes.tmp-1-2", "run.yaml", "stats.csv", "tissue.pvd", "tissue_000000.vtu", "tissue_000001.vtu"});
}
