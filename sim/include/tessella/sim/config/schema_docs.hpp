// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The key reference of docs/config.md, generated from the schema
// (`tessella schema` prints it), so the docs cannot drift from the code.

#include <string>

#include "tessella/sim/config/schema.hpp"

namespace tessella::sim {

/// Markdown: one table per section (key, type, default, range/choices,
/// meaning), sections in declaration order.
std::string schemaReferenceMarkdown(const Schema& schema);

/// Markers around the generated reference in docs/config.md.
inline constexpr const char* kReferenceBegin = "<!-- BEGIN GENERATED KEY REFERENCE (tessella schema) -->";
inline constexpr const char* kReferenceEnd = "<!-- END GENERATED KEY REFERENCE -->";

}  // namespace tessella::sim
