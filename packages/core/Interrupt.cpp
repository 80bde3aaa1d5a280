#include "signorini/core/Interrupt.hpp"

#include <time.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <string>

#include <Teuchos_CommHelpers.hpp>

namespace signorini::core {
namespace {

volatile std::sig_atomic_t received = 0;
volatile std::sig_atomic_t announce = 0;  ///< this process prints the notice (rank 0)
timespec firstAt{};

double secondsSince(const timespec& t) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return static_cast<double>(now.tv_sec - t.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec - t.tv_nsec);
}

extern "C" void recordSignal(int signal) {
  if (signal == SIGPIPE) {  // stdout or stderr is gone: stop cleanly, never at once
    if (!received) received = signal;
    return;
  }
  if (!received || received == SIGPIPE) {  // the first request of the user (or of a signal sender)
    received = signal;
    clock_gettime(CLOCK_MONOTONIC, &firstAt);
    if (announce) {
      static const char notice[] =
          "\nsignorini: stopping at the next time step; the run removes its files unless they are written "
          "already (signal again: stop at once)\n";
      [[maybe_unused]] const auto written = ::write(STDERR_FILENO, notice, sizeof notice - 1);
    }
    return;
  }
  // A copy within a second is the same request (timeout(1) and shells signal the process and its
  // group); a later one ends the process at once.
  if (received == signal && secondsSince(firstAt) < 1.0) return;
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error("interrupted by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")"),
      signal_(signal) {}

void installInterruptHandlers(bool printNotice) {
  announce = printNotice;
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(signal, recordSignal);
}

void throwIfInterrupted(const Comm& comm) {
  const int local = received;
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  if (global) throw Interrupted(global);
}

}  // namespace signorini::core
