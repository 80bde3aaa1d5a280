#pragma once
/// \file Morton.hpp
/// Morton (space-filling-curve) ranges of p4est quadrants at the finest quadrant level, for
/// comparing cells of two forests of the same coarse mesh without p4est's bit-by-bit loops.
#include <cstdint>
#include <utility>

#include <p4est_bits.h>

namespace signorini::mesh::morton {

/// Spreads the low 32 bits of v to the even bit positions of the result.
inline uint64_t spreadBits(uint64_t v) {
  v &= 0xffffffffULL;
  v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
  v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
  v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | (v << 2)) & 0x3333333333333333ULL;
  v = (v | (v << 1)) & 0x5555555555555555ULL;
  return v;
}

/// The inverse of spreadBits: the even bits of v packed into the low 32 bits.
inline uint64_t compactBits(uint64_t v) {
  v &= 0x5555555555555555ULL;
  v = (v | (v >> 1)) & 0x3333333333333333ULL;
  v = (v | (v >> 2)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | (v >> 4)) & 0x00ff00ff00ff00ffULL;
  v = (v | (v >> 8)) & 0x0000ffff0000ffffULL;
  v = (v | (v >> 16)) & 0x00000000ffffffffULL;
  return v;
}

/// Morton id of the first finest (level P4EST_QMAXLEVEL) descendant of q within its tree: the
/// number p4est_quadrant_linear_id gives that descendant (x bits even, y bits odd).
inline uint64_t firstId(const p4est_quadrant_t& q) {
  constexpr int shift = P4EST_MAXLEVEL - P4EST_QMAXLEVEL;
  return spreadBits(static_cast<uint64_t>(q.x) >> shift) | (spreadBits(static_cast<uint64_t>(q.y) >> shift) << 1);
}

/// p4est coordinates (x, y) of the finest quadrant with Morton id \p id (the inverse of firstId).
inline std::pair<p4est_qcoord_t, p4est_qcoord_t> coordinates(uint64_t id) {
  constexpr int shift = P4EST_MAXLEVEL - P4EST_QMAXLEVEL;
  return {static_cast<p4est_qcoord_t>(compactBits(id) << shift), static_cast<p4est_qcoord_t>(compactBits(id >> 1) << shift)};
}

/// Number of finest descendants of a quadrant of \p level.
inline uint64_t span(int level) { return uint64_t(1) << (2 * (P4EST_QMAXLEVEL - level)); }

/// [first, last] Morton ids of q's finest descendants.
inline std::pair<uint64_t, uint64_t> range(const p4est_quadrant_t& q) {
  const uint64_t first = firstId(q);
  return {first, first + span(q.level) - 1};
}

}  // namespace signorini::mesh::morton
