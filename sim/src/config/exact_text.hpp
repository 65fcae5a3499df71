// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Reading back numbers written as text bit for bit (the run state a snapshot
// carries for an exact restart); they are written by tessella::formatNumber.

#include <charconv>
#include <string>
#include <system_error>

namespace tessella::sim::detail {

/// Parses the whole of `text` into `out`; false on anything else.
template <typename T>
bool parseExact(const std::string& text, T& out) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

}  // namespace tessella::sim::detail
