#pragma once
// Positional numeric arguments of the bench programs: a value that is not a
// whole number in range ends the program with a usage message, not an
// uncaught exception.

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tessella::bench {

/// argv[index] as a whole number in [lo, hi], or `fallback` when absent.
inline std::size_t countArgument(int argc, char** argv, int index, const char* name, std::size_t fallback,
                                 std::size_t lo, std::size_t hi, const char* usage) {
  if (argc <= index) return fallback;
  const std::string text = argv[index];
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
    std::fprintf(stderr, "%s: %s must be a whole number in [%zu, %zu], got '%s'\nusage: %s\n", argv[0], name, lo,
                 hi, text.c_str(), usage);
    std::exit(2);
  }
  return static_cast<std::size_t>(v);
}

/// True (after printing the usage) when the first argument asks for help.
inline bool helpRequested(int argc, char** argv, const char* usage) {
  if (argc < 2) return false;
  const std::string a = argv[1];
  if (a != "-h" && a != "--help") return false;
  std::printf("usage: %s\n", usage);
  return true;
}

}  // namespace tessella::bench
