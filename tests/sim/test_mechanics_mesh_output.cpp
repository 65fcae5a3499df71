// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The walls' mechanics in the mesh series (mesh.output): every wall facet of
// mesh_walls_NNNNNN.vtu carries its wall's values, the very numbers of the
// walls file beside the snapshot, and on a pressurised sphere the closed-form
// membrane tension P r / 2 in the facet's plane. A curved sheet's membranes
// are its cells: every element of mesh_NNNNNN.vtu carries its cell's values,
// those of the tissue snapshot, and on a pressurised sphere sheet P r / 2.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "tessella/io/mesh_vtu.hpp"
#include "tessella/io/pvd.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/mechanics/wall_stress.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/sections/mechanics_section.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/builders.hpp"
#include "test_support.hpp"

using namespace tessella;
using namespace tessella::sim;
using tessella::sim::test::ScratchDir;
using tessella::sim::test::sourcePath;

namespace {

// A sphere of radius R as triangles (outward): the poles are vertices 0 (south) and 1 (north), then `rings`
// staggered rings of `around` points (ring 0 starts on the +x axis, vertex 2).
struct SphereTriangles {
  std::vector<Vec3> points;
  std::vector<std::vector<Index>> faces;
};

SphereTriangles sphereTriangles(double R, int rings, int around) {
  SphereTriangles s;
  std::vector<Vec3>& points = s.points;
  points = {Vec3(0, 0, -R), Vec3(0, 0, R)};
  for (int k = 0; k < rings; ++k) {
    const double theta = std::numbers::pi * (k + 1) / (rings + 1), shift = 0.5 * (k % 2);
    for (int j = 0; j < around; ++j) {
      const double angle = 2.0 * std::numbers::pi * (j + shift) / around;
      points.emplace_back(R * std::sin(theta) * std::cos(angle), R * std::sin(theta) * std::sin(angle),
                          -R * std::cos(theta));
    }
  }
  auto ring = [&](int k, int j) { return static_cast<Index>(2 + k * around + (j + around) % around); };
  std::vector<std::vector<Index>>& faces = s.faces;
  for (int j = 0; j < around; ++j) faces.push_back({0, ring(0, j + 1), ring(0, j)});
  for (int k = 0; k + 1 < rings; ++k)
    for (int j = 0; j < around; ++j) {
      if (k % 2 == 0) {
        faces.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j)});
        faces.push_back({ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)});
      } else {
        faces.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
        faces.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      }
    }
  for (int j = 0; j < around; ++j) faces.push_back({1, ring(rings - 1, j), ring(rings - 1, j + 1)});
  return s;
}

// The sphere as a 3D tissue of one cell whose walls are its triangles.
Tissue sphereCell(double R, int rings, int around) {
  const SphereTriangles s = sphereTriangles(R, rings, around);
  std::vector<std::vector<CellFace>> cells(1);
  for (std::size_t f = 0; f < s.faces.size(); ++f) cells[0].push_back({static_cast<Index>(f), false});
  return buildPolyhedralTissue(s.points, s.faces, cells);
}

// The sphere as a closed curved sheet whose cells are its triangles (each cell a membrane).
Tissue sphereSheet(double R, int rings, int around) {
  const SphereTriangles s = sphereTriangles(R, rings, around);
  return buildPolygonTissue(s.points, s.faces, Embedding::Surface);
}

// No rigid motion left, free to inflate: the north pole fixed, the south pole held in x and y, the first ring
// point (on the +x axis) held in y.
std::vector<std::uint8_t> sphereSupports(const Tissue& sphere) {
  std::vector<std::uint8_t> fixed(3 * sphere.numVertices(), 0);
  fixed[3] = fixed[4] = fixed[5] = 1;
  fixed[0] = fixed[1] = 1;
  fixed[3 * 2 + 1] = 1;
  return fixed;
}

// A wall facet's unit normal from its three nodes.
Vec3 facetNormal(const mesh::FeMesh& m, Eigen::Index f) {
  const Vec3 a = m.nodes.row(m.wall_facets(f, 0)).transpose(), b = m.nodes.row(m.wall_facets(f, 1)).transpose(),
             c = m.nodes.row(m.wall_facets(f, 2)).transpose();
  return (b - a).cross(c - a).normalized();
}

double facetArea(const mesh::FeMesh& m, Eigen::Index f) {
  const Vec3 a = m.nodes.row(m.wall_facets(f, 0)).transpose(), b = m.nodes.row(m.wall_facets(f, 1)).transpose(),
             c = m.nodes.row(m.wall_facets(f, 2)).transpose();
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace

TEST_CASE("mesh series of a 3D membranes run: each wall facet carries its wall's values from the walls file",
          "[sim][mechanics][output][mesh]") {
  namespace fs = std::filesystem;
  ScratchDir dir;
  const std::string out = (dir.path() / "run").string();
  PreparedRun run = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/turgor_tissue_3d.yaml"),
                               {"tissue.voronoi.count=30", "time.end=0.1", "output.every=1", "mesh.output=true",
                                "mechanics.fibres=fixed", "mechanics.fibre_vector=[1, 0, 0]"}),
      RunOptions{out, false});
  run.execute();
  const auto listed = io::readPvdFile((fs::path(out) / "mesh_walls.pvd").string());
  REQUIRE(listed.size() == 2);
  const io::WallsFile walls = io::readWallsVtu((fs::path(out) / "tissue_000001.walls.vtu").string());
  const io::WallsFile facets = io::readWallsVtu((fs::path(out) / listed[1].file).string());
  REQUIRE(facets.wall_id.size() > walls.wall_id.size());  // several facets per wall
  std::map<int, std::size_t> row;
  for (std::size_t i = 0; i < walls.wall_id.size(); ++i) row[walls.wall_id[i]] = i;
  // Every array of the walls file (the table of mechanics::membraneWallOutputNames()), value for value.
  std::size_t arrays = 0, nonzero = 0;
  for (const auto& [name, values] : walls.arrays.scalars) {
    CAPTURE(name);
    REQUIRE(facets.arrays.scalars.count(name));
    const auto& got = facets.arrays.scalars.at(name);
    for (std::size_t f = 0; f < facets.wall_id.size(); ++f) {
      REQUIRE(row.count(facets.wall_id[f]));
      REQUIRE(got[f] == values[row.at(facets.wall_id[f])]);
      nonzero += got[f] != 0.0;
    }
    ++arrays;
  }
  for (const auto& [name, values] : walls.arrays.vectors) {
    CAPTURE(name);
    REQUIRE(facets.arrays.vectors.count(name));
    for (std::size_t f = 0; f < facets.wall_id.size(); ++f)
      REQUIRE(facets.arrays.vectors.at(name)[f] == values[row.at(facets.wall_id[f])]);
    ++arrays;
  }
  for (const auto& [name, values] : walls.arrays.tensors) {
    CAPTURE(name);
    REQUIRE(facets.arrays.tensors.count(name));
    for (std::size_t f = 0; f < facets.wall_id.size(); ++f)
      REQUIRE(facets.arrays.tensors.at(name)[f].v == values[row.at(facets.wall_id[f])].v);
    ++arrays;
  }
  CHECK(arrays == mechanics::membraneWallOutputNames().size());
  CHECK(nonzero > facets.wall_id.size());  // the step's values, not the zeros before it
  // The fibres (along x) lie in each facet's plane: a vector field ParaView can glyph on the mesh.
  CHECK(facets.arrays.vectors.count(mechanics::kFibreDirectionName));
}

// A sphere of radius R, one cell whose walls are its triangles, inflated by P: the exact St Venant-Kirchhoff
// radius r = lambda R solves t E (lambda^2 - 1) / (1 - nu) = P R lambda, and every wall carries N = P r / 2 both
// ways (the stress P r / (2 t)). Meshed with tetrahedra, the facets written by the mesh series carry that
// tension (2 % RMS at this resolution, as the walls: tests/mechanics/test_membrane_outputs.cpp), with unit
// principal directions at right angles in the facet's plane.
TEST_CASE("mesh series: the facets of a pressurised sphere carry the closed-form tension P r / 2 in their plane",
          "[sim][mechanics][output][mesh]") {
  const double R = 1.0, P = 1.0, E = 1000.0, t = 0.01, nu = 0.3;
  const double c = P * R * (1 - nu) / (t * E);
  const double lambda = 0.5 * (c + std::sqrt(c * c + 4.0));
  const double N = P * lambda * R / 2.0;
  Tissue tissue = sphereCell(R, 11, 24);
  mechanics::MembraneGrowthParams params;
  params.material = {.young = E, .poisson = nu, .thickness = t};
  params.pressure = P;
  mechanics::MembraneRestState state;
  const mechanics::FanMembraneModel model = mechanics::buildTissueMembranes(tissue, params, state);
  Eigen::VectorXd x = mechanics::spatialDofs(tissue);
  mechanics::solveEquilibrium(model, x, sphereSupports(tissue), params.solver);
  mechanics::setSpatialDofs(tissue, x);
  mechanics::writeMembraneWallOutputs(tissue, model, x);

  ScratchDir dir;
  io::MeshSeriesWriter writer(dir.path().string(), "mesh");
  const mesh::FeMesh m = mesh::meshTissue(tissue);
  io::MeshFields fields;
  fields.walls = io::wallPropertyArrays(tissue, mechanics::membraneWallOutputNames());
  for (WallId w : tissue.walls()) fields.wall_ids.push_back(static_cast<int>(w.index()));
  writer.write(m, 0.0, fields);
  const io::WallsFile f = io::readWallsVtu((dir.path() / "mesh_walls_000000.vtu").string());
  REQUIRE(static_cast<Eigen::Index>(f.wall_id.size()) == m.numWallFacets());
  const auto& high = f.arrays.scalars.at(mechanics::kStressMaxName);
  const auto& low = f.arrays.scalars.at(mechanics::kStressMinName);
  const auto& dir_max = f.arrays.vectors.at(mechanics::kStressDirectionName);
  const auto& dir_min = f.arrays.vectors.at(mechanics::kStressMinDirectionName);
  const auto& tensor = f.arrays.tensors.at(mechanics::kWallStressName);
  double sum = 0.0, weight = 0.0;
  for (Eigen::Index k = 0; k < m.numWallFacets(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    CHECK(f.wall_id[i] == m.facet_wall(k));
    const double a = facetArea(m, k);
    sum += a * (std::pow(high[i] / N - 1.0, 2) + std::pow(low[i] / N - 1.0, 2)) / 2.0;
    weight += a;
    const Vec3 n = facetNormal(m, k);
    CHECK(dir_max[i].norm() == Approx(1.0).epsilon(1e-12));
    CHECK(std::abs(dir_max[i].dot(dir_min[i])) < 1e-12);
    CHECK(std::abs(dir_max[i].dot(n)) < 1e-8);
    CHECK(std::abs(dir_min[i].dot(n)) < 1e-8);
    // The tensor (VTK order read back) has the principal values along its directions and none across the facet.
    const Mat3 s = tensor[i].matrix();
    CHECK(dir_max[i].dot(s * dir_max[i]) == Approx(high[i]).epsilon(1e-10));
    CHECK(std::abs(n.dot(s * n)) < 1e-8 * N);
  }
  const double rms = std::sqrt(sum / weight);
  CAPTURE(rms);
  CHECK(rms < 0.02);
}

TEST_CASE("mesh series: wall arrays that do not fit the mesh are errors naming them", "[sim][output][mesh]") {
  const Tissue tissue = sphereCell(1.0, 3, 6);
  const mesh::FeMesh m = mesh::meshTissue(tissue);
  io::MeshFields fields;
  for (WallId w : tissue.walls()) fields.wall_ids.push_back(static_cast<int>(w.index()));
  fields.walls.scalars["stress_max"] = std::vector<double>(tissue.numWalls() - 1, 1.0);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields),
                    Contains("wall array 'stress_max' has " + std::to_string(tissue.numWalls() - 1) + " values for " +
                             std::to_string(tissue.numWalls()) + " walls"));
  fields.walls.scalars["stress_max"].push_back(1.0);
  fields.wall_ids.pop_back();
  fields.walls.scalars["stress_max"].pop_back();
  const int last = static_cast<int>(tissue.numWalls() - 1);
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields), Contains("lies on wall " + std::to_string(last) +
                                                         ", which has no values in the wall arrays"));
  fields.wall_ids.push_back(last);
  fields.walls.scalars["stress_max"].push_back(1.0);
  fields.walls.scalars["wall_id"] = fields.walls.scalars["stress_max"];
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields), Contains("wall array name 'wall_id'"));
}

// A closed curved sheet's element: its triangle's unit normal.
Vec3 elementNormal(const mesh::FeMesh& m, Eigen::Index e) {
  const Vec3 a = m.nodes.row(m.elements(e, 0)).transpose(), b = m.nodes.row(m.elements(e, 1)).transpose(),
             c = m.nodes.row(m.elements(e, 2)).transpose();
  return (b - a).cross(c - a).normalized();
}

TEST_CASE("mesh series of a curved sheet's membranes run: each element carries its cell's values from the snapshot",
          "[sim][mechanics][output][mesh]") {
  namespace fs = std::filesystem;
  ScratchDir dir;
  const std::string out = (dir.path() / "run").string();
  PreparedRun run = PreparedRun::prepare(
      loadSimulationConfigFile(sourcePath("configs/turgor_dome_2p5d.yaml"),
                               {"time.end=0.2", "output.every=1", "mesh.output=true"}),
      RunOptions{out, false});
  run.execute();
  const auto meshes = io::readPvdFile((fs::path(out) / "mesh.pvd").string());
  const auto snapshots = io::readPvdFile((fs::path(out) / "tissue.pvd").string());
  REQUIRE(meshes.size() == 3);
  REQUIRE(snapshots.size() == meshes.size());
  const std::vector<std::string> names = MechanicsStage::sheetCellOutputNames();
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    CAPTURE(k);
    CHECK(meshes[k].time == snapshots[k].time);
    const Tissue snapshot = io::readTissueVtu((fs::path(out) / snapshots[k].file).string());
    REQUIRE(snapshot.embedding() == Embedding::Surface);
    const io::FeMeshElementsFile elements = io::readFeMeshElementsVtu((fs::path(out) / meshes[k].file).string());
    REQUIRE(elements.cell_id.size() > snapshot.numCells());  // several elements per cell
    // Every cell column of the table the snapshot holds is on every element, value for value.
    const PropertyStore& cells = snapshot.cellProperties();
    std::size_t arrays = 0, nonzero = 0;
    for (const std::string& name : names) {
      CAPTURE(name);
      if (!cells.has(name)) continue;
      ++arrays;
      for (std::size_t e = 0; e < elements.cell_id.size(); ++e) {
        const CellId c(static_cast<Index>(elements.cell_id[e]));
        REQUIRE(snapshot.alive(c));
        if (elements.arrays.scalars.count(name)) {
          REQUIRE(elements.arrays.scalars.at(name)[e] == cells.get<double>(name)[c]);
          nonzero += elements.arrays.scalars.at(name)[e] != 0.0;
        } else if (elements.arrays.vectors.count(name)) {
          REQUIRE(elements.arrays.vectors.at(name)[e] == cells.get<Vec3>(name)[c]);
        } else {
          REQUIRE(elements.arrays.tensors.count(name));
          REQUIRE(elements.arrays.tensors.at(name)[e].v == cells.get<Sym3>(name)[c].v);
        }
      }
    }
    // The sheet's cells hold what a 3D wall holds (tension and Green strain tensors, their principal values and
    // directions, the fibre direction, rest area, growth rate and pressure load) and the turgor.
    CHECK(arrays == names.size());
    CHECK(elements.arrays.tensors.count(mechanics::kWallStressName));
    CHECK(elements.arrays.tensors.count(mechanics::kGreenStrainName));
    CHECK(elements.arrays.vectors.count(mechanics::kStressDirectionName));
    CHECK(elements.arrays.vectors.count(mechanics::kFibreDirectionName));
    CHECK(elements.arrays.scalars.count(mechanics::kTurgorPressureName));
    // Nothing else but the arrays of the table (no stray columns such as young_scale).
    CHECK(elements.arrays.scalars.size() + elements.arrays.vectors.size() + elements.arrays.tensors.size() == arrays);
    if (k > 0) CHECK(nonzero > 3 * elements.cell_id.size());  // the step's values, not the zeros before it
  }
}

// The sphere as a closed sheet of 11 rings, its cells the triangles, inflated by P: the exact St Venant-Kirchhoff
// sphere as above, N = P r / 2 both ways. Every element of the mesh series carries its cell's tension: within
// 2 % RMS (the same constant-tension triangles as the walls of the 3D sphere), directions unit and in the plane.
TEST_CASE("mesh series: the elements of a pressurised sphere sheet carry the closed-form tension P r / 2",
          "[sim][mechanics][output][mesh]") {
  const double R = 1.0, P = 1.0, E = 1000.0, t = 0.01, nu = 0.3;
  const double c = P * R * (1 - nu) / (t * E);
  const double lambda = 0.5 * (c + std::sqrt(c * c + 4.0));
  const double N = P * lambda * R / 2.0;
  Tissue tissue = sphereSheet(R, 11, 24);
  REQUIRE(tissue.embedding() == Embedding::Surface);
  mechanics::MembraneGrowthParams params;
  params.material = {.young = E, .poisson = nu, .thickness = t};
  params.pressure = P;
  mechanics::MembraneRestState state;
  const mechanics::FanMembraneModel model = mechanics::buildTissueMembranes(tissue, params, state);
  Eigen::VectorXd x = mechanics::spatialDofs(tissue);
  mechanics::solveEquilibrium(model, x, sphereSupports(tissue), params.solver);
  mechanics::setSpatialDofs(tissue, x);
  mechanics::cellOutput(tissue, mechanics::kTurgorPressureName, P);
  mechanics::writeMembraneCellStress(tissue, model, x);

  ScratchDir dir;
  io::MeshSeriesWriter writer(dir.path().string(), "mesh");
  const mesh::FeMesh m = mesh::meshTissue(tissue);
  io::MeshFields fields;
  fields.cells = io::cellPropertyArrays(tissue, MechanicsStage::sheetCellOutputNames());
  for (CellId cell : tissue.cells()) fields.cell_ids.push_back(static_cast<int>(cell.index()));
  writer.write(m, 0.0, fields);
  const io::FeMeshElementsFile f = io::readFeMeshElementsVtu((dir.path() / "mesh_000000.vtu").string());
  REQUIRE(static_cast<Eigen::Index>(f.cell_id.size()) == m.numElements());
  const auto& high = f.arrays.scalars.at(mechanics::kStressMaxName);
  const auto& low = f.arrays.scalars.at(mechanics::kStressMinName);
  const auto& dir_max = f.arrays.vectors.at(mechanics::kStressDirectionName);
  const auto& tensor = f.arrays.tensors.at(mechanics::kWallStressName);
  const auto& pressure = f.arrays.scalars.at(mechanics::kTurgorPressureName);
  double sum = 0.0, weight = 0.0;
  for (Eigen::Index k = 0; k < m.numElements(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    CHECK(f.cell_id[i] == m.element_cell(k));
    CHECK(pressure[i] == P);
    const Vec3 a = m.nodes.row(m.elements(k, 0)).transpose(), b = m.nodes.row(m.elements(k, 1)).transpose(),
               d = m.nodes.row(m.elements(k, 2)).transpose();
    const double area = 0.5 * (b - a).cross(d - a).norm();
    sum += area * (std::pow(high[i] / N - 1.0, 2) + std::pow(low[i] / N - 1.0, 2)) / 2.0;
    weight += area;
    // Each cell is one flat triangle, so is each of its elements: the tension lies in the element's plane.
    const Vec3 n = elementNormal(m, k);
    CHECK(dir_max[i].norm() == Approx(1.0).epsilon(1e-12));
    CHECK(std::abs(dir_max[i].dot(n)) < 1e-8);
    const Mat3 s = tensor[i].matrix();
    CHECK(dir_max[i].dot(s * dir_max[i]) == Approx(high[i]).epsilon(1e-10));
    CHECK(std::abs(n.dot(s * n)) < 1e-8 * N);
  }
  const double rms = std::sqrt(sum / weight);
  CAPTURE(rms);
  CHECK(rms < 0.02);
}

TEST_CASE("mesh series: cell arrays that do not fit the mesh are errors naming them", "[sim][output][mesh]") {
  const Tissue tissue = sphereSheet(1.0, 3, 6);
  const mesh::FeMesh m = mesh::meshTissue(tissue);
  io::MeshFields fields;
  for (CellId c : tissue.cells()) fields.cell_ids.push_back(static_cast<int>(c.index()));
  fields.cells.scalars["stress_max"] = std::vector<double>(tissue.numCells() - 1, 1.0);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields),
                    Contains("cell array 'stress_max' has " + std::to_string(tissue.numCells() - 1) + " values for " +
                             std::to_string(tissue.numCells()) + " cells"));
  fields.cells.scalars["stress_max"].push_back(1.0);
  fields.cell_ids.pop_back();
  fields.cells.scalars["stress_max"].pop_back();
  const int last = static_cast<int>(tissue.numCells() - 1);
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields), Contains("lies on cell " + std::to_string(last) +
                                                         ", which has no values in the cell arrays"));
  fields.cell_ids.push_back(last);
  fields.cells.scalars["stress_max"].push_back(1.0);
  fields.cells.scalars["cell_id"] = fields.cells.scalars["stress_max"];
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields), Contains("cell array name 'cell_id'"));
  fields.cells.scalars.erase("cell_id");
  fields.element["stress_max"] = Eigen::VectorXd::Zero(m.numElements());
  CHECK_THROWS_WITH(io::checkFeMesh(m, fields), Contains("cell array name 'stress_max'"));
}
