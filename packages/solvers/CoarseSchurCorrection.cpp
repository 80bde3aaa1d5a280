#include "signorini/solvers/CoarseSchurCorrection.hpp"

#include <Amesos2.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini::solvers {

struct CoarseSchurCorrection::Impl {
  RCP<const CrsMatrix> A;
  RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver;
};

CoarseSchurCorrection::CoarseSchurCorrection(RCP<const CrsMatrix> A) : impl_(std::make_unique<Impl>()) {
  SIGNORINI_ASSERT(A->getComm()->getSize() == 1, "the coarse matrix must live on one rank");
  impl_->A = A;
  impl_->solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", A);
  impl_->solver->symbolicFactorization().numericFactorization();
}

CoarseSchurCorrection::~CoarseSchurCorrection() = default;

std::vector<double> CoarseSchurCorrection::schur(const std::vector<double>& loads, int m) const {
  std::vector<double> Q(static_cast<size_t>(m) * m, 0.0);
  if (m == 0) return Q;
  const auto map = impl_->A->getRowMap();
  const size_t n = map->getNodeNumElements();
  SIGNORINI_ASSERT(loads.size() == n * static_cast<size_t>(m), "coarse loads do not match the coarse matrix");
  auto L = Teuchos::rcp(new MultiVector(map, static_cast<size_t>(m)));
  auto X = Teuchos::rcp(new MultiVector(map, static_cast<size_t>(m)));
  {
    auto h = L->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int j = 0; j < m; ++j)
      for (size_t i = 0; i < n; ++i) h(i, j) = loads[static_cast<size_t>(j) * n + i];
  }
  impl_->solver->setX(X);
  impl_->solver->setB(L);
  impl_->solver->solve();
  auto l = L->getLocalViewHost(Tpetra::Access::ReadOnly);
  auto x = X->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (int a = 0; a < m; ++a)
    for (int b = a; b < m; ++b) {
      double sum = 0;
      for (size_t i = 0; i < n; ++i) sum += l(i, a) * x(i, b);
      Q[static_cast<size_t>(a) * m + b] = Q[static_cast<size_t>(b) * m + a] = sum;
    }
  return Q;
}

}  // namespace signorini::solvers
