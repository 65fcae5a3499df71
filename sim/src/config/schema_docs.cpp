// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/config/schema_docs.hpp"

namespace tessella::sim {

namespace {

std::string escapeCell(std::string s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string defaultText(const KeySpec& k) {
  if (k.default_value) return "`" + formatValue(*k.default_value) + "`";
  if (k.required) return "**required**";
  return k.absent_doc.empty() ? "—" : k.absent_doc;
}

std::string allowedText(const KeySpec& k) {
  if (k.type == ValueType::Enum) {
    std::string s;
    for (std::size_t i = 0; i < k.choices.size(); ++i) s += (i ? ", " : "") + ("`" + k.choices[i] + "`");
    return s;
  }
  const std::string r = k.rangeText();
  return r.empty() ? "—" : r;
}

std::string conditionText(const std::optional<Condition>& c) {
  if (!c) return "";
  std::string s = "Used when `" + c->key + "` is ";
  for (std::size_t i = 0; i < c->values.size(); ++i) s += (i ? " or " : "") + ("`" + c->values[i] + "`");
  return s + ". ";
}

void table(std::string& out, const Schema& schema, const std::string& section) {
  std::string rows;
  for (const std::string& name : schema.childNames(section)) {
    const KeySpec* k = schema.findKey(joinPath(section, name));
    if (!k) continue;
    const std::string unless = k->unless_set.empty() ? "" : "Not used when `" + k->unless_set + "` is given. ";
    rows += "| `" + k->path + "` | " + valueTypeName(k->type) + " | " + escapeCell(defaultText(*k)) + " | " +
            escapeCell(allowedText(*k)) + " | " + escapeCell(conditionText(k->active_when) + unless + k->doc) +
            " |\n";
  }
  if (rows.empty()) return;
  out += "| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n" + rows + "\n";
}

}  // namespace

std::string schemaReferenceMarkdown(const Schema& schema) {
  std::string out;
  out += "### Top level\n\n";
  table(out, schema, "");
  for (const SectionSpec& s : schema.sections()) {
    const std::string unless = s.unless_set.empty() ? "" : "Not used when `" + s.unless_set + "` is given. ";
    out += "### `" + s.path + "`\n\n" + conditionText(s.active_when) + unless + s.doc + "\n\n";
    table(out, schema, s.path);
  }
  return out;
}

}  // namespace tessella::sim
