#include "signorini/adapt/Marking.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <Teuchos_DefaultMpiComm.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::adapt {
namespace {

/// Order-preserving integer key of a non-negative double.
uint64_t key(double x) {
  SIGNORINI_ASSERT(x >= 0 && std::isfinite(x), "indicators must be finite and non-negative");
  uint64_t k;
  std::memcpy(&k, &x, sizeof k);
  return k;
}

/// The largest t in [lo, hi] with accept(t) true, given accept(lo) and accept monotone (true for small t).
template <class T, class Accept>
T largestAccepted(T lo, T hi, Accept accept) {
  while (lo < hi) {
    const T mid = lo + (hi - lo + 1) / 2;
    if (accept(mid))
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

/// The largest threshold key t with accept(t) true, given accept is monotone (true for small t).
template <class Accept>
uint64_t bisect(Accept accept) {
  return largestAccepted<uint64_t>(0, key(std::numeric_limits<double>::max()), accept);
}

/// The keys of the local indicators in ascending order: each bisection step then counts the
/// cells on either side of a threshold by binary search instead of a pass over all cells.
std::vector<uint64_t> sortedKeys(const std::vector<double>& v) {
  std::vector<uint64_t> keys(v.size());
  for (size_t i = 0; i < v.size(); ++i) keys[i] = key(v[i]);
  std::sort(keys.begin(), keys.end());
  return keys;
}

/// Number of cells of all ranks with key >= threshold (above) or key <= threshold (!above).
long long globalCount(const std::vector<uint64_t>& sorted, uint64_t threshold, bool above, MPI_Comm comm) {
  const long long local =
      above ? static_cast<long long>(sorted.end() - std::lower_bound(sorted.begin(), sorted.end(), threshold))
            : static_cast<long long>(std::upper_bound(sorted.begin(), sorted.end(), threshold) - sorted.begin());
  long long global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return global;
}

double fromKey(uint64_t k) {
  double x;
  std::memcpy(&x, &k, sizeof x);
  return x;
}

/// tieTolerance times the largest indicator of all ranks: the distance below which two indicators tie.
double tieWidth(const std::vector<double>& v, double tieTolerance, MPI_Comm comm) {
  SIGNORINI_ASSERT(tieTolerance >= 0 && tieTolerance < 1, "tie tolerance in [0, 1)");
  double local = 0, global = 0;
  for (double x : v) local = std::max(local, x);
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm);
  return tieTolerance * global;
}

/// Flags the cells whose indicator is at least the value of key t less the tie width.
std::vector<char> flagFrom(const std::vector<double>& v, uint64_t t, double width) {
  const uint64_t lowest = key(std::max(0.0, fromKey(t) - width));
  std::vector<char> flags(v.size(), 0);
  // A cell whose indicator ties with 0 has nothing to refine: a step without error (nothing moves
  // yet) would otherwise tie every cell at the threshold 0, and a step whose error sits in part of
  // the domain (the rest at rest, indicators of rounding size) would refine all of it.
  for (size_t i = 0; i < v.size(); ++i) flags[i] = v[i] > width && key(v[i]) >= lowest;
  return flags;
}

long long globalSize(const std::vector<double>& v, MPI_Comm comm) {
  long long local = static_cast<long long>(v.size()), global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return global;
}

/// The first \p allowed cells along the curve among those whose indicator ties with 0 (at most
/// \p width): when they alone exceed the allowance, no threshold on the indicators can choose.
std::vector<char> firstAlongCurve(const std::vector<double>& v, const std::vector<long long>& positions, double width,
                                  long long allowed, MPI_Comm comm) {
  std::vector<long long> zero;
  long long last = -1;
  for (size_t i = 0; i < v.size(); ++i)
    if (v[i] <= width) zero.push_back(positions[i]), last = std::max(last, positions[i]);
  std::sort(zero.begin(), zero.end());
  MPI_Allreduce(MPI_IN_PLACE, &last, 1, MPI_LONG_LONG, MPI_MAX, comm);
  auto upTo = [&](long long p) {
    long long local = std::upper_bound(zero.begin(), zero.end(), p) - zero.begin(), global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_LONG_LONG, MPI_SUM, comm);
    return global;
  };
  // The largest position with at most `allowed` of them up to it.
  const long long lo = largestAccepted<long long>(-1, last, [&](long long p) { return upTo(p) <= allowed; });
  std::vector<char> flags(v.size(), 0);
  for (size_t i = 0; i < v.size(); ++i) flags[i] = v[i] <= width && positions[i] <= lo;
  return flags;
}

}  // namespace

long long cellsOfFraction(double fraction, long long cells, bool roundUp) {
  const double x = fraction * static_cast<double>(cells);
  // A decimal fraction is stored with a relative error up to 2^-53 and the product adds as much:
  // 0.55 * 100 gives 55.000000000000007, which means 55 cells, not 56.
  const double nearest = std::round(x);
  if (std::abs(x - nearest) <= 8 * std::numeric_limits<double>::epsilon() * x)  // relative: 1e-17 of 100 is 1
    return static_cast<long long>(nearest);
  return static_cast<long long>(roundUp ? std::ceil(x) : std::floor(x));
}

std::vector<char> markFixedFraction(const std::vector<double>& indicators, double fraction, double tieTolerance,
                                    MPI_Comm comm) {
  const long long wanted = cellsOfFraction(fraction, globalSize(indicators, comm), true);
  if (wanted <= 0) return std::vector<char>(indicators.size(), 0);
  const double width = tieWidth(indicators, tieTolerance, comm);
  const auto sorted = sortedKeys(indicators);
  const uint64_t t = bisect([&](uint64_t th) { return globalCount(sorted, th, true, comm) >= wanted; });
  return flagFrom(indicators, t, width);
}

std::vector<char> markBulk(const std::vector<double>& indicators, double fraction, double tieTolerance,
                           MPI_Comm comm) {
  // Under reproducible arithmetic the sums have the same bits on any number of ranks, and so has
  // the threshold they decide.
  const bool reproducible = core::reproducibleArithmetic();
  const Teuchos::MpiComm<int> teuchosComm(comm);
  auto sumAbove = [&](uint64_t th) {
    if (reproducible) {
      double g;
      core::reproducibleSums(teuchosComm, 1, indicators.size(),
                             [&](size_t i, double* t) { t[0] = key(indicators[i]) >= th ? indicators[i] : 0.0; }, &g);
      return g;
    }
    double s = 0, g = 0;
    for (double x : indicators)
      if (key(x) >= th) s += x;
    MPI_Allreduce(&s, &g, 1, MPI_DOUBLE, MPI_SUM, comm);
    return g;
  };
  const double total = sumAbove(0);
  if (!(total > 0) || fraction <= 0) return std::vector<char>(indicators.size(), 0);
  const double width = tieWidth(indicators, tieTolerance, comm);
  const uint64_t t = bisect([&](uint64_t th) { return sumAbove(th) >= fraction * total; });
  return flagFrom(indicators, t, width);
}

std::vector<char> markSmallest(const std::vector<double>& indicators, const std::vector<long long>& positions,
                               double fraction, double tieTolerance, MPI_Comm comm) {
  SIGNORINI_ASSERT(positions.size() == indicators.size(), "one curve position per cell");
  const long long allowed = cellsOfFraction(fraction, globalSize(indicators, comm), false);
  std::vector<char> flags(indicators.size(), 0);
  if (allowed <= 0) return flags;
  const double width = tieWidth(indicators, tieTolerance, comm);
  const auto sorted = sortedKeys(indicators);
  if (globalCount(sorted, key(width), false, comm) > allowed) return firstAlongCurve(indicators, positions, width, allowed, comm);
  // The largest threshold with at most `allowed` cells at or below it.
  const uint64_t lo = bisect([&](uint64_t th) { return globalCount(sorted, th, false, comm) <= allowed; });
  // Cells that tie with the smallest indicator left out are left out too.
  const auto above = std::upper_bound(sorted.begin(), sorted.end(), lo);
  double firstKept = above == sorted.end() ? std::numeric_limits<double>::infinity() : fromKey(*above);
  MPI_Allreduce(MPI_IN_PLACE, &firstKept, 1, MPI_DOUBLE, MPI_MIN, comm);
  for (size_t i = 0; i < flags.size(); ++i)
    flags[i] = key(indicators[i]) <= lo && indicators[i] < firstKept - width;
  return flags;
}

std::vector<char> markAmong(const std::vector<double>& indicators, const std::vector<char>& among,
                            const std::function<std::vector<char>(const std::vector<double>&)>& mark) {
  std::vector<size_t> cells;
  std::vector<double> theirs;
  for (size_t e = 0; e < indicators.size(); ++e)
    if (among[e]) cells.push_back(e), theirs.push_back(indicators[e]);
  const std::vector<char> marked = mark(theirs);
  std::vector<char> flags(indicators.size(), 0);
  for (size_t i = 0; i < cells.size(); ++i) flags[cells[i]] = marked[i];
  return flags;
}

std::vector<char> markSmallestAbove(const std::vector<double>& indicators, const std::vector<long long>& positions,
                                    const std::vector<int>& levels, int minLevel, double fraction,
                                    double tieTolerance, MPI_Comm comm) {
  std::vector<char> above(indicators.size());
  std::vector<long long> theirPositions;
  for (size_t e = 0; e < indicators.size(); ++e)
    if ((above[e] = levels[e] > minLevel)) theirPositions.push_back(positions[e]);
  return markAmong(indicators, above, [&](const std::vector<double>& v) {
    return markSmallest(v, theirPositions, fraction, tieTolerance, comm);
  });
}

}  // namespace signorini::adapt
