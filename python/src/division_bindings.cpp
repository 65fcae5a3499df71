// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Division from Python: rules (built-in and Python functions), size
// thresholds and the scheduler that divides the cells due each step.
#include <memory>

#include "bindings.hpp"
#include "deferred_error.hpp"
#include "param_values.hpp"
#include "tessella/growth/division_scheduler.hpp"
#include "tessella/growth/fixed_direction_rule.hpp"
#include "tessella/growth/main_axis_rule.hpp"
#include "tessella/growth/random_direction_rule.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/growth/shortest_wall_rule.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::python {

namespace {

using growth::DivisionRule;

/// A division rule written in Python: fn(tissue, cell) -> (point, normal).
/// The scheduler asks for planes one cell at a time on the calling thread
/// (divisions edit the tissue, so they are serial), which holds the GIL.
/// `tissue` is the dividing tissue itself, valid during the call only.
class PythonRule final : public DivisionRule {
 public:
  PythonRule(py::function fn, std::string name) : fn_(std::move(fn)), name_(std::move(name)) {}
  ~PythonRule() override {
    py::gil_scoped_acquire gil;
    fn_ = py::function();
  }
  Plane plane(const Tissue& t, CellId c, growth::Rng&) const override {
    py::gil_scoped_acquire gil;
    py::object r = fn_(py::cast(&t, py::return_value_policy::reference), c.index());
    py::sequence s = py::reinterpret_borrow<py::object>(r).cast<py::sequence>();
    if (s.size() != 2)
      throw InputError("division rule '" + name_ + "': expected (point, normal) for cell " +
                       std::to_string(c.index()) + ", got " + std::string(py::repr(r)));
    Plane p{s[0].cast<Vec3>(), s[1].cast<Vec3>()};
    if (!p.point.allFinite() || !p.normal.allFinite() || p.normal.norm() == 0.0)
      throw GeometryError("division rule '" + name_ + "': cell " + std::to_string(c.index()) +
                          ": the plane needs a finite point and a non-zero normal");
    return p;
  }
  std::string name() const override { return name_; }

 private:
  py::function fn_;
  std::string name_;
};

py::dict recordDict(const growth::DivisionRecord& r) {
  py::dict d;
  d["mother_lineage"] = r.mother_lineage;
  d["cell"] = r.cell.index();
  d["daughter"] = r.daughter.index();
  d["wall"] = r.wall.index();
  d["attempts"] = r.attempts;
  return d;
}

}  // namespace

void bindDivision(py::module_& m) {
  py::class_<DivisionRule, std::shared_ptr<DivisionRule>>(m, "DivisionRule", "Where a cell divides (abstract).")
      .def(
          "plane",
          [](const DivisionRule& rule, const Tissue& t, long long c, std::uint64_t seed) {
            growth::Rng rng(seed);
            const Plane p = rule.plane(t, checkedCell(t, c), rng);
            return py::make_tuple(p.point, p.normal);
          },
          py::arg("tissue"), py::arg("cell"), py::arg("rng_seed") = 0, "(point, normal) of the dividing plane.")
      .def_property_readonly("name", &DivisionRule::name);
  py::class_<growth::MainAxisRule, DivisionRule, std::shared_ptr<growth::MainAxisRule>>(
      m, "MainAxisRule", "Across the cell's longest principal axis, through its centroid.")
      .def(py::init<>());
  py::class_<growth::ShortestWallRule, DivisionRule, std::shared_ptr<growth::ShortestWallRule>>(
      m, "ShortestWallRule", "The shortest new wall through the centroid (Errera).")
      .def(py::init<>());
  py::class_<growth::RandomDirectionRule, DivisionRule, std::shared_ptr<growth::RandomDirectionRule>>(
      m, "RandomDirectionRule", "A uniformly random orientation through the centroid.")
      .def(py::init<>());
  py::class_<growth::FixedDirectionRule, DivisionRule, std::shared_ptr<growth::FixedDirectionRule>>(
      m, "FixedDirectionRule", "A plane through the centroid with a given normal.")
      .def(py::init<const Vec3&>(), py::arg("normal"));
  py::class_<PythonRule, DivisionRule, std::shared_ptr<PythonRule>>(m, "PythonRule", R"doc(
A division rule written in Python: fn(tissue, cell) -> (point, normal), the
cutting plane of `cell`. `tissue` is the dividing tissue itself (no copy):
read it, do not edit it, and do not keep it after the call.
)doc")
      .def(py::init<py::function, std::string>(), py::arg("fn"), py::arg("name") = "python");
  const auto& rules = growth::divisionRules();
  const std::string make_rule_doc =
      "A rule by its configuration name, with its parameters as keywords (a parameter of another rule is "
      "ignored; positional parameters are fixed_normal, beta, junction_tolerance, in that order):" +
      registryDoc(rules);
  m.def(
      "make_division_rule",
      [](const std::string& name, const py::args& args, const py::kwargs& kwargs) {
        const auto& table = growth::divisionRules();
        const auto& entry = table.at(name);
        // The order of the positional parameters before the table existed.
        static const std::vector<std::string> positional = {"fixed_normal", "beta", "junction_tolerance"};
        if (args.size() > positional.size())
          throw InputError("make_division_rule: at most " + std::to_string(positional.size()) +
                           " positional parameters, got " + std::to_string(args.size()));
        std::vector<std::pair<std::string, py::handle>> given;
        for (std::size_t i = 0; i < args.size(); ++i) given.emplace_back(positional[i], args[i]);
        for (const auto& [key, value] : kwargs) given.emplace_back(py::cast<std::string>(key), value);
        ParamValues values;
        for (const auto& [param, value] : given) {
          if (values.has(param)) throw InputError("make_division_rule: parameter '" + param + "' given twice");
          if (const ParamSpec* spec = findParam(entry, param)) {
            values.set(param, paramValueFromPython(*spec, value));
            continue;
          }
          bool another_rule_reads_it = false;
          for (const auto& e : table.entries()) another_rule_reads_it = another_rule_reads_it || findParam(e, param);
          if (!another_rule_reads_it)
            throw InputError("make_division_rule: no division rule has a parameter '" + param + "'");
        }
        return std::const_pointer_cast<DivisionRule>(table.make(name, values));
      },
      py::arg("name"), make_rule_doc.c_str());

  py::class_<growth::SizeThreshold>(m, "SizeThreshold", "When a cell divides: its area/volume exceeds a threshold.")
      .def_static("fixed", &growth::SizeThreshold::fixed, py::arg("size"))
      .def_static("from_property", &growth::SizeThreshold::fromProperty, py::arg("name"),
                  "The threshold is a float64 cell property the model maintains.")
      .def_static("noisy", &growth::SizeThreshold::noisy, py::arg("mean"), py::arg("stddev"),
                  py::arg("property") = "division_threshold", "Drawn per cell at birth from N(mean, stddev).")
      .def("__repr__", [](const growth::SizeThreshold& s) { return "<tessella.SizeThreshold " + s.describe() + ">"; });

  py::class_<growth::DivisionScheduler, std::shared_ptr<growth::DivisionScheduler>>(m, "DivisionScheduler", R"doc(
Divides every cell over its size threshold with the rule (at most once per
step); a refused plane is retried perturbed, then the cell is skipped until
the next step. Property columns divide by their policies; lineage follows.
)doc")
      .def(py::init([](const growth::SizeThreshold& trigger, std::shared_ptr<DivisionRule> rule, int max_attempts,
                       std::uint64_t seed) {
             if (!rule) throw InputError("DivisionScheduler: rule must not be None");
             growth::DivisionOptions o;
             o.max_attempts = max_attempts;
             o.seed = seed;
             return std::make_shared<growth::DivisionScheduler>(trigger, std::move(rule), o);
           }),
           py::arg("threshold"), py::arg("rule"), py::arg("max_attempts") = 5, py::arg("rng_seed") = 1)
      .def(
          "step",
          [](growth::DivisionScheduler& s, Tissue& t) {
            GeometryCache geometry;  // stale: the scheduler computes it
            const growth::DivisionReport r = s.step(t, geometry);
            raiseDeferredError();
            py::list divided, skipped;
            for (const auto& d : r.divided) divided.append(recordDict(d));
            for (const auto& k : r.skipped) skipped.append(py::make_tuple(k.cell.index(), k.lineage, k.reason));
            py::dict out;
            out["divided"] = divided;
            out["skipped"] = skipped;
            return out;
          },
          py::arg("tissue"),
          "Divides every due cell. Returns {'divided': [record dicts], 'skipped': [(cell, lineage, reason)]}.")
      .def("divide",
           [](growth::DivisionScheduler& s, Tissue& t, long long c) {
             const growth::DivisionRecord r = s.divide(t, checkedCell(t, c));
             raiseDeferredError();
             return recordDict(r);
           },
           py::arg("tissue"), py::arg("cell"), "Divides one cell now (GeometryError if every attempt fails).");
}

}  // namespace tessella::python
