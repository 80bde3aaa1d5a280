// Marking strategies mark what they promise, identically on any number of ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Tpetra_Core.hpp>

#include "Marking.hpp"
#include "MpiComm.hpp"

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

TEST(Marking, FixedFractionMarksTheLargestFractionOfCells) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  for (double fraction : {0.0, 0.1, 0.5, 1.0}) {
    const auto flags = gather(adapt::markFixedFraction(mine, fraction, raw), raw);
    const long long wanted = static_cast<long long>(std::ceil(fraction * all.size()));
    const long long marked = std::count(flags.begin(), flags.end(), 1);
    EXPECT_GE(marked, wanted);
    double minMarked = 1e300, maxUnmarked = -1;
    for (size_t i = 0; i < all.size(); ++i)
      (flags[i] ? minMarked = std::min(minMarked, all[i]) : maxUnmarked = std::max(maxUnmarked, all[i]));
    if (marked > 0 && marked < static_cast<long long>(all.size())) EXPECT_GT(minMarked, maxUnmarked);
    if (marked > wanted) {  // only ties at the threshold may exceed the count
      long long atThreshold = std::count(all.begin(), all.end(), minMarked);
      EXPECT_LE(marked - wanted, atThreshold - 1);
    }
  }
}

TEST(Marking, BulkMarksTheFewestLargestCellsReachingTheFraction) {
  auto comm = Tpetra::getDefaultComm();
  MPI_Comm raw = core::rawMpiComm(*comm);
  const auto all = globalIndicators();
  size_t offset;
  const auto mine = localPart(all, comm->getRank(), comm->getSize(), offset);
  const double total = std::accumulate(all.begin(), all.end(), 0.0);
  for (double fraction : {0.2, 0.5, 0.9}) {
    const auto flags = gather(adapt::markBulk(mine, fraction, raw), raw);
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
  const auto flags = gather(adapt::markSmallest(mine, 0.25, raw), raw);
  const long long marked = std::count(flags.begin(), flags.end(), 1);
  EXPECT_LE(marked, static_cast<long long>(0.25 * all.size()));
  EXPECT_GE(marked, static_cast<long long>(0.25 * all.size()) - 2);  // ties at the threshold
  double maxMarked = -1, minUnmarked = 1e300;
  for (size_t i = 0; i < all.size(); ++i)
    (flags[i] ? maxMarked = std::max(maxMarked, all[i]) : minUnmarked = std::min(minUnmarked, all[i]));
  EXPECT_LT(maxMarked, minUnmarked);
}

}  // namespace
