// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// stats.csv: one row per snapshot, checked against the snapshots themselves
// (cell counts, total measure, field amounts) and against conservation (each
// division adds exactly one cell), and kept row by row when a run stops.

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;

namespace {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return static_cast<std::size_t>(it - header.begin());
  }
  double number(std::size_t row, const std::string& name) const { return std::stod(rows[row][column(name)]); }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(item);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

Table readCsv(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  Table t;
  std::string line;
  std::getline(in, line);
  t.header = split(line);
  while (std::getline(in, line)) {
    t.rows.push_back(split(line));
    REQUIRE(t.rows.back().size() == t.header.size());
  }
  return t;
}

std::vector<fs::path> snapshots(const std::string& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu" && e.path().filename().string().rfind("tissue_", 0) == 0)
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("stats.csv has a row per snapshot that matches the snapshot", "[sim][run][stats]") {
  ScratchDir scratch;
  const std::string out = scratch / "run";
  PreparedRun run = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/voronoi_growth.yaml"), {"time.end=3", "output.every=7"}),
      RunOptions{out, false});
  run.execute();
  const Table stats = readCsv(out + "/stats.csv");
  const auto files = snapshots(out);
  REQUIRE(stats.rows.size() == files.size());
  REQUIRE(files.size() == run.snapshots());
  double divisions = 0;
  for (std::size_t r = 0; r < files.size(); ++r) {
    const Tissue t = io::readTissueVtu(files[r].string());
    INFO(files[r].filename().string());
    CHECK(stats.number(r, "time") == t.time());
    CHECK(stats.number(r, "cells") == double(t.numCells()));
    CHECK(stats.number(r, "area_total") == Approx(totalMeasure(t)).epsilon(1e-12));
    double lo = 1e300, hi = 0;
    for (CellId c : t.cells()) lo = std::min(lo, cellMeasure(t, c)), hi = std::max(hi, cellMeasure(t, c));
    CHECK(stats.number(r, "area_min") == Approx(lo).epsilon(1e-12));
    CHECK(stats.number(r, "area_max") == Approx(hi).epsilon(1e-12));
    CHECK(stats.number(r, "area_mean") == Approx(totalMeasure(t) / double(t.numCells())).epsilon(1e-12));
    divisions += stats.number(r, "divisions");
  }
  CHECK(stats.number(0, "divisions") == 0);
  // Every division adds exactly one cell.
  CHECK(divisions == stats.number(stats.rows.size() - 1, "cells") - stats.number(0, "cells"));
  CHECK(divisions > 0);
}

TEST_CASE("stats.csv sums each solver field's amount", "[sim][run][stats]") {
  ScratchDir scratch;
  const std::string out = scratch / "run";
  PreparedRun run = PreparedRun::prepare(loadSimulationConfigFile(sourcePath("configs/compartment_polar_2d.yaml")),
                                         RunOptions{out, false});
  const std::string field = run.config().compartments.field;
  run.execute();
  const Table stats = readCsv(out + "/stats.csv");
  const auto files = snapshots(out);
  REQUIRE(stats.rows.size() == files.size());
  const Tissue last = io::readTissueVtu(files.back().string());
  double amount = 0, lo = 1e300, hi = -1e300;
  for (CellId c : last.cells()) {
    amount += last.cellProperties().get<double>(field + "_amount")[c];
    lo = std::min(lo, last.cellProperties().get<double>(field)[c]);
    hi = std::max(hi, last.cellProperties().get<double>(field)[c]);
  }
  const std::size_t r = stats.rows.size() - 1;
  CHECK(stats.number(r, field + "_total") == Approx(amount).epsilon(1e-12));
  CHECK(stats.number(r, field + "_min") == lo);
  CHECK(stats.number(r, field + "_max") == hi);
  CHECK(amount > 0);
}

TEST_CASE("an interrupted run keeps the statistics rows it reached", "[sim][run][stats]") {
  ScratchDir scratch;
  const std::string out = scratch / "run";
  PreparedRun run = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/voronoi_growth.yaml"), {"time.end=3", "output.every=5"}),
      RunOptions{out, false});
  run.simulation().onStep([](const Simulation& s) {
    if (s.stepsDone() == 12) throw std::runtime_error("stopped by the test");
  });
  CHECK_THROWS(run.execute());
  const Table stats = readCsv(out + "/stats.csv");
  // Rows at steps 0, 5 and 10, all complete.
  REQUIRE(stats.rows.size() == 3);
  CHECK(stats.number(2, "time") == Approx(1.0));
}
