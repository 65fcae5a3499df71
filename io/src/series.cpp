// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/series.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tessella/io/pvd.hpp"
#include "tessella/io/wall_vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "series_naming.hpp"

namespace tessella::io {

SeriesWriter::SeriesWriter(std::string directory, std::string name, VtuOptions options)
    : directory_(std::move(directory)), name_(std::move(name)), options_(options) {
  detail::checkSeriesName(name_);
  detail::createSeriesDirectory(directory_);
  pvd_path_ = (std::filesystem::path(directory_) / (name_ + ".pvd")).string();
}

std::string SeriesWriter::nextPath() const {
  return (std::filesystem::path(directory_) / detail::stepFileName(name_, entries_.size())).string();
}

std::string SeriesWriter::write(const Tissue& tissue, double time, const RunState& state, GeometryCache* geometry) {
  detail::checkNextTime(pvd_path_, entries_.empty() ? nullptr : &entries_.back().time, time);
  const std::string file = detail::stepFileName(name_, entries_.size());
  const std::string path = (std::filesystem::path(directory_) / file).string();
  writeTissueVtu(tissue, path, options_, state, geometry);
  entries_.push_back({time, file});
  try {
    writePvd();
  } catch (...) {
    entries_.pop_back();  // the .pvd on disk still lists the earlier steps only
    throw;
  }
  for (Beside& b : beside_) {
    const std::filesystem::path beside(besideSnapshotPath(path, b.tag));
    std::error_code ec;
    if (!std::filesystem::exists(beside, ec)) continue;
    b.entries.push_back({time, beside.filename().string()});
    writePvdFile(besidePvdPath(b.tag), b.entries, options_.durable);
  }
  return path;
}

void SeriesWriter::setBesideSeries(std::vector<std::string> tags) {
  beside_.clear();
  for (std::string& tag : tags) {
    if (tag.empty() || tag.find_first_of("/\\.") != std::string::npos)
      throw InputError("series '" + name_ + "': the tag '" + tag + "' of files beside its snapshots must be a "
                       "non-empty name without '.' or a path separator");
    beside_.push_back({std::move(tag), {}});
  }
}

std::string SeriesWriter::besidePvdPath(const std::string& tag) const {
  return (std::filesystem::path(directory_) / (name_ + "." + tag + ".pvd")).string();
}

void SeriesWriter::continueAfter(double last_time) {
  entries_.clear();
  for (PvdEntry& e : detail::truncateSeries(pvd_path_, name_, last_time, options_.durable))
    entries_.push_back({e.time, std::move(e.file)});
  // Each beside series keeps the entries of the snapshots kept whose files are there.
  namespace fs = std::filesystem;
  for (Beside& b : beside_) {
    b.entries.clear();
    const std::string pvd = besidePvdPath(b.tag);
    std::error_code ec;
    if (!fs::exists(pvd, ec)) continue;
    const std::vector<PvdEntry> listed = readPvdFile(pvd);
    for (const PvdEntry& e : listed)
      if (e.time <= last_time && fs::exists(fs::path(directory_) / e.file, ec)) b.entries.push_back(e);
    if (b.entries.size() != listed.size()) writePvdFile(pvd, b.entries, options_.durable);
  }
}

void SeriesWriter::writePvd() const {
  std::vector<PvdEntry> list;
  list.reserve(entries_.size());
  for (const Entry& e : entries_) list.push_back({e.time, e.file});
  writePvdFile(pvd_path_, list, options_.durable);
}

}  // namespace tessella::io
