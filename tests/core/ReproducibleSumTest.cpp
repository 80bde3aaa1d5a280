// Reproducible global sums (core::reproducibleSums): the bits of a sum depend only on the multiset
// of all ranks' terms. Every test distributes one global list of terms over the ranks in several
// ways (contiguous blocks, round robin, everything on one rank, each rank's terms reversed) and
// requires bitwise equal results; the terms span 30 orders of magnitude with heavy cancellation, so
// an ordinary sum differs between those distributions (checked as the control).
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>

#include "signorini/core/ReproducibleSum.hpp"

namespace {

using signorini::core::reproducibleSum;
using signorini::core::reproducibleSums;

std::vector<double> hardTerms(std::size_t n, unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-15.0, 15.0);
  std::vector<double> t(n);
  for (auto& v : t) v = unit(gen) * std::pow(10.0, exponent(gen));
  return t;
}

/// The terms of this rank under distribution \p how of the global list.
std::vector<double> share(const std::vector<double>& all, int how, int rank, int size) {
  std::vector<double> mine;
  const std::size_t n = all.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool take = how == 0   ? static_cast<int>(i * size / n) == rank     // blocks
                      : how == 1 ? static_cast<int>(i % size) == rank         // round robin
                      : how == 2 ? rank == size - 1                           // all on the last rank
                                 : static_cast<int>((n - 1 - i) * size / n) == rank;  // blocks, reversed
    if (take) mine.push_back(all[i]);
  }
  if (how == 3) std::reverse(mine.begin(), mine.end());
  return mine;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ReproducibleSum, SameBitsForEveryDistributionAndOrderOfTheTerms) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto all = hardTerms(20000, 7);
  std::vector<double> results, plain;
  for (int how = 0; how < 4; ++how) {
    const auto mine = share(all, how, comm->getRank(), comm->getSize());
    results.push_back(reproducibleSum(*comm, mine.size(), mine.data()));
    double local = 0, global = 0;
    for (double v : mine) local += v;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    plain.push_back(global);
  }
  for (int how = 1; how < 4; ++how) EXPECT_TRUE(sameBits(results[0], results[how])) << results[0] << " " << results[how];
  // Control: the ordinary sums of the same terms differ between the distributions.
  bool plainDiffers = false;
  for (int how = 1; how < 4; ++how) plainDiffers = plainDiffers || !sameBits(plain[0], plain[how]);
  EXPECT_TRUE(plainDiffers);
  // Accuracy: the long double reference has errors up to about n 2^-64 max|t| = 1e-15 max|t|; an
  // ordinary double sum may be off by n 2^-53 max|t| = 2e-12 max|t|.
  long double exact = 0;
  double largest = 0;
  for (double v : all) exact += v, largest = std::max(largest, std::fabs(v));
  EXPECT_LE(std::fabs(static_cast<long double>(results[0]) - exact), 1e-14L * largest);
}

TEST(ReproducibleSum, ExactWhenCancellationLeavesSmallTerms) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<double> all;
  for (int i = 1; i <= 500; ++i) all.push_back(1e16 * i / 7.0), all.push_back(-1e16 * i / 7.0);
  all.push_back(1.0);
  all.push_back(3.0);
  std::mt19937 gen(3);
  std::shuffle(all.begin(), all.end(), gen);
  for (int how = 0; how < 4; ++how) {
    const auto mine = share(all, how, comm->getRank(), comm->getSize());
    EXPECT_EQ(reproducibleSum(*comm, mine.size(), mine.data()), 4.0) << "distribution " << how;
  }
}

TEST(ReproducibleSum, SeveralSumsAtOnceEqualSingleSums) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto x = hardTerms(5000, 11), y = hardTerms(5000, 12);
  const auto mx = share(x, 1, comm->getRank(), comm->getSize()), my = share(y, 1, comm->getRank(), comm->getSize());
  double both[3];
  reproducibleSums(
      *comm, 3, mx.size(),
      [&](std::size_t i, double* t) {
        t[0] = mx[i];
        t[1] = my[i];
        t[2] = mx[i] * my[i];
      },
      both);
  std::vector<double> products(mx.size());
  for (std::size_t i = 0; i < mx.size(); ++i) products[i] = mx[i] * my[i];
  EXPECT_TRUE(sameBits(both[0], reproducibleSum(*comm, mx.size(), mx.data())));
  EXPECT_TRUE(sameBits(both[1], reproducibleSum(*comm, my.size(), my.data())));
  EXPECT_TRUE(sameBits(both[2], reproducibleSum(*comm, products.size(), products.data())));
}

TEST(ReproducibleSum, GivenLargestTermsGiveTheBitsOfTheTwoPassSums) {
  // A caller that found each sum's largest local |term| itself (the Jacobi CG, in its update loop)
  // gets the two-pass sums' bits, with and without a known term count, and on a rank without terms.
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto x = hardTerms(6000, 21), y = hardTerms(6000, 22);
  for (int how = 0; how < 4; ++how) {
    const auto mx = share(x, how, comm->getRank(), comm->getSize()), my = share(y, how, comm->getRank(), comm->getSize());
    auto terms = [&](std::size_t i, double* t) { t[0] = mx[i] * mx[i], t[1] = mx[i] * my[i]; };
    for (const std::size_t globalTerms : {std::size_t(0), x.size()}) {
      double twoPass[2], given[2], largest[2] = {0.0, 0.0};
      reproducibleSums(*comm, 2, mx.size(), terms, twoPass, globalTerms);
      for (std::size_t i = 0; i < mx.size(); ++i) {
        double t[2];
        terms(i, t);
        for (int k = 0; k < 2; ++k) largest[k] = std::max(largest[k], std::fabs(t[k]));
      }
      signorini::core::reproducibleSumsGivenLargest(*comm, 2, mx.size(), terms, largest, given, globalTerms);
      for (int k = 0; k < 2; ++k)
        EXPECT_TRUE(sameBits(twoPass[k], given[k])) << "distribution " << how << ", sum " << k << ": " << twoPass[k]
                                                    << " against " << given[k];
    }
  }
  // Control: the largest term's size sets the grid of the parts (27 bits each, three of them without
  // a term count): one 2^60 times too large leaves 21 bits of the sum.
  const auto mx = share(x, 0, comm->getRank(), comm->getSize());
  auto term = [&](std::size_t i, double* t) { t[0] = mx[i] * mx[i]; };
  double twoPass, wrong, largest = 0.0;
  reproducibleSums(*comm, 1, mx.size(), term, &twoPass);
  for (double v : mx) largest = std::max(largest, v * v);
  largest *= 0x1p60;
  signorini::core::reproducibleSumsGivenLargest(*comm, 1, mx.size(), term, &largest, &wrong);
  EXPECT_FALSE(sameBits(twoPass, wrong));
}

TEST(ReproducibleSum, EmptyZeroAndNonFiniteSums) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  EXPECT_EQ(reproducibleSum(*comm, 0, nullptr), 0.0);
  const std::vector<double> zeros(10, 0.0);
  EXPECT_EQ(reproducibleSum(*comm, zeros.size(), zeros.data()), 0.0);
  std::vector<double> withInf = {1.0, comm->getRank() == 0 ? std::numeric_limits<double>::infinity() : 2.0};
  EXPECT_TRUE(std::isinf(reproducibleSum(*comm, withInf.size(), withInf.data())));
  std::vector<double> withNan = {1.0, comm->getRank() == comm->getSize() - 1 ? std::nan("") : 2.0};
  EXPECT_TRUE(std::isnan(reproducibleSum(*comm, withNan.size(), withNan.data())));
  // Tiny and huge magnitudes keep their bits through the scaling.
  const std::vector<double> tiny = {1e-300, 3e-300}, huge = {1e300, -3e299};
  const std::vector<double> tinyMine = share(tiny, 0, comm->getRank(), comm->getSize());
  const std::vector<double> hugeMine = share(huge, 0, comm->getRank(), comm->getSize());
  EXPECT_NEAR(reproducibleSum(*comm, tinyMine.size(), tinyMine.data()), 4e-300, 4e-300 * 0x1p-52);
  EXPECT_NEAR(reproducibleSum(*comm, hugeMine.size(), hugeMine.data()), 7e299, 7e299 * 0x1p-52);
}

}  // namespace

TEST(ReproducibleSum, SubnormalTermsKeepTheirBitsAndStayFinite) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  std::vector<double> all = hardTerms(3000, 5);
  for (auto& v : all) v *= 1e-310;  // most of them subnormal
  std::vector<double> results;
  for (int how = 0; how < 4; ++how) {
    const auto mine = share(all, how, comm->getRank(), comm->getSize());
    results.push_back(reproducibleSum(*comm, mine.size(), mine.data()));
  }
  EXPECT_TRUE(std::isfinite(results[0]));
  for (int how = 1; how < 4; ++how) EXPECT_TRUE(sameBits(results[0], results[how]));
  const std::vector<double> tiny = {4.9406564584124654e-324, 4.9406564584124654e-324};
  const auto mine = share(tiny, 0, comm->getRank(), comm->getSize());
  EXPECT_EQ(reproducibleSum(*comm, mine.size(), mine.data()), 2 * 4.9406564584124654e-324);
}

// With the global number of terms given (globalTerms), sums of up to 2^17 terms use two wider
// parts: still the same bits for every distribution, and within the documented 2^-54 max|term| of
// the exact sum (a compensated long double sum of the global list stands in for it). Sizes at the
// edges: 3 terms (the widest parts, 50 bits), 2^17 (the last with two parts), 2^17 + 1 (three parts).
// Two kinds of terms: 30 orders of magnitude with cancellation, and positive terms of one size
// (squares, as in a norm), whose parts' sums grow to the bound that the widths must leave room for.
TEST(ReproducibleSum, AKnownTermCountKeepsTheBitsAndTheAccuracy) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  for (const std::size_t n : {std::size_t(3), std::size_t(5000), std::size_t(1) << 17, (std::size_t(1) << 17) + 1}) {
    for (const bool positive : {false, true}) {
      auto all = hardTerms(n, 31 + static_cast<unsigned>(n % 97));
      if (positive)
        for (auto& v : all) v = 1.0 + std::fabs(v) * 1e-15;
      long double sum = 0, compensation = 0;
      double largest = 0;
      for (double v : all) {  // Neumaier
        const long double t = sum + v;
        compensation += std::fabs(static_cast<double>(sum)) >= std::fabs(v) ? (sum - t) + v : (v - t) + sum;
        sum = t;
        largest = std::max(largest, std::fabs(v));
      }
      const double exact = static_cast<double>(sum + compensation);
      std::vector<double> results;
      for (int how = 0; how < 4; ++how) {
        const auto mine = share(all, how, comm->getRank(), comm->getSize());
        double s;
        reproducibleSums(*comm, 1, mine.size(), [&](std::size_t i, double* t) { t[0] = mine[i]; }, &s, n);
        results.push_back(s);
      }
      for (int how = 1; how < 4; ++how)
        EXPECT_TRUE(sameBits(results[0], results[how])) << n << (positive ? " positive" : "") << " terms, distribution " << how;
      // the parts' error, and up to one unit in the last place from adding the parts up
      EXPECT_LE(std::fabs(results[0] - exact), 0x1p-54 * largest + 0x1p-52 * std::fabs(exact)) << n << " terms";
    }
  }
}

// The width of the two parts (detail::twoPartWidth) leaves exactly enough room: N terms just
// below 1 with full mantissas, folded into one accumulator in one order (no lanes, no ranks to
// split the sum), give parts' sums equal to their exact integer sums. The control: one more bit of
// width makes the same sums inexact for every N whose bound is filled, so the test sees a width
// that is too large by a single bit.
TEST(ReproducibleSum, TwoPartWidthKeepsTheFoldSumsExact) {
  using signorini::core::detail::addFoldedTwo;
  using signorini::core::detail::twoPartWidth;
  EXPECT_EQ(twoPartWidth(0), 0);
  EXPECT_EQ(twoPartWidth((std::size_t(1) << 17) + 1), 0);
  auto exact = [](std::size_t n, int width) {  // whether both folds equal their exact sums
    std::mt19937_64 gen(99 + n);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double sigma[2] = {std::ldexp(1.5, 52 - width), std::ldexp(1.5, 52 - 2 * width)};
    double folds[2] = {0.0, 0.0};
    __int128 sums[2] = {0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 1.0 - std::ldexp(unit(gen), -10);  // in [1 - 2^-10, 1), random low bits
      double rest = t;
      for (int f = 0; f < 2; ++f) {
        const double part = (sigma[f] + rest) - sigma[f];
        sums[f] += static_cast<__int128>(std::ldexp(part, width * (f + 1)));  // an integer below 2^51
        rest -= part;
      }
      addFoldedTwo(t, sigma, folds);
    }
    return static_cast<__int128>(std::ldexp(folds[0], width)) == sums[0] &&
           static_cast<__int128>(std::ldexp(folds[1], 2 * width)) == sums[1];
  };
  for (const std::size_t n : {std::size_t(3), std::size_t(5), std::size_t(1000), std::size_t(5000),
                              std::size_t(65537), std::size_t(131071), std::size_t(1) << 17}) {
    const int width = twoPartWidth(n);
    ASSERT_GE(width, 36) << n;
    ASSERT_LE(width, 50) << n;
    EXPECT_TRUE(exact(n, width)) << n << " terms, width " << width;
    // One bit wider halves the room, 2^(52 - width): the parts' sum (about 0.9995 n) passes it for
    // every n here but the smallest and 65537 (which sits just above 2^16).
    if (n >= 1000 && 0.999 * static_cast<double>(n) > std::ldexp(1.0, 52 - width))
      { EXPECT_FALSE(exact(n, width + 1)) << n << " terms"; }
  }
}
