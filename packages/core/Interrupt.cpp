#include "Interrupt.hpp"

#include <csignal>
#include <cstring>
#include <string>

#include <Teuchos_CommHelpers.hpp>

namespace signorini::core {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void recordSignal(int signal) {
  received = signal;
  std::signal(signal, SIG_DFL);  // a second one ends the process at once
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error("interrupted by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")"),
      signal_(signal) {}

void installInterruptHandlers() {
  std::signal(SIGINT, recordSignal);
  std::signal(SIGTERM, recordSignal);
}

void throwIfInterrupted(const Comm& comm) {
  const int local = received;
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  if (global) throw Interrupted(global);
}

}  // namespace signorini::core
