#include "signorini/mesh/ForestOverlap.hpp"

#include <algorithm>

#include <p4est_bits.h>

#include "signorini/core/Error.hpp"
#include "signorini/mesh/Morton.hpp"
#include "signorini/core/MpiComm.hpp"

namespace signorini::mesh {
namespace {

bool less(int ta, uint64_t a, int tb, uint64_t b) { return ta < tb || (ta == tb && a < b); }

}  // namespace

ForestOverlap::ForestOverlap(const Forest& source, const Forest& target, const std::vector<double>& payload,
                             int payloadSize)
    : payloadSize_(payloadSize) {
  p4est_t* src = source.p4est();
  p4est_t* dst = target.p4est();
  MPI_Comm comm = dst->mpicomm;
  const int size = dst->mpisize;
  // Target partition markers: rank r owns positions in [marker r, marker r+1).
  std::vector<std::pair<int, uint64_t>> marker(size + 1);
  for (int r = 0; r <= size; ++r) {
    const auto& g = dst->global_first_position[r];
    marker[r] = {static_cast<int>(g.p.which_tree), r == size ? 0 : p4est_quadrant_linear_id(&g, P4EST_QMAXLEVEL)};
  }
  marker[size] = {static_cast<int>(src->connectivity->num_trees), 0};

  // Every local source cell goes to each target rank whose range it intersects: counted first, then
  // packed in place (one buffer; on one rank it is the received buffer itself).
  const int record = 4 + payloadSize;  // tree, x-id, y-id, level, payload (as doubles)
  const double root = static_cast<double>(P4EST_ROOT_LEN);
  auto forEachDestination = [&](auto&& visit) {
    int e = 0;
    for (p4est_topidx_t t = src->first_local_tree; t <= src->last_local_tree; ++t) {
      p4est_tree_t* tree = p4est_tree_array_index(src->trees, t);
      for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi, ++e) {
        const auto* q = p4est_quadrant_array_index(&tree->quadrants, qi);
        const auto [f, l] = morton::range(*q);
        // Target ranks r with marker[r] <= (t, l) and marker[r+1] > (t, f), skipping empty ranks.
        const auto pos = std::make_pair(static_cast<int>(t), f);
        int r = static_cast<int>(std::upper_bound(marker.begin(), marker.end(), pos,
                                                  [](const auto& a, const auto& b) {
                                                    return less(a.first, a.second, b.first, b.second);
                                                  }) -
                                 marker.begin()) - 1;
        for (r = std::max(r, 0); r < size && !less(static_cast<int>(t), l, marker[r].first, marker[r].second); ++r) {
          const bool empty = !less(marker[r].first, marker[r].second, marker[r + 1].first, marker[r + 1].second);
          if (empty || !less(static_cast<int>(t), f, marker[r + 1].first, marker[r + 1].second)) continue;
          visit(r, t, *q, e);
        }
      }
    }
  };
  std::vector<int> sendOff(size + 1, 0);
  forEachDestination([&](int r, p4est_topidx_t, const p4est_quadrant_t&, int) { sendOff[r + 1] += record; });
  for (int r = 0; r < size; ++r) sendOff[r + 1] += sendOff[r];
  std::vector<double> sendBuf(static_cast<size_t>(sendOff[size]));
  std::vector<int> fill(sendOff.begin(), sendOff.end() - 1);
  // On one rank the records are received as packed: their keys come from the quadrants directly.
  std::vector<Key> keys;
  if (size == 1) keys.reserve(static_cast<size_t>(sendOff[size] / record));
  forEachDestination([&](int r, p4est_topidx_t t, const p4est_quadrant_t& q, int e) {
    double* o = &sendBuf[static_cast<size_t>(fill[r])];
    fill[r] += record;
    if (size == 1) {
      const auto [f, l] = morton::range(q);
      keys.push_back({static_cast<int>(t), f, l});
    }
    o[0] = static_cast<double>(t);
    o[1] = q.x / root;
    o[2] = q.y / root;
    o[3] = q.level;
    std::copy_n(payload.begin() + static_cast<size_t>(e) * payloadSize, payloadSize, o + 4);
  });
  if (size == 1) {
    buffer_ = std::move(sendBuf);
  } else {
    buffer_ = core::exchange(comm, sendBuf, sendOff).values;
  }

  // Sort by position (the records stay where they are; the payload pointers point into them).
  const size_t n = buffer_.size() / record;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  if (size > 1) {
    keys.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const double* rec = &buffer_[i * record];
      p4est_quadrant_t q;
      P4EST_QUADRANT_INIT(&q);
      q.level = static_cast<int8_t>(rec[3]);
      q.x = static_cast<p4est_qcoord_t>(std::llround(rec[1] * root));
      q.y = static_cast<p4est_qcoord_t>(std::llround(rec[2] * root));
      const auto [f, l] = morton::range(q);
      keys[i] = {static_cast<int>(rec[0]), f, l};
    }
  }
  SIGNORINI_ASSERT(keys.size() == n, "one key per received cell");
  auto byPosition = [&](size_t a, size_t b) { return less(keys[a].tree, keys[a].first, keys[b].tree, keys[b].first); };
  // Usually sorted already: each rank sends its cells in curve order, and the ranks' parts follow the curve.
  if (!std::is_sorted(order.begin(), order.end(), byPosition)) std::sort(order.begin(), order.end(), byPosition);
  received_.reserve(n);
  receivedCells_.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    const double* rec = &buffer_[i * record];
    received_.push_back(keys[i]);
    const int level = static_cast<int>(rec[3]);
    receivedCells_.push_back({keys[i].tree, level, rec[1], rec[2], 1.0 / (1 << level), payloadSize ? rec + 4 : nullptr});
  }

  // For each local target cell, the received cells whose range intersects its range. The target
  // cells come in curve order, so each search starts where the previous one ended.
  targetRange_.reserve(static_cast<size_t>(dst->local_num_quadrants));
  targetCells_.reserve(static_cast<size_t>(dst->local_num_quadrants));
  auto searchFrom = received_.begin();
  for (p4est_topidx_t t = dst->first_local_tree; t <= dst->last_local_tree; ++t) {
    p4est_tree_t* tree = p4est_tree_array_index(dst->trees, t);
    for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi) {
      const auto* q = p4est_quadrant_array_index(&tree->quadrants, qi);
      const auto [f, l] = morton::range(*q);
      // First received cell with last >= f in this tree: cells are disjoint and sorted, so search by first.
      auto it = std::upper_bound(searchFrom, received_.end(), std::make_pair(static_cast<int>(t), f),
                                 [](const auto& v, const Key& k) { return less(v.first, v.second, k.tree, k.first); });
      if (it != received_.begin()) {
        auto prev = std::prev(it);
        if (prev->tree == static_cast<int>(t) && prev->last >= f) it = prev;
      }
      auto end = it;
      while (end != received_.end() && end->tree == static_cast<int>(t) && end->first <= l) ++end;
      SIGNORINI_ASSERT(end != it, "target cell without an overlapping source cell");
      searchFrom = it;
      targetRange_.push_back({static_cast<size_t>(it - received_.begin()), static_cast<size_t>(end - received_.begin())});
      targetCells_.push_back({static_cast<int>(t), q->level, q->x / root, q->y / root, 1.0 / (1 << q->level), nullptr});
    }
  }
}

OverlapRange ForestOverlap::overlapping(int e) const {
  const auto [b, en] = targetRange_[e];
  return {receivedCells_.data() + b, receivedCells_.data() + en};
}

}  // namespace signorini::mesh
