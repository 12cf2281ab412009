// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_FIRST_VALUE_MAP_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_FIRST_VALUE_MAP_H

// A map from 64-bit keys to the first 32-bit value inserted with each key: open addressing
// with linear probing, at most half full, its memory kept by clear(), so that a loop that fills
// it again at every pass (the reductions) allocates nothing per key.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

class First_value_map
{
public:
  static constexpr std::uint64_t no_key = std::uint64_t(-1); // the one key that cannot be stored

  // empties the map, sized for about `expected` keys (it grows when needed)
  void clear(std::size_t expected)
  {
    bits_ = 4;
    while((std::size_t(1) << bits_) < 2 * expected) ++bits_;
    keys_.assign(std::size_t(1) << bits_, no_key);
    values_.resize(keys_.size());
    count_ = 0;
  }

  // the value stored with `key`, after storing `value` with it if there was none
  std::uint32_t insert(std::uint64_t key, std::uint32_t value)
  {
    std::size_t i = slot(key);
    if(keys_[i] == key) return values_[i];
    if(2 * (count_ + 1) > keys_.size()) { // grow: rehash into a table twice as large
      std::vector<std::uint64_t> keys = std::move(keys_);
      std::vector<std::uint32_t> values = std::move(values_);
      ++bits_;
      keys_.assign(std::size_t(1) << bits_, no_key);
      values_.resize(keys_.size());
      for(std::size_t j = 0; j < keys.size(); ++j)
        if(keys[j] != no_key) {
          const std::size_t k = slot(keys[j]);
          keys_[k] = keys[j];
          values_[k] = values[j];
        }
      i = slot(key);
    }
    keys_[i] = key;
    values_[i] = value;
    ++count_;
    return value;
  }

  static constexpr std::uint32_t no_value = std::uint32_t(-1);

  // the value stored with `key`, or `no_value`
  std::uint32_t find(std::uint64_t key) const
  {
    const std::size_t i = slot(key);
    return keys_[i] == key ? values_[i] : no_value;
  }

  std::size_t size() const { return count_; }

private:
  // the slot of `key`, or the empty slot where it goes (Fibonacci hashing)
  std::size_t slot(std::uint64_t key) const
  {
    const std::size_t mask = keys_.size() - 1;
    std::size_t i = std::size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
    while(keys_[i] != key && keys_[i] != no_key) i = (i + 1) & mask;
    return i;
  }

  std::vector<std::uint64_t> keys_ = std::vector<std::uint64_t>(16, no_key);
  std::vector<std::uint32_t> values_ = std::vector<std::uint32_t>(16);
  std::size_t count_ = 0;
  int bits_ = 4;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_FIRST_VALUE_MAP_H
