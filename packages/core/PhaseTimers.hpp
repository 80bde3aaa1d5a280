#pragma once
/// \file PhaseTimers.hpp
/// Wall-clock accumulators per named phase (assembly, preconditioner setup, contact, output, ...)
/// and rank-0 logging. Times in seconds.
#include <chrono>
#include <map>
#include <ostream>
#include <string>
#include <utility>

namespace signorini::core {

/// Phases are exclusive: a scope opened inside another one pauses it, so that every second is
/// booked to one phase only (the innermost), and the phases of a run add up to at most its wall time.
class PhaseTimers {
 public:
  using Clock = std::chrono::steady_clock;  ///< wall clock (monotonic)
  /// RAII: adds the time of its lifetime, less that of scopes opened inside it, to the phase.
  class Scope {
   public:
    /// Opens a scope of \p phase on \p t (kept by reference: \p t must outlive the scope), pausing the innermost one.
    Scope(PhaseTimers& t, std::string phase) : t_(t), phase_(std::move(phase)), enclosing_(t.innermost_) {
      start_ = Clock::now();
      if (enclosing_) enclosing_->book(start_);
      t_.innermost_ = this;
    }
    ~Scope() {
      const auto now = Clock::now();
      book(now);
      t_.innermost_ = enclosing_;
      if (enclosing_) enclosing_->start_ = now;
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    void book(Clock::time_point now) { t_.add(phase_, std::chrono::duration<double>(now - start_).count()); }
    PhaseTimers& t_;
    std::string phase_;
    Scope* enclosing_;
    Clock::time_point start_;
  };

  /// A Scope of \p phase on this object.
  Scope scope(const std::string& phase) { return Scope(*this, phase); }
  /// Adds \p seconds [s] to \p phase.
  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  /// The seconds [s] booked to \p phase (0 if none).
  double seconds(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  /// Seconds [s] per phase, by name.
  const std::map<std::string, double>& all() const { return seconds_; }
  /// Forgets all phases (open scopes keep booking to this object).
  void clear() { seconds_.clear(); }

 private:
  std::map<std::string, double> seconds_;
  Scope* innermost_ = nullptr;
};

/// A stream that prints on rank 0 only.
std::ostream& rootOut(int rank);

}  // namespace signorini::core
