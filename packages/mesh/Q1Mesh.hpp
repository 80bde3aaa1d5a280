#pragma once
/// \file Q1Mesh.hpp
/// Bilinear (Q1) node numbering of one Forest (Q1Mesh) and its boundary edges (BoundaryEdge).
#include <array>
#include <vector>

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>

#include "signorini/mesh/BoundarySegments.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::mesh {

/// A fine boundary edge of a local cell. Its two end points are independent (never hanging) nodes.
struct BoundaryEdge {
  LO cell;                 ///< local cell index
  int face;                ///< p4est face 0:-x 1:+x 2:-y 3:+y
  unsigned segments;       ///< bit mask of BoundarySegments containing the edge
  LO node[2];              ///< overlap-map local ids of the end points (p4est_face_corners order)
  double x[2][2];          ///< end point coordinates [point][dim]
  int level;               ///< refinement level of the cell
  /// Place of the edge in its tree's dyadic hierarchy: tree, p4est level of the cell and index
  /// of the edge along the tree face at that level (the edge's parent has index faceIndex / 2).
  int tree;
  int quadrantLevel;    ///< p4est level of the cell (level plus the coarse mesh's level offset)
  long long faceIndex;  ///< index of the edge along its tree face at quadrantLevel
  /// |x[1] - x[0]| [length, the deck's unit].
  double length() const;
  /// The point (1 - w) x[0] + w x[1] of the edge.
  std::array<double, 2> at(double w) const {
    return {(1 - w) * x[0][0] + w * x[1][0], (1 - w) * x[0][1] + w * x[1][1]};
  }
};

/// Bilinear (Q1) node numbering of one 2:1 balanced Forest, hanging nodes included (p4est lnodes, or on one tree a
/// direct numbering of the corner points): the Tpetra maps of owned and owned-plus-shared nodes, per-cell geometry
/// and corner constraints in Kokkos views, and the boundary edges with their segment tags. Copies what it needs from
/// the forest (which may be compacted afterwards) and keeps \p comm.
class Q1Mesh {
 public:
  using CellCoords = Kokkos::View<double* [4][2], DeviceType>;  ///< per cell, corner and dimension: coordinates
  using CellDofs = Kokkos::View<LO* [4][2], DeviceType>;        ///< per cell, corner and slot: overlap node id or -1
  using CellWeights = Kokkos::View<double* [4][2], DeviceType>; ///< per cell, corner and slot: constraint weight

  /// How the nodes are found: p4est lnodes always, or (automatic) a direct numbering of the
  /// corner points when the forest has one tree, on any number of ranks (the same nodes and
  /// constraints, numbered in another order and on several ranks owned by other ranks; on one
  /// rank the whole constructor 2.3 -> 0.75 unconstrained solves per step of the membrane
  /// benchmark, on two ranks the last cycle's 0.88 -> 0.42 s per rank).
  /// (direct: the direct numbering, which must apply.)
  enum class Numbering { automatic, lnodes, direct };
  /// \p forest must be 2:1 balanced (Forest::balance()) and expanded; \p segments tag the boundary edges;
  /// \p comm spans the forest's ranks (kept: the maps live on it). Collective.
  Q1Mesh(const Forest& forest, const BoundarySegments& segments, RCP<const Comm> comm,
         Numbering numbering = Numbering::automatic);
  Q1Mesh(const Q1Mesh&) = delete;
  Q1Mesh& operator=(const Q1Mesh&) = delete;

  /// The communicator given to the constructor.
  RCP<const Comm> comm() const { return comm_; }
  /// The numbering used: Numbering::direct or Numbering::lnodes.
  Numbering numbering() const { return numbering_; }
  /// Nodes owned by this rank (rows of matrices).
  RCP<const Map> ownedMap() const { return ownedMap_; }
  /// Owned nodes followed by the shared nodes owned elsewhere.
  RCP<const Map> overlapMap() const { return overlapMap_; }
  /// Owned to overlap (values of shared nodes from their owners) and overlap to owned (sums).
  const Tpetra::Import<LO, GO, Node>& ownedToOverlap() const { return *importer_; }
  /// Overlap to owned (sums of the shared nodes' values at their owners).
  const Tpetra::Export<LO, GO, Node>& overlapToOwned() const { return *exporter_; }
  /// Cells on this rank (the forest's local cells, in its order).
  LO numLocalCells() const { return numCells_; }
  /// Independent (non-hanging) nodes on all ranks.
  GO numGlobalNodes() const { return ownedMap_->getGlobalNumElements(); }
  /// Cells on all ranks.
  long long numGlobalCells() const { return numGlobalCells_; }

  /// Corner c (z-order) of cell e: physical coordinates cornerCoords(e,c,d).
  CellCoords cornerCoords;
  /// Value at corner c of cell e = sum_k cornerWeights(e,c,k) * u[cornerDofs(e,c,k)] (overlap ids;
  /// k = 1 is used only at hanging corners, where both weights are 1/2; unused slots hold -1 / 0).
  CellDofs cornerDofs;
  CellWeights cornerWeights;  ///< the weights of cornerDofs (see there)
  CellCoords::HostMirror cornerCoordsHost;    ///< host copy of cornerCoords
  CellDofs::HostMirror cornerDofsHost;        ///< host copy of cornerDofs
  CellWeights::HostMirror cornerWeightsHost;  ///< host copy of cornerWeights

  /// Refinement level of each local cell, counted from the coarse mesh's cells (0 on them).
  const std::vector<int>& cellLevel() const { return cellLevel_; }
  /// The cells that refining the \p flagged ones (local cell order) forces under 2:1 balance over
  /// faces and corners, flags included, for a balanced forest: refining them once gives the
  /// forest of Forest::refineMarkedBalanced() (refineMarked() then balance()). Two touching cells
  /// of a balanced forest share a regular corner node, so the closure spreads through the nodes
  /// (finest flagged level per node, exchanged between ranks): no p4est face/corner iteration.
  std::vector<char> balanceClosure(const std::vector<char>& flagged) const;
  /// p4est tree of each local cell.
  const std::vector<int>& cellTree() const { return cellTree_; }
  /// The fine edges of the local cells on the domain boundary, in cell order.
  const std::vector<BoundaryEdge>& boundaryEdges() const { return boundaryEdges_; }
  /// Coordinates of every overlap node.
  const std::vector<std::array<double, 2>>& nodeCoords() const { return nodeCoords_; }
  /// A partition-independent key of overlap node \p node: its coordinates rounded to the grid of
  /// spacing hMin() / 64 (the same integers on any partition, where the node's coordinates may
  /// come from another cell and differ in the last bits; distinct for distinct nodes).
  std::array<long long, 2> canonicalKey(LO node) const;
  /// Smallest and largest edge length over all cells of all ranks [length, the deck's unit].
  double hMin() const { return hMin_; }
  double hMax() const { return hMax_; }  ///< largest edge length over all cells of all ranks [length]

  /// Local cell containing (x, y) and the point's reference coordinates (s, r) in [0,1]^2; -1 if
  /// no local cell contains it.
  LO locate(double x, double y, double& s, double& r) const;
  /// A local cell that contains a point, with the point's reference coordinates in it.
  struct CellPoint {
    LO cell;      ///< local cell id
    double s, r;  ///< reference coordinates in [0,1]^2 (to 1e-10)
  };
  /// Every local cell whose closure contains (x, y) (up to four; several where the point lies on
  /// cell edges), in local order.
  std::vector<CellPoint> locateAll(double x, double y) const;
  /// Flags (1 / 0, one char per node) on the overlap map for the nodes that lie on a boundary edge whose
  /// segment mask intersects \p mask, consistent across ranks. Collective.
  std::vector<char> nodesOnSegments(unsigned mask) const;

 private:
  /// Whether the closure of local cell \p e contains (x, y) (to 1e-10 in reference coordinates), and where (s, r).
  bool cellContains(LO e, double x, double y, double& s, double& r) const;
  Numbering numbering_ = Numbering::lnodes;
  RCP<const Comm> comm_;
  RCP<const Map> ownedMap_, overlapMap_;
  RCP<const Tpetra::Import<LO, GO, Node>> importer_;
  RCP<const Tpetra::Export<LO, GO, Node>> exporter_;
  LO numCells_ = 0;
  long long numGlobalCells_ = 0;
  std::vector<int> cellLevel_, cellTree_;
  std::vector<BoundaryEdge> boundaryEdges_;
  std::vector<std::array<double, 2>> nodeCoords_;
  double hMin_ = 0, hMax_ = 0;
};

}  // namespace signorini::mesh
