// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The strict PLY reader: every type, both byte orders, and an error naming
// the file, the line or byte offset and the element for every malformed input.

#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

std::string writeText(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

const std::string kAsciiHeader =
    "ply\nformat ascii 1.0\ncomment test\nelement vertex 2\nproperty float x\nproperty uchar flag\n"
    "property int16 s\nproperty double d\nelement face 2\nproperty list uchar int vertex_indices\n"
    "property uint label\nend_header\n";

std::string errorOf(const std::string& path) {
  try {
    PlyFile::read(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("ply: ASCII with every kind of property reads into columns by name", "[io][ply]") {
  TempDir dir;
  const auto path = writeText(dir, "a.ply", kAsciiHeader + "1.5 255 -3 0.1\n-2 0 7 1e300\n3 0 1 2 4\n4 0 1 1 3 9\n");
  const PlyFile f = PlyFile::read(path);
  CHECK(f.header().format == PlyFormat::Ascii);
  CHECK(f.header().comments == std::vector<std::string>{"test"});
  CHECK(f.count("vertex") == 2);
  CHECK(f.scalar("vertex", "x").values == std::vector<double>{1.5, -2});
  CHECK(f.scalar("vertex", "flag").values == std::vector<double>{255, 0});
  CHECK(f.scalar("vertex", "s").type == PlyType::Int16);
  CHECK(f.scalar("vertex", "d").values[1] == 1e300);
  const PlyColumn& faces = f.list("face", "vertex_indices");
  CHECK(faces.offsets == std::vector<std::size_t>{0, 3, 7});
  CHECK(faces.values == std::vector<double>{0, 1, 2, 0, 1, 1, 3});
  CHECK(f.integerScalar("face", "label").values == std::vector<double>{4, 9});
  CHECK_THROWS_WITH(f.scalar("face", "vertex_indices"), Contains("is a list"));
  CHECK_THROWS_WITH(f.integerScalar("vertex", "x"), Contains("expected an integer type"));
  CHECK_THROWS_WITH(f.column("vertex", "nope"), Contains("has no property 'nope'"));
  CHECK_THROWS_WITH(f.column("edge", "source"), Contains("has no element 'edge'"));
}

TEST_CASE("ply: binary little and big endian read the same values as ASCII", "[io][ply]") {
  TempDir dir;
  for (const std::string order : {"binary_little_endian", "binary_big_endian"}) {
    const bool big = order == "binary_big_endian";
    std::string bytes = "ply\nformat " + order +
                        " 1.0\nelement vertex 2\nproperty float32 x\nproperty int8 c\nproperty uint16 u\n"
                        "property float64 d\nelement face 1\nproperty list uint8 uint32 vertex_indices\nend_header\n";
    auto put = [&](const void* p, std::size_t n) {
      std::string b(static_cast<const char*>(p), n);
      if (big) std::reverse(b.begin(), b.end());
      bytes += b;
    };
    for (int i = 0; i < 2; ++i) {
      const float x = 1.25f * float(i + 1);
      const std::int8_t c = static_cast<std::int8_t>(-5 * (i + 1));
      const std::uint16_t u = static_cast<std::uint16_t>(60000 + i);
      const double d = 0.1 * (i + 1);
      put(&x, 4), put(&c, 1), put(&u, 2), put(&d, 8);
    }
    const std::uint8_t n = 3;
    put(&n, 1);
    for (std::uint32_t v : {0u, 1u, 4000000000u}) put(&v, 4);
    const PlyFile f = PlyFile::read(writeText(dir, order + ".ply", bytes));
    CHECK(f.scalar("vertex", "x").values == std::vector<double>{1.25, 2.5});
    CHECK(f.scalar("vertex", "c").values == std::vector<double>{-5, -10});
    CHECK(f.scalar("vertex", "u").values == std::vector<double>{60000, 60001});
    CHECK(f.scalar("vertex", "d").values == std::vector<double>{0.1, 0.2});
    CHECK(f.list("face", "vertex_indices").values == std::vector<double>{0, 1, 4000000000.0});
    // Cut the last byte: truncated, with the byte offset and the element.
    const std::string cut = writeText(dir, "cut.ply", bytes.substr(0, bytes.size() - 1));
    CHECK_THROWS_WITH(PlyFile::read(cut), Contains("is truncated at byte offset") &&
                                              Contains("element 'face' 0, property 'vertex_indices'"));
    const std::string extra = writeText(dir, "extra.ply", bytes + "xy");
    CHECK_THROWS_WITH(PlyFile::read(extra), Contains("2 bytes of data after the last element"));
  }
}

TEST_CASE("ply: a binary count that the file cannot hold fails before allocating", "[io][ply]") {
  TempDir dir;
  const auto path = writeText(dir, "huge.ply",
                              "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                              "property double x\nend_header\n12345678");
  CHECK_THROWS_WITH(PlyFile::read(path), Contains("declares 1000000000000 entries") && Contains("only 8 remain"));
}

TEST_CASE("ply: malformed headers name the line and what is wrong", "[io][ply]") {
  TempDir dir;
  CHECK_THROWS_WITH(PlyFile::read(dir.file("missing.ply")), Contains("no such file"));
  CHECK_THROWS_WITH(PlyFile::read(writeText(dir, "a.ply", "PLY\nformat ascii 1.0\nend_header\n")),
                    Contains("is not a PLY file: its first line is 'PLY'"));
  CHECK_THROWS_WITH(PlyFile::read(writeText(dir, "b.ply", "ply\nformat ascii 2.0\nend_header\n")),
                    Contains("line 2: unsupported PLY version '2.0'"));
  CHECK_THROWS_WITH(
      PlyFile::read(writeText(dir, "c.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\nend_header\n1\n")),
      Contains("line 4: unknown type 'flot'"));
  CHECK_THROWS_WITH(PlyFile::read(writeText(dir, "d.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n")),
                    Contains("line 3: element 'vertex': count '-3' is not a non-negative integer"));
  CHECK_THROWS_WITH(PlyFile::read(writeText(dir, "e.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n")),
                    Contains("no end_header line"));
  CHECK_THROWS_WITH(
      PlyFile::read(writeText(dir, "f.ply",
                              "ply\nformat ascii 1.0\nelement v 1\nproperty list float int i\nend_header\n1 2\n")),
      Contains("line 4: list length type 'float' is not an integer type"));
  CHECK_THROWS_WITH(
      PlyFile::read(writeText(dir, "g.ply",
                              "ply\nformat ascii 1.0\nelement v 1\nproperty int a\nproperty int a\nend_header\n1 2\n")),
      Contains("line 5: element 'v' declares property 'a' twice"));
  CHECK_THROWS_WITH(PlyFile::read(writeText(dir, "h.ply", "ply\nformat ascii 1.0\nbogus\nend_header\n")),
                    Contains("line 3: unknown header keyword 'bogus'"));
}

TEST_CASE("ply: malformed ASCII data names the line, the element and the token", "[io][ply]") {
  TempDir dir;
  // Header lines 1..12; the data start at line 13.
  CHECK_THAT(errorOf(writeText(dir, "a.ply", kAsciiHeader + "1 2 3 4\n")),
             Contains("is truncated: it ends at line 13 after 1 of the 2 'vertex' elements"));
  CHECK_THAT(errorOf(writeText(dir, "b.ply", kAsciiHeader + "1 2 3 4\n1 2 x3 4\n")),
             Contains("line 14: element 'vertex' 1, property 's': 'x3' is not an integer (short)"));
  CHECK_THAT(errorOf(writeText(dir, "c.ply", kAsciiHeader + "1 256 3 4\n")),
             Contains("line 13: element 'vertex' 0, property 'flag': '256' is out of the range of uchar (0 .. 255)"));
  CHECK_THAT(errorOf(writeText(dir, "d.ply", kAsciiHeader + "1 2 3\n")),
             Contains("line 13: element 'vertex' 0 has only 3 values: property 'd' is missing"));
  CHECK_THAT(errorOf(writeText(dir, "e.ply", kAsciiHeader + "1 2 3 4 5\n")),
             Contains("line 13: element 'vertex' 0 has 5 values, 1 more than its properties take (next: '5')"));
  CHECK_THAT(errorOf(writeText(dir, "f.ply", kAsciiHeader + "1 2 3 4\n1 2 3 4\n5 0 1 2 7\n")),
             Contains("line 15: element 'face' 0, property 'vertex_indices': the list length is 5 but only 4 "
                      "values follow"));
  CHECK_THAT(errorOf(writeText(dir, "g.ply", kAsciiHeader + "1 2 3 4\n1 2 3 4\n3 0 1 2 7\n3 0 1 2 7\nextra\n")),
             Contains("line 17: data after the last element: 'extra'"));
  CHECK_THAT(errorOf(writeText(dir, "h.ply", kAsciiHeader + "1 2 3 4\n1 2 3 4\n3 0 1 2 7\n3 0 1 2 -7\n")),
             Contains("line 16: element 'face' 1, property 'label': '-7' is out of the range of uint"));
  // A hostile token is cut and escaped.
  const std::string junk = "\x01\x02" + std::string(100, 'z');
  CHECK_THAT(errorOf(writeText(dir, "i.ply", kAsciiHeader + "1 2 3 " + junk + "\n")),
             Contains("'\\x01\\x02zzzz") && Contains("zzz...' is not a number (double)"));
}

TEST_CASE("ply: quotedToken cuts and escapes", "[io][ply]") {
  CHECK(quotedToken("abc") == "'abc'");
  CHECK(quotedToken(std::string("a\0b\n", 4)) == "'a\\x00b\\x0a'");
  CHECK(quotedToken(std::string(61, 'q')) == "'" + std::string(60, 'q') + "...'");
}
