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

// The paths of RemovedOnSignal, in chunks of slots that are never freed, as the path copies are
// not (the handler may read a slot on another thread at any time): a slot's path is published
// before its kind, and its kind cleared before it is reused.
constexpr int kChunkSlots = 256;
enum SlotKind : int { kFree = 0, kFile = 1, kDirectory = 2 };
struct Chunk {
  RemovedOnSignal::Slot slots[kChunkSlots];
  std::atomic<Chunk*> next{nullptr};
};
Chunk firstChunk;
long registrations = 0;             // main thread only
std::atomic<int> removalPaused{0};  // SignalRemovalPause
std::atomic<int> removalDone{0};    // the first signal's removal ran (two signals at once: one removal)
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<const char*>::is_always_lock_free &&
                  std::atomic<Chunk*>::is_always_lock_free,
              "the signal handler reads the slots");

/// Removes the registered paths: files first, then directories, the newest first
/// (async-signal-safe: lock-free atomics, unlink and rmdir only).
void removeRegisteredPaths() {
  if (removalPaused.load() || removalDone.exchange(1)) return;
  for (Chunk* c = &firstChunk; c; c = c->next.load())
    for (auto& slot : c->slots)
      if (slot.kind.load() == kFile) ::unlink(slot.path.load());
  for (long below = LONG_MAX;;) {
    const char* newest = nullptr;
    long newestOrder = 0;
    for (Chunk* c = &firstChunk; c; c = c->next.load())
      for (auto& slot : c->slots) {
        const long order = slot.order.load();
        if (slot.kind.load() == kDirectory && order < below && order > newestOrder) newest = slot.path.load(), newestOrder = order;
      }
    if (!newest) return;
    ::rmdir(newest);
    below = newestOrder;
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

int stopSignal() {
  const int signal = received;
  return signal == SIGPIPE ? 0 : signal;
}

void throwIfSignalled() {
  if (const int signal = stopSignal()) throw Interrupted(signal);
}

RemovedOnSignal::RemovedOnSignal(const std::string& path, bool directory) {
  if (path.empty()) return;
  for (Chunk* c = &firstChunk;; c = c->next.load()) {
    for (auto& slot : c->slots) {
      if (slot.kind.load() != kFree) continue;
      const char* previous = slot.path.load();
      if (!previous || path != previous) slot.path.store(strdup(path.c_str()));  // never freed (see above)
      slot.order.store(++registrations);
      slot.kind.store(directory ? kDirectory : kFile);
      slot_ = &slot;
      return;
    }
    if (!c->next.load()) c->next.store(new Chunk);  // never freed
  }
}

RemovedOnSignal::~RemovedOnSignal() {
  if (slot_) slot_->kind.store(kFree);
}

RemovedOnSignal::RemovedOnSignal(RemovedOnSignal&& other) noexcept : slot_(std::exchange(other.slot_, nullptr)) {}

RemovedOnSignal& RemovedOnSignal::operator=(RemovedOnSignal&& other) noexcept {
  if (this != &other) {
    if (slot_) slot_->kind.store(kFree);
    slot_ = std::exchange(other.slot_, nullptr);
  }
  return *this;
}

SignalRemovalPause::SignalRemovalPause() { removalPaused.store(1); }

SignalRemovalPause::~SignalRemovalPause() { removalPaused.store(0); }

}  // namespace signorini::core
