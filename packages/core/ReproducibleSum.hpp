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
/// is at most 2^-54 M (2^26 terms, each off by at most 2^-82 2^e) plus the rounding of adding the
/// parts' sums up (half a unit in the last place of each addition), far below that of an ordinary
/// sum (about n 2^-53 M). Sums of at most 2^17 terms can use two wider parts (globalTerms below).
///
/// Cost: two passes over the terms (the largest term, then the parts) and two global reductions.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"

#ifdef __FAST_MATH__
#error "reproducible sums need value-safe floating point: do not build with -ffast-math"
#endif

namespace signorini::core {

namespace detail {
/// Splitting constants 1.5 * 2^(52 - 27 (f + 1)): (sigma + t) - sigma rounds t to a multiple of 2^(-27 (f + 1)).
inline constexpr double kFoldSigma[3] = {1.5 * 33554432.0, 1.5 * 0.25, 1.5 * 0.25 / 134217728.0};
/// Most terms of one reproducible sum over all ranks (2^26; asserted).
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
inline constexpr double kShortFoldSigma[2] = {1.5 * 64.0, 1.5 / 1099511627776.0};  ///< the short sums' constants
/// Adds the two parts of \p t (|t| < 1) to folds[0..1] (as addFolded()).
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

/// The width W of the two parts for a sum of \p globalTerms terms (all ranks), or 0 for three parts
/// of 27 bits: W = 53 - ceil(log2 globalTerms) for 1 <= globalTerms <= 2^17 (at most 50), so that
/// the sum of globalTerms parts below 1 on the grid 2^-W stays below 2^53 grid units: exact.
inline int twoPartWidth(std::size_t globalTerms) {
  if (globalTerms == 0 || globalTerms > (std::size_t(1) << 17)) return 0;
  int bits = 3;
  while ((std::size_t(1) << bits) < globalTerms) ++bits;
  return 53 - bits;
}

/// Adds the two parts of \p t (|t| < 1; multiples of 2^-W and 2^-2W for the splitting constants
/// \p sigma = 1.5 * 2^(52 - W), 1.5 * 2^(52 - 2W), 36 <= W <= 50) to folds[0..1].
inline void addFoldedTwo(double t, const double* sigma, double* folds) {
  for (int f = 0; f < 2; ++f) {
    const double part = (sigma[f] + t) - sigma[f];
    folds[f] += part;
    t -= part;
  }
}

/// The second pass of reproducibleSumsOf: \p largest holds this rank's largest |term| of each sum
/// (overwritten by the global ones). The sums' bits depend on the terms only.
template <int Count, class Term>
void foldedSumsOf(const Comm& comm, std::size_t n, const Term& term, double* largest, double* sums,
                  std::size_t globalTerms) {
  constexpr int kLanes = 4;
  double t[kLanes][Count];
  maxAll(comm, Count, largest);
  int exponent[Count];
  double scale[Count], folds[kLanes][3 * Count] = {};
  bool finite = true;
  for (int k = 0; k < Count; ++k) {
    finite = finite && std::isfinite(largest[k]);
    exponent[k] = largest[k] > 0 && std::isfinite(largest[k]) ? boundExponent(largest[k]) : 0;
    scale[k] = std::ldexp(1.0, -exponent[k]);
  }
  if (!finite) {  // the ordinary sums carry the inf or nan
    double plain[Count] = {};
    for (std::size_t j = 0; j < n; ++j) {
      term(j, t[0]);
      for (int k = 0; k < Count; ++k) plain[k] += t[0][k];
    }
    sumAll(comm, Count, plain);
    for (int k = 0; k < Count; ++k) sums[k] = plain[k];
    return;
  }
  const int width = twoPartWidth(globalTerms);
  auto foldAll = [&](const auto& add) {
    std::size_t j = 0;
    for (; j + kLanes <= n; j += kLanes)
      for (int l = 0; l < kLanes; ++l) {
        term(j + l, t[l]);
        for (int k = 0; k < Count; ++k) add(t[l][k] * scale[k], folds[l] + 3 * k);
      }
    for (; j < n; ++j) {
      term(j, t[0]);
      for (int k = 0; k < Count; ++k) add(t[0][k] * scale[k], folds[0] + 3 * k);
    }
  };
  if (width > 0) {
    const double sigma[2] = {std::ldexp(1.5, 52 - width), std::ldexp(1.5, 52 - 2 * width)};
    foldAll([&](double v, double* f) { addFoldedTwo(v, sigma, f); });
  } else {
    foldAll([](double v, double* f) { addFolded(v, f); });
  }
  double total[3 * Count + 1];
  for (int j = 0; j < 3 * Count; ++j) {  // exact: sums of parts
    total[j] = folds[0][j];
    for (int l = 1; l < kLanes; ++l) total[j] += folds[l][j];
  }
  total[3 * Count] = static_cast<double>(n);
  sumAll(comm, 3 * Count + 1, total);
  SIGNORINI_ASSERT(total[3 * Count] <= static_cast<double>(kMaxTerms), "reproducibleSums: more than 2^26 terms in one sum");
  SIGNORINI_ASSERT(globalTerms == 0 || total[3 * Count] == static_cast<double>(globalTerms),
                   "reproducibleSums: globalTerms is not the number of terms");
  for (int k = 0; k < Count; ++k)
    sums[k] = std::ldexp((total[3 * k] + total[3 * k + 1]) + total[3 * k + 2], exponent[k]);
}

/// reproducibleSums with the number of sums known at compile time (kept in registers). Both passes
/// run kLanes interleaved accumulators (independent dependency chains); the maximum and the parts'
/// sums are exact, so how the terms are split between the lanes does not change a bit.
template <int Count, class Term>
void reproducibleSumsOf(const Comm& comm, std::size_t n, const Term& term, double* sums, std::size_t globalTerms) {
  constexpr int kLanes = 4;
  double largestOf[kLanes][Count] = {}, t[kLanes][Count];
  std::size_t i = 0;
  // std::max skips a nan term; its parts, and so the sum, are nan.
  for (; i + kLanes <= n; i += kLanes)
    for (int l = 0; l < kLanes; ++l) {
      term(i + l, t[l]);
      for (int k = 0; k < Count; ++k) largestOf[l][k] = std::max(largestOf[l][k], std::fabs(t[l][k]));
    }
  for (; i < n; ++i) {
    term(i, t[0]);
    for (int k = 0; k < Count; ++k) largestOf[0][k] = std::max(largestOf[0][k], std::fabs(t[0][k]));
  }
  double largest[Count];
  for (int k = 0; k < Count; ++k) {
    largest[k] = largestOf[0][k];
    for (int l = 1; l < kLanes; ++l) largest[k] = std::max(largest[k], largestOf[l][k]);
  }
  foldedSumsOf<Count>(comm, n, term, largest, sums, globalTerms);
}
}  // namespace detail

/// The \p count sums over i < n (local) and over all ranks of the terms term(i, t) writes into
/// t[0 .. count) (count <= 4). term must give the same values when called again for the same i.
/// Collective. At most 2^26 terms per sum over all ranks (asserted). A sum with a non-finite term is
/// the ordinary sum (inf or nan).
///
/// \p globalTerms, when known to every rank without communication (a map's global number of
/// entries), is the number of terms over all ranks (asserted). Up to 2^17 terms the parts are then
/// two, of 53 - ceil(log2 globalTerms) bits, instead of three of 27 bits (a third less work); the
/// parts' error stays below 2^-54 max|term| either way. It must not depend on the partition: the number
/// of parts is part of the result's bits.
template <class Term>
void reproducibleSums(const Comm& comm, int count, std::size_t n, const Term& term, double* sums,
                      std::size_t globalTerms = 0) {
  switch (count) {
    case 1: return detail::reproducibleSumsOf<1>(comm, n, term, sums, globalTerms);
    case 2: return detail::reproducibleSumsOf<2>(comm, n, term, sums, globalTerms);
    case 3: return detail::reproducibleSumsOf<3>(comm, n, term, sums, globalTerms);
    case 4: return detail::reproducibleSumsOf<4>(comm, n, term, sums, globalTerms);
    default: SIGNORINI_ASSERT(false, "reproducibleSums: 1 to 4 sums at once");
  }
}

/// reproducibleSums for a caller that has already found this rank's largest |term| of each sum
/// (\p localLargest[k], the maximum of std::fabs over its local terms, 0 without terms; a nan term
/// skipped as std::max skips it), for instance in the loop that computed the terms' factors: one
/// pass over the terms instead of two, the same bits. \p localLargest is overwritten.
template <class Term>
void reproducibleSumsGivenLargest(const Comm& comm, int count, std::size_t n, const Term& term, double* localLargest,
                                  double* sums, std::size_t globalTerms = 0) {
  switch (count) {
    case 1: return detail::foldedSumsOf<1>(comm, n, term, localLargest, sums, globalTerms);
    case 2: return detail::foldedSumsOf<2>(comm, n, term, localLargest, sums, globalTerms);
    case 3: return detail::foldedSumsOf<3>(comm, n, term, localLargest, sums, globalTerms);
    case 4: return detail::foldedSumsOf<4>(comm, n, term, localLargest, sums, globalTerms);
    default: SIGNORINI_ASSERT(false, "reproducibleSumsGivenLargest: 1 to 4 sums at once");
  }
}

/// Process-wide switch of partition-independent arithmetic (off by default): where it is on, the
/// solvers and assemblers that support it order every sum so that its bits do not depend on the
/// number of ranks (docs/reproducibility.md lists which do). Set once by the driver from the deck.
void setReproducibleArithmetic(bool on);
/// Whether partition-independent arithmetic is on (setReproducibleArithmetic()).
bool reproducibleArithmetic();

/// One reproducible sum of \p n local terms.
inline double reproducibleSum(const Comm& comm, std::size_t n, const double* terms) {
  double s;
  reproducibleSums(comm, 1, n, [terms](std::size_t i, double* t) { t[0] = terms[i]; }, &s);
  return s;
}

}  // namespace signorini::core
