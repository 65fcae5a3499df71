// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/run_record.hpp"

#include <yaml-cpp/yaml.h>

#include "tessella/io/text_file.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

namespace {

bool hasActiveValue(const Config& c, const std::string& section) {
  for (const auto& [path, entry] : c.entries())
    if (path.rfind(section + ".", 0) == 0 && c.isActive(path)) return true;
  return false;
}

void emitValue(YAML::Emitter& out, const KeySpec& spec, const ConfigValue& value) {
  switch (spec.type) {
    case ValueType::Bool: out << std::get<bool>(value); break;
    case ValueType::Int: out << std::get<std::int64_t>(value); break;
    case ValueType::Float: out << formatValue(value); break;  // shortest round-trip text
    case ValueType::Enum: out << std::get<std::string>(value); break;
    case ValueType::String:
    case ValueType::Path: out << YAML::DoubleQuoted << std::get<std::string>(value); break;
    case ValueType::Vec2:
    case ValueType::Vec3:
    case ValueType::Vec2or3:
      out << YAML::Flow << YAML::BeginSeq;
      for (double x : std::get<std::vector<double>>(value)) out << formatValue(x);
      out << YAML::EndSeq;
      break;
  }
}

void emitSection(YAML::Emitter& out, const Config& c, const std::string& section) {
  out << YAML::BeginMap;
  // An entry map's children are the entries given, not its declared template.
  const bool entries = c.schema().isEntryMap(section);
  for (const std::string& name : entries ? c.entryNames(section) : c.schema().childNames(section)) {
    const std::string path = joinPath(section, name);
    if (!c.isActive(path)) continue;
    if (c.schema().isSection(path)) {
      if (!hasActiveValue(c, path) && !entries) continue;  // an entry with no keys is still an entry
      out << YAML::Key << name << YAML::Value;
      emitSection(out, c, path);
    } else if (c.has(path)) {
      out << YAML::Key << name << YAML::Value;
      emitValue(out, *c.schema().findKey(path), c.entry(path).value);
    }
  }
  out << YAML::EndMap;
}

}  // namespace

std::string resolvedConfigYaml(const Config& config) {
  YAML::Emitter out;
  out.SetIndent(2);
  emitSection(out, config, "");
  return "# The fully resolved configuration of a Tessella run: every key that applies, defaults\n"
         "# filled in, the RNG seed actually used. Reproduce the run with\n"
         "#   tessella run run.yaml --out OTHER_DIRECTORY\n" +
         std::string(out.c_str()) + "\n";
}

void writeRunRecord(const Config& config, const std::string& path) {
  io::writeTextFile(path, resolvedConfigYaml(config));  // atomic; a failure leaves no temporary
}

}  // namespace tessella::sim
