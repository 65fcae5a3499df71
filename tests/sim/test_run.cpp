// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// End-to-end: example configs -> PreparedRun -> series on disk -> read back.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/run/run_record.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;
using Catch::Matchers::Contains;

namespace {

std::string readText(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<fs::path> snapshotsIn(const fs::path& dir, const std::string& name = "tissue") {
  std::vector<fs::path> files;
  const std::regex pattern(name + R"(_\d+\.vtu)");
  for (const auto& e : fs::directory_iterator(dir))
    if (std::regex_match(e.path().filename().string(), pattern)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The timestep attributes of a .pvd, in file order.
std::vector<double> pvdTimes(const fs::path& pvd) {
  const std::string text = readText(pvd);
  std::vector<double> times;
  const std::regex dataset(R"re(<DataSet[^>]*timestep="([^"]+)")re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset); it != std::sregex_iterator(); ++it)
    times.push_back(std::stod((*it)[1]));
  return times;
}

struct RunResult {
  std::string directory;
  std::size_t steps = 0;
  std::size_t every = 1;
  std::size_t initial_cells = 0;
  std::size_t final_cells = 0;  // differs when the config divides cells
  double start = 0, end = 0;
};

RunResult runConfig(const std::string& config_path, const std::string& out,
                    const std::vector<std::string>& overrides = {}, bool overwrite = false) {
  PreparedRun run = PreparedRun::prepare(loadSimulationConfigFile(config_path, overrides), RunOptions{out, overwrite});
  CHECK_FALSE(fs::exists(out));  // nothing written before execute()
  const std::size_t initial = run.simulation().tissue().numCells();
  run.execute();
  return RunResult{run.outputDirectory(), run.simulation().stepsDone(), run.config().output.every, initial,
                   run.simulation().tissue().numCells(), run.config().time.start, run.config().time.end};
}

void checkSeries(const RunResult& r) {
  const fs::path dir = r.directory;
  const auto snapshots = snapshotsIn(dir);
  const std::size_t expected = expectedSnapshots(r.steps, r.every);
  CHECK(snapshots.size() == expected);
  const auto times = pvdTimes(dir / "tissue.pvd");
  REQUIRE(times.size() == expected);
  CHECK(times.front() == Approx(r.start));
  CHECK(times.back() == Approx(r.end));
  CHECK(std::is_sorted(times.begin(), times.end()));
  REQUIRE(fs::exists(dir / kRunRecordName));
  // The first and last snapshots read back as valid tissues with every cell.
  CHECK(io::readTissueVtu(snapshots.front().string()).numCells() == r.initial_cells);
  const Tissue last = io::readTissueVtu(snapshots.back().string());
  CHECK(last.numCells() == r.final_cells);
  const ValidationReport report = validate(last);
  CHECK(report.ok);
  INFO(report.message);
}

}  // namespace

TEST_CASE("every example config runs end to end and writes a complete series", "[sim][run][configs]") {
  std::vector<fs::path> configs;
  for (const auto& e : fs::directory_iterator(sourcePath("configs")))
    if (e.path().extension() == ".yaml") configs.push_back(e.path());
  std::sort(configs.begin(), configs.end());
  REQUIRE(configs.size() >= 4);
  for (const fs::path& config : configs) {
    DYNAMIC_SECTION(config.filename().string()) {
      ScratchDir scratch;
      const RunResult r = runConfig(config.string(), scratch / "out");
      CHECK(r.initial_cells > 0);
      checkSeries(r);
      // run.yaml reloads to the same resolved configuration.
      const fs::path record = fs::path(r.directory) / kRunRecordName;
      const SimulationConfig reloaded = loadSimulationConfigFile(record.string());
      CHECK(resolvedConfigYaml(reloaded.config) == readText(record));
    }
  }
}

TEST_CASE("the example configs are what their comments say", "[sim][run][configs]") {
  const auto hex = loadSimulationConfigFile(sourcePath("configs/hex_grid_2d.yaml"));
  CHECK(hex.time.numSteps() == 5);
  CHECK(expectedSnapshots(5, hex.output.every) == 4);  // steps 0, 2, 4, 5
  const auto disk = loadSimulationConfigFile(sourcePath("configs/voronoi_disk_2d.yaml"));
  CHECK(std::get<GeneratorSpec>(disk.tissue).shape().dim == 2);
  const auto box = loadSimulationConfigFile(sourcePath("configs/voronoi_box_3d.yaml"));
  CHECK(std::get<GeneratorSpec>(box.tissue).shape().dim == 3);
  const auto dome = loadSimulationConfigFile(sourcePath("configs/dome.yaml"));
  CHECK(std::get<GeneratorSpec>(dome.tissue).name == "dome");
}

TEST_CASE("re-running from run.yaml reproduces the run, random seed included", "[sim][run]") {
  ScratchDir scratch;
  // No rng_seed: one is drawn, and run.yaml must record it.
  const std::string config = scratch.write(
      "random.yaml",
      "tissue:\n  generator: voronoi\n  voronoi:\n    domain: disk\n    count: 25\n    lloyd_iterations: 1\n"
      "    disk: {radius: 3, boundary_segments: 64}\n"
      "time: {end: 2, dt: 1}\n");
  const RunResult first = runConfig(config, scratch / "first");
  const std::string record = (fs::path(first.directory) / kRunRecordName).string();
  CHECK_THAT(readText(record), Contains("rng_seed: "));
  const RunResult second = runConfig(record, scratch / "second");

  const auto a = snapshotsIn(first.directory), b = snapshotsIn(second.directory);
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Tissue ta = io::readTissueVtu(a[i].string()), tb = io::readTissueVtu(b[i].string());
    REQUIRE(ta.numCells() == tb.numCells());
    REQUIRE(ta.numVertices() == tb.numVertices());
    REQUIRE(ta.positions().size() == tb.positions().size());
    for (std::size_t v = 0; v < ta.positions().size(); ++v) CHECK(ta.positions()[v] == tb.positions()[v]);
  }
  // The second run.yaml differs from the first only in its output directory.
  auto withoutDirectory = [](std::string text) {
    return std::regex_replace(text, std::regex(R"(\n  directory: [^\n]*)"), "");
  };
  CHECK(withoutDirectory(readText(record)) ==
        withoutDirectory(readText(fs::path(second.directory) / kRunRecordName)));
}

TEST_CASE("a directory that holds a run is refused unless overwriting", "[sim][run]") {
  ScratchDir scratch;
  const std::string config = sourcePath("configs/hex_grid_2d.yaml");
  const std::string out = scratch / "out";
  runConfig(config, out, {"time.end=6"});
  REQUIRE(snapshotsIn(out).size() == expectedSnapshots(6, 2));

  const ConfigError e = configErrorOf(
      [&] { PreparedRun::prepare(loadSimulationConfigFile(config), RunOptions{out, false}); });
  CHECK(e.keyPath() == "output.directory");
  CHECK_THAT(e.what(), Contains("--out " + out) && Contains("already holds a run") && Contains("--overwrite"));

  // Overwriting a longer run with a shorter one leaves no stale snapshots.
  PreparedRun again =
      PreparedRun::prepare(loadSimulationConfigFile(config, {"time.end=1"}), RunOptions{out, true});
  again.execute();
  CHECK(snapshotsIn(out).size() == expectedSnapshots(1, 2));
  CHECK(pvdTimes(fs::path(out) / "tissue.pvd").size() == expectedSnapshots(1, 2));
}

TEST_CASE("bad input found while building the tissue writes nothing", "[sim][run]") {
  ScratchDir scratch;
  scratch.write("bad.csv", "x,y\n1,1\n2,oops\n3,1\n");
  const std::string config = scratch.write(
      "c.yaml", "tissue:\n  generator: voronoi\n  voronoi:\n    seed_file: bad.csv\n");
  const std::string out = scratch / "out";
  const ConfigError e =
      configErrorOf([&] { PreparedRun::prepare(loadSimulationConfigFile(config), RunOptions{out, false}); });
  CHECK(e.keyPath() == "tissue.voronoi.seed_file");
  CHECK_THAT(e.what(), Contains("c.yaml:4:16") && Contains("bad.csv"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("the default output directory is runs/<config name>", "[sim][run]") {
  ScratchDir scratch;
  const std::string config = scratch.write("my_tissue.yaml", "tissue: {generator: rectangular_grid}\n");
  const fs::path cwd = fs::current_path();
  fs::current_path(scratch.path());
  const std::string dir = [&] {
    PreparedRun run = PreparedRun::prepare(loadSimulationConfigFile(config));
    return run.outputDirectory();
  }();
  fs::current_path(cwd);
  CHECK(dir == (scratch.path() / "runs" / "my_tissue").string());
  CHECK_FALSE(fs::exists(dir));
}

TEST_CASE("an empty output directory given (--out '') is refused, not taken for the default", "[sim][run]") {
  ScratchDir scratch;
  const std::string config = scratch.write("my_tissue.yaml", "tissue: {generator: rectangular_grid}\n");
  const fs::path cwd = fs::current_path();
  fs::current_path(scratch.path());
  const ConfigError e = configErrorOf(
      [&] { PreparedRun::prepare(loadSimulationConfigFile(config), RunOptions{std::string(), false}); });
  fs::current_path(cwd);
  CHECK(e.keyPath() == "output.directory");
  CHECK_THAT(e.what(), Contains("--out ''") && Contains("empty"));
  CHECK_FALSE(fs::exists(scratch.path() / "runs"));
}

TEST_CASE("a run restarted from a snapshot ends where the uninterrupted run ends", "[sim][run][restart]") {
  ScratchDir scratch;
  // figure17 is deterministic (fixed threshold, main-axis division): the
  // restart must reproduce every cell, by lineage id, of the whole run.
  const std::string config = sourcePath("configs/figure17.yaml");
  const RunResult whole = runConfig(config, scratch / "whole", {"time.end=2", "output.every=20"});
  const auto snapshots = snapshotsIn(whole.directory);
  const auto times = pvdTimes(fs::path(whole.directory) / "tissue.pvd");
  REQUIRE(snapshots.size() == 3);
  REQUIRE(times[1] == Approx(1.0));
  const Tissue middle = io::readTissueVtu(snapshots[1].string());
  const Tissue end = io::readTissueVtu(snapshots.back().string());
  REQUIRE(end.numCells() > middle.numCells());  // divisions happen after the restart point

  const std::vector<std::string> restart{"tissue.generator=snapshot",
                                         "tissue.snapshot.file=" + snapshots[1].string(), "time.end=2",
                                         "output.every=20"};
  PreparedRun run = PreparedRun::prepare(loadSimulationConfigFile(config, restart), RunOptions{scratch / "rest", false});
  CHECK(run.config().time.start == Approx(1.0));  // the clock continues the snapshot's
  REQUIRE(run.simulation().tissue().numCells() == middle.numCells());
  run.execute();
  const Tissue& resumed = run.simulation().tissue();
  REQUIRE(resumed.numCells() == end.numCells());
  std::map<std::int64_t, CellId> by_lineage;
  for (CellId c : end.cells()) by_lineage[end.lineageId(c)] = c;
  for (CellId c : resumed.cells()) {
    const auto it = by_lineage.find(resumed.lineageId(c));
    REQUIRE(it != by_lineage.end());
    CHECK(resumed.parentId(c) == end.parentId(it->second));
    CHECK(resumed.birthTime(c) == Approx(end.birthTime(it->second)));
    CHECK(cellMeasure(resumed, c) == Approx(cellMeasure(end, it->second)).epsilon(1e-9));
    CHECK((cellCentroid(resumed, c) - cellCentroid(end, it->second)).norm() < 1e-9);
  }
  CHECK(validate(resumed).ok);
}

TEST_CASE("a bad restart snapshot is a located error", "[sim][run][restart]") {
  ScratchDir scratch;
  scratch.write("not_a_snapshot.vtu", "this is not VTK XML\n");
  const std::string config = scratch.write(
      "restart.yaml", "tissue:\n  generator: snapshot\n  snapshot:\n    file: not_a_snapshot.vtu\n");
  const ConfigError bad = configErrorOf([&] { loadSimulationConfigFile(config); });
  CHECK(bad.keyPath() == "tissue.snapshot.file");
  CHECK_THAT(bad.what(), Contains("restart.yaml:4:11") && Contains("not_a_snapshot.vtu"));

  const std::string missing = scratch.write(
      "missing.yaml", "tissue:\n  generator: snapshot\n  snapshot:\n    file: nowhere.vtu\n");
  CHECK(configErrorOf([&] { loadSimulationConfigFile(missing); }).keyPath() == "tissue.snapshot.file");
  const std::string absent = scratch.write("absent.yaml", "tissue:\n  generator: snapshot\n");
  CHECK(configErrorOf([&] { loadSimulationConfigFile(absent); }).keyPath() == "tissue.snapshot.file");
}
