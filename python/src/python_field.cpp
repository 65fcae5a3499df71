// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "python_field.hpp"

namespace tessella::python {

PythonField::PythonField(py::function fn, std::string description)
    : fn_(std::move(fn)), description_(std::move(description)) {}

PythonField::~PythonField() {
  // The last owner may be a C++ object released without the GIL.
  py::gil_scoped_acquire gil;
  fn_ = py::function();
}

Vec3 PythonField::velocity(const Vec3& x, double t) const {
  Vec3 v;
  velocities(std::span<const Vec3>(&x, 1), t, std::span<Vec3>(&v, 1));
  return v;
}

void PythonField::velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const {
  py::gil_scoped_acquire gil;
  // A read-only copy: the function must not keep or edit the integrator's buffers.
  py::array_t<double> points = vec3Copy(x);
  py::detail::array_proxy(points.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  py::object result = fn_(points, t);
  auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(result);
  if (!v || v.ndim() != 2 || static_cast<std::size_t>(v.shape(0)) != x.size() || v.shape(1) != 3)
    throw InputError("velocity field '" + description_ + "': the function must return an (n, 3) array of numbers for " +
                     std::to_string(x.size()) + " points, got " +
                     std::string(py::str(v ? py::object(py::cast(v.request().shape)) : py::object(py::type::of(result)))));
  auto r = v.unchecked<2>();
  for (std::size_t i = 0; i < x.size(); ++i) {
    out[i] = Vec3(r(i, 0), r(i, 1), r(i, 2));
    if (!out[i].allFinite())
      throw InputError("velocity field '" + description_ + "': non-finite velocity at point " + std::to_string(i));
  }
}

}  // namespace tessella::python
