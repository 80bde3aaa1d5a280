#pragma once
/// Brute-force geometric checks of forests, independent of p4est's algorithms and of the project's
/// overlap code: the leaves of a forest are gathered to every rank as integer squares of their
/// tree's reference square [0, P4EST_ROOT_LEN]^2, and the properties of Algorithms 5.2 and 5.3 are
/// computed from these squares alone. Every rank computes the same verdict.
///
/// Trees are treated separately: squares of different trees never overlap, and a hanging node
/// across a tree boundary (a corner of one tree's cell inside an edge of another tree's cell) is
/// not seen. The tests use forests of one tree.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <mpi.h>
#include <p4est.h>

#include "signorini/mesh/Forest.hpp"

namespace signorini::test {

/// A leaf as a square [x0, x0 + size] x [y0, y0 + size] of its tree's reference square.
struct LeafSquare {
  int tree;
  int level;  ///< p4est level: size = P4EST_ROOT_LEN >> level
  std::int64_t x0, y0, size;
};

/// All leaves of the forest (expanded, not compact), on every rank. Collective.
inline std::vector<LeafSquare> gatherLeaves(const mesh::Forest& forest) {
  const p4est_t* p = forest.p4est();
  std::vector<int> local;  // (tree, x, y, level) per local leaf
  for (p4est_topidx_t t = p->first_local_tree; t >= 0 && t <= p->last_local_tree; ++t) {
    sc_array_t* quadrants = &p4est_tree_array_index(p->trees, t)->quadrants;
    for (size_t i = 0; i < quadrants->elem_count; ++i) {
      const auto* q = p4est_quadrant_array_index(quadrants, i);
      local.insert(local.end(), {static_cast<int>(t), static_cast<int>(q->x), static_cast<int>(q->y), static_cast<int>(q->level)});
    }
  }
  int numRanks = 0;
  MPI_Comm_size(forest.comm(), &numRanks);
  const int localCount = static_cast<int>(local.size());
  std::vector<int> counts(numRanks), offsets(numRanks, 0);
  MPI_Allgather(&localCount, 1, MPI_INT, counts.data(), 1, MPI_INT, forest.comm());
  for (int r = 1; r < numRanks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<int> all(offsets.back() + counts.back());
  MPI_Allgatherv(local.data(), localCount, MPI_INT, all.data(), counts.data(), offsets.data(), MPI_INT, forest.comm());
  std::vector<LeafSquare> leaves;
  for (size_t i = 0; i < all.size(); i += 4)
    leaves.push_back({all[i], all[i + 3], all[i + 1], all[i + 2], static_cast<std::int64_t>(P4EST_QUADRANT_LEN(all[i + 3]))});
  return leaves;
}

/// Area of the intersection of two squares of the same tree (0 for different trees).
inline std::int64_t overlapArea(const LeafSquare& a, const LeafSquare& b) {
  if (a.tree != b.tree) return 0;
  const std::int64_t w = std::min(a.x0 + a.size, b.x0 + b.size) - std::max(a.x0, b.x0);
  const std::int64_t h = std::min(a.y0 + a.size, b.y0 + b.size) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0;
}

/// Over all edges of all cells: the largest number of distinct cell corners (of any cell of the
/// same tree) lying strictly inside the edge. A 2:1 balanced mesh has at most one (the midpoint).
inline int maxHangingNodesPerEdge(const mesh::Forest& forest) {
  const auto leaves = gatherLeaves(forest);
  // The corners twice: sorted by (tree, x, y) to search along vertical edges, by (tree, y, x)
  // along horizontal ones.
  using Point = std::array<std::int64_t, 3>;
  std::vector<Point> byX, byY;
  for (const auto& c : leaves)
    for (std::int64_t dx : {std::int64_t{0}, c.size})
      for (std::int64_t dy : {std::int64_t{0}, c.size}) {
        byX.push_back({c.tree, c.x0 + dx, c.y0 + dy});
        byY.push_back({c.tree, c.y0 + dy, c.x0 + dx});
      }
  for (auto* points : {&byX, &byY}) {
    std::sort(points->begin(), points->end());
    points->erase(std::unique(points->begin(), points->end()), points->end());
  }
  // Corners (tree, fixed, t) with from < t < to.
  auto strictlyBetween = [](const std::vector<Point>& points, int tree, std::int64_t fixed, std::int64_t from,
                            std::int64_t to) {
    const auto first = std::upper_bound(points.begin(), points.end(), Point{tree, fixed, from});
    const auto last = std::lower_bound(points.begin(), points.end(), Point{tree, fixed, to});
    return static_cast<int>(std::max<std::ptrdiff_t>(0, last - first));
  };
  int most = 0;
  for (const auto& c : leaves) {
    most = std::max(most, strictlyBetween(byX, c.tree, c.x0, c.y0, c.y0 + c.size));           // left
    most = std::max(most, strictlyBetween(byX, c.tree, c.x0 + c.size, c.y0, c.y0 + c.size));  // right
    most = std::max(most, strictlyBetween(byY, c.tree, c.y0, c.x0, c.x0 + c.size));           // bottom
    most = std::max(most, strictlyBetween(byY, c.tree, c.y0 + c.size, c.x0, c.x0 + c.size));  // top
  }
  return most;
}

/// Largest level(K') - level(K) over the cells K of \p target and K' of \p neighbour that overlap
/// with positive area (both forests refine the same coarse mesh). Every pair is tried.
inline int maxCoarserThanOverlapping(const mesh::Forest& target, const mesh::Forest& neighbour) {
  const auto targetLeaves = gatherLeaves(target), neighbourLeaves = gatherLeaves(neighbour);
  int most = std::numeric_limits<int>::min();
  for (const auto& k : targetLeaves)
    for (const auto& n : neighbourLeaves)
      if (overlapArea(k, n) > 0) most = std::max(most, n.level - k.level);
  return most;
}

/// True if every cell of \p original is covered entirely by cells of \p refined (their overlaps
/// add up to its area) and only by cells of its own level or finer. Every pair is tried.
inline bool containsRefinement(const mesh::Forest& refined, const mesh::Forest& original) {
  const auto refinedLeaves = gatherLeaves(refined), originalLeaves = gatherLeaves(original);
  for (const auto& k : originalLeaves) {
    std::int64_t covered = 0;
    for (const auto& r : refinedLeaves) {
      const std::int64_t area = overlapArea(k, r);
      if (area > 0 && r.level < k.level) return false;
      covered += area;
    }
    if (covered != k.size * k.size) return false;
  }
  return true;
}

}  // namespace signorini::test
