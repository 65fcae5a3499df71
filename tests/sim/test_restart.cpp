// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// A run restarted from any of its snapshots must end where the uninterrupted
// run ends, bit for bit: the snapshot carries the tissue with every
// property's policy and default, and the run state (clock, random stream,
// the dome a sheet lives on), and the diffusion stage's mesh and nodal
// fields lie beside it. Every bundled config is stopped half way, written
// (Simulation::writeSnapshot), read back as `tissue.generator: snapshot`,
// and run to its end.

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tessella/io/field_state.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/run/field_output.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<Index> liveIndex(const Tissue& t) {
  std::vector<Index> index(t.slots(0), kInvalidIndex);
  Index next = 0;
  for (VertexId v : t.vertices()) index[v.index()] = next++;
  return index;
}

// Equal up to the slot numbering of removed elements: the same live
// vertices at the same positions, the same cells (loops, lineage, every
// double property) in the same order, to the bit.
void requireSameTissue(const Tissue& a, const Tissue& b) {
  REQUIRE(a.dim() == b.dim());
  REQUIRE(a.numCells() == b.numCells());
  REQUIRE(a.numVertices() == b.numVertices());
  CHECK(sameBits(a.time(), b.time()));
  std::vector<VertexId> va(a.vertices().begin(), a.vertices().end()), vb(b.vertices().begin(), b.vertices().end());
  std::size_t moved = 0;
  double worst = 0;
  for (std::size_t i = 0; i < va.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!sameBits(a.position(va[i])[k], b.position(vb[i])[k])) {
        ++moved;
        worst = std::max(worst, std::abs(a.position(va[i])[k] - b.position(vb[i])[k]));
      }
  INFO(moved << " coordinates differ, by up to " << worst);
  CHECK(moved == 0);

  std::vector<CellId> ca(a.cells().begin(), a.cells().end()), cb(b.cells().begin(), b.cells().end());
  const auto ia = liveIndex(a), ib = liveIndex(b);
  std::size_t other_lineage = 0, other_loop = 0, other_measure = 0;
  double measure_gap = 0, centroid_gap = 0;
  for (std::size_t i = 0; i < ca.size(); ++i) {
    if (a.lineageId(ca[i]) != b.lineageId(cb[i]) || a.parentId(ca[i]) != b.parentId(cb[i]) ||
        !sameBits(a.birthTime(ca[i]), b.birthTime(cb[i])))
      ++other_lineage;
    centroid_gap = std::max(centroid_gap, (cellCentroid(a, ca[i]) - cellCentroid(b, cb[i])).norm());
    if (!sameBits(cellMeasure(a, ca[i]), cellMeasure(b, cb[i]))) {
      ++other_measure;
      measure_gap = std::max(measure_gap, std::abs(cellMeasure(a, ca[i]) / cellMeasure(b, cb[i]) - 1));
    }
    if (a.dim() == 2) {
      const auto la = a.topology().faceVertices(FaceId(ca[i].index()));
      const auto lb = b.topology().faceVertices(FaceId(cb[i].index()));
      bool same = la.size() == lb.size();
      for (std::size_t k = 0; same && k < la.size(); ++k) same = ia[la[k].index()] == ib[lb[k].index()];
      if (!same) ++other_loop;
    }
  }
  INFO(other_lineage << " cells with other lineage, " << other_loop << " with other loops, " << other_measure
                     << " with other measures (relative gap up to "
                     << measure_gap << "), centroids apart by up to " << centroid_gap);
  CHECK(other_lineage == 0);
  CHECK(other_loop == 0);
  CHECK(other_measure == 0);
  CHECK(centroid_gap == 0);
  // The very same complex, every wall and edge numbered, directed and
  // listed as in the uninterrupted run (the snapshot stores it).
  CHECK(a.topology().layout() == b.topology().layout());

  REQUIRE(a.cellProperties().names() == b.cellProperties().names());
  for (const std::string& name : a.cellProperties().names()) {
    const PropertyColumnBase* column = a.cellProperties().find(name);
    if (column->type() != typeid(double)) continue;
    const auto& xa = a.cellProperties().get<double>(name);
    const auto& xb = b.cellProperties().get<double>(name);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < ca.size(); ++i) differ += !sameBits(xa[ca[i]], xb[cb[i]]);
    INFO("cell property '" << name << "'");
    CHECK(differ == 0);
    CHECK(sameBits(xa.defaultValue(), xb.defaultValue()));
    CHECK(column->policy() == b.cellProperties().find(name)->policy());
  }
}

// The solver stages' mesh and nodal fields, to the bit.
void requireSameFields(const Simulation& a, const Simulation& b) {
  const auto ma = findFieldMesh(a), mb = findFieldMesh(b);
  REQUIRE(ma);
  REQUIRE(mb);
  REQUIRE(ma->hasMesh() == mb->hasMesh());
  if (!ma->hasMesh()) return;
  const mesh::FeMesh &x = ma->mesh(), &y = mb->mesh();
  REQUIRE(x.numNodes() == y.numNodes());
  REQUIRE(x.numElements() == y.numElements());
  CHECK(x.elements == y.elements);
  CHECK(x.element_cell == y.element_cell);
  CHECK(std::memcmp(x.nodes.data(), y.nodes.data(), sizeof(double) * static_cast<std::size_t>(x.nodes.size())) == 0);
  REQUIRE(ma->fields().size() == mb->fields().size());
  for (const auto& [name, values] : ma->fields()) {
    INFO("field " << name);
    REQUIRE(mb->hasField(name));
    const Eigen::VectorXd& other = mb->field(name);
    REQUIRE(other.size() == values.size());
    std::size_t differ = 0;
    for (Eigen::Index i = 0; i < values.size(); ++i) differ += !sameBits(values[i], other[i]);
    CHECK(differ == 0);
  }
}

// `path` with `overrides` run straight through, and stopped after `stop`
// steps, written with Simulation::writeSnapshot and restarted: both ends
// must be the same to the bit, tissue and (with `fields`) fields.
void requireExactRestart(const std::string& path, const std::vector<std::string>& overrides, std::size_t stop,
                         bool fields = true) {
  ScratchDir dir;
  Simulation whole = Simulation::fromFile(path, overrides);
  REQUIRE(stop < whole.numSteps());
  Simulation first = Simulation::fromFile(path, overrides);
  while (first.stepsDone() < stop) first.step();
  const std::string snapshot = dir / "stop.vtu";
  first.writeSnapshot(snapshot);
  std::vector<std::string> restart = overrides;
  restart.insert(restart.end(), {"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
  Simulation rest = Simulation::fromFile(path, restart);
  CHECK(rest.numSteps() == whole.numSteps() - stop);
  rest.run();
  whole.run();
  requireSameTissue(whole.tissue(), rest.tissue());
  if (fields) requireSameFields(whole, rest);
}

}  // namespace

TEST_CASE("every bundled config, restarted half way from its snapshot, ends as the uninterrupted run",
          "[sim][configs][restart]") {
  std::vector<std::filesystem::path> configs;
  for (const auto& entry : std::filesystem::directory_iterator(sourcePath("configs")))
    if (entry.path().extension() == ".yaml") configs.push_back(entry.path());
  std::sort(configs.begin(), configs.end());
  REQUIRE(configs.size() >= 9);
  ScratchDir dir;
  int with_diffusion = 0;
  for (const auto& path : configs) {
    INFO(path.filename().string());
    Simulation whole = Simulation::fromFile(path.string());
    const std::size_t half = whole.numSteps() / 2;
    if (half == 0) continue;  // a one-step run has no middle
    Simulation first = Simulation::fromFile(path.string());
    while (first.stepsDone() < half) first.step();
    const std::string snapshot = dir / (path.stem().string() + "_half.vtu");
    first.writeSnapshot(snapshot);

    std::vector<std::string> restart{"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot};
    const SimulationConfig config = loadSimulationConfigFile(path.string());
    // A config that gives time.start would start the clock there (with a
    // note): restart it at the snapshot's time, as docs/config.md says.
    if (config.config.isGiven("time.start")) {
      char start[64];
      std::snprintf(start, sizeof start, "time.start=%.17g", first.time());
      restart.push_back(start);
    }
    Simulation rest = Simulation::fromFile(path.string(), restart);
    CHECK(rest.numSteps() == whole.numSteps() - half);
    CHECK(sameBits(rest.time(), first.time()));
    rest.run();
    whole.run();
    requireSameTissue(whole.tissue(), rest.tissue());
    if (!config.diffusion.species.empty()) {
      ++with_diffusion;
      requireSameFields(whole, rest);
    }
  }
  CHECK(with_diffusion >= 2);  // activator_inhibitor_2d, morphogen_gradient_2d
}

TEST_CASE("a noisy division threshold survives a restart: daughters born after it draw theirs", "[sim][restart]") {
  // The runaway of issue "Reliability first": read back without its NaN
  // default, the threshold column gave every later daughter 0, and every
  // cell divided at every step.
  ScratchDir dir;
  const std::string config = sourcePath("configs/voronoi_growth.yaml");
  Simulation first = Simulation::fromFile(config, {"time.end=1"});
  first.run();
  const std::string snapshot = dir / "t1.vtu";
  io::writeTissueVtu(first.tissue(), snapshot, {}, first.runState());

  const Tissue back = io::readTissueVtu(snapshot);
  const auto& column = back.cellProperties().get<double>("division_threshold");
  CHECK(std::isnan(column.defaultValue()));
  CHECK(column.policy() == DivisionPolicy::Reset);

  Simulation straight = Simulation::fromFile(config, {"time.end=3"});
  straight.run();
  // Another seed: the restarted run draws a stream of its own, and its cell
  // count must still be of the uninterrupted run's order.
  Simulation rest = Simulation::fromFile(
      config, {"time.end=3", "rng_seed=999", "tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
  rest.run();
  INFO("uninterrupted " << straight.tissue().numCells() << " cells, restarted " << rest.tissue().numCells());
  CHECK(rest.tissue().numCells() < 2 * straight.tissue().numCells());
  const auto& thresholds = rest.tissue().cellProperties().get<double>("division_threshold");
  for (CellId c : rest.tissue().cells()) REQUIRE(thresholds[c] > 0);
}

TEST_CASE("a damaged random stream in a snapshot's run state is a located error", "[sim][restart]") {
  ScratchDir dir;
  const std::string config = sourcePath("configs/voronoi_growth.yaml");
  Simulation first = Simulation::fromFile(config, {"time.end=0.2"});
  first.run();
  io::RunState state = first.runState();
  state["rng.stream"] = "not a state";
  const std::string snapshot = dir / "bad_state.vtu";
  io::writeTissueVtu(first.tissue(), snapshot, {}, state);
  try {
    Simulation::fromFile(config, {"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
    FAIL("the damaged stream was accepted");
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("tissue.snapshot.file") != std::string::npos);
    CHECK(what.find("rng.stream = 'not a state'") != std::string::npos);
  }
}

TEST_CASE("a restart between two solves keeps the solver's schedule", "[sim][restart]") {
  // compartment_polar_2d solving every 5 steps; restarted after step 7, the
  // next solve must still end step 10 and cover the time since step 5, as
  // in the uninterrupted run (its state, the cell amounts, is in the snapshot).
  ScratchDir dir;
  const std::string path = sourcePath("configs/compartment_polar_2d.yaml");
  const std::string every = "compartments.every=5";
  Simulation whole = Simulation::fromFile(path, {every});
  REQUIRE(whole.numSteps() > 12);
  Simulation first = Simulation::fromFile(path, {every});
  while (first.stepsDone() < 7) first.step();
  const std::string snapshot = dir / "step7.vtu";
  io::writeTissueVtu(first.tissue(), snapshot, {}, first.runState());
  char start[64];
  std::snprintf(start, sizeof start, "time.start=%.17g", first.time());
  Simulation rest =
      Simulation::fromFile(path, {every, "tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot, start});
  CHECK(rest.clockStep() == 7);
  rest.run();
  whole.run();
  requireSameTissue(whole.tissue(), rest.tissue());
}

TEST_CASE("transient diffusion restarts exactly between two solves, in 2D and on a growing, dividing 3D tissue",
          "[sim][restart][diffusion]") {
  // Solving every 3 (2D) or 2 (3D) steps and stopped after a step without a
  // solve, the tissue has grown since its mesh: the restart carries the
  // saved fields from the saved mesh to a new one, as the uninterrupted run does.
  SECTION("2D, every 3 steps") {
    requireExactRestart(sourcePath("configs/morphogen_gradient_2d.yaml"), {"diffusion.every=3"}, 7);
  }
  SECTION("2D, stopped right after a solve") {
    requireExactRestart(sourcePath("configs/activator_inhibitor_2d.yaml"), {"time.end=5"}, 4);
  }
  SECTION("3D, every 2 steps, Crank-Nicolson with a source") {
    requireExactRestart(sourcePath("configs/box_growth_3d.yaml"),
                        {"time.end=1.4", "diffusion.mode=transient", "diffusion.species=u", "diffusion.every=2",
                         "diffusion.scheme=crank_nicolson", "diffusion.dirichlet=x_min=1", "diffusion.decay=0.5"},
                        5);
  }
  SECTION("3D steady, stopped between two solves") {
    requireExactRestart(sourcePath("configs/steady_diffusion_3d.yaml"),
                        {"time.end=4", "diffusion.every=2"}, 3);
  }
}

TEST_CASE("a missing, damaged or mismatched diffusion state beside a snapshot is an error naming it",
          "[sim][restart][diffusion]") {
  ScratchDir dir;
  const std::string config = sourcePath("configs/morphogen_gradient_2d.yaml");
  Simulation first = Simulation::fromFile(config);
  while (first.stepsDone() < 5) first.step();
  const std::string snapshot = dir / "step5.vtu";
  first.writeSnapshot(snapshot);
  const std::string beside = io::fieldStatePath(snapshot);
  REQUIRE(beside == (dir / "step5.fields.vtu"));
  REQUIRE(std::filesystem::exists(beside));
  first.step();
  const std::string later = dir / "step6.vtu";
  first.writeSnapshot(later);

  const std::vector<std::string> restart{"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot};
  auto refused = [&](const std::vector<std::string>& parts, std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.begin(), restart.begin(), restart.end());
    try {
      Simulation::fromFile(config, overrides);
      FAIL("the restart was accepted");
    } catch (const std::exception& e) {
      const std::string what = e.what();
      INFO(what);
      for (const std::string& part : parts) CHECK(what.find(part) != std::string::npos);
    }
  };
  const auto fresh = [&] {
    std::vector<std::string> overrides = restart;
    overrides.push_back("diffusion.restart=fresh");
    Simulation rest = Simulation::fromFile(config, overrides);
    rest.run();
    CHECK(rest.finished());
  };

  // Missing.
  std::filesystem::rename(beside, dir / "away.vtu");
  refused({beside, "is missing", "diffusion.restart: fresh"});
  fresh();  // asked for explicitly: the species start again
  std::filesystem::rename(dir / "away.vtu", beside);
  Simulation::fromFile(config, restart);  // back in place: accepted

  // Another step's file in its place.
  std::filesystem::copy_file(beside, dir / "keep.vtu");
  std::filesystem::copy_file(io::fieldStatePath(later), beside, std::filesystem::copy_options::overwrite_existing);
  refused({beside, "is not the diffusion state written with snapshot", snapshot});

  // Damaged: one byte changed near the end (the appended data).
  std::filesystem::copy_file(dir / "keep.vtu", beside, std::filesystem::copy_options::overwrite_existing);
  {
    std::fstream file(beside, std::ios::in | std::ios::out | std::ios::binary);
    file.seekg(-200, std::ios::end);
    char byte = 0;
    file.read(&byte, 1);
    file.seekp(-200, std::ios::end);
    byte = static_cast<char>(byte ^ 0x10);
    file.write(&byte, 1);
  }
  refused({beside, "CRC-32"});
  // ... and read directly, the file's own checksums name the array.
  CHECK_THROWS_WITH(io::readFieldState(beside), Catch::Contains(beside));
  std::filesystem::copy_file(dir / "keep.vtu", beside, std::filesystem::copy_options::overwrite_existing);

  // Other species than the config's.
  {
    const std::string other = dir / "other.vtu";
    io::RunState state = first.snapshotState(other);
    state["diffusion.species"] = "ions";
    io::writeTissueVtu(first.tissue(), other, {}, state);
    try {
      Simulation::fromFile(config, {"tissue.generator=snapshot", "tissue.snapshot.file=" + other});
      FAIL("other species were accepted");
    } catch (const std::exception& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find("continues the species 'ions', the config has 'auxin'") != std::string::npos);
    }
  }

  // A snapshot written without the stage's state (the tissue and the clock only).
  const std::string bare = dir / "bare.vtu";
  io::writeTissueVtu(first.tissue(), bare, {}, first.runState());
  try {
    Simulation::fromFile(config, {"tissue.generator=snapshot", "tissue.snapshot.file=" + bare});
    FAIL("a snapshot without the diffusion state was accepted");
  } catch (const std::exception& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("holds no state of the diffusion stage") != std::string::npos);
    CHECK(std::string(e.what()).find(bare) != std::string::npos);
  }
  Simulation::fromFile(config, {"tissue.generator=snapshot", "tissue.snapshot.file=" + bare,
                                "diffusion.restart=fresh"});
  // A tissue file that is not a run's snapshot is an initial tissue: the species start from `initial`.
  const std::string plain = dir / "plain.vtu";
  io::writeTissueVtu(first.tissue(), plain);
  Simulation::fromFile(config, {"tissue.generator=snapshot", "tissue.snapshot.file=" + plain});
}

TEST_CASE("neo-Hookean membranes restart exactly: a growing cylinder and a dividing dome",
          "[sim][restart][mechanics][neo-hookean]") {
  SECTION("hypocotyl cylinder, hoop fibres ratio 10") {
    requireExactRestart(sourcePath("configs/hypocotyl_cylinder.yaml"), {"mechanics.material=neo_hookean"}, 10,
                        false);
  }
  SECTION("dome sheet, soft summit, divisions") {
    requireExactRestart(sourcePath("configs/turgor_dome_2p5d.yaml"),
                        {"mechanics.material=neo_hookean", "time.end=2.0"}, 10,
                        false);
  }
}

// The point support's anchor point (the vertex mean at the start, unless given) travels in the run
// state; the symmetry planes are configuration.
TEST_CASE("membranes held at one point or by a symmetry plane restart exactly",
          "[sim][restart][mechanics]") {
  SECTION("3D tissue, point support") {
    requireExactRestart(sourcePath("configs/turgor_tissue_3d.yaml"),
                        {"mechanics.membrane_support=point"}, 2, false);
  }
  SECTION("3D tissue, base and the plane x = 0") {
    requireExactRestart(sourcePath("configs/turgor_tissue_3d.yaml"),
                        {"mechanics.symmetry_planes=x=0"}, 2, false);
  }
}

// A 3D tissue's walls are its faces, which a snapshot does not hold: their fibre ratios (a model's, per wall)
// and rest ratios (what a divided wall's parts start from) travel in the mechanics run state. A run with stiff
// fibres along x whose walls have ratios 1 to 4 (new walls: the column's default, 2.5) and cells dividing is
// stopped half way and restarted: it ends as the uninterrupted run, walls and their outputs included.
TEST_CASE("3D membranes with a fibre ratio per wall restart exactly, through divisions",
          "[sim][restart][mechanics]") {
  const std::string path = sourcePath("configs/turgor_tissue_3d.yaml");
  // Noisy thresholds drawn at birth keep daughters dividing step after step (a daughter whose draw is below its
  // size divides at the next step), so divisions happen on both sides of the restart.
  const std::vector<std::string> overrides = {
      "tissue.voronoi.count=40", "mechanics.fibres=fixed", "mechanics.fibre_vector=[1, 0, 0]",
      "division.rule=shortest_wall", "division.threshold=noisy", "division.mean=3.5", "division.stddev=0.8",
      "time.end=0.4"};
  auto setRatios = [](Simulation& s) {
    Tissue& t = s.tissue();
    auto& ratio = t.wallProperties().add<double>("fibre_ratio", 2.5, DivisionPolicy::Copy);
    for (WallId w : t.walls()) ratio[w] = 1.0 + static_cast<double>(w.index() % 4);
  };
  ScratchDir dir;
  Simulation whole = Simulation::fromFile(path, overrides);
  setRatios(whole);
  const std::size_t cells = whole.tissue().numCells();
  Simulation first = Simulation::fromFile(path, overrides);
  setRatios(first);
  const std::size_t stop = whole.numSteps() / 2;
  while (first.stepsDone() < stop) first.step();
  const std::string snapshot = dir / "stop.vtu";
  first.writeSnapshot(snapshot);
  std::vector<std::string> restart = overrides;
  restart.insert(restart.end(), {"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
  Simulation rest = Simulation::fromFile(path, restart);
  const std::size_t cells_at_restart = rest.tissue().numCells();
  rest.run();
  whole.run();
  INFO(cells << " cells at the start, " << cells_at_restart << " at the restart, " << whole.tissue().numCells()
             << " at the end");
  CHECK(cells_at_restart > cells);                        // divisions before the restart
  CHECK(whole.tissue().numCells() > cells_at_restart);  // and after it
  requireSameTissue(whole.tissue(), rest.tissue());
  // The mechanics' wall columns of both runs to the bit: the ratios the membranes read and the walls' outputs.
  // (The division module's wall tags, division_of, are not in a snapshot: not compared here.)
  const PropertyStore &a = whole.tissue().wallProperties(), &b = rest.tissue().wallProperties();
  std::vector<WallId> wa(whole.tissue().walls().begin(), whole.tissue().walls().end());
  std::vector<WallId> wb(rest.tissue().walls().begin(), rest.tissue().walls().end());
  REQUIRE(wa.size() == wb.size());
  std::vector<std::string> names = mechanics::membraneWallOutputNames();
  names.insert(names.end(), {"fibre_ratio", "membrane_rest_ratio"});
  std::size_t compared = 0;
  for (const std::string& name : names) {
    INFO("wall property '" << name << "'");
    REQUIRE(a.has(name));
    REQUIRE(b.has(name));
    const PropertyColumnBase* column = a.find(name);
    CHECK(column->policy() == b.find(name)->policy());
    std::size_t differ = 0;
    if (column->type() == typeid(double)) {
      const auto &x = a.get<double>(name), &y = b.get<double>(name);
      CHECK(sameBits(x.defaultValue(), y.defaultValue()));
      for (std::size_t i = 0; i < wa.size(); ++i) differ += !sameBits(x[wa[i]], y[wb[i]]);
    } else if (column->type() == typeid(Vec3)) {
      const auto &x = a.get<Vec3>(name), &y = b.get<Vec3>(name);
      for (std::size_t i = 0; i < wa.size(); ++i)
        for (int k = 0; k < 3; ++k) differ += !sameBits(x[wa[i]][k], y[wb[i]][k]);
    } else if (column->type() == typeid(Sym3)) {
      const auto &x = a.get<Sym3>(name), &y = b.get<Sym3>(name);
      for (std::size_t i = 0; i < wa.size(); ++i)
        for (int k = 0; k < 6; ++k) differ += !sameBits(x[wa[i]].v[k], y[wb[i]].v[k]);
    } else {
      continue;
    }
    CHECK(differ == 0);
    ++compared;
  }
  CHECK(compared >= 16);  // fibre_ratio, membrane_rest_ratio and the 14 outputs of a walls file
  // The new walls of divisions took the column's default; the ratios are the model's, not the section's 1.
  const auto& ratio = rest.tissue().wallProperties().get<double>("fibre_ratio");
  std::size_t at_default = 0, above_one = 0;
  for (WallId w : rest.tissue().walls()) {
    at_default += ratio[w] == 2.5;
    above_one += ratio[w] > 1.0;
  }
  CHECK(at_default > 0);
  CHECK(above_one > wb.size() / 2);
}

TEST_CASE("a damaged wall column in a 3D membranes snapshot's run state is an error naming it",
          "[sim][restart][mechanics]") {
  const std::string path = sourcePath("configs/turgor_tissue_3d.yaml");
  const std::vector<std::string> overrides = {"tissue.voronoi.count=20", "time.end=0.1"};
  ScratchDir dir;
  Simulation first = Simulation::fromFile(path, overrides);
  first.tissue().wallProperties().add<double>("fibre_ratio", 2.0, DivisionPolicy::Copy);
  first.run();
  const Tissue& tissue = first.tissue();
  auto attempt = [&](const std::string& text) {
    const std::string snapshot = dir / "damaged.vtu";
    io::RunState damaged = first.snapshotState(snapshot, {});
    REQUIRE(damaged.count("mechanics.wall.fibre_ratio"));
    damaged["mechanics.wall.fibre_ratio"] = text;
    io::writeTissueVtu(tissue, snapshot, {}, damaged);
    std::vector<std::string> restart = overrides;
    restart.insert(restart.end(), {"tissue.generator=snapshot", "tissue.snapshot.file=" + snapshot});
    return Simulation::fromFile(path, restart);
  };
  using Catch::Matchers::Contains;
  const std::string walls = std::to_string(tissue.numWalls());
  CHECK_THROWS_WITH(attempt("copy 2 3"), Contains("damaged.vtu") && Contains("mechanics.wall.fibre_ratio") &&
                                             Contains("1 values (after its default) for " + walls + " walls"));
  CHECK_THROWS_WITH(attempt("copy 2 x"), Contains("mechanics.wall.fibre_ratio holds 'x', not a number"));
  CHECK_THROWS_WITH(attempt("custom 2"), Contains("the division policy 'custom'"));
}
