#pragma once
// Numbers as text that reads back bit for bit (the run state a snapshot
// carries for an exact restart).

#include <charconv>
#include <string>
#include <system_error>

namespace tessella::sim::detail {

/// Shortest text that reads back to the same double.
inline std::string exactText(double x) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

/// Parses the whole of `text` into `out`; false on anything else.
template <typename T>
bool parseExact(const std::string& text, T& out) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), out);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

}  // namespace tessella::sim::detail
