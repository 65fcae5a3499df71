// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "coupling_values.hpp"

#include "tessella/sim/config/suggest.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

namespace tessella::sim {

namespace detail {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
}  // namespace

std::vector<std::pair<std::string, std::string>> parseNamedItems(const Config& c, const std::string& key) {
  std::vector<std::pair<std::string, std::string>> out;
  std::stringstream all(c.getString(key));
  std::string item;
  std::set<std::string> seen;
  while (std::getline(all, item, ',')) {
    item = trim(item);
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw c.errorAt(key, "expected name=value items separated by commas, got '" + item + "'");
    std::string name = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    if (name.empty() || value.empty()) throw c.errorAt(key, "item '" + item + "' is not name=value");
    if (!seen.insert(name).second) throw c.errorAt(key, "'" + name + "' is given twice");
    out.emplace_back(std::move(name), std::move(value));
  }
  return out;
}

double parseNumber(const Config& c, const std::string& key, const std::string& item, const std::string& text) {
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data() + (text[0] == '+' ? 1 : 0), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v))
    throw c.errorAt(key, "'" + item + "=" + text + "': '" + text + "' is not a finite number");
  return v;
}

BoundaryRegion parseRegion(const Config& c, const std::string& key, const std::string& name) {
  const auto& names = boundaryRegionNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    std::string problem = "unknown boundary region '" + name + "'";
    if (const auto m = closestMatch(name, names)) problem += "; did you mean '" + *m + "'?";
    throw c.errorAt(key, problem + " (regions: " + known + ")");
  }
  return static_cast<BoundaryRegion>(it - names.begin());
}

std::vector<RegionValue> parseRegionValues(const Config& c, const std::string& key) {
  std::vector<RegionValue> out;
  if (!c.has(key)) return out;
  for (const auto& [name, value] : parseNamedItems(c, key))
    out.push_back({parseRegion(c, key, name), parseNumber(c, key, name, value)});
  return out;
}

std::vector<std::int64_t> parseIdList(const Config& c, const std::string& key, const std::string& text) {
  std::vector<std::int64_t> out;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ',')) {
    item = trim(item);
    if (item.empty()) continue;
    std::int64_t v = 0;
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (ec != std::errc() || ptr != item.data() + item.size() || v < 0)
      throw c.errorAt(key, "'" + item + "' is not a lineage id (an integer >= 0)");
    out.push_back(v);
  }
  return out;
}

std::map<std::int64_t, double> parseTypeValues(const Config& c, const std::string& key) {
  std::map<std::int64_t, double> out;
  if (!c.has(key)) return out;
  for (const auto& [name, value] : parseNamedItems(c, key)) {
    std::int64_t type = 0;
    const auto [ptr, ec] = std::from_chars(name.data(), name.data() + name.size(), type);
    if (ec != std::errc() || ptr != name.data() + name.size())
      throw c.errorAt(key, "cell type '" + name + "' is not an integer");
    out[type] = parseNumber(c, key, name, value);
  }
  return out;
}

void declareEveryAndStep(Schema& s, const std::string& p, const Condition& when) {
  s.key(p + ".every", ValueType::Int, "Solve every this many simulation steps (the solve follows growth and division).")
      .byDefault(std::int64_t{1})
      .atLeast(1)
      .activeWhen(when.key, when.values);
  s.key(p + ".dt", ValueType::Float,
        "Time step of the solver within the time since the last solve (steps of equal length "
        "covering it exactly).")
      .above(0)
      .whenAbsent("one solver step per solve")
      .activeWhen(when.key, when.values);
  s.key(p + ".by_property", ValueType::String,
        "Integer cell property holding each cell's type, for the `*_by` per-type coefficients "
        "(e.g. cell_type). Cells of types not listed take the uniform value.")
      .whenAbsent("coefficients are uniform")
      .activeWhen(when.key, when.values);
}

KeySpec& declarePerTypeKey(Schema& s, const std::string& path, const std::string& doc, const Condition& when) {
  return s.key(path, ValueType::String, doc).whenAbsent("uniform").activeWhen(when.key, when.values);
}

SectionSpec& declareSourceKeys(Schema& s, const std::string& p, const Condition& when) {
  SectionSpec& section = s.section(p + ".source",
            "Source cells, chosen at the first solve: cells whose centroid lies within `radius` of "
            "`center`, and cells whose lineage id is listed. They are marked with the cell property "
            "<name>_source (daughters inherit it) and get the extra production `rate`.")
      .activeWhen(when.key, when.values);
  s.key(p + ".source.rate", ValueType::Float, "Extra production in source cells (per unit time).").byDefault(0.0);
  s.key(p + ".source.center", ValueType::Vec3, "Centre of the source ball.").byDefault(std::vector<double>{0, 0, 0});
  s.key(p + ".source.radius", ValueType::Float, "Radius of the source ball (0: no ball).").byDefault(0.0).atLeast(0);
  s.key(p + ".source.cells", ValueType::String, "Lineage ids of source cells, e.g. \"0, 12\".")
      .whenAbsent("no listed cells");
  return section;
}

SourceSpec readSource(const Config& c, const std::string& p) {
  SourceSpec s;
  s.rate = c.getFloat(p + ".source.rate");
  s.center = c.getVec(p + ".source.center");
  s.radius = c.getFloat(p + ".source.radius");
  if (c.has(p + ".source.cells")) s.lineage_ids = parseIdList(c, p + ".source.cells", c.getString(p + ".source.cells"));
  if (s.rate != 0.0 && s.radius == 0.0 && s.lineage_ids.empty())
    throw c.errorAt(p + ".source.rate", "a source rate needs source cells: give source.radius or source.cells");
  return s;
}

CellCoefficient readCoefficient(const Config& c, const std::string& p, const std::string& name,
                                const std::string& by_property) {
  const std::string type_key = by_property.empty() ? p + ".by_property" : by_property;
  CellCoefficient k;
  k.uniform = c.getFloat(p + "." + name);
  const std::string by = p + "." + name + "_by";
  k.by_type = parseTypeValues(c, by);
  // Per-type values obey the range of the uniform key.
  if (const KeySpec* spec = c.schema().findKey(p + "." + name))
    for (const auto& [type, v] : k.by_type) {
      const bool low = spec->min && (spec->min_exclusive ? v <= *spec->min : v < *spec->min);
      const bool high = spec->max && (spec->max_exclusive ? v >= *spec->max : v > *spec->max);
      if (low || high)
        throw c.errorAt(by, "value " + formatValue(v) + " for type " + std::to_string(type) +
                                " is out of range; expected " + spec->expectation());
    }
  if (!k.by_type.empty() && !c.has(type_key))
    throw c.errorAt(by, "per-type values need " + type_key + " (the cell property holding the type)");
  return k;
}

}  // namespace detail
}  // namespace tessella::sim
