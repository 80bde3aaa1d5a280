#pragma once
/// \file EnvelopeCholesky.hpp
/// A serial sparse (envelope) Cholesky factorisation for thin domains (EnvelopeCholesky).
#include <cstddef>
#include <vector>

namespace signorini::solvers {

/// A serial sparse Cholesky factorisation A = L L^T for the small SPD matrices of thin domains
/// (the strip along Gamma_C of StripSchurApproximation): reverse Cuthill-McKee ordering (or a
/// given one with a much smaller envelope), then
/// L stored row by row from the first non-zero of each row (the envelope, which holds all fill).
/// A strip of w node layers has an envelope of about 2 w entries per row, so the factorisation
/// costs O(n w^2) and a solve O(n w) per right-hand side, with no set-up beyond that.
/// Owns the factor; keeps no reference to the input arrays.
class EnvelopeCholesky {
 public:
  /// Factors the n x n matrix given by CRS arrays holding both triangles (columns in any order,
  /// the structure symmetric). Throws core::SolverError if a pivot is not positive (A not SPD).
  /// \p preferred (empty, or a permutation: preferred[p] = row at position p) is another ordering,
  /// for example by coordinates along a strip; it is used when its envelope has at most half the
  /// entries of the reverse Cuthill-McKee one (whose breadth-first levels run through the coarse
  /// cells of a graded strip, each reaching along many fine edges).
  EnvelopeCholesky(int n, const std::vector<int>& rowPtr, const std::vector<int>& cols,
                   const std::vector<double>& values, const std::vector<int>& preferred = {});

  /// Solves A X = B in place for \p m right-hand sides: \p X is row-major n x m (row i, column j
  /// at i m + j) holding B on entry. Columns that start with zero rows (in the factor's ordering)
  /// skip them in the forward sweep.
  void solveInPlace(std::vector<double>& X, int m) const;

  /// Stored entries of L (the envelope including the diagonal).
  std::size_t envelopeSize() const { return env_.size(); }
  /// Whether the factor uses the constructor's preferred ordering (else reverse Cuthill-McKee).
  bool usesPreferredOrdering() const { return preferred_; }

 private:
  int n_;
  std::vector<int> perm_;    // perm_[p] = original row at position p
  std::vector<int> first_;   // first column of row p of L (positions)
  std::vector<std::size_t> off_;  // row p of L at env_[off_[p] .. off_[p] + p - first_[p]]
  std::vector<double> env_;
  bool preferred_ = false;
};

}  // namespace signorini::solvers
