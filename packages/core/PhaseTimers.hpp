#pragma once
/// \file PhaseTimers.hpp
/// Wall-clock accumulators per named phase (assembly, preconditioner setup, contact, output, ...)
/// and rank-0 logging. Times in seconds.
#include <chrono>
#include <map>
#include <ostream>
#include <string>

namespace signorini::core {

class PhaseTimers {
 public:
  using Clock = std::chrono::steady_clock;
  /// RAII: adds the time of its lifetime to the phase.
  class Scope {
   public:
    Scope(PhaseTimers& t, std::string phase) : t_(t), phase_(std::move(phase)), start_(Clock::now()) {}
    ~Scope() { t_.add(phase_, std::chrono::duration<double>(Clock::now() - start_).count()); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseTimers& t_;
    std::string phase_;
    Clock::time_point start_;
  };

  Scope scope(const std::string& phase) { return Scope(*this, phase); }
  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  double seconds(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  const std::map<std::string, double>& all() const { return seconds_; }
  void clear() { seconds_.clear(); }

 private:
  std::map<std::string, double> seconds_;
};

/// A stream that prints on rank 0 only.
std::ostream& rootOut(int rank);

}  // namespace signorini::core
