#pragma once
/// \file SameEstimate.hpp
/// The estimator tests' check that two estimates of one discrete state agree (e.g. the same problem
/// stated in two units of force).
#include <algorithm>

#include <gtest/gtest.h>

#include "signorini/estimate/EstimatorTools.hpp"

namespace signorini::test {

/// eta_*, s0 and s1 of \p b equal those of \p a to 1e-12 (relative), every cell indicator to 1e-8 of
/// the largest: the cell residuals of the step equation (rho (p - u), beta k^2 f and beta k^2 div
/// sigma) cancel in part, which shows at 1e-9. s0 and s1 of \p a must be positive (exercised).
inline void expectSameEstimate(const estimate::EstimatorResult& a, const estimate::EstimatorResult& b) {
  EXPECT_GT(a.s0, 0.0);
  EXPECT_GT(a.s1, 0.0);
  EXPECT_NEAR(b.etaStar, a.etaStar, 1e-12 * a.etaStar);
  EXPECT_NEAR(b.s0, a.s0, 1e-12 * a.s0);
  EXPECT_NEAR(b.s1, a.s1, 1e-12 * a.s1);
  ASSERT_EQ(b.cellIndicator.size(), a.cellIndicator.size());
  const double largest = *std::max_element(a.cellIndicator.begin(), a.cellIndicator.end());
  for (size_t e = 0; e < a.cellIndicator.size(); ++e)
    EXPECT_NEAR(b.cellIndicator[e], a.cellIndicator[e], 1e-8 * largest) << "cell " << e;
}

}  // namespace signorini::test
