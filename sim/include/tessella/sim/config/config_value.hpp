// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The typed values a configuration key can hold, and where each came from.
// Kept free of yaml-cpp so that code embedding a Simulation does not need it.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "tessella/tissue/parameters.hpp"

namespace tessella::sim {

/// The type a key expects: the parameter types of the registries
/// (tessella/tissue/parameters.hpp), so a registry entry's parameters are
/// config keys as they stand. Vec2/Vec3 are YAML sequences of 2 or 3 numbers;
/// Enum is a string from a fixed list; Path is a string naming an existing
/// file, resolved relative to the configuration file that names it.
using ValueType = ParamType;
using ConfigValue = ParamValue;

inline const char* valueTypeName(ValueType type) { return paramTypeName(type); }

/// Formats a value the way it is written in YAML (flow style for vectors,
/// shortest round-trip form for floats), so messages and run.yaml agree.
inline std::string formatValue(const ConfigValue& value) { return formatParamValue(value); }

/// Where a value was written: "file:line:column", or a --set argument.
struct SourceLocation {
  std::string file;    ///< config file path, or "--set 'key=value'" for an override
  int line = 0;        ///< 1-based; 0 when unknown (defaults, overrides)
  int column = 0;      ///< 1-based; 0 when unknown
  bool known() const { return !file.empty(); }
  /// "file:line:column" (or the parts that are known).
  std::string str() const;
};

/// Why a key has its value.
enum class ValueOrigin { Default, File, Override, Derived };

}  // namespace tessella::sim
