#include "signorini/fem/EntrySums.hpp"

#include <algorithm>
#include <limits>

#include <mpi.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Distributor.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::fem {

namespace {
struct Packed {
  long long row, column;
  double value;
};
}  // namespace

bool needEntrySums(const Comm& comm) { return core::reproducibleArithmetic() && (comm.getSize() > 1 || kAtomicScatter); }

std::vector<char> sharedRows(const Map& overlap, const Tpetra::Import<LO, GO, Node>& ownedToOverlap) {
  const size_t nOwned = ownedToOverlap.getSourceMap()->getNodeNumElements();
  SIGNORINI_ASSERT(ownedToOverlap.getNumSameIDs() == nOwned, "sharedRows: the owned rows must come first in the overlap map");
  std::vector<char> rows(overlap.getNodeNumElements(), 0);
  for (size_t i = nOwned; i < rows.size(); ++i) rows[i] = 1;
  for (const LO i : ownedToOverlap.getExportLIDs()) rows[i] = 1;
  return rows;
}

EntrySums::EntrySums(const Map& owned, const Map& overlap, const Tpetra::Import<LO, GO, Node>& ownedToOverlap,
                     const std::vector<Contribution>& contributions) {
  const LO nOwned = static_cast<LO>(owned.getNodeNumElements());
  const MPI_Comm comm = core::rawMpiComm(*owned.getComm());
  int size, rank;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  // Owner of every overlap row.
  std::vector<int> owner(overlap.getNodeNumElements(), rank);
  {  // the remote rows arrive from their owners in the distributor's order
    const auto remote = ownedToOverlap.getRemoteLIDs();
    const auto& distributor = ownedToOverlap.getDistributor();
    const auto from = distributor.getProcsFrom();
    const auto lengths = distributor.getLengthsFrom();
    size_t j = 0;
    for (size_t i = 0; i < distributor.getNumReceives(); ++i)
      for (size_t k = 0; k < lengths[i]; ++k) owner[remote[j++]] = from[i];
    SIGNORINI_ASSERT(j == static_cast<size_t>(remote.size()), "EntrySums: remote rows do not match the importer");
  }
  // The owned rows' contributions (row: the owned local id, which is the overlap one), with those
  // received from the other ranks (row: the global id until they are bucketed below).
  std::vector<Packed> mine;
  mine.reserve(contributions.size());
  std::vector<std::vector<Packed>> outgoing(size);
  for (const auto& c : contributions) {
    SIGNORINI_ASSERT(c.row >= 0 && static_cast<size_t>(c.row) < owner.size(), "EntrySums: row outside the overlap map");
    if (owner[c.row] == rank) {
      SIGNORINI_ASSERT(c.row < nOwned, "EntrySums: the owned rows must come first in the overlap map");
      mine.push_back({static_cast<long long>(c.row), static_cast<long long>(c.column), c.value});
    } else {
      outgoing[owner[c.row]].push_back(
          {static_cast<long long>(overlap.getGlobalElement(c.row)), static_cast<long long>(c.column), c.value});
    }
  }
  // The contributions in the one-rank order: by source rank (p4est's partition splits the
  // space-filling curve into consecutive pieces), each rank's in the order it made them.
  std::vector<std::pair<const Packed*, size_t>> pieces;  // (first, count) per source rank
  std::vector<Packed> received;
  if (size > 1) {
    std::vector<int> sendCounts(size), recvCounts(size), sendOffsets(size, 0), recvOffsets(size, 0);
    size_t total = 0;
    for (const auto& o : outgoing) total += o.size() * sizeof(Packed);
    SIGNORINI_ASSERT(total < static_cast<size_t>(std::numeric_limits<int>::max()),
                     "EntrySums: more than 2 GiB of contributions to send from one rank");
    for (int r = 0; r < size; ++r) sendCounts[r] = static_cast<int>(outgoing[r].size() * sizeof(Packed));
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm);
    std::vector<Packed> send;
    for (int r = 0; r < size; ++r) {
      if (r > 0) sendOffsets[r] = sendOffsets[r - 1] + sendCounts[r - 1];
      if (r > 0) recvOffsets[r] = recvOffsets[r - 1] + recvCounts[r - 1];
      send.insert(send.end(), outgoing[r].begin(), outgoing[r].end());
    }
    size_t receivedBytes = 0;
    for (int r = 0; r < size; ++r) receivedBytes += static_cast<size_t>(recvCounts[r]);
    SIGNORINI_ASSERT(receivedBytes < static_cast<size_t>(std::numeric_limits<int>::max()),
                     "EntrySums: more than 2 GiB of contributions to receive on one rank");
    received.resize(receivedBytes / sizeof(Packed));
    MPI_Alltoallv(send.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, received.data(), recvCounts.data(),
                  recvOffsets.data(), MPI_BYTE, comm);
    for (int r = 0; r < size; ++r)
      if (r == rank)
        pieces.emplace_back(mine.data(), mine.size());
      else
        pieces.emplace_back(received.data() + recvOffsets[r] / sizeof(Packed), recvCounts[r] / sizeof(Packed));
  } else {
    pieces.emplace_back(mine.data(), mine.size());
  }
  // Bucket by owned row, keeping that order; sort each row stably by column and add the runs of
  // one column in order.
  const size_t count = mine.size() + received.size();
  std::vector<size_t> start(nOwned + 1, 0);
  std::vector<LO> rowOf(count);
  {
    size_t i = 0;
    for (int r = 0; r < static_cast<int>(pieces.size()); ++r)
      for (size_t k = 0; k < pieces[r].second; ++k, ++i) {
        const Packed& c = pieces[r].first[k];
        rowOf[i] = r == rank || size == 1 ? static_cast<LO>(c.row) : owned.getLocalElement(c.row);
        SIGNORINI_ASSERT(rowOf[i] >= 0, "EntrySums: a contribution reached a rank that does not own its row");
        ++start[rowOf[i] + 1];
      }
  }
  for (LO r = 0; r < nOwned; ++r) start[r + 1] += start[r];
  std::vector<std::pair<GO, double>> sorted(count);
  {
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    size_t i = 0;
    for (const auto& [first, n] : pieces)
      for (size_t k = 0; k < n; ++k, ++i) sorted[fill[rowOf[i]]++] = {first[k].column, first[k].value};
  }
  rowStart_.assign(nOwned + 1, 0);
  column_.reserve(sorted.size());
  value_.reserve(sorted.size());
  for (LO r = 0; r < nOwned; ++r) {
    for (size_t i = start[r] + 1; i < start[r + 1]; ++i) {  // insertion sort: stable, rows are short
      const auto item = sorted[i];
      size_t j = i;
      for (; j > start[r] && sorted[j - 1].first > item.first; --j) sorted[j] = sorted[j - 1];
      sorted[j] = item;
    }
    for (size_t i = start[r]; i < start[r + 1];) {
      const GO column = sorted[i].first;
      double sum = 0.0;
      for (; i < start[r + 1] && sorted[i].first == column; ++i) sum += sorted[i].second;
      column_.push_back(column);
      value_.push_back(sum);
    }
    rowStart_[r + 1] = column_.size();
  }
}

double EntrySums::operator()(LO row, GO column) const {
  const auto begin = column_.begin() + rowStart_[row], end = column_.begin() + rowStart_[row + 1];
  const auto it = std::lower_bound(begin, end, column);
  return it != end && *it == column ? value_[it - column_.begin()] : 0.0;
}

void EntrySums::writeInto(CrsMatrix& A, const std::vector<char>& keepRows) const {
  const auto local = A.getLocalMatrixDevice();
  const auto colMap = A.getColMap();
  SIGNORINI_ASSERT(static_cast<size_t>(local.numRows()) + 1 == rowStart_.size(), "EntrySums: rows do not match");
  for (LO r = 0; r < local.numRows(); ++r) {
    if (!keepRows.empty() && keepRows[r]) continue;
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      local.values(k) = (*this)(r, colMap->getGlobalElement(local.graph.entries(k)));
  }
}

void EntrySums::writeInto(Vector& out, bool accumulate, const std::vector<char>& shared, const Vector* localSums) const {
  auto h = out.getLocalViewHost(Tpetra::Access::ReadWrite);
  SIGNORINI_ASSERT(h.extent(0) + 1 == rowStart_.size(), "EntrySums: rows do not match");
  const bool all = shared.empty();
  SIGNORINI_ASSERT(all || (localSums && localSums->getLocalLength() >= h.extent(0) && shared.size() >= h.extent(0)),
                   "EntrySums: the local sums do not cover the owned rows");
  decltype(localSums->getLocalViewHost(Tpetra::Access::ReadOnly)) local;
  if (!all) local = localSums->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (size_t r = 0; r < h.extent(0); ++r) {
    const double s = all || shared[r] ? (*this)(static_cast<LO>(r), 0) : local(r, 0);
    h(r, 0) = accumulate ? h(r, 0) + s : s;
  }
}

}  // namespace signorini::fem
