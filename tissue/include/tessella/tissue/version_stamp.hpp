// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// VersionStamp: a change counter whose values are unique in the process.
//
// Caches key their contents on a tissue's topology and geometry versions. A
// per-tissue counter would let a cache mistake another tissue (built the same
// way, or rebuilt at the same address) for the one it was filled from; here
// every bump takes a value no other stamp has had. A copy keeps the value: it
// has the same content until one of the two changes (and then gets a new one).

#include <cstdint>

namespace tessella {

class VersionStamp {
 public:
  VersionStamp() : value_(next()) {}
  /// Moves to a new value, which no stamp has had (greater than those this thread gave before).
  VersionStamp& operator++() {
    value_ = next();
    return *this;
  }
  std::uint64_t value() const { return value_; }

 private:
  static std::uint64_t next();
  std::uint64_t value_;
};

}  // namespace tessella
