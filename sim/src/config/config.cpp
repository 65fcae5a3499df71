// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/config/config.hpp"

#include <algorithm>
#include <stdexcept>

namespace tessella::sim {

Config::Config(const Schema& schema, std::string name, std::string source, std::string base_directory)
    : schema_(&schema),
      name_(std::move(name)),
      source_(std::move(source)),
      base_directory_(std::move(base_directory)) {}

bool Config::isGiven(const std::string& path) const {
  auto it = entries_.find(path);
  return it != entries_.end() &&
         (it->second.origin == ValueOrigin::File || it->second.origin == ValueOrigin::Override);
}

const Config::Entry& Config::entry(const std::string& path) const {
  auto it = entries_.find(path);
  if (it == entries_.end()) throw std::logic_error("config: no value for key " + path);
  return it->second;
}

namespace {
template <typename T>
const T& typed(const Config::Entry& e, const std::string& path) {
  if (const T* v = std::get_if<T>(&e.value)) return *v;
  throw std::logic_error("config: key " + path + " holds another type");
}
}  // namespace

bool Config::getBool(const std::string& path) const { return typed<bool>(entry(path), path); }
std::int64_t Config::getInt(const std::string& path) const {
  return typed<std::int64_t>(entry(path), path);
}
double Config::getFloat(const std::string& path) const { return typed<double>(entry(path), path); }
const std::string& Config::getString(const std::string& path) const {
  return typed<std::string>(entry(path), path);
}
Vec3 Config::getVec(const std::string& path) const {
  const auto& v = typed<std::vector<double>>(entry(path), path);
  return Vec3(v.at(0), v.at(1), v.size() > 2 ? v[2] : 0.0);
}

ParamValues Config::params(const std::string& section, const std::vector<ParamSpec>& params) const {
  ParamValues values;
  for (const ParamSpec& p : params) {
    const std::string path = joinPath(section, p.name);
    if (has(path)) values.set(p.name, entry(path).value);
  }
  return values;
}

bool Config::conditionHolds(const Condition& c) const {
  if (!isActive(c.key) || !has(c.key)) return false;
  const auto* value = std::get_if<std::string>(&entry(c.key).value);
  return value && std::find(c.values.begin(), c.values.end(), *value) != c.values.end();
}

bool Config::isActive(const std::string& path) const {
  if (path.empty()) return true;
  if (!isActive(parentPath(path))) return false;
  if (const SectionSpec* s = schema_->findSection(path))
    return (!s->active_when || conditionHolds(*s->active_when)) && (s->unless_set.empty() || !isSet(s->unless_set));
  if (const KeySpec* k = schema_->findKey(path))
    return (!k->active_when || conditionHolds(*k->active_when)) && (k->unless_set.empty() || !isSet(k->unless_set));
  return false;
}

void Config::set(const std::string& path, ConfigValue value, SourceLocation where, ValueOrigin origin) {
  entries_[path] = Entry{std::move(value), std::move(where), origin};
}

std::vector<std::string> Config::entryNames(const std::string& map_path) const {
  auto it = entry_names_.find(map_path);
  return it == entry_names_.end() ? std::vector<std::string>{} : it->second;
}

void Config::addEntry(const std::string& map_path, const std::string& name, SourceLocation where) {
  auto& names = entry_names_[map_path];
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  names.push_back(name);
  entry_where_[joinPath(map_path, name)] = std::move(where);
}

SourceLocation Config::entryLocation(const std::string& entry_path) const {
  auto it = entry_where_.find(entry_path);
  return it == entry_where_.end() ? SourceLocation{source_, 0, 0} : it->second;
}

ConfigError Config::errorAt(const std::string& path, const std::string& problem) const {
  auto it = entries_.find(path);
  SourceLocation where;
  if (it != entries_.end() && it->second.where.known()) {
    where = it->second.where;
  } else {
    where.file = source_;  // a default: the file is all we can point at
  }
  return ConfigError(where, path, problem);
}

}  // namespace tessella::sim
