// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The simulation loop from Python: from a YAML file or string, or from code
// with a tissue and stages (integrators, schedulers, Python functions); step
// callbacks in Python; ParaView series output.
#include <memory>

#include "bindings.hpp"
#include "deferred_error.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/run/series_output.hpp"
#include "tessella/sim/sections/simulation_config.hpp"
#include "tessella/sim/simulation.hpp"
#include "tessella/sim/stages/growth_stages.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::python {

namespace {

using sim::Simulation;
using sim::Stage;
using sim::StepContext;

/// A sim stage after which the error a Python division function deferred
/// (deferred_error.hpp) is raised, so that the Simulation names the stage and
/// the step it happened in.
class RaisingDeferredErrors final : public Stage {
 public:
  explicit RaisingDeferredErrors(std::unique_ptr<Stage> stage) : stage_(std::move(stage)) {}
  std::string name() const override { return stage_->name(); }
  void prepare(Tissue& t, double time) override { stage_->prepare(t, time); }
  void apply(Tissue& t, const StepContext& c) override {
    stage_->apply(t, c);
    raiseDeferredError();
  }

 private:
  std::unique_ptr<Stage> stage_;
};

/// A stage written in Python: fn(tissue, step, time, dt), run on the calling thread.
class PythonStage final : public Stage {
 public:
  PythonStage(py::function fn, std::string name) : fn_(std::move(fn)), name_(std::move(name)) {}
  ~PythonStage() override {
    py::gil_scoped_acquire gil;
    fn_ = py::function();
  }
  std::string name() const override { return name_; }
  void apply(Tissue& t, const StepContext& c) override {
    py::gil_scoped_acquire gil;
    fn_(py::cast(&t, py::return_value_policy::reference), c.step, c.time, c.dt);
  }

 private:
  py::function fn_;
  std::string name_;
};

sim::OutputSpec outputSpec(std::size_t every, const std::string& name, const std::string& compression) {
  if (every == 0) throw InputError("attach_series: every must be >= 1");
  sim::OutputSpec o;
  o.every = every;
  o.name = name;
  o.vtu.compression = io::parseCompression(compression);
  return o;
}

}  // namespace

void bindSim(py::module_& m) {
  py::class_<sim::SeriesOutput, std::shared_ptr<sim::SeriesOutput>>(
      m, "SeriesOutput", "A ParaView series a Simulation keeps up to date (see Simulation.attach_series).")
      .def_property_readonly("snapshots", &sim::SeriesOutput::snapshots)
      .def_property_readonly("pvd_path", &sim::SeriesOutput::pvdPath);

  py::class_<Simulation>(m, "Simulation", R"doc(
A tissue, a time span [start, end] in steps of dt, and stages run each step in
order (growth, division, Python functions), then the clock advances, then the
on_step callbacks run. Simulation.from_file / from_yaml build everything a
configuration describes (docs/config.md); Simulation(tissue, ...) starts from
code, with add_stage(). The simulation owns its tissue (a copy of the one
given): read and edit it through sim.tissue, which stays valid while the
simulation lives. A stage's exception is raised as SimulationError naming the
stage, step and time, followed by the cause's message.
)doc")
      .def(py::init([](const Tissue& t, double start, double end, double dt, std::uint64_t seed) {
             if (!(dt > 0.0)) throw InputError("Simulation: dt must be > 0, got " + formatNumber(dt));
             if (!(end >= start))
               throw InputError("Simulation: end (" + formatNumber(end) + ") must be >= start (" + formatNumber(start) +
                                ")");
             return Simulation(t, sim::SimulationOptions{.time = {start, end, dt}, .rng_seed = seed, .rng_state = {}, .carried = {}});
           }),
           py::arg("tissue"), py::arg("start") = 0.0, py::arg("end") = 10.0, py::arg("dt") = 1.0, py::arg("rng_seed") = 0)
      .def_static("from_file", &Simulation::fromFile, py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
                  "From a YAML configuration file; overrides are 'key.path=value' strings (the CLI's --set).")
      .def_static("from_yaml", &Simulation::fromYaml, py::arg("yaml"), py::arg("overrides") = std::vector<std::string>{},
                  py::arg("base_directory") = ".", "From YAML text; InputError (ValueError) names the key, line and value.")
      .def_property_readonly("tissue", py::overload_cast<>(&Simulation::tissue), py::return_value_policy::reference_internal,
                             "The simulated tissue (no copy; valid while the simulation lives).")
      .def_property_readonly("time", &Simulation::time)
      .def_property_readonly("steps_done", &Simulation::stepsDone)
      .def_property_readonly("num_steps", &Simulation::numSteps)
      .def_property_readonly("finished", &Simulation::finished)
      .def_property_readonly("dt", [](const Simulation& s) { return s.options().time.dt; })
      .def_property_readonly("stage_names",
                             [](const Simulation& s) {
                               std::vector<std::string> names;
                               for (std::size_t i = 0; i < s.numStages(); ++i) names.push_back(s.stage(i).name());
                               return names;
                             })
      .def(
          "add_stage",
          [](Simulation& s, py::object stage, const std::string& name) {
            if (py::isinstance<growth::GrowthIntegrator>(stage))
              s.addStage(std::make_unique<sim::GrowthStage>(stage.cast<std::shared_ptr<growth::GrowthIntegrator>>()));
            else if (py::isinstance<growth::DivisionScheduler>(stage))
              s.addStage(std::make_unique<RaisingDeferredErrors>(
                  std::make_unique<sim::DivisionStage>(stage.cast<std::shared_ptr<growth::DivisionScheduler>>())));
            else if (PyCallable_Check(stage.ptr()))
              s.addStage(std::make_unique<PythonStage>(stage.cast<py::function>(), name.empty() ? "python" : name));
            else
              throw InputError("add_stage: expected a GrowthIntegrator, a DivisionScheduler or a callable "
                               "fn(tissue, step, time, dt), got " + std::string(py::str(py::type::of(stage))));
          },
          py::arg("stage"), py::arg("name") = "",
          "Appends a stage: a GrowthIntegrator, a DivisionScheduler (drawing from the run's random stream) or a "
          "Python function fn(tissue, step, time, dt).")
      .def(
          "on_step",
          [](Simulation& s, py::function fn) {
            s.onStep([fn](const Simulation& sim) {
              py::gil_scoped_acquire gil;
              fn(py::cast(&sim, py::return_value_policy::reference));
            });
          },
          py::arg("callback"), "callback(simulation) after every step (exceptions propagate out of step/run).")
      // Step by step, so that an error a division deferred (deferred_error.hpp)
      // is raised after the step it happened in.
      .def("step", [](Simulation& s) { s.step(); raiseDeferredError(); }, "One step (RuntimeError once finished).")
      .def(
          "run_until",
          [](Simulation& s, double t) {
            const double slack = 1e-6 * s.options().time.dt;  // as Simulation::runUntil
            while (!s.finished() && s.time() < t - slack) {
              s.step();
              raiseDeferredError();
            }
          },
          py::arg("time"), "Steps while time < t (stops at the end of the span).")
      .def(
          "run",
          [](Simulation& s) {
            while (!s.finished()) {
              s.step();
              raiseDeferredError();
            }
          },
          "Steps to the end of the time span.")
      .def("write_snapshot", [](const Simulation& s, const std::string& path) { s.writeSnapshot(path); },
           py::arg("path"),
           "Writes a snapshot a restart (tissue.generator: snapshot) continues bit for bit: the tissue with the "
           "run's clock and random stream, and a diffusion stage's mesh and fields beside it (<stem>.fields.vtu).")
      .def(
          "attach_series",
          [](Simulation& s, const std::string& directory, std::size_t every, const std::string& name,
             const std::string& compression) {
            return sim::attachSeriesOutput(s, directory, outputSpec(every, name, compression));
          },
          py::arg("directory"), py::arg("every") = 1, py::arg("name") = "tissue", py::arg("compression") = std::string(io::compressionName(io::VtuOptions{}.compression)),
          "Writes the current state now, then every `every` steps and the final state, as a ParaView series.");

  m.def(
      "run_config",
      [](const std::string& path, const std::optional<std::string>& out, const std::vector<std::string>& overrides,
         bool overwrite) {
        sim::PreparedRun run = sim::PreparedRun::prepare(sim::loadSimulationConfigFile(path, overrides),
                                                         sim::RunOptions{.output_directory = out, .overwrite = overwrite});
        run.execute();
        py::dict d;
        d["directory"] = run.outputDirectory();
        d["snapshots"] = run.snapshots();
        d["run_record"] = run.runRecordPath();
        d["steps"] = run.simulation().stepsDone();
        d["cells"] = run.simulation().tissue().numCells();
        return d;
      },
      py::arg("path"), py::arg("out") = py::none(), py::arg("overrides") = std::vector<std::string>{}, py::arg("overwrite") = false,
      "What `tessella run` does: checks the config, writes run.yaml and the series into `out` (or output.directory, or "
      "runs/<name>; an empty `out` is refused). A directory holding a run is refused unless overwrite=True.");
}

}  // namespace tessella::python
