// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Parameters of the things a user picks by name (a division rule, a velocity
// field, a generator): their declarations (ParamSpec: name, type, doc,
// default, range) and their values (ParamValues). The registries
// (registry.hpp) hold one ParamSpec list per entry; the YAML schema, the
// Python bindings and the generated docs are all derived from it, so a
// parameter is declared in exactly one place.
//
// The value types are those of a configuration key, so sim/ can read a
// parameter straight from YAML: Vec2/Vec3 are lists of 2 or 3 numbers, Enum a
// string from `choices`, Path a file name.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"  // formatNumber, which the texts of values use
#include "tessella/tissue/vec3.hpp"

namespace tessella {

// In a scope of its own: the enumerator Vec3 would shadow the type tessella::Vec3.
namespace param_types {
/// Vec2or3: a list of 2 or 3 numbers (a pixel or voxel size, as the image is 2D or 3D).
enum class ParamType { Bool, Int, Float, String, Enum, Vec2, Vec3, Vec2or3, Path };
}
using param_types::ParamType;

/// "bool", "integer", "float", ...
const char* paramTypeName(ParamType type);

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>>;

/// A value as written in YAML: flow style for lists, floats always with a
/// point or exponent ("1.0", not "1"), so the text reads back as the same type.
std::string formatParamValue(const ParamValue& value);

/// An allowed interval of an Int or Float parameter (either end optional).
struct ParamRange {
  std::optional<double> min, max;
  bool min_exclusive = false, max_exclusive = false;

  bool contains(double x) const;
  /// In words: "> 0", ">= 3 and <= 1000", or "" when unbounded.
  std::string text() const;
};

struct ParamSpec {
  std::string name;  ///< leaf name, e.g. "beta"
  ParamType type = ParamType::Float;
  std::string doc;
  /// Used when the value is not given; none: the parameter is required, or
  /// optional with the meaning `absent_doc`.
  std::optional<ParamValue> default_value;
  std::string absent_doc;
  ParamRange range;                  ///< Int and Float only
  std::vector<std::string> choices;  ///< Enum only
  /// Does not apply when this sibling parameter is given (count vs seed_file).
  std::string unless_set;

  ParamSpec(std::string name_, ParamType type_, std::string doc_)
      : name(std::move(name_)), type(type_), doc(std::move(doc_)) {}
  // Fluent setters, so declarations read like a table.
  ParamSpec& byDefault(ParamValue v) { default_value = std::move(v); return *this; }
  ParamSpec& whenAbsent(std::string meaning) { absent_doc = std::move(meaning); return *this; }
  ParamSpec& atLeast(double v) { range.min = v; range.min_exclusive = false; return *this; }
  ParamSpec& above(double v) { range.min = v; range.min_exclusive = true; return *this; }
  ParamSpec& atMost(double v) { range.max = v; range.max_exclusive = false; return *this; }
  ParamSpec& below(double v) { range.max = v; range.max_exclusive = true; return *this; }
  ParamSpec& oneOf(std::vector<std::string> c) { choices = std::move(c); return *this; }
  ParamSpec& unlessSet(std::string sibling) { unless_set = std::move(sibling); return *this; }
};

/// Values by parameter name. Getters throw InputError naming the parameter
/// when it is missing or holds another type.
class ParamValues {
 public:
  ParamValues() = default;
  ParamValues(std::initializer_list<std::pair<const std::string, ParamValue>> values) : values_(values) {}

  ParamValues& set(const std::string& name, ParamValue value);
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  const ParamValue& get(const std::string& name) const;
  bool getBool(const std::string& name) const;
  std::int64_t getInt(const std::string& name) const;
  /// Floats; an integer value is accepted and converted.
  double getFloat(const std::string& name) const;
  const std::string& getString(const std::string& name) const;
  /// Vec3 (or a Vec2 padded with z = 0).
  Vec3 getVec3(const std::string& name) const;
  const std::vector<double>& getList(const std::string& name) const;
  const std::map<std::string, ParamValue>& all() const { return values_; }

 private:
  std::map<std::string, ParamValue> values_;
};

/// `values` completed with the defaults of `specs` and checked against them:
/// InputError naming `owner` ("division rule 'besson_dumais'"), the parameter
/// and the value for an unknown name, a wrong type, a value out of range or
/// not among the choices, or a missing required parameter.
ParamValues completeParams(const std::vector<ParamSpec>& specs, const ParamValues& values, const std::string& owner);

/// An InputError caused by one parameter's value, naming it, so a reader
/// can point at that parameter's key (sim/ makes it a ConfigError there).
class ParamError : public InputError {
 public:
  ParamError(std::string param, const std::string& what) : InputError(what), param_(std::move(param)) {}
  const std::string& param() const { return param_; }

 private:
  std::string param_;
};

/// make(), with an InputError it throws blamed on `param` (a ParamError
/// stays as it is): for a factory whose constructor checks its arguments
/// together but whose likely culprit is one parameter.
template <typename Make>
auto blameParam(const std::string& param, Make&& make) {
  try {
    return make();
  } catch (const ParamError&) {
    throw;
  } catch (const InputError& e) {
    throw ParamError(param, e.what());
  }
}

}  // namespace tessella
