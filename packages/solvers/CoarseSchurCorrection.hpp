#pragma once
/// \file CoarseSchurCorrection.hpp
/// The far-field part of the Schur complement Q = B^T A^{-1} B (CoarseSchurCorrection).
#include <memory>
#include <vector>

#include "signorini/core/Types.hpp"

namespace signorini::solvers {

/// The far-field part of the Schur complement Q = B^T A^{-1} B (DESIGN 1.6): the step matrix A_c
/// of a coarse mesh (a uniform refinement of the deck's coarse mesh no finer than its initial mesh,
/// Contact/Coarse Correction Cells), held whole on every rank and factored once per run
/// with Amesos2/KLU2, gives Q_c = (P^T B)^T A_c^{-1} (P^T B), P the embedding of the coarse space.
/// Added to the strip approximation it forms B^T (R^T A_s^{-1} R + P A_c^{-1} P^T) B, the
/// two-level additive Schwarz approximation of A^{-1} seen through B: needed when A^{-1} reaches
/// further than any affordable strip (elasticity, where c k is as large as the body).
/// Keeps the RCP of A_c it is given and owns the factorisation.
class CoarseSchurCorrection {
 public:
  /// Factors \p A (KLU2) at once: later changes of its values are not seen.
  /// \param A the coarse step matrix on a one-rank communicator (each rank its own copy); kept.
  explicit CoarseSchurCorrection(RCP<const CrsMatrix> A);
  ~CoarseSchurCorrection();
  /// L^T A_c^{-1} L for the column-major n x m loads L (fem::ContactCoupling::coarseLoads):
  /// dense, row-major m x m.
  std::vector<double> schur(const std::vector<double>& loads, int m) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini::solvers
