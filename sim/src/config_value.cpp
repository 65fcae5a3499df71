#include "tessella/sim/config_value.hpp"

#include <string>

#include "tessella/tissue/format.hpp"

namespace tessella::sim {

const char* valueTypeName(ValueType type) {
  switch (type) {
    case ValueType::Bool: return "bool";
    case ValueType::Int: return "integer";
    case ValueType::Float: return "float";
    case ValueType::String: return "string";
    case ValueType::Enum: return "enum";
    case ValueType::Vec2: return "vec2";
    case ValueType::Vec3: return "vec3";
    case ValueType::Path: return "path";
  }
  return "?";
}

namespace {
// Shortest text that reads back as the same double, so run.yaml reproduces
// a run bit for bit.
std::string formatDouble(double x) {
  std::string s = formatNumber(x);
  // Keep floats recognisable as floats ("1.0", not "1").
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}
}  // namespace

std::string formatValue(const ConfigValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return formatDouble(d); }
    std::string operator()(const std::string& s) const { return s; }
    std::string operator()(const std::vector<double>& v) const {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + formatDouble(v[i]);
      return out + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

std::string SourceLocation::str() const {
  std::string s = file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  return s;
}

}  // namespace tessella::sim
