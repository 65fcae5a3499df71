// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/series_output.hpp"

#include <algorithm>

namespace tessella::sim {

SeriesOutput::SeriesOutput(const std::string& directory, const OutputSpec& spec)
    : writer_(directory, spec.name, spec.vtu), every_(spec.every) {}

void SeriesOutput::writeIfDue(const Simulation& simulation) {
  if (simulation.clockStep() % every_ == 0 || simulation.finished()) write(simulation);
}

void SeriesOutput::write(const Simulation& simulation) {
  if (simulation.stepsDone() == last_written_step_) return;
  // The stages' files beside the snapshot first: a complete snapshot has them.
  const io::RunState state = simulation.snapshotState(writer_.nextPath(), writer_.options());
  writer_.write(simulation.tissue(), simulation.time(), state, &simulation.geometry());
  last_written_step_ = simulation.stepsDone();
}

void SeriesOutput::listBesideFiles(const Simulation& simulation) {
  std::vector<std::string> tags;
  for (std::size_t i = 0; i < simulation.numStages(); ++i)
    for (const std::string& tag : simulation.stage(i).besideFileTags())
      if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
  writer_.setBesideSeries(std::move(tags));
}

void SeriesOutput::continueAfter(const Simulation& simulation, double time) {
  writer_.continueAfter(time);
  last_written_step_ = simulation.stepsDone();
}

std::shared_ptr<SeriesOutput> attachSeriesOutput(Simulation& simulation, const std::string& directory,
                                                 const OutputSpec& spec, std::optional<double> resume_after) {
  auto output = std::make_shared<SeriesOutput>(directory, spec);
  output->listBesideFiles(simulation);
  if (resume_after)
    output->continueAfter(simulation, *resume_after);
  else
    output->write(simulation);
  simulation.onStep([output](const Simulation& s) { output->writeIfDue(s); });
  return output;
}

std::size_t expectedSnapshots(std::size_t steps, std::size_t every) {
  // step 0, every multiple of `every` up to steps, and the last step if it is not one.
  return 1 + steps / every + (steps % every != 0 ? 1 : 0);
}

}  // namespace tessella::sim
