// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Positional numeric arguments of the bench programs: a value that is not a
// whole number in range ends the program with a usage message, not an
// uncaught exception.

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
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

/// For programs whose only argument is one optional flag: answers --help /
/// -h with the usage (exit 0) and refuses anything but one of `flags` with
/// one line (exit 2). Returns the flag given, or "" when there is none.
inline std::string flagArgument(int argc, char** argv, std::initializer_list<const char*> flags, const char* usage) {
  if (helpRequested(argc, argv, usage)) std::exit(0);
  if (argc < 2) return "";
  const std::string a = argv[1];
  bool listed = false;
  for (const char* f : flags) listed = listed || a == f;
  if (!listed || argc > 2) {
    std::fprintf(stderr, "%s: unexpected argument '%s'; usage: %s\n", argv[0], listed ? argv[2] : argv[1], usage);
    std::exit(2);
  }
  return a;
}

}  // namespace tessella::bench
