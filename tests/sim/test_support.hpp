// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shared helpers of the sim tests: scratch directories and error capture.

#include <catch2/catch.hpp>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <string>

#include "tessella/sim/config/config_error.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/tissue/validate.hpp"

namespace tessella::sim::test {

/// After every step of `sim`: the tissue validates and no two cells share a
/// lineage id.
inline void validateEveryStep(Simulation& sim) {
  sim.onStep([](const Simulation& s) {
    const ValidationReport v = validate(s.tissue());
    INFO("t = " << s.time() << ": " << v.message);
    REQUIRE(v.ok);
    std::set<std::int64_t> ids;
    for (CellId c : s.tissue().cells()) ids.insert(s.tissue().lineageId(c));
    REQUIRE(ids.size() == s.tissue().numCells());
  });
}

/// A fresh directory under the system temp dir, removed at scope exit.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("tessella_sim_test_" + std::to_string(rd()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to a file in the directory; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = *this / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

/// The ConfigError `f` throws (the test fails if it throws nothing or something else).
inline ConfigError configErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e;
  }
  FAIL("expected a ConfigError");
  throw std::logic_error("unreachable");
}

inline std::string sourcePath(const std::string& relative) {
  return std::string(TESSELLA_SOURCE_DIR) + "/" + relative;
}

}  // namespace tessella::sim::test
