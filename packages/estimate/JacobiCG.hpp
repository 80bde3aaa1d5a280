#pragma once
/// \file JacobiCG.hpp
/// A lean Jacobi-preconditioned conjugate gradient method for the small SPD solve of the
/// estimator's s1 (the harmonic continuation): one matrix apply, three fused vector kernels and
/// two reductions per iteration, no solver or preconditioner objects to set up per call.
#include "Types.hpp"

namespace signorini::estimate {

/// Solves A x = b (A SPD with a positive diagonal) from the initial guess in \p x until
/// ||b - A x|| <= relativeTolerance ||b|| (the recursively updated residual). Returns the number of
/// iterations; throws core::SolverError after \p maxIterations.
int solveJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance, int maxIterations);

}  // namespace signorini::estimate
