#include "signorini/core/Interrupt.hpp"

#include <limits.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>
#include <utility>

#include <Teuchos_CommHelpers.hpp>

namespace signorini::core {
namespace {

volatile std::sig_atomic_t received = 0;
volatile std::sig_atomic_t announce = 0;  ///< this process prints the notice (rank 0)
timespec firstAt{};

// The paths of RemovedOnSignal: a slot's kind is published after its path is written, so the
// handler (on any thread) reads only complete paths.
constexpr int kSlots = 128;
enum SlotKind : int { kFree = 0, kFile = 1, kDirectory = 2 };
char slotPath[kSlots][PATH_MAX];
std::atomic<int> slotKind[kSlots];
long slotOrder[kSlots];  // registration order: directories are removed newest first
long registrations = 0;
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots");

/// Removes the registered paths (async-signal-safe: unlink and rmdir only).
void removeRegisteredPaths() {
  bool removed[kSlots] = {};
  for (int i = 0; i < kSlots; ++i)
    if (slotKind[i].load() == kFile) ::unlink(slotPath[i]);
  for (;;) {
    int newest = -1;
    for (int i = 0; i < kSlots; ++i)
      if (!removed[i] && slotKind[i].load() == kDirectory && (newest < 0 || slotOrder[i] > slotOrder[newest])) newest = i;
    if (newest < 0) return;
    removed[newest] = true;
    ::rmdir(slotPath[newest]);
  }
}

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
    removeRegisteredPaths();
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

void throwIfSignalled() {
  const int signal = received;
  if (signal && signal != SIGPIPE) throw Interrupted(signal);
}

RemovedOnSignal::RemovedOnSignal(const std::string& path, bool directory) {
  if (path.empty() || path.size() >= PATH_MAX) return;
  for (int i = 0; i < kSlots; ++i)
    if (slotKind[i].load() == kFree) {
      std::memcpy(slotPath[i], path.c_str(), path.size() + 1);
      slotOrder[i] = ++registrations;
      slotKind[i].store(directory ? kDirectory : kFile);
      slot_ = i;
      return;
    }
}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_ >= 0) slotKind[slot_].store(kFree);
}

RemovedOnSignal::RemovedOnSignal(RemovedOnSignal&& other) noexcept : slot_(std::exchange(other.slot_, -1)) {}

RemovedOnSignal& RemovedOnSignal::operator=(RemovedOnSignal&& other) noexcept {
  if (this != &other) {
    if (slot_ >= 0) slotKind[slot_].store(kFree);
    slot_ = std::exchange(other.slot_, -1);
  }
  return *this;
}

}  // namespace signorini::core
