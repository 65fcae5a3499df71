// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Helpers shared by the io tests: a scratch directory that cleans up after
// itself, and a field-by-field comparison of a tissue with its read-back copy.

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::io::testing {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("tessella_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  /// Names of the entries in the directory (to spot stray temporaries).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

/// The i-th live element of a degree: the reader numbers live elements compactly.
template <typename H>
std::vector<H> liveList(LiveRange<H> range) {
  std::vector<H> out;
  for (H h : range) out.push_back(h);
  return out;
}

/// Relative difference, safe at zero.
inline double relDiff(double a, double b) { return std::abs(a - b) / std::max({1.0, std::abs(a), std::abs(b)}); }

/// Checks the read-back tissue `b` against the written `a`: kind, time,
/// counts, positions (bit-exact: Float64 is stored raw), cell measures, and
/// lineage.
inline void requireSameTissue(const Tissue& a, const Tissue& b) {
  REQUIRE(b.dim() == a.dim());
  REQUIRE(b.embedding() == a.embedding());
  REQUIRE(b.time() == a.time());
  REQUIRE(b.numVertices() == a.numVertices());
  REQUIRE(b.numEdges() == a.numEdges());
  REQUIRE(b.numFaces() == a.numFaces());
  REQUIRE(b.numCells() == a.numCells());
  const auto va = liveList(a.vertices());
  for (std::size_t i = 0; i < va.size(); ++i) REQUIRE(b.position(VertexId(static_cast<Index>(i))) == a.position(va[i]));
  const auto ca = liveList(a.cells());
  for (std::size_t i = 0; i < ca.size(); ++i) {
    const CellId cb(static_cast<Index>(i));
    REQUIRE(relDiff(cellMeasure(b, cb), cellMeasure(a, ca[i])) < 1e-12);
    REQUIRE(b.lineageId(cb) == a.lineageId(ca[i]));
    REQUIRE(b.parentId(cb) == a.parentId(ca[i]));
    REQUIRE(b.birthTime(cb) == a.birthTime(ca[i]));
  }
}

/// Values of a column of `b` (compact numbering) equal those of `a` at its live elements.
template <typename T, typename H>
void requireSameColumn(const Tissue& a, const Tissue& b, int degree, const std::string& name, LiveRange<H> live) {
  INFO("property " << name);
  const auto& ca = a.properties(degree).template get<T>(name);
  const auto& cb = b.properties(degree).template get<T>(name);
  // Policies are saved; a custom policy's function is not, so it copies.
  REQUIRE(cb.policy() == (ca.policy() == DivisionPolicy::Custom ? DivisionPolicy::Copy : ca.policy()));
  const auto list = liveList(live);
  REQUIRE(cb.values().size() == list.size());
  for (std::size_t i = 0; i < list.size(); ++i) REQUIRE(cb[static_cast<Index>(i)] == ca[list[i]]);
}

}  // namespace tessella::io::testing
