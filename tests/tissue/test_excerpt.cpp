// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/excerpt.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;

TEST_CASE("excerpt cuts long text and escapes bytes that are not printable", "[excerpt]") {
  CHECK(excerpt("0.5, 0.25") == "0.5, 0.25");
  CHECK(excerpt(std::string("a\0b\tc\x7f\xc3\xa9", 8)) == "a\\x00b\\x09c\\x7F\\xC3\\xA9");
  CHECK(excerpt(std::string(100, 'x')) == std::string(80, 'x') + "... (20 more bytes)");
  CHECK(excerpt(std::string(80, 'x')) == std::string(80, 'x'));
  CHECK(excerpt("abcdef", 3) == "abc... (3 more bytes)");
  CHECK(excerpt("") == "");
}

TEST_CASE("a seed file's huge binary line is quoted as a short escaped excerpt", "[seeds][csv][errors][excerpt]") {
  const auto path = (std::filesystem::temp_directory_path() / "tessella_test_excerpt_seeds.csv").string();
  const std::string blob(2'000'000, '\x01');
  for (const std::string& line : {"3,4," + blob, "3," + blob}) {  // too many fields; a field that is no number
    std::ofstream(path, std::ios::binary) << "x,y\n1,2\n" << line << "\n";
    try {
      readSeedsCsv(path, 2);
      FAIL("no error");
    } catch (const InputError& e) {
      const std::string what = e.what();
      INFO(what.substr(0, 400));
      CHECK(what.size() < 500);
      CHECK_THAT(what, Catch::Contains(path + ":3") && Catch::Contains("\\x01\\x01") && Catch::Contains("more bytes)"));
      CHECK(what.find('\x01') == std::string::npos);
    }
  }
  std::filesystem::remove(path);
}
