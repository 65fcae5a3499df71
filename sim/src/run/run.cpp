// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/run.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <cstdio>
#include <regex>

#include "tessella/io/pvd.hpp"
#include "tessella/io/vtu.hpp"

#include "tessella/sim/run/field_output.hpp"
#include "tessella/sim/run/primordia_output.hpp"
#include "tessella/sim/run/run_record.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/sim/run/statistics_output.hpp"

namespace fs = std::filesystem;

namespace tessella::sim {

namespace {

/// The files of a previous run of series `name` in `dir` (its snapshots with
/// the solver fields' state and the walls files beside them, the walls files'
/// series, its statistics and primordia tables;
/// with_fields: and the solver-field series), with the temporaries an interrupted write
/// left behind (FILE.tmp-PID-N, run.yaml.tmp of older versions).
std::vector<fs::path> previousRunFiles(const fs::path& dir, const std::string& name, bool with_fields = false) {
  std::vector<fs::path> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return files;
  const std::string tmp = R"((\.tmp-\d+-\d+)?)";
  const std::regex series(std::regex_replace(name, std::regex(R"([.^$|()\[\]{}*+?\\-])"), R"(\$&)") +
                          R"(((\.pin|\.walls)?\.pvd|_\d+(\.fields|\.pin|\.walls)?\.vtu))" + tmp);
  const std::regex fields(std::string(kFieldSeriesName) + R"((_walls)?(\.pvd|_\d+\.vtu))" + tmp);
  const std::regex record(std::regex_replace(kRunRecordName, std::regex(R"(\.)"), R"(\.)") +
                          R"((\.tmp|\.tmp-\d+-\d+)?)");
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string file = entry.path().filename().string();
    if (std::regex_match(file, record) || file == kStatisticsName || file == kPrimordiaName ||
        file == std::string(kPrimordiaName) + ".tmp" || std::regex_match(file, series) ||
        (with_fields && std::regex_match(file, fields)))
      files.push_back(entry.path());
  }
  return files;
}

}  // namespace

PreparedRun::PreparedRun(SimulationConfig config, Simulation simulation, std::string directory, bool overwrite)
    : config_(std::move(config)),
      simulation_(std::move(simulation)),
      directory_(std::move(directory)),
      overwrite_(overwrite) {}

PreparedRun PreparedRun::prepare(SimulationConfig config, const RunOptions& options) {
  // Where the directory comes from decides where an error about it points.
  std::string chosen;
  std::function<ConfigError(const std::string&)> error;
  if (options.output_directory) {
    chosen = *options.output_directory;
    if (chosen.empty())
      throw ConfigError(SourceLocation{"--out ''", 0, 0}, "output.directory",
                        "the output directory is empty; give a directory name (or leave --out out to use "
                        "output.directory, else runs/<config name>)");
    error = [&](const std::string& p) {
      return ConfigError(SourceLocation{"--out " + chosen, 0, 0}, "output.directory", p);
    };
  } else if (!config.output.directory.empty()) {
    chosen = config.output.directory;
    error = [&](const std::string& p) { return config.config.errorAt("output.directory", p); };
  } else {
    chosen = (fs::path("runs") / config.config.name()).string();
    error = [&](const std::string& p) {
      return ConfigError(SourceLocation{config.config.source(), 0, 0}, "output.directory",
                         "(default " + chosen + ") " + p);
    };
  }
  const fs::path dir = fs::absolute(chosen).lexically_normal();
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw error("'" + dir.string() + "' exists and is not a directory");
  if (!options.overwrite) {
    const auto previous = previousRunFiles(dir, config.output.name);
    if (!previous.empty())
      throw error("'" + dir.string() + "' already holds a run (" + previous.front().filename().string() +
                  "); choose another directory or pass --overwrite to replace it");
  }

  Simulation simulation = Simulation::fromConfig(config);  // the tissue, before anything is written
  readMeshSection(config.config);  // its errors too (read again by execute())
  config.output.directory = dir.string();
  config.config.set("output.directory", dir.string(), {}, ValueOrigin::Derived);
  return PreparedRun(std::move(config), std::move(simulation), dir.string(), options.overwrite);
}

PreparedRun PreparedRun::resume(const std::string& run_directory) {
  const fs::path dir = fs::absolute(run_directory).lexically_normal();
  const std::string quoted = "'" + run_directory + "'";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError("cannot resume " + quoted + ": no such directory");
  const fs::path record = dir / kRunRecordName;
  if (!fs::exists(record, ec))
    throw InputError("cannot resume " + quoted + ": it is not a run directory (no " + kRunRecordName +
                     ", which tessella run writes first)");
  const SimulationConfig original = loadSimulationConfigFile(record.string());
  const fs::path pvd = dir / (original.output.name + ".pvd");
  if (!fs::exists(pvd, ec))
    throw InputError("cannot resume " + quoted + ": it has no complete snapshot (no " +
                     pvd.filename().string() + ")");
  const std::vector<io::PvdEntry> entries = io::readPvdFile(pvd.string());
  const fs::path stats = dir / kStatisticsName;
  const bool with_stats = fs::exists(stats, ec);
  const std::vector<double> rows = with_stats ? statisticsRowTimes(stats.string()) : std::vector<double>{};
  // The last snapshot that reads back with its run state and, when the run
  // keeps statistics, has its row: a run killed between the two writes
  // continues from the snapshot before.
  std::string chosen;
  double chosen_time = 0;
  for (auto it = entries.rbegin(); it != entries.rend() && chosen.empty(); ++it) {
    if (with_stats && std::find(rows.begin(), rows.end(), it->time) == rows.end()) continue;
    const std::string file = (dir / it->file).string();
    try {
      const io::Snapshot snapshot = io::readSnapshot(file);
      if (snapshot.state.count("clock.step") && snapshot.tissue.time() == it->time) {
        chosen = file;
        chosen_time = it->time;
      }
    } catch (const InputError&) {
      // damaged or missing: try the one before
    }
  }
  if (chosen.empty())
    throw InputError("cannot resume " + quoted + ": none of the " + std::to_string(entries.size()) +
                     " snapshots listed in " + pvd.filename().string() +
                     " is complete (reads back with its run state" + (with_stats ? " and has its stats.csv row" : "") +
                     ")");
  char start[40];
  std::snprintf(start, sizeof start, "%.17g", chosen_time);
  SimulationConfig config = loadSimulationConfigFile(
      record.string(), {"tissue.generator=snapshot", "tissue.snapshot.file=" + chosen, std::string("time.start=") + start,
                        "output.directory=" + dir.string()});
  Simulation simulation = Simulation::fromConfig(config);
  if (simulation.finished())
    throw InputError("cannot resume " + quoted + ": the run is already finished (its last snapshot, " +
                     fs::path(chosen).filename().string() + ", is at t = " + formatNumber(chosen_time) +
                     ", the end of its time span)");
  readMeshSection(config.config);
  PreparedRun run(std::move(config), std::move(simulation), dir.string(), false);
  run.resume_after_ = chosen_time;
  run.resumed_from_ = chosen;
  return run;
}

std::string PreparedRun::runRecordPath() const { return (fs::path(directory_) / kRunRecordName).string(); }

void PreparedRun::execute() {
  if (output_) throw std::logic_error("PreparedRun::execute: already executed");
  if (simulation_.stopRequested()) return;  // stopped before anything was written
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec) throw InputError("cannot create the output directory " + directory_ + ": " + ec.message());
  if (overwrite_)
    for (const fs::path& file : previousRunFiles(directory_, config_.output.name, true)) {
      fs::remove(file, ec);
      if (ec) throw InputError("cannot remove the previous run's " + file.string() + ": " + ec.message());
    }
  if (overwrite_)
    for (const std::string& series : {MeshSpec{}.name, MeshSpec{}.name + "_walls"})  // a previous mesh.output
      for (const fs::path& file : previousRunFiles(directory_, series)) {
        fs::remove(file, ec);
        if (ec) throw InputError("cannot remove the previous run's " + file.string() + ": " + ec.message());
      }
  if (!resume_after_) writeRunRecord(config_.config, runRecordPath());  // a resumed run keeps its record
  output_ = attachSeriesOutput(simulation_, directory_, config_.output, resume_after_);
  mesh_output_ =
      attachMeshOutput(simulation_, directory_, readMeshSection(config_.config), config_.output, resume_after_);
  field_output_ = attachFieldOutput(simulation_, directory_, config_.output, resume_after_);
  statistics_ =
      attachStatisticsOutput(simulation_, directory_, solverFields(config_), config_.output.every, resume_after_);
  attachPrimordiaOutput(simulation_, directory_);
  simulation_.run();
}

}  // namespace tessella::sim
