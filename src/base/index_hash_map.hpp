// A compact open-addressing hash map from 64-bit keys to indices (linear probing, backward-shift
// deletion, no tombstones). Used for the P2 edge table and the element-face -> boundary-facet map,
// where std::unordered_map would cost a heap node per entry.
#pragma once

#include <cstdint>
#include <vector>

#include "base/index.hpp"

namespace hocav {

class IndexHashMap {
 public:
  static constexpr std::uint64_t kEmptyKey = ~std::uint64_t{0};

  explicit IndexHashMap(std::size_t expected_size = 0) { reserve(expected_size); }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return keys_.size(); }

  // Makes room for `count` entries without rehashing (load factor at most 1/2).
  void reserve(std::size_t count) {
    std::size_t wanted = 16;
    while (wanted < 2 * count) wanted *= 2;
    if (wanted > keys_.size()) rehash(wanted);
  }

  Index find(std::uint64_t key) const {
    if (keys_.empty()) return kNoIndex;
    for (std::size_t slot = home(key);; slot = next(slot)) {
      if (keys_[slot] == key) return values_[slot];
      if (keys_[slot] == kEmptyKey) return kNoIndex;
    }
  }

  // Inserts key -> value unless the key is present; returns the value stored for the key.
  Index insert(std::uint64_t key, Index value) {
    if (2 * (size_ + 1) > keys_.size()) rehash(keys_.empty() ? 16 : 2 * keys_.size());
    for (std::size_t slot = home(key);; slot = next(slot)) {
      if (keys_[slot] == key) return values_[slot];
      if (keys_[slot] == kEmptyKey) {
        keys_[slot] = key;
        values_[slot] = value;
        ++size_;
        return value;
      }
    }
  }

  // Sets key -> value, inserting or overwriting.
  void assign(std::uint64_t key, Index value) {
    if (insert(key, value) != value) values_[locate(key)] = value;
  }

  // Removes the key if present; returns whether it was.
  bool erase(std::uint64_t key) {
    if (keys_.empty()) return false;
    std::size_t hole = locate(key);
    if (hole == kNotFound) return false;
    // Backward shift: move later entries of the probe run into the hole when their home allows.
    for (std::size_t slot = next(hole);; slot = next(slot)) {
      if (keys_[slot] == kEmptyKey) break;
      std::size_t wanted = home(keys_[slot]);
      bool movable = (hole <= slot) ? (wanted <= hole || wanted > slot) : (wanted <= hole && wanted > slot);
      if (movable) {
        keys_[hole] = keys_[slot];
        values_[hole] = values_[slot];
        hole = slot;
      }
    }
    keys_[hole] = kEmptyKey;
    --size_;
    return true;
  }

  void clear() {
    keys_.assign(keys_.size(), kEmptyKey);
    size_ = 0;
  }

  std::size_t memory_bytes() const { return keys_.capacity() * sizeof(std::uint64_t) + values_.capacity() * sizeof(Index); }

 private:
  static constexpr std::size_t kNotFound = ~std::size_t{0};

  std::size_t home(std::uint64_t key) const {
    // Fibonacci hashing spreads the structured keys (vertex pairs, element slots) over the table.
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  std::size_t next(std::size_t slot) const { return (slot + 1) & (keys_.size() - 1); }

  std::size_t locate(std::uint64_t key) const {
    for (std::size_t slot = home(key);; slot = next(slot)) {
      if (keys_[slot] == key) return slot;
      if (keys_[slot] == kEmptyKey) return kNotFound;
    }
  }

  void rehash(std::size_t new_capacity) {
    std::vector<std::uint64_t> old_keys(new_capacity, kEmptyKey);
    std::vector<Index> old_values(new_capacity, kNoIndex);
    old_keys.swap(keys_);
    old_values.swap(values_);
    shift_ = 64;
    for (std::size_t c = new_capacity; c > 1; c /= 2) --shift_;
    size_ = 0;
    for (std::size_t i = 0; i < old_keys.size(); ++i)
      if (old_keys[i] != kEmptyKey) insert(old_keys[i], old_values[i]);
  }

  std::vector<std::uint64_t> keys_;
  std::vector<Index> values_;
  std::size_t size_ = 0;
  int shift_ = 64;
};

}  // namespace hocav
