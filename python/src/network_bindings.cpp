// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Cell-level regulatory networks from Python (networks/): the model as code
// (species, parameters, reactions, transport, PIN), its graph (from a tissue
// or from arrays), and the system: right-hand side, Jacobian, PIN, polarity,
// and integration by CVODE; primordium detection on a dome (primordia.hpp). States are AMOUNTS per cell and
// species, laid out cell by cell: y[cell * num_species + species], then (with_the_flux / expression PIN) two PIN
// densities per interface: y[num_cells * num_species + 2 k + side].
#include <array>

#include "bindings.hpp"
#include "tessella/networks/initial_values.hpp"
#include "tessella/networks/network_graph.hpp"
#include "tessella/networks/network_integrator.hpp"
#include "tessella/networks/network_system.hpp"
#include "tessella/networks/primordia.hpp"

namespace tessella::python {

using namespace tessella::networks;

namespace {

std::vector<double> checkedState(const NetworkSystem& s, const std::vector<double>& y) {
  if (y.size() != s.size())
    throw InputError("network: " + std::to_string(y.size()) + " values for a system of " +
                     std::to_string(s.numCells()) + " cells x " + std::to_string(s.numSpecies()) + " species + " +
                     std::to_string(s.numPinStates()) + " PIN densities");
  return y;
}

py::array_t<double> vec3Array(const std::vector<Vec3>& v) {
  py::array_t<double> out({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = v[i][k];
  return out;
}

}  // namespace

void bindNetworks(py::module_& m) {
  py::class_<NetworkSpecies>(m, "NetworkSpecies",
                             "A species of a cell network: its name, the rate of change of its concentration "
                             "by reactions (a muparser expression, '' for none) and its passive permeability.")
      .def(py::init([](std::string name, std::string reaction, double permeability) {
             return NetworkSpecies{std::move(name), std::move(reaction), permeability};
           }),
           py::arg("name"), py::arg("reaction") = "", py::arg("permeability") = 0.0)
      .def_readwrite("name", &NetworkSpecies::name)
      .def_readwrite("reaction", &NetworkSpecies::reaction)
      .def_readwrite("permeability", &NetworkSpecies::permeability);

  py::class_<PinTransport>(m, "PinTransport", R"doc(
PIN efflux of one species (docs/networks.md).
model "up_the_gradient": PIN_ij = P_i * L_ij f(c_j) / (saturation + sum_k L_ik f(c_k)), f(c) = base**c
("exponential") or c**exponent ("power"), P_i = total + total_per_concentration * c_i; the efflux from i into j
is rate * PIN_ij * g(c_i), g(c) = c (efflux "linear") or c**2 / (1 + efflux_saturation * c**2) (efflux
"saturating", Smith et al. 2006).
model "with_the_flux": the PIN density p_ij on each interface side is a state,
dp_ij/dt = (basal + production h(phi_ij)) B_i - decay p_ij, h(phi) = phi**flux_exponent / (1 + flux_saturation
phi**flux_exponent) for a net flux density phi > 0 from i into j (else 0), B_i = 1 - sum_k L_ik p_ik / total when
bounded (else 1); the efflux from i into j is rate * L_ij * p_ij * c_i.
model "expression": dp_ij/dt = expression, over c_i, c_j, pin, pin_opposite, flux, wall, measure, pin_cell, t and
the parameters. `initial` is the densities' starting value in a simulation.
)doc")
      .def(py::init([](std::string species, const std::string& model, const std::string& function, double base,
                       double exponent, double rate, double total, double saturation, double basal,
                       double production, double decay, double flux_exponent, double flux_saturation, bool bounded,
                       double initial, std::string expression, const std::string& efflux,
                       double efflux_saturation, double total_per_concentration) {
             PinTransport p;
             p.species = std::move(species);
             p.model = pinModels().parse(model);
             p.function = pinFunctions().parse(function);
             p.base = base;
             p.exponent = exponent;
             p.rate = rate;
             p.total = total;
             p.saturation = saturation;
             p.basal = basal;
             p.production = production;
             p.decay = decay;
             p.flux_exponent = flux_exponent;
             p.flux_saturation = flux_saturation;
             p.bounded = bounded;
             p.initial = initial;
             p.expression = std::move(expression);
             p.efflux = pinEffluxes().parse(efflux);
             p.efflux_saturation = efflux_saturation;
             p.total_per_concentration = total_per_concentration;
             return p;
           }),
           py::arg("species"), py::arg("model") = "up_the_gradient", py::arg("function") = "exponential",
           py::arg("base") = 3.0, py::arg("exponent") = 1.0, py::arg("rate") = 1.0, py::arg("total") = 1.0,
           py::arg("saturation") = 0.0, py::arg("basal") = 0.0, py::arg("production") = 1.0,
           py::arg("decay") = 1.0, py::arg("flux_exponent") = 2.0, py::arg("flux_saturation") = 0.0,
           py::arg("bounded") = false, py::arg("initial") = 0.0, py::arg("expression") = "",
           py::arg("efflux") = "linear", py::arg("efflux_saturation") = 0.0, py::arg("total_per_concentration") = 0.0)
      .def_property(
          "model", [](const PinTransport& p) { return pinModels().name(p.model); },
          [](PinTransport& p, const std::string& name) { p.model = pinModels().parse(name); })
      .def_property(
          "efflux", [](const PinTransport& p) { return pinEffluxes().name(p.efflux); },
          [](PinTransport& p, const std::string& name) { p.efflux = pinEffluxes().parse(name); })
      .def_readwrite("efflux_saturation", &PinTransport::efflux_saturation)
      .def_readwrite("total_per_concentration", &PinTransport::total_per_concentration)
      .def_property_readonly("dynamic", &PinTransport::dynamic, "PIN is a state (with_the_flux, expression).")
      .def_readwrite("basal", &PinTransport::basal)
      .def_readwrite("production", &PinTransport::production)
      .def_readwrite("decay", &PinTransport::decay)
      .def_readwrite("flux_exponent", &PinTransport::flux_exponent)
      .def_readwrite("flux_saturation", &PinTransport::flux_saturation)
      .def_readwrite("bounded", &PinTransport::bounded)
      .def_readwrite("initial", &PinTransport::initial)
      .def_readwrite("expression", &PinTransport::expression)
      .def_readwrite("species", &PinTransport::species)
      .def_readwrite("base", &PinTransport::base)
      .def_readwrite("exponent", &PinTransport::exponent)
      .def_readwrite("rate", &PinTransport::rate)
      .def_readwrite("total", &PinTransport::total)
      .def_readwrite("saturation", &PinTransport::saturation);

  py::class_<NetworkModel>(m, "NetworkModel",
                           "Species, named parameters, the cell properties the reactions read, and PIN transport.")
      .def(py::init([](std::vector<NetworkSpecies> species, std::map<std::string, double> parameters,
                       std::vector<std::string> cell_properties, std::optional<PinTransport> pin) {
             NetworkModel model{std::move(species), std::move(parameters), std::move(cell_properties),
                                pin.value_or(PinTransport{})};
             model.validate();
             return model;
           }),
           py::arg("species"), py::arg("parameters") = std::map<std::string, double>{},
           py::arg("cell_properties") = std::vector<std::string>{}, py::arg("pin") = py::none())
      .def_readwrite("species", &NetworkModel::species)
      .def_readwrite("parameters", &NetworkModel::parameters)
      .def_readwrite("cell_properties", &NetworkModel::cell_properties)
      .def_readwrite("pin", &NetworkModel::pin);

  py::class_<NetworkGraph>(m, "NetworkGraph", "Cell measures and centroids, interfaces between cells, properties.")
      .def(py::init([](std::vector<double> measure, std::vector<std::tuple<int, int, double>> interfaces,
                       std::optional<Eigen::MatrixXd> centroid, std::map<std::string, std::vector<double>> properties) {
             NetworkGraph g;
             g.measure = std::move(measure);
             for (const auto& [i, j, L] : interfaces) g.interfaces.push_back({i, j, L, Vec3::Zero()});
             g.centroid.assign(g.measure.size(), Vec3::Zero());
             if (centroid) {
               if (centroid->rows() != static_cast<Eigen::Index>(g.measure.size()) || centroid->cols() != 3)
                 throw InputError("NetworkGraph: centroid must be an (n, 3) array, one row per cell");
               for (std::size_t c = 0; c < g.measure.size(); ++c)
                 g.centroid[c] = centroid->row(static_cast<Eigen::Index>(c)).transpose();
             }
             // Without centroids the normals point along the line of the two cells' centroids, if any.
             for (NetworkInterface& f : g.interfaces)
               if (f.cell_i >= 0 && f.cell_j >= 0 && static_cast<std::size_t>(f.cell_i) < g.centroid.size() &&
                   static_cast<std::size_t>(f.cell_j) < g.centroid.size()) {
                 const auto i = static_cast<std::size_t>(f.cell_i), j = static_cast<std::size_t>(f.cell_j);
                 const Vec3 d = g.centroid[j] - g.centroid[i];
                 if (d.norm() > 0) f.normal = d.normalized();
               }
             g.properties = std::move(properties);
             g.validate();
             return g;
           }),
           py::arg("measure"), py::arg("interfaces"), py::arg("centroid") = py::none(),
           py::arg("properties") = std::map<std::string, std::vector<double>>{},
           "interfaces: (i, j, measure) triples, one per pair of neighbouring cells.")
      .def_property_readonly("num_cells", &NetworkGraph::numCells)
      .def_property_readonly("measure", [](const NetworkGraph& g) { return g.measure; })
      .def_property_readonly("interfaces",
                             [](const NetworkGraph& g) {
                               std::vector<std::tuple<int, int, double>> out;
                               for (const auto& f : g.interfaces) out.emplace_back(f.cell_i, f.cell_j, f.measure);
                               return out;
                             })
      .def_property_readonly("normals", [](const NetworkGraph& g) {
        std::vector<Vec3> n;
        for (const auto& f : g.interfaces) n.push_back(f.normal);
        return vec3Array(n);
      });

  m.def("network_graph",
        [](const Tissue& t, const std::vector<std::string>& properties) {
          GeometryCache geometry;
          std::vector<CellId> cells;
          NetworkGraph g = networkGraph(t, geometry, properties, &cells);
          std::vector<long long> slots;
          for (CellId c : cells) slots.push_back(c.index());
          return py::make_tuple(std::move(g), slots);
        },
        py::arg("tissue"), py::arg("properties") = std::vector<std::string>{},
        "The network graph of a tissue's live cells and their slot indices, (graph, cells).");

  m.def("initial_concentrations",
        [](const std::string& expression, const NetworkGraph& graph, const std::map<std::string, double>& parameters,
           double noise, std::uint64_t seed) {
          std::mt19937_64 rng(seed);
          return initialConcentrations(expression, graph, parameters, noise, rng);
        },
        py::arg("expression"), py::arg("graph"), py::arg("parameters") = std::map<std::string, double>{},
        py::arg("noise") = 0.0, py::arg("seed") = 0,
        "The expression (over x, y, z, measure, parameters) in every cell, plus uniform noise in [0, noise).");

  py::class_<NetworkSystem>(m, "NetworkSystem", R"doc(
The ODE system of a model on a graph: dy/dt = F(t, y) for the AMOUNTS y[cell * num_species + species]
(concentration = amount / measure), then, with a with_the_flux / expression PIN model, the PIN densities
y[pin_index(interface, side)]. Integrate with integrate() (CVODE BDF, Newton with KLU or GMRES).
)doc")
      .def(py::init([](const NetworkModel& model, const NetworkGraph& graph, const std::string& jacobian) {
             return std::make_unique<NetworkSystem>(model, graph, jacobianKinds().parse(jacobian));
           }),
           py::arg("model"), py::arg("graph"), py::arg("jacobian") = "exact",
           "jacobian: 'exact', or 'neighbours' (without the second-neighbour PIN terms; cheaper Newton matrices).")
      .def_property_readonly("size", &NetworkSystem::size)
      .def_property_readonly("num_cells", &NetworkSystem::numCells)
      .def_property_readonly("num_species", &NetworkSystem::numSpecies)
      .def_property_readonly("num_pin_states", &NetworkSystem::numPinStates,
                             "2 per interface with a with_the_flux / expression PIN model, else 0.")
      .def("pin_index", &NetworkSystem::pinIndex, py::arg("interface"), py::arg("side"),
           "State index of the PIN density on side 0 (cell_i's) or 1 (cell_j's) of an interface.")
      .def("rhs",
           [](NetworkSystem& s, double t, const std::vector<double>& y) {
             const std::vector<double> state = checkedState(s, y);
             std::vector<double> ydot(s.size());
             s.rhs(t, state, ydot);
             return ydot;
           },
           py::arg("t"), py::arg("y"), "dy/dt at (t, y).")
      .def("jacobian",
           [](NetworkSystem& s, double t, const std::vector<double>& y) {
             const std::vector<double> state = checkedState(s, y);
             CsrMatrix J;
             s.jacobian(t, state, J);
             Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(s.size()),
                                                           static_cast<Eigen::Index>(s.size()));
             for (std::size_t r = 0; r < J.rows; ++r)
               for (std::size_t k = J.row_start[r]; k < J.row_start[r + 1]; ++k)
                 dense(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(J.column[k])) = J.value[k];
             return dense;
           },
           py::arg("t"), py::arg("y"), "dF/dy at (t, y) as a dense array (for small systems and checks).")
      .def("pin",
           [](const NetworkSystem& s, const std::vector<double>& y) {
             const auto sides = s.pin(checkedState(s, y));
             Eigen::MatrixXd out(static_cast<Eigen::Index>(sides.size()), 2);
             for (std::size_t k = 0; k < sides.size(); ++k) {
               out(static_cast<Eigen::Index>(k), 0) = sides[k].ij;
               out(static_cast<Eigen::Index>(k), 1) = sides[k].ji;
             }
             return out;
           },
           py::arg("y"),
           "PIN per interface (amount: wall measure times density): column 0 on cell_i's side (toward j), column 1 "
           "on cell_j's side.")
      .def("pin_density",
           [](const NetworkSystem& s, const std::vector<double>& y) {
             const auto sides = s.pinDensity(checkedState(s, y));
             Eigen::MatrixXd out(static_cast<Eigen::Index>(sides.size()), 2);
             for (std::size_t k = 0; k < sides.size(); ++k) {
               out(static_cast<Eigen::Index>(k), 0) = sides[k].ij;
               out(static_cast<Eigen::Index>(k), 1) = sides[k].ji;
             }
             return out;
           },
           py::arg("y"), "PIN per unit interface measure, columns as pin().")
      .def("polarity",
           [](const NetworkSystem& s, const std::vector<double>& y) {
             return vec3Array(s.polarity(checkedState(s, y)));
           },
           py::arg("y"), "Per cell, the sum of PIN times the outward unit normal of each interface, (n, 3).")
      .def("total_amount", [](const NetworkSystem& s, const std::vector<double>& y, std::size_t species) {
             return s.totalAmount(checkedState(s, y), species);
           },
           py::arg("y"), py::arg("species"))
      .def("integrate",
           [](NetworkSystem& s, const std::vector<double>& y, double t0, double t1, double rtol, double atol,
              long max_steps, const std::string& linear_solver) {
             std::vector<double> state = checkedState(s, y);
             IntegratorOptions o;
             o.relative_tolerance = rtol;
             o.absolute_tolerance = atol;
             o.max_steps = max_steps;
             o.linear_solver = linearSolvers().parse(linear_solver);
             NetworkIntegrator integrator(s, o);
             integrator.advance(state, t0, t1);
             return state;
           },
           py::arg("y"), py::arg("t0"), py::arg("t1"), py::arg("relative_tolerance") = 1e-6,
           py::arg("absolute_tolerance") = 1e-9, py::arg("max_steps") = 100000, py::arg("linear_solver") = "klu",
           "The amounts at t1 from y at t0 (a new list); tessella.Error naming the time, CVODE's flag, the "
           "species and the cell when CVODE fails. linear_solver: 'klu' (sparse LU) or 'gmres' (GMRES with a "
           "block-Jacobi preconditioner per cell).");

  using Point = std::array<double, 3>;
  auto vec = [](const Point& p) { return Vec3(p[0], p[1], p[2]); };
  m.def("axial_position",
        [vec](const Point& point, const Point& apex, const Point& axis) {
          const AxialPosition a = axialPosition(vec(point), vec(apex), vec(axis));
          return py::make_tuple(a.angle_deg, a.radius, a.distance);
        },
        py::arg("point"), py::arg("apex") = Point{0, 0, 0}, py::arg("axis") = Point{0, 0, 1},
        "(angle_deg in [0, 360) counterclockwise about the axis from the projected x axis, distance from the "
        "axis, distance from the apex).");
  m.def("divergence_deg", &divergenceDeg, py::arg("previous_angle_deg"), py::arg("angle_deg"),
        "(angle - previous) reduced to [0, 360).");
  m.def("find_primordia",
        [vec](const NetworkGraph& graph, const std::vector<double>& concentration, double threshold,
              double min_radius, double max_radius, double min_separation, const Point& apex, const Point& axis,
              const std::vector<Point>& existing) {
          PrimordiumOptions o;
          o.threshold = threshold;
          o.min_radius = min_radius;
          o.max_radius = max_radius;
          o.min_separation = min_separation;
          o.apex = vec(apex);
          o.axis = vec(axis);
          o.validate();
          std::vector<Vec3> e;
          for (const Point& p : existing) e.push_back(vec(p));
          return findPrimordia(graph, concentration, o, e);
        },
        py::arg("graph"), py::arg("concentration"), py::arg("threshold"), py::arg("min_radius") = 0.0,
        py::arg("max_radius") = 1e300, py::arg("min_separation") = 0.0, py::arg("apex") = Point{0, 0, 0},
        py::arg("axis") = Point{0, 0, 1}, py::arg("existing") = std::vector<Point>{},
        "Cells (graph indices) that start primordia: strict local maxima above the threshold, at a distance from "
        "the apex in [min_radius, max_radius], at least min_separation from the existing primordia and from "
        "each other (taken by decreasing concentration). docs/networks.md.");
}

}  // namespace tessella::python
