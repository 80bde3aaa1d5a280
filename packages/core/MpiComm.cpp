#include "MpiComm.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include "Error.hpp"

namespace signorini::core {

MPI_Comm rawMpiComm(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  SIGNORINI_ASSERT(mpi != nullptr, "signorini needs an MPI communicator");
  return *mpi->getRawMpiComm();
}

}  // namespace signorini::core
