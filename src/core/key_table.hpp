// SPDX-License-Identifier: GPL-3.0-or-later
// A map from 64-bit keys (an edge's, directed or not: edge_keys.hpp) to small values,
// in two flat arrays with linear probing. The manifold extraction and the mending of a bordered
// surface ask about every edge of a surface, several times over; std::unordered_map made a node
// per edge (a noisy scan of 20k points: 4% of the whole run in the mending's inserts and finds).
// It cannot be iterated over, so no result depends on its order.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sculpt {

template <class Value>
class Key_table {
 public:
  Key_table() { rehash(16); }
  Key_table(std::initializer_list<std::pair<std::uint64_t, Value>> entries) : Key_table() {
    for (const auto& [key, value] : entries) (*this)[key] = value;
  }

  // Room for `count` keys without growing.
  void reserve(std::size_t count) {
    std::size_t slots = keys_.size();
    while (slots < 2 * count) slots *= 2;
    if (slots != keys_.size()) rehash(slots);
  }

  // The key's value, made Value{} if the key is new.
  Value& operator[](std::uint64_t key) {
    std::size_t slot = slot_of(key);
    if (keys_[slot] == key) return values_[slot];
    if (2 * (size_ + 1) > keys_.size()) {
      rehash(2 * keys_.size());
      slot = slot_of(key);
    }
    keys_[slot] = key;
    values_[slot] = Value{};
    ++size_;
    return values_[slot];
  }

  // The key's value, or null.
  const Value* find(std::uint64_t key) const {
    const std::size_t slot = slot_of(key);
    return keys_[slot] == key ? &values_[slot] : nullptr;
  }
  std::size_t count(std::uint64_t key) const { return find(key) ? 1 : 0; }
  const Value& at(std::uint64_t key) const {
    const Value* value = find(key);
    if (!value) throw std::out_of_range("Key_table::at: no such key");
    return *value;
  }
  std::size_t size() const { return size_; }

 private:
  // No key of an edge is this: both its ends would be 2^32 - 1.
  static constexpr std::uint64_t empty = ~std::uint64_t{0};

  // The key's slot, or the empty slot where it would go. The table is never over half full.
  std::size_t slot_of(std::uint64_t key) const {
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
    while (keys_[slot] != key && keys_[slot] != empty) slot = (slot + 1) & (keys_.size() - 1);
    return slot;
  }

  void rehash(std::size_t slots) {  // slots: a power of two
    std::vector<std::uint64_t> keys(slots, empty);
    std::vector<Value> values(slots);
    keys.swap(keys_);
    values.swap(values_);
    shift_ = 64;
    for (std::size_t s = slots; s > 1; s /= 2) --shift_;
    for (std::size_t s = 0; s < keys.size(); ++s) {
      if (keys[s] == empty) continue;
      const std::size_t slot = slot_of(keys[s]);
      keys_[slot] = keys[s];
      values_[slot] = std::move(values[s]);
    }
  }

  std::vector<std::uint64_t> keys_;
  std::vector<Value> values_;
  std::size_t size_ = 0;
  int shift_ = 60;
};

}  // namespace sculpt
