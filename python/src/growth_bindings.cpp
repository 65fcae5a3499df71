// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Growth from Python: velocity fields (built-in, expressions, Python
// functions), surface projections and the growth integrator.
#include <memory>

#include "bindings.hpp"
#include "param_values.hpp"
#include "python_field.hpp"
#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/growth/radial_field.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/growth/surface_projection.hpp"
#include "tessella/tissue/dome_surface.hpp"

namespace tessella::python {

namespace {

using growth::VelocityField;

/// A surface projection (a C++ function run inside OpenMP loops, so it
/// cannot be written in Python) with a name for repr().
struct Projection {
  growth::SurfaceProjection f;
  std::string description;
};

growth::IntegrationScheme scheme(const std::string& s) { return growth::parseScheme(s); }

growth::VelocitySource source(const std::string& s) {
  try {
    return growth::velocitySources().parse(s);
  } catch (const InputError& e) {
    throw InputError(std::string("velocities: ") + e.what());
  }
}

// "  name: doc" for every value of an enum table.
template <typename E>
std::string enumDoc(const EnumTable<E>& table) {
  std::string out;
  for (const auto& e : table.entries()) out += "\n  " + e.name + ": " + e.doc;
  return out;
}

}  // namespace

void bindGrowth(py::module_& m) {
  py::class_<VelocityField, std::shared_ptr<VelocityField>>(m, "VelocityField",
                                                            "A velocity field v(x, t) (abstract; see the subclasses).")
      .def("velocity", &VelocityField::velocity, py::arg("x"), py::arg("t") = 0.0, "Velocity at one point.")
      .def(
          "velocities",
          [](const VelocityField& f, py::handle points, double t) {
            const std::vector<Vec3> x = vec3FromArray(points, "velocities: points");
            std::vector<Vec3> v(x.size());
            f.velocities(x, t, v);
            return vec3Copy(v);
          },
          py::arg("points"), py::arg("t") = 0.0, "Velocities of an (n, 3) array of points, as (n, 3).")
      .def("describe", &VelocityField::describe)
      .def("__repr__", [](const VelocityField& f) { return "<tessella." + f.describe() + ">"; });

  py::class_<growth::LinearField, VelocityField, std::shared_ptr<growth::LinearField>>(
      m, "LinearField", "v = G (x - c): uniform expansion (G = r I), anisotropic growth, rotation.")
      .def(py::init<const Mat3&, const Vec3&>(), py::arg("rate"), py::arg("center") = Vec3(Vec3::Zero()))
      .def_property_readonly("rate", &growth::LinearField::rate)
      .def_property_readonly("center", &growth::LinearField::center);
  m.def("uniform_expansion",
        [](double r, const Vec3& c) { return std::make_shared<growth::LinearField>(growth::uniformExpansion(r, c)); },
        py::arg("rate"), py::arg("center") = Vec3(Vec3::Zero()),
        "v = r (x - c): lengths grow as exp(r t), areas exp(2 r t), volumes exp(3 r t).");
  m.def("anisotropic_growth",
        [](const Vec3& r, const Vec3& c) { return std::make_shared<growth::LinearField>(growth::anisotropicGrowth(r, c)); },
        py::arg("axis_rates"), py::arg("center") = Vec3(Vec3::Zero()), "v = diag(rx, ry, rz) (x - c).");

  py::class_<growth::RadialField, VelocityField, std::shared_ptr<growth::RadialField>>(
      m, "RadialField", "Outward from a centre (or an axis) at speed rate * d^exponent.")
      .def(py::init([](const Vec3& center, const Vec3& axis, double rate, double exponent) {
             return std::make_shared<growth::RadialField>(
                 growth::RadialFieldParams{.center = center, .axis = axis, .rate = rate, .exponent = exponent});
           }),
           py::arg("center") = Vec3(Vec3::Zero()), py::arg("axis") = Vec3(Vec3::Zero()), py::arg("rate") = 1.0,
           py::arg("exponent") = 1.0);

  py::class_<growth::MeristemField, VelocityField, std::shared_ptr<growth::MeristemField>>(
      m, "MeristemField", "Slow central zone around the apex, fast periphery: v = k(rho) (x - apex).")
      .def(py::init([](const Vec3& apex, const Vec3& axis, double central_radius, double transition_width,
                       double central_rate, double peripheral_rate) {
             return std::make_shared<growth::MeristemField>(growth::MeristemFieldParams{
                 .apex = apex, .axis = axis, .central_radius = central_radius, .transition_width = transition_width,
                 .central_rate = central_rate, .peripheral_rate = peripheral_rate});
           }),
           py::arg("apex") = Vec3(Vec3::Zero()), py::arg("axis") = Vec3(Vec3::UnitZ()), py::arg("central_radius") = 0.3,
           py::arg("transition_width") = 0.05, py::arg("central_rate") = 0.02, py::arg("peripheral_rate") = 0.1)
      .def("rate_at", &growth::MeristemField::rateAt, py::arg("rho"), "k(rho): relative rate at distance rho from the axis.");

  py::class_<growth::BumpField, VelocityField, std::shared_ptr<growth::BumpField>>(
      m, "BumpField", "The bump field of the PlantGL paper's figure 17.")
      .def(py::init([](double a, double b, double h, double x0) {
             return std::make_shared<growth::BumpField>(growth::BumpFieldParams{.a = a, .b = b, .h = h, .x0 = x0});
           }),
           py::arg("a") = 1.0, py::arg("b") = 1.0, py::arg("h") = 1.0, py::arg("x0") = 0.0);

  py::class_<growth::ExpressionField, VelocityField, std::shared_ptr<growth::ExpressionField>>(
      m, "ExpressionField", "Three muparser expressions of x, y, z, t and named parameters.")
      .def(py::init([](std::string vx, std::string vy, std::string vz, std::map<std::string, double> parameters) {
             return std::make_shared<growth::ExpressionField>(
                 growth::ExpressionFieldParams{std::move(vx), std::move(vy), std::move(vz), std::move(parameters)});
           }),
           py::arg("vx") = "0", py::arg("vy") = "0", py::arg("vz") = "0",
           py::arg("parameters") = std::map<std::string, double>{});

  const std::string make_field_doc =
      "A velocity field by its configuration name (growth.field), with its parameters as keywords:" +
      registryDoc(growth::velocityFields());
  m.def(
      "make_velocity_field",
      [](const std::string& name, const py::kwargs& kwargs) {
        const auto& entry = growth::velocityFields().at(name);
        ParamValues values;
        for (const auto& [key, value] : kwargs) {
          const std::string param = py::cast<std::string>(key);
          const ParamSpec* spec = findParam(entry, param);
          // Unknown names go through as they are, so make() names the field and its parameters.
          values.set(param, spec ? paramValueFromPython(*spec, value) : ParamValue(std::string(py::str(value))));
        }
        return std::const_pointer_cast<VelocityField>(growth::velocityFields().make(name, values));
      },
      py::arg("name"), make_field_doc.c_str());

  py::class_<PythonField, VelocityField, std::shared_ptr<PythonField>>(m, "PythonField", R"doc(
A velocity field written in Python: fn(points, t) -> velocities, where points
is a read-only (n, 3) float64 array (a copy of the positions being evaluated)
and the result an (n, 3) array. Called once per integrator stage with every
vertex, on the calling thread (never from OpenMP workers), so write it with
vectorised NumPy. An exception raised in fn propagates out of step().
)doc")
      .def(py::init([](py::function fn, std::string description) {
             return std::make_shared<PythonField>(std::move(fn), std::move(description));
           }),
           py::arg("fn"), py::arg("description") = "python field");

  py::class_<Projection>(m, "Projection", "Keeps a curved tissue on its surface during growth (a C++ function).")
      .def("__call__", [](const Projection& p, const Vec3& x) { return p.f(x); }, py::arg("point"))
      .def("__repr__", [](const Projection& p) { return "<tessella.Projection " + p.description + ">"; });
  m.def("dome_projection", [](const Dome& d) { return Projection{growth::domeProjection(d), "dome"}; }, py::arg("dome"),
        "Nearest point on the dome's surface, extended past its base.");
  m.def("sphere_projection",
        [](const Vec3& c, double r) { return Projection{growth::sphereProjection(c, r), "sphere"}; }, py::arg("center"),
        py::arg("radius"));
  m.def("paraboloid_projection",
        [](const Vec3& apex, double k) { return Projection{growth::paraboloidProjection(apex, k), "paraboloid"}; },
        py::arg("apex"), py::arg("curvature"));

  const std::string integrator_doc =
      "Moves every vertex with a velocity field over one step, projects onto the surface, advances the tissue\n"
      "clock and refuses (GeometryError, positions and clock restored) a step that inverts or collapses a cell.\n"
      "scheme:" + enumDoc(growth::integrationSchemes()) + "\nvelocities:" + enumDoc(growth::velocitySources()) + "\n";
  py::class_<growth::GrowthIntegrator, std::shared_ptr<growth::GrowthIntegrator>>(m, "GrowthIntegrator",
                                                                                 integrator_doc.c_str())
      .def(py::init([](std::shared_ptr<VelocityField> field, const std::string& sch, std::optional<Projection> projection,
                       const std::string& velocities, bool check_inversion, double min_cell_measure) {
             if (!field) throw InputError("GrowthIntegrator: field must not be None");
             growth::GrowthOptions o;
             o.scheme = scheme(sch);
             o.source = source(velocities);
             if (projection) o.projection = projection->f;
             o.check_inversion = check_inversion;
             o.min_cell_measure = min_cell_measure;
             return std::make_shared<growth::GrowthIntegrator>(std::move(field), o);
           }),
           py::arg("field"), py::arg("scheme") = "heun", py::arg("projection") = py::none(),
           py::arg("velocities") = "field", py::arg("check_inversion") = true, py::arg("min_cell_measure") = 0.0)
      .def("step", py::overload_cast<Tissue&, double>(&growth::GrowthIntegrator::step), py::arg("tissue"), py::arg("dt"),
           "Advances the tissue from tissue.time to tissue.time + dt; on any error positions and clock are restored.")
      .def(
          "velocities",
          [](growth::GrowthIntegrator& g, const Tissue& t, std::optional<double> time) {
            std::vector<Vec3> v(t.slots(0));
            g.velocities(t, t.positions(), time.value_or(t.time()), v);
            return vec3Copy(v);
          },
          py::arg("tissue"), py::arg("time") = py::none(),
          "The velocity of every vertex slot the integrator would use now, (vertex_slots, 3).")
      .def_property_readonly("field", [](const growth::GrowthIntegrator& g) { return g.field().describe(); });
}

}  // namespace tessella::python
