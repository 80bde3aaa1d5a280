#pragma once
/// \file CoordinateTable.hpp
/// A hash table from p4est coordinates to local indices (CoordinateTable).
#include <cstdint>
#include <vector>

#include <p4est.h>

#include "signorini/core/Types.hpp"

namespace signorini::mesh {

/// A hash table from integer p4est coordinates (x, y) within one tree to a local index: the corner points of
/// Q1Mesh's direct numbering and the cells of the estimator's face walk. Open addressing with a capacity fixed by the
/// constructor (no growth: insert at most maxEntries keys); no removal.
class CoordinateTable {
 public:
  /// Room for \p maxEntries entries (open addressing, at most half full).
  explicit CoordinateTable(size_t maxEntries) {
    while (capacity_ < 2 * maxEntries) capacity_ <<= 1;
    shift_ = 64 - __builtin_ctzll(capacity_);
    keys_.assign(capacity_, kEmpty);
    values_.resize(capacity_);
  }
  /// The index stored at (x, y), or -1.
  LO find(p4est_qcoord_t x, p4est_qcoord_t y) const {
    const std::uint64_t key = pack(x, y);
    for (size_t slot = first(key);; slot = (slot + 1) & (capacity_ - 1)) {
      if (keys_[slot] == key) return values_[slot];
      if (keys_[slot] == kEmpty) return -1;
    }
  }
  /// The index stored at (x, y), after storing \p value there if there was none.
  LO insert(p4est_qcoord_t x, p4est_qcoord_t y, LO value) {
    const std::uint64_t key = pack(x, y);
    for (size_t slot = first(key);; slot = (slot + 1) & (capacity_ - 1)) {
      if (keys_[slot] == key) return values_[slot];
      if (keys_[slot] == kEmpty) {
        keys_[slot] = key;
        return values_[slot] = value;
      }
    }
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static std::uint64_t pack(p4est_qcoord_t x, p4est_qcoord_t y) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) | static_cast<std::uint32_t>(y);
  }
  size_t first(std::uint64_t key) const { return (key * 0x9E3779B97F4A7C15ull) >> shift_; }  // Fibonacci hashing

  size_t capacity_ = 16;
  int shift_ = 60;
  std::vector<std::uint64_t> keys_;
  std::vector<LO> values_;
};

}  // namespace signorini::mesh
