// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The checksum list of a snapshot: it covers every array of the file, and a
// single flipped bit in any array's data is refused with the array's name.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <zlib.h>

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using tessella::io::testing::readBytes;
using tessella::io::testing::writeBytes;
using Catch::Contains;

namespace {

struct ArrayInFile {
  std::string key;     // as the checksum list names it
  std::size_t offset;  // of its block in the appended data
};

/// The arrays of an uncompressed snapshot, keyed as the checksum list keys
/// them, with their offsets.
std::vector<ArrayInFile> arraysIn(const std::string& bytes) {
  const std::string header = bytes.substr(0, bytes.find("<AppendedData"));
  static const std::regex token(R"(<(FieldData|PointData|CellData|Points|Cells)[ >/]|<(?:Data)?Array [^>]*>)");
  static const std::regex name_re(R"re(Name="([^"]*)")re"), offset_re(R"re(offset="([0-9]+)")re");
  std::vector<ArrayInFile> out;
  std::string section;
  for (std::sregex_iterator it(header.begin(), header.end(), token), end; it != end; ++it) {
    if ((*it)[1].matched) {
      section = (*it)[1].str();
      continue;
    }
    const std::string element = it->str();
    std::smatch name, offset;
    REQUIRE(std::regex_search(element, name, name_re));
    REQUIRE(std::regex_search(element, offset, offset_re));
    std::string key = name[1].str();
    if (section == "Points") key = "points";
    else if (section == "Cells") key = "cells/" + (key == "faceoffsets" ? std::string("face_locations") : key);
    else if (section == "PointData") key = "point_data/" + key;
    else if (section == "CellData") key = "cell_data/" + key;
    else key = "field_data/" + key;
    out.push_back({key, std::stoull(offset[1].str())});
  }
  return out;
}

std::vector<std::string> checksumList(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto* list = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("tessella_checksums"));
  REQUIRE(list != nullptr);
  std::vector<std::string> entries;
  for (vtkIdType i = 0; i < list->GetNumberOfValues(); ++i) entries.push_back(list->GetValue(i));
  return entries;
}

Tissue withProperties(Tissue t) {
  auto& growth = t.cellProperties().add<double>("growth", 0.5, DivisionPolicy::SplitByMeasure);
  t.cellProperties().add<std::int32_t>("label", 3, DivisionPolicy::Reset);
  t.cellProperties().add<Vec3>("direction", Vec3::UnitX());
  t.properties(0).add<float>("auxin", 0.25f);
  for (CellId c : t.cells()) growth[c] = 1.0 / (3.0 + c.index());
  return t;
}

}  // namespace

TEST_CASE("the checksum list covers every array, and a flipped bit in any of them is refused by name",
          "[io][vtu][errors][checksum]") {
  TempDir dir;
  const Tissue tissue = GENERATE(as<int>{}, 2, 3) == 2 ? withProperties(hexagonalGrid(3, 2))
                                                         : withProperties(boxGrid(2, 2, 1));
  INFO("dimension " << tissue.dim());
  const std::string good = dir.file("good.vtu");
  VtuOptions options;
  options.compression = Compression::None;  // so that the arrays' bytes can be found
  writeTissueVtu(tissue, good, options);
  const std::string bytes = readBytes(good);
  const std::size_t data_start = bytes.find('_', bytes.find("<AppendedData")) + 1;
  const std::vector<ArrayInFile> arrays = arraysIn(bytes);

  // Every array but the list itself is listed once, in key order.
  const std::vector<std::string> entries = checksumList(good);
  std::vector<std::string> listed, in_file;
  for (const std::string& e : entries) {
    REQUIRE(std::regex_match(e, std::regex("[0-9a-f]{8} .+")));
    listed.push_back(e.substr(9));
  }
  for (const ArrayInFile& a : arrays)
    if (a.key != "field_data/tessella_checksums") in_file.push_back(a.key);
  std::sort(in_file.begin(), in_file.end());
  CHECK(std::is_sorted(listed.begin(), listed.end()));
  CHECK(listed == in_file);
  CHECK(std::count(listed.begin(), listed.end(), "points") == 1);
  CHECK(std::count(listed.begin(), listed.end(), "cell_data/growth") == 1);
  CHECK(std::count(listed.begin(), listed.end(), "point_data/auxin") == 1);
  CHECK(std::count(listed.begin(), listed.end(), "field_data/TimeValue") == 1);
  if (tissue.dim() == 3) CHECK(std::count(listed.begin(), listed.end(), "cells/faces") == 1);

  // Bit 0 of the first value of each array (after its 8-byte size header):
  // the file still decodes, and only the checksum can tell.
  for (const ArrayInFile& a : arrays) {
    INFO("array " << a.key);
    std::string damaged = bytes;
    const std::size_t at = data_start + a.offset + 8;
    REQUIRE(at < damaged.size());
    damaged[at] = static_cast<char>(damaged[at] ^ 1);
    const std::string bad = dir.file("bad.vtu");
    writeBytes(bad, damaged);
    if (a.key == "field_data/tessella_checksums")  // a damaged entry names the array it was for
      REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("does not match its checksum"));
    else if (a.key == "cells/faces")  // VTK's reader sees that it no longer fits faceoffsets
      REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("faces"));
    else if (a.key == "cells/face_locations")  // VTK 9.1 finds the faces without these offsets
      tessella::io::testing::requireSameTissue(tissue, readTissueVtu(bad));
    else
      REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("array '" + a.key + "' does not match its checksum") &&
                                                  Contains("the file is corrupted"));
  }
}

TEST_CASE("a file VTK's reader crashes on is an InputError naming the file and the crash", "[io][vtu][errors]") {
  TempDir dir;
  const std::string good = dir.file("good.vtu");
  writeTissueVtu(withProperties(rectangularGrid(3, 2)), good);
  const std::string bytes = readBytes(good);
  // Both crash VTK 9.1's reader in process: SIGSEGV and SIGFPE.
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"type=\"String\"", "type=\"Xtring\""},
                                 {"header_type=\"UInt64\"", "header_type=\"UInt32\""}}) {
    INFO(from << " -> " << to);
    std::string damaged = bytes;
    const auto at = damaged.find(from);
    REQUIRE(at != std::string::npos);
    damaged.replace(at, from.size(), to);
    const std::string bad = dir.file("bad.vtu");
    writeBytes(bad, damaged);
    REQUIRE_THROWS_AS(readTissueVtu(bad), InputError);
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains("cannot read '" + bad + "'") && Contains("the file is corrupted"));
  }
}

namespace {

/// zlib's CRC-32 of `bytes` continued from `crc`: the reference the
/// checksums are defined by, computed here without the writer's code.
std::uint32_t zlibCrc(std::uint32_t crc, const void* bytes, std::size_t n) {
  return static_cast<std::uint32_t>(crc32_z(crc, static_cast<const Bytef*>(bytes), n));
}

// (a little-endian host, as the test machines are)
std::uint32_t zlibCrcWord(std::uint32_t crc, std::uint64_t v) { return zlibCrc(crc, &v, sizeof v); }

}  // namespace

TEST_CASE("the checksums are zlib's CRC-32 of the documented canonical form", "[io][vtu]") {
  // 300 x 300 cells: the points (1.9 MB) go through the CRC in large blocks.
  const Tissue t = rectangularGrid(300, 300);
  TempDir dir;
  const std::string path = dir.file("grid.vtu");
  writeTissueVtu(t, path);
  std::string points_entry, time_entry;
  for (const std::string& e : checksumList(path)) {
    if (e.size() > 9 && e.substr(9) == "points") points_entry = e.substr(0, 8);
    if (e.size() > 9 && e.substr(9) == "field_data/TimeValue") time_entry = e.substr(0, 8);
  }
  // tuple count, component count, value type (floating point: 2 * 16 + size), values
  std::uint32_t crc = zlibCrcWord(zlibCrcWord(zlibCrcWord(0, t.numVertices()), 3), 2 * 16 + 8);
  for (VertexId v : t.vertices()) crc = zlibCrc(crc, t.position(v).data(), 3 * sizeof(double));
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", crc);
  CHECK(points_entry == hex);
  const double time = t.time();
  crc = zlibCrc(zlibCrcWord(zlibCrcWord(zlibCrcWord(0, 1), 1), 2 * 16 + 8), &time, sizeof time);
  std::snprintf(hex, sizeof hex, "%08x", crc);
  CHECK(time_entry == hex);
}
