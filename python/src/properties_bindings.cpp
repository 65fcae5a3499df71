// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Property columns from Python: add with a division policy, read as a NumPy
// copy or view, write from an array. One column type per NumPy dtype:
//   float64 <-> double, int64 <-> int64, int32 <-> int (C++ `int`),
//   uint8 <-> flags, "vec3" <-> Vec3 ((n, 3) float64), "sym3" <-> Sym3 (a
//   symmetric tensor: (n, 3, 3) float64; set from the upper triangle).
// `degree` selects the element kind (0 vertices, 1 edges, 2 faces, 3
// volumes); None means the cells (dim) and "wall" the walls (dim - 1).
#include <cstdint>
#include <typeindex>

#include "bindings.hpp"
#include "deferred_error.hpp"

namespace tessella::python {

namespace {

int resolveDegree(const Tissue& t, const py::object& degree) {
  if (degree.is_none()) return t.cellDegree();
  if (py::isinstance<py::str>(degree)) {
    const std::string s = degree.cast<std::string>();
    if (s == "cell") return t.cellDegree();
    if (s == "wall") return t.wallDegree();
    if (s == "vertex") return 0;
    throw InputError("degree: expected 0..3, 'cell', 'wall' or 'vertex', got '" + s + "'");
  }
  const long long d = degree.cast<long long>();
  if (d < 0 || d > t.dim())
    throw InputError("degree: expected 0.." + std::to_string(t.dim()) + ", got " + std::to_string(d));
  return static_cast<int>(d);
}

DivisionPolicy parsePolicy(const std::string& s) {
  if (s == "copy") return DivisionPolicy::Copy;
  if (s == "split_by_measure") return DivisionPolicy::SplitByMeasure;
  if (s == "reset") return DivisionPolicy::Reset;
  if (s == "custom") return DivisionPolicy::Custom;
  throw InputError("policy: expected 'copy', 'split_by_measure', 'reset' or 'custom', got '" + s + "'");
}

const char* policyKey(DivisionPolicy p) {
  switch (p) {
    case DivisionPolicy::Copy: return "copy";
    case DivisionPolicy::SplitByMeasure: return "split_by_measure";
    case DivisionPolicy::Reset: return "reset";
    case DivisionPolicy::Custom: return "custom";
  }
  return "?";
}

/// Calls f.template operator()<T>() for the column's C++ type.
template <typename F>
decltype(auto) dispatch(const PropertyColumnBase& c, const std::string& name, F&& f) {
  const std::type_index ty = c.type();
  if (ty == typeid(double)) return f.template operator()<double>();
  if (ty == typeid(std::int64_t)) return f.template operator()<std::int64_t>();
  if (ty == typeid(std::int32_t)) return f.template operator()<std::int32_t>();
  if (ty == typeid(std::uint8_t)) return f.template operator()<std::uint8_t>();
  if (ty == typeid(Vec3)) return f.template operator()<Vec3>();
  if (ty == typeid(Sym3)) return f.template operator()<Sym3>();
  // Further types a snapshot read back may hold (io::readTissueVtu).
  if (ty == typeid(float)) return f.template operator()<float>();
  if (ty == typeid(std::int8_t)) return f.template operator()<std::int8_t>();
  if (ty == typeid(std::int16_t)) return f.template operator()<std::int16_t>();
  if (ty == typeid(std::uint16_t)) return f.template operator()<std::uint16_t>();
  if (ty == typeid(std::uint32_t)) return f.template operator()<std::uint32_t>();
  if (ty == typeid(std::uint64_t)) return f.template operator()<std::uint64_t>();
  throw InputError("property '" + name + "' has a C++ type the Python module does not convert");
}

template <typename T>
std::string dtypeName() {
  if constexpr (std::is_same_v<T, Vec3>) return "vec3";
  else if constexpr (std::is_same_v<T, Sym3>) return "sym3";
  else return std::string(py::str(py::dtype::of<T>()));  // "float64", "int32", ...
}

/// Symmetric tensors as an (n, 3, 3) array (a copy owned by NumPy).
py::array_t<double> sym3Copy(std::span<const Sym3> v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}, py::ssize_t{3}});
  auto r = a.mutable_unchecked<3>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Mat3 m = v[i].matrix();
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r(static_cast<py::ssize_t>(i), j, k) = m(j, k);
  }
  return a;
}

/// An (n, 3, 3) array as symmetric tensors, from its upper triangles.
std::vector<Sym3> sym3FromArray(const py::handle& obj, const std::string& what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 3 || a.shape(1) != 3 || a.shape(2) != 3)
    throw InputError(what + ": expected an (n, 3, 3) array of symmetric tensors");
  auto r = a.unchecked<3>();
  std::vector<Sym3> v(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    v[static_cast<std::size_t>(i)] = Sym3{{r(i, 0, 0), r(i, 1, 1), r(i, 2, 2), r(i, 0, 1), r(i, 0, 2), r(i, 1, 2)}};
  return v;
}

PropertyColumnBase& findColumn(PropertyStore& store, const std::string& name, int degree) {
  PropertyColumnBase* c = store.find(name);
  if (!c) {
    std::string known;
    for (const auto& n : store.names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("no property named '" + name + "' on degree " + std::to_string(degree) + " (known: " +
                     (known.empty() ? "none" : known) + ")");
  }
  return *c;
}

/// A Python function (mother_value, fraction) -> (stays, part) as a C++
/// custom division. Division runs on the calling thread, which holds the GIL.
/// Its errors never unwind through the division (deferred_error.hpp): both
/// parts keep the mother's value and the error is raised after the split.
template <typename T>
typename PropertyColumn<T>::CustomDivision customDivision(py::function fn, const std::string& name) {
  return [fn, name](const T& mother, T& stays, T& part, double fraction) {
    py::gil_scoped_acquire gil;
    try {
      py::object r = fn(mother, fraction);
      if (!py::isinstance<py::sequence>(r) || py::len(r) != 2)
        throw InputError("property '" + name + "': the division function must return (stays, part), got " +
                         std::string(py::repr(r)));
      const T s = r[py::int_(0)].cast<T>(), p = r[py::int_(1)].cast<T>();
      stays = s;
      part = p;
    } catch (...) {
      stays = part = mother;
      if (!deferredError()) deferredError() = std::current_exception();
    }
  };
}

template <typename T>
void addColumn(PropertyStore& store, const std::string& name, const py::object& default_value, DivisionPolicy policy,
               const py::object& divide) {
  T def{};
  if constexpr (std::is_same_v<T, Vec3>) {
    def = default_value.is_none() ? Vec3::Zero() : default_value.cast<Vec3>();
  } else {
    if (!default_value.is_none()) def = default_value.cast<T>();
  }
  typename PropertyColumn<T>::CustomDivision custom;
  if (!divide.is_none()) {
    if (policy != DivisionPolicy::Custom)
      throw InputError("property '" + name + "': a divide function needs policy='custom'");
    custom = customDivision<T>(divide.cast<py::function>(), name);
  }
  store.add<T>(name, def, policy, std::move(custom));
}

}  // namespace

void bindProperties(py::class_<Tissue>& cls) {

  cls.def(
      "add_property",
      [](Tissue& t, const std::string& name, py::object default_value, const std::string& policy, std::string dtype,
         py::object degree, py::object divide) {
        const int d = resolveDegree(t, degree);
        PropertyStore& store = t.properties(d);
        const DivisionPolicy p = parsePolicy(policy);
        if (dtype.empty()) {  // inferred from the default value
          if (py::isinstance<py::bool_>(default_value)) dtype = "uint8";
          else if (py::isinstance<py::int_>(default_value)) dtype = "int64";
          else if (py::isinstance<py::sequence>(default_value) || py::isinstance<py::array>(default_value)) dtype = "vec3";
          else dtype = "float64";
        }
        if (dtype == "float64" || dtype == "float" || dtype == "double") addColumn<double>(store, name, default_value, p, divide);
        else if (dtype == "int64") addColumn<std::int64_t>(store, name, default_value, p, divide);
        else if (dtype == "int32" || dtype == "int") addColumn<int>(store, name, default_value, p, divide);
        else if (dtype == "uint8" || dtype == "bool") addColumn<std::uint8_t>(store, name, default_value, p, divide);
        else if (dtype == "vec3") addColumn<Vec3>(store, name, default_value, p, divide);
        else
          throw InputError("property '" + name + "': dtype must be 'float64', 'int64', 'int32', 'uint8' or 'vec3', got '" +
                           dtype + "'");
      },
      py::arg("name"), py::arg("default") = py::none(), py::arg("policy") = "copy", py::arg("dtype") = "",
      py::arg("degree") = py::none(), py::arg("divide") = py::none(), R"doc(
Registers a property column (one value per element slot).

policy: what division does to it — 'copy' (both parts keep the value: cell
identity), 'split_by_measure' (parts get their area/volume fraction: amounts,
totals conserved), 'reset' (both get the default), 'custom' (divide(value,
fraction) -> (stays, part), a Python function called during division).
dtype: 'float64' | 'int64' | 'int32' | 'uint8' | 'vec3'; by default inferred
from `default` (float -> float64, int -> int64, bool -> uint8, 3-sequence -> vec3).
degree: None (cells), 'wall', 'vertex' or 0..dim.
)doc")
      .def(
          "property",
          [](Tissue& t, const std::string& name, py::object degree) -> py::object {
            const int d = resolveDegree(t, degree);
            PropertyColumnBase& c = findColumn(t.properties(d), name, d);
            return dispatch(c, name, [&]<typename T>() -> py::object {
              const auto& v = static_cast<PropertyColumn<T>&>(c).values();
              if constexpr (std::is_same_v<T, Vec3>) return vec3Copy(v);
              else if constexpr (std::is_same_v<T, Sym3>) return sym3Copy(v);
              else return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
            });
          },
          py::arg("name"), py::arg("degree") = py::none(),
          "The column's values per slot, as a NumPy array (a copy; vec3: (n, 3), sym3: (n, 3, 3)).")
      .def(
          "property_view",
          [](py::object self, const std::string& name, py::object degree) -> py::object {
            Tissue& t = self.cast<Tissue&>();
            const int d = resolveDegree(t, degree);
            PropertyColumnBase& c = findColumn(t.properties(d), name, d);
            return dispatch(c, name, [&]<typename T>() -> py::object {
              auto& v = static_cast<PropertyColumn<T>&>(c).values();
              if constexpr (std::is_same_v<T, Vec3>) return vec3View(v.data(), v.size(), self, true);
              else if constexpr (std::is_same_v<T, Sym3>)
                throw InputError("property_view('" + name + "'): a symmetric tensor column (sym3) has no view; "
                                 "read it with property() (an (n, 3, 3) copy)");
              else return py::array_t<T>({static_cast<py::ssize_t>(v.size())}, {static_cast<py::ssize_t>(sizeof(T))}, v.data(), self);
            });
          },
          py::arg("name"), py::arg("degree") = py::none(), R"doc(
The column's values as a writable NumPy array sharing the tissue's memory (no
copy); it keeps the Tissue alive. Valid until the next topological edit
(division, split, removal, compact): the column may be reallocated when cells
are added. Fetch a new view after each step that can divide cells.
)doc")
      .def(
          "set_property",
          [](Tissue& t, const std::string& name, py::object values, py::object degree) {
            const int d = resolveDegree(t, degree);
            PropertyColumnBase& c = findColumn(t.properties(d), name, d);
            dispatch(c, name, [&]<typename T>() {
              auto& v = static_cast<PropertyColumn<T>&>(c).values();
              if constexpr (std::is_same_v<T, Vec3>) {
                const std::vector<Vec3> in = vec3FromArray(values, "set_property('" + name + "')");
                if (in.size() != v.size())
                  throw InputError("set_property('" + name + "'): expected " + std::to_string(v.size()) + " rows, got " +
                                   std::to_string(in.size()));
                v = in;
              } else if constexpr (std::is_same_v<T, Sym3>) {
                const std::vector<Sym3> in = sym3FromArray(values, "set_property('" + name + "')");
                if (in.size() != v.size())
                  throw InputError("set_property('" + name + "'): expected " + std::to_string(v.size()) +
                                   " tensors, got " + std::to_string(in.size()));
                v = in;
              } else {
                auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(values);
                if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != v.size())
                  throw InputError("set_property('" + name + "'): expected a 1-D array of " + std::to_string(v.size()) +
                                   " values (one per slot) convertible to " + dtypeName<T>());
                std::copy(a.data(), a.data() + a.shape(0), v.begin());
              }
            });
          },
          py::arg("name"), py::arg("values"), py::arg("degree") = py::none(),
          "Copies an array (one value per slot) into the column.")
      .def("property_names", [](Tissue& t, py::object degree) { return t.properties(resolveDegree(t, degree)).names(); },
           py::arg("degree") = py::none())
      .def("has_property", [](Tissue& t, const std::string& name, py::object degree) {
             return t.properties(resolveDegree(t, degree)).has(name);
           }, py::arg("name"), py::arg("degree") = py::none())
      .def("remove_property", [](Tissue& t, const std::string& name, py::object degree) {
             t.properties(resolveDegree(t, degree)).remove(name);
           }, py::arg("name"), py::arg("degree") = py::none())
      .def(
          "property_info",
          [](Tissue& t, const std::string& name, py::object degree) {
            const int d = resolveDegree(t, degree);
            PropertyColumnBase& c = findColumn(t.properties(d), name, d);
            const std::string dtype = dispatch(c, name, []<typename T>() { return dtypeName<T>(); });
            return py::make_tuple(dtype, policyKey(c.policy()));
          },
          py::arg("name"), py::arg("degree") = py::none(), "(dtype, policy) of a column.");
}

}  // namespace tessella::python
