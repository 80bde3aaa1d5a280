#pragma once
/// \file Interrupt.hpp
/// Ctrl-C (SIGINT), SIGTERM, SIGHUP and SIGPIPE end a run cleanly: the handler only records the
/// signal, the time stepper checks at every step (and the runs before their files get their
/// final names) on all ranks together and throws Interrupted, and the run's output staging
/// removes its files on the way out (io::OutputStaging). The paths registered with
/// RemovedOnSignal (the run's ".part" files and the folders it made; not its lock) go at once, in
/// the handler: mpirun kills its ranks about a second after it passes a Ctrl-C on as SIGTERM, which a
/// long time step outlasts. A second SIGINT, SIGTERM or SIGHUP ends the
/// process at once (the default action), except a copy of the first within a second (a signal to
/// the process and to its group), which counts as one; SIGPIPE never ends it at once.
#include <atomic>
#include <stdexcept>
#include <string>

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
/// The SIGINT, SIGTERM or SIGHUP this process received, 0 if none (not collective).
int stopSignal();
/// Throws Interrupted if stopSignal() is not 0 (not collective): for code that has just created a
/// file, which the signal's handler may have run too early to remove (it removes the file, then
/// calls this). Rank 0's file writing runs in core::onRootCollectively, which passes the exception
/// on to every rank.
void throwIfSignalled();

/// While it lives, \p path (a file, or a directory removed if empty) is removed by the first
/// SIGINT, SIGTERM or SIGHUP in the signal handler itself (files first, then directories, the
/// newest first), so that a process killed soon after the signal (mpirun) leaves nothing; the
/// normal path removes it too. Registration only; the destructor does not remove the path. The
/// main thread registers; any number of paths (their copies stay allocated until the process
/// ends, a few bytes per file a run writes).
class RemovedOnSignal {
 public:
  /// A registration (internal: kind, path and order, read by the signal handler).
  struct Slot {
    std::atomic<int> kind{0};
    std::atomic<const char*> path{nullptr};
    std::atomic<long> order{0};
  };

  RemovedOnSignal() = default;
  explicit RemovedOnSignal(const std::string& path, bool directory = false);
  ~RemovedOnSignal();
  RemovedOnSignal(RemovedOnSignal&& other) noexcept;
  RemovedOnSignal& operator=(RemovedOnSignal&& other) noexcept;
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

 private:
  Slot* slot_ = nullptr;
};

/// While it lives, a signal's handler removes nothing: for the commit of a run's files, where
/// removing the files not renamed yet would make the commit remove the renamed ones too, and with
/// them the earlier run's results they replaced. (The run then keeps its files and says so.)
class SignalRemovalPause {
 public:
  SignalRemovalPause();
  ~SignalRemovalPause();
  SignalRemovalPause(const SignalRemovalPause&) = delete;
  SignalRemovalPause& operator=(const SignalRemovalPause&) = delete;
};

}  // namespace signorini::core
