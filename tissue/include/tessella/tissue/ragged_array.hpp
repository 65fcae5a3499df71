// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// RaggedArray: many short lists (a face's edge loop, a vertex's star) in one
// contiguous pool.
//
// Lists built in order sit back to back, so a sweep over all faces streams
// through memory. A list that outgrows its capacity is moved to the end of
// the pool (its old place becomes garbage); when garbage passes half the pool
// everything is repacked. Spans returned by operator[] are invalidated by any
// mutation of the array. The pool grows without writing its new items (see
// uninitialized_vector.hpp): items are trivially copyable.

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/parallel_prefix_sum.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella {

template <typename T>
class RaggedArray {
 public:
  std::size_t size() const { return slots_.size(); }
  bool empty() const { return slots_.empty(); }

  std::span<const T> operator[](std::size_t i) const {
    const Slot& s = slots_[i];
    return {data_.data() + s.offset, s.size};
  }
  std::span<T> mutableList(std::size_t i) {
    const Slot& s = slots_[i];
    return {data_.data() + s.offset, s.size};
  }
  std::uint32_t listSize(std::size_t i) const { return slots_[i].size; }

  /// Appends a new list; returns its index.
  std::size_t pushList(std::span<const T> items) {
    Slot s{static_cast<std::uint32_t>(data_.size()), static_cast<std::uint32_t>(items.size()),
           static_cast<std::uint32_t>(items.size())};
    data_.insert(data_.end(), items.begin(), items.end());
    slots_.push_back(s);
    return slots_.size() - 1;
  }
  std::size_t pushList(std::initializer_list<T> items) {
    return pushList(std::span<const T>(items.begin(), items.size()));
  }

  /// Replaces the contents of list i.
  void assign(std::size_t i, std::span<const T> items) {
    if (items.size() > slots_[i].capacity) {
      std::vector<T> copy(items.begin(), items.end());  // items may alias the pool
      relocate(i, copy.size());
      std::copy(copy.begin(), copy.end(), data_.begin() + slots_[i].offset);
    } else {
      std::copy(items.begin(), items.end(), data_.begin() + slots_[i].offset);
    }
    slots_[i].size = static_cast<std::uint32_t>(items.size());
  }

  void insert(std::size_t i, std::size_t pos, const T& value) {
    const T v = value;  // value may alias the pool
    if (slots_[i].size == slots_[i].capacity) relocate(i, slots_[i].size + 1);
    Slot& s = slots_[i];
    assert(pos <= s.size);
    auto first = data_.begin() + s.offset;
    std::move_backward(first + pos, first + s.size, first + s.size + 1);
    first[pos] = v;
    ++s.size;
  }
  void pushBack(std::size_t i, const T& value) { insert(i, slots_[i].size, value); }

  void erase(std::size_t i, std::size_t pos) {
    Slot& s = slots_[i];
    assert(pos < s.size);
    auto first = data_.begin() + s.offset;
    std::move(first + pos + 1, first + s.size, first + pos);
    --s.size;
  }
  /// Removes the first occurrence of value; returns whether it was found.
  bool eraseValue(std::size_t i, const T& value) {
    auto list = (*this)[i];
    auto it = std::find(list.begin(), list.end(), value);
    if (it == list.end()) return false;
    erase(i, static_cast<std::size_t>(it - list.begin()));
    return true;
  }
  /// Replaces the first occurrence of old_value; returns whether it was found.
  bool replaceValue(std::size_t i, const T& old_value, const T& new_value) {
    auto list = mutableList(i);
    auto it = std::find(list.begin(), list.end(), old_value);
    if (it == list.end()) return false;
    *it = new_value;
    return true;
  }
  void clearList(std::size_t i) { slots_[i].size = 0; }

  // --- batch edits (Tissue::splitCells): room is made first (where each list
  // goes by parallel prefix sums, parallelPrefixSum), then lists are written
  // from several threads, each list by one thread.

  /// Appends one list per entry of `sizes`, their items unspecified until
  /// written; returns the index of the first.
  std::size_t appendLists(std::span<const std::uint32_t> sizes) {
    const std::size_t first = slots_.size();
    growInParallel(slots_, first + sizes.size());
    const std::uint32_t start = static_cast<std::uint32_t>(data_.size());
    const std::uint32_t added = parallelPrefixSum<std::uint32_t>(
        static_cast<std::ptrdiff_t>(sizes.size()), [&](std::ptrdiff_t k) { return sizes[k]; },
        [&](std::ptrdiff_t k, std::uint32_t at) { slots_[first + k] = Slot{start + at, sizes[k], sizes[k]}; });
    growInParallel(data_, std::size_t{start} + added);
    return first;
  }
  /// Makes list lists[k] hold sizes[k] items (the lists distinct): a list
  /// without the room moves to the end of the pool keeping its items (the
  /// moved lists back to back in the order given, so the pool is the same
  /// for any number of threads); items past the old size are unspecified
  /// until written. The copies run in parallel (OpenMP) for many lists.
  void resizeLists(std::span<const Index> lists, std::span<const std::uint32_t> sizes) {
    assert(lists.size() == sizes.size());
    if (garbage_ > 1024 && garbage_ * 2 > data_.size()) repack();  // first: a repack resets capacities
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(lists.size());
    UninitializedVector<std::uint32_t> room(lists.size()), at(lists.size());
#pragma omp parallel for schedule(static) if (m >= 4096)
    for (std::ptrdiff_t k = 0; k < m; ++k) {
      const Slot& s = slots_[lists[k]];
      room[k] = sizes[k] > s.capacity ? std::max<std::uint32_t>(sizes[k] + 2, s.size * 3 / 2) : 0;
    }
    const std::size_t start = data_.size();
    const std::size_t end = start + parallelPrefixSum<std::size_t>(
                                        m, [&](std::ptrdiff_t k) { return std::size_t{room[k]}; },
                                        [&](std::ptrdiff_t k, std::size_t before) {
                                          at[k] = static_cast<std::uint32_t>(start + before);
                                        });
    growInParallel(data_, end);
    std::size_t freed = 0;
    // Chunks dealt in turn: the lists that move (copies, and first touch of
    // the pool's new end) are not spread evenly over `lists` (in a batch
    // split the neighbours, given last, grow; the split faces mostly do not).
#pragma omp parallel for schedule(static, 1024) reduction(+ : freed) if (m >= 4096)
    for (std::ptrdiff_t k = 0; k < m; ++k) {
      Slot& s = slots_[lists[k]];
      if (room[k] > 0) {
        std::copy(data_.begin() + s.offset, data_.begin() + s.offset + s.size, data_.begin() + at[k]);
        freed += s.capacity;
        s.offset = at[k];
        s.capacity = room[k];
      }
      s.size = sizes[k];
    }
    garbage_ += freed;
  }
  /// Sets the size of list i to n <= its capacity (a list shortened after a
  /// batch write); safe from the thread that writes list i.
  void setListSize(std::size_t i, std::uint32_t n) {
    assert(n <= slots_[i].capacity);
    slots_[i].size = n;
  }
  /// replaceValue for lists that other threads edit at the same time, each
  /// thread replacing values no other thread looks for (relaxed atomic reads
  /// and writes of single items).
  bool replaceValueShared(std::size_t i, const T& old_value, const T& new_value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const Slot s = slots_[i];
    for (std::uint32_t k = 0; k < s.size; ++k) {
      std::atomic_ref<T> item(data_[s.offset + k]);
      if (item.load(std::memory_order_relaxed) == old_value) {
        item.store(new_value, std::memory_order_relaxed);
        return true;
      }
    }
    return false;
  }

  /// Renumbers lists: list i moves to old_to_new[i] (kInvalidIndex drops it),
  /// and the pool is repacked in the new order. `transform` maps each item.
  template <typename Transform>
  void compact(const std::vector<Index>& old_to_new, std::size_t new_count, Transform transform) {
    std::vector<Index> new_to_old(new_count, kInvalidIndex);
    for (std::size_t i = 0; i < old_to_new.size(); ++i)
      if (old_to_new[i] != kInvalidIndex) new_to_old[old_to_new[i]] = static_cast<Index>(i);
    RaggedArray packed;
    packed.slots_.reserve(new_count);
    std::size_t total = 0;
    for (Index o : new_to_old) total += slots_[o].size;
    packed.data_.reserve(total);
    for (Index o : new_to_old) {
      auto list = (*this)[o];
      Slot s{static_cast<std::uint32_t>(packed.data_.size()), static_cast<std::uint32_t>(list.size()),
             static_cast<std::uint32_t>(list.size())};
      for (const T& item : list) packed.data_.push_back(transform(item));
      packed.slots_.push_back(s);
    }
    *this = std::move(packed);
  }

  /// Repacks every list back to back, dropping garbage (order unchanged);
  /// the lists are copied in parallel (OpenMP) for many lists.
  void repack() {
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(slots_.size());
    UninitializedVector<std::uint32_t> at(slots_.size());
    const std::uint32_t total = parallelPrefixSum<std::uint32_t>(
        n, [&](std::ptrdiff_t i) { return slots_[i].size; },
        [&](std::ptrdiff_t i, std::uint32_t before) { at[i] = before; });
    UninitializedVector<T> data;
    data.reserve(std::max<std::size_t>(total, data_.size() - garbage_));
    data.resize(total);
#pragma omp parallel for schedule(static) if (n >= 4096)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      Slot& s = slots_[i];
      std::copy(data_.begin() + s.offset, data_.begin() + s.offset + s.size, data.begin() + at[i]);
      s.offset = at[i];
      s.capacity = s.size;
    }
    data_ = std::move(data);
    garbage_ = 0;
  }

  /// Bulk construction: list i is pool[at[i] .. at[i] + sizes[i]). The lists
  /// may lie in the pool in any order (e.g. the order a builder produced
  /// them in), so nothing is copied; they must not overlap, and pool items
  /// in no list count as garbage (reclaimed by the next repack).
  static RaggedArray fromPool(UninitializedVector<T> pool, std::span<const std::uint32_t> at,
                              std::span<const std::uint32_t> sizes) {
    assert(at.size() == sizes.size());
    RaggedArray r;
    r.slots_.resize(at.size());
    std::size_t used = 0;
    for (std::size_t i = 0; i < at.size(); ++i) {
      assert(at[i] + sizes[i] <= pool.size());
      r.slots_[i] = Slot{at[i], sizes[i], sizes[i]};
      used += sizes[i];
    }
    r.garbage_ = pool.size() - used;
    r.data_ = std::move(pool);
    return r;
  }

  void reserve(std::size_t lists, std::size_t items) {
    slots_.reserve(lists);
    data_.reserve(items);
  }
  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot) + data_.capacity() * sizeof(T); }

 private:
  struct Slot {  // no default values: slots grow unwritten (appendLists writes them)
    std::uint32_t offset;
    std::uint32_t size;
    std::uint32_t capacity;
  };

  // Moves list i to the end of the pool with room for at least min_capacity.
  void relocate(std::size_t i, std::size_t min_capacity) {
    if (garbage_ > 1024 && garbage_ * 2 > data_.size()) repack();
    Slot& s = slots_[i];
    const std::uint32_t capacity =
        static_cast<std::uint32_t>(std::max<std::size_t>(min_capacity + 2, s.size * 3 / 2));
    const std::uint32_t offset = static_cast<std::uint32_t>(data_.size());
    data_.resize(data_.size() + capacity);  // items past the list's size unspecified until written
    std::copy(data_.begin() + s.offset, data_.begin() + s.offset + s.size, data_.begin() + offset);
    garbage_ += s.capacity;
    s.offset = offset;
    s.capacity = capacity;
  }

  UninitializedVector<Slot> slots_;
  UninitializedVector<T> data_;
  std::size_t garbage_ = 0;
};

}  // namespace tessella
