// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// checkOutputFile: an output path is checked before any work, with a message
// naming the flag, the path and what is wrong with it.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "tessella/io/output_file.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using tessella::io::checkOutputFile;
using tessella::io::testing::TempDir;
using Catch::Contains;

TEST_CASE("an output file in a writable directory passes, existing or not", "[io][output]") {
  TempDir dir;
  const std::string fresh = (dir.path() / "mesh.vtu").string();
  CHECK_NOTHROW(checkOutputFile(fresh, "--out"));
  std::ofstream(fresh) << "old";
  CHECK_NOTHROW(checkOutputFile(fresh, "--out"));  // replacing a file is fine
  CHECK(std::filesystem::file_size(fresh) == 3);   // and checking touches nothing
}

TEST_CASE("an output file that cannot be written is an InputError naming flag, path and reason", "[io][output]") {
  TempDir dir;
  CHECK_THROWS_WITH(checkOutputFile("", "--out"), Contains("--out: the output file name is empty"));
  CHECK_THROWS_AS(checkOutputFile(dir.path().string(), "--out"), InputError);
  CHECK_THROWS_WITH(checkOutputFile(dir.path().string(), "--out"), Contains(": is a directory"));
  const std::string missing = (dir.path() / "no_dir" / "w.vtu").string();
  CHECK_THROWS_WITH(checkOutputFile(missing, "--walls"),
                    Contains("--walls " + missing + ": the directory " + (dir.path() / "no_dir").string() +
                             " does not exist"));
  const std::string file = (dir.path() / "plain").string();
  std::ofstream(file) << "x";
  CHECK_THROWS_WITH(checkOutputFile(file + "/m.vtu", "--out"), Contains(" is not a directory"));
  if (::geteuid() != 0) {  // root writes anywhere
    const auto locked = dir.path() / "locked";
    std::filesystem::create_directory(locked);
    std::filesystem::permissions(locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    CHECK_THROWS_WITH(checkOutputFile((locked / "m.vtu").string(), "--out"), Contains("cannot write into"));
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  }
}
