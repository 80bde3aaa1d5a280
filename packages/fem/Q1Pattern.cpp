#include "signorini/fem/Q1Pattern.hpp"

#include <algorithm>
#include <numeric>
#include <type_traits>

#include <Teuchos_OrdinalTraits.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include "signorini/fem/AssemblyTools.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"

namespace signorini::fem {

static_assert(std::is_same_v<GO, long long>, "the global ids travel as MPI_LONG_LONG");

Q1Pattern::Q1Pattern(const mesh::Q1Mesh& mesh, int components, const RCP<const Map>& owned,
                     const RCP<const Map>& overlap)
    : owned_(owned), overlap_(overlap) {
  const int C = components;
  const LO nRows = static_cast<LO>(overlap->getNodeNumElements());
  const LO nOwned = static_cast<LO>(owned->getNodeNumElements());
  const size_t nNodes = static_cast<size_t>(nRows / C);
  const Q1NodeAdjacency adj = q1NodeAdjacency(mesh, nNodes);
  // The overlap unknowns row r couples to (through its node's cells), in the order of the adjacency.
  auto forEachColumn = [&](LO r, auto&& visit) {
    const size_t n = static_cast<size_t>(r / C);
    for (size_t k = adj.offset[n]; k < adj.offset[n] + adj.count[n]; ++k)
      for (int d = 0; d < C; ++d) visit(static_cast<LO>(C * adj.adjacent[k] + d));
  };
  const bool oneRank = overlap->getComm()->getSize() == 1;
  SIGNORINI_ASSERT(!oneRank || overlap->isSameAs(*owned), "on one rank every overlap unknown is owned");
  if (oneRank) {  // the adjacency itself: columns are overlap unknowns, sorted
    Kokkos::View<size_t*, Kokkos::HostSpace> rh("q1PatternRows", static_cast<size_t>(nRows) + 1);
    for (size_t n = 0; n < nNodes; ++n)
      for (int c = 0; c < C; ++c) rh(C * n + c + 1) = rh(C * n + c) + C * adj.count[n];
    Kokkos::View<LO*, Kokkos::HostSpace> ch("q1PatternColumns", rh(nRows));
    for (LO r = 0; r < nRows; ++r) {
      auto at = rh(r);
      forEachColumn(r, [&](LO u) { ch(at++) = u; });
    }
    LocalMatrix::row_map_type::non_const_type rowPtr("q1PatternRows", static_cast<size_t>(nRows) + 1);
    LocalMatrix::index_type::non_const_type cols("q1PatternColumns", rh(nRows));
    Kokkos::deep_copy(rowPtr, rh);
    Kokkos::deep_copy(cols, ch);
    rowPtr_ = rowPtr;
    cols_ = cols;
    ownedEntries_ = rh(nRows);
    numColumns_ = nRows;
    columns_ = overlap;
    Kokkos::View<LO*, DeviceType> toCol("toCol", nRows);
    Kokkos::parallel_for(
        "signorini::q1PatternColumns", Kokkos::RangePolicy<ExecSpace>(0, nRows), KOKKOS_LAMBDA(const LO i) { toCol(i) = i; });
    toCol_ = toCol;
    return;
  }

  // Several ranks: the foreign rows' patterns go to their owners, grouped by owner.
  std::vector<GO> sent;  // per foreign row: global row id, number of columns, their global ids
  std::vector<GO> received;
  const MPI_Comm comm = core::rawMpiComm(*overlap->getComm());
  const int size = overlap->getComm()->getSize();
  {
    std::vector<GO> foreign(static_cast<size_t>(nRows - nOwned));
    for (LO r = nOwned; r < nRows; ++r) foreign[r - nOwned] = overlap->getGlobalElement(r);
    Teuchos::Array<int> owner(foreign.size());
    owned->getRemoteIndexList(Teuchos::ArrayView<const GO>(foreign), owner());
    sendRows_.resize(foreign.size());
    std::iota(sendRows_.begin(), sendRows_.end(), nOwned);
    std::stable_sort(sendRows_.begin(), sendRows_.end(), [&](LO a, LO b) { return owner[a - nOwned] < owner[b - nOwned]; });
    sendOffsets_.assign(size + 1, 0);
    std::vector<int> patternOffsets(size + 1, 0);
    for (const LO r : sendRows_) {
      const int to = owner[r - nOwned];
      SIGNORINI_ASSERT(to >= 0 && to != overlap->getComm()->getRank(), "a foreign row without another owner");
      sent.push_back(overlap->getGlobalElement(r));
      const size_t countAt = sent.size();
      sent.push_back(0);
      forEachColumn(r, [&](LO u) { sent.push_back(overlap->getGlobalElement(u)); });
      sent[countAt] = static_cast<GO>(sent.size() - countAt - 1);
      sendOffsets_[to + 1] += static_cast<int>(sent[countAt]);
      patternOffsets[to + 1] += static_cast<int>(sent[countAt]) + 2;
    }
    for (int r = 0; r < size; ++r) sendOffsets_[r + 1] += sendOffsets_[r], patternOffsets[r + 1] += patternOffsets[r];
    auto got = core::exchange(comm, sent, patternOffsets);
    received = std::move(got.values);
    recvOffsets_.assign(size + 1, 0);  // in values: the received rows' column counts
    for (int r = 0; r < size; ++r) {
      recvOffsets_[r + 1] = recvOffsets_[r];
      for (int j = got.offsets[r]; j < got.offsets[r + 1]; j += static_cast<int>(received[j + 1]) + 2)
        recvOffsets_[r + 1] += static_cast<int>(received[j + 1]);
    }
    sendCounts_.resize(size), recvCounts_.resize(size);
    for (int r = 0; r < size; ++r)
      sendCounts_[r] = sendOffsets_[r + 1] - sendOffsets_[r], recvCounts_[r] = recvOffsets_[r + 1] - recvOffsets_[r];
  }

  // The column map: the owned unknowns, then every other unknown the owned rows couple to, by global id.
  const auto ownedGids = owned->getNodeElementList();
  std::vector<GO> remote;
  auto addIfRemote = [&](GO g) {
    if (!owned->isNodeGlobalElement(g)) remote.push_back(g);
  };
  for (LO r = 0; r < nOwned; ++r) forEachColumn(r, [&](LO u) { addIfRemote(overlap->getGlobalElement(u)); });
  for (size_t j = 0; j < received.size(); j += static_cast<size_t>(received[j + 1]) + 2)
    for (GO k = 0; k < received[j + 1]; ++k) addIfRemote(received[j + 2 + k]);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  auto columnOf = [&](GO g) -> LO {
    const LO o = owned->getLocalElement(g);
    if (o != Teuchos::OrdinalTraits<LO>::invalid()) return o;
    const auto it = std::lower_bound(remote.begin(), remote.end(), g);
    return it != remote.end() && *it == g ? static_cast<LO>(nOwned + (it - remote.begin())) : -1;
  };
  {
    std::vector<GO> gids(ownedGids.begin(), ownedGids.end());
    gids.insert(gids.end(), remote.begin(), remote.end());
    columns_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                    Teuchos::ArrayView<const GO>(gids), owned->getIndexBase(), owned->getComm()));
  }
  numColumns_ = static_cast<LO>(nOwned + remote.size());
  // Overlap unknowns that only foreign rows couple to get columns after the column map's.
  auto toColHost = Kokkos::View<LO*, Kokkos::HostSpace>("toCol", nRows);
  for (LO u = 0; u < nRows; ++u) {
    const LO c = columnOf(overlap->getGlobalElement(u));
    toColHost(u) = c >= 0 ? c : numColumns_++;
  }

  // The owned rows: this rank's couplings and the received ones, sorted by column.
  std::vector<std::vector<LO>> receivedColumns;  // per owned row, when it received any
  std::vector<int> receivedRow(static_cast<size_t>(nOwned), -1);
  for (size_t j = 0; j < received.size(); j += static_cast<size_t>(received[j + 1]) + 2) {
    const LO row = owned->getLocalElement(received[j]);
    SIGNORINI_ASSERT(row != Teuchos::OrdinalTraits<LO>::invalid(), "a received row this rank does not own");
    if (receivedRow[row] < 0) receivedRow[row] = static_cast<int>(receivedColumns.size()), receivedColumns.emplace_back();
    for (GO k = 0; k < received[j + 1]; ++k) receivedColumns[receivedRow[row]].push_back(columnOf(received[j + 2 + k]));
  }
  Kokkos::View<size_t*, Kokkos::HostSpace> rh("q1PatternRows", static_cast<size_t>(nRows) + 1);
  std::vector<LO> columns;
  columns.reserve(adj.adjacent.size() * C * C + received.size());
  std::vector<LO> row;
  for (LO r = 0; r < nOwned; ++r) {
    row.clear();
    forEachColumn(r, [&](LO u) { row.push_back(toColHost(u)); });
    if (receivedRow[r] >= 0) {
      const auto& more = receivedColumns[receivedRow[r]];
      row.insert(row.end(), more.begin(), more.end());
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    columns.insert(columns.end(), row.begin(), row.end());
    rh(r + 1) = columns.size();
  }
  ownedEntries_ = columns.size();
  for (LO r = nOwned; r < nRows; ++r) {  // each row's columns in the order its pattern message lists them
    forEachColumn(r, [&](LO u) { columns.push_back(toColHost(u)); });
    rh(r + 1) = columns.size();
  }
  // Where each received value goes (the message lists a row's columns in the sender's row order).
  for (size_t j = 0; j < received.size(); j += static_cast<size_t>(received[j + 1]) + 2) {
    const LO r = owned->getLocalElement(received[j]);
    for (GO k = 0; k < received[j + 1]; ++k) {
      const LO c = columnOf(received[j + 2 + k]);
      const auto at = std::lower_bound(columns.begin() + rh(r), columns.begin() + rh(r + 1), c);
      receivedAt_.push_back(static_cast<size_t>(at - columns.begin()));
    }
  }
  LocalMatrix::row_map_type::non_const_type rowPtr("q1PatternRows", static_cast<size_t>(nRows) + 1);
  LocalMatrix::index_type::non_const_type cols("q1PatternColumns", columns.size());
  Kokkos::deep_copy(rowPtr, rh);
  Kokkos::deep_copy(cols, Kokkos::View<const LO*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(columns.data(), columns.size()));
  rowPtr_ = rowPtr;
  cols_ = cols;
  Kokkos::View<LO*, DeviceType> toCol("toCol", nRows);
  Kokkos::deep_copy(toCol, toColHost);
  toCol_ = toCol;
  importer_ = Teuchos::rcp(new Tpetra::Import<LO, GO, Node>(owned_, columns_));
}

Q1Pattern::Fill Q1Pattern::begin() const {
  LocalMatrix::values_type values("q1PatternValues", cols_.extent(0));
  return {LocalMatrix("q1Matrix", static_cast<LO>(rowPtr_.extent(0) - 1), numColumns_, cols_.extent(0), values,
                      rowPtr_, cols_)};
}

RCP<CrsMatrix> Q1Pattern::end(Fill& f, const std::vector<char>& identityRows) const {
  const LO nOwned = static_cast<LO>(owned_->getNodeNumElements());
  auto values = Kokkos::create_mirror_view(f.local.values);
  Kokkos::deep_copy(values, f.local.values);
  const auto rh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), rowPtr_);
  const auto ch = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cols_);
  if (importer_) {  // the foreign rows' values to their owners, added in the order of the source ranks
    std::vector<double> send(static_cast<size_t>(sendOffsets_.back())), recv(static_cast<size_t>(recvOffsets_.back()));
    size_t at = 0;
    for (const LO r : sendRows_)
      for (auto k = rh(r); k < rh(r + 1); ++k) send[at++] = values(k);
    MPI_Alltoallv(send.data(), sendCounts_.data(), sendOffsets_.data(), MPI_DOUBLE, recv.data(), recvCounts_.data(),
                  recvOffsets_.data(), MPI_DOUBLE, core::rawMpiComm(*owned_->getComm()));
    for (size_t j = 0; j < recv.size(); ++j) values(receivedAt_[j]) += recv[j];
  }
  for (LO i = 0; i < nOwned; ++i)  // owned unknowns come first in the overlap order and the columns
    if (identityRows[i])
      for (auto k = rh(i); k < rh(i + 1); ++k)
        if (ch(k) == i) values(k) = 1.0;
  Kokkos::deep_copy(f.local.values, values);
  const std::pair<size_t, size_t> ownedRows(0, static_cast<size_t>(nOwned) + 1), ownedEntries(0, ownedEntries_);
  const LocalMatrix owned("q1Matrix", nOwned, static_cast<LO>(columns_->getNodeNumElements()), ownedEntries_,
                          Kokkos::subview(f.local.values, ownedEntries), Kokkos::subview(rowPtr_, ownedRows),
                          Kokkos::subview(cols_, ownedEntries));
  return Teuchos::rcp(new CrsMatrix(owned, owned_, columns_, owned_, owned_, importer_, Teuchos::null));
}

}  // namespace signorini::fem
