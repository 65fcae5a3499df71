// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/version_stamp.hpp"

#include <atomic>

namespace tessella {

std::uint64_t VersionStamp::next() {
  // Each thread draws its values from blocks it reserves from one global
  // counter: unique across threads, without an atomic operation per bump
  // (building a tissue bumps once per element).
  constexpr std::uint64_t kBlock = 1u << 16;
  static std::atomic<std::uint64_t> blocks{0};
  thread_local std::uint64_t next_value = 0, block_end = 0;
  if (next_value == block_end) {
    next_value = blocks.fetch_add(1, std::memory_order_relaxed) * kBlock + 1;  // 0 is never a value
    block_end = next_value + kBlock;
  }
  return next_value++;
}

}  // namespace tessella
