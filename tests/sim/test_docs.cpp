// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "tessella/sim/config/schema_docs.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "test_support.hpp"

using namespace tessella::sim;
using tessella::sim::test::sourcePath;

namespace {
std::string docsText() {
  std::ifstream f(sourcePath("docs/config.md"));
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("docs/config.md documents every key and section of the schema", "[sim][docs]") {
  const std::string docs = docsText();
  REQUIRE_FALSE(docs.empty());
  for (const KeySpec& k : tessellaSchema().keys()) {
    INFO(k.path);
    CHECK(docs.find("`" + k.path + "`") != std::string::npos);
    CHECK_FALSE(k.doc.empty());
  }
  for (const SectionSpec& s : tessellaSchema().sections()) {
    INFO(s.path);
    CHECK(docs.find("### `" + s.path + "`") != std::string::npos);
  }
}

TEST_CASE("the key reference in docs/config.md is the one the schema generates", "[sim][docs]") {
  const std::string docs = docsText();
  const auto begin = docs.find(kReferenceBegin);
  const auto end = docs.find(kReferenceEnd);
  REQUIRE(begin != std::string::npos);
  REQUIRE(end != std::string::npos);
  const auto from = begin + std::string(kReferenceBegin).size() + 1;  // after the marker's newline
  // Regenerate with: tessella schema, pasted between the markers.
  CHECK(docs.substr(from, end - from) == schemaReferenceMarkdown(tessellaSchema()));
}

TEST_CASE("schema declarations are consistent", "[sim][schema]") {
  for (const KeySpec& k : tessellaSchema().keys()) {
    INFO(k.path);
    // A key has a default, is required, or says what its absence means.
    CHECK((k.default_value.has_value() || k.required || !k.absent_doc.empty()));
    if (k.type == ValueType::Enum) {
      CHECK_FALSE(k.choices.empty());
      if (k.default_value)
        CHECK(std::find(k.choices.begin(), k.choices.end(), std::get<std::string>(*k.default_value)) !=
              k.choices.end());
    }
    if (k.default_value && k.type == ValueType::Int) {
      const double v = static_cast<double>(std::get<std::int64_t>(*k.default_value));
      if (k.min) CHECK(v >= *k.min);
      if (k.max) CHECK(v <= *k.max);
    }
    if (k.default_value && k.type == ValueType::Float) {
      const double v = std::get<double>(*k.default_value);
      if (k.min) CHECK((k.min_exclusive ? v > *k.min : v >= *k.min));
      if (k.max) CHECK(v <= *k.max);
    }
    if (k.active_when) {
      const KeySpec* controller = tessellaSchema().findKey(k.active_when->key);
      REQUIRE(controller);
      CHECK(controller->type == ValueType::Enum);
    }
  }
  for (const SectionSpec& s : tessellaSchema().sections())
    if (s.active_when) {
      const KeySpec* controller = tessellaSchema().findKey(s.active_when->key);
      REQUIRE(controller);
      for (const std::string& v : s.active_when->values)
        CHECK(std::find(controller->choices.begin(), controller->choices.end(), v) != controller->choices.end());
    }
}
