#pragma once
/// \file Forest.hpp
/// One adaptive quadrilateral mesh as a p4est forest (Forest).
#include <functional>
#include <memory>
#include <vector>

#include <mpi.h>
#include <p4est.h>

#include "signorini/mesh/CoarseMesh.hpp"

namespace signorini::mesh {

/// Initialises libsc/p4est once per process (quiet logging). Safe to call repeatedly.
void initializeP4est(MPI_Comm comm);

/// One adaptive quadrilateral mesh: a p4est forest refining a CoarseMesh, distributed over the ranks of an MPI
/// communicator along p4est's space-filling curve, stored as a p4est (expanded) or as levels only (compact()).
/// Owns its p4est; shares the CoarseMesh (and its connectivity); stores the raw MPI_Comm without duplicating it.
class Forest {
 public:
  /// Uniform forest at \p level on \p coarse, partitioned over \p comm. \p comm is stored as given (not
  /// duplicated): it must stay valid while the forest lives. Collective.
  Forest(std::shared_ptr<const CoarseMesh> coarse, MPI_Comm comm, int level);
  Forest(const Forest& other);  ///< deep copy (same partition, same form, same communicator)
  Forest& operator=(const Forest&) = delete;
  ~Forest();

  /// The p4est of an expanded forest (asserts !isCompact()). Owned by the forest: do not destroy it; compact() and
  /// the destructor destroy it, expand() makes a new one; refinement, coarsening and partition() change it in place.
  p4est_t* p4est() const;
  /// The coarse mesh the forest refines (shared; lives as long as any forest or holder of coarsePtr()).
  const CoarseMesh& coarse() const { return *coarse_; }
  /// The shared pointer to the coarse mesh.
  std::shared_ptr<const CoarseMesh> coarsePtr() const { return coarse_; }
  /// The communicator given to the constructor (not owned).
  MPI_Comm comm() const { return comm_; }
  /// Cells on all ranks (either form).
  long long numGlobalCells() const;
  /// Cells on this rank (either form).
  int numLocalCells() const;
  /// Nodes of the bilinear space on these cells, on all ranks: the cells' vertices but the hanging
  /// ones (p4est lnodes of degree 1), as mesh::Q1Mesh numbers them. Collective; expanded form.
  long long numGlobalNodes() const;
  /// Position on the space-filling curve of this rank's first cell among the cells of all ranks
  /// (local cell i is at firstGlobalCell() + i): the same cell has the same position on any
  /// number of ranks. Either form.
  long long firstGlobalCell() const;

  /// Replaces the p4est by a compact form of the same cells and partition: the level of every
  /// local cell in curve order (1 byte per cell) plus the partition (p4est's global first
  /// quadrants and this rank's first position, the cumulative cells per tree); a step mesh is
  /// stored so between its uses (about 35 bytes per cell as a p4est). Collective. No-op if compact.
  void compact();
  /// Rebuilds the p4est from the compact form (p4est_inflate): the same cells and partition as
  /// before compact(). Collective. No-op if expanded.
  void expand();
  /// True between compact() and expand(): p4est() is then unavailable.
  bool isCompact() const { return p4est_ == nullptr; }

  /// Refines every local cell for which \p refine(tree, quadrant) is true (once, not recursively).
  void refineIf(const std::function<bool(int tree, const p4est_quadrant_t& q)>& refine);
  /// Refines the local cells whose flag (local cell order) is set, once.
  void refineMarked(const std::vector<char>& flags);
  /// Refines the flagged cells (local cell order) once and, with them, the cells the 2:1 balance
  /// over faces and corners then requires: the same forest as refineMarked() followed by
  /// balance(), for a forest that is balanced on entry, without p4est's general balance.
  void refineMarkedBalanced(const std::vector<char>& flags);
  /// Replaces each family of four sibling cells that are all flagged by their parent, never
  /// going below \p minLevel.
  void coarsenMarked(const std::vector<char>& flags, int minLevel);
  /// Coarsens the families all flagged in \p coarsen (not below \p minLevel), then refines the
  /// cells flagged in \p refine (both in local cell order of the forest as it is on entry).
  void refineAndCoarsen(const std::vector<char>& refine, const std::vector<char>& coarsen, int minLevel);
  /// True if both forests have the same cells, compared cell by cell (collective; the same answer
  /// on every rank; either forest may be compact). Equal cells partitioned differently over the
  /// ranks count as different (only a rebuild that was not needed, never a wrong reuse).
  bool sameCells(const Forest& other) const;
  /// The smallest level of all cells of all ranks, counted from the coarse mesh's cells (as
  /// Q1Mesh::cellLevel; either form). Collective.
  int minimumLevel() const;
  /// Bytes of memory this rank uses for the forest (in whichever form it is).
  size_t bytes() const;
  /// Enforces the 2:1 balance across faces and corners (P4EST_CONNECT_FULL; at most one hanging node per edge;
  /// paper Algorithm 5.2). Collective.
  void balance();
  /// Re-partitions the cells evenly over the ranks.
  void partition();

 private:
  struct Compact;
  /// Levels of the local cells in curve order (from either form) and this rank's first position.
  void localLevels(std::vector<unsigned char>& levels, p4est_quadrant_t& first) const;
  std::shared_ptr<const CoarseMesh> coarse_;
  MPI_Comm comm_;
  p4est_t* p4est_ = nullptr;          ///< expanded form
  std::unique_ptr<Compact> compact_;  ///< compact form
};

}  // namespace signorini::mesh
