// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// configs/phyllotaxis_dome.yaml and primordium recording in a run: the
// records' angles, radii and divergences recomputed from their positions
// (atan2 about the z axis here, independently of networks::axialPosition;
// the annulus in the distance from the apex),
// the primordium cell property, primordia.csv, and the records across a
// restart. The divergence angles the model gives are reported in
// docs/networks.md; no test asserts them.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "tessella/sim/run/primordia_output.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/network_stage.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;

namespace {

const NetworkStage& networkStageOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const NetworkStage*>(&sim.stage(i))) return *s;
  throw std::logic_error("no network stage");
}

// Every record against its own position: the config's axis is +z through
// (0, 0, 2.5), so the angle is atan2(y, x) in degrees and the radius
// hypot(x, y); the divergence is the difference of successive angles mod 360.
void checkRecords(const Simulation& sim) {
  const NetworkStage& stage = networkStageOf(sim);
  const auto& records = stage.primordia();
  const auto& o = stage.spec().primordia.options;
  REQUIRE(o.axis == Vec3(0, 0, 1));
  REQUIRE(o.apex.head<2>().isZero());
  double previous_time = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const PrimordiumRecord& r = records[i];
    INFO("primordium " << r.id << " at t = " << r.time);
    CHECK(r.id == static_cast<int>(i) + 1);
    CHECK(r.time >= previous_time);
    previous_time = r.time;
    double angle = std::atan2(r.position.y(), r.position.x()) * 180 / std::numbers::pi;
    if (angle < 0) angle += 360;
    CHECK(r.angle_deg == Approx(angle).margin(1e-9));
    CHECK(r.radius == Approx(std::hypot(r.position.x(), r.position.y())));
    CHECK(r.distance == Approx((r.position - o.apex).norm()));
    CHECK(r.distance >= o.min_radius);
    CHECK(r.distance <= o.max_radius);
    if (i == 0) {
      CHECK(std::isnan(r.divergence_deg));
    } else {
      double d = r.angle_deg - records[i - 1].angle_deg;
      if (d < 0) d += 360;
      CHECK(r.divergence_deg == Approx(d).margin(1e-9));
    }
  }
  // Every primordium's id is on its cell or the cell's descendants (the
  // property is copied to daughters), unless all of them left... they cannot:
  // no stage removes cells here.
  const auto& id = sim.tissue().cellProperties().get<int>(kPrimordiumProperty);
  std::set<int> seen;
  for (CellId c : sim.tissue().cells())
    if (id[c] > 0) seen.insert(id[c]);
  CHECK(seen.size() == records.size());
  if (!seen.empty()) CHECK(*seen.rbegin() == static_cast<int>(records.size()));
}

std::size_t laterThanFirst(const std::vector<PrimordiumRecord>& records) {
  std::size_t n = 0;
  for (const auto& r : records) n += r.time > records.front().time ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("phyllotaxis_dome.yaml, short: primordia with angles and divergences computed from their positions",
          "[sim][network][primordia]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/phyllotaxis_dome.yaml"), {"time.end=4"});
  sim.run();
  const auto& records = networkStageOf(sim).primordia();
  REQUIRE(!records.empty());
  checkRecords(sim);
  // The CSV holds the same rows.
  ScratchDir dir;
  Simulation again = Simulation::fromFile(sourcePath("configs/phyllotaxis_dome.yaml"), {"time.end=1"});
  REQUIRE(attachPrimordiaOutput(again, dir.path().string()) != nullptr);
  again.run();
  std::ifstream in(dir.path() / kPrimordiaName);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == primordiaCsv(networkStageOf(again).primordia()));
  std::size_t rows = 0;
  for (char ch : text.str()) rows += ch == '\n' ? 1 : 0;
  CHECK(rows == networkStageOf(again).primordia().size() + 1);
}

TEST_CASE("phyllotaxis_dome.yaml: the primordia records and cells survive a restart from a snapshot",
          "[sim][network][primordia][restart]") {
  const std::string config = sourcePath("configs/phyllotaxis_dome.yaml");
  Simulation straight = Simulation::fromFile(config, {"time.end=4"});
  straight.run();
  Simulation first = Simulation::fromFile(config, {"time.end=2"});
  first.run();
  ScratchDir dir;
  const std::string snapshot = (dir.path() / "half.vtu").string();
  first.writeSnapshot(snapshot);
  Simulation second =
      Simulation::fromFile(config, {"time.end=4", "tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
  second.run();
  const auto& a = networkStageOf(straight).primordia();
  const auto& b = networkStageOf(second).primordia();
  REQUIRE(a.size() == b.size());
  CHECK(networkStageOf(first).primordia().size() < a.size());  // some were found after the restart
  CHECK(primordiaCsv(a) == primordiaCsv(b));  // exact numbers
  const auto& ia = straight.tissue().cellProperties().get<int>(kPrimordiumProperty);
  const auto& ib = second.tissue().cellProperties().get<int>(kPrimordiumProperty);
  REQUIRE(straight.tissue().numCells() == second.tissue().numCells());
  std::vector<CellId> ca(straight.tissue().cells().begin(), straight.tissue().cells().end());
  std::vector<CellId> cb(second.tissue().cells().begin(), second.tissue().cells().end());
  std::size_t other = 0;
  for (std::size_t i = 0; i < ca.size(); ++i) other += ia[ca[i]] != ib[cb[i]] ? 1 : 0;
  CHECK(other == 0);
}

TEST_CASE("phyllotaxis_dome.yaml to t = 20: successive primordia appear after the first ones",
          "[sim][network][primordia][slow]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/phyllotaxis_dome.yaml"), {"time.end=20"});
  sim.run();
  const auto& records = networkStageOf(sim).primordia();
  REQUIRE(!records.empty());
  checkRecords(sim);
  CHECK(laterThanFirst(records) >= 3);
  std::ostringstream table;
  for (const auto& r : records)
    table << "t = " << r.time << "  angle " << r.angle_deg << "  radius " << r.radius << "  divergence "
          << r.divergence_deg << "\n";
  WARN("primordia of phyllotaxis_dome.yaml:\n" << table.str());
}

TEST_CASE("network.primordia: errors at their keys", "[sim][network][primordia][errors]") {
  const std::string config = sourcePath("configs/phyllotaxis_dome.yaml");
  auto error = [&](const std::string& o) {
    return configErrorOf([&] { Simulation::fromFile(config, {o}); });
  };
  ConfigError e = error("network.primordia.species=pin");
  CHECK(e.keyPath() == "network.primordia.species");
  CHECK_THAT(e.what(), Catch::Contains("'pin' is not a species"));
  e = error("network.primordia.max_radius=1");
  CHECK(e.keyPath() == "network.primordia.max_radius");
  CHECK_THAT(e.what(), Catch::Contains("max_radius = 1"));
  e = error("network.primordia.axis=[0, 0, 0]");
  CHECK(e.keyPath() == "network.primordia.axis");
}
