// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/properties.hpp"

#include <algorithm>
#include <exception>
#include <utility>
#include <vector>

namespace tessella {

namespace {
constexpr std::size_t kParallelResizeMin = std::size_t{1} << 14;  // fewer items added: one thread
}  // namespace

const char* divisionPolicyName(DivisionPolicy policy) {
  switch (policy) {
    case DivisionPolicy::Copy: return "copy";
    case DivisionPolicy::SplitByMeasure: return "split_by_measure";
    case DivisionPolicy::Reset: return "reset";
    case DivisionPolicy::Custom: return "custom";
  }
  return "?";
}

PropertyStore::PropertyStore(const PropertyStore& other) : locked_(other.locked_), size_(other.size_) {
  columns_.reserve(other.columns_.size());
  for (const auto& c : other.columns_) columns_.push_back(c->clone());
}

PropertyStore& PropertyStore::operator=(const PropertyStore& other) {
  if (this != &other) {
    PropertyStore copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void PropertyStore::remove(const std::string& name) {
  if (std::find(locked_.begin(), locked_.end(), name) != locked_.end())
    throw InputError("property '" + name + "' is built in and cannot be removed");
  auto it = std::find_if(columns_.begin(), columns_.end(),
                         [&](const auto& c) { return c->name() == name; });
  if (it == columns_.end()) throw InputError("no property named '" + name + "' to remove");
  columns_.erase(it);
}

PropertyColumnBase* PropertyStore::find(const std::string& name) {
  for (auto& c : columns_)
    if (c->name() == name) return c.get();
  return nullptr;
}

const PropertyColumnBase* PropertyStore::find(const std::string& name) const {
  for (const auto& c : columns_)
    if (c->name() == name) return c.get();
  return nullptr;
}

std::vector<std::string> PropertyStore::names() const {
  std::vector<std::string> out;
  out.reserve(columns_.size());
  for (const auto& c : columns_) out.push_back(c->name());
  return out;
}

void PropertyStore::resize(std::size_t n) {
  size_ = n;
  for (auto& c : columns_) c->resize(n);
}

void PropertyStore::resizeTogether(std::span<PropertyStore* const> stores, std::span<const std::size_t> sizes) {
  std::vector<std::pair<PropertyColumnBase*, std::size_t>> columns;
  std::size_t added = 0;
  for (std::size_t k = 0; k < stores.size(); ++k) {
    stores[k]->size_ = sizes[k];
    for (auto& c : stores[k]->columns_) {
      columns.emplace_back(c.get(), sizes[k]);
      added += sizes[k] > c->size() ? sizes[k] - c->size() : 0;
    }
  }
  // A column grows in one thread (a std::vector: copied and filled by one
  // thread); many columns grow side by side, each thread first touching the
  // new memory of its columns.
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(columns.size());
  std::vector<std::exception_ptr> failed(columns.size());  // (std::bad_alloc) rethrown outside the threads
#pragma omp parallel for schedule(dynamic, 1) if (m > 1 && added >= kParallelResizeMin)
  for (std::ptrdiff_t i = 0; i < m; ++i) {
    try {
      columns[static_cast<std::size_t>(i)].first->resize(columns[static_cast<std::size_t>(i)].second);
    } catch (...) {
      failed[static_cast<std::size_t>(i)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

void PropertyStore::divide(Index mother, Index part, double fraction) {
  for (auto& c : columns_) c->divide(mother, part, fraction);
}

void PropertyStore::reset(Index i) {
  for (auto& c : columns_) c->reset(i);
}

void PropertyStore::compact(const std::vector<Index>& old_to_new, std::size_t new_count) {
  size_ = new_count;
  for (auto& c : columns_) c->compact(old_to_new, new_count);
}

std::size_t PropertyStore::bytes() const {
  std::size_t b = columns_.capacity() * sizeof(void*);
  for (const auto& c : columns_) b += c->bytes();
  return b;
}

}  // namespace tessella
