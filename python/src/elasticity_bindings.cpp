// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Linear elasticity from Python: plane stress / plane strain on flat
// triangles, 3D solids on tetrahedra, membranes on triangle sheets in 3D.
// Results are NumPy arrays; stresses and strains in Voigt order
// [xx, yy, zz, yz, xz, xy] (engineering shear strains).
#include "bindings.hpp"
#include "enum_strings.hpp"
#include "tessella/solvers/elasticity.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::mesh;
using namespace tessella::solvers;

void bindElasticity(py::module_& m) {
  bindEnum(m, "ElasticModel", "Kinematics of the elastic problem.", solvers::elasticModels());

  py::class_<DisplacementCondition>(m, "DisplacementCondition",
                                    "Fixes the selected components (fixed = (x, y, z)) to value on facets and nodes.")
      .def(py::init([](std::vector<int> facets, std::vector<int> nodes, std::array<bool, 3> fixed, Eigen::Vector3d value) {
             return DisplacementCondition{std::move(facets), std::move(nodes), fixed, value};
           }),
           py::arg("facets") = std::vector<int>{}, py::arg("nodes") = std::vector<int>{},
           py::arg("fixed") = std::array<bool, 3>{true, true, true}, py::arg("value") = Eigen::Vector3d::Zero().eval())
      .def_readwrite("facets", &DisplacementCondition::facets)
      .def_readwrite("nodes", &DisplacementCondition::nodes)
      .def_readwrite("fixed", &DisplacementCondition::fixed)
      .def_readwrite("value", &DisplacementCondition::value);
  py::class_<TractionCondition>(m, "TractionCondition", "Force per unit area on facets.")
      .def(py::init([](std::vector<int> facets, Eigen::Vector3d traction) { return TractionCondition{std::move(facets), traction}; }),
           py::arg("facets"), py::arg("traction"))
      .def_readwrite("facets", &TractionCondition::facets)
      .def_readwrite("traction", &TractionCondition::traction);
  py::class_<PressureCondition>(m, "PressureCondition", "Pressure on boundary facets (traction -p n; p > 0 pushes in).")
      .def(py::init([](std::vector<int> facets, double pressure) { return PressureCondition{std::move(facets), pressure}; }),
           py::arg("facets"), py::arg("pressure"))
      .def_readwrite("facets", &PressureCondition::facets)
      .def_readwrite("pressure", &PressureCondition::pressure);

  py::class_<ElasticityProblem>(m, "ElasticityProblem", R"doc(
Model, per-cell Young's modulus and Poisson ratio (one value = uniform),
thickness (triangles), body force, boundary conditions, membrane pressure and
linear-solver options.
)doc")
      .def(py::init([](ElasticModel model, Eigen::VectorXd young, Eigen::VectorXd poisson, double thickness,
                       Eigen::Vector3d body_force, std::vector<DisplacementCondition> displacement,
                       std::vector<TractionCondition> traction, std::vector<PressureCondition> pressure,
                       double membrane_pressure, LinearSolverOptions linear) {
             return ElasticityProblem{.model = model, .young = std::move(young), .poisson = std::move(poisson),
                                      .thickness = thickness, .body_force = body_force,
                                      .displacement = std::move(displacement), .traction = std::move(traction),
                                      .pressure = std::move(pressure), .membrane_pressure = membrane_pressure,
                                      .linear = linear};
           }),
           py::arg("model") = solvers::ElasticModel::Solid, py::arg("young") = Eigen::VectorXd::Ones(1).eval(),
           py::arg("poisson") = Eigen::VectorXd::Constant(1, 0.3).eval(), py::arg("thickness") = 1.0,
           py::arg("body_force") = Eigen::Vector3d::Zero().eval(),
           py::arg("displacement") = std::vector<DisplacementCondition>{},
           py::arg("traction") = std::vector<TractionCondition>{}, py::arg("pressure") = std::vector<PressureCondition>{},
           py::arg("membrane_pressure") = 0.0, py::arg("linear") = LinearSolverOptions{})
      .def_readwrite("model", &ElasticityProblem::model)
      .def_readwrite("young", &ElasticityProblem::young)
      .def_readwrite("poisson", &ElasticityProblem::poisson)
      .def_readwrite("thickness", &ElasticityProblem::thickness)
      .def_readwrite("body_force", &ElasticityProblem::body_force)
      .def_readwrite("displacement", &ElasticityProblem::displacement)
      .def_readwrite("traction", &ElasticityProblem::traction)
      .def_readwrite("pressure", &ElasticityProblem::pressure)
      .def_readwrite("membrane_pressure", &ElasticityProblem::membrane_pressure)
      .def_readwrite("linear", &ElasticityProblem::linear);

  py::class_<ElasticityResult>(m, "ElasticityResult", R"doc(
displacement (num_nodes, 3); strain, stress (num_elements, 6); cell_strain,
cell_stress (num_cells, 6) measure-weighted per cell; principal_stress
(num_cells, 3) ascending and principal_directions (num_cells, 3, 3), column k
going with value k; report (SolveReport).
)doc")
      .def_readonly("displacement", &ElasticityResult::displacement)
      .def_readonly("strain", &ElasticityResult::strain)
      .def_readonly("stress", &ElasticityResult::stress)
      .def_readonly("cell_strain", &ElasticityResult::cell_strain)
      .def_readonly("cell_stress", &ElasticityResult::cell_stress)
      .def_readonly("principal_stress", &ElasticityResult::principal_stress)
      .def_property_readonly("principal_directions",
                             [](const ElasticityResult& r) {
                               const auto n = static_cast<py::ssize_t>(r.principal_directions.size());
                               py::array_t<double> a({n, py::ssize_t{3}, py::ssize_t{3}});
                               auto w = a.mutable_unchecked<3>();
                               for (py::ssize_t c = 0; c < n; ++c)
                                 for (int i = 0; i < 3; ++i)
                                   for (int j = 0; j < 3; ++j) w(c, i, j) = r.principal_directions[static_cast<std::size_t>(c)](i, j);
                               return a;
                             })
      .def_readonly("report", &ElasticityResult::report);

  m.def("solve_elasticity", &solveElasticity, py::arg("mesh"), py::arg("problem"),
        "Assembles and solves; ValueError for bad input or an under-constrained body.");
  m.def("voigt_to_tensor", [](const Eigen::Matrix<double, 1, 6>& v) { return voigtToTensor(v); }, py::arg("voigt"),
        "3x3 symmetric tensor from [xx, yy, zz, yz, xz, xy].");
}

}  // namespace tessella::python
