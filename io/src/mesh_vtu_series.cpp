// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/mesh_vtu.hpp"

#include <filesystem>

#include "series_naming.hpp"
#include "tessella/io/pvd.hpp"

namespace tessella::io {

MeshSeriesWriter::MeshSeriesWriter(std::string directory, std::string name, VtuOptions options)
    : directory_(std::move(directory)), name_(std::move(name)), options_(options) {
  detail::checkSeriesName(name_);
  detail::createSeriesDirectory(directory_);
  pvd_path_ = (std::filesystem::path(directory_) / (name_ + ".pvd")).string();
  walls_pvd_path_ = (std::filesystem::path(directory_) / (name_ + "_walls.pvd")).string();
}

std::string MeshSeriesWriter::write(const mesh::FeMesh& mesh, double time, const MeshFields& fields) {
  detail::checkNextTime(pvd_path_, times_.empty() ? nullptr : &times_.back(), time);
  const std::size_t step = times_.size();
  const std::string file = detail::stepFileName(name_, step);
  const std::string walls_file = detail::stepFileName(name_ + "_walls", step);
  const std::filesystem::path dir(directory_);
  writeFeMeshVtu(mesh, (dir / file).string(), fields, options_);
  writeWallFacetsVtu(mesh, (dir / walls_file).string(), fields, options_);

  std::vector<PvdEntry> entries, wall_entries;
  for (std::size_t s = 0; s <= step; ++s) {
    const double t = s < step ? times_[s] : time;
    entries.push_back({t, detail::stepFileName(name_, s)});
    wall_entries.push_back({t, detail::stepFileName(name_ + "_walls", s)});
  }
  // Walls first: if the second rename fails, the main series still lists
  // only complete steps.
  writePvdFile(walls_pvd_path_, wall_entries, options_.durable);
  writePvdFile(pvd_path_, entries, options_.durable);
  times_.push_back(time);
  return (dir / file).string();
}

void MeshSeriesWriter::continueAfter(double last_time) {
  detail::truncateSeries(walls_pvd_path_, name_ + "_walls", last_time, options_.durable);
  times_.clear();
  for (const PvdEntry& e : detail::truncateSeries(pvd_path_, name_, last_time, options_.durable))
    times_.push_back(e.time);
}

}  // namespace tessella::io
