#pragma once
/// \file JacobiCG.hpp
/// A lean Jacobi-preconditioned conjugate gradient method for the small SPD solves inside an
/// adaptive step (the estimator's s1, the mass solve of the L2 projection between meshes): one
/// matrix apply, three vector kernels (two of them fused reductions, one global sum each) per
/// iteration, the inverse diagonal computed once, no solver or preconditioner objects to set up per call.
#include "Types.hpp"

namespace signorini::solvers {

/// Solves A x = b (A SPD with a positive diagonal) from the initial guess in \p x until
/// ||b - A x|| <= relativeTolerance ||b|| (the recursively updated residual). Returns the number of
/// iterations; throws core::SolverError after \p maxIterations. For b = 0 it returns x = 0.
int solveJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance, int maxIterations);

}  // namespace signorini::solvers
