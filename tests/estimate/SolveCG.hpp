#pragma once
/// \file SolveCG.hpp
/// The estimator tests' SPD solver for s1: Jacobi-preconditioned CG to a relative residual of 1e-14.
#include <algorithm>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Types.hpp"

namespace signorini::test {

/// Jacobi-preconditioned CG to a tight relative residual (the estimator's s1 solve).
inline void solveCG(const RCP<const CrsMatrix>& A, const Vector& b, Vector& x) {
  const auto map = A->getRowMap();
  Vector d(map), r(map), z(map), p(map), Ap(map);
  A->getLocalDiagCopy(d);
  d.reciprocal(d);
  A->apply(x, r);
  r.update(1.0, b, -1.0);
  z.elementWiseMultiply(1.0, d, r, 0.0);
  p.assign(z);
  double rz = r.dot(z);
  const double bnorm = std::max(b.norm2(), 1e-300);
  for (int it = 0; it < 20000 && r.norm2() > 1e-14 * bnorm; ++it) {
    A->apply(p, Ap);
    const double alpha = rz / p.dot(Ap);
    x.update(alpha, p, 1.0);
    r.update(-alpha, Ap, 1.0);
    z.elementWiseMultiply(1.0, d, r, 0.0);
    const double rzNew = r.dot(z);
    p.update(1.0, z, rzNew / rz);
    rz = rzNew;
  }
}

}  // namespace signorini::test
