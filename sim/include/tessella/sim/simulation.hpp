// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Simulation: a tissue, a time span and the stages applied at every step.
//
//   auto sim = Simulation::fromFile("configs/hex_grid_2d.yaml");
//   sim.onStep([](const Simulation& s) { ... });   // after every step
//   sim.runUntil(5.0);                               // or step(), or run()
//
// or from code, with your own tissue and stages:
//
//   Simulation sim(hexagonalGrid(10, 10), {.time = {0, 20, 0.5}, .rng_seed = 42});
//   sim.addStage(std::make_unique<MyGrowth>(...));
//
// One step: every stage in order over [t, t + dt], then the clock advances
// (the tissue's time too), then the step callbacks run. The Simulation does
// not write files; attach a SeriesOutput (series_output.hpp) for that.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/stages/stage.hpp"
#include "tessella/sim/time_span.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim {

/// A validated config read into its sections (sections/simulation_config.hpp).
struct SimulationConfig;

/// A stage failed: names the stage, the step and the time, then the cause.
class SimulationError : public Error {
 public:
  using Error::Error;
};

struct SimulationOptions {
  TimeSpan time;
  std::uint64_t rng_seed = 0;
  /// The stage stream's saved state (runState()["rng.stream"]) to continue
  /// instead of starting the stream of rng_seed; empty for a fresh run.
  std::string rng_state;
  /// Entries every snapshot of the run carries unchanged (the dome a curved
  /// sheet lives on, so that a restart keeps it on that surface).
  io::RunState carried;
};

class Simulation {
 public:
  using StepCallback = std::function<void(const Simulation&)>;

  /// From code: the tissue's clock is set to time.start.
  Simulation(Tissue tissue, SimulationOptions options);

  /// From a validated config: builds the tissue its generator describes and
  /// the stages its sections ask for (makeStages). Defined with the config
  /// (run/build_simulation.cpp): include sections/simulation_config.hpp to
  /// call fromConfig. Throws ConfigError.
  static Simulation fromConfig(const SimulationConfig& config);
  static Simulation fromFile(const std::string& path, const std::vector<std::string>& overrides = {});
  static Simulation fromYaml(const std::string& yaml, const std::vector<std::string>& overrides = {},
                             const std::string& base_directory = ".");

  Simulation(Simulation&&) noexcept = default;
  Simulation& operator=(Simulation&&) noexcept = default;

  // --- state ------------------------------------------------------------------
  const Tissue& tissue() const { return tissue_; }
  /// Mutable access for models that edit the tissue between steps.
  Tissue& tissue() { return tissue_; }
  const SimulationOptions& options() const { return options_; }
  double time() const { return options_.time.timeAt(step_); }
  /// Steps taken so far.
  std::size_t stepsDone() const { return step_; }
  std::size_t numSteps() const { return options_.time.numSteps(); }
  /// Steps taken on the run's clock: stepsDone() plus the steps before the
  /// snapshot a restart continues from. Output schedules count these, so a
  /// resumed run writes at the steps the uninterrupted run writes at.
  std::size_t clockStep() const { return options_.time.origin_steps + step_; }
  bool finished() const { return step_ >= numSteps(); }
  std::mt19937_64& rng() { return rng_; }
  /// The tissue's geometry shared by the stages (StepContext::geometry) and
  /// the outputs: `sim.geometry().require(sim.tissue(), kCellMeasures)`.
  /// A cache of quantities that depend on the tissue only, so it can be
  /// filled through a const Simulation (an output's step callback).
  GeometryCache& geometry() const { return geometry_; }
  /// What a restart needs besides the tissue to continue this run exactly:
  /// the clock (clock.start, clock.dt, clock.step) and the random stream
  /// (rng_seed, rng.stream), with the options' carried entries. Written
  /// into every snapshot by SeriesOutput;
  /// continueRunState() reads it back.
  io::RunState runState() const;
  /// runState() with what every stage keeps besides the tissue
  /// (Stage::saveState: the diffusion stage's mesh and nodal fields, written
  /// now to files beside `snapshot_path`): the state to write with a
  /// snapshot at that path.
  io::RunState snapshotState(const std::string& snapshot_path, const io::VtuOptions& options = {}) const;
  /// Writes a snapshot a restart continues exactly: the stages' files first,
  /// then the tissue with snapshotState() (io::writeTissueVtu, atomically).
  void writeSnapshot(const std::string& path, const io::VtuOptions& options = {}) const;

  // --- composition ------------------------------------------------------------
  void addStage(std::unique_ptr<Stage> stage);
  std::size_t numStages() const { return stages_.size(); }
  const Stage& stage(std::size_t i) const { return *stages_[i]; }
  /// Called after every step, in registration order.
  void onStep(StepCallback callback);

  // --- advancing --------------------------------------------------------------
  /// Takes one step. Throws std::logic_error when already finished, and
  /// SimulationError (naming stage, step and time) when a stage throws.
  void step();
  /// Steps while time() < t (within a millionth of dt) and not finished;
  /// stops at the end of the time span if t lies beyond it.
  void runUntil(double t);
  /// Steps to the end of the time span.
  void run();

  // --- stopping early ---------------------------------------------------------
  /// A flag that stops run() and runUntil() between steps once it is true: the
  /// step in progress and its callbacks (the output it writes) finish first.
  /// Another thread or a signal handler may set it (storing to a lock-free
  /// atomic is async-signal-safe). The flag must outlive the runs; null: none.
  void setStopFlag(const std::atomic<bool>* flag) { stop_ = flag; }
  /// The stop flag is set (run() and runUntil() return without finishing).
  bool stopRequested() const { return stop_ && stop_->load(); }

 private:
  Tissue tissue_;
  SimulationOptions options_;
  std::mt19937_64 rng_;
  mutable GeometryCache geometry_;
  std::size_t step_ = 0;
  std::vector<std::unique_ptr<Stage>> stages_;
  std::vector<StepCallback> callbacks_;
  const std::atomic<bool>* stop_ = nullptr;
};

/// For a run restarted from a snapshot written with `state` (Simulation::
/// runState()): when `time` starts at the snapshot's time with the saved dt,
/// continues the saved clock (time.origin, time.origin_steps), so every later
/// step time is the uninterrupted run's, bit for bit; returns the random stream to continue when `seed` is the saved seed
/// (else ""). Changes nothing and returns "" for a state without these keys.
std::string continueRunState(const io::RunState& state, double snapshot_time, std::uint64_t seed, TimeSpan& time);

}  // namespace tessella::sim
