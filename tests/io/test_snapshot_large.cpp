// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Snapshots large enough that their arrays are handed from the worker that
// parses the file to the reader on pages of their own (mapped, not copied):
// they read back equal to what was written, bit for bit, numbering included.

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/io/vtu.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <typename T>
bool sameColumn(const Tissue& a, const Tissue& b, int degree, const std::string& name) {
  return sameBytes(a.properties(degree).get<T>(name).values(), b.properties(degree).get<T>(name).values());
}

void requireEqual(const Tissue& a, const Tissue& b) {
  REQUIRE(b.dim() == a.dim());
  REQUIRE(b.time() == a.time());
  const ComplexLayout la = a.topology().layout(), lb = b.topology().layout();
  CHECK(lb.num_vertices == la.num_vertices);
  CHECK(lb.edge_vertices == la.edge_vertices);
  CHECK(lb.face_edge_offsets == la.face_edge_offsets);
  CHECK(lb.face_edges == la.face_edges);
  CHECK(lb.volume_face_offsets == la.volume_face_offsets);
  CHECK(lb.volume_faces == la.volume_faces);
  CHECK(lb.vertex_edges == la.vertex_edges);
  CHECK(lb.edge_faces == la.edge_faces);
  CHECK(lb.face_volumes == la.face_volumes);
  REQUIRE(b.numVertices() == a.numVertices());
  bool same_positions = true;
  for (std::size_t i = 0; i < a.numVertices(); ++i)
    same_positions = same_positions && std::memcmp(a.positions()[i].data(), b.positions()[i].data(), 24) == 0;
  CHECK(same_positions);
  bool same_lineage = true;
  for (CellId c : a.cells())
    same_lineage = same_lineage && a.lineageId(c) == b.lineageId(c) && a.parentId(c) == b.parentId(c) &&
                   a.birthTime(c) == b.birthTime(c);
  CHECK(same_lineage);
  CHECK(sameColumn<double>(a, b, a.dim(), "growth"));
  CHECK(sameColumn<std::int32_t>(a, b, a.dim(), "label"));
  CHECK(sameColumn<Vec3>(a, b, a.dim(), "direction"));
  CHECK(sameColumn<float>(a, b, 0, "auxin"));
  CHECK(b.cellProperties().get<double>("growth").policy() == DivisionPolicy::SplitByMeasure);
}

Tissue withProperties(Tissue t) {
  auto& growth = t.cellProperties().add<double>("growth", 0.5, DivisionPolicy::SplitByMeasure);
  auto& label = t.cellProperties().add<std::int32_t>("label", 7);
  auto& direction = t.cellProperties().add<Vec3>("direction", Vec3::UnitX());
  auto& auxin = t.properties(0).add<float>("auxin", 0.0f);
  for (CellId c : t.cells()) {
    const double i = c.index();
    growth[c] = 0.1 * i + 1.0 / 3.0;
    label[c] = static_cast<std::int32_t>(100000 - c.index());
    direction[c] = Vec3(i, 1.0 / (i + 1.0), -0.25 * i);
  }
  for (VertexId v : t.vertices()) auxin[v] = 0.5f * static_cast<float>(v.index()) + 0.125f;
  t.setTime(1.5);
  return t;
}

}  // namespace

TEST_CASE("large snapshots (arrays over 1 MiB) read back equal, element numbering included", "[io][vtu]") {
  TempDir dir;
  struct Case {
    const char* name;
    Tissue tissue;
    Compression compression;
  };
  // 200 x 200 cells: the connectivity alone is 1.3 MB; 24^3 boxes: a face stream of 2.3 MB.
  const std::vector<Case> cases = {
      {"2d-lz4", withProperties(rectangularGrid(200, 200)), Compression::LZ4},
      {"2d-raw", withProperties(hexagonalGrid(120, 120)), Compression::None},
      {"3d-zlib", withProperties(boxGrid(24, 24, 24)), Compression::ZLib},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.file(std::string(c.name) + ".vtu");
    VtuOptions options;
    options.compression = c.compression;
    writeTissueVtu(c.tissue, path, options);
    requireEqual(c.tissue, readTissueVtu(path));
  }
}
