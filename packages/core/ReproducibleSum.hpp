#pragma once
/// \file ReproducibleSum.hpp
/// Global sums whose bits depend only on the multiset of the terms of all ranks: not on the order
/// in which they are added, nor on how they are distributed over the ranks. A run on 2 ranks then
/// gets the same dot products, norms and energies as on 1 rank, which an ordinary sum of per-rank
/// partial sums does not give (docs/reproducibility.md).
///
/// Method (pre-rounding, after Demmel and Nguyen's reproducible summation): with M the largest
/// |term| over all ranks and 2^e > M, each term t is scaled to t 2^-e (exact) and split into three
/// parts, multiples of 2^-27, 2^-54 and 2^-81, by adding and subtracting fixed constants. Sums of
/// such parts are exact in double precision for up to 2^26 terms, so each part's sum, and their sum
/// over ranks, has the same bits in any order. The result is (S0 + S1) + S2, scaled back: its error
/// is at most 2^26 2^-82 M, far below that of an ordinary sum (about n 2^-53 M).
///
/// Cost: two passes over the terms (the largest term, then the parts) and two global reductions.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "Error.hpp"
#include "MpiComm.hpp"

#ifdef __FAST_MATH__
#error "reproducible sums need value-safe floating point: do not build with -ffast-math"
#endif

namespace signorini::core {

namespace detail {
/// Splitting constants 1.5 * 2^(52 - 27 (f + 1)): (sigma + t) - sigma rounds t to a multiple of 2^(-27 (f + 1)).
inline constexpr double kFoldSigma[3] = {1.5 * 33554432.0, 1.5 * 0.25, 1.5 * 0.25 / 134217728.0};
inline constexpr std::size_t kMaxTerms = std::size_t(1) << 26;

/// The exponent e with |t| < 2^e for every term bounded by \p largest (> 0, finite), at least
/// -1021 so that 2^-e stays finite (scaling subnormal terms by it is exact).
inline int boundExponent(double largest) { return std::max(std::ilogb(largest) + 1, -1021); }

/// Adds the three parts of \p t (|t| < 1) to folds[0..2]. (sigma + t) - sigma must be evaluated
/// as written: the project is never built with -ffast-math (reassociation), and a contraction
/// into an FMA cannot change a result here (the only product before it, the scaling by a power
/// of two, is exact).
inline void addFolded(double t, double* folds) {
  for (int f = 0; f < 3; ++f) {
    const double part = (kFoldSigma[f] + t) - kFoldSigma[f];
    folds[f] += part;
    t -= part;
  }
}

/// Short sums (at most 64 terms, a matrix row): two parts, multiples of 2^-46 and 2^-92, whose sums
/// of 64 terms stay exact (constants 1.5 * 2^(52 - 46 (f + 1))); the error is below 64 2^-93 max|t|.
inline constexpr std::size_t kMaxShortTerms = 64;
inline constexpr double kShortFoldSigma[2] = {1.5 * 64.0, 1.5 / 1099511627776.0};
inline void addFoldedShort(double t, double* folds) {
  for (int f = 0; f < 2; ++f) {
    const double part = (kShortFoldSigma[f] + t) - kShortFoldSigma[f];
    folds[f] += part;
    t -= part;
  }
}

/// 2^e as a double for e in [-1022, 1023] (exact; built from the exponent bits).
inline double powerOfTwo(int e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(1023 + e) << 52;
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

/// Global maxima of \p count values (in place).
void maxAll(const Comm& comm, int count, double* values);
/// Global sums of \p count values (in place).
void sumAll(const Comm& comm, int count, double* values);
}  // namespace detail

/// The \p count sums over i < n (local) and over all ranks of the terms term(i, t) writes into
/// t[0 .. count) (count <= 8). term must give the same values when called again for the same i.
/// Collective. At most 2^26 terms per sum over all ranks (asserted). A sum with a non-finite term is
/// the ordinary sum (inf or nan).
template <class Term>
void reproducibleSums(const Comm& comm, int count, std::size_t n, const Term& term, double* sums) {
  constexpr int kMax = 8;
  SIGNORINI_ASSERT(count >= 1 && count <= kMax, "reproducibleSums: 1 to 8 sums at once");
  double largest[kMax] = {}, plain[kMax + 1] = {}, t[kMax];
  for (std::size_t i = 0; i < n; ++i) {
    term(i, t);
    for (int k = 0; k < count; ++k) {
      const double a = std::fabs(t[k]);
      largest[k] = a > largest[k] || std::isnan(a) ? a : largest[k];
      plain[k] += t[k];
    }
  }
  detail::maxAll(comm, count, largest);
  int exponent[kMax];
  double scale[kMax], folds[3 * kMax + 1] = {};
  bool finite = true;
  for (int k = 0; k < count; ++k) {
    finite = finite && std::isfinite(largest[k]);
    exponent[k] = largest[k] > 0 && std::isfinite(largest[k]) ? detail::boundExponent(largest[k]) : 0;
    scale[k] = std::ldexp(1.0, -exponent[k]);
  }
  if (!finite) {  // the ordinary sums carry the inf or nan
    detail::sumAll(comm, count, plain);
    for (int k = 0; k < count; ++k) sums[k] = plain[k];
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    term(i, t);
    for (int k = 0; k < count; ++k) detail::addFolded(t[k] * scale[k], folds + 3 * k);
  }
  folds[3 * count] = static_cast<double>(n);
  detail::sumAll(comm, 3 * count + 1, folds);
  SIGNORINI_ASSERT(folds[3 * count] <= static_cast<double>(detail::kMaxTerms),
                   "reproducibleSums: more than 2^26 terms in one sum");
  for (int k = 0; k < count; ++k)
    sums[k] = std::ldexp((folds[3 * k] + folds[3 * k + 1]) + folds[3 * k + 2], exponent[k]);
}

/// Process-wide switch of partition-independent arithmetic (off by default): where it is on, the
/// solvers and assemblers that support it order every sum so that its bits do not depend on the
/// number of ranks (docs/reproducibility.md lists which do). Set once by the driver from the deck.
void setReproducibleArithmetic(bool on);
bool reproducibleArithmetic();

/// One reproducible sum of \p n local terms.
inline double reproducibleSum(const Comm& comm, std::size_t n, const double* terms) {
  double s;
  reproducibleSums(comm, 1, n, [terms](std::size_t i, double* t) { t[0] = terms[i]; }, &s);
  return s;
}

}  // namespace signorini::core
