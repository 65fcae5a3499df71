// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "series_naming.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io::detail {

void checkSeriesName(const std::string& name) {
  if (name.empty()) throw InputError("series name must not be empty");
  if (name.find_first_of("/\\") != std::string::npos || name == "." || name == "..")
    throw InputError("series name '" + name + "' must not contain a path separator");
}

void createSeriesDirectory(const std::string& directory) {
  if (directory.empty()) throw InputError("series directory must not be empty");
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec || !std::filesystem::is_directory(directory))
    throw InputError("cannot create the output directory '" + directory + "'" + (ec ? ": " + ec.message() : std::string()));
}

std::string stepFileName(const std::string& name, std::size_t step) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%06zu", step);
  return name + "_" + digits + ".vtu";
}

void checkNextTime(const std::string& pvd_path, const double* previous, double time) {
  if (!std::isfinite(time))
    throw InputError("'" + pvd_path + "': step time " + formatNumber(time) + " is not finite");
  if (previous && !(time > *previous))
    throw InputError("'" + pvd_path + "': step time " + formatNumber(time) + " is not after the previous step's time " +
                     formatNumber(*previous) + " (ParaView would merge the two steps)");
}

std::vector<PvdEntry> truncateSeries(const std::string& pvd_path, const std::string& name, double last_time,
                                     bool durable) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(pvd_path).parent_path();
  std::error_code ec;
  auto removeFile = [&](const fs::path& file) {
    fs::remove(file, ec);
    if (ec) throw InputError("cannot remove '" + file.string() + "': " + ec.message());
  };
  // Temporaries of this series (<name>_NNNNNN.vtu.tmp-PID-N, <name>.pvd.tmp-PID-N and those of the files and
  // series beside it: <name>_NNNNNN.<tag>.vtu.tmp-PID-N, <name>.<tag>.pvd.tmp-PID-N).
  const std::string step_prefix = name + "_", pvd_prefix = name + ".";
  for (const auto& entry : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    const std::string file = entry.path().filename().string();
    const bool temporary = file.find(".vtu.tmp-") != std::string::npos || file.find(".pvd.tmp-") != std::string::npos;
    if (temporary && (file.rfind(step_prefix, 0) == 0 || file.rfind(pvd_prefix, 0) == 0)) removeFile(entry.path());
  }
  if (!fs::exists(pvd_path, ec)) return {};
  std::vector<PvdEntry> kept;
  std::vector<std::string> dropped_stems;  // "<name>_NNNNNN." of the snapshots dropped
  bool dropped = false;
  for (PvdEntry& entry : readPvdFile(pvd_path)) {
    if (entry.time <= last_time) {
      kept.push_back(std::move(entry));
    } else {
      removeFile(dir / entry.file);
      dropped_stems.push_back(fs::path(entry.file).stem().string() + ".");
      dropped = true;
    }
  }
  // The files written beside the dropped snapshots (<stem>.<tag>.vtu: the solver fields' state,
  // field_state.hpp; walls files, wall_vtu.hpp).
  if (!dropped_stems.empty()) {
    std::vector<fs::path> beside;
    for (const auto& entry : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
      const std::string file = entry.path().filename().string();
      if (file.size() < 4 || file.compare(file.size() - 4, 4, ".vtu") != 0) continue;
      for (const std::string& stem : dropped_stems)
        if (file.rfind(stem, 0) == 0) beside.push_back(entry.path());
    }
    for (const fs::path& file : beside) removeFile(file);
  }
  if (dropped) writePvdFile(pvd_path, kept, durable);
  return kept;
}

}  // namespace tessella::io::detail
