#include "StripSchurApproximation.hpp"

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "Error.hpp"

namespace signorini::solvers {

struct StripSchurApproximation::Impl {
  RCP<const Map> stripMap;
  std::vector<LO> stripToOwned;      // owned local id of each local strip node
  RCP<MultiVector> W;                // A_s^{-1} B on the strip, m columns
};

StripSchurApproximation::StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B, int layers)
    : impl_(std::make_unique<Impl>()) {
  SIGNORINI_ASSERT(layers >= 1, "strip needs at least one layer");
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const LO nOwned = static_cast<LO>(rowMap->getNodeNumElements());
  const int m = B.numSegments();

  // Strip nodes: graph distance <= layers from a node with a non-zero row of B.
  std::vector<char> inStrip(nOwned, 0);
  const auto Bm = B.matrix();
  for (LO i = 0; i < nOwned; ++i) inStrip[i] = Bm->getNumEntriesInLocalRow(i) > 0;
  const auto importer = A.getGraph()->getImporter();
  Vector owned(rowMap), cols(colMap);
  typename CrsMatrix::local_inds_host_view_type idx;
  typename CrsMatrix::values_host_view_type vals;
  auto toColumns = [&]() {  // strip flags of the owned nodes -> flags on A's column map
    {
      auto h = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO i = 0; i < nOwned; ++i) h(i, 0) = inStrip[i];
    }
    if (importer.is_null())
      cols.assign(owned);
    else
      cols.doImport(owned, *importer, Tpetra::INSERT);
  };
  for (int layer = 0; layer < layers; ++layer) {
    toColumns();
    auto c = cols.getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<char> next = inStrip;
    for (LO i = 0; i < nOwned && !next.empty(); ++i) {
      if (inStrip[i]) continue;
      A.getLocalRowView(i, idx, vals);
      for (size_t k = 0; k < idx.extent(0); ++k)
        if (c(idx(k), 0) > 0) {
          next[i] = 1;
          break;
        }
    }
    inStrip.swap(next);
  }

  // The strip matrix: rows and columns of A on strip nodes only, renumbered contiguously
  // (Amesos2 needs contiguous maps).
  for (LO i = 0; i < nOwned; ++i)
    if (inStrip[i]) impl_->stripToOwned.push_back(i);
  const LO nStrip = static_cast<LO>(impl_->stripToOwned.size());
  const auto comm = rowMap->getComm();
  impl_->stripMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), nStrip, 0, comm));
  stripSize_ = static_cast<long long>(impl_->stripMap->getGlobalNumElements());
  {
    auto h = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(h, -1.0);
    for (LO s = 0; s < nStrip; ++s) h(impl_->stripToOwned[s], 0) = static_cast<double>(impl_->stripMap->getGlobalElement(s));
  }
  if (importer.is_null())
    cols.assign(owned);
  else
    cols.doImport(owned, *importer, Tpetra::INSERT);
  auto As = Teuchos::rcp(new CrsMatrix(impl_->stripMap, A.getNodeMaxNumRowEntries()));
  {
    auto c = cols.getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<GO> rowCols;
    std::vector<double> rowVals;
    for (LO s = 0; s < nStrip; ++s) {
      A.getLocalRowView(impl_->stripToOwned[s], idx, vals);
      rowCols.clear();
      rowVals.clear();
      for (size_t k = 0; k < idx.extent(0); ++k)
        if (c(idx(k), 0) >= 0) {
          rowCols.push_back(static_cast<GO>(c(idx(k), 0)));
          rowVals.push_back(vals(k));
        }
      As->insertGlobalValues(impl_->stripMap->getGlobalElement(s), Teuchos::ArrayView<const GO>(rowCols),
                             Teuchos::ArrayView<const double>(rowVals));
    }
  }
  As->fillComplete();

  // W = A_s^{-1} B_s for all segments at once.
  MultiVector Bs(impl_->stripMap, std::max(m, 1));
  {
    auto h = Bs.getLocalViewHost(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(h, 0.0);
    const auto bcol = Bm->getColMap();
    for (LO s = 0; s < nStrip; ++s) {
      Bm->getLocalRowView(impl_->stripToOwned[s], idx, vals);
      for (size_t k = 0; k < idx.extent(0); ++k) h(s, bcol->getGlobalElement(idx(k))) = vals(k);
    }
  }
  // Factor on rank 0 alone: Amesos2 13.2's KLU2 solves distributed matrices wrongly here (a
  // residual of order one on 2 ranks), so the strip system is gathered, factored and solved on
  // a one-rank communicator, and the solution scattered back.
  const int mm = std::max(m, 1);
  const GO nGlobal = static_cast<GO>(stripSize_);
  auto rootMap = Teuchos::rcp(new Map(nGlobal, comm->getRank() == 0 ? static_cast<size_t>(nGlobal) : 0, 0, comm));
  Tpetra::Export<LO, GO, Node> toRoot(impl_->stripMap, rootMap);
  CrsMatrix Aroot(rootMap, 0);
  Aroot.doExport(*As, toRoot, Tpetra::INSERT);
  Aroot.fillComplete(rootMap, rootMap);
  MultiVector Broot(rootMap, mm), Wroot(rootMap, mm);
  Broot.doExport(Bs, toRoot, Tpetra::INSERT);
  auto self = comm->split(comm->getRank() == 0 ? 0 : 1, 0);
  if (comm->getRank() == 0 && m > 0) {
    auto selfMap = Teuchos::rcp(new Map(nGlobal, 0, self));
    auto Aself = Teuchos::rcp(new CrsMatrix(selfMap, Aroot.getNodeMaxNumRowEntries()));
    const auto rootCols = Aroot.getColMap();
    std::vector<GO> rowCols;
    for (LO i = 0; i < static_cast<LO>(nGlobal); ++i) {
      Aroot.getLocalRowView(i, idx, vals);
      rowCols.resize(idx.extent(0));
      for (size_t k = 0; k < idx.extent(0); ++k) rowCols[k] = rootCols->getGlobalElement(idx(k));
      Aself->insertGlobalValues(static_cast<GO>(i), Teuchos::ArrayView<const GO>(rowCols),
                                Teuchos::ArrayView<const double>(vals.data(), vals.extent(0)));
    }
    Aself->fillComplete();
    auto Bself = Teuchos::rcp(new MultiVector(selfMap, mm));
    auto Wself = Teuchos::rcp(new MultiVector(selfMap, mm));
    {
      auto from = Broot.getLocalViewHost(Tpetra::Access::ReadOnly);
      auto to = Bself->getLocalViewHost(Tpetra::Access::OverwriteAll);
      Kokkos::deep_copy(to, from);
    }
    auto solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", Aself, Wself, Bself);
    solver->symbolicFactorization().numericFactorization().solve();
    auto from = Wself->getLocalViewHost(Tpetra::Access::ReadOnly);
    auto to = Wroot.getLocalViewHost(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(to, from);
  }
  impl_->W = Teuchos::rcp(new MultiVector(impl_->stripMap, mm));
  impl_->W->doImport(Wroot, Tpetra::Import<LO, GO, Node>(rootMap, impl_->stripMap), Tpetra::INSERT);
  // Qs = B_s^T W (local sums over owned strip rows, then summed over ranks).
  std::vector<double> local(static_cast<size_t>(m) * m, 0.0);
  {
    auto b = Bs.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto w = impl_->W->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO s = 0; s < nStrip; ++s)
      for (int i = 0; i < m; ++i) {
        if (b(s, i) == 0.0) continue;
        for (int j = 0; j < m; ++j) local[static_cast<size_t>(i) * m + j] += b(s, i) * w(s, j);
      }
  }
  Qs_.assign(local.size(), 0.0);
  if (!local.empty())
    Teuchos::reduceAll(*rowMap->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), Qs_.data());
  for (int i = 0; i < m; ++i)  // symmetrise the rounding
    for (int j = 0; j < i; ++j) {
      const double avg = 0.5 * (Qs_[static_cast<size_t>(i) * m + j] + Qs_[static_cast<size_t>(j) * m + i]);
      Qs_[static_cast<size_t>(i) * m + j] = Qs_[static_cast<size_t>(j) * m + i] = avg;
    }
}

StripSchurApproximation::~StripSchurApproximation() = default;

void StripSchurApproximation::applyStripInverse(const std::vector<double>& p, Vector& out) const {
  auto o = out.getLocalViewHost(Tpetra::Access::OverwriteAll);
  Kokkos::deep_copy(o, 0.0);
  auto w = impl_->W->getLocalViewHost(Tpetra::Access::ReadOnly);
  const int m = static_cast<int>(p.size());
  for (size_t s = 0; s < impl_->stripToOwned.size(); ++s) {
    double sum = 0;
    for (int j = 0; j < m; ++j)
      if (p[j] != 0.0) sum += w(s, j) * p[j];
    o(impl_->stripToOwned[s], 0) = sum;
  }
}

}  // namespace signorini::solvers
