// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/statistics_output.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

#include "tessella/sim/stages/growth_stages.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::sim {

namespace {

// Every value reads back exactly; empty for "no value".
std::string cell(double x) { return std::isnan(x) ? std::string() : formatNumber(x); }

struct Summary {
  double total = 0, mean = std::numeric_limits<double>::quiet_NaN(), min = mean, max = mean, std = mean;
};

Summary summarise(const std::vector<double>& values) {
  Summary s;
  if (values.empty()) return s;
  for (double v : values) s.total += v;
  s.mean = s.total / static_cast<double>(values.size());
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / static_cast<double>(values.size()));
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  return s;
}

std::size_t divisionsSoFar(const Simulation& simulation) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < simulation.numStages(); ++i)
    if (const auto* division = dynamic_cast<const DivisionStage*>(&simulation.stage(i))) n += division->divisions();
  return n;
}

}  // namespace

StatisticsOutput::StatisticsOutput(std::string path, int dim, std::vector<std::string> fields, std::size_t every,
                                   std::optional<double> resume_after)
    : path_(std::move(path)), fields_(std::move(fields)), every_(std::max<std::size_t>(every, 1)) {
  const std::string m = dim == 2 ? "area" : "volume";
  std::string header = "time,cells,divisions," + m + "_total," + m + "_mean," + m + "_min," + m + "_max," + m + "_std";
  for (const std::string& f : fields_) header += "," + f + "_total," + f + "_min," + f + "_max";
  std::vector<std::string> lines{header};
  if (resume_after) {
    // The rows the interrupted run wrote up to its snapshot; later ones go.
    std::ifstream in(path_);
    if (!in) throw InputError("cannot read '" + path_ + "': " + std::strerror(errno));
    std::string line;
    std::getline(in, line);
    if (line != header)
      throw InputError("'" + path_ + "' has the header '" + line.substr(0, 80) + "', not this run's '" +
                       header.substr(0, 80) + "'");
    const std::vector<double> times = statisticsRowTimes(path_);
    for (std::size_t row = 0; row < times.size() && std::getline(in, line); ++row)
      if (times[row] <= *resume_after) lines.push_back(line);
    rows_ = lines.size() - 1;
  }
  file_.open(path_, std::ios::out | std::ios::trunc);
  if (!file_) throw InputError("cannot write '" + path_ + "': " + std::strerror(errno));
  for (const std::string& line : lines) append(line);
}

void StatisticsOutput::append(const std::string& line) {
  errno = 0;
  file_ << line << '\n';
  file_.flush();
  if (!file_)
    throw InputError("cannot write '" + path_ + "': " + (errno ? std::strerror(errno) : "the write failed"));
}

void StatisticsOutput::writeIfDue(const Simulation& simulation) {
  if (simulation.clockStep() % every_ == 0 || simulation.finished()) write(simulation);
}

void StatisticsOutput::write(const Simulation& simulation) {
  if (simulation.stepsDone() == last_step_) return;
  const Tissue& t = simulation.tissue();
  const GeometryCache& geometry = simulation.geometry().require(t, kCellMeasures);
  std::vector<double> measures;
  measures.reserve(t.numCells());
  for (CellId c : t.cells()) measures.push_back(geometry.cellMeasure(t, c));
  const Summary m = summarise(measures);
  const std::size_t divisions = divisionsSoFar(simulation);
  std::string line = cell(simulation.time()) + "," + std::to_string(t.numCells()) + "," +
                     std::to_string(divisions - divisions_before_) + "," + cell(m.total) + "," + cell(m.mean) + "," +
                     cell(m.min) + "," + cell(m.max) + "," + cell(m.std);
  const PropertyStore& properties = t.cellProperties();
  for (const std::string& f : fields_) {
    const PropertyColumnBase* values = properties.find(f);
    if (!values || values->type() != typeid(double)) {
      line += ",,,";  // not solved yet (a steady field before its first solve)
      continue;
    }
    const auto& concentration = properties.get<double>(f);
    const PropertyColumnBase* amount = properties.find(f + "_amount");
    double total = 0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::size_t i = 0;
    for (CellId c : t.cells()) {
      const double v = concentration[c];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      total += amount && amount->type() == typeid(double) ? properties.get<double>(f + "_amount")[c]
                                                           : v * measures[i];
      ++i;
    }
    if (t.numCells() == 0) lo = hi = std::numeric_limits<double>::quiet_NaN();
    line += "," + cell(total) + "," + cell(lo) + "," + cell(hi);
  }
  append(line);
  divisions_before_ = divisions;
  last_step_ = simulation.stepsDone();
  ++rows_;
}

std::vector<std::string> solverFields(const SimulationConfig& config) {
  std::vector<std::string> fields;
  for (const SpeciesSpec& species : config.diffusion.species) fields.push_back(species.name);
  if (!config.compartments.field.empty()) fields.push_back(config.compartments.field);
  return fields;
}

std::vector<double> statisticsRowTimes(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  std::vector<double> times;
  std::string line;
  std::getline(in, line);  // the header
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    const std::string first = line.substr(0, line.find(','));
    char* end = nullptr;
    const double time = std::strtod(first.c_str(), &end);
    if (first.empty() || *end != '\0')
      throw InputError("'" + path + "' line " + std::to_string(number) + ": '" + first.substr(0, 40) +
                       "' is not a time");
    times.push_back(time);
  }
  return times;
}

std::shared_ptr<StatisticsOutput> attachStatisticsOutput(Simulation& simulation, const std::string& directory,
                                                         std::vector<std::string> fields, std::size_t every,
                                                         std::optional<double> resume_after) {
  auto output = std::make_shared<StatisticsOutput>((std::filesystem::path(directory) / kStatisticsName).string(),
                                                   simulation.tissue().dim(), std::move(fields), every, resume_after);
  if (!resume_after) output->write(simulation);
  simulation.onStep([output](const Simulation& s) { output->writeIfDue(s); });
  return output;
}

}  // namespace tessella::sim
