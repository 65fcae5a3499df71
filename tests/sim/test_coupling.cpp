// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The solver sections (diffusion:, compartments:, elasticity:), their stages
// in the loop, the division gate, and the example configs that use them,
// checked against exact solutions and conservation laws.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>

#include "tessella/sim/run/run.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"
#include "tessella/tissue/geometry.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::configErrorOf;
using tessella::sim::test::sourcePath;

namespace {

double sumProperty(const Tissue& t, const std::string& name) {
  const auto& column = t.cellProperties().get<double>(name);
  double s = 0;
  for (CellId c : t.cells()) s += column[c];
  return s;
}

const FieldMesh& fieldMeshOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const MeshFieldStage*>(&sim.stage(i))) return *s->fieldMesh();
  throw std::logic_error("no solver stage with a mesh");
}

template <typename S>
const S& stageOf(const Simulation& sim) {
  for (std::size_t i = 0; i < sim.numStages(); ++i)
    if (const auto* s = dynamic_cast<const S*>(&sim.stage(i))) return *s;
  throw std::logic_error("stage not found");
}

}  // namespace

TEST_CASE("steady_diffusion_3d.yaml: the linear slab profile in Voronoi cells", "[sim][coupling][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/steady_diffusion_3d.yaml"));
  sim.run();
  const Tissue& t = sim.tissue();
  REQUIRE(t.dim() == 3);
  // P1 reproduces the exact solution u = 1 - x/3 at every node ...
  const FieldMesh& fm = fieldMeshOf(sim);
  const Eigen::VectorXd& u = fm.field("u");
  const mesh::FeMesh& mesh = fm.mesh();
  double worst = 0;
  for (int n = 0; n < mesh.numNodes(); ++n) worst = std::max(worst, std::abs(u[n] - (1.0 - mesh.nodes(n, 0) / 3.0)));
  CHECK(worst < 1e-8);
  // ... the maximum principle holds ...
  CHECK(u.minCoeff() >= -1e-12);
  CHECK(u.maxCoeff() <= 1 + 1e-12);
  // ... and the cell average of a linear field is its value at the centroid.
  const auto& avg = t.cellProperties().get<double>("u");
  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    CHECK(avg[c] == Approx(1.0 - cellCentroid(t, c).x() / 3.0).margin(1e-8));
  }
}

TEST_CASE("stretched_block_3d.yaml: uniaxial tension gives sigma_xx = E strain in every cell",
          "[sim][coupling][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/stretched_block_3d.yaml"));
  sim.run();
  const Tissue& t = sim.tissue();
  const double E = 2.0, strain = 0.03 / 3.0, nu = 0.3;
  const auto& sxx = t.cellProperties().get<double>("stress_xx");
  double mean = 0, volume = 0;
  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    CHECK(sxx[c] == Approx(E * strain).epsilon(1e-8));
    for (const char* other : {"stress_yy", "stress_zz", "stress_yz", "stress_xz", "stress_xy"})
      CHECK(std::abs(t.cellProperties().get<double>(other)[c]) < 1e-9);
    mean += sxx[c] * cellMeasure(t, c);
    volume += cellMeasure(t, c);
  }
  CHECK(mean / volume == Approx(E * strain).epsilon(1e-10));
  // Nodal displacements: u_x = strain x, u_y = -nu strain y (free lateral faces).
  const FieldMesh& fm = fieldMeshOf(sim);
  const mesh::FeMesh& mesh = fm.mesh();
  double worst = 0;
  for (int n = 0; n < mesh.numNodes(); ++n) {
    worst = std::max(worst, std::abs(fm.field("displacement_x")[n] - strain * mesh.nodes(n, 0)));
    worst = std::max(worst, std::abs(fm.field("displacement_y")[n] + nu * strain * mesh.nodes(n, 1)));
  }
  CHECK(worst < 1e-9);
}

TEST_CASE("compartment_polar_2d.yaml: polar transport along the file of cells conserves the total",
          "[sim][coupling][configs]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/compartment_polar_2d.yaml"));
  const double area = totalMeasure(sim.tissue());
  sim.run();
  const Tissue& t = sim.tissue();
  CHECK(sumProperty(t, "pin_auxin_amount") == Approx(1.0 * area).epsilon(1e-12));
  // The file's cells are the middle row; substance piles up at its downstream end.
  const auto& polar = t.cellProperties().get<std::int64_t>("pin_auxin_polar");
  const auto& c = t.cellProperties().get<double>("pin_auxin");
  std::map<double, double> row;  // centroid x -> concentration, middle row
  for (CellId cell : t.cells()) {
    const Vec3 x = cellCentroid(t, cell);
    CHECK((polar[cell] == 1) == (std::abs(x.y() - 1.5) < 1e-9));
    if (polar[cell] == 1) row[x.x()] = c[cell];
  }
  REQUIRE(row.size() == 10);
  CHECK(std::prev(row.end())->second > 2.0);                 // the sink end gained
  CHECK(row.begin()->second < 0.5);                          // the source end lost
  double previous = -1;
  for (const auto& [x, value] : std::map<double, double>(std::next(row.begin()), row.end())) {
    CHECK(value > previous);  // increasing downstream (after the first cell)
    previous = value;
  }
}

TEST_CASE("compartments conserve the total amount across growth and divisions", "[sim][coupling]") {
  Simulation sim = Simulation::fromFile(sourcePath("configs/compartment_polar_2d.yaml"),
                                        {"growth.field=anisotropic", "growth.anisotropic.rates=[0.1, 0.05, 0]",
                                         "division.rule=main_axis", "division.size=1.3", "time.end=6"});
  const double area0 = totalMeasure(sim.tissue());
  const std::size_t cells0 = sim.tissue().numCells();
  sim.run();
  CHECK(sim.tissue().numCells() > cells0);
  CHECK(totalMeasure(sim.tissue()) > 1.5 * area0);
  CHECK(sumProperty(sim.tissue(), "pin_auxin_amount") == Approx(area0).epsilon(1e-12));
}

TEST_CASE("morphogen_gradient_2d.yaml: a gradient from the source, conserved amount without decay",
          "[sim][coupling][configs]") {
  SECTION("as shipped: a decreasing gradient away from the source, divisions only where gated open") {
    Simulation sim = Simulation::fromFile(sourcePath("configs/morphogen_gradient_2d.yaml"));
    sim.run();
    const Tissue& t = sim.tissue();
    const auto& a = t.cellProperties().get<double>("auxin");
    double near = 0, far = 0;
    int n_near = 0, n_far = 0;
    for (CellId c : t.cells()) {
      const double d = (cellCentroid(t, c) - Vec3(0, 2, 0)).norm();
      if (d < 1.5) near += a[c], ++n_near;
      if (d > 4.0) far += a[c], ++n_far;
      CHECK(a[c] >= -1e-6);
    }
    REQUIRE(n_near > 0);
    REQUIRE(n_far > 0);
    CHECK(near / n_near > 3 * (far / n_far));
    CHECK(stageOf<DiffusionStage>(sim).solves() == sim.numSteps());
    CHECK(fieldMeshOf(sim).remeshes() == sim.numSteps() + 1);  // the start, then every step (growth)
  }
  SECTION("no decay, no source, uniform start: the amount stays the initial one while the tissue grows") {
    Simulation sim = Simulation::fromFile(
        sourcePath("configs/morphogen_gradient_2d.yaml"),
        {"diffusion.decay=0", "diffusion.source.rate=0", "diffusion.initial=1", "division.gate.above=0.1"});
    const double area0 = totalMeasure(sim.tissue());
    const std::size_t cells0 = sim.tissue().numCells();
    sim.run();
    CHECK(sim.tissue().numCells() > cells0);  // divisions happened (the gate is open everywhere)
    CHECK(totalMeasure(sim.tissue()) > 1.2 * area0);
    CHECK(stageOf<DiffusionStage>(sim).totalAmount() == Approx(area0).epsilon(1e-9));
    CHECK(sumProperty(sim.tissue(), "auxin_amount") == Approx(area0).epsilon(1e-9));
  }
}

TEST_CASE("division.gate: only cells whose field average exceeds the value divide", "[sim][coupling][growth]") {
  const std::string config = sourcePath("configs/morphogen_gradient_2d.yaml");
  const std::size_t start = Simulation::fromFile(config).tissue().numCells();
  SECTION("a closed gate stops every division") {
    Simulation sim = Simulation::fromFile(config, {"division.gate.above=1e9", "time.end=2"});
    sim.run();
    CHECK(sim.tissue().numCells() == start);
  }
  SECTION("every mother had the field above the value when it divided") {
    const double above = 0.3;
    Simulation sim = Simulation::fromFile(config, {"time.end=3"});
    std::map<std::int64_t, double> field;  // lineage id -> auxin after the last step
    std::size_t births = 0, near_source = 0;
    sim.onStep([&](const Simulation& s) {
      const Tissue& t = s.tissue();
      const auto& a = t.cellProperties().get<double>("auxin");
      for (CellId c : t.cells()) {
        if (t.birthTime(c) != s.time() || t.parentId(c) < 0) continue;
        ++births;
        INFO("cell " << t.lineageId(c) << " born at t = " << s.time() << " of " << t.parentId(c));
        REQUIRE(field.count(t.parentId(c)) == 1);
        CHECK(field.at(t.parentId(c)) > above);
        if ((cellCentroid(t, c) - Vec3(0, 2, 0)).norm() < 3.0) ++near_source;
      }
      field.clear();
      for (CellId c : t.cells()) field[t.lineageId(c)] = a[c];
    });
    sim.run();
    CHECK(births > 0);
    CHECK(near_source == births);  // the gate keeps divisions near the source
  }
}

TEST_CASE("per-cell-type coefficients come from an integer cell property", "[sim][coupling]") {
  // Two materials in series along x (type 1 in the last column, x > 2): the
  // steady flux is continuous, so the slopes are in the inverse ratio of the
  // diffusivities.
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 3, ny: 2}}\n"
      "diffusion: {mode: steady, by_property: cell_type, diffusivity: 1, diffusivity_by: \"1=3\", "
      "dirichlet: \"x_min=0, x_max=1\"}\n"
      "time: {end: 1, dt: 1}\n");
  auto& type = sim.tissue().cellProperties().add<std::int64_t>("cell_type", 0);
  for (CellId c : sim.tissue().cells()) type[c] = cellCentroid(sim.tissue(), c).x() > 2.0 ? 1 : 0;
  sim.run();
  // Exact: slope s0 on [0, 2], s1 = s0 / 3 on [2, 3]; 2 s0 + s0 / 3 = 1 ->
  // s0 = 3/7, u(2) = 6/7.
  const FieldMesh& fm = fieldMeshOf(sim);
  const mesh::FeMesh& mesh = fm.mesh();
  for (int n = 0; n < mesh.numNodes(); ++n) {
    const double x = mesh.nodes(n, 0);
    const double exact = x <= 2.0 ? 3.0 / 7.0 * x : 6.0 / 7.0 + (x - 2.0) / 7.0;
    CHECK(fm.field("u")[n] == Approx(exact).margin(1e-9));
  }
}

TEST_CASE("solver section errors name their key", "[sim][coupling][errors]") {
  const auto error = [](const std::string& yaml) {
    return configErrorOf([&] { Simulation::fromYaml("tissue: {generator: rectangular_grid}\n" + yaml); });
  };
  ConfigError e = error("diffusion: {mode: steady, dirichlet: \"x_mn=1\"}\n");
  CHECK(e.keyPath() == "diffusion.dirichlet");
  CHECK_THAT(e.what(), Catch::Contains("unknown boundary region 'x_mn'; did you mean 'x_min'?"));

  e = error("diffusion: {mode: steady}\n");
  CHECK(e.keyPath() == "diffusion.mode");
  CHECK_THAT(e.what(), Catch::Contains("up to a constant"));

  e = error("diffusion: {mode: transient, diffusivity_by: \"1=2\"}\n");
  CHECK(e.keyPath() == "diffusion.diffusivity_by");
  CHECK_THAT(e.what(), Catch::Contains("by_property"));

  e = error("diffusion: {mode: transient, by_property: t, diffusivity_by: \"1=-2\"}\n");
  CHECK_THAT(e.what(), Catch::Contains("out of range"));

  e = error("diffusion: {mode: transient, robin: \"all=abc\"}\n");
  CHECK_THAT(e.what(), Catch::Contains("'abc' is not a finite number"));

  e = error("diffusion: {mode: transient, source: {rate: 1}}\n");
  CHECK(e.keyPath() == "diffusion.source.rate");

  e = error("elasticity: {model: solid}\n");
  CHECK(e.keyPath() == "elasticity.fixed");
  CHECK_THAT(e.what(), Catch::Contains("missing required key"));

  e = error("elasticity: {model: solid, fixed: \"x_min=xw\"}\n");
  CHECK_THAT(e.what(), Catch::Contains("components are letters among x, y, z"));

  e = error("elasticity: {model: solid, fixed: \"x_min=x\", poisson: 0.5}\n");
  CHECK(e.keyPath() == "elasticity.poisson");

  e = error("compartments: {mode: transient, polar: {rate: 1, direction: [0, 0, 0]}}\n");
  CHECK(e.keyPath() == "compartments.polar.direction");

  e = error("division: {rule: main_axis, gate: {field: auxn}}\ndiffusion: {mode: transient, species: auxin}\n");
  CHECK(e.keyPath() == "division.gate.field");
  CHECK_THAT(e.what(), Catch::Contains("known: auxin, auxin_amount"));
}

TEST_CASE("a bad file of polar cells is an error at its line", "[sim][coupling][errors]") {
  test::ScratchDir dir;
  dir.write("cells.txt", "3\n# comment\n4 5\n");
  const ConfigError e = configErrorOf([&] {
    Simulation::fromYaml("tissue: {generator: rectangular_grid}\n"
                         "compartments: {mode: transient, polar: {rate: 1, cells: cells.txt}}\n", {},
                         dir.path().string());
  });
  CHECK(e.keyPath() == "compartments.polar.cells");
  CHECK_THAT(e.what(), Catch::Contains("cells.txt:3"));
}

TEST_CASE("a huge binary line in the file of polar cells is quoted short and escaped", "[sim][coupling][errors]") {
  test::ScratchDir dir;
  dir.write("cells.txt", "3\n" + std::string(1'000'000, '\x02') + "\n");
  const ConfigError e = configErrorOf([&] {
    Simulation::fromYaml("tissue: {generator: rectangular_grid}\n"
                         "compartments: {mode: transient, polar: {rate: 1, cells: cells.txt}}\n", {},
                         dir.path().string());
  });
  const std::string what = e.what();
  CHECK(what.size() < 500);
  CHECK_THAT(what, Catch::Contains("cells.txt:2") && Catch::Contains("\\x02\\x02") && Catch::Contains("more bytes)"));
}

TEST_CASE("runtime problems of the solver stages name the stage and the key", "[sim][coupling][errors]") {
  // A region with no facet: a 2D tissue's mesh is flat, so z_max is every
  // boundary facet; a grid's x_min face exists; a Voronoi disk has no flat face.
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: voronoi, voronoi: {domain: disk, count: 10}}\n"
      "diffusion: {mode: steady, dirichlet: \"x_min=1\"}\n"
      "time: {end: 1, dt: 1}\n");
  try {
    sim.run();
    FAIL("expected an error");
  } catch (const SimulationError& e) {
    CHECK_THAT(e.what(), Catch::Contains("stage 'diffusion'"));
    CHECK_THAT(e.what(), Catch::Contains("diffusion.dirichlet"));
  }
  // A model of the wrong dimension is refused when the config is read (test_tissue_shape.cpp).
  const ConfigError e = configErrorOf([] {
    Simulation::fromYaml("tissue: {generator: rectangular_grid}\n"
                         "elasticity: {model: solid, fixed: \"x_min=xyz\"}\n"
                         "time: {end: 1, dt: 1}\n");
  });
  CHECK(e.keyPath() == "elasticity.model");
  CHECK_THAT(e.what(), Catch::Contains("'solid' needs a 3D tissue"));
}

TEST_CASE("a run writes the solver fields as point data of the fields series", "[sim][coupling][run]") {
  test::ScratchDir dir;
  PreparedRun run = PreparedRun::prepare(loadSimulationConfigFile(sourcePath("configs/morphogen_gradient_2d.yaml"),
                                                                  {"time.end=1", "output.every=2"}),
                                         RunOptions{dir.path().string(), false});
  run.execute();
  const std::filesystem::path pvd = dir.path() / "fields.pvd";
  REQUIRE(std::filesystem::exists(pvd));
  REQUIRE(std::filesystem::exists(dir.path() / "fields_walls.pvd"));
  // Steps 0, 2, 4 of 4: the initial field (a transient species is meshed at the start) and two more.
  std::size_t snapshots = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = e.path().filename().string();
    if (name.rfind("fields_0", 0) != 0) continue;
    ++snapshots;
    std::ifstream in(e.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.find("Name=\"auxin\"") != std::string::npos);
  }
  CHECK(snapshots == 3);
  // A second run into the same directory with --overwrite replaces the field series too.
  PreparedRun again = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/morphogen_gradient_2d.yaml"), {"time.end=0.5", "output.every=2"}),
      RunOptions{dir.path().string(), true});
  again.execute();
  std::size_t after = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    if (e.path().filename().string().rfind("fields_0", 0) == 0) ++after;
  CHECK(after == 2);
}

TEST_CASE("every: the solver runs every N steps over the time since its last solve", "[sim][coupling]") {
  // Compartments, no transport between cells (permeability 0), decay k: each
  // cell follows c' = -k c; implicit Euler with one step over N dt gives
  // c = 1 / (1 + k N dt) per solve, whatever the step count in between.
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 2, ny: 1}}\n"
      "compartments: {mode: transient, initial: 1, permeability: 0, decay: 0.5, every: 3}\n"
      "time: {end: 6, dt: 1}\n");
  const auto value = [&] { return sim.tissue().cellProperties().get<double>("c")[CellId(0)]; };
  sim.step();
  sim.step();
  CHECK(value() == 1.0);  // not solved yet
  sim.step();
  CHECK(value() == Approx(1.0 / 2.5).epsilon(1e-14));
  sim.run();
  CHECK(value() == Approx(1.0 / 6.25).epsilon(1e-14));
  CHECK(stageOf<CompartmentStage>(sim).solves() == 2);
}

TEST_CASE("2D elasticity from YAML: a stretch gives uniaxial stress, a traction balances the stresses",
          "[sim][coupling]") {
  const std::string base =
      "tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 4, ny: 3}}\n"
      "time: {end: 1, dt: 1}\n";
  const auto stressXX = [](const Simulation& sim) {
    std::vector<double> v;
    const auto& s = sim.tissue().cellProperties().get<double>("stress_xx");
    for (CellId c : sim.tissue().cells()) v.push_back(s[c]);
    return v;
  };
  // Hexagons (pointy side up) have vertical walls at the ends of the rows that
  // reach x_min / x_max; their bottom is jagged, so x_min also holds y.
  Simulation pulled = Simulation::fromYaml(
      base + "elasticity: {model: plane_stress, young: 3, fixed: \"x_min=xy\", traction_region: x_max, "
             "traction: [0.2, 0, 0]}\n");
  pulled.run();
  // On a rectangle with rollers the uniaxial state u = (eps x, -nu eps y) is exact.
  Simulation stretched = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 4, ny: 3}}\n"
      "time: {end: 1, dt: 1}\n"
      "elasticity: {model: plane_stress, young: 3, fixed: \"x_min=x, y_min=y\", stretch_region: x_max, "
      "stretch: 0.05}\n");
  stretched.run();
  // Stretch: every node has u_x = eps x, so sigma_xx = E eps in every cell,
  // eps = 0.05 / width.
  const mesh::FeMesh& mesh = fieldMeshOf(stretched).mesh();
  const double width = mesh.nodes.col(0).maxCoeff() - mesh.nodes.col(0).minCoeff();
  for (double s : stressXX(stretched)) CHECK(s == Approx(3 * 0.05 / width).epsilon(1e-8));
  // Traction on part of a jagged boundary is not uniaxial everywhere, but with
  // v = (x, 0) in the discrete equilibrium (no body force; x reactions only on
  // x = x_min): integral of sigma_xx = T * L * (x_max - x_min), L the loaded length.
  const mesh::FeMesh& pm = fieldMeshOf(pulled).mesh();
  const double x_min = pm.nodes.col(0).minCoeff(), x_max = pm.nodes.col(0).maxCoeff();
  double loaded = 0;
  for (int f = 0; f < pm.numWallFacets(); ++f) {
    const int i = pm.wall_facets(f, 0), j = pm.wall_facets(f, 1);
    if (pm.facet_on_boundary[f] && std::abs(pm.nodes(i, 0) - x_max) < 1e-9 && std::abs(pm.nodes(j, 0) - x_max) < 1e-9)
      loaded += (pm.nodes.row(i) - pm.nodes.row(j)).norm();
  }
  REQUIRE(loaded > 0);
  double integral = 0;
  const auto& sxx = pulled.tissue().cellProperties().get<double>("stress_xx");
  for (CellId c : pulled.tissue().cells()) integral += sxx[c] * cellMeasure(pulled.tissue(), c);
  CHECK(integral == Approx(0.2 * loaded * (x_max - x_min)).epsilon(1e-8));
}

TEST_CASE("steady diffusion with decay and an influx: the exponential profile of a strip", "[sim][coupling]") {
  // -D u'' + k u = 0 on [0, L], D u'(0) = -g (influx g at x = 0), u'(L) = 0:
  // u = g lambda / D cosh((L - x) / lambda) / sinh(L / lambda), lambda = sqrt(D / k).
  const double D = 1.0, k = 0.25, g = 1.0, L = 10.0, lambda = std::sqrt(D / k);
  Simulation sim = Simulation::fromYaml(
      "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 10, ny: 1}}\n"
      "diffusion: {mode: steady, species: m, diffusivity: 1, decay: 0.25, flux: \"x_min=1\"}\n"
      "mesh: {max_edge_length: 0.1}\n"
      "time: {end: 1, dt: 1}\n");
  sim.run();
  const Tissue& t = sim.tissue();
  const auto& m = t.cellProperties().get<double>("m");
  const double scale = g * lambda / D / std::sinh(L / lambda);
  for (CellId c : t.cells()) {
    const double x0 = cellCentroid(t, c).x() - 0.5;
    // The cell average of the exact solution over [x0, x0 + 1].
    const double exact = scale * lambda * (std::sinh((L - x0) / lambda) - std::sinh((L - x0 - 1) / lambda));
    INFO("cell at x0 = " << x0);
    CHECK(m[c] == Approx(exact).epsilon(2e-3));
  }
  // The steady balance: everything that enters decays, k * total = g * (strip height 1).
  CHECK(k * sumProperty(t, "m_amount") == Approx(g * 1.0).epsilon(1e-9));
}

TEST_CASE("a Robin end and a production: exact linear profile and exact amount growth", "[sim][coupling]") {
  SECTION("u = 1 at x = 0, -D u' = h u at x = L: u = 1 - h x / (D + h L), exact for P1") {
    const double D = 2.0, h = 0.5, L = 4.0;
    Simulation sim = Simulation::fromYaml(
        "tissue: {generator: rectangular_grid, rectangular_grid: {nx: 4, ny: 2}}\n"
        "diffusion: {mode: steady, diffusivity: 2, dirichlet: \"x_min=1\", robin: \"x_max=0.5\", exterior: 0}\n"
        "time: {end: 1, dt: 1}\n");
    sim.run();
    const FieldMesh& fm = fieldMeshOf(sim);
    for (int n = 0; n < fm.mesh().numNodes(); ++n)
      CHECK(fm.field("u")[n] == Approx(1.0 - h * fm.mesh().nodes(n, 0) / (D + h * L)).margin(1e-10));
  }
  SECTION("zero-flux boundaries, production p: the amount grows by p * area * t in both schemes") {
    for (const char* scheme : {"implicit_euler", "crank_nicolson"}) {
      INFO(scheme);
      Simulation sim = Simulation::fromYaml(
          std::string("tissue: {generator: hexagonal_grid, hexagonal_grid: {nx: 3, ny: 3}}\n"
                      "diffusion: {mode: transient, production: 0.3, initial: 0.5, dt: 0.1, scheme: ") +
          scheme + "}\ntime: {end: 2, dt: 0.5}\n");
      const double area = totalMeasure(sim.tissue());
      sim.run();
      CHECK(stageOf<DiffusionStage>(sim).totalAmount() == Approx(area * (0.5 + 0.3 * 2.0)).epsilon(1e-11));
    }
  }
}
