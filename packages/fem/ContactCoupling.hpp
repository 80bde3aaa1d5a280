#pragma once
/// \file ContactCoupling.hpp
/// The multiplier segments of Gamma_C and the coupling matrix B of paper (3.7)-(3.8) (ContactCoupling).
#include <array>
#include <utility>
#include <vector>

#include "signorini/fem/Assembler.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

/// Which unknowns a contact constraint acts on: component \p component of each node (of
/// \p components per node, numbered as in fem::Assembler), with \p sign: sign u_c >= g.
/// Null maps: the mesh's node maps (one unknown per node).
struct ContactUnknowns {
  /// \var owned
  /// owned unknowns (null: the mesh's owned node map)
  /// \var overlap
  /// owned + shared unknowns (null: the mesh's overlap node map)
  RCP<const Map> owned, overlap;
  /// \var components
  /// unknowns per node
  /// \var component
  /// the constrained component c
  int components = 1, component = 0;
  double sign = 1.0;  ///< +1 or -1: the constraint sign u_c >= g
};

/// The contact boundary Gamma_C split into multiplier segments E_j (paper Sec. 3.2): H = 2h
/// following the local mesh size on graded meshes, each segment two sibling fine edges (the halves
/// of one edge of the parent cells); a lone edge, whose sibling half is refined further, joins the
/// segment next to it inside that half, so a segment is at most its edges' parent edge and a mesh
/// and its mirror image get mirrored segments. Or one edge each (H = h). Provides B_ij = int_{E_j} phi_i ds
/// of (3.7)-(3.8) as a Tpetra matrix, its products with replicated multiplier vectors, and the weighted
/// obstacle gbar_j = int_{E_j} g ds. The segment data (a few hundred numbers) are replicated
/// on every rank in the same order, independent of the number of ranks.
/// Keeps no reference to the mesh; B's row map is unknowns.owned (or the mesh's owned map), shared.
class ContactCoupling {
 public:
  /// Segments of two sibling fine edges (H = 2h, the paper's) or of one edge (H = h, unstable: paper Fig. 3.1).
  enum class SegmentSize { TwoEdges, OneEdge };
  using Unknowns = ContactUnknowns;  ///< which unknowns the constraint acts on

  /// Segments of the boundary edges in \p contactMask; rows of Dirichlet unknowns (flags on the
  /// overlap unknowns) stay empty. Collective over the mesh's communicator.
  ContactCoupling(const mesh::Q1Mesh& mesh, unsigned contactMask, SegmentSize size, const std::vector<char>& dirichlet,
                  const Unknowns& unknowns = Unknowns());

  /// m, the number of segments (columns of B), the same on every rank.
  int numSegments() const { return static_cast<int>(length_.size()); }
  /// |E_j| [length], replicated.
  const std::vector<double>& segmentLength() const { return length_; }
  /// Midpoint of E_j (replicated).
  const std::vector<std::array<double, 2>>& segmentMidpoint() const { return midpoint_; }
  /// Number of fine edges of E_j.
  const std::vector<int>& segmentEdges() const { return edgeCount_; }
  /// Segment of each of the mesh's local boundary edges (-1 if not a contact edge).
  const std::vector<int>& localEdgeSegment() const { return localEdgeSegment_; }

  /// y (owned) = scale * B lambda (+ y if accumulate).
  void apply(const std::vector<double>& lambda, Vector& y, double scale = 1.0, bool accumulate = false) const;
  /// The part of B lambda in the rows of the Dirichlet unknowns, which B leaves out: sum over the
  /// contact edges that end at a Dirichlet unknown of sign |E| / 2 lambda_j (a contact edge next to a
  /// clamped corner). The supports carry it; it belongs to their reaction. Replicated; collective.
  /// With \p rows (flags on the overlap unknowns), only the Dirichlet unknowns flagged there.
  double heldShare(const std::vector<double>& lambda, const std::vector<char>* rows = nullptr) const;
  /// The moment about \p p of B lambda over all of Gamma_C, Dirichlet rows included: r^T B lambda =
  /// sum_j lambda_j sign int_{E_j} r_c ds for the rigid rotation r(x) = (-(y - p_y), x - p_x) of a
  /// two-component problem (c the constrained component); -moment() in physical units is the
  /// contact force's moment. Replicated; collective; the bits do not depend on the partition.
  double moment(const std::vector<double>& lambda, const std::array<double, 2>& p) const;
  /// The part of moment() in the rows of the Dirichlet unknowns (heldShare() weighted by r_c at the
  /// Dirichlet end points; with \p rows only those flagged there). Replicated; collective.
  double heldMoment(const std::vector<double>& lambda, const std::array<double, 2>& p,
                    const std::vector<char>* rows = nullptr) const;
  /// B^T u for an owned vector u; the result is replicated on every rank.
  std::vector<double> applyTranspose(const Vector& u) const;
  /// gbar_j = int_{E_j} g(., t) ds (3-point Gauss per fine edge), replicated.
  std::vector<double> weightedObstacle(const core::Expression& g, double t) const;
  /// The smallest gap sign u_c - g(., t) [length] of each segment at the 3 Gauss points of each of
  /// its fine edges (those of weightedObstacle()), u linear along each edge; replicated
  /// (the minimum over the ranks). The mean gap (B^T u - gbar)_j / |E_j| can be positive while u
  /// penetrates the obstacle inside E_j by up to the obstacle's variation over it. \p uOverlap: u
  /// on the overlap unknowns of \p mesh, the mesh this coupling was built on.
  std::vector<double> smallestGaps(const mesh::Q1Mesh& mesh, const Vector& uOverlap, const core::Expression& g,
                                   double t) const;
  /// B as a Tpetra matrix: rows on the owned unknowns, columns = segments (domain map: all on rank 0).
  RCP<const CrsMatrix> matrix() const { return B_; }
  /// P^T B for a coarser discretisation \p coarse of the same domain held whole on one rank (its
  /// mesh refines the same coarse mesh less): column j holds sign int_{E_j} phi^c_i ds for the
  /// coarse unknowns i of the constrained component (3-point Gauss on every fine edge; Dirichlet
  /// unknowns of \p coarse left zero). Dense, column-major, n_coarse x m, the same on every rank.
  std::vector<double> coarseLoads(const Assembler& coarse) const;
  /// The "lumped" Schur complement B^T D^{-1} B, entries sum_i B_ij B_il / d_i, for a positive diagonal
  /// D = diag(d) (\p d an owned vector): the full dense row-major m x m matrix, replicated on all ranks. Collective.
  std::vector<double> lumpedSchurComplement(const Vector& d) const;
  /// A key of each owned unknown that does not depend on the partition (its node's coordinates
  /// rounded to h_min / 64, then its component): orders the strip of StripSchurApproximation
  /// under reproducible arithmetic.
  const std::vector<std::array<long long, 3>>& canonicalKeys() const { return canonicalKeys_; }

 private:
  /// The replicated sums over all ranks of the terms (index, value) of every rank, each index's
  /// terms sorted by value and added in that order (reproducible arithmetic).
  std::vector<double> canonicalSums(int n, const std::vector<std::pair<int, double>>& terms) const;
  std::vector<std::array<long long, 3>> canonicalKeys_;
  RCP<const Comm> comm_;
  ContactUnknowns unknowns_;
  RCP<const Map> segmentMap_;
  RCP<CrsMatrix> B_;
  std::vector<double> length_;
  std::vector<std::array<double, 2>> midpoint_;
  std::vector<int> edgeCount_;
  std::vector<int> localEdgeSegment_;
  /// A local contact edge (or, in heldEnds_, one of its Dirichlet end points): its segment, weight
  /// (sign |E|, or sign |E| / 2 at an end) and the point where r is taken (midpoint, or end).
  struct WeightedPoint {
    int segment;
    double weight, x, y;
    LO row = -1;  ///< heldEnds_: the Dirichlet unknown (overlap index)
  };
  std::vector<WeightedPoint> localEdges_, heldEnds_;
  /// sum over \p points (those whose row \p rows flags, if given) of weight lambda_segment times
  /// r_c(x, y) (\p p given) or 1, over all ranks
  double weightedSum(const std::vector<WeightedPoint>& points, const std::vector<double>& lambda,
                     const std::array<double, 2>* p, const std::vector<char>* rows) const;
  std::vector<std::array<double, 4>> edges_;  // all contact edges (x0, y0, x1, y1), replicated
  std::vector<int> edgeSegment_;              // segment of each replicated edge
  Kokkos::View<double* [4], DeviceType> edgeCoords_;  // the same, for kernels
  Kokkos::View<int*, DeviceType> edgeSegmentView_;
};

}  // namespace signorini::fem
