// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Large fresh arrays on transparent huge pages. A bulk build
// (CellComplex::fromLoops) or an import (the 2D label image's runs, corner
// graph, walls and outlines) writes arrays of tens of MB once; faulted in 4 KB
// pages, their first touch is a large share of its time (docs/import.md,
// "Label images"; docs/generators.md, "Building from loops"). Memory advised
// with madvise(MADV_HUGEPAGE) is faulted 2 MB at a time where the kernel has
// transparent huge pages in `madvise` or `always` mode; elsewhere the advice
// changes nothing. Only the arrays that ask for it are advised: no
// process-wide malloc policy is set.
//
// - adviseHugePages(p, bytes): advise the whole 2 MB pages inside an array
//   not yet written (a plain std::vector handed on by move);
// - freshArray<T>(n [, value]): an UninitializedVector of n items so advised;
// - HugePageAllocator: arrays of at least kHugePageMin bytes mapped on their
//   own, 2 MB aligned, advised, and returned to the system when freed (an
//   import's scratch arrays); smaller ones from std::allocator.
//   HugePageVector value-initialises as std::vector does;
//   HugePageUninitializedVector leaves new items unwritten (as
//   UninitializedVector).

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella::detail {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
/// Below this an array is left alone (a huge page would be mostly unused).
inline constexpr std::size_t kHugePageMin = std::size_t{4} << 20;

/// Advises huge pages for the whole 2 MB pages inside [data, data + bytes);
/// nothing for arrays below kHugePageMin or off Linux. A hint: errors ignored.
void adviseHugePages(const void* data, std::size_t bytes);

/// `bytes` (>= kHugePageMin) of zeroed memory, 2 MB aligned and advised;
/// std::bad_alloc if it cannot be mapped. Freed by unmapHugePages.
void* mapHugePages(std::size_t bytes);
void unmapHugePages(void* p, std::size_t bytes) noexcept;

/// n unwritten items in storage advised for huge pages.
template <typename T>
UninitializedVector<T> freshArray(std::size_t n) {
  UninitializedVector<T> v;
  v.reserve(n);  // allocates, writes nothing
  adviseHugePages(v.data(), n * sizeof(T));
  v.resize(n);
  return v;
}

/// n copies of value in storage advised for huge pages, written on one thread
/// (a fill of a few MB costs less than a parallel region's team on a busy machine).
template <typename T>
UninitializedVector<T> freshArray(std::size_t n, T value) {
  UninitializedVector<T> v = freshArray<T>(n);
  std::fill(v.begin(), v.end(), value);
  return v;
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

template <typename T>
using HugePageVector = std::vector<T, HugePageAllocator<T, true>>;
template <typename T>
using HugePageUninitializedVector = std::vector<T, HugePageAllocator<T, false>>;

}  // namespace tessella::detail
