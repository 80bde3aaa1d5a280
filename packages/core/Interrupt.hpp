#pragma once
/// \file Interrupt.hpp
/// Ctrl-C (SIGINT), SIGTERM, SIGHUP and SIGPIPE end a run cleanly: the handler only records the
/// signal, the time stepper checks at every step (and the runs before their files get their
/// final names) on all ranks together and throws Interrupted, and the run's output staging
/// removes its files on the way out (io::OutputStaging). A second SIGINT, SIGTERM or SIGHUP ends the
/// process at once (the default action), except a copy of the first within a second (a signal to
/// the process and to its group), which counts as one; SIGPIPE never ends it at once.
#include <stdexcept>

#include "signorini/core/Types.hpp"

namespace signorini::core {

/// Thrown on every rank when a rank received SIGINT, SIGTERM, SIGHUP or SIGPIPE.
class Interrupted : public std::runtime_error {
 public:
  /// The message names \p signal ("interrupted by signal 2 (Interrupt)").
  explicit Interrupted(int signal);
  /// The signal number (throwIfInterrupted(): the largest over the ranks that received one).
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Installs the handlers (once, in the driver's main); \p printNotice (rank 0) prints a line on
/// stderr when the first signal arrives.
void installInterruptHandlers(bool printNotice);
/// Throws Interrupted on every rank if any rank of \p comm received a signal. Collective.
void throwIfInterrupted(const Comm& comm);

}  // namespace signorini::core
