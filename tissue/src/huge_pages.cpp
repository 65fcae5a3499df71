// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/huge_pages.hpp"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tessella::detail {

void adviseHugePages([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < kHugePageMin) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHugePage - 1);
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

#if defined(__linux__)
void* mapHugePages(std::size_t bytes) {
  const std::size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  // Mapped one huge page longer, then trimmed to a 2 MB aligned start (mmap aligns to 4 KB only).
  void* raw = ::mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) ::munmap(raw, aligned - start);
  if (const std::uintptr_t end = start + size + kHugePage, used = aligned + size; end > used)
    ::munmap(reinterpret_cast<void*>(used), end - used);
#if defined(MADV_HUGEPAGE)
  (void)::madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // advice: ordinary pages if refused
#endif
  return reinterpret_cast<void*>(aligned);
}

void unmapHugePages(void* p, std::size_t bytes) noexcept {
  ::munmap(p, (bytes + kHugePage - 1) / kHugePage * kHugePage);
}
#else
// Elsewhere: ordinary zeroed memory.
void* mapHugePages(std::size_t bytes) {
  void* p = std::calloc(1, bytes);
  if (!p) throw std::bad_alloc();
  return p;
}
void unmapHugePages(void* p, std::size_t) noexcept { std::free(p); }
#endif

}  // namespace tessella::detail
