// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Generators: grids, Voronoi tissues of random or given seeds, dome sheets.
// Seeds travel as (n, 3) float64 arrays (z = 0 for 2D domains).
#include "bindings.hpp"
#include "tessella/generators/dome.hpp"
#include "tessella/generators/generator_registry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"

namespace tessella::python {

namespace {

VoronoiOptions voronoiOptions(int lloyd, double duplicate_tolerance) {
  return VoronoiOptions{.lloyd_iterations = lloyd, .duplicate_tolerance = duplicate_tolerance};
}

template <typename Domain>
void bindVoronoi(py::module_& m) {
  m.def("random_seeds",
        [](const Domain& d, std::size_t count, std::uint64_t seed) { return vec3Copy(randomSeeds(d, count, seed)); },
        py::arg("domain"), py::arg("count"), py::arg("rng_seed"));
  m.def("voronoi_tissue",
        [](py::handle seeds, const Domain& d, int lloyd, double tol) {
          const std::vector<Vec3> s = vec3FromArray(seeds, "voronoi_tissue: seeds");
          return voronoiTissue(s, d, voronoiOptions(lloyd, tol));
        },
        py::arg("seeds"), py::arg("domain"), py::arg("lloyd_iterations") = 0, py::arg("duplicate_tolerance") = 1e-9);
}

// A Python dict of parameters as ParamValues: bool, int, float, str, or a
// sequence of numbers (a vector). The generator's table checks the rest.
ParamValues paramValues(const py::dict& params) {
  ParamValues values;
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key);
    if (py::isinstance<py::bool_>(value))
      values.set(name, value.cast<bool>());
    else if (py::isinstance<py::int_>(value))
      values.set(name, value.cast<std::int64_t>());
    else if (py::isinstance<py::float_>(value))
      values.set(name, value.cast<double>());
    else if (py::isinstance<py::str>(value))
      values.set(name, value.cast<std::string>());
    else
      values.set(name, value.cast<std::vector<double>>());
  }
  return values;
}

// generate()'s docstring: every generator of the table with its parameters.
std::string generateDoc() {
  std::string doc =
      "generate(name, params={}, rng_seed=0): the tissue of the generator `name`, as `tissue.generator: name` "
      "with the keys `params` of its section in a configuration (docs/config.md). `rng_seed` draws random "
      "seed points. Generators:\n";
  for (const auto& g : generators().entries()) {
    doc += "\n" + g.name + ": " + g.doc + "\n  parameters:";
    for (const ParamSpec& p : g.params) doc += " " + p.name;
    doc += "\n";
  }
  return doc;
}

}  // namespace

void bindGenerators(py::module_& m) {
  m.def("rectangular_grid", &rectangularGrid, py::arg("nx"), py::arg("ny"), py::arg("dx") = 1.0, py::arg("dy") = 1.0,
        py::arg("origin") = Vec3(Vec3::Zero()), "nx x ny rectangular cells of size dx x dy (planar).");
  m.def("hexagonal_grid", &hexagonalGrid, py::arg("nx"), py::arg("ny"), py::arg("radius") = 1.0,
        py::arg("origin") = Vec3(Vec3::Zero()), "nx x ny regular hexagons of circumradius `radius` (planar).");
  m.def("box_grid", &boxGrid, py::arg("nx"), py::arg("ny"), py::arg("nz"), py::arg("dx") = 1.0, py::arg("dy") = 1.0,
        py::arg("dz") = 1.0, py::arg("origin") = Vec3(Vec3::Zero()), "nx x ny x nz box cells (3D).");

  py::class_<Rectangle>(m, "Rectangle", "Axis-aligned rectangle in the z = 0 plane.")
      .def(py::init([](const Vec3& lo, const Vec3& hi) { return Rectangle{lo, hi}; }), py::arg("min"), py::arg("max"))
      .def_readwrite("min", &Rectangle::min)
      .def_readwrite("max", &Rectangle::max);
  py::class_<Disk>(m, "Disk", "Disk in the z = 0 plane (a polygon of boundary_segments sides).")
      .def(py::init([](const Vec3& c, double r, int segments) { return Disk{c, r, segments}; }),
           py::arg("center") = Vec3(Vec3::Zero()), py::arg("radius") = 1.0, py::arg("boundary_segments") = 256)
      .def_readwrite("center", &Disk::center)
      .def_readwrite("radius", &Disk::radius);
  py::class_<Box>(m, "Box", "Axis-aligned box.")
      .def(py::init([](const Vec3& lo, const Vec3& hi) { return Box{lo, hi}; }), py::arg("min"), py::arg("max"))
      .def_readwrite("min", &Box::min)
      .def_readwrite("max", &Box::max);
  py::class_<Ball>(m, "Ball", "Ball (an icosphere of `subdivisions` levels).")
      .def(py::init([](const Vec3& c, double r, int sub) { return Ball{c, r, sub}; }),
           py::arg("center") = Vec3(Vec3::Zero()), py::arg("radius") = 1.0, py::arg("subdivisions") = 3)
      .def_readwrite("center", &Ball::center)
      .def_readwrite("radius", &Ball::radius);
  bindVoronoi<Rectangle>(m);
  bindVoronoi<Disk>(m);
  bindVoronoi<Box>(m);
  bindVoronoi<Ball>(m);
  m.def("read_seeds_csv", [](const std::string& path, int dim) { return vec3Copy(readSeedsCsv(path, dim)); },
        py::arg("path"), py::arg("dim"), "Seeds from a CSV file of x,y (dim 2) or x,y,z (dim 3) rows.");

  py::class_<Dome>(m, "Dome", "A spherical-cap or paraboloid dome over a footprint disk (meristem models).")
      .def(py::init([](const std::string& shape, double base_radius, double height, const Vec3& center) {
             Dome d;
             d.shape = domeShapes().parse(shape);
             d.base_radius = base_radius;
             d.height = height;
             d.base_center = center;
             return d;
           }),
           py::arg("shape") = "spherical_cap", py::arg("base_radius") = 1.0, py::arg("height") = 0.5,
           py::arg("base_center") = Vec3(Vec3::Zero()))
      .def_readwrite("base_radius", &Dome::base_radius)
      .def_readwrite("height", &Dome::height)
      .def_readwrite("base_center", &Dome::base_center)
      .def_property_readonly("summit", [](const Dome& d) { return Vec3(d.base_center + Vec3(0, 0, d.height)); })
      .def("height_at", &Dome::heightAt, py::arg("r"))
      .def("lift", &Dome::lift, py::arg("point"));
  m.def("dome_tissue",
        [](py::handle seeds, const Dome& dome, int lloyd, double tol) {
          const std::vector<Vec3> s = vec3FromArray(seeds, "dome_tissue: footprint_seeds");
          return domeTissue(s, dome, voronoiOptions(lloyd, tol));
        },
        py::arg("footprint_seeds"), py::arg("dome"), py::arg("lloyd_iterations") = 0,
        py::arg("duplicate_tolerance") = 1e-9, "A Voronoi sheet of the footprint disk lifted onto the dome (surface).");

  static const std::string generate_doc = generateDoc();  // pybind11 keeps the pointer
  m.def(
      "generate",
      [](const std::string& name, const py::dict& params, std::uint64_t rng_seed) {
        return generators().make(name, paramValues(params), rng_seed);
      },
      py::arg("name"), py::arg("params") = py::dict(), py::arg("rng_seed") = 0, generate_doc.c_str());
}

}  // namespace tessella::python
