// Marking strategies mark what they promise, identically on any number of ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <Tpetra_Core.hpp>

#include "signorini/adapt/Marking.hpp"
#include "signorini/core/MpiComm.hpp"

using namespace signorini;

namespace {

/// The same global list of indicators (with ties) split into contiguous chunks over the ranks.
std::vector<double> globalIndicators() {
  std::vector<double> v;
  for (int i = 0; i < 101; ++i) v.push_back(std::fmod(37.0 * i, 101.0) / 7.0);  // a permutation of 0..100, /7
  v.push_back(3.0);  // ties
  v.push_back(3.0);
  v.push_back(0.0);
  return v;
}

std::vector<double> localPart(const std::vector<double>& all, int rank, int size, size_t& offset) {
  const size_t n = all.size(), b = n * rank / size, e = n * (rank + 1) / size;
  offset = b;
  return std::vector<double>(all.begin() + b, all.begin() + e);
}

std::vector<char> gather(const std::vector<char>& local, MPI_Comm comm) { return core::allGatherv(comm, local); }

/// Curve positions of the local cells of contiguous chunks: their indices in the global list.
std::vector<long long> positionsOf(const std::vector<double>& mine, MPI_Comm comm) {
  long long n = static_cast<long long>(mine.size()), first = 0;
  MPI_Exscan(&n, &first, 1, MPI_LONG_LONG, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::vector<long long> p(mine.size());
  std::iota(p.begin(), p.end(), rank == 0 ? 0 : first);  // MPI_Exscan leaves rank 0's result undefined
  return p;
}

TEST(Marking, FixedFractionMarksTheLargestFractionOfCells) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  for (double fraction : {0.0, 0.1, 0.5, 1.0}) {
    const auto flags = gather(adapt::markFixedFraction(mine, fraction, 0.0, raw), raw);
    // ceil(f N) cells, but none whose indicator is 0 (two here)
    const long long positive = std::count_if(all.begin(), all.end(), [](double x) { return x > 0; });
    const long long wanted = std::min(static_cast<long long>(std::ceil(fraction * all.size())), positive);
    const long long marked = std::count(flags.begin(), flags.end(), 1);
    EXPECT_GE(marked, wanted);
    for (size_t i = 0; i < all.size(); ++i)
      if (all[i] == 0) { EXPECT_FALSE(flags[i]) << "cell " << i << " has nothing to refine"; }
    double minMarked = 1e300, maxUnmarked = -1;
    for (size_t i = 0; i < all.size(); ++i)
      (flags[i] ? minMarked = std::min(minMarked, all[i]) : maxUnmarked = std::max(maxUnmarked, all[i]));
    if (marked > 0 && marked < static_cast<long long>(all.size())) { EXPECT_GT(minMarked, maxUnmarked); }
    if (marked > wanted) {  // only ties at the threshold may exceed the count
      long long atThreshold = std::count(all.begin(), all.end(), minMarked);
      EXPECT_LE(marked - wanted, atThreshold - 1);
    }
  }
}

TEST(Marking, AStepWithoutErrorRefinesNothing) {
  // Every indicator 0 (nothing moves yet): the threshold is 0 and every cell would tie with it.
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const std::vector<double> zeros(10, 0.0);
  for (double tie : {0.0, 0.01}) {
    const auto fixed = gather(adapt::markFixedFraction(zeros, 0.5, tie, raw), raw);
    EXPECT_EQ(std::count(fixed.begin(), fixed.end(), 1), 0) << "tie tolerance " << tie;
    const auto bulk = gather(adapt::markBulk(zeros, 0.5, tie, raw), raw);
    EXPECT_EQ(std::count(bulk.begin(), bulk.end(), 1), 0) << "tie tolerance " << tie;
  }
  // One cell with error in a step: it alone, although 50% asks for more.
  std::vector<double> one(10, 0.0);
  if (comm->getRank() == 0) one[3] = 1.0;
  const auto flags = gather(adapt::markFixedFraction(one, 0.5, 0.01, raw), raw);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), 1);
  // The rest at rest up to rounding (indicators within the tie width of 0): still it alone. Tied
  // with the threshold at the fifth largest indicator, all ten were refined.
  std::vector<double> rest(10);
  for (int i = 0; i < 10; ++i) rest[i] = 1e-12 * (1 + i + 10 * comm->getRank());  // distinct
  if (comm->getRank() == 0) rest[3] = 1.0;
  const auto atRest = gather(adapt::markFixedFraction(rest, 0.5, 1e-8, raw), raw);
  EXPECT_EQ(std::count(atRest.begin(), atRest.end(), 1), 1);
  EXPECT_EQ(atRest[3], 1);
  const auto bulkAtRest = gather(adapt::markBulk(rest, 1.0, 1e-8, raw), raw);  // all the error: the one cell
  EXPECT_EQ(std::count(bulkAtRest.begin(), bulkAtRest.end(), 1), 1);
  // Compared exactly (tie tolerance 0), such cells are cells with error like any other.
  const auto exact = gather(adapt::markFixedFraction(rest, 0.5, 0.0, raw), raw);
  EXPECT_EQ(std::count(exact.begin(), exact.end(), 1), 5 * comm->getSize());
}

TEST(Marking, BulkMarksTheFewestLargestCellsReachingTheFraction) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  const double total = std::accumulate(all.begin(), all.end(), 0.0);
  for (double fraction : {0.2, 0.5, 0.9}) {
    const auto flags = gather(adapt::markBulk(mine, fraction, 0.0, raw), raw);
    double sum = 0, minMarked = 1e300, maxUnmarked = -1;
    for (size_t i = 0; i < all.size(); ++i) {
      if (flags[i]) sum += all[i], minMarked = std::min(minMarked, all[i]);
      else maxUnmarked = std::max(maxUnmarked, all[i]);
    }
    EXPECT_GE(sum, fraction * total);
    EXPECT_GT(minMarked, maxUnmarked);
    EXPECT_LT(sum - minMarked, fraction * total);  // dropping the smallest marked value falls short
  }
}

TEST(Marking, SmallestMarksAtMostTheFraction) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  const auto flags = gather(adapt::markSmallest(mine, positionsOf(mine, raw), 0.25, 0.0, raw), raw);
  const long long marked = std::count(flags.begin(), flags.end(), 1);
  EXPECT_LE(marked, static_cast<long long>(0.25 * all.size()));
  EXPECT_GE(marked, static_cast<long long>(0.25 * all.size()) - 2);  // ties at the threshold
  double maxMarked = -1, minUnmarked = 1e300;
  for (size_t i = 0; i < all.size(); ++i)
    (flags[i] ? maxMarked = std::max(maxMarked, all[i]) : minUnmarked = std::min(minUnmarked, all[i]));
  EXPECT_LT(maxMarked, minUnmarked);
}

// Coarsening ranks only the cells above the deck's level: here the cells at the level have the
// smallest indicators, and markSmallest over all cells would flag them (and nothing that coarsens).
TEST(Marking, SmallestAboveFlagsOnlyCellsAboveTheLevelAndCountsOnlyThem) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  std::vector<int> allLevels(all.size());
  long long above = 0;
  for (size_t i = 0; i < all.size(); ++i) above += (allLevels[i] = all[i] > 5.0 ? 3 : 2) > 2;  // large ones refined
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  const std::vector<int> myLevels(allLevels.begin() + offset, allLevels.begin() + offset + mine.size());
  const auto flags = gather(adapt::markSmallestAbove(mine, positionsOf(mine, raw), myLevels, 2, 0.5, 0.0, raw), raw);
  const long long marked = std::count(flags.begin(), flags.end(), 1);
  EXPECT_GE(marked, above / 2 - 2);  // half of the cells above the level (ties at the threshold)
  EXPECT_LE(marked, above / 2);
  double maxMarked = -1, minUnmarked = 1e300;
  for (size_t i = 0; i < all.size(); ++i) {
    if (flags[i]) { EXPECT_EQ(allLevels[i], 3) << "cell " << i << " is at the deck's level"; }
    if (allLevels[i] == 3) (flags[i] ? maxMarked = std::max(maxMarked, all[i]) : minUnmarked = std::min(minUnmarked, all[i]));
  }
  EXPECT_LT(maxMarked, minUnmarked);  // the smallest of them
  // markSmallest over all cells spends the fraction on the cells at the level.
  const auto overAll = gather(adapt::markSmallest(mine, positionsOf(mine, raw), 0.5, 0.0, raw), raw);
  long long overAllAbove = 0;
  for (size_t i = 0; i < all.size(); ++i) overAllAbove += overAll[i] && allLevels[i] == 3;
  EXPECT_LT(overAllAbove, marked / 2);
}

// A region at rest has indicators 0 (or within the tie width of 0): more such cells than the
// coarsening allowance tie at the threshold, and no threshold on the indicators can choose among
// them. The curve positions do: the first ones along the curve, exactly the allowance, on any
// number of ranks.
TEST(Marking, CellsAtRestCoarsenAlongTheCurveUpToTheFraction) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  for (double tolerance : {0.0, 1e-8}) {
    std::vector<double> all;
    for (int i = 0; i < 48; ++i) {
      const bool moving = i % 4 == 1;  // 12 cells with error, 36 at rest
      all.push_back(moving ? 1.0 + i : (tolerance > 0 && i % 3 == 0 ? 1e-12 : 0.0));
    }
    size_t offset;
    const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
    const auto flags = gather(adapt::markSmallest(mine, positionsOf(mine, raw), 0.5, tolerance, raw), raw);
    std::vector<char> expected(all.size(), 0);
    for (size_t i = 0, chosen = 0; i < all.size() && chosen < 24; ++i)
      if (all[i] < 1) expected[i] = 1, ++chosen;  // the first 24 cells at rest
    EXPECT_EQ(flags, expected) << "tie tolerance " << tolerance;
    // Among the cells above the deck's level: the first half of those at rest that are above it.
    std::vector<int> levels(all.size());
    for (size_t i = 0; i < all.size(); ++i) levels[i] = i < 8 ? 2 : 3;
    const std::vector<int> myLevels(levels.begin() + offset, levels.begin() + offset + mine.size());
    const auto above = gather(adapt::markSmallestAbove(mine, positionsOf(mine, raw), myLevels, 2, 0.5, tolerance, raw), raw);
    std::fill(expected.begin(), expected.end(), 0);
    for (size_t i = 8, chosen = 0; i < all.size() && chosen < 20; ++i)
      if (all[i] < 1) expected[i] = 1, ++chosen;  // 40 cells above the level: 20
    EXPECT_EQ(above, expected) << "tie tolerance " << tolerance;
  }
}

TEST(Marking, DecimalFractionsCountTheCellsTheyMean) {
  // Every two-digit fraction p/100 as a deck gives it, of every N up to 2000 cells, against integer
  // arithmetic; several products evaluate just above or below the integer (0.55 * 100, 0.29 * 100).
  int offByRounding = 0;
  for (int p = 0; p <= 100; ++p) {
    const double fraction = p == 100 ? 1.0 : std::stod((p < 10 ? "0.0" : "0.") + std::to_string(p));
    for (long long n = 1; n <= 2000; ++n) {
      const long long up = (p * n + 99) / 100, down = p * n / 100;
      ASSERT_EQ(adapt::cellsOfFraction(fraction, n, true), up) << p << "% of " << n;
      ASSERT_EQ(adapt::cellsOfFraction(fraction, n, false), down) << p << "% of " << n;
      offByRounding += std::ceil(fraction * n) != up || std::floor(fraction * n) != down;
    }
  }
  EXPECT_GT(offByRounding, 0);  // the plain ceil/floor would fail this test
  // Tiny fractions of a few cells still mean a cell when rounded up (not a rounding error of 0).
  EXPECT_EQ(adapt::cellsOfFraction(1e-17, 100, true), 1);
  EXPECT_EQ(adapt::cellsOfFraction(1e-17, 100, false), 0);
  EXPECT_EQ(adapt::cellsOfFraction(0.0, 100, true), 0);
  // ... and the strategies use it: 55% and 29% of 100 distinct indicators.
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  std::vector<double> all(100);
  for (int i = 0; i < 100; ++i) all[i] = std::fmod(37.0 * i, 100.0) + 1;
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  const auto refine = gather(adapt::markFixedFraction(mine, 0.55, 0.0, raw), raw);
  EXPECT_EQ(std::count(refine.begin(), refine.end(), 1), 55);
  const auto coarsen = gather(adapt::markSmallest(mine, positionsOf(mine, raw), 0.29, 0.0, raw), raw);
  EXPECT_EQ(std::count(coarsen.begin(), coarsen.end(), 1), 29);
}

/// The global indicators with the ten cells of a tied group (value 5) perturbed at the level of rounding,
/// upwards for odd and downwards for even cells (\p sign = 1) or the other way round (-1).
std::vector<double> nearTies(double sign) {
  std::vector<double> v;
  for (int i = 0; i < 40; ++i) v.push_back(1.1 + i * 0.25);  // 1.1 .. 10.85: 16 below 5, 24 above
  for (int j = 0; j < 10; ++j) v.push_back(5.0 * (1 + sign * (j % 2 ? 1 : -1) * (j + 1) * 1e-15));
  return v;
}

/// Flags of all ranks for both perturbations of the tied group.
template <class Mark>
std::pair<std::vector<char>, std::vector<char>> markBothWays(Mark mark) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  size_t offset;
  std::pair<std::vector<char>, std::vector<char>> flags;
  flags.first = gather(mark(localPart(nearTies(1), comm->getRank(), comm->getSize(), offset), raw), raw);
  flags.second = gather(mark(localPart(nearTies(-1), comm->getRank(), comm->getSize(), offset), raw), raw);
  return flags;
}

long long countGroup(const std::vector<char>& flags) { return std::count(flags.begin() + 40, flags.end(), 1); }

TEST(Marking, NearTiesAreMarkedAlikeWhateverTheRounding) {
  // 50 cells, 25 wanted: the 24 values above 5 and one of the ten cells at 5. The tied group is marked
  // (fixed fraction, bulk) or kept (coarsening) as a whole, the same for both perturbations.
  for (double tolerance : {1e-12, 1e-8}) {
    const auto fixed = markBothWays([&](const std::vector<double>& v, MPI_Comm c) {
      return adapt::markFixedFraction(v, 0.5, tolerance, c);
    });
    EXPECT_EQ(fixed.first, fixed.second);
    EXPECT_EQ(countGroup(fixed.first), 10);
    EXPECT_EQ(std::count(fixed.first.begin(), fixed.first.end(), 1), 24 + 10);
    // bulk: a fraction of the sum that needs the values above 5 and two of the group
    double total = 0, upTo = 0;
    for (double x : nearTies(0)) total += x;
    for (double x : nearTies(0)) upTo += x > 5 ? x : 0;
    const double share = (upTo + 1.5 * 5.0) / total;
    const auto bulk = markBothWays([&](const std::vector<double>& v, MPI_Comm c) {
      return adapt::markBulk(v, share, tolerance, c);
    });
    EXPECT_EQ(bulk.first, bulk.second);
    EXPECT_EQ(countGroup(bulk.first), 10);
    // coarsening 24 of 50: the 16 values below 5 and none of the group
    const auto small = markBothWays([&](const std::vector<double>& v, MPI_Comm c) {
      return adapt::markSmallest(v, positionsOf(v, c), 0.48, tolerance, c);
    });
    EXPECT_EQ(small.first, small.second);
    EXPECT_EQ(countGroup(small.first), 0);
    EXPECT_EQ(std::count(small.first.begin(), small.first.end(), 1), 16);
  }
  // Compared exactly, the rounding decides: a different part of the group each way.
  const auto exact = markBothWays([](const std::vector<double>& v, MPI_Comm c) {
    return adapt::markFixedFraction(v, 0.5, 0.0, c);
  });
  EXPECT_NE(exact.first, exact.second);
  EXPECT_EQ(std::count(exact.first.begin(), exact.first.end(), 1), 25);
}

}  // namespace
