// The envelope Cholesky of the contact strip: exact solves of a shifted Laplacian on a thin grid
// in scrambled numbering (two components), a narrow envelope after the reverse Cuthill-McKee
// ordering, zero right-hand sides and a clear error for an indefinite matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "EnvelopeCholesky.hpp"
#include "Error.hpp"

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

TEST(EnvelopeCholesky, RejectsAnIndefiniteMatrix) {
  const GridMatrix A(3, {10}, -4.5, 5);  // the shift moves eigenvalues below zero
  try {
    solvers::EnvelopeCholesky L(A.n, A.rowPtr, A.cols, A.values);
    FAIL() << "an indefinite matrix was factored";
  } catch (const core::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos);
  }
}
