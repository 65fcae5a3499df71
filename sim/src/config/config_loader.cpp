// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/config/config_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "tessella/sim/config/suggest.hpp"
#include "tessella/tissue/excerpt.hpp"

namespace fs = std::filesystem;

namespace tessella::sim {

namespace {

std::string quoted(const std::string& s) {
  return "'" + excerpt(s, 60) + "'";  // a pasted blob must not flood the message
}

std::string describe(const YAML::Node& node) {
  if (!node || node.IsNull()) return "nothing";
  if (node.IsScalar()) return quoted(node.Scalar());
  if (node.IsSequence()) return "a sequence";
  if (node.IsMap()) return "a mapping";
  return "an unknown node";
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::optional<std::int64_t> parseInt(std::string s) {
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  std::int64_t v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::optional<double> parseDouble(std::string s) {
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

/// Walks YAML nodes against the schema, filling a Config.
class Loader {
 public:
  Loader(const Schema& schema, Config& config) : schema_(schema), config_(config) {}

  void loadDocument(const YAML::Node& root, const std::string& file, const fs::path& base) {
    source_ = file;
    base_ = base;
    origin_ = ValueOrigin::File;
    if (!root || root.IsNull()) return;  // an empty file: every key takes its default
    if (!root.IsMap())
      throw ConfigError(at(root.Mark()), "",
                        "the top level must be a mapping of sections and keys, got " + describe(root));
    walkSection(root, "", at(root.Mark()));
  }

  void loadOverride(const std::string& argument) {
    source_ = "--set " + argument;
    base_ = fs::current_path();
    origin_ = ValueOrigin::Override;
    const SourceLocation where{source_, 0, 0};
    const auto eq = argument.find('=');
    std::string path = eq == std::string::npos ? std::string() : argument.substr(0, eq);
    path.erase(0, path.find_first_not_of(" \t"));
    path.erase(path.find_last_not_of(" \t") + 1);
    if (path.empty()) throw ConfigError(where, "", "expected KEY.PATH=VALUE, e.g. time.end=20");
    YAML::Node value;
    try {
      value = YAML::Load(argument.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw ConfigError(where, path, "the value is not valid YAML: " + e.msg);
    }
    if (schema_.isSection(path)) return walkSection(value, path, where);
    if (const KeySpec* spec = schema_.findKey(path)) {
      noteEntries(path, where);
      return setValue(path, *spec, value, where);
    }
    unknownPath(path, where);
  }

  /// Defaults, required keys and notes, once every source is in.
  void finish() {
    // Keys declared inside entry maps exist once per entry given.
    for (const KeySpec& spec : schema_.keys())
      for (const std::string& path : concretePaths(spec.path))
        if (!config_.has(path) && spec.default_value)
          config_.set(path, *spec.default_value, {}, ValueOrigin::Default);
    for (const KeySpec& spec : schema_.keys())
      for (const std::string& path : concretePaths(spec.path)) {
        if (!spec.required || config_.has(path) || !config_.isActive(path)) continue;
        SourceLocation where{config_.source(), 0, 0};
        for (std::string s = parentPath(path);; s = parentPath(s)) {
          if (auto it = section_marks_.find(s); it != section_marks_.end()) {
            where = it->second;
            break;
          }
          if (s.empty()) break;
        }
        throw ConfigError(where, path, "missing required key; expected " + spec.expectation());
      }
    std::set<std::string> noted;
    for (const auto& [path, entry] : config_.entries()) {
      if (entry.origin == ValueOrigin::Default || config_.isActive(path)) continue;
      std::string outer = path;  // the outermost inactive part names the reason
      while (!parentPath(outer).empty() && !config_.isActive(parentPath(outer))) outer = parentPath(outer);
      if (!noted.insert(outer).second) continue;
      config_.addNote(entry.where.str() + ": " + outer + " is ignored: " + inactiveReason(outer));
    }
  }

 private:
  SourceLocation at(const YAML::Mark& mark) const {
    if (origin_ == ValueOrigin::Override || mark.is_null()) return {source_, 0, 0};
    return {source_, mark.line + 1, mark.column + 1};
  }

  /// The concrete paths of a declared one: itself, or one per entry given
  /// for each entry-map level it passes through.
  std::vector<std::string> concretePaths(const std::string& declared) const {
    const std::string marker = std::string(".") + kEntryPlaceholder;
    const auto at = declared.find(marker);
    if (at == std::string::npos) return {declared};
    const std::string map = declared.substr(0, at), rest = declared.substr(at + marker.size());
    std::vector<std::string> out;
    for (const std::string& name : config_.entryNames(map))
      for (std::string p : concretePaths(joinPath(map, name) + rest)) out.push_back(std::move(p));
    return out;
  }

  /// Records the entry names along `path` (an entry map's children), checking
  /// each: it names outputs and expression variables, so letters, digits and
  /// '_', not starting with a digit.
  void noteEntries(const std::string& path, const SourceLocation& where) {
    std::string prefix;
    std::size_t start = 0;
    while (start < path.size()) {
      const auto dot = path.find('.', start);
      const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      if (schema_.isEntryMap(prefix)) {
        const std::string kind = schema_.findSection(prefix)->entry_kind;
        bool ok = !part.empty() && !std::isdigit(static_cast<unsigned char>(part[0]));
        for (unsigned char ch : part) ok = ok && (std::isalnum(ch) || ch == '_');
        if (!ok)
          throw ConfigError(where, joinPath(prefix, part),
                            "bad " + kind + " name " + quoted(part) +
                                "; a name is letters, digits and '_', not starting with a digit");
        config_.addEntry(prefix, part, where);
      }
      prefix = joinPath(prefix, part);
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
  }

  std::string inactiveReason(const std::string& path) const {
    std::optional<Condition> c;
    if (const SectionSpec* s = schema_.findSection(path)) {
      if (!s->unless_set.empty() && config_.isSet(s->unless_set)) return s->unless_set + " is given";
      c = s->active_when;
    }
    if (const KeySpec* k = schema_.findKey(path)) {
      if (!k->unless_set.empty() && config_.isSet(k->unless_set)) return k->unless_set + " is given";
      c = k->active_when;
    }
    if (!c || !config_.has(c->key)) return "it does not apply";
    return c->key + " is " + formatValue(config_.entry(c->key).value);
  }

  void walkSection(const YAML::Node& node, const std::string& section, const SourceLocation& where) {
    noteEntries(section, where);  // before the empty check: "A:" alone is an entry with defaults
    if (!node || node.IsNull()) return;  // "tissue:" alone is an empty section
    if (!node.IsMap())
      throw ConfigError(at(node.Mark()), section,
                        "expected a section (key: value lines), got " + describe(node));
    if (origin_ == ValueOrigin::File) section_marks_.emplace(section, at(node.Mark()));
    std::map<std::string, YAML::Mark> seen;
    for (auto it = node.begin(); it != node.end(); ++it) {
      const YAML::Node& key = it->first;
      const YAML::Node& value = it->second;
      if (!key.IsScalar())
        throw ConfigError(at(key.Mark()), section, "a key must be a plain name, got " + describe(key));
      const std::string name = key.Scalar();
      const std::string path = joinPath(section, name);
      if (auto [first, inserted] = seen.emplace(name, key.Mark()); !inserted)
        throw ConfigError(at(key.Mark()), path,
                          "duplicate key (first given at " + at(first->second).str() + ")");
      if (schema_.isSection(path)) {  // in an entry map, every name is an entry (checked by noteEntries)
        walkSection(value, path, at(key.Mark()));
      } else if (const KeySpec* spec = schema_.findKey(path)) {
        const bool has_mark = value && !value.IsNull() && !value.Mark().is_null();
        setValue(path, *spec, value, at(has_mark ? value.Mark() : key.Mark()));
      } else {
        throw ConfigError(at(key.Mark()), path, unknownProblem(name, section));
      }
    }
  }

  std::string unknownProblem(const std::string& name, const std::string& section) const {
    const std::vector<std::string> siblings = schema_.childNames(section);
    std::string problem = "unknown key " + quoted(name);
    if (auto m = closestMatch(name, siblings)) return problem + "; did you mean '" + *m + "'?";
    // Right name, wrong place? ("count" at the top level)
    std::vector<std::string> elsewhere;
    for (const KeySpec& k : schema_.keys())
      if (k.name() == name) elsewhere.push_back(k.path);
    if (!elsewhere.empty()) {
      problem += "; did you mean '" + elsewhere[0] + "'";
      for (std::size_t i = 1; i < elsewhere.size(); ++i) problem += " or '" + elsewhere[i] + "'";
      return problem + "?";
    }
    problem += "; known keys here: ";
    for (std::size_t i = 0; i < siblings.size(); ++i) problem += (i ? ", " : "") + siblings[i];
    return problem;
  }

  /// An override path that is not in the schema: find where it leaves it.
  [[noreturn]] void unknownPath(const std::string& path, const SourceLocation& where) const {
    std::string section;
    std::size_t start = 0;
    while (true) {
      const auto dot = path.find('.', start);
      const std::string name = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      const std::string here = joinPath(section, name);
      if (dot != std::string::npos && schema_.isSection(here)) {
        section = here;
        start = dot + 1;
        continue;
      }
      if (dot != std::string::npos && schema_.findKey(here))
        throw ConfigError(where, path, here + " is a value, not a section");
      std::string problem = unknownProblem(name, section);
      // For overrides, name the whole corrected path.
      if (auto m = closestMatch(name, schema_.childNames(section)))
        problem = "unknown key " + quoted(name) + "; did you mean '" + joinPath(section, *m) +
                  (dot == std::string::npos ? "" : path.substr(dot)) + "'?";
      throw ConfigError(where, path, problem);
    }
  }

  // `path` is the concrete path of `spec` (they differ inside entry maps).
  void setValue(const std::string& path, const KeySpec& spec, const YAML::Node& node, const SourceLocation& where) {
    config_.set(path, convert(path, spec, node, where), where, origin_);
  }

  ConfigValue convert(const std::string& path, const KeySpec& spec, const YAML::Node& node,
                      const SourceLocation& where) const {
    auto fail = [&](const std::string& problem) -> ConfigError {
      return ConfigError(where, path, problem);
    };
    auto expected = [&](const YAML::Node& n) {
      return fail("expected " + spec.expectation() + ", got " + describe(n));
    };
    if (!node || node.IsNull()) throw fail("no value given; expected " + spec.expectation());
    switch (spec.type) {
      case ValueType::Bool: {
        if (!node.IsScalar()) throw expected(node);
        const std::string s = lower(node.Scalar());
        if (s == "true" || s == "yes" || s == "on") return true;
        if (s == "false" || s == "no" || s == "off") return false;
        throw expected(node);
      }
      case ValueType::Int: {
        if (!node.IsScalar()) throw expected(node);
        auto v = parseInt(node.Scalar());
        if (!v) throw expected(node);
        checkRange(path, spec, static_cast<double>(*v), node, where);
        return *v;
      }
      case ValueType::Float: {
        if (!node.IsScalar()) throw expected(node);
        auto v = parseDouble(node.Scalar());
        if (!v || !std::isfinite(*v)) throw expected(node);
        checkRange(path, spec, *v, node, where);
        return *v;
      }
      case ValueType::String:
        if (!node.IsScalar()) throw expected(node);
        return node.Scalar();
      case ValueType::Enum: {
        if (!node.IsScalar()) throw expected(node);
        const std::string& s = node.Scalar();
        if (std::find(spec.choices.begin(), spec.choices.end(), s) != spec.choices.end()) return s;
        std::string problem = "expected " + spec.expectation() + ", got " + describe(node);
        if (auto m = closestMatch(s, spec.choices)) problem += "; did you mean '" + *m + "'?";
        throw fail(problem);
      }
      case ValueType::Vec2:
      case ValueType::Vec3:
      case ValueType::Vec2or3: {
        const std::size_t n =
            spec.type == ValueType::Vec2 || (spec.type == ValueType::Vec2or3 && node.IsSequence() && node.size() == 2)
                ? 2
                : 3;
        if (!node.IsSequence() || node.size() != n) {
          std::string got = describe(node);
          if (node.IsSequence()) got = "a sequence of " + std::to_string(node.size());
          throw fail("expected " + spec.expectation() + ", got " + got);
        }
        std::vector<double> v;
        for (std::size_t i = 0; i < n; ++i) {
          const YAML::Node item = node[i];
          std::optional<double> x;
          if (item.IsScalar()) x = parseDouble(item.Scalar());
          if (!x || !std::isfinite(*x)) {
            const bool has_mark = origin_ == ValueOrigin::File && !item.Mark().is_null();
            throw ConfigError(has_mark ? at(item.Mark()) : where,
                              path + "[" + std::to_string(i) + "]",
                              "expected a finite number, got " + describe(item));
          }
          v.push_back(*x);
        }
        return v;
      }
      case ValueType::Path: {
        if (!node.IsScalar() || node.Scalar().empty()) throw expected(node);
        const fs::path given = node.Scalar();
        const fs::path full = (given.is_absolute() ? given : base_ / given).lexically_normal();
        std::error_code ec;
        const auto status = fs::status(full, ec);
        if (ec || !fs::exists(status))
          throw fail("file not found: " + quoted(given.string()) + " (looked for " + full.string() + ")");
        if (!fs::is_regular_file(status))
          throw fail(quoted(given.string()) + " is not a regular file (" + full.string() + ")");
        return full.string();
      }
    }
    throw fail("unsupported value type");
  }

  static void checkRange(const std::string& path, const KeySpec& spec, double v, const YAML::Node& node,
                         const SourceLocation& where) {
    const bool low = spec.min && (spec.min_exclusive ? v <= *spec.min : v < *spec.min);
    const bool high = spec.max && (spec.max_exclusive ? v >= *spec.max : v > *spec.max);
    if (low || high)
      throw ConfigError(where, path,
                        "value " + node.Scalar() + " is out of range; expected " + spec.expectation());
  }

  const Schema& schema_;
  Config& config_;
  std::string source_;
  fs::path base_;
  ValueOrigin origin_ = ValueOrigin::File;
  std::map<std::string, SourceLocation> section_marks_;
};

/// The 1-based line of the `---` that starts the document whose first node is
/// on 0-based line `content_line` (that line itself when no marker precedes it).
int documentStartLine(const std::string& text, int content_line) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.emplace_back(text.data() + start, end - start);
    start = end + 1;
  }
  for (int i = std::min<int>(content_line, static_cast<int>(lines.size()) - 1); i >= 0; --i) {
    const std::string_view l = lines[static_cast<std::size_t>(i)];
    if (l.rfind("---", 0) == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r')) return i + 1;
  }
  return content_line + 1;
}

YAML::Node parseYaml(const std::string& text, const std::string& source) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    SourceLocation where{source, 0, 0};
    if (!e.mark.is_null()) where = {source, e.mark.line + 1, e.mark.column + 1};
    throw ConfigError(where, "", "malformed YAML: " + e.msg);
  }
  // A second document (after a `---`) would be ignored: refuse it.
  if (documents.size() > 1) {
    const YAML::Mark mark = documents[1].Mark();
    const int line = documentStartLine(text, mark.is_null() ? 0 : mark.line);
    throw ConfigError(SourceLocation{source, line, 1}, "",
                      "a second YAML document starts here; a config is one document, so its keys would be "
                      "ignored: remove this '---' (and join the keys to the first document) or split the file");
  }
  return documents.empty() ? YAML::Node() : documents.front();
}

Config load(const std::string& text, const std::vector<std::string>& overrides, const Schema& schema,
            const std::string& name, const std::string& source, const fs::path& base) {
  Config config(schema, name, source, base.string());
  Loader loader(schema, config);
  loader.loadDocument(parseYaml(text, source), source, base);
  for (const std::string& o : overrides) loader.loadOverride(o);
  loader.finish();
  return config;
}

}  // namespace

Config loadConfigFile(const std::string& path, const std::vector<std::string>& overrides,
                      const Schema& schema) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw ConfigError(SourceLocation{path, 0, 0}, "",
                      fs::exists(path, ec) ? "not a regular file" : "config file not found");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(SourceLocation{path, 0, 0}, "", "cannot open the config file");
  std::ostringstream text;
  text << in.rdbuf();
  const fs::path full = fs::absolute(path).lexically_normal();
  return load(text.str(), overrides, schema, full.stem().string(), path, full.parent_path());
}

Config loadConfigString(const std::string& yaml, const std::vector<std::string>& overrides,
                        const Schema& schema, const std::string& name, const std::string& source,
                        const std::string& base_directory) {
  return load(yaml, overrides, schema, name, source, fs::absolute(base_directory).lexically_normal());
}

}  // namespace tessella::sim
