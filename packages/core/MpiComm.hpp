#pragma once
/// \file MpiComm.hpp
/// The raw MPI communicator behind a Teuchos communicator (p4est and a few collectives need it).
#include <functional>
#include <string>
#include <vector>

#include <mpi.h>

#include "Types.hpp"

namespace signorini::core {

/// Throws std::logic_error if \p comm is not an MPI communicator.
MPI_Comm rawMpiComm(const Comm& comm);

/// Runs \p action on rank 0 only (output files are written there) and makes its failure every
/// rank's: a core::UserError thrown by \p action is rethrown on every rank with rank 0's message,
/// any other std::exception as std::runtime_error. Collective: call it on every rank.
void onRootCollectively(const Comm& comm, const std::function<void()>& action);

/// Makes a user error found on some ranks every rank's: if any rank passes a non-empty \p localMessage,
/// every rank throws core::UserError with the message of the lowest such rank. Collective.
void throwFirstUserError(const Comm& comm, const std::string& localMessage);

/// The physical memory of this node [bytes] divided by the ranks of \p comm on it
/// (MPI_COMM_TYPE_SHARED): what one rank can use. Collective.
double memoryPerRank(const Comm& comm);

/// The MPI datatype of T (int, long long, double, char).
template <class T>
MPI_Datatype mpiType();
template <>
inline MPI_Datatype mpiType<int>() { return MPI_INT; }
template <>
inline MPI_Datatype mpiType<long long>() { return MPI_LONG_LONG; }
template <>
inline MPI_Datatype mpiType<double>() { return MPI_DOUBLE; }
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

}  // namespace signorini::core
