#include "HarmonicContinuation.hpp"

#include <algorithm>
#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace signorini::estimate {

double harmonicContinuationNorm(const fem::Q1Assembler& scalar, const std::vector<char>& contact, const Vector& boundary,
                                const std::function<void(const RCP<const CrsMatrix>&, const Vector&, Vector&)>& solveSPD) {
  const auto owned = scalar.mesh().ownedMap();
  const LO nOwned = static_cast<LO>(owned->getNodeNumElements());
  const std::vector<char>& dirichlet = scalar.dirichletFlags();
  std::vector<char> prescribed(dirichlet.size());
  for (size_t i = 0; i < prescribed.size(); ++i) prescribed[i] = (dirichlet[i] || contact[i]) ? 1 : 0;
  // K + M with the Dirichlet rows and columns eliminated: v^T A v is the full H1 norm for v = 0 there.
  const RCP<const CrsMatrix> full = scalar.assembleOperator(1.0, 1.0, 1.0, 1.0);
  const RCP<const CrsMatrix> A = scalar.assembleOperator(1.0, 1.0, 1.0, 1.0, {}, &prescribed);
  // Lifting: b = -A_full w on the free nodes, b = w on the prescribed ones (identity rows).
  Vector b(owned), d(owned), Ad(owned);
  full->apply(boundary, b);
  {
    auto bh = b.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto wh = boundary.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < nOwned; ++i) bh(i, 0) = prescribed[i] ? wh(i, 0) : -bh(i, 0);
  }
  d.assign(boundary);
  solveSPD(A, b, d);
  {
    auto dh = d.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto wh = boundary.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < nOwned; ++i)
      if (prescribed[i]) dh(i, 0) = wh(i, 0);
  }
  full->apply(d, Ad);
  return std::sqrt(std::max(d.dot(Ad), 0.0));
}

}  // namespace signorini::estimate
