#pragma once
/// \file Assembler.hpp
/// The discretisation interface of the time stepper (Assembler) and helpers for its vectors and matrices.
#include <array>
#include <utility>
#include <vector>

#include <Tpetra_Export.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Expression.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

/// out (owned) = (out if accumulate, else 0) + the sum over ranks of the overlap contributions.
/// (Tpetra's doExport with ADD replaces, rather than adds to, the target's own entries.)
inline void addExported(const Vector& overlap, const Tpetra::Export<LO, GO, Node>& exporter, Vector& out,
                        bool accumulate) {
  if (!accumulate) {
    out.putScalar(0.0);
    out.doExport(overlap, exporter, Tpetra::ADD);
    return;
  }
  Vector sum(out.getMap());
  sum.doExport(overlap, exporter, Tpetra::ADD);
  out.update(1.0, sum, 1.0);
}

/// cm M + ck K for two fill-complete matrices on one local graph (null if they do not share one),
/// with the rows flagged in \p identityRows (owned rows; M and K are the identity there) kept
/// identity rows. The sum is formed from the values (no assembly).
RCP<CrsMatrix> combineOnGraph(const CrsMatrix& M, double cm, const CrsMatrix& K, double ck,
                              const std::vector<char>& identityRows);

/// What the time stepper needs from a finite element discretisation on one Q1Mesh, whatever the
/// number of unknowns per node: the scalar wave equation (Q1Assembler, one unknown per node) or
/// plane strain elasticity (ElasticityAssembler, two). Unknown c of overlap node i is overlap
/// entry components() * i + c (owned entries likewise; owned nodes come first in the overlap order).
/// The implementations keep a reference to their mesh, which must outlive them; each assembly returns a new matrix.
class Assembler {
 public:
  virtual ~Assembler() = default;

  /// The mesh the assembler was built on (a reference it keeps).
  virtual const mesh::Q1Mesh& mesh() const = 0;
  /// Unknowns per node (1 or 2).
  virtual int components() const = 0;
  /// Owned unknowns (rows of the matrices) and owned + shared unknowns.
  virtual RCP<const Map> ownedMap() const = 0;
  /// Owned unknowns followed by the shared ones owned by other ranks.
  virtual RCP<const Map> overlapMap() const = 0;
  /// Dirichlet flags on the overlap unknowns.
  virtual const std::vector<char>& dirichletFlags() const = 0;

  /// massCoeff * M + stiffCoeff * K with the problem's material (paper (3.7)); Dirichlet rows and
  /// columns replaced by the identity. \p lumpAt (overlap unknown flags, optional): mass couplings
  /// of the flagged unknowns moved to the diagonal (row sums kept).
  virtual RCP<CrsMatrix> assembleSystem(double massCoeff, double stiffCoeff, const ProblemData& problem,
                                        const std::vector<char>& lumpAt = {}) const = 0;
  /// out (owned) = scale * int f(., t) . phi_i dx, or += if \p accumulate (one expression per component).
  virtual void assembleLoad(const core::ExpressionList& f, double t, double scale, Vector& out,
                            bool accumulate = false) const = 0;
  /// out (owned) += scale * int_{edges in mask} q(., t) . phi_i ds.
  virtual void addBoundaryLoad(const core::ExpressionList& q, double t, unsigned mask, double scale,
                               Vector& out) const = 0;
  /// Sets the Dirichlet entries of an owned vector to zero.
  virtual void zeroDirichlet(Vector& v) const = 0;
  /// Values on the overlap map of an owned vector.
  virtual void toOverlap(const Vector& owned, Vector& overlap) const = 0;
  /// L2 norm and H1 seminorm of u_h - u_exact(., t), summed over the components.
  virtual std::pair<double, double> errorNorms(const Vector& uOwned, const core::ExpressionList& exact,
                                               double t) const = 0;
  /// Component \p c of u_h at a point (every rank gets the value); NaN outside the mesh.
  virtual double evaluateComponent(const Vector& uOverlap, double x, double y, int c) const = 0;

  /// For each component c, the sum over its Dirichlet unknowns d of the rows that the elimination
  /// drops: sum_d (M a + K u - f(t) - q(t))_d [force], with the problem's body force f and Neumann
  /// data q, mass couplings lumped at \p lumpAt as in assembleSystem(). With the contact force's
  /// share of those rows added, it is the force that the supports exert on the body (the reaction);
  /// \p uOverlap and \p aOverlap are u and a on the overlap unknowns. Collective; the bits do not
  /// depend on the partition.
  /// With \p momentPoint (two components only) a third entry: the rows' moment about that point,
  /// sum_d r_d (M a + K u - f(t) - q(t))_d for the rigid rotation r(x) = (-(y - p_y), x - p_x)
  /// [force length / length] (the supports' moment, with the contact's share added). \p rows (flags
  /// on the overlap unknowns): only the rows of the Dirichlet unknowns flagged there (one support's).
  virtual std::vector<double> dirichletRowSums(const Vector& uOverlap, const Vector& aOverlap,
                                               const ProblemData& problem, double t, const std::vector<char>& lumpAt,
                                               const std::array<double, 2>* momentPoint = nullptr,
                                       const std::vector<char>* rows = nullptr) const = 0;
  /// \p out (owned) = M w with the mass matrix before the Dirichlet elimination (lumped at \p lumpAt
  /// as in assembleSystem()) and \p wOverlap = w on all overlap unknowns, Dirichlet ones included:
  /// for the rigid rotation w = r, (M r) . v is the angular momentum of a velocity v. Collective.
  virtual void massBeforeElimination(const Vector& wOverlap, const ProblemData& problem,
                                     const std::vector<char>& lumpAt, Vector& out) const = 0;

  /// The element stiffness matrix of a cell with physical corners \p X (z-order) as K assembles
  /// it, unknowns interleaved: Ke[nc a + i][nc b + j] (nc = components()). For the Ritz projection
  /// between meshes (MeshTransfer::stiffnessLoads).
  virtual void elementStiffness(const ProblemData& problem, const double X[4][2], double Ke[8][8]) const = 0;

  /// M (lumped at \p lumpAt) and K of assembleSystem(1, 0, ...) and assembleSystem(0, 1, ...); an
  /// assembler may compute both in one pass over the cells.
  virtual std::pair<RCP<CrsMatrix>, RCP<CrsMatrix>> assembleMassAndStiffness(const ProblemData& problem,
                                                                             const std::vector<char>& lumpAt) const {
    return {assembleSystem(1.0, 0.0, problem, lumpAt), assembleSystem(0.0, 1.0, problem)};
  }

  /// The step's matrices, on one graph, Dirichlet rows and columns the identity in each.
  struct StepMatrices {
    /// \var M
    /// mass matrix M_rho (lumped at the flagged unknowns)
    /// \var K
    /// stiffness matrix (K_kappa, or elasticity's)
    /// \var A
    /// step matrix A = M + stiffCoeff K
    RCP<CrsMatrix> M, K, A;
  };
  /// M (mass, lumped at \p lumpAt), K (stiffness) and A = M + stiffCoeff K (paper (3.7); stiffCoeff = beta k^2).
  /// A is formed from the values of M and K (two assemblies instead of three).
  StepMatrices assembleStepMatrices(double stiffCoeff, const ProblemData& problem,
                                    const std::vector<char>& lumpAt = {}) const;

  /// Flags on the overlap unknowns of the nodes on the segments in \p mask (component \p c only, or
  /// every component for c < 0).
  std::vector<char> unknownsOnSegments(unsigned mask, int c = -1) const {
    const auto nodes = mesh().nodesOnSegments(mask);
    const int nc = components();
    std::vector<char> flags(nodes.size() * static_cast<size_t>(nc), 0);
    for (size_t i = 0; i < nodes.size(); ++i)
      for (int k = 0; k < nc; ++k)
        if (c < 0 || k == c) flags[i * nc + k] = nodes[i];
    return flags;
  }
};

}  // namespace signorini::fem
