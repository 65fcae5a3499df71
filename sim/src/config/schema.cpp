// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/config/schema.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tessella/tissue/parameters.hpp"

namespace tessella::sim {

std::string joinPath(const std::string& section, const std::string& name) {
  return section.empty() ? name : section + "." + name;
}

std::string parentPath(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string leafName(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

bool isTemplatePath(const std::string& path) { return path.find(kEntryPlaceholder) != std::string::npos; }

std::string KeySpec::name() const { return leafName(path); }

std::string KeySpec::rangeText() const {
  return ParamRange{.min = min, .max = max, .min_exclusive = min_exclusive, .max_exclusive = max_exclusive}.text();
}

std::string KeySpec::expectation() const {
  std::string s;
  switch (type) {
    case ValueType::Bool: return "true or false";
    case ValueType::Int: s = "an integer"; break;
    case ValueType::Float: s = "a number"; break;
    case ValueType::String: return "a string";
    case ValueType::Path: return "a file path";
    case ValueType::Vec2: return "a sequence of 2 numbers, e.g. [0, 1]";
    case ValueType::Vec3: return "a sequence of 3 numbers, e.g. [0, 1, 2]";
    case ValueType::Vec2or3: return "a sequence of 2 or 3 numbers, e.g. [0.5, 0.5] or [0.5, 0.5, 1]";
    case ValueType::Enum: {
      s = "one of ";
      for (std::size_t i = 0; i < choices.size(); ++i) s += (i ? ", " : "") + choices[i];
      return s;
    }
  }
  const std::string r = rangeText();
  return r.empty() ? s : s + " " + r;
}

SectionSpec& Schema::section(std::string path, std::string doc) {
  if (isSection(path) || findKey(path)) throw std::logic_error("schema: duplicate path " + path);
  if (!isSection(parentPath(path))) throw std::logic_error("schema: undeclared parent of " + path);
  if (isEntryMap(parentPath(path)) != (leafName(path) == kEntryPlaceholder))
    throw std::logic_error("schema: an entry map holds exactly its entry section <name>: " + path);
  order_.push_back(path);
  SectionSpec spec;
  spec.path = std::move(path);
  spec.doc = std::move(doc);
  sections_.push_back(std::move(spec));
  return sections_.back();
}

KeySpec& Schema::key(std::string path, ValueType type, std::string doc) {
  if (isSection(path) || findKey(path)) throw std::logic_error("schema: duplicate path " + path);
  if (!isSection(parentPath(path))) throw std::logic_error("schema: undeclared section of " + path);
  if (isEntryMap(parentPath(path))) throw std::logic_error("schema: keys of an entry map go in its entries: " + path);
  order_.push_back(path);
  KeySpec spec;
  spec.path = std::move(path);
  spec.type = type;
  spec.doc = std::move(doc);
  keys_.push_back(std::move(spec));
  return keys_.back();
}

KeySpec& Schema::key(const std::string& section, const ParamSpec& param) {
  KeySpec& k = key(joinPath(section, param.name), param.type, param.doc);
  k.default_value = param.default_value;
  k.absent_doc = param.absent_doc;
  k.min = param.range.min;
  k.max = param.range.max;
  k.min_exclusive = param.range.min_exclusive;
  k.max_exclusive = param.range.max_exclusive;
  k.choices = param.choices;
  if (!param.unless_set.empty()) k.unless_set = joinPath(section, param.unless_set);
  // What completeParams() requires, the schema requires too.
  k.required = !param.default_value && param.absent_doc.empty() && param.unless_set.empty();
  return k;
}

std::string Schema::templatePath(const std::string& path) const {
  bool any_map = false;
  for (const SectionSpec& s : sections_) any_map = any_map || s.entry_map;
  if (!any_map) return path;  // the common case: nothing to replace
  std::string out;
  std::size_t start = 0;
  bool after_map = false;
  while (start <= path.size()) {
    const auto dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    out = joinPath(out, after_map ? std::string(kEntryPlaceholder) : part);
    const SectionSpec* s = nullptr;
    for (const SectionSpec& candidate : sections_)
      if (candidate.path == out) s = &candidate;
    after_map = s && s->entry_map;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return out;
}

const KeySpec* Schema::findKey(const std::string& path) const {
  const std::string declared = templatePath(path);
  for (const KeySpec& k : keys_)
    if (k.path == declared) return &k;
  return nullptr;
}

const SectionSpec* Schema::findSection(const std::string& path) const {
  const std::string declared = templatePath(path);
  for (const SectionSpec& s : sections_)
    if (s.path == declared) return &s;
  return nullptr;
}

bool Schema::isEntryMap(const std::string& path) const {
  const SectionSpec* s = path.empty() ? nullptr : findSection(path);
  return s && s->entry_map;
}

std::vector<std::string> Schema::childNames(const std::string& section_path) const {
  const std::string declared = templatePath(section_path);
  std::vector<std::string> names;
  for (const std::string& p : order_)
    if (parentPath(p) == declared && !p.empty())
      names.push_back(declared.empty() ? p : p.substr(declared.size() + 1));
  return names;
}

}  // namespace tessella::sim
