// The envelope Cholesky of the contact strip: exact solves of a shifted Laplacian on a thin grid
// in scrambled numbering (two components), a narrow envelope after the reverse Cuthill-McKee
// ordering, zero right-hand sides and a clear error for an indefinite matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "signorini/solvers/EnvelopeCholesky.hpp"
#include "signorini/core/Error.hpp"

using namespace signorini;

namespace {

/// 5-point Laplacian + shift * identity on grids of width x length nodes (one per entry of
/// \p lengths, uncoupled), numbered by a random permutation; CRS with both triangles.
struct GridMatrix {
  int n = 0;
  std::vector<int> rowPtr, cols;
  std::vector<double> values;
  GridMatrix(int width, const std::vector<int>& lengths, double shift, unsigned seed) {
    std::vector<std::vector<std::pair<int, double>>> rows;
    for (int length : lengths) {
      const int base = n;
      n += width * length;
      rows.resize(n);
      auto id = [&](int i, int j) { return base + i * width + j; };
      for (int i = 0; i < length; ++i)
        for (int j = 0; j < width; ++j) {
          auto& row = rows[id(i, j)];
          row.push_back({id(i, j), 4.0 + shift});
          if (i > 0) row.push_back({id(i - 1, j), -1.0});
          if (i + 1 < length) row.push_back({id(i + 1, j), -1.0});
          if (j > 0) row.push_back({id(i, j - 1), -1.0});
          if (j + 1 < width) row.push_back({id(i, j + 1), -1.0});
        }
    }
    std::vector<int> scramble(n);
    std::iota(scramble.begin(), scramble.end(), 0);
    std::shuffle(scramble.begin(), scramble.end(), std::mt19937(seed));
    std::vector<std::vector<std::pair<int, double>>> scrambled(n);
    for (int r = 0; r < n; ++r)
      for (auto [c, v] : rows[r]) scrambled[scramble[r]].push_back({scramble[c], v});
    rowPtr.assign(1, 0);
    for (const auto& row : scrambled) {
      for (auto [c, v] : row) cols.push_back(c), values.push_back(v);
      rowPtr.push_back(static_cast<int>(cols.size()));
    }
  }
  /// max_ij |(A X - B)_ij| for row-major n x m X and B.
  double residual(const std::vector<double>& X, const std::vector<double>& B, int m) const {
    double worst = 0;
    for (int r = 0; r < n; ++r)
      for (int j = 0; j < m; ++j) {
        double s = -B[static_cast<size_t>(r) * m + j];
        for (int k = rowPtr[r]; k < rowPtr[r + 1]; ++k) s += values[k] * X[static_cast<size_t>(cols[k]) * m + j];
        worst = std::max(worst, std::abs(s));
      }
    return worst;
  }
};

}  // namespace

TEST(EnvelopeCholesky, SolvesSeveralRightHandSidesExactly) {
  const int width = 5, m = 6;
  const GridMatrix A(width, {120, 40}, 0.3, 7);
  const solvers::EnvelopeCholesky L(A.n, A.rowPtr, A.cols, A.values);
  std::vector<double> B(static_cast<size_t>(A.n) * m, 0.0);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> row(0, A.n - 1);
  for (int j = 0; j < 4; ++j)  // sparse columns (like B's segments) at random rows
    for (int k = 0; k < 3; ++k) B[static_cast<size_t>(row(gen)) * m + j] = value(gen);
  for (int r = 0; r < A.n; ++r) B[static_cast<size_t>(r) * m + 4] = value(gen);  // a dense column; column 5 stays 0
  std::vector<double> X = B;
  L.solveInPlace(X, m);
  EXPECT_LT(A.residual(X, B, m), 1e-13);
  for (int r = 0; r < A.n; ++r) EXPECT_EQ(X[static_cast<size_t>(r) * m + 5], 0.0);
}

TEST(EnvelopeCholesky, OrdersAThinGridIntoANarrowEnvelope) {
  // Reverse Cuthill-McKee numbers a width-w grid level by level (levels of at most w nodes): at
  // most 2 w entries per row of L, where the scrambled numbering gives an envelope of order n^2.
  const int width = 4;
  const GridMatrix A(width, {300}, 0.0, 11);
  const solvers::EnvelopeCholesky L(A.n, A.rowPtr, A.cols, A.values);
  EXPECT_LE(L.envelopeSize(), static_cast<size_t>(A.n) * 2 * width);
}

namespace {

/// A graded strip in miniature: a grid of 3 x length fine nodes along x and one coarse node per
/// 32 fine columns behind it, coupled to the 32 nodes of the grid's inner row under it and to its
/// coarse neighbours (as a coarse cell reaches along many fine edges). Diagonally dominant.
/// position[r]: the node's x position (a coarse node at the middle of its span), for an ordering
/// along the strip.
struct HighwayStrip {
  int n = 0;
  std::vector<int> rowPtr, cols;
  std::vector<double> values;
  std::vector<double> position;
  explicit HighwayStrip(int length) {
    const int width = 3, span = 32, coarse = length / span;
    n = width * length + coarse;
    std::vector<std::vector<int>> adjacent(static_cast<size_t>(n));
    auto link = [&](int a, int b) { adjacent[a].push_back(b), adjacent[b].push_back(a); };
    auto fine = [&](int i, int j) { return i * width + j; };  // column i along x, row j
    position.assign(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < length; ++i)
      for (int j = 0; j < width; ++j) {
        position[fine(i, j)] = i;
        if (i + 1 < length) link(fine(i, j), fine(i + 1, j));
        if (j + 1 < width) link(fine(i, j), fine(i, j + 1));
      }
    for (int c = 0; c < coarse; ++c) {
      const int id = width * length + c;
      position[id] = c * span + span / 2 - 0.5;
      for (int i = c * span; i < (c + 1) * span; ++i) link(id, fine(i, width - 1));
      if (c > 0) link(id, id - 1);
    }
    rowPtr.assign(1, 0);
    for (int r = 0; r < n; ++r) {
      cols.push_back(r), values.push_back(static_cast<double>(adjacent[r].size()) + 0.5);
      for (int c : adjacent[r]) cols.push_back(c), values.push_back(-1.0);
      rowPtr.push_back(static_cast<int>(cols.size()));
    }
  }
  std::vector<int> orderAlongX() const {
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return position[a] < position[b]; });
    return order;
  }
};

}  // namespace

TEST(EnvelopeCholesky, TakesAPreferredOrderingThatHalvesTheEnvelope) {
  // The breadth-first levels of reverse Cuthill-McKee run along the coarse nodes, so each level
  // holds the fine nodes under several coarse ones; ordered along x the envelope stays narrow.
  const HighwayStrip A(1024);
  const solvers::EnvelopeCholesky rcm(A.n, A.rowPtr, A.cols, A.values);
  const solvers::EnvelopeCholesky along(A.n, A.rowPtr, A.cols, A.values, A.orderAlongX());
  EXPECT_FALSE(rcm.usesPreferredOrdering());
  ASSERT_TRUE(along.usesPreferredOrdering()) << "envelope " << rcm.envelopeSize();
  EXPECT_LE(2 * along.envelopeSize(), rcm.envelopeSize());
  // Both solve A x = b to rounding.
  const int m = 2;
  std::vector<double> B(static_cast<size_t>(A.n) * m);
  for (int r = 0; r < A.n; ++r) B[2 * r] = std::sin(0.1 * r), B[2 * r + 1] = r % 7 == 0 ? 1.0 : 0.0;
  for (const auto* L : {&rcm, &along}) {
    std::vector<double> X = B;
    L->solveInPlace(X, m);
    for (int r = 0; r < A.n; ++r)
      for (int j = 0; j < m; ++j) {
        double s = -B[static_cast<size_t>(r) * m + j];
        for (int k = A.rowPtr[r]; k < A.rowPtr[r + 1]; ++k) s += A.values[k] * X[static_cast<size_t>(A.cols[k]) * m + j];
        EXPECT_LE(std::abs(s), 1e-12) << "row " << r << ", column " << j;
      }
  }
}

TEST(EnvelopeCholesky, KeepsReverseCuthillMcKeeAgainstAWorseOrdering) {
  // A scrambled "preferred" ordering of a plain thin grid is far worse than reverse Cuthill-McKee
  // and is declined. (An ordering along such a grid is no better than reverse Cuthill-McKee
  // either: StripSchurApproximation.OrdersAGradedStripAlongTheContactBoundary, uniform case.)
  const int width = 4;
  const GridMatrix A(width, {300}, 0.0, 11);
  const solvers::EnvelopeCholesky rcm(A.n, A.rowPtr, A.cols, A.values);
  std::vector<int> identity(static_cast<size_t>(A.n));  // the scrambled numbering itself
  std::iota(identity.begin(), identity.end(), 0);
  const solvers::EnvelopeCholesky declined(A.n, A.rowPtr, A.cols, A.values, identity);
  EXPECT_FALSE(declined.usesPreferredOrdering());
  EXPECT_EQ(declined.envelopeSize(), rcm.envelopeSize());
}

TEST(EnvelopeCholesky, RejectsAnIndefiniteMatrix) {
  const GridMatrix A(3, {10}, -4.5, 5);  // the shift moves eigenvalues below zero
  try {
    solvers::EnvelopeCholesky L(A.n, A.rowPtr, A.cols, A.values);
    FAIL() << "an indefinite matrix was factored";
  } catch (const core::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos);
  }
}
