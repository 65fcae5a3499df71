// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Output from Python: single VTK snapshots and ParaView series.
#include "bindings.hpp"
#include "tessella/io/cell_complex_ply.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/series.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/io/wall_vtu.hpp"

namespace tessella::python {

namespace {

io::VtuOptions vtuOptions(const std::string& compression, int level) {
  io::VtuOptions o;
  o.compression = io::parseCompression(compression);
  o.compression_level = level;
  return o;
}

}  // namespace

py::dict importReportDict(const io::ImportReport& r) {
  py::dict report;
  report["path"] = r.path;
  report["format"] = r.format;
  report["file_vertices"] = r.file_vertices;
  report["file_faces"] = r.file_faces;
  report["file_faces_noun"] = r.file_faces_noun;
  report["simplified_vertices"] = r.simplified_vertices;
  report["repairs"] = r.repairs;
  report["notes"] = r.notes;
  return report;
}

void bindIo(py::module_& m) {
  m.def("write_vtu",
        [](const Tissue& t, const std::string& path, const std::string& compression, int level) {
          io::writeTissueVtu(t, path, vtuOptions(compression, level));
        },
        py::arg("tissue"), py::arg("path"), py::arg("compression") = std::string(io::compressionName(io::VtuOptions{}.compression)), py::arg("compression_level") = 5,
        "One .vtu snapshot with every writable cell and vertex property (written atomically).");
  m.def("read_vtu", &io::readTissueVtu, py::arg("path"), "A tissue back from a snapshot written by write_vtu.");
  m.def(
      "read_walls",
      [](const std::string& path) {
        const io::WallsFile f = io::readWallsVtu(path);
        py::dict d;
        d["wall_id"] = py::array_t<int>(static_cast<py::ssize_t>(f.wall_id.size()), f.wall_id.data());
        for (const auto& [name, values] : f.arrays.scalars)
          d[py::str(name)] = py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
        for (const auto& [name, values] : f.arrays.vectors) d[py::str(name)] = vec3Copy(values);
        for (const auto& [name, values] : f.arrays.tensors) {
          py::array_t<double> a({static_cast<py::ssize_t>(values.size()), py::ssize_t{3}, py::ssize_t{3}});
          auto r = a.mutable_unchecked<3>();
          for (std::size_t i = 0; i < values.size(); ++i) {
            const Mat3 m3 = values[i].matrix();
            for (int j = 0; j < 3; ++j)
              for (int k = 0; k < 3; ++k) r(static_cast<py::ssize_t>(i), j, k) = m3(j, k);
          }
          d[py::str(name)] = a;
        }
        return d;
      },
      py::arg("path"), R"doc(
The arrays of a walls file (<stem>.pin.vtu, <stem>.walls.vtu; docs/output.md) as a dict of NumPy arrays, one row
per wall in the file's order: wall_id (the wall's slot), scalars (n,), vectors (n, 3), symmetric tensors (n, 3, 3).
)doc");

  m.def("import_tissue_with_report",
        [](const std::string& path, const std::string& format, double scale, double simplify, bool repair,
           const std::string& label_array) {
          io::ImportResult r =
              io::importTissue(path, io::ImportOptions{format, scale, simplify, repair, label_array});
          return py::make_tuple(std::move(r.tissue), importReportDict(r.report));
        },
        py::arg("path"), py::arg("format") = "auto", py::arg("scale") = 1.0, py::arg("simplify") = 0.0,
        py::arg("repair") = false, py::arg("label_array") = "", R"doc(
Imports a segmented tissue (docs/import.md) and returns (tissue, report): the
report is a dict with path, format, file_vertices, file_faces (file_faces_noun:
what they count), simplified_vertices, repairs (one line per repair) and notes.
)doc");
  m.def("import_tissue",
        [](const std::string& path, const std::string& format, double scale, double simplify, bool repair,
           const std::string& label_array) {
          return io::importTissue(path, io::ImportOptions{format, scale, simplify, repair, label_array}).tissue;
        },
        py::arg("path"), py::arg("format") = "auto", py::arg("scale") = 1.0, py::arg("simplify") = 0.0,
        py::arg("repair") = false, py::arg("label_array") = "", R"doc(
Imports a segmented tissue from another tool's file. format: "auto" (from the
extension and, for .ply, the properties) or one of import_formats(). Cells keep
their label as the cell property "label" (and "parent" where the file has one).
scale multiplies positions; simplify (> 0) simplifies wall polylines between
junctions; repair fixes harmless defects (see import_tissue_with_report).
label_array names the face property / cell-data array holding the cell labels
(labelled_mesh, labelled_vtu; "A,B" for the cells on either side of each face).
Raises InputError naming the file, element and cell label on bad input.
)doc");
  m.def("import_formats", &io::importFormatNames, "The names import_tissue accepts as format (auto first).");
  m.def("export_cell_complex",
        [](const Tissue& t, const std::string& path, bool binary) {
          const io::CellComplexPlyInfo info = io::writeCellComplexPly(t, path, io::CellComplexPlyOptions{binary});
          py::dict out;
          out["vertices"] = info.vertices;
          out["edges"] = info.edges;
          out["faces"] = info.faces;
          out["volumes"] = info.volumes;
          out["label_source"] = info.label_source;
          return out;
        },
        py::arg("tissue"), py::arg("path"), py::arg("binary") = false, R"doc(
Writes the tissue as a cell-complex PLY file (OpenAlea property topomesh
layout; import_tissue reads it back, docs/import.md): a 3D tissue as closed
volumes sharing their walls, a 2D tissue as one single-polygon volume per cell.
Volume labels are the int64 cell property "label" when every cell has its
own, else the lineage ids. Returns the counts written and label_source.
)doc");

  py::class_<io::SeriesWriter>(m, "SeriesWriter", R"doc(
A ParaView time series: DIRECTORY/NAME.pvd listing NAME_000000.vtu, ... with
the time of each snapshot. The .pvd is rewritten after every write, so an
interrupted run leaves an openable series.
)doc")
      .def(py::init([](const std::string& directory, const std::string& name, const std::string& compression, int level) {
             return io::SeriesWriter(directory, name, vtuOptions(compression, level));
           }),
           py::arg("directory"), py::arg("name") = "tissue", py::arg("compression") = std::string(io::compressionName(io::VtuOptions{}.compression)),
           py::arg("compression_level") = 5)
      .def(
          "write",
          [](io::SeriesWriter& w, const Tissue& t, std::optional<double> time) { return w.write(t, time.value_or(t.time())); },
          py::arg("tissue"), py::arg("time") = py::none(), "Writes one snapshot (at tissue.time by default); returns its path.")
      .def_property_readonly("pvd_path", &io::SeriesWriter::pvdPath)
      .def_property_readonly("steps", &io::SeriesWriter::steps, "Snapshots written so far.");
}

}  // namespace tessella::python
