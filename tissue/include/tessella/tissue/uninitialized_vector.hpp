// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// UninitializedVector: a std::vector of trivially copyable items whose
// resize(n) and vector(n) leave the new items unwritten (the allocator's
// construct without arguments does nothing), for arrays that grow in one
// serial step and are then written in parallel (Tissue::splitCells): the
// value-initialising write of every new item (and the first touch of its
// memory page) no longer runs serially before the parallel writes.
// Items are written only with a value (push_back, insert, assignment,
// construct(p, value)) or stay unspecified until written.
//
// growInParallel(v, n): v.resize(n), but a reallocation copies the old items
// in parallel (OpenMP) into the new storage instead of one thread's memmove;
// filledInParallel(n, value): n copies of value, written in parallel.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessella {

template <typename T>
class UninitializedAllocator : public std::allocator<T> {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "items left unwritten must be trivially copyable and destructible");

 public:
  using value_type = T;
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() noexcept = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}  // NOLINT: converting, as std::allocator

  /// Default construction: nothing is written.
  template <typename U>
  void construct(U*) noexcept {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T, typename U>
bool operator==(const UninitializedAllocator<T>&, const UninitializedAllocator<U>&) noexcept {
  return true;
}

template <typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

/// Below this many items a reallocation copies on one thread.
inline constexpr std::size_t kParallelCopyMin = std::size_t{1} << 16;

/// v.resize(n) where new items need no value (for UninitializedVector, and
/// for std::vector of types whose default constructor writes nothing, such as
/// Eigen's fixed-size vectors). When n exceeds the capacity, the storage
/// grows to at least twice the size and the old items are copied in parallel.
template <typename T, typename A>
void growInParallel(std::vector<T, A>& v, std::size_t n) {
  if (n <= v.capacity()) {
    v.resize(n);
    return;
  }
  std::vector<T, A> grown(v.get_allocator());
  grown.reserve(std::max(n, 2 * v.size()));
  grown.resize(n);
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(v.size());
  constexpr std::ptrdiff_t kBlock = 4096;
  const std::ptrdiff_t blocks = (m + kBlock - 1) / kBlock;
  const T* from = v.data();
  T* to = grown.data();
#pragma omp parallel for schedule(static) if (v.size() >= kParallelCopyMin)
  for (std::ptrdiff_t b = 0; b < blocks; ++b)
    std::copy(from + b * kBlock, from + std::min(m, (b + 1) * kBlock), to + b * kBlock);
  v.swap(grown);
}

/// n copies of value, written in parallel (OpenMP) for large n.
template <typename T>
UninitializedVector<T> filledInParallel(std::size_t n, T value) {
  UninitializedVector<T> v(n);
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (n >= kParallelCopyMin)
  for (std::ptrdiff_t i = 0; i < m; ++i) v[i] = value;
  return v;
}

}  // namespace tessella
