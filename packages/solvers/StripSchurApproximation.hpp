#pragma once
/// \file StripSchurApproximation.hpp
/// A local approximation of the Schur complement Q = B^T A^{-1} B on a strip along Gamma_C (StripSchurApproximation).
#include <memory>
#include <vector>

#include "signorini/fem/ContactCoupling.hpp"

namespace signorini::solvers {

/// A local approximation of the Schur complement Q = B^T A^{-1} B (DESIGN 1.6): A restricted to
/// a strip of a few layers of nodes along the contact boundary (homogeneous Dirichlet at its
/// inner edge), factored once per mesh (EnvelopeCholesky, on rank 0). Provides
///  - Qs = B^T A_s^{-1} B (dense m x m, replicated): a preconditioner for CG on Q_AA, whose
///    entries decay like exp(-1.4 d/k) so a strip of about 6 c k captures them;
///  - W_s p = A_s^{-1} B p (zero outside the strip): an initial guess for the exact A-solve.
/// Computes Qs and the local rows of A_s^{-1} B in the constructor and keeps them; keeps no reference to A or B.
class StripSchurApproximation {
 public:
  /// The same number of layers along every segment. Collective.
  /// \param A      the step matrix (rows on the owned unknowns).
  /// \param B      the contact coupling on the same unknowns.
  /// \param layers number of node layers of the strip (>= 1) counted from the contact nodes.
  StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B, int layers);
  /// A strip whose width follows the segments: nodes within layers[j] (>= 1) node layers of a node
  /// of segment E_j, for some j (graded meshes: fewer layers along coarse parts of Gamma_C). Collective.
  StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B, const std::vector<int>& layers);
  ~StripSchurApproximation();

  /// B^T A_s^{-1} B, row-major m x m, identical on all ranks.
  const std::vector<double>& matrix() const { return Qs_; }
  /// out (owned map of A) = A_s^{-1} B p, zero outside the strip.
  void applyStripInverse(const std::vector<double>& p, Vector& out) const;
  /// Number of strip nodes over all ranks.
  long long stripSize() const { return stripSize_; }
  /// Whether the strip's factor orders its nodes along Gamma_C (by coordinates) rather than by
  /// reverse Cuthill-McKee: taken where it at least halves the envelope. The same on all ranks.
  bool ordersAlongContact() const { return ordersAlongContact_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<double> Qs_;
  long long stripSize_ = 0;
  bool ordersAlongContact_ = false;
};

}  // namespace signorini::solvers
