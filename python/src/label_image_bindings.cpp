// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Label images from Python: a NumPy integer array (or an image file) with a
// pixel or voxel size into a planar or 3D tissue (docs/import.md, "Label images").
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::python {

namespace {

io::LabelImage imageFromArray(const py::array& array, const std::optional<std::vector<double>>& voxel_size,
                              const std::optional<std::vector<double>>& origin) {
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError("label image array: dtype " + std::string(py::str(array.dtype())) +
                     " is not an integer type (a label image holds one integer label per pixel)");
  if (array.ndim() != 2 && array.ndim() != 3)
    throw InputError("label image array: " + std::to_string(array.ndim()) +
                     " dimensions; give a 2D array [y, x] or a 3D one [z, y, x]");
  io::LabelImage img;
  img.name = "label image array";
  const auto n = array.ndim();
  img.dims = {static_cast<std::int64_t>(array.shape(n - 1)), static_cast<std::int64_t>(array.shape(n - 2)),
              n == 3 ? static_cast<std::int64_t>(array.shape(0)) : 1};
  if (kind == 'u' && array.itemsize() == 8) {
    auto a = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    const std::uint64_t* data = a.data();
    img.labels.resize(static_cast<std::size_t>(a.size()));
    for (std::size_t k = 0; k < img.labels.size(); ++k) {
      if (data[k] > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        throw InputError("label image array: label " + std::to_string(data[k]) + " is beyond a 64-bit signed integer");
      img.labels[k] = static_cast<std::int64_t>(data[k]);
    }
  } else {
    auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    img.labels.assign(a.data(), a.data() + a.size());
  }
  if (voxel_size) {
    if (voxel_size->size() != 2 && voxel_size->size() != 3)
      throw InputError("label image array: voxel_size needs 2 or 3 numbers (x, y[, z]), got " +
                       std::to_string(voxel_size->size()));
    for (std::size_t k = 0; k < voxel_size->size(); ++k) img.spacing[k] = (*voxel_size)[k];
    for (std::size_t k = 0; k < voxel_size->size(); ++k)
      if (!(img.spacing[k] > 0)) img.spacing[k] = 1;  // the option's own check names the bad value
  }
  // Default origin: the image spans [0, nx * sx] x [0, ny * sy] (x [0, nz * sz] in 3D).
  for (int k = 0; k < 3; ++k) img.origin[k] = k < 2 || img.dims[2] > 1 ? img.spacing[k] / 2 : 0.0;
  if (origin) {
    if (origin->size() != 2 && origin->size() != 3)
      throw InputError("label image array: origin needs 2 or 3 numbers, got " + std::to_string(origin->size()));
    for (std::size_t k = 0; k < origin->size(); ++k) img.origin[k] = (*origin)[k];
  }
  return img;
}

}  // namespace

void bindLabelImage(py::module_& m) {
  m.def(
      "tissue_from_label_image_with_report",
      [](const py::object& image, std::optional<std::vector<double>> voxel_size,
         std::optional<std::vector<double>> origin, std::vector<std::int64_t> background,
         std::vector<std::int64_t> drop_labels, std::int64_t min_cell_size, const std::string& small_cells,
         std::optional<std::vector<std::int64_t>> crop, bool keep_pieces, double simplify, double scale) {
        io::ImportOptions o;
        o.format = "label_image";
        o.scale = scale;
        o.simplify = simplify;
        o.image.background = std::move(background);
        o.image.drop_labels = std::move(drop_labels);
        o.image.min_cell_size = min_cell_size;
        o.image.small_cells = small_cells;
        o.image.keep_pieces = keep_pieces;
        if (crop) o.image.crop = *crop;
        io::LabelImage img;
        if (py::isinstance<py::str>(image) || py::hasattr(image, "__fspath__")) {
          if (origin) throw InputError("origin applies to arrays; an image file gives its own");
          img = io::readLabelImage(py::str(image).cast<std::string>());
        } else {
          img = imageFromArray(py::array::ensure(image), voxel_size, origin);
        }
        if (voxel_size) o.image.voxel_size = *voxel_size;  // checked (and named) as an option
        io::ImportResult r = io::tissueFromLabelImage(std::move(img), o);
        r.report.format = "label_image";
        return py::make_tuple(std::move(r.tissue), importReportDict(r.report));
      },
      py::arg("image"), py::arg("voxel_size") = py::none(), py::arg("origin") = py::none(),
      py::arg("background") = std::vector<std::int64_t>{0, 1}, py::arg("drop_labels") = std::vector<std::int64_t>{},
      py::arg("min_cell_size") = 0, py::arg("small_cells") = "drop", py::arg("crop") = py::none(),
      py::arg("keep_pieces") = false, py::arg("simplify") = 0.0, py::arg("scale") = 1.0, R"doc(
A tissue from a label image (docs/import.md, "Label images") and a report
dict (path, format, file_faces = pixels or voxels, simplified_vertices,
notes): a planar tissue from a 2D image, a 3D tissue from a 3D one.
image: a NumPy integer array indexed [y, x] or [z, y, x] (one z layer: 2D),
or the path of an image file (.tif, .nrrd, .mha, .mhd, .vti). voxel_size:
(sx, sy) or, for a 3D image, (sx, sy, sz), in x, y, z order (an array:
default 1 each; a file: overrides the file's). origin (arrays only): the
centre of voxel [0, 0(, 0)]; by default half a voxel, so the image spans
[0, nx*sx] x [0, ny*sy] (x [0, nz*sz]). background: labels that are no cell;
drop_labels: labels made background; min_cell_size (pixels or voxels) with
small_cells "drop" or "merge"; crop: (x0, y0, x1, y1), or in 3D
(x0, y0, z0, x1, y1, z1), the voxels x0 <= x < x1, ...; keep_pieces: one cell
per disconnected piece of a label instead of an error; simplify: tolerance in
pixels (voxels) for the wall polylines (2D) or junction lines (3D). Cells
keep their label as the cell property "label". Raises InputError naming the
image, the label and the value.
)doc");
  m.def(
      "tissue_from_label_image",
      [](py::args args, py::kwargs kwargs) {
        py::module_ tessella = py::module_::import("tessella");
        const py::tuple result = tessella.attr("tissue_from_label_image_with_report")(*args, **kwargs);
        return py::object(result[0]);
      },
      "tissue_from_label_image_with_report(...)[0]: the tissue only (same arguments).");
}

}  // namespace tessella::python
