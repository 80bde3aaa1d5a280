#pragma once
/// \file JacobiCG.hpp
/// A lean Jacobi-preconditioned conjugate gradient method for the small SPD solves inside an
/// adaptive step (the estimator's s1, the mass solves of the L2 projection between meshes): one
/// matrix apply, three vector kernels (two of them fused reductions, one global sum each) per
/// iteration, the inverse diagonal computed once, no solver or preconditioner objects to set up per call.
#include <vector>

#include "signorini/core/Types.hpp"

namespace signorini::solvers {

/// Solves A x = b (A SPD with a positive diagonal) from the initial guess in \p x until
/// ||b - A x|| <= relativeTolerance ||b|| (the recursively updated residual). Returns the number of
/// iterations; throws core::SolverError after \p maxIterations. For b = 0 it returns x = 0.
int solveJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance, int maxIterations);

/// Solves A x_f = b_f for several right-hand sides with one matrix (the projection's fields): each
/// field takes exactly the steps, and gets exactly the result, of its own solve above (same
/// operations in the same order on one rank), but the fields share the matrix applies (one
/// multi-vector apply while all iterate), the vector kernels and the global sums. Returns each
/// field's iterations; throws core::SolverError when a field has not converged after \p maxIterations.
/// Under core::reproducibleArithmetic() each field gets exactly the bits of its own
/// solveReproducibleJacobiCG (on any number of ranks), the fields again sharing the matrix sweeps
/// (core::applyCanonicalColumns).
std::vector<int> solveJacobiCG(const CrsMatrix& A, const std::vector<const Vector*>& b, const std::vector<Vector*>& x,
                               double relativeTolerance, int maxIterations);

/// Jacobi CG as solveJacobiCG for one field, with the partition-independent apply above and
/// core::reproducibleSums for every global sum: the iterates, and so the result and the iteration
/// count, have the same bits on any number of ranks. solveJacobiCG uses it when
/// core::reproducibleArithmetic() is on.
int solveReproducibleJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance,
                              int maxIterations);
/// The same with A's diagonal given (\p diagonal on A's row map, as A.getLocalDiagCopy gives it),
/// for a caller that solves with one matrix many times.
int solveReproducibleJacobiCG(const CrsMatrix& A, const Vector& diagonal, const Vector& b, Vector& x,
                              double relativeTolerance, int maxIterations);

}  // namespace signorini::solvers
