// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// HugePageAllocator: an allocator for the large intermediate arrays of an
// import (the 2D label image's runs, corner graph, walls and outlines), tens
// of megabytes each, written once and freed within the call. Fresh memory is
// faulted in 4 KB pages: a 4096^2 image's arrays took about 60 000 page faults
// per import (docs/import.md, "Label images"). An allocation of at least
// kHugePageMin bytes is mapped on its own, 2 MB aligned, with
// madvise(MADV_HUGEPAGE), so the kernel backs it with 2 MB pages where it has
// them (transparent huge pages in `madvise` or `always` mode; otherwise it is
// ordinary memory) and returns it to the system when freed. Smaller ones go
// to std::allocator. Only the memory of the containers using it is advised:
// nothing process-wide (malloc's own settings) is changed.
//
// kValueInit false: default construction writes nothing (as
// UninitializedAllocator), for arrays whose items are all written later.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessella::io::detail {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
/// Below this an allocation goes to std::allocator (a huge page would be mostly unused).
inline constexpr std::size_t kHugePageMin = std::size_t{4} << 20;

/// `bytes` (>= kHugePageMin) of zeroed memory, 2 MB aligned and advised to huge pages; freed by unmapHugePages.
inline void* mapHugePages(std::size_t bytes) {
  const std::size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  // Mapped one huge page longer, then trimmed to a 2 MB aligned start (mmap aligns to 4 KB only).
  void* raw = ::mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start) ::munmap(raw, aligned - start);
  if (const std::uintptr_t end = start + size + kHugePage, used = aligned + size; end > used)
    ::munmap(reinterpret_cast<void*>(used), end - used);
  ::madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // advice: ordinary pages if refused
  return reinterpret_cast<void*>(aligned);
}

inline void unmapHugePages(void* p, std::size_t bytes) {
  ::munmap(p, (bytes + kHugePage - 1) / kHugePage * kHugePage);
}

/// Advises the 2 MB aligned pages inside [p, p + bytes) to huge pages: for a large array that must be a plain
/// std::vector (handed on by move) and is not yet written. The advice is only that: it changes no contents.
inline void adviseHugePages(void* p, std::size_t bytes) {
  if (bytes < kHugePageMin) return;
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (start + kHugePage - 1) / kHugePage * kHugePage;
  const std::uintptr_t last = (start + bytes) / kHugePage * kHugePage;
  if (last > first) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

template <typename T, bool kValueInit = true>
class HugePageAllocator {
 public:
  using value_type = T;
  template <typename U>
  struct rebind {
    using other = HugePageAllocator<U, kValueInit>;
  };
  HugePageAllocator() noexcept = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U, kValueInit>&) noexcept {}  // NOLINT: converting, as std::allocator

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMin) return std::allocator<T>().allocate(n);
    return static_cast<T*>(mapHugePages(bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMin) std::allocator<T>().deallocate(p, n);
    else unmapHugePages(p, bytes);
  }

  /// Default construction: a value-initialised item, or (kValueInit false) nothing written.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    if constexpr (kValueInit) ::new (static_cast<void*>(p)) U();
    else static_assert(std::is_trivially_copyable_v<U>, "items left unwritten must be trivially copyable");
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T, typename U, bool I>
bool operator==(const HugePageAllocator<T, I>&, const HugePageAllocator<U, I>&) noexcept {
  return true;
}

/// A std::vector of large arrays (see above), value-initialising as std::vector does.
template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T, true>>;
/// The same, with resize(n) leaving new items unwritten (as UninitializedVector).
template <typename T>
using HugePageUninitializedVector = std::vector<T, HugePageAllocator<T, false>>;

}  // namespace tessella::io::detail
