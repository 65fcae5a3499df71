// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Meshing from Python: MeshOptions, mesh_tissue() -> FeMesh (its arrays as
// NumPy copies), mesh measures and .vtu output of a mesh with nodal,
// element and facet fields.
#include <cctype>
#include <map>
#include <string>

#include "bindings.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/mesh/mesh_tissue.hpp"

namespace tessella::python {

// The API bound in this file, by its own names.
using namespace tessella::mesh;

namespace {

std::vector<double> perItem(int n, const auto& f) {
  std::vector<double> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = f(i);
  return out;
}

py::array_t<double> asArray(const std::vector<double>& v) { return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data()); }

}  // namespace

void bindMesh(py::module_& m) {
  py::enum_<VolumeMethod> volume_method_enum(m, "VolumeMethod",
                                             "How a 3D tissue is filled with tetrahedra (docs/meshing.md).");
  for (const auto& e : mesh::volumeMethods().entries()) {
    std::string upper = e.name;  // cell_by_cell -> CELL_BY_CELL
    for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    volume_method_enum.value(upper.c_str(), e.value);
  }
  py::class_<MeshOptions>(m, "MeshOptions", "Size and quality targets of a tissue mesh (docs/meshing.md).")
      .def(py::init([](double min_angle_degrees, double max_edge_length, double max_volume, double radius_edge_ratio,
                       double min_dihedral_degrees, double tolerance, VolumeMethod volume_method,
                       std::size_t max_elements, double cell_time_limit, double time_limit) {
             // Designated: a field added to MeshOptions cannot shift the others.
             MeshOptions o{.min_angle_degrees = min_angle_degrees, .max_edge_length = max_edge_length,
                           .max_volume = max_volume, .radius_edge_ratio = radius_edge_ratio,
                           .min_dihedral_degrees = min_dihedral_degrees, .tolerance = tolerance,
                           .volume_method = volume_method, .max_elements = max_elements,
                           .cell_time_limit = cell_time_limit, .time_limit = time_limit};
             validateMeshOptions(o);
             return o;
           }),
           py::arg("min_angle_degrees") = 20.0, py::arg("max_edge_length") = 0.0, py::arg("max_volume") = 0.0,
           py::arg("radius_edge_ratio") = 1.5, py::arg("min_dihedral_degrees") = 0.0, py::arg("tolerance") = 1e-10,
           py::arg("volume_method") = mesh::VolumeMethod::CellByCell, py::arg("max_elements") = kDefaultMaxElements,
           py::arg("cell_time_limit") = kDefaultCellTimeLimit, py::arg("time_limit") = kDefaultTimeLimit)
      .def_readwrite("min_angle_degrees", &MeshOptions::min_angle_degrees, "2D/surface: lower bound on triangle angles.")
      .def_readwrite("max_edge_length", &MeshOptions::max_edge_length, "2D/surface: edge length bound (0 = none).")
      .def_readwrite("max_volume", &MeshOptions::max_volume, "3D: tetrahedron volume bound (0 = none).")
      .def_readwrite("radius_edge_ratio", &MeshOptions::radius_edge_ratio, "3D: circumradius / shortest edge bound (> 1).")
      .def_readwrite("min_dihedral_degrees", &MeshOptions::min_dihedral_degrees)
      .def_readwrite("tolerance", &MeshOptions::tolerance)
      .def_readwrite("volume_method", &MeshOptions::volume_method, "3D: VolumeMethod.CELL_BY_CELL or WHOLE_TISSUE.")
      .def_readwrite("max_elements", &MeshOptions::max_elements,
                     "Refuse (InputError) a mesh estimated above this many elements, before meshing (0 = no limit).")
      .def_readwrite("cell_time_limit", &MeshOptions::cell_time_limit,
                     "3D, cell by cell: seconds one cell's TetGen tries may take together (0 = no limit).")
      .def_readwrite("time_limit", &MeshOptions::time_limit,
                     "3D: seconds all TetGen runs of one mesh may take together (0 = no limit).");

  py::class_<FeMesh>(m, "FeMesh", R"doc(
A finite-element mesh of a tissue: triangles (dim 2, flat or on a surface) or
tetrahedra (dim 3). Array properties are NumPy copies:
  nodes (n, 3), elements (m, dim+1), element_cell (m,), wall_facets (f, dim),
  facet_wall (f,), facet_on_boundary (f,) bool, node_vertex (n,) (-1: mesher node).
FeMesh(nodes, elements, element_cell, ...) builds one from arrays (checked).
)doc")
      .def(py::init([](int dim, RowMatrix<double> nodes, RowMatrix<int> elements, Eigen::VectorXi element_cell,
                       std::optional<RowMatrix<int>> wall_facets, std::optional<Eigen::VectorXi> facet_wall,
                       std::optional<Eigen::Matrix<bool, Eigen::Dynamic, 1>> facet_on_boundary,
                       std::optional<Eigen::VectorXi> node_vertex) {
             FeMesh mesh;
             mesh.dim = dim;
             mesh.nodes = std::move(nodes);
             mesh.elements = std::move(elements);
             mesh.element_cell = std::move(element_cell);
             mesh.wall_facets = wall_facets.value_or(RowMatrix<int>(0, dim));
             mesh.facet_wall = facet_wall.value_or(Eigen::VectorXi(0));
             mesh.facet_on_boundary = facet_on_boundary.value_or(Eigen::Matrix<bool, Eigen::Dynamic, 1>(0));
             mesh.node_vertex = node_vertex.value_or(Eigen::VectorXi::Constant(mesh.nodes.rows(), -1));
             if (dim != 2 && dim != 3) throw InputError("FeMesh: dim must be 2 or 3, got " + std::to_string(dim));
             io::checkFeMesh(mesh);
             return mesh;
           }),
           py::arg("dim"), py::arg("nodes"), py::arg("elements"), py::arg("element_cell"), py::arg("wall_facets") = py::none(),
           py::arg("facet_wall") = py::none(), py::arg("facet_on_boundary") = py::none(), py::arg("node_vertex") = py::none())
      .def_readonly("dim", &FeMesh::dim)
      .def_property_readonly("num_nodes", &FeMesh::numNodes)
      .def_property_readonly("num_elements", &FeMesh::numElements)
      .def_property_readonly("num_wall_facets", &FeMesh::numWallFacets)
      .def_property_readonly("nodes", [](const FeMesh& f) { return RowMatrix<double>(f.nodes); })
      .def_property_readonly("elements", [](const FeMesh& f) { return RowMatrix<int>(f.elements); })
      .def_property_readonly("element_cell", [](const FeMesh& f) { return Eigen::VectorXi(f.element_cell); })
      .def_property_readonly("wall_facets", [](const FeMesh& f) { return RowMatrix<int>(f.wall_facets); })
      .def_property_readonly("facet_wall", [](const FeMesh& f) { return Eigen::VectorXi(f.facet_wall); })
      .def_property_readonly("facet_on_boundary",
                             [](const FeMesh& f) { return Eigen::Matrix<bool, Eigen::Dynamic, 1>(f.facet_on_boundary); })
      .def_property_readonly("node_vertex", [](const FeMesh& f) { return Eigen::VectorXi(f.node_vertex); })
      .def("element_measures",
           [](const FeMesh& f) { return asArray(perItem(f.numElements(), [&](int e) { return elementMeasure(f, e); })); },
           "Area (triangles) or volume (tetrahedra) of every element.")
      .def("wall_facet_measures",
           [](const FeMesh& f) { return asArray(perItem(f.numWallFacets(), [&](int i) { return wallFacetMeasure(f, i); })); },
           "Length (dim 2) or area (dim 3) of every wall facet.")
      .def("cell_measures", [](const FeMesh& f, std::size_t slots) { return asArray(cellMeasuresOfMesh(f, slots)); },
           py::arg("cell_slots") = 0, "Sum of element measures per cell index (compare with Tissue.cell_measures).")
      .def("total_measure", &totalMeasureOfMesh)
      .def("min_angles",
           [](const FeMesh& f) {
             if (f.dim != 2) throw InputError("FeMesh.min_angles: needs triangles (dim 2), the mesh has dim 3");
             return asArray(perItem(f.numElements(), [&](int e) { return triangleMinAngleDegrees(f, e); }));
           },
           "Smallest angle (degrees) of every triangle.")
      .def("radius_edge_ratios",
           [](const FeMesh& f) {
             if (f.dim != 3) throw InputError("FeMesh.radius_edge_ratios: needs tetrahedra (dim 3), the mesh has dim 2");
             return asArray(perItem(f.numElements(), [&](int e) { return tetRadiusEdgeRatio(f, e); }));
           },
           "Circumradius / shortest edge of every tetrahedron.")
      .def("__repr__", [](const FeMesh& f) {
        return "FeMesh(dim=" + std::to_string(f.dim) + ", nodes=" + std::to_string(f.numNodes()) +
               ", elements=" + std::to_string(f.numElements()) + ", wall_facets=" + std::to_string(f.numWallFacets()) + ")";
      });

  m.def("mesh_tissue", &meshTissue, py::arg("tissue"), py::arg("options") = MeshOptions{},
        "A conforming mesh of any tissue (triangles for planar and surface tissues, tetrahedra for volume "
        "ones); bad geometry raises GeometryError naming the cell or wall.");

  m.def("write_mesh_vtu",
        [](const FeMesh& mesh, const std::string& path, std::map<std::string, Eigen::VectorXd> point_data,
           std::map<std::string, Eigen::VectorXd> element_data, std::map<std::string, Eigen::VectorXd> facet_data,
           std::optional<std::string> walls_path, const std::string& compression, int level) {
          io::MeshFields fields{std::move(point_data), std::move(element_data), std::move(facet_data)};
          io::VtuOptions o;
          o.compression = io::parseCompression(compression);
          o.compression_level = level;
          io::checkFeMesh(mesh, fields);
          io::writeFeMeshVtu(mesh, path, fields, o);
          if (walls_path) io::writeWallFacetsVtu(mesh, *walls_path, fields, o);
        },
        py::arg("mesh"), py::arg("path"), py::arg("point_data") = std::map<std::string, Eigen::VectorXd>{},
        py::arg("element_data") = std::map<std::string, Eigen::VectorXd>{},
        py::arg("facet_data") = std::map<std::string, Eigen::VectorXd>{}, py::arg("walls_path") = py::none(),
        py::arg("compression") = std::string(io::compressionName(io::VtuOptions{}.compression)), py::arg("compression_level") = 5,
        "Writes the elements (cell_id, vertex_id and the given fields) as .vtu, and the wall facets to "
        "walls_path when given. Fields are dicts name -> array (one value per node / element / facet).");
}

}  // namespace tessella::python
