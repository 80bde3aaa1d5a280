#pragma once
/// \file MpiComm.hpp
/// The raw MPI communicator behind a Teuchos communicator (p4est and a few collectives need it).
#include <functional>
#include <string>
#include <vector>

#include <mpi.h>

#include "signorini/core/Types.hpp"

namespace signorini::core {

/// Throws std::logic_error if \p comm is not an MPI communicator.
MPI_Comm rawMpiComm(const Comm& comm);

/// Runs \p action on rank 0 only (output files are written there) and makes its failure every
/// rank's: a core::UserError, core::SolverError or core::Interrupted thrown by \p action is rethrown as such on every
/// rank with rank 0's message, any other std::exception as std::runtime_error. Collective: call it on every rank.
void onRootCollectively(const Comm& comm, const std::function<void()>& action);

/// Makes a user error found on some ranks every rank's: if any rank passes a non-empty \p localMessage,
/// every rank throws core::UserError with the message of the lowest such rank. Collective.
void throwFirstUserError(const Comm& comm, const std::string& localMessage);
/// The same for a core::SolverError (a failure of work that every rank does for itself, such as
/// factoring its own copy of a matrix, which may run out of memory on some ranks only). Collective.
void throwFirstSolverError(const Comm& comm, const std::string& localMessage);

/// throwFirstUserError() after a call into a library whose collectives a rank may have left by an
/// exception while the others wait in them (MueLu's set-up failing on some ranks only): a rank with
/// a message waits at most \p seconds for the others; if they do not come, it prints its message
/// to stderr ("signorini: error: ...") and ends every rank with MPI_Abort (exit status 1; the
/// run's .part files stay behind, and the next run in the folder removes them). Collective.
void throwFirstUserErrorOrAbort(const Comm& comm, const std::string& localMessage, double seconds = 20.0);

/// This node's physical memory and the ranks of a communicator on it (MPI_COMM_TYPE_SHARED).
struct NodeMemory {
  double bytes;     ///< physical memory of the node [bytes]
  int ranksOnNode;  ///< ranks of the communicator on the node
};
/// This rank's node: its memory and the ranks of \p comm on it. Collective.
NodeMemory nodeMemory(const Comm& comm);
/// The physical memory of this node [bytes] divided by the ranks of \p comm on it
/// (MPI_COMM_TYPE_SHARED): what one rank can use. Collective.
double memoryPerRank(const Comm& comm);

/// The MPI datatype of T (int, long long, double, char).
template <class T>
MPI_Datatype mpiType();
/// MPI_INT.
template <>
inline MPI_Datatype mpiType<int>() { return MPI_INT; }
/// MPI_LONG_LONG.
template <>
inline MPI_Datatype mpiType<long long>() { return MPI_LONG_LONG; }
/// MPI_DOUBLE.
template <>
inline MPI_Datatype mpiType<double>() { return MPI_DOUBLE; }
/// MPI_CHAR.
template <>
inline MPI_Datatype mpiType<char>() { return MPI_CHAR; }

/// Concatenation, in rank order, of every rank's \p mine (variable lengths), on every rank.
template <class T>
std::vector<T> allGatherv(MPI_Comm comm, const std::vector<T>& mine) {
  int n = static_cast<int>(mine.size()), size;
  MPI_Comm_size(comm, &size);
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<T> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), n, mpiType<T>(), all.data(), counts.data(), offsets.data(), mpiType<T>(), comm);
  return all;
}

/// What a rank receives in exchange(): the values of all ranks, by source rank, rank r's at
/// [offsets[r], offsets[r + 1]).
template <class T>
struct Exchanged {
  std::vector<T> values;     ///< the received values, by source rank
  std::vector<int> offsets;  ///< one entry per rank and the end: rank r's values start at offsets[r]
};

/// All-to-all exchange: send[sendOffsets[r] .. sendOffsets[r + 1]) goes to rank r (\p sendOffsets:
/// one entry per rank and the end, in values). Collective: the counts first, then the values.
template <class T>
Exchanged<T> exchange(MPI_Comm comm, const std::vector<T>& send, const std::vector<int>& sendOffsets) {
  const int size = static_cast<int>(sendOffsets.size()) - 1;
  std::vector<int> sendCounts(size), recvCounts(size);
  for (int r = 0; r < size; ++r) sendCounts[r] = sendOffsets[r + 1] - sendOffsets[r];
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm);
  Exchanged<T> got;
  got.offsets.assign(size + 1, 0);
  for (int r = 0; r < size; ++r) got.offsets[r + 1] = got.offsets[r] + recvCounts[r];
  got.values.resize(static_cast<size_t>(got.offsets[size]));
  MPI_Alltoallv(send.data(), sendCounts.data(), sendOffsets.data(), mpiType<T>(), got.values.data(), recvCounts.data(),
                got.offsets.data(), mpiType<T>(), comm);
  return got;
}

}  // namespace signorini::core
