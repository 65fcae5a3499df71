// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Named, typed property columns per degree, each with a division policy.
//
// A column holds one value per element slot (tombstones included) and grows
// with the store. When an element divides, the Tissue calls divide() on every
// column of its degree, so no caller can forget a policy:
//   Copy            both parts keep the mother's value (cell type, identity);
//   SplitByMeasure  parts get value * their fraction of the mother's length,
//                   area or volume (amounts of a substance); integers are
//                   rounded so the two parts still add up to the mother;
//   Reset           both parts get the column's default;
//   Custom          a user function (mother, part1, part2, fraction1).
// References to a column stay valid until the column is removed; its values
// are renumbered by Tissue::compact() like the elements.

#include <cmath>
#include <concepts>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <typeindex>
#include <utility>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/handles.hpp"

namespace tessella {

enum class DivisionPolicy { Copy, SplitByMeasure, Reset, Custom };

const char* divisionPolicyName(DivisionPolicy policy);

/// Types a SplitByMeasure column can hold: they scale by a double.
template <typename T>
concept Scalable = std::is_arithmetic_v<T> || requires(T a, double f) {
  { a * f } -> std::convertible_to<T>;
  { a - a } -> std::convertible_to<T>;
};

class PropertyColumnBase {
 public:
  PropertyColumnBase(std::string name, DivisionPolicy policy)
      : name_(std::move(name)), policy_(policy) {}
  virtual ~PropertyColumnBase() = default;
  PropertyColumnBase(const PropertyColumnBase&) = default;
  PropertyColumnBase& operator=(const PropertyColumnBase&) = delete;

  const std::string& name() const { return name_; }
  DivisionPolicy policy() const { return policy_; }
  virtual std::type_index type() const = 0;
  virtual std::size_t size() const = 0;
  virtual std::size_t bytes() const = 0;

  /// Grows (new slots get the default) or shrinks the column.
  virtual void resize(std::size_t n) = 0;
  /// Element `mother` was split into itself and `part`; `fraction` is the
  /// share of the mother's measure that stayed with `mother`.
  virtual void divide(Index mother, Index part, double fraction) = 0;
  /// Gives slot i the default value (a new element that is nobody's part).
  virtual void reset(Index i) = 0;
  /// Moves value i to old_to_new[i], dropping kInvalidIndex entries.
  virtual void compact(const std::vector<Index>& old_to_new, std::size_t new_count) = 0;
  virtual std::unique_ptr<PropertyColumnBase> clone() const = 0;

 private:
  std::string name_;
  DivisionPolicy policy_;
};

template <typename T>
class PropertyColumn final : public PropertyColumnBase {
  static_assert(!std::is_same_v<T, bool>, "use std::uint8_t for flags (std::vector<bool> has no references)");

 public:
  using CustomDivision = std::function<void(const T& mother, T& stays, T& part, double fraction)>;

  PropertyColumn(std::string name, T default_value, DivisionPolicy policy, CustomDivision custom = {})
      : PropertyColumnBase(std::move(name), policy),
        default_(std::move(default_value)),
        custom_(std::move(custom)) {}

  T& operator[](Index i) { return values_[i]; }
  const T& operator[](Index i) const { return values_[i]; }
  template <typename Tag>
  T& operator[](Handle<Tag> h) { return values_[h.index()]; }
  template <typename Tag>
  const T& operator[](Handle<Tag> h) const { return values_[h.index()]; }

  const T& defaultValue() const { return default_; }
  std::vector<T>& values() { return values_; }
  const std::vector<T>& values() const { return values_; }

  std::type_index type() const override { return typeid(T); }
  std::size_t size() const override { return values_.size(); }
  std::size_t bytes() const override { return values_.capacity() * sizeof(T); }
  void resize(std::size_t n) override { values_.resize(n, default_); }
  void reset(Index i) override { values_[i] = default_; }

  void divide(Index mother, Index part, double fraction) override {
    const T m = values_[mother];
    switch (policy()) {
      case DivisionPolicy::Copy: values_[part] = m; break;
      case DivisionPolicy::Reset: values_[mother] = values_[part] = default_; break;
      case DivisionPolicy::Custom: custom_(m, values_[mother], values_[part], fraction); break;
      case DivisionPolicy::SplitByMeasure:
        if constexpr (std::is_integral_v<T>) {
          values_[mother] = static_cast<T>(std::llround(static_cast<double>(m) * fraction));
          values_[part] = static_cast<T>(m - values_[mother]);
        } else if constexpr (Scalable<T>) {
          values_[mother] = static_cast<T>(m * fraction);
          values_[part] = static_cast<T>(m - values_[mother]);  // the parts add up exactly
        }
        break;
    }
  }

  void compact(const std::vector<Index>& old_to_new, std::size_t new_count) override {
    std::vector<T> out(new_count, default_);
    for (std::size_t i = 0; i < old_to_new.size() && i < values_.size(); ++i)
      if (old_to_new[i] != kInvalidIndex) out[old_to_new[i]] = std::move(values_[i]);
    values_ = std::move(out);
  }

  std::unique_ptr<PropertyColumnBase> clone() const override {
    return std::make_unique<PropertyColumn>(*this);
  }

 private:
  std::vector<T> values_;
  T default_;
  CustomDivision custom_;
};

/// The columns of one degree.
class PropertyStore {
 public:
  PropertyStore() = default;
  PropertyStore(const PropertyStore& other);
  PropertyStore& operator=(const PropertyStore& other);
  PropertyStore(PropertyStore&&) noexcept = default;
  PropertyStore& operator=(PropertyStore&&) noexcept = default;

  /// Registers a column; throws InputError if the name is taken or the policy
  /// does not suit the type (SplitByMeasure needs a scalable type, Custom a function).
  template <typename T>
  PropertyColumn<T>& add(const std::string& name, T default_value,
                         DivisionPolicy policy = DivisionPolicy::Copy,
                         typename PropertyColumn<T>::CustomDivision custom = {}) {
    if (name.empty()) throw InputError("property name must not be empty");
    if (find(name)) throw InputError("property '" + name + "' is already registered");
    if (policy == DivisionPolicy::SplitByMeasure && !Scalable<T>)
      throw InputError("property '" + name + "': SplitByMeasure needs a type that scales by a double");
    if (policy == DivisionPolicy::Custom && !custom)
      throw InputError("property '" + name + "': Custom policy needs a division function");
    auto column = std::make_unique<PropertyColumn<T>>(name, std::move(default_value), policy,
                                                      std::move(custom));
    column->resize(size_);
    auto& ref = *column;
    columns_.push_back(std::move(column));
    return ref;
  }

  /// The column `name` of type T; throws InputError if missing or of another type.
  template <typename T>
  PropertyColumn<T>& get(const std::string& name) {
    return const_cast<PropertyColumn<T>&>(std::as_const(*this).template get<T>(name));
  }
  template <typename T>
  const PropertyColumn<T>& get(const std::string& name) const {
    const PropertyColumnBase* c = find(name);
    if (!c) throw InputError("no property named '" + name + "'");
    if (c->type() != typeid(T)) throw InputError("property '" + name + "' has another type");
    return static_cast<const PropertyColumn<T>&>(*c);
  }

  bool has(const std::string& name) const { return find(name) != nullptr; }
  /// Removes a column; throws InputError for a missing or locked (built-in) one.
  void remove(const std::string& name);
  /// Marks a column as built-in: it can no longer be removed.
  void lock(const std::string& name) { locked_.push_back(name); }
  PropertyColumnBase* find(const std::string& name);
  const PropertyColumnBase* find(const std::string& name) const;
  std::vector<std::string> names() const;
  std::size_t numColumns() const { return columns_.size(); }
  PropertyColumnBase& column(std::size_t i) { return *columns_[i]; }
  const PropertyColumnBase& column(std::size_t i) const { return *columns_[i]; }

  // Kept in step with the element store by the Tissue.
  std::size_t size() const { return size_; }
  void resize(std::size_t n);
  /// stores[k]->resize(sizes[k]) for every k, the columns of all the stores
  /// resized in parallel (OpenMP), each by one thread, when many items are added.
  static void resizeTogether(std::span<PropertyStore* const> stores, std::span<const std::size_t> sizes);
  void divide(Index mother, Index part, double fraction);
  void reset(Index i);
  void compact(const std::vector<Index>& old_to_new, std::size_t new_count);
  std::size_t bytes() const;

 private:
  std::vector<std::unique_ptr<PropertyColumnBase>> columns_;
  std::vector<std::string> locked_;
  std::size_t size_ = 0;
};

}  // namespace tessella
