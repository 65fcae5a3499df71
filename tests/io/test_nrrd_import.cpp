// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// NRRD label images written here byte by byte (raw in either byte order, gzip, ASCII, attached or with a
// detached header) and read back: the labels as written, and the imported tissue's cells, areas in pixels
// and neighbours as the array itself gives them. Small images included: VTK 9.1's vtkNrrdReader crashed
// on a first axis of 9 or fewer pixels. Malformed headers and data give an InputError naming the file.

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>
#include <zlib.h>

#include "io_test_support.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

struct Type {
  std::string name;
  int bytes;
  std::int64_t base;  // the smallest label written: beyond the next smaller type's range
};

const std::vector<Type> kTypes = {{"uint8", 1, 2},          {"int8", 1, 2},     {"int16", 2, 300},
                                  {"uint16", 2, 40000},     {"int32", 4, 70000}, {"uint32", 4, 3000000000},
                                  {"int64", 8, 1LL << 40}, {"uint64", 8, 1LL << 41}};

// Labels x fastest: rectangular blocks (up to 2 along x, 3 along y, 2 along z), each block one label.
std::vector<std::int64_t> blockLabels(const std::array<std::int64_t, 3>& n, std::int64_t base) {
  std::vector<std::int64_t> labels;
  const std::int64_t bx = std::min<std::int64_t>(n[0], 2), by = std::min<std::int64_t>(n[1], 3),
                     bz = std::min<std::int64_t>(n[2], 2);
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i)
        labels.push_back(base + i * bx / n[0] + bx * (j * by / n[1] + by * (k * bz / n[2])));
  return labels;
}

std::string valueBytes(const std::vector<std::int64_t>& labels, int bytes, bool big_endian) {
  std::string out;
  for (std::int64_t l : labels)
    for (int b = 0; b < bytes; ++b) {
      const int shift = 8 * (big_endian ? bytes - 1 - b : b);
      out.push_back(static_cast<char>((static_cast<std::uint64_t>(l) >> shift) & 0xff));
    }
  return out;
}

std::string gzipped(const std::string& data) {
  z_stream z{};
  REQUIRE(deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) == Z_OK);  // 15 + 16: a gzip stream
  std::string out(deflateBound(&z, static_cast<uLong>(data.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

struct Nrrd {
  std::array<std::int64_t, 3> n{1, 1, 1};
  int dimension = 2;
  Type type = kTypes[0];
  std::string encoding = "raw";
  bool big_endian = false;
  bool detached = false;
  std::string extra_fields;  // whole lines
};

std::string sizesField(const Nrrd& f) {
  std::string s = std::to_string(f.n[0]) + " " + std::to_string(f.n[1]);
  return f.dimension == 3 ? s + " " + std::to_string(f.n[2]) : s;
}

std::string encoded(const Nrrd& f, const std::vector<std::int64_t>& labels) {
  if (f.encoding == "ascii") {
    std::string text;
    for (std::size_t k = 0; k < labels.size(); ++k) text += std::to_string(labels[k]) + (k % 7 == 6 ? "\n" : " ");
    return text + "\n";
  }
  const std::string raw = valueBytes(labels, f.type.bytes, f.big_endian);
  return f.encoding == "gzip" ? gzipped(raw) : raw;
}

// Writes the header (and a data file beside it when detached) with `data` as the data; returns the header path.
std::string writeNrrd(const TempDir& dir, const std::string& stem, const Nrrd& f, const std::string& data) {
  const std::string path = dir.file(stem + (f.detached ? ".nhdr" : ".nrrd"));
  std::ofstream out(path, std::ios::binary);
  std::string header = "NRRD0004\n# written by test_nrrd_import\ntype: " + f.type.name + "\ndimension: " +
                       std::to_string(f.dimension) + "\nsizes: " + sizesField(f) + "\nencoding: " + f.encoding +
                       "\nendian: " + (f.big_endian ? "big" : "little") + "\n" + f.extra_fields;
  if (f.detached) {
    std::ofstream(dir.file(stem + ".data"), std::ios::binary) << data;
    out << header << "data file: " << stem << ".data\n";
  } else {
    out << header << "\n" << data;
  }
  return path;
}

// Cells, areas (volumes) in pixels and neighbour pairs of the labels, from the array itself (0 and 1: none).
struct Expected {
  std::map<std::int64_t, double> size;
  std::set<std::pair<std::int64_t, std::int64_t>> neighbours;
};

Expected fromArray(const std::array<std::int64_t, 3>& n, const std::vector<std::int64_t>& labels) {
  Expected e;
  auto at = [&](std::int64_t i, std::int64_t j, std::int64_t k) { return labels[static_cast<std::size_t>((k * n[1] + j) * n[0] + i)]; };
  for (std::int64_t k = 0; k < n[2]; ++k)
    for (std::int64_t j = 0; j < n[1]; ++j)
      for (std::int64_t i = 0; i < n[0]; ++i) {
        const std::int64_t l = at(i, j, k);
        e.size[l] += 1;
        const std::int64_t next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& q : next)
          if (q[0] < n[0] && q[1] < n[1] && q[2] < n[2] && at(q[0], q[1], q[2]) != l)
            e.neighbours.insert(std::minmax(l, at(q[0], q[1], q[2])));
      }
  return e;
}

void checkImport(const std::string& path, const std::array<std::int64_t, 3>& n, const std::vector<std::int64_t>& labels) {
  const LabelImage image = readLabelImage(path);
  CHECK(image.dims == std::array<std::int64_t, 3>{n[0], n[1], n[2]});
  CHECK(image.labels == labels);
  const ImportResult r = importTissue(path, ImportOptions{});
  const Tissue& t = r.tissue;
  CHECK(validate(t).ok);
  const Expected want = fromArray(n, labels);
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  std::map<std::int64_t, double> size;
  for (CellId c : t.cells()) size[label[c]] += cellMeasure(t, c);
  REQUIRE(size.size() == want.size.size());
  for (const auto& [l, pixels] : want.size) {
    INFO("label " << l);
    CHECK(size[l] == Approx(pixels));
  }
  std::set<std::pair<std::int64_t, std::int64_t>> neighbours;
  for (WallId w : t.walls()) {
    const auto cs = t.wallCells(w);
    if (cs.size() == 2) neighbours.insert(std::minmax(label[cs[0]], label[cs[1]]));
  }
  CHECK(neighbours == want.neighbours);
}

}  // namespace

TEST_CASE("small and large NRRD label images of every integer type import as written", "[io][label_image][nrrd]") {
  TempDir dir;
  const std::vector<std::array<std::int64_t, 3>> sizes2d = {{1, 9, 1}, {9, 1, 1}, {5, 9, 1}, {4, 4, 1}, {2, 3, 1},
                                                          {10, 10, 1}, {20, 20, 1}, {37, 11, 1}};
  for (const auto& n : sizes2d)
    for (const Type& type : kTypes) {
      Nrrd f;
      f.n = n;
      f.type = type;
      const std::vector<std::int64_t> labels = blockLabels(n, type.base);
      INFO(n[0] << " x " << n[1] << " " << type.name);
      checkImport(writeNrrd(dir, "raw", f, encoded(f, labels)), n, labels);
    }
}

TEST_CASE("NRRD label images: 3D, big-endian, gzip, ASCII and detached headers", "[io][label_image][nrrd]") {
  TempDir dir;
  for (const std::array<std::int64_t, 3> n : {std::array<std::int64_t, 3>{3, 4, 5}, {5, 9, 1}, {12, 10, 3}})
    for (const std::string encoding : {"raw", "gzip", "ascii"})
      for (const bool big_endian : {false, true})
        for (const bool detached : {false, true})
          for (const Type& type : {kTypes[0], kTypes[2], kTypes[5], kTypes[6]}) {
            Nrrd f;
            f.n = n;
            f.dimension = n[2] > 1 ? 3 : 2;
            f.type = type;
            f.encoding = encoding;
            f.big_endian = big_endian;
            f.detached = detached;
            const std::vector<std::int64_t> labels = blockLabels(n, type.base);
            INFO(sizesField(f) << " " << type.name << " " << encoding << (big_endian ? " big" : " little")
                               << (detached ? " detached" : " attached"));
            checkImport(writeNrrd(dir, "img", f, encoded(f, labels)), n, labels);
          }
}

TEST_CASE("NRRD spacings, space directions and origin give the pixel size and position", "[io][label_image][nrrd]") {
  TempDir dir;
  Nrrd f;
  f.n = {4, 3, 1};
  const std::vector<std::int64_t> labels = blockLabels(f.n, 2);
  f.extra_fields = "spacings: 0.5 2\n";
  LabelImage image = readLabelImage(writeNrrd(dir, "spacings", f, encoded(f, labels)));
  CHECK(image.spacing[0] == 0.5);
  CHECK(image.spacing[1] == 2);
  f.extra_fields = "space dimension: 2\nspace directions: (0,3) (4,0)\nspace origin: (1.5,-2)\n";
  image = readLabelImage(writeNrrd(dir, "directions", f, encoded(f, labels)));
  CHECK(image.spacing[0] == 3);
  CHECK(image.spacing[1] == 4);
  CHECK(image.origin[0] == 1.5);
  CHECK(image.origin[1] == -2);
  CHECK(image.labels == labels);
}

TEST_CASE("malformed NRRD headers and data give an InputError naming the file and the field", "[io][label_image][nrrd]") {
  TempDir dir;
  Nrrd f;
  f.n = {5, 9, 1};
  f.type = kTypes[2];  // int16
  const std::vector<std::int64_t> labels = blockLabels(f.n, 2);
  const std::string raw = encoded(f, labels);
  const auto fails = [&](const std::string& stem, Nrrd g, const std::string& data, std::vector<std::string> parts) {
    const std::string path = writeNrrd(dir, stem, g, data);
    INFO(stem);
    parts.push_back(path);
    try {
      readLabelImage(path);
      FAIL("no error for " << stem);
    } catch (const InputError& e) {
      const std::string what = e.what();
      INFO(what);
      for (const std::string& part : parts) CHECK(what.find(part) != std::string::npos);
    }
    CHECK_THROWS_AS(importTissue(path, ImportOptions{}), InputError);
  };
  Nrrd g = f;
  g.type.name = "int12";
  fails("bad_type", g, raw, {"'type'", "int12"});
  g = f;
  g.type.name = "float";
  fails("float_type", g, raw, {"'type'", "float", "integers"});
  fails("short_data", f, raw.substr(0, raw.size() - 2), {"88 bytes", "need 90"});
  fails("long_data", f, raw + "xx", {"92 bytes", "need 90"});
  g = f;
  g.n = {9, 9, 1};
  fails("sizes_too_large", g, raw, {"90 bytes", "9 x 9", "need 162"});
  g = f;
  g.encoding = "bzip3";
  fails("unknown_encoding", g, raw, {"'encoding'", "bzip3"});
  g = f;
  g.encoding = "gzip";
  fails("gzip_short", g, gzipped(raw.substr(0, 80)), {"80 bytes of gzip data", "need 90"});
  fails("gzip_corrupt", g, "this is not gzip data at all", {"gzip"});
  g.n = {100000, 100000, 1};  // 20 GB claimed: refused before any allocation
  fails("gzip_huge", g, gzipped(raw), {"gzip data, too few", "100000 x 100000"});
  g.encoding = "ascii";
  fails("ascii_huge", g, "2 3 4\n", {"ASCII data, too few", "100000 x 100000"});
  g = f;
  g.encoding = "ascii";
  fails("ascii_short", g, "2 3 4" + std::string(60, ' ') + "\n", {"3 ASCII values", "need 45"});
  g.type = kTypes[0];  // uint8
  std::string text = encoded(g, labels);
  text.replace(0, 1, "300");
  fails("ascii_range", g, text, {"'300'", "8-bit"});
  g = f;
  g.extra_fields = "kinds: RGB-color domain\n";
  fails("colour_axis", g, raw, {"'kinds'", "RGB-color"});
  g = f;
  g.n = {5, 0, 1};
  fails("zero_size", g, raw, {"'sizes'", "'0'"});
  for (const auto& [stem, header, part] :
       {std::tuple<std::string, std::string, std::string>{"no_endian", "NRRD0004\ntype: int16\ndimension: 2\nsizes: 5 9\nencoding: raw\n\n", "'endian'"},
        {"sizes_count", "NRRD0004\ntype: int16\ndimension: 3\nsizes: 5 9\nencoding: raw\nendian: little\n\n", "'sizes'"},
        {"no_blank_line", "NRRD0004\ntype: int16\ndimension: 2\nsizes: 5 9\nencoding: raw\nendian: little\n", "blank line"},
        {"bad_magic", "NRRDX\ntype: int16\ndimension: 2\nsizes: 5 9\nencoding: raw\nendian: little\n\n", "magic"},
        {"bad_spacing", "NRRD0004\ntype: int16\ndimension: 2\nsizes: 5 9\nspacings: 1 x\nencoding: raw\nendian: little\n\n", "'spacings'"}}) {
    const std::string path = dir.file(stem + ".nrrd");
    std::ofstream(path, std::ios::binary) << header << (stem == "no_blank_line" ? "" : raw);
    INFO(stem);
    CHECK_THROWS_WITH(readLabelImage(path), Contains(path) && Contains(part));
  }
  g = f;
  g.detached = true;
  const std::string detached = writeNrrd(dir, "missing_data", g, raw);
  std::filesystem::remove(dir.file("missing_data.data"));
  CHECK_THROWS_WITH(readLabelImage(detached), Contains(detached) && Contains("missing_data.data"));
}
