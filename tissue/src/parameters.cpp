// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/parameters.hpp"

#include <cmath>

#include "tessella/tissue/errors.hpp"

namespace tessella {

const char* paramTypeName(ParamType type) {
  switch (type) {
    case ParamType::Bool: return "bool";
    case ParamType::Int: return "integer";
    case ParamType::Float: return "float";
    case ParamType::String: return "string";
    case ParamType::Enum: return "enum";
    case ParamType::Vec2: return "vec2";
    case ParamType::Vec3: return "vec3";
    case ParamType::Vec2or3: return "vec2 or vec3";
    case ParamType::Path: return "path";
  }
  return "?";
}

namespace {
// A float keeps a point or exponent, so it reads back as a float.
std::string floatText(double x) {
  std::string s = formatNumber(x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

const char* valueKind(const ParamValue& v) {
  switch (v.index()) {
    case 0: return "a bool";
    case 1: return "an integer";
    case 2: return "a float";
    case 3: return "a string";
    default: return "a list";
  }
}
}  // namespace

std::string formatParamValue(const ParamValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return floatText(d); }
    std::string operator()(const std::string& s) const { return s; }
    std::string operator()(const std::vector<double>& v) const {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + floatText(v[i]);
      return out + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

bool ParamRange::contains(double x) const {
  if (min && (min_exclusive ? !(x > *min) : !(x >= *min))) return false;
  if (max && (max_exclusive ? !(x < *max) : !(x <= *max))) return false;
  return true;
}

std::string ParamRange::text() const {
  // Six significant digits, as printf's %g: bounds are round declared numbers, and integer bounds read
  // "100000" rather than the shorter "1e+05" (docs/config.md is generated from this text).
  const auto bound = [](double x) { return formatNumber(x, 6); };
  std::string out;
  if (min) out = std::string(min_exclusive ? "> " : ">= ") + bound(*min);
  if (max) out += std::string(out.empty() ? "" : " and ") + (max_exclusive ? "< " : "<= ") + bound(*max);
  return out;
}

ParamValues& ParamValues::set(const std::string& name, ParamValue value) {
  values_[name] = std::move(value);
  return *this;
}

const ParamValue& ParamValues::get(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw InputError("parameter '" + name + "' is not set");
  return it->second;
}

namespace {
template <typename T>
const T& typed(const ParamValues& values, const std::string& name, const char* expected) {
  const ParamValue& v = values.get(name);
  if (const T* p = std::get_if<T>(&v)) return *p;
  throw InputError("parameter '" + name + "' must be " + expected + ", got " + valueKind(v) + " (" +
                   formatParamValue(v) + ")");
}
}  // namespace

bool ParamValues::getBool(const std::string& name) const { return typed<bool>(*this, name, "a bool"); }
std::int64_t ParamValues::getInt(const std::string& name) const {
  return typed<std::int64_t>(*this, name, "an integer");
}
double ParamValues::getFloat(const std::string& name) const {
  if (const auto* i = std::get_if<std::int64_t>(&get(name))) return static_cast<double>(*i);
  return typed<double>(*this, name, "a number");
}
const std::string& ParamValues::getString(const std::string& name) const {
  return typed<std::string>(*this, name, "a string");
}
const std::vector<double>& ParamValues::getList(const std::string& name) const {
  return typed<std::vector<double>>(*this, name, "a list of numbers");
}
Vec3 ParamValues::getVec3(const std::string& name) const {
  const auto& v = getList(name);
  if (v.size() != 2 && v.size() != 3)
    throw InputError("parameter '" + name + "' must be a list of 3 numbers, got " + formatParamValue(v));
  return Vec3(v[0], v[1], v.size() == 3 ? v[2] : 0.0);
}

namespace {
// The value converted to the spec's type (an integer where a float is
// expected), or an InputError in the owner's and parameter's words.
ParamValue checked(const ParamSpec& spec, const ParamValue& value, const std::string& owner) {
  const std::string where = owner + ": parameter '" + spec.name + "' ";
  const auto fail = [&](const std::string& expected) {
    return ParamError(spec.name, where + "must be " + expected + ", got " + formatParamValue(value));
  };
  const auto inRange = [&](double x) {
    if (!std::isfinite(x)) throw fail("a finite number");
    if (!spec.range.contains(x)) throw fail("a number " + spec.range.text());
  };
  switch (spec.type) {
    case ParamType::Bool:
      if (!std::holds_alternative<bool>(value)) throw fail("true or false");
      return value;
    case ParamType::Int:
      if (!std::holds_alternative<std::int64_t>(value)) throw fail("an integer");
      inRange(static_cast<double>(std::get<std::int64_t>(value)));
      return value;
    case ParamType::Float: {
      double x = 0;
      if (const auto* i = std::get_if<std::int64_t>(&value))
        x = static_cast<double>(*i);
      else if (const auto* d = std::get_if<double>(&value))
        x = *d;
      else
        throw fail("a number");
      inRange(x);
      return x;
    }
    case ParamType::String:
    case ParamType::Path:
      if (!std::holds_alternative<std::string>(value)) throw fail("a string");
      return value;
    case ParamType::Enum: {
      const auto* s = std::get_if<std::string>(&value);
      std::string names;
      for (const auto& c : spec.choices) names += (names.empty() ? "" : ", ") + c;
      if (!s) throw fail("one of " + names);
      for (const auto& c : spec.choices)
        if (c == *s) return value;
      throw fail("one of " + names);
    }
    case ParamType::Vec2:
    case ParamType::Vec3:
    case ParamType::Vec2or3: {
      const std::size_t n = spec.type == ParamType::Vec2 ? 2 : 3;
      const auto* v = std::get_if<std::vector<double>>(&value);
      const bool sized = v && (v->size() == n || (spec.type == ParamType::Vec2or3 && v->size() == 2));
      if (!sized) throw fail(spec.type == ParamType::Vec2or3 ? "a list of 2 or 3 numbers" : "a list of " + std::to_string(n) + " numbers");
      for (double x : *v)
        if (!std::isfinite(x)) throw fail("a list of finite numbers");
      return value;
    }
  }
  return value;
}
}  // namespace

ParamValues completeParams(const std::vector<ParamSpec>& specs, const ParamValues& values, const std::string& owner) {
  std::string known;
  for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.name;
  for (const auto& [name, value] : values.all()) {
    bool found = false;
    for (const auto& s : specs) found = found || s.name == name;
    if (!found)
      throw InputError(owner + " has no parameter '" + name + "'" +
                       (known.empty() ? std::string(" (it takes none)") : " (known: " + known + ")"));
  }
  ParamValues out;
  for (const auto& spec : specs) {
    if (values.has(spec.name)) {
      out.set(spec.name, checked(spec, values.get(spec.name), owner));
    } else if (spec.default_value && !(!spec.unless_set.empty() && values.has(spec.unless_set))) {
      out.set(spec.name, *spec.default_value);
    } else if (!spec.default_value && spec.absent_doc.empty() && spec.unless_set.empty()) {
      throw ParamError(spec.name, owner + ": parameter '" + spec.name + "' is required");
    }
  }
  return out;
}

}  // namespace tessella
