// Output from Python: single VTK snapshots and ParaView series.
#include "bindings.hpp"
#include "tessella/io/series.hpp"
#include "tessella/io/vtu.hpp"

namespace tessella::python {

namespace {

io::VtuOptions vtuOptions(const std::string& compression, int level) {
  io::VtuOptions o;
  o.compression = io::parseCompression(compression);
  o.compression_level = level;
  return o;
}

}  // namespace

void bindIo(py::module_& m) {
  m.def("write_vtu",
        [](const Tissue& t, const std::string& path, const std::string& compression, int level) {
          io::writeTissueVtu(t, path, vtuOptions(compression, level));
        },
        py::arg("tissue"), py::arg("path"), py::arg("compression") = "lz4", py::arg("compression_level") = 5,
        "One .vtu snapshot with every writable cell and vertex property (written atomically).");
  m.def("read_vtu", &io::readTissueVtu, py::arg("path"), "A tissue back from a snapshot written by write_vtu.");

  py::class_<io::SeriesWriter>(m, "SeriesWriter", R"doc(
A ParaView time series: DIRECTORY/NAME.pvd listing NAME_000000.vtu, ... with
the time of each snapshot. The .pvd is rewritten after every write, so an
interrupted run leaves an openable series.
)doc")
      .def(py::init([](const std::string& directory, const std::string& name, const std::string& compression, int level) {
             return io::SeriesWriter(directory, name, vtuOptions(compression, level));
           }),
           py::arg("directory"), py::arg("name") = "tissue", py::arg("compression") = "lz4",
           py::arg("compression_level") = 5)
      .def(
          "write",
          [](io::SeriesWriter& w, const Tissue& t, std::optional<double> time) { return w.write(t, time.value_or(t.time())); },
          py::arg("tissue"), py::arg("time") = py::none(), "Writes one snapshot (at tissue.time by default); returns its path.")
      .def_property_readonly("pvd_path", &io::SeriesWriter::pvdPath)
      .def_property_readonly("steps", &io::SeriesWriter::steps, "Snapshots written so far.");
}

}  // namespace tessella::python
