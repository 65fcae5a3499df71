// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shared pieces of the Python module `tessella`: one bind function per C++
// module, and the conversions every binding file uses (handles as plain
// slot indices, Vec3 arrays as (n, 3) float64 NumPy arrays).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <span>
#include <string>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::io {
struct ImportReport;
}

namespace tessella::python {

namespace py = pybind11;

void bindErrors(py::module_& m);
/// Defines tessella.Tissue; bindProperties adds the property methods to it.
py::class_<Tissue> bindTissue(py::module_& m);
void bindProperties(py::class_<Tissue>& cls);
void bindGenerators(py::module_& m);
void bindGrowth(py::module_& m);
void bindDivision(py::module_& m);
void bindIo(py::module_& m);
void bindSim(py::module_& m);
void bindMesh(py::module_& m);
void bindFieldTransfer(py::module_& m);
void bindLinearSolver(py::module_& m);
void bindDiffusion(py::module_& m);
void bindCompartments(py::module_& m);
void bindNetworks(py::module_& m);
void bindElasticity(py::module_& m);
void bindLabelImage(py::module_& m);

/// An import's report as the dict every importer returns beside its tissue
/// (path, format, file counts, simplified vertices, repairs, notes).
py::dict importReportDict(const io::ImportReport& report);

/// Python code names cells by their slot index; a dead or out-of-range one
/// is bad input (ValueError), never undefined behaviour.
inline CellId checkedCell(const Tissue& t, long long index) {
  if (index < 0 || static_cast<std::size_t>(index) >= t.cellSlots() ||
      !t.alive(CellId(static_cast<Index>(index))))
    throw InputError("cell " + std::to_string(index) + " is not a live cell (the tissue has " +
                     std::to_string(t.cellSlots()) + " cell slots, " + std::to_string(t.numCells()) +
                     " live)");
  return CellId(static_cast<Index>(index));
}

inline VertexId checkedVertex(const Tissue& t, long long index) {
  if (index < 0 || static_cast<std::size_t>(index) >= t.slots(0) ||
      !t.alive(VertexId(static_cast<Index>(index))))
    throw InputError("vertex " + std::to_string(index) + " is not a live vertex (the tissue has " +
                     std::to_string(t.slots(0)) + " vertex slots)");
  return VertexId(static_cast<Index>(index));
}

/// A copy of Vec3s as an (n, 3) array (owned by NumPy).
inline py::array_t<double> vec3Copy(std::span<const Vec3> v) {
  py::array_t<double> out({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto r = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) r(static_cast<py::ssize_t>(i), k) = v[i][k];
  return out;
}

/// An (n, 3) float64 array as Vec3s; `what` names the argument in errors.
inline std::vector<Vec3> vec3FromArray(const py::handle& obj, const std::string& what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) throw InputError(what + ": expected an (n, 3) array of numbers");
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw InputError(what + ": expected an (n, 3) array, got shape " +
                     std::string(py::str(py::cast(a.request().shape))));
  std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) v[i] = Vec3(r(i, 0), r(i, 1), r(i, 2));
  return v;
}

/// A view of a Vec3 vector as an (n, 3) array sharing its memory; `base`
/// keeps the owner alive as long as the array lives.
inline py::array_t<double> vec3View(Vec3* data, std::size_t n, py::handle base, bool writable) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  py::array_t<double> a({static_cast<py::ssize_t>(n), py::ssize_t{3}},
                        {static_cast<py::ssize_t>(sizeof(Vec3)), static_cast<py::ssize_t>(sizeof(double))},
                        reinterpret_cast<double*>(data), base);
  if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

}  // namespace tessella::python
