#pragma once
/// \file Interrupt.hpp
/// Ctrl-C (SIGINT) and SIGTERM end a run cleanly: the handler only records the signal, the time
/// stepper checks at every step on all ranks together and throws Interrupted, and the run's
/// output staging removes its files on the way out (io::OutputStaging). A second signal ends the
/// process at once (the default action).
#include <stdexcept>

#include "Types.hpp"

namespace signorini::core {

/// Thrown on every rank when a rank received SIGINT or SIGTERM.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Installs the handlers for SIGINT and SIGTERM (once, in the driver's main).
void installInterruptHandlers();
/// Throws Interrupted on every rank if any rank of \p comm received a signal. Collective.
void throwIfInterrupted(const Comm& comm);

}  // namespace signorini::core
