#pragma once
/// \file MpiComm.hpp
/// The raw MPI communicator behind a Teuchos communicator (p4est and a few collectives need it).
#include <mpi.h>

#include "Types.hpp"

namespace signorini::core {

/// Throws std::logic_error if \p comm is not an MPI communicator.
MPI_Comm rawMpiComm(const Comm& comm);

}  // namespace signorini::core
