// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The solver fields' state beside a snapshot (field_state.hpp): a round trip
// gives back every array to the bit; damage, and a file that is not a field
// state, are refused naming the file.

#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include <vtkCellData.h>
#include <vtkPointData.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/field_state.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using tessella::io::testing::TempDir;

namespace {

// Two unit squares split into triangles, nodes moved off the grid by random
// amounts (so that no coordinate is a short decimal).
io::FieldState twoSquares() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  io::FieldState s;
  mesh::FeMesh& m = s.mesh;
  m.dim = 2;
  m.nodes.resize(6, 3);
  for (int i = 0; i < 6; ++i) m.nodes.row(i) << (i % 3) + jitter(rng), (i / 3) + jitter(rng), 0.0;
  m.elements.resize(4, 3);
  m.elements << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4;
  m.element_cell.resize(4);
  m.element_cell << 0, 0, 1, 1;
  m.wall_facets.resize(3, 2);
  m.wall_facets << 0, 1, 1, 4, 4, 3;
  m.facet_wall.resize(3);
  m.facet_wall << 7, 2, 9;
  m.facet_on_boundary.resize(3);
  m.facet_on_boundary << true, false, true;
  m.node_vertex.resize(6);
  m.node_vertex << 0, 1, 2, 3, -1, 5;
  s.cell_lineage = {40, 12};
  Eigen::VectorXd u(6), v(6);
  for (int i = 0; i < 6; ++i) u[i] = std::exp(jitter(rng)), v[i] = -jitter(rng) / 3;
  s.fields = {{"auxin", u}, {"inhibitor", v}};
  return s;
}

bool sameBits(const double* a, const double* b, Eigen::Index n) {
  return std::memcmp(a, b, sizeof(double) * static_cast<std::size_t>(n)) == 0;
}

}  // namespace

TEST_CASE("a field state reads back to the bit, every array of it", "[io][field_state]") {
  TempDir dir;
  const io::FieldState s = twoSquares();
  const std::string path = dir.file("state.fields.vtu");
  const std::uint32_t crc = io::writeFieldState(s, path);
  CHECK(crc == io::fileChecksum(path));
  const io::FieldState r = io::readFieldState(path);
  CHECK(r.mesh.dim == 2);
  REQUIRE(r.mesh.nodes.rows() == 6);
  CHECK(sameBits(r.mesh.nodes.data(), s.mesh.nodes.data(), s.mesh.nodes.size()));
  CHECK(r.mesh.elements == s.mesh.elements);
  CHECK(r.mesh.element_cell == s.mesh.element_cell);
  CHECK(r.mesh.wall_facets == s.mesh.wall_facets);
  CHECK(r.mesh.facet_wall == s.mesh.facet_wall);
  CHECK(r.mesh.facet_on_boundary == s.mesh.facet_on_boundary);
  CHECK(r.mesh.node_vertex == s.mesh.node_vertex);
  CHECK(r.cell_lineage == s.cell_lineage);
  REQUIRE(r.fields.size() == 2);
  for (const auto& [name, values] : s.fields) {
    INFO(name);
    REQUIRE(r.fields.count(name));
    CHECK(sameBits(r.fields.at(name).data(), values.data(), values.size()));
  }
}

TEST_CASE("a field state file is named after its snapshot", "[io][field_state]") {
  CHECK(io::fieldStatePath("/runs/a/tissue_000035.vtu") == "/runs/a/tissue_000035.fields.vtu");
  CHECK(io::fieldStatePath("half.vtu") == "half.fields.vtu");
}

TEST_CASE("a damaged, foreign or inconsistent field state is refused naming the file", "[io][field_state]") {
  TempDir dir;
  const std::string path = dir.file("state.fields.vtu");
  io::writeFieldState(twoSquares(), path);
  auto refused = [](const std::string& file, const std::string& part) {
    try {
      io::readFieldState(file);
      FAIL("accepted");
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(file) != std::string::npos);
      CHECK(std::string(e.what()).find(part) != std::string::npos);
    }
  };
  refused(dir.file("missing.fields.vtu"), "no such file");

  // A value changed under its checksum.
  const std::string flipped = dir.file("flipped.vtu");
  const auto flip = [](vtkUnstructuredGrid* grid) { grid->GetPointData()->GetArray("auxin")->SetComponent(2, 0, 1.5); };
  io::testing::tamper(path, flipped, flip, true);
  refused(flipped, "auxin");

  // An element in a cell the lineage list does not have (checksums removed).
  const std::string stray = dir.file("stray.vtu");
  io::testing::tamper(path, stray, [](vtkUnstructuredGrid* grid) {
    grid->GetCellData()->GetArray("cell_id")->SetComponent(3, 0, 5);
  });
  refused(stray, "element 3 lies in cell 5");

  // A mesh file of the fields series is not a field state.
  const std::string mesh = dir.file("mesh.vtu");
  io::writeFeMeshVtu(twoSquares().mesh, mesh);
  refused(mesh, "not a field state file");

  // Refused at write time: an element in a cell the lineage list lacks.
  io::FieldState bad = twoSquares();
  bad.cell_lineage.pop_back();
  CHECK_THROWS_WITH(io::writeFieldState(bad, dir.file("bad.vtu")), Catch::Contains("element 2 lies in cell 1"));
}
