// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// StatisticsOutput: DIR/stats.csv, a summary row for every snapshot of the
// tissue series (the initial state, every `output.every` steps, the final
// state): time, cells, divisions since the previous row, total / mean /
// min / max / standard deviation of cell area (2D) or volume (3D), and for
// every solver field (diffusion species, compartment field) its total
// amount and the range of its cell values. Each row is appended and
// flushed as it is made, so an interrupted run keeps the rows it reached.

#include <cstddef>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessella/sim/sections/output_section.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"

namespace tessella::sim {

/// File name of the statistics inside the output directory.
inline constexpr const char* kStatisticsName = "stats.csv";

class StatisticsOutput {
 public:
  /// Creates (truncates) `path` and writes the header. `fields` are the
  /// solver fields: cell properties holding a concentration, each with an
  /// amount column `<name>_amount` where the solver keeps one.
  /// With `resume_after` (a resumed run), the file is continued instead:
  /// its header must be this run's, its rows up to that time stay and later
  /// ones go (InputError naming the file otherwise).
  StatisticsOutput(std::string path, int dim, std::vector<std::string> fields, std::size_t every,
                   std::optional<double> resume_after = std::nullopt);

  /// Appends a row if due at the simulation's step (as SeriesOutput does).
  void writeIfDue(const Simulation& simulation);
  /// Appends a row for the current state now (once per step).
  void write(const Simulation& simulation);
  std::size_t rows() const { return rows_; }
  const std::string& path() const { return path_; }

 private:
  void append(const std::string& line);

  std::string path_;
  std::vector<std::string> fields_;
  std::size_t every_;
  std::ofstream file_;
  std::size_t rows_ = 0;
  std::size_t last_step_ = static_cast<std::size_t>(-1);
  std::size_t divisions_before_ = 0;
};

/// The solver fields of a config: diffusion species and the compartment field.
std::vector<std::string> solverFields(const SimulationConfig& config);

/// Writes the current state's row now and registers a step callback that
/// keeps the statistics up to date. The callback owns the returned output.
/// `resume_after` as for attachSeriesOutput: the rows up to that time stay,
/// and the current state's row, already there, is not written again.
std::shared_ptr<StatisticsOutput> attachStatisticsOutput(Simulation& simulation, const std::string& directory,
                                                         std::vector<std::string> fields, std::size_t every,
                                                         std::optional<double> resume_after = std::nullopt);

/// The times of the rows of a stats.csv (its first column), in file order;
/// InputError naming the file and line for a row that does not start with a number.
std::vector<double> statisticsRowTimes(const std::string& path);

}  // namespace tessella::sim
