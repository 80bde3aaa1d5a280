#include "signorini/core/MpiComm.hpp"

#include <chrono>
#include <iostream>
#include <string>
#include <thread>

#include <unistd.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/Interrupt.hpp"

namespace signorini::core {

MPI_Comm rawMpiComm(const Comm& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  SIGNORINI_ASSERT(mpi != nullptr, "signorini needs an MPI communicator");
  return *mpi->getRawMpiComm();
}

NodeMemory nodeMemory(const Comm& comm) {
  MPI_Comm node;
  MPI_Comm_split_type(rawMpiComm(comm), MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranksOnNode = 1;
  MPI_Comm_size(node, &ranksOnNode);
  MPI_Comm_free(&node);
  return {static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE)), ranksOnNode};
}

double memoryPerRank(const Comm& comm) {
  const NodeMemory node = nodeMemory(comm);
  return node.bytes / node.ranksOnNode;
}

namespace {
/// The message of the lowest rank with a non-empty \p localMessage, on every rank ("" if none). Collective.
std::string firstMessage(const Comm& comm, const std::string& localMessage) {
  MPI_Comm c = rawMpiComm(comm);
  int rank = 0, size = 1;
  MPI_Comm_rank(c, &rank);
  MPI_Comm_size(c, &size);
  int mine = localMessage.empty() ? size : rank, first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, c);
  if (first == size) return "";
  std::string message = rank == first ? localMessage : std::string();
  int length = static_cast<int>(message.size());
  MPI_Bcast(&length, 1, MPI_INT, first, c);
  message.resize(static_cast<size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, first, c);
  return message;
}
}  // namespace

void throwFirstUserError(const Comm& comm, const std::string& localMessage) {
  const std::string message = firstMessage(comm, localMessage);
  if (!message.empty()) throw UserError(message);
}

void throwFirstSolverError(const Comm& comm, const std::string& localMessage) {
  const std::string message = firstMessage(comm, localMessage);
  if (!message.empty()) throw SolverError(message);
}

void throwFirstUserErrorOrAbort(const Comm& comm, const std::string& localMessage, double seconds) {
  MPI_Comm c = rawMpiComm(comm);
  int size = 1;
  MPI_Comm_size(c, &size);
  if (size > 1) {
    // Only a rank with a message can be left alone here: the others are then still inside the library.
    int mine = localMessage.empty() ? 0 : 1, any = 0, done = 0;
    MPI_Request request;
    MPI_Iallreduce(&mine, &any, 1, MPI_INT, MPI_MAX, c, &request);
    if (!mine) {
      MPI_Wait(&request, MPI_STATUS_IGNORE);  // the usual case: no polling
    } else {
      const auto start = std::chrono::steady_clock::now();
      for (MPI_Test(&request, &done, MPI_STATUS_IGNORE); !done; MPI_Test(&request, &done, MPI_STATUS_IGNORE)) {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) {
          std::cerr << "signorini: error: " << localMessage
                    << " (on this rank only; the other ranks wait inside the library: ending them)" << std::endl;
          MPI_Abort(c, 1);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    if (!any) return;
  }
  throwFirstUserError(comm, localMessage);
}

void onRootCollectively(const Comm& comm, const std::function<void()>& action) {
  MPI_Comm c = rawMpiComm(comm);
  int rank = 0;
  MPI_Comm_rank(c, &rank);
  int kind = 0;  // 0: done, 1: user error, 2: another exception, 3: solver error, 4 + signal: interrupted
  std::string message;
  if (rank == 0) {
    try {
      action();
    } catch (const Interrupted& e) {
      kind = 4 + e.signal();
    } catch (const UserError& e) {
      kind = 1, message = e.what();
    } catch (const SolverError& e) {
      kind = 3, message = e.what();
    } catch (const std::exception& e) {
      kind = 2, message = e.what();
    }
  }
  MPI_Bcast(&kind, 1, MPI_INT, 0, c);
  if (kind == 0) return;
  if (kind >= 4) throw Interrupted(kind - 4);
  int length = static_cast<int>(message.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, c);
  message.resize(static_cast<size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, 0, c);
  if (kind == 1) throw UserError(message);
  if (kind == 3) throw SolverError(message);
  throw std::runtime_error(message);
}

}  // namespace signorini::core
