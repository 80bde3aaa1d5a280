#pragma once
/// \file ForestOverlap.hpp
/// Which cells of one forest overlap which cells of another on the same coarse mesh, across MPI ranks (ForestOverlap).
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "signorini/mesh/Forest.hpp"

namespace signorini::mesh {

/// A source cell as seen on the target rank: position in the tree's reference square and payload.
struct OverlapCell {
  int tree;   ///< p4est tree
  int level;  ///< p4est level of the cell
  /// \var s0
  /// first reference coordinate of the cell's lower-left corner in its tree's [0,1]^2
  /// \var r0
  /// second reference coordinate of the cell's lower-left corner
  double s0, r0, size;  ///< reference square [s0, s0 + size] x [r0, r0 + size] of its tree
  const double* payload;  ///< payloadSize doubles owned by the ForestOverlap; null for target cells and payloadSize 0
};

/// A contiguous run of OverlapCells (a view: valid as long as its ForestOverlap lives).
struct OverlapRange {
  const OverlapCell* first;  ///< the first cell
  const OverlapCell* last;   ///< one past the last cell
  const OverlapCell* begin() const { return first; }  ///< for range-for
  const OverlapCell* end() const { return last; }     ///< for range-for
  size_t size() const { return static_cast<size_t>(last - first); }  ///< number of cells
};

/// Which cells of one forest overlap which cells of another forest on the same coarse mesh (two meshes T^{n-1},
/// T^n of a time step sequence), across MPI ranks: every cell of the source forest, with a payload of doubles, is
/// sent to the ranks whose target partition (p4est's space-filling-curve ranges) it intersects (DESIGN 1.7). Each
/// target cell then sees the one source cell containing it or the source cells inside it: their intersection is the
/// common refinement of the two meshes. Owns copies of the received cells; keeps no reference to the forests.
class ForestOverlap {
 public:
  /// Collective over the forests' communicator.
  /// \param source   the forest the cells and payloads come from (expanded).
  /// \param target   the forest whose local cells get their overlapping source cells (expanded).
  /// \param payload  payloadSize doubles per local source cell (local cell order); may be empty
  ///                 when payloadSize is 0.
  /// \param payloadSize doubles per cell (>= 0).
  ForestOverlap(const Forest& source, const Forest& target, const std::vector<double>& payload, int payloadSize);
  ForestOverlap(const ForestOverlap&) = delete;  ///< the payload pointers point into buffer_
  ForestOverlap& operator=(const ForestOverlap&) = delete;

  /// The source cells overlapping local target cell e, in curve order (the range and the payload
  /// pointers stay valid as long as this object lives).
  OverlapRange overlapping(int e) const;
  /// Local cells of the target forest.
  int numTargetCells() const { return static_cast<int>(targetRange_.size()); }
  /// Reference square of local target cell e in its tree and its tree and level.
  const OverlapCell& target(int e) const { return targetCells_[e]; }

 private:
  struct Key {
    int tree;
    uint64_t first, last;  // Morton ids of the first and last finest descendants
  };
  int payloadSize_;
  std::vector<Key> received_;          // source cells received, sorted by (tree, first)
  std::vector<OverlapCell> receivedCells_;
  std::vector<double> buffer_;         // the received records (tree, x, y, level, payload), in arrival order
  std::vector<std::pair<size_t, size_t>> targetRange_;  // [begin, end) in received_ per target cell
  std::vector<OverlapCell> targetCells_;
};

}  // namespace signorini::mesh
