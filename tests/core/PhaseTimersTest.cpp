// PhaseTimers: a scope opened inside another books its time to its own phase only, so the phases
// partition the time they cover (they used to overlap: the outer phase counted the inner one too).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "signorini/core/PhaseTimers.hpp"

using signorini::core::PhaseTimers;

TEST(PhaseTimers, NestedScopesBookEverySecondOnce) {
  using namespace std::chrono_literals;
  PhaseTimers timers;
  const auto start = PhaseTimers::Clock::now();
  {
    auto outer = timers.scope("outer");
    std::this_thread::sleep_for(10ms);
    {
      auto inner = timers.scope("inner");
      std::this_thread::sleep_for(30ms);
      {
        auto again = timers.scope("outer");  // the same phase nested: still booked once
        std::this_thread::sleep_for(5ms);
      }
    }
    std::this_thread::sleep_for(10ms);
  }
  const double total = std::chrono::duration<double>(PhaseTimers::Clock::now() - start).count();
  const double outer = timers.seconds("outer"), inner = timers.seconds("inner");
  EXPECT_GE(inner, 0.030);  // its own sleep, the nested scope's 5 ms excluded below
  EXPECT_GE(outer, 0.025);  // 10 + 5 + 10 ms
  EXPECT_LE(outer + inner, total);
  // The inner phase's 30 ms are not in the outer one (which would then exceed total - 30 ms).
  EXPECT_LE(outer, total - 0.030);
}
