// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Reading the compact values of the solver sections: "name=value" lists
// (per-type coefficients, conditions per boundary region), lineage-id lists
// and the keys every solver section shares (every, dt, scheme, source).
// Every problem is a ConfigError at the key.

#include <string>
#include <utility>
#include <vector>

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/registry_config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/sections/coupling_section.hpp"

namespace tessella::sim::detail {

/// "a=1, b=2.5" -> {(a, 1), (b, 2.5)} in order; names must be distinct.
std::vector<std::pair<std::string, std::string>> parseNamedItems(const Config& c, const std::string& key);
double parseNumber(const Config& c, const std::string& key, const std::string& item, const std::string& text);
BoundaryRegion parseRegion(const Config& c, const std::string& key, const std::string& name);
/// "x_min=1, x_max=0" -> region values.
std::vector<RegionValue> parseRegionValues(const Config& c, const std::string& key);
/// "0=1.5, 2=0.1" -> by-type map (integer types).
std::map<std::int64_t, double> parseTypeValues(const Config& c, const std::string& key);
/// "3, 17, 42" -> integers.
std::vector<std::int64_t> parseIdList(const Config& c, const std::string& key, const std::string& text);

/// The shared keys of a solver section at `prefix`, active when `when` holds.
void declareEveryAndStep(Schema& s, const std::string& prefix, const Condition& when);
/// Declares the section `<prefix>.source` and its keys; returns the section.
SectionSpec& declareSourceKeys(Schema& s, const std::string& prefix, const Condition& when);
/// Declares `path` (e.g. "diffusion.decay_by"): the per-cell-type values of
/// a coefficient, a string "type=value, ...", uniform when absent.
KeySpec& declarePerTypeKey(Schema& s, const std::string& path, const std::string& doc, const Condition& when);
SourceSpec readSource(const Config& c, const std::string& prefix);
/// Reads `<prefix>.<name>` (uniform) and `<prefix>.<name>_by` (per type,
/// checked against the uniform key's range, and needing the key
/// `by_property`, by default `<prefix>.by_property`).
CellCoefficient readCoefficient(const Config& c, const std::string& prefix, const std::string& name,
                                const std::string& by_property = "");

}  // namespace tessella::sim::detail
