#include "StripSchurApproximation.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "EnvelopeCholesky.hpp"
#include "Error.hpp"
#include "MpiComm.hpp"

namespace signorini::solvers {

struct StripSchurApproximation::Impl {
  std::vector<LO> stripToOwned;  // owned local id of each local strip node
  std::vector<double> W;         // A_s^{-1} B on the local strip rows, row-major nStrip x m
  int m = 0;
};

namespace {
/// Concatenation on rank 0, in rank order, of every rank's \p mine (empty elsewhere).
template <class T>
std::vector<T> gatherToRoot(MPI_Comm comm, const std::vector<T>& mine) {
  int n = static_cast<int>(mine.size()), size, rank;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<T> all(rank == 0 ? offsets.back() + counts.back() : 0);
  MPI_Gatherv(mine.data(), n, core::mpiType<T>(), all.data(), counts.data(), offsets.data(), core::mpiType<T>(), 0,
              comm);
  return all;
}
}  // namespace

StripSchurApproximation::StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B, int layers)
    : impl_(std::make_unique<Impl>()) {
  SIGNORINI_ASSERT(layers >= 1, "strip needs at least one layer");
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto comm = rowMap->getComm();
  const MPI_Comm raw = core::rawMpiComm(*comm);
  const LO nOwned = static_cast<LO>(rowMap->getNodeNumElements());
  const int m = B.numSegments();
  impl_->m = m;
  const auto Al = A.getLocalMatrixHost();
  const auto Bm = B.matrix();
  const auto Bl = Bm->getLocalMatrixHost();

  // Strip nodes: graph distance <= layers from a node with a non-zero row of B.
  std::vector<char> inStrip(nOwned, 0);
  for (LO i = 0; i < nOwned; ++i) inStrip[i] = Bl.graph.row_map(i + 1) > Bl.graph.row_map(i);
  const auto importer = A.getGraph()->getImporter();
  Vector owned(rowMap), cols(colMap);
  auto toColumns = [&](const auto& value) {  // a value per owned node -> the same on A's column map
    {
      auto h = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO i = 0; i < nOwned; ++i) h(i, 0) = value(i);
    }
    if (importer.is_null())
      cols.assign(owned);
    else
      cols.doImport(owned, *importer, Tpetra::INSERT);
  };
  if (importer.is_null()) {
    // One rank: column and row ids coincide, so the layers grow breadth-first from the contact nodes.
    std::vector<LO> front;
    for (LO i = 0; i < nOwned; ++i)
      if (inStrip[i]) front.push_back(i);
    for (int layer = 0; layer < layers; ++layer) {
      std::vector<LO> grown;
      for (LO i : front)
        for (auto k = Al.graph.row_map(i); k < Al.graph.row_map(i + 1); ++k)
          if (!inStrip[Al.graph.entries(k)]) inStrip[Al.graph.entries(k)] = 1, grown.push_back(Al.graph.entries(k));
      front.swap(grown);
    }
  } else {
    for (int layer = 0; layer < layers; ++layer) {
      toColumns([&](LO i) { return static_cast<double>(inStrip[i]); });
      auto c = cols.getLocalViewHost(Tpetra::Access::ReadOnly);
      std::vector<char> next = inStrip;
      for (LO i = 0; i < nOwned; ++i) {
        if (inStrip[i]) continue;
        for (auto k = Al.graph.row_map(i); k < Al.graph.row_map(i + 1); ++k)
          if (c(Al.graph.entries(k), 0) > 0) {
            next[i] = 1;
            break;
          }
      }
      inStrip.swap(next);
    }
  }

  // The strip matrix: rows and columns of A on strip nodes only, numbered contiguously in rank
  // order; gathered with B_s on rank 0, which factors it alone (EnvelopeCholesky is serial; the
  // strip is thin, so its envelope is narrow).
  for (LO i = 0; i < nOwned; ++i)
    if (inStrip[i]) impl_->stripToOwned.push_back(i);
  const LO nStrip = static_cast<LO>(impl_->stripToOwned.size());
  long long first = 0, mine = nStrip;
  MPI_Exscan(&mine, &first, 1, MPI_LONG_LONG, MPI_SUM, raw);
  if (comm->getRank() == 0) first = 0;
  MPI_Allreduce(&mine, &stripSize_, 1, MPI_LONG_LONG, MPI_SUM, raw);
  toColumns([&](LO) { return -1.0; });  // resets owned; the strip ids follow
  {
    auto h = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO s = 0; s < nStrip; ++s) h(impl_->stripToOwned[s], 0) = static_cast<double>(first + s);
  }
  if (importer.is_null())
    cols.assign(owned);
  else
    cols.doImport(owned, *importer, Tpetra::INSERT);
  std::vector<int> rowLength(nStrip);
  std::vector<long long> stripCols;
  std::vector<double> stripVals, Bs(static_cast<size_t>(nStrip) * m, 0.0);
  {
    auto c = cols.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto bcol = Bm->getColMap();
    for (LO s = 0; s < nStrip; ++s) {
      const LO i = impl_->stripToOwned[s];
      for (auto k = Al.graph.row_map(i); k < Al.graph.row_map(i + 1); ++k) {
        const double col = c(Al.graph.entries(k), 0);
        if (col < 0) continue;
        stripCols.push_back(static_cast<long long>(col));
        stripVals.push_back(Al.values(k));
        ++rowLength[s];
      }
      for (auto k = Bl.graph.row_map(i); k < Bl.graph.row_map(i + 1); ++k)
        Bs[static_cast<size_t>(s) * m + bcol->getGlobalElement(Bl.graph.entries(k))] = Bl.values(k);
    }
  }
  const auto allLength = gatherToRoot(raw, rowLength);
  const auto allCols = gatherToRoot(raw, stripCols);
  const auto allVals = gatherToRoot(raw, stripVals);
  auto allW = gatherToRoot(raw, Bs);  // B_s, overwritten by A_s^{-1} B_s on rank 0
  if (comm->getRank() == 0 && m > 0) {
    const int n = static_cast<int>(stripSize_);
    std::vector<int> rowPtr(n + 1, 0), cols(allCols.begin(), allCols.end());
    for (int r = 0; r < n; ++r) rowPtr[r + 1] = rowPtr[r] + allLength[r];
    const EnvelopeCholesky As(n, rowPtr, cols, allVals);
    As.solveInPlace(allW, m);
  }
  // W back to the owners of the strip rows (row-major blocks in rank order).
  {
    int size;
    MPI_Comm_size(raw, &size);
    const int count = nStrip * m;
    std::vector<int> counts(size), offsets(size, 0);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, raw);
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    impl_->W.assign(static_cast<size_t>(count), 0.0);
    if (m > 0)
      MPI_Scatterv(allW.data(), counts.data(), offsets.data(), MPI_DOUBLE, impl_->W.data(), count, MPI_DOUBLE, 0, raw);
  }
  // Qs = B_s^T W (local sums over owned strip rows, then summed over ranks).
  std::vector<double> local(static_cast<size_t>(m) * m, 0.0);
  for (LO s = 0; s < nStrip; ++s)
    for (int i = 0; i < m; ++i) {
      const double b = Bs[static_cast<size_t>(s) * m + i];
      if (b == 0.0) continue;
      for (int j = 0; j < m; ++j) local[static_cast<size_t>(i) * m + j] += b * impl_->W[static_cast<size_t>(s) * m + j];
    }
  Qs_.assign(local.size(), 0.0);
  if (!local.empty())
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), Qs_.data());
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
  const int m = impl_->m;
  SIGNORINI_ASSERT(static_cast<int>(p.size()) == m, "one value per segment");
  for (size_t s = 0; s < impl_->stripToOwned.size(); ++s) {
    double sum = 0;
    for (int j = 0; j < m; ++j)
      if (p[j] != 0.0) sum += impl_->W[s * m + j] * p[j];
    o(impl_->stripToOwned[s], 0) = sum;
  }
}

}  // namespace signorini::solvers
