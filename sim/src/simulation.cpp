// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/simulation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "config/exact_text.hpp"
#include "tessella/sim/config/config_value.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::sim {

namespace {
// The stage stream is derived from the run's seed rather than equal to it,
// so it does not replay the draws the generator made for seed points.
std::mt19937_64 stageStream(std::uint64_t seed) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), 0x5eedu};
  return std::mt19937_64(seq);
}

std::string number(double x) { return formatValue(x); }
}  // namespace

using detail::parseExact;

io::RunState Simulation::runState() const {
  std::ostringstream stream;
  stream << rng_;
  io::RunState state = options_.carried;
  state["clock.start"] = formatNumber(options_.time.clockOrigin());
  state["clock.dt"] = formatNumber(options_.time.dt);
  state["clock.step"] = std::to_string(options_.time.origin_steps + step_);
  state["rng_seed"] = std::to_string(options_.rng_seed);
  state["rng.stream"] = stream.str();
  return state;
}

io::RunState Simulation::snapshotState(const std::string& snapshot_path, const io::VtuOptions& options) const {
  io::RunState state = runState();
  for (const auto& stage : stages_) stage->saveState(tissue_, snapshot_path, options, state);
  return state;
}

void Simulation::writeSnapshot(const std::string& path, const io::VtuOptions& options) const {
  io::writeTissueVtu(tissue_, path, options, snapshotState(path, options), &geometry_);
}

std::string continueRunState(const io::RunState& state, double snapshot_time, std::uint64_t seed, TimeSpan& time) {
  const auto value = [&](const char* key) -> const std::string* {
    const auto it = state.find(key);
    return it == state.end() ? nullptr : &it->second;
  };
  double start = 0, dt = 0;
  std::size_t step = 0;
  const std::string *s = value("clock.start"), *d = value("clock.dt"), *k = value("clock.step");
  // The original clock, when it is the one the config runs on and it lands
  // on the snapshot's time exactly; otherwise the clock starts afresh there.
  if (time.start == snapshot_time && s && d && k && parseExact(*s, start) && parseExact(*d, dt) &&
      parseExact(*k, step) && step > 0 && dt == time.dt && start + static_cast<double>(step) * dt == snapshot_time) {
    time.origin = start;
    time.origin_steps = step;
  }
  std::uint64_t saved_seed = 0;
  const std::string *saved = value("rng_seed"), *stream = value("rng.stream");
  if (!(saved && stream && parseExact(*saved, saved_seed) && saved_seed == seed)) return {};
  std::istringstream text(*stream);
  std::mt19937_64 check;
  text >> check;
  if (text.fail())
    throw InputError("its run state holds rng.stream = '" + stream->substr(0, 40) +
                     (stream->size() > 40 ? "...'" : "'") + ", which is not a state of the random stream");
  return *stream;
}

Simulation::Simulation(Tissue tissue, SimulationOptions options)
    : tissue_(std::move(tissue)), options_(options), rng_(stageStream(options.rng_seed)) {
  const TimeSpan& t = options_.time;
  if (!std::isfinite(t.start) || !std::isfinite(t.end) || !(t.end >= t.start))
    throw InputError("Simulation: time span [" + number(t.start) + ", " + number(t.end) +
                     "] is not a finite interval with end >= start");
  if (!(t.dt > 0) || !std::isfinite(t.dt)) throw InputError("Simulation: dt must be > 0, got " + number(t.dt));
  if ((t.end - t.start) / t.dt > kMaxSteps)
    throw InputError("Simulation: " + number((t.end - t.start) / t.dt) + " steps is more than the limit of " +
                     number(kMaxSteps));
  if (!options_.rng_state.empty()) {
    std::istringstream saved(options_.rng_state);
    saved >> rng_;
    if (saved.fail()) throw InputError("Simulation: the saved random stream (rng.stream) is not a valid state");
  }
  tissue_.setTime(t.start);
}

void Simulation::addStage(std::unique_ptr<Stage> stage) {
  if (!stage) throw std::invalid_argument("Simulation::addStage: null stage");
  try {
    stage->prepare(tissue_, time());
  } catch (const std::exception& e) {
    throw SimulationError("t = " + number(time()) + ", preparing stage '" + stage->name() + "': " + e.what());
  }
  stages_.push_back(std::move(stage));
}

void Simulation::onStep(StepCallback callback) {
  if (!callback) throw std::invalid_argument("Simulation::onStep: empty callback");
  callbacks_.push_back(std::move(callback));
}

void Simulation::step() {
  if (finished()) throw std::logic_error("Simulation::step: the time span is already over");
  const double t0 = time();
  const double t1 = options_.time.timeAt(step_ + 1);
  const TimeSpan& span = options_.time;
  const StepContext context{.step = step_,
                            .clock_step = clockStep(),
                            .clock_origin = span.clockOrigin(),
                            .clock_dt = span.dt,
                            .time = t0,
                            .dt = t1 - t0,
                            .rng = &rng_,
                            .end_time = t1,
                            .geometry = &geometry_};
  for (auto& stage : stages_) {
    try {
      stage->apply(tissue_, context);
    } catch (const std::exception& e) {
      throw SimulationError("step " + std::to_string(step_ + 1) + " (t = " + number(t0) + "), stage '" +
                            stage->name() + "': " + e.what());
    }
  }
  ++step_;
  tissue_.setTime(t1);
  for (auto& callback : callbacks_) callback(*this);
}

void Simulation::runUntil(double t) {
  const double slack = 1e-6 * options_.time.dt;
  while (!finished() && !stopRequested() && time() < t - slack) step();
}

void Simulation::run() {
  while (!finished() && !stopRequested()) step();
}

}  // namespace tessella::sim
