// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtu_property_arrays.hpp"

#include <type_traits>

#include <vtkAOSDataArrayTemplate.h>
#include <vtkSetGet.h>
#include <vtkType.h>

#include "tessella/io/vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::io::detail {

namespace {

template <typename... Ts>
struct TypeList {};

using ScalarTypes = TypeList<double, float, char, signed char, unsigned char, short, unsigned short, int,
                             unsigned int, long, unsigned long, long long, unsigned long long>;

// Fixed-size double tuples: how many components, and how to (un)pack them.
template <typename T>
struct Tuple;
template <>
struct Tuple<Eigen::Vector2d> {
  static constexpr int n = 2;
  static void pack(const Eigen::Vector2d& v, double* out) { out[0] = v[0], out[1] = v[1]; }
  static Eigen::Vector2d unpack(const double* in) { return {in[0], in[1]}; }
  static Eigen::Vector2d zero() { return Eigen::Vector2d::Zero(); }
};
template <>
struct Tuple<Vec3> {
  static constexpr int n = 3;
  static void pack(const Vec3& v, double* out) { out[0] = v[0], out[1] = v[1], out[2] = v[2]; }
  static Vec3 unpack(const double* in) { return {in[0], in[1], in[2]}; }
  static Vec3 zero() { return Vec3::Zero(); }
};
template <>
struct Tuple<Sym3> {
  static constexpr int n = 6;
  // Sym3 stores xx yy zz xy xz yz; VTK's symmetric tensors are XX YY ZZ XY YZ XZ.
  static void pack(const Sym3& s, double* out) {
    out[0] = s.v[0], out[1] = s.v[1], out[2] = s.v[2], out[3] = s.v[3], out[4] = s.v[5], out[5] = s.v[4];
  }
  static Sym3 unpack(const double* in) { return Sym3{{in[0], in[1], in[2], in[3], in[5], in[4]}}; }
  static Sym3 zero() { return Sym3{}; }
};
template <>
struct Tuple<Mat3> {
  static constexpr int n = 9;
  static void pack(const Mat3& m, double* out) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[3 * r + c] = m(r, c);
  }
  static Mat3 unpack(const double* in) {
    Mat3 m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = in[3 * r + c];
    return m;
  }
  static Mat3 zero() { return Mat3::Zero(); }
};
using TupleTypes = TypeList<Eigen::Vector2d, Vec3, Sym3, Mat3>;

template <typename T>
vtkSmartPointer<vtkDataArray> scalarArray(const PropertyColumn<T>& column, const RowSelection& rows) {
  auto array = vtkSmartPointer<vtkAOSDataArrayTemplate<T>>::New();
  array->SetName(column.name().c_str());
  const auto n = static_cast<vtkIdType>(rows.count);
  if (rows.identity && n > 0) {
    // save = 1: VTK must not free the column's memory.
    array->SetArray(const_cast<T*>(column.values().data()), n, 1);
  } else {
    T* out = array->WritePointer(0, n);
    const T* in = column.values().data();
    for (vtkIdType r = 0; r < n; ++r) out[r] = in[rows.slot(static_cast<std::size_t>(r))];
  }
  return array;
}

template <typename T>
vtkSmartPointer<vtkDataArray> tupleArray(const PropertyColumn<T>& column, const RowSelection& rows) {
  auto array = vtkSmartPointer<vtkAOSDataArrayTemplate<double>>::New();
  array->SetName(column.name().c_str());
  array->SetNumberOfComponents(Tuple<T>::n);
  const auto n = static_cast<vtkIdType>(rows.count);
  double* out = array->WritePointer(0, n * Tuple<T>::n);
  for (vtkIdType r = 0; r < n; ++r)
    Tuple<T>::pack(column.values()[rows.slot(static_cast<std::size_t>(r))], out + r * Tuple<T>::n);
  return array;
}

// The column's default as a one-tuple array of the same VTK type, so that a
// restart gives new elements what the run gave them (a Reset column's NaN
// "not set yet" must not come back as 0).
template <typename T>
vtkSmartPointer<vtkDataArray> scalarDefault(const PropertyColumn<T>& column, const std::string& name) {
  auto array = vtkSmartPointer<vtkAOSDataArrayTemplate<T>>::New();
  array->SetName(name.c_str());
  array->InsertNextValue(column.defaultValue());
  return array;
}

template <typename T>
vtkSmartPointer<vtkDataArray> tupleDefault(const PropertyColumn<T>& column, const std::string& name) {
  auto array = vtkSmartPointer<vtkAOSDataArrayTemplate<double>>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(Tuple<T>::n);
  Tuple<T>::pack(column.defaultValue(), array->WritePointer(0, Tuple<T>::n));
  return array;
}

// Calls f with the column downcast to the one type of the list it holds;
// nullptr when it holds none of them.
template <typename... Ts, typename F>
vtkSmartPointer<vtkDataArray> visitColumn(TypeList<Ts...>, const PropertyColumnBase& c, F&& f) {
  vtkSmartPointer<vtkDataArray> result;
  ((c.type() == typeid(Ts) ? (result = f(static_cast<const PropertyColumn<Ts>&>(c)), true) : false) || ...);
  return result;
}

template <typename... Ts>
bool isOneOf(TypeList<Ts...>, const std::type_index& t) {
  return ((t == typeid(Ts)) || ...);
}

// Copies n values of the array's own type into `out`, converting each exactly
// (integers to integers, floating to floating).
template <typename Out>
void copyFirstComponent(vtkDataArray* array, Out* out) {
  const vtkIdType n = array->GetNumberOfTuples();
  const int stride = array->GetNumberOfComponents();
  switch (array->GetDataType()) {
    vtkTemplateMacro({
      const auto* in = static_cast<const VTK_TT*>(array->GetVoidPointer(0));
      for (vtkIdType i = 0; i < n; ++i) out[i] = static_cast<Out>(in[i * stride]);
    });
    default:
      throw InputError(std::string("array '") + (array->GetName() ? array->GetName() : "") +
                       "' has an unsupported VTK data type");
  }
}

template <typename T>
void addScalarColumn(PropertyStore& store, const std::string& name, vtkDataArray* array, DivisionPolicy policy,
                     vtkDataArray* default_value) {
  T initial{};
  if (default_value) copyFirstComponent(default_value, &initial);
  auto& column = store.add<T>(name, initial, policy);
  column.values().resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  copyFirstComponent(array, column.values().data());
}

template <typename T>
void addTupleColumn(PropertyStore& store, const std::string& name, vtkDataArray* array, DivisionPolicy policy,
                    vtkDataArray* default_value) {
  double tuple[9];
  T initial = Tuple<T>::zero();
  if (default_value) {
    default_value->GetTuple(0, tuple);
    initial = Tuple<T>::unpack(tuple);
  }
  auto& column = store.add<T>(name, initial, policy);
  const vtkIdType n = array->GetNumberOfTuples();
  column.values().resize(static_cast<std::size_t>(n), initial);
  for (vtkIdType i = 0; i < n; ++i) {
    array->GetTuple(i, tuple);
    column.values()[static_cast<std::size_t>(i)] = Tuple<T>::unpack(tuple);
  }
}

}  // namespace

RowSelection liveRows(const std::vector<std::uint8_t>& alive_flags, std::size_t live_count) {
  RowSelection rows;
  rows.count = live_count;
  rows.identity = live_count == alive_flags.size();
  if (!rows.identity) {
    rows.slots.reserve(live_count);
    for (std::size_t i = 0; i < alive_flags.size(); ++i)
      if (alive_flags[i]) rows.slots.push_back(static_cast<Index>(i));
  }
  return rows;
}

vtkSmartPointer<vtkDataArray> columnToArray(const PropertyColumnBase& column, const RowSelection& rows) {
  if (auto a = visitColumn(ScalarTypes{}, column, [&](const auto& c) { return scalarArray(c, rows); })) return a;
  return visitColumn(TupleTypes{}, column, [&](const auto& c) { return tupleArray(c, rows); });
}

vtkSmartPointer<vtkDataArray> defaultToArray(const PropertyColumnBase& column, const std::string& array_name) {
  if (auto a = visitColumn(ScalarTypes{}, column, [&](const auto& c) { return scalarDefault(c, array_name); }))
    return a;
  return visitColumn(TupleTypes{}, column, [&](const auto& c) { return tupleDefault(c, array_name); });
}

void addColumnFromArray(PropertyStore& store, const std::string& name, vtkDataArray* array,
                        const std::string& where, DivisionPolicy policy, vtkDataArray* default_value) {
  const int components = array->GetNumberOfComponents();
  const int type = array->GetDataType();
  if (default_value && (default_value->GetDataType() != type || default_value->GetNumberOfComponents() != components ||
                        default_value->GetNumberOfTuples() != 1))
    throw InputError(where + ": the default of property '" + name + "' (" +
                     std::to_string(default_value->GetNumberOfTuples()) + " x " +
                     std::to_string(default_value->GetNumberOfComponents()) + " " +
                     default_value->GetDataTypeAsString() + ") does not match its array (" +
                     std::to_string(components) + " component(s) of " + array->GetDataTypeAsString() + ")");
  if (components == 1) {
    switch (type) {
      case VTK_DOUBLE: return addScalarColumn<double>(store, name, array, policy, default_value);
      case VTK_FLOAT: return addScalarColumn<float>(store, name, array, policy, default_value);
      case VTK_CHAR:
      case VTK_SIGNED_CHAR: return addScalarColumn<std::int8_t>(store, name, array, policy, default_value);
      case VTK_UNSIGNED_CHAR: return addScalarColumn<std::uint8_t>(store, name, array, policy, default_value);
      case VTK_SHORT: return addScalarColumn<std::int16_t>(store, name, array, policy, default_value);
      case VTK_UNSIGNED_SHORT: return addScalarColumn<std::uint16_t>(store, name, array, policy, default_value);
      case VTK_INT: return addScalarColumn<std::int32_t>(store, name, array, policy, default_value);
      case VTK_UNSIGNED_INT: return addScalarColumn<std::uint32_t>(store, name, array, policy, default_value);
      case VTK_LONG:
      case VTK_LONG_LONG:
      case VTK_ID_TYPE: return addScalarColumn<std::int64_t>(store, name, array, policy, default_value);
      case VTK_UNSIGNED_LONG:
      case VTK_UNSIGNED_LONG_LONG: return addScalarColumn<std::uint64_t>(store, name, array, policy, default_value);
      default: break;
    }
  } else if (type == VTK_DOUBLE || type == VTK_FLOAT) {
    switch (components) {
      case 2: return addTupleColumn<Eigen::Vector2d>(store, name, array, policy, default_value);
      case 3: return addTupleColumn<Vec3>(store, name, array, policy, default_value);
      case 6: return addTupleColumn<Sym3>(store, name, array, policy, default_value);
      case 9: return addTupleColumn<Mat3>(store, name, array, policy, default_value);
      default: break;
    }
  }
  throw InputError(where + ": array '" + name + "' has " + std::to_string(components) +
                   " component(s) of VTK type '" + array->GetDataTypeAsString() +
                   "', which matches no property type");
}

std::vector<std::int64_t> integerValues(vtkDataArray* array) {
  std::vector<std::int64_t> out(static_cast<std::size_t>(array->GetNumberOfTuples()));
  copyFirstComponent(array, out.data());
  return out;
}

std::vector<double> doubleValues(vtkDataArray* array) {
  std::vector<double> out(static_cast<std::size_t>(array->GetNumberOfTuples()));
  copyFirstComponent(array, out.data());
  return out;
}

}  // namespace tessella::io::detail

namespace tessella::io {

bool isWritableProperty(const PropertyColumnBase& column) {
  return detail::isOneOf(detail::ScalarTypes{}, column.type()) ||
         detail::isOneOf(detail::TupleTypes{}, column.type());
}

std::vector<std::string> unwritableProperties(const PropertyStore& store) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < store.numColumns(); ++i)
    if (!isWritableProperty(store.column(i))) names.push_back(store.column(i).name());
  return names;
}

}  // namespace tessella::io
