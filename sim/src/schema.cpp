#include "tessella/sim/schema.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tessella::sim {

std::string joinPath(const std::string& section, const std::string& name) {
  return section.empty() ? name : section + "." + name;
}

std::string parentPath(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string KeySpec::name() const {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

namespace {
std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

std::string KeySpec::rangeText() const {
  std::string s;
  if (min) s += (min_exclusive ? "> " : ">= ") + number(*min);
  if (max) s += (s.empty() ? "" : " and ") + std::string(max_exclusive ? "< " : "<= ") + number(*max);
  return s;
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
  order_.push_back(path);
  sections_.push_back(SectionSpec{std::move(path), std::move(doc), std::nullopt});
  return sections_.back();
}

KeySpec& Schema::key(std::string path, ValueType type, std::string doc) {
  if (isSection(path) || findKey(path)) throw std::logic_error("schema: duplicate path " + path);
  if (!isSection(parentPath(path))) throw std::logic_error("schema: undeclared section of " + path);
  order_.push_back(path);
  KeySpec spec;
  spec.path = std::move(path);
  spec.type = type;
  spec.doc = std::move(doc);
  keys_.push_back(std::move(spec));
  return keys_.back();
}

const KeySpec* Schema::findKey(const std::string& path) const {
  for (const KeySpec& k : keys_)
    if (k.path == path) return &k;
  return nullptr;
}

const SectionSpec* Schema::findSection(const std::string& path) const {
  for (const SectionSpec& s : sections_)
    if (s.path == path) return &s;
  return nullptr;
}

std::vector<std::string> Schema::childNames(const std::string& section_path) const {
  std::vector<std::string> names;
  for (const std::string& p : order_)
    if (parentPath(p) == section_path && !p.empty())
      names.push_back(section_path.empty() ? p : p.substr(section_path.size() + 1));
  return names;
}

}  // namespace tessella::sim
