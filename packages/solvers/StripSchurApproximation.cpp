#include "signorini/solvers/StripSchurApproximation.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <numeric>
#include <tuple>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/solvers/EnvelopeCholesky.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"

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

/// The strip ids ordered along Gamma_C, each connected piece of the strip (graph \p rowPtr, \p cols)
/// by itself, the pieces by their smallest id: by the coordinate in which the piece's contact rows
/// (those with a non-zero in \p Bs, row-major n x m in id order) extend furthest, then by the other
/// one, then by the component (\p keys: three per gathered row, \p position[id] the row of id). So
/// contact on two opposite sides gives two pieces, each ordered along its side. Partition-
/// independent, like the keys. Empty (no preference) when no strip row touches a segment, as when
/// every node of Gamma_C is a Dirichlet node.
std::vector<int> orderAlongContact(int n, int m, const std::vector<int>& rowPtr, const std::vector<int>& cols,
                                   const std::vector<double>& Bs, const std::vector<int>& position,
                                   const std::vector<long long>& keys) {
  std::vector<int> piece(static_cast<size_t>(n), -1), stack;
  int pieces = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (piece[seed] >= 0) continue;
    piece[seed] = pieces;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int k = rowPtr[v]; k < rowPtr[v + 1]; ++k)
        if (piece[cols[k]] < 0) piece[cols[k]] = pieces, stack.push_back(cols[k]);
    }
    ++pieces;
  }
  constexpr long long kMax = std::numeric_limits<long long>::max(), kMin = std::numeric_limits<long long>::min();
  std::vector<std::array<long long, 4>> extent(static_cast<size_t>(pieces), {kMax, kMin, kMax, kMin});
  bool contact = false;
  for (int id = 0; id < n; ++id) {
    const auto row = Bs.begin() + static_cast<std::ptrdiff_t>(id) * m;
    if (std::all_of(row, row + m, [](double b) { return b == 0.0; })) continue;
    contact = true;
    auto& e = extent[static_cast<size_t>(piece[id])];
    for (int d = 0; d < 2; ++d) {
      e[2 * d] = std::min(e[2 * d], keys[3 * static_cast<size_t>(position[id]) + d]);
      e[2 * d + 1] = std::max(e[2 * d + 1], keys[3 * static_cast<size_t>(position[id]) + d]);
    }
  }
  if (!contact) return {};
  std::vector<int> along(static_cast<size_t>(pieces), 0);  // a piece without contact rows: x first
  for (int p = 0; p < pieces; ++p) {
    const auto& e = extent[static_cast<size_t>(p)];
    if (e[0] <= e[1]) along[p] = e[1] - e[0] >= e[3] - e[2] ? 0 : 1;
  }
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int id) {
    const long long* k = keys.data() + 3 * static_cast<size_t>(position[id]);
    const int a = along[static_cast<size_t>(piece[id])];
    return std::make_tuple(piece[id], k[a], k[1 - a], k[2]);
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  return order;
}

}  // namespace

StripSchurApproximation::StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B, int layers)
    : StripSchurApproximation(A, B, std::vector<int>(static_cast<size_t>(B.numSegments()), layers)) {}

StripSchurApproximation::StripSchurApproximation(const CrsMatrix& A, const fem::ContactCoupling& B,
                                                 const std::vector<int>& layers)
    : impl_(std::make_unique<Impl>()) {
  const int m = B.numSegments();
  SIGNORINI_ASSERT(static_cast<int>(layers.size()) == m, "one layer count per segment");
  SIGNORINI_ASSERT(m == 0 || *std::min_element(layers.begin(), layers.end()) >= 1, "strip needs at least one layer");
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto comm = rowMap->getComm();
  const MPI_Comm raw = core::rawMpiComm(*comm);
  const LO nOwned = static_cast<LO>(rowMap->getNodeNumElements());
  impl_->m = m;
  const auto Al = A.getLocalMatrixHost();
  const auto Bm = B.matrix();
  const auto Bl = Bm->getLocalMatrixHost();
  const auto bcol = Bm->getColMap();

  // Strip nodes: graph distance <= layers_j from a node of segment j (a non-zero in column j of B).
  // reach[i]: the most layers left at node i over all segments (-1: not in the strip).
  std::vector<int> reach(nOwned, -1);
  int maxLayers = 0;
  for (LO i = 0; i < nOwned; ++i)
    for (auto k = Bl.graph.row_map(i); k < Bl.graph.row_map(i + 1); ++k) {
      const int l = layers[static_cast<size_t>(bcol->getGlobalElement(Bl.graph.entries(k)))];
      reach[i] = std::max(reach[i], l);
      maxLayers = std::max(maxLayers, l);
    }
  {
    const int mine = maxLayers;  // the sweeps below are collective
    MPI_Allreduce(&mine, &maxLayers, 1, MPI_INT, MPI_MAX, raw);
  }
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
    // One rank: column and row ids coincide, so the strip grows breadth-first from the contact
    // nodes, the nodes with the most layers left first (a bucket per count).
    std::vector<std::vector<LO>> bucket(static_cast<size_t>(maxLayers) + 1);
    for (LO i = 0; i < nOwned; ++i)
      if (reach[i] > 0) bucket[static_cast<size_t>(reach[i])].push_back(i);
    for (int left = maxLayers; left > 0; --left)
      for (LO i : bucket[static_cast<size_t>(left)]) {
        if (reach[i] != left) continue;  // reached again with more layers left
        for (auto k = Al.graph.row_map(i); k < Al.graph.row_map(i + 1); ++k) {
          const LO j = Al.graph.entries(k);
          if (reach[j] < left - 1) {
            reach[j] = left - 1;
            if (left > 1) bucket[static_cast<size_t>(left - 1)].push_back(j);
          }
        }
      }
  } else {
    for (int layer = 0; layer < maxLayers; ++layer) {
      toColumns([&](LO i) { return static_cast<double>(reach[i]); });
      auto c = cols.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (LO i = 0; i < nOwned; ++i)
        for (auto k = Al.graph.row_map(i); k < Al.graph.row_map(i + 1); ++k)
          reach[i] = std::max(reach[i], static_cast<int>(c(Al.graph.entries(k), 0)) - 1);
    }
  }

  // The strip matrix: rows and columns of A on strip nodes only, numbered contiguously in rank
  // order; gathered with B_s on rank 0, which factors it alone (EnvelopeCholesky is serial; the
  // strip is thin, so its envelope is narrow).
  for (LO i = 0; i < nOwned; ++i)
    if (reach[i] >= 0) impl_->stripToOwned.push_back(i);
  const LO nStrip = static_cast<LO>(impl_->stripToOwned.size());
  long long first = 0, mine = nStrip;
  MPI_Exscan(&mine, &first, 1, MPI_LONG_LONG, MPI_SUM, raw);
  if (comm->getRank() == 0) first = 0;
  MPI_Allreduce(&mine, &stripSize_, 1, MPI_LONG_LONG, MPI_SUM, raw);
  // Strip ids: contiguous in rank order, or under reproducible arithmetic in the order of the
  // unknowns' canonical keys (the same on any number of ranks, so is the factorisation).
  const bool reproducible = core::reproducibleArithmetic();
  std::vector<long long> stripId(static_cast<size_t>(nStrip));
  for (LO s = 0; s < nStrip; ++s) stripId[s] = first + s;
  if (reproducible) {
    std::vector<long long> keys;
    for (LO s = 0; s < nStrip; ++s)
      for (long long k : B.canonicalKeys()[impl_->stripToOwned[s]]) keys.push_back(k);
    const auto allKeys = core::allGatherv(raw, keys);
    std::vector<long long> order(allKeys.size() / 3);
    for (size_t g = 0; g < order.size(); ++g) order[g] = static_cast<long long>(g);
    auto key = [&](long long g) { return std::tie(allKeys[3 * g], allKeys[3 * g + 1], allKeys[3 * g + 2]); };
    std::sort(order.begin(), order.end(), [&](long long a, long long b) { return key(a) < key(b); });
    for (size_t r = 1; r < order.size(); ++r)
      SIGNORINI_ASSERT(key(order[r - 1]) < key(order[r]), "two strip unknowns with one canonical key");
    std::vector<long long> rankOf(order.size());
    for (size_t r = 0; r < order.size(); ++r) rankOf[order[r]] = static_cast<long long>(r);
    for (LO s = 0; s < nStrip; ++s) stripId[s] = rankOf[first + s];
  }
  toColumns([&](LO) { return -1.0; });  // resets owned; the strip ids follow
  {
    auto h = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO s = 0; s < nStrip; ++s) h(impl_->stripToOwned[s], 0) = static_cast<double>(stripId[s]);
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
  const auto allIds = gatherToRoot(raw, stripId);
  std::vector<long long> stripKeys;  // the rows' canonical keys (coordinates, component)
  stripKeys.reserve(3 * static_cast<size_t>(nStrip));
  for (LO s = 0; s < nStrip; ++s)
    for (long long k : B.canonicalKeys()[impl_->stripToOwned[s]]) stripKeys.push_back(k);
  const auto allKeys = gatherToRoot(raw, stripKeys);
  std::vector<double> canonicalQs;  // reproducible: B_s^T W summed on rank 0 in strip id order
  // Rank 0 factors the strip; its failure (a matrix that is not positive definite to rounding) is
  // every rank's, which would otherwise wait for it in the scatter below.
  core::onRootCollectively(*comm, [&] {
    if (m == 0) return;
    const int n = static_cast<int>(stripSize_);
    // Rows in strip id order: position[id] is the row's place in the gathered (rank) order.
    std::vector<int> position(n), rowStart(n + 1, 0);
    for (int r = 0; r < n; ++r) position[allIds[r]] = r, rowStart[r + 1] = rowStart[r] + allLength[r];
    std::vector<int> rowPtr(n + 1, 0), cols;
    std::vector<double> vals, W(static_cast<size_t>(n) * m);
    std::vector<std::pair<long long, double>> row;
    for (int id = 0; id < n; ++id) {
      const int r = position[id];
      rowPtr[id + 1] = rowPtr[id] + allLength[r];
      row.clear();
      for (int k = rowStart[r]; k < rowStart[r + 1]; ++k) row.push_back({allCols[k], allVals[k]});
      // Columns in strip id order: the ordering of the factorisation follows the row order (and
      // so does not depend on the column maps of the ranks).
      if (reproducible) std::sort(row.begin(), row.end());
      for (const auto& [c, v] : row) cols.push_back(static_cast<int>(c)), vals.push_back(v);
      std::copy(allW.begin() + static_cast<size_t>(r) * m, allW.begin() + static_cast<size_t>(r + 1) * m,
                W.begin() + static_cast<size_t>(id) * m);
    }
    const std::vector<double> Bs = reproducible ? W : std::vector<double>();
    std::unique_ptr<EnvelopeCholesky> factor;
    try {
      factor = std::make_unique<EnvelopeCholesky>(n, rowPtr, cols, vals,
                                                  orderAlongContact(n, m, rowPtr, cols, W, position, allKeys));
    } catch (const core::SolverError& e) {
      throw core::SolverError(std::string("the contact Schur preconditioner (the step matrix on a strip along "
                                          "Gamma_C, Contact/Schur Preconditioner): ") + e.what() +
                              ": the step matrix is not positive definite to rounding (" + kNotPositiveDefiniteHint +
                              ")");
    }
    const EnvelopeCholesky& As = *factor;
    ordersAlongContact_ = As.usesPreferredOrdering();
    As.solveInPlace(W, m);
    for (int id = 0; id < n; ++id)
      std::copy(W.begin() + static_cast<size_t>(id) * m, W.begin() + static_cast<size_t>(id + 1) * m,
                allW.begin() + static_cast<size_t>(position[id]) * m);
    if (reproducible) {
      canonicalQs.assign(static_cast<size_t>(m) * m, 0.0);
      for (int id = 0; id < n; ++id)
        for (int i = 0; i < m; ++i) {
          const double b = Bs[static_cast<size_t>(id) * m + i];
          if (b == 0.0) continue;
          for (int j = 0; j < m; ++j) canonicalQs[static_cast<size_t>(i) * m + j] += b * W[static_cast<size_t>(id) * m + j];
        }
    }
  });
  {
    int along = ordersAlongContact_ ? 1 : 0;
    MPI_Bcast(&along, 1, MPI_INT, 0, raw);
    ordersAlongContact_ = along != 0;
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
  // Qs = B_s^T W: local sums over the owned strip rows, then summed over ranks (reproducible: the
  // sum rank 0 made in strip id order).
  Qs_.assign(static_cast<size_t>(m) * m, 0.0);
  if (reproducible) {
    if (comm->getRank() == 0) Qs_ = canonicalQs;
    if (!Qs_.empty()) Teuchos::broadcast(*comm, 0, static_cast<int>(Qs_.size()), Qs_.data());
  } else if (!Qs_.empty()) {
    std::vector<double> local(Qs_.size(), 0.0);
    for (LO s = 0; s < nStrip; ++s)
      for (int i = 0; i < m; ++i) {
        const double b = Bs[static_cast<size_t>(s) * m + i];
        if (b == 0.0) continue;
        for (int j = 0; j < m; ++j) local[static_cast<size_t>(i) * m + j] += b * impl_->W[static_cast<size_t>(s) * m + j];
      }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), Qs_.data());
  }
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
