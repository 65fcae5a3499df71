// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Diffusion-reaction on an FeMesh from Python: species with per-cell
// coefficients and boundary conditions, the time schemes and the steady
// solve. Functions of (x, t) and the reaction are Python callables, called
// serially on the calling thread (the solver runs them outside any OpenMP
// loop), once per node: fine for setting up, slow inside long runs.
#include <pybind11/functional.h>

#include "bindings.hpp"
#include "enum_strings.hpp"
#include "tessella/solvers/diffusion_reaction.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::mesh;
using namespace tessella::solvers;

namespace {

using OptFunction = std::optional<SpatialFunction>;

int checkedSpecies(const DiffusionReaction& d, int s) {
  if (s < 0 || s >= d.numSpecies())
    throw InputError("species " + std::to_string(s) + " out of range (the problem has " +
                     std::to_string(d.numSpecies()) + " species)");
  return s;
}

Eigen::VectorXd orEmpty(const std::optional<Eigen::VectorXd>& v) { return v.value_or(Eigen::VectorXd()); }

}  // namespace

void bindDiffusion(py::module_& m) {
  bindEnum(m, "TimeScheme", "Time stepping of the implicit (linear) part.", solvers::timeSchemes());
  bindEnum(m, "MassType", "Consistent (exact) or lumped (row-sum, keeps positivity) mass matrix.", solvers::massTypes());

  py::class_<DirichletCondition>(m, "DirichletCondition", "u = value (or function(x, t)) on the nodes of the facets.")
      .def(py::init([](std::vector<int> facets, double value, OptFunction function) {
             return DirichletCondition{std::move(facets), value, function.value_or(SpatialFunction{})};
           }),
           py::arg("facets"), py::arg("value") = 0.0, py::arg("function") = py::none())
      .def_readwrite("facets", &DirichletCondition::facets)
      .def_readwrite("value", &DirichletCondition::value);
  py::class_<FluxCondition>(m, "FluxCondition",
                            "Influx D grad u . n = influx (or function(x, t)) through the facets, per unit area and time.")
      .def(py::init([](std::vector<int> facets, double influx, OptFunction function) {
             return FluxCondition{std::move(facets), influx, function.value_or(SpatialFunction{})};
           }),
           py::arg("facets"), py::arg("influx") = 0.0, py::arg("function") = py::none())
      .def_readwrite("facets", &FluxCondition::facets)
      .def_readwrite("influx", &FluxCondition::influx);
  py::class_<RobinCondition>(m, "RobinCondition", "Exchange -D grad u . n = transfer (u - exterior) on the facets.")
      .def(py::init([](std::vector<int> facets, double transfer, double exterior) {
             return RobinCondition{std::move(facets), transfer, exterior};
           }),
           py::arg("facets"), py::arg("transfer") = 0.0, py::arg("exterior") = 0.0)
      .def_readwrite("facets", &RobinCondition::facets)
      .def_readwrite("transfer", &RobinCondition::transfer)
      .def_readwrite("exterior", &RobinCondition::exterior);

  py::class_<Species>(m, "Species", R"doc(
One diffusing species: du/dt = div(D grad u) - k u + p + source(x, t).
diffusivity, decay and production are per tissue cell (indexed by the mesh's
element_cell; one value = uniform; decay/production None = zero).
)doc")
      .def(py::init([](std::string name, Eigen::VectorXd diffusivity, std::optional<Eigen::VectorXd> decay,
                       std::optional<Eigen::VectorXd> production, OptFunction source,
                       std::vector<DirichletCondition> dirichlet, std::vector<FluxCondition> flux,
                       std::vector<RobinCondition> robin) {
             Species s;
             s.name = std::move(name);
             s.diffusivity = std::move(diffusivity);
             s.decay = orEmpty(decay);
             s.production = orEmpty(production);
             s.source = source.value_or(SpatialFunction{});
             s.dirichlet = std::move(dirichlet);
             s.flux = std::move(flux);
             s.robin = std::move(robin);
             return s;
           }),
           py::arg("name") = "u", py::arg("diffusivity") = Eigen::VectorXd::Ones(1), py::arg("decay") = py::none(),
           py::arg("production") = py::none(), py::arg("source") = py::none(),
           py::arg("dirichlet") = std::vector<DirichletCondition>{}, py::arg("flux") = std::vector<FluxCondition>{},
           py::arg("robin") = std::vector<RobinCondition>{})
      .def_readwrite("name", &Species::name)
      .def_readwrite("diffusivity", &Species::diffusivity)
      .def_readwrite("decay", &Species::decay)
      .def_readwrite("production", &Species::production)
      .def_readwrite("dirichlet", &Species::dirichlet, "List of DirichletCondition (assign a new list to change it).")
      .def_readwrite("flux", &Species::flux)
      .def_readwrite("robin", &Species::robin);

  py::class_<DiffusionOptions>(m, "DiffusionOptions")
      .def(py::init([](TimeScheme scheme, MassType mass, LinearSolverOptions linear, int picard_max_iterations,
                       double picard_tolerance) {
             return DiffusionOptions{.scheme = scheme, .mass = mass, .linear = linear,
                                     .picard_max_iterations = picard_max_iterations,
                                     .picard_tolerance = picard_tolerance};
           }),
           py::arg("scheme") = solvers::TimeScheme::ImplicitEuler, py::arg("mass") = solvers::MassType::Consistent,
           py::arg("linear") = LinearSolverOptions{}, py::arg("picard_max_iterations") = 200,
           py::arg("picard_tolerance") = 1e-10)
      .def_readwrite("scheme", &DiffusionOptions::scheme)
      .def_readwrite("mass", &DiffusionOptions::mass)
      .def_readwrite("linear", &DiffusionOptions::linear)
      .def_readwrite("picard_max_iterations", &DiffusionOptions::picard_max_iterations)
      .def_readwrite("picard_tolerance", &DiffusionOptions::picard_tolerance);

  py::class_<DiffusionReaction>(m, "DiffusionReaction", R"doc(
P1 diffusion-reaction of one or more species on an FeMesh (which it keeps
alive). The state is (num_nodes, num_species), one column per species.
)doc")
      .def(py::init([](const FeMesh& mesh, std::vector<Species> species, DiffusionOptions options) {
             return DiffusionReaction(mesh, std::move(species), options);
           }),
           py::arg("mesh"), py::arg("species"), py::arg("options") = DiffusionOptions{}, py::keep_alive<1, 2>())
      .def(
          "set_reaction",
          [](DiffusionReaction& d, py::function fn) {
            const int n = d.numSpecies();
            d.setReaction([fn, n](std::span<const double> u, std::span<double> rate) {
              py::array_t<double> arg(static_cast<py::ssize_t>(u.size()), u.data());
              auto r = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(fn(arg));
              if (!r || r.ndim() != 1 || r.shape(0) != n)
                throw InputError("reaction: the function must return " + std::to_string(n) +
                                 " rates (one per species) as a 1-D array");
              for (int i = 0; i < n; ++i) rate[static_cast<std::size_t>(i)] = r.at(i);
            });
          },
          py::arg("function"),
          "fn(u) -> rates: u and the result hold one value per species at one node; called once per node and step.")
      .def_property_readonly("num_species", &DiffusionReaction::numSpecies)
      .def_property("time", &DiffusionReaction::time, &DiffusionReaction::setTime)
      .def_property_readonly("state", [](const DiffusionReaction& d) { return Eigen::MatrixXd(d.state()); },
                             "Nodal values (num_nodes, num_species), a copy.")
      .def("values", [](const DiffusionReaction& d, int s) { return Eigen::VectorXd(d.state().col(checkedSpecies(d, s))); },
           py::arg("species") = 0, "Nodal values of one species (a copy).")
      .def("set_state", [](DiffusionReaction& d, const Eigen::MatrixXd& u) { d.setState(u); }, py::arg("state"),
           "Sets all species: (num_nodes, num_species).")
      .def("set_state",
           [](DiffusionReaction& d, int s, const Eigen::VectorXd& u) { d.setState(checkedSpecies(d, s), u); },
           py::arg("species"), py::arg("values"))
      .def("set_state",
           [](DiffusionReaction& d, int s, const SpatialFunction& f) { d.setState(checkedSpecies(d, s), f); },
           py::arg("species"), py::arg("function"), "Interpolates function(x, t) at the nodes, at the current time.")
      .def("step", &DiffusionReaction::step, py::arg("dt"), "One step of length dt.")
      .def("advance", &DiffusionReaction::advance, py::arg("duration"), py::arg("dt"),
           "ceil(duration / dt) equal steps covering exactly duration.")
      .def("solve_steady", [](DiffusionReaction& d) { return Eigen::MatrixXd(d.solveSteady()); },
           "Solves the steady problem, stores it as the state and returns it.")
      .def("total_amount", [](const DiffusionReaction& d, int s) { return d.totalAmount(checkedSpecies(d, s)); },
           py::arg("species") = 0, "Integral of a species over the mesh (with the mass matrix in use).")
      .def_property_readonly("last_report", &DiffusionReaction::lastReport, "SolveReport of the last linear solve.");
}

}  // namespace tessella::python
