#include "signorini/solvers/EnvelopeCholesky.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "signorini/core/Error.hpp"

namespace signorini::solvers {

namespace {
/// Reverse Cuthill-McKee: breadth-first from a pseudo-peripheral node of each connected
/// component, neighbours by increasing degree; returns order[p] = node at position p.
std::vector<int> reverseCuthillMcKee(int n, const std::vector<int>& rowPtr, const std::vector<int>& cols) {
  std::vector<int> degree(n);
  for (int i = 0; i < n; ++i) degree[i] = rowPtr[i + 1] - rowPtr[i];
  std::vector<int> order, level(n, -1), scratch;
  order.reserve(n);
  std::vector<char> placed(n, 0);
  // Breadth-first levels from s over the unplaced nodes; returns a node of the last level of least degree.
  auto farthest = [&](int s, int& depth) {
    scratch.assign(1, s);
    level[s] = 0;
    for (size_t h = 0; h < scratch.size(); ++h)
      for (int k = rowPtr[scratch[h]]; k < rowPtr[scratch[h] + 1]; ++k)
        if (!placed[cols[k]] && level[cols[k]] < 0) level[cols[k]] = level[scratch[h]] + 1, scratch.push_back(cols[k]);
    depth = level[scratch.back()];
    int best = scratch.back();
    for (int v : scratch) {
      if (level[v] == depth && degree[v] < degree[best]) best = v;
      level[v] = -1;
    }
    return best;
  };
  for (int seed = 0; seed < n; ++seed) {
    if (placed[seed]) continue;
    int start = seed, depth = 0, next = farthest(start, depth);
    for (int round = 0; round < 4; ++round) {  // pseudo-peripheral: until the eccentricity stops growing
      int nextDepth = 0;
      const int candidate = farthest(next, nextDepth);
      if (nextDepth <= depth) break;
      start = next, next = candidate, depth = nextDepth;
    }
    const size_t begin = order.size();
    order.push_back(start);
    placed[start] = 1;
    for (size_t h = begin; h < order.size(); ++h) {
      const size_t before = order.size();
      for (int k = rowPtr[order[h]]; k < rowPtr[order[h] + 1]; ++k)
        if (!placed[cols[k]]) placed[cols[k]] = 1, order.push_back(cols[k]);
      std::stable_sort(order.begin() + before, order.end(), [&](int a, int b) { return degree[a] < degree[b]; });
    }
  }
  std::reverse(order.begin(), order.end());
  return order;
}
}  // namespace

EnvelopeCholesky::EnvelopeCholesky(int n, const std::vector<int>& rowPtr, const std::vector<int>& cols,
                                   const std::vector<double>& values, const std::vector<int>& preferred)
    : n_(n) {
  SIGNORINI_ASSERT(static_cast<int>(rowPtr.size()) == n + 1 && cols.size() == values.size() &&
                       static_cast<size_t>(rowPtr[n]) == cols.size(),
                   "inconsistent CRS arrays");
  std::vector<int> pos(n);
  // The envelope of an ordering: first_, off_ and pos for it.
  auto envelope = [&](const std::vector<int>& order) {
    for (int p = 0; p < n; ++p) pos[order[p]] = p;
    first_.assign(n, 0);
    off_.assign(n + 1, 0);
    for (int p = 0; p < n; ++p) {
      int f = p;
      for (int k = rowPtr[order[p]]; k < rowPtr[order[p] + 1]; ++k) f = std::min(f, pos[cols[k]]);
      first_[p] = f;
      off_[p + 1] = off_[p] + static_cast<size_t>(p - f + 1);
    }
    return off_[n];
  };
  perm_ = reverseCuthillMcKee(n, rowPtr, cols);
  if (!preferred.empty()) {
    SIGNORINI_ASSERT(static_cast<int>(preferred.size()) == n, "the preferred ordering must be a permutation");
    {
      std::vector<char> seen(n, 0);
      for (int r : preferred) {
        SIGNORINI_ASSERT(r >= 0 && r < n && !seen[r], "the preferred ordering must be a permutation");
        seen[r] = 1;
      }
    }
    const size_t rcm = envelope(perm_);
    preferred_ = 2 * envelope(preferred) <= rcm;
    if (preferred_) perm_ = preferred;
  }
  envelope(perm_);
  env_.assign(off_[n], 0.0);
  for (int p = 0; p < n; ++p)
    for (int k = rowPtr[perm_[p]]; k < rowPtr[perm_[p] + 1]; ++k)
      if (pos[cols[k]] <= p) env_[off_[p] + (pos[cols[k]] - first_[p])] += values[k];
  // Row by row: L(p,q) = (A(p,q) - sum_k L(p,k) L(q,k)) / L(q,q) within the envelope.
  for (int p = 0; p < n; ++p) {
    double* Lp = env_.data() + off_[p] - first_[p];  // Lp[q] = L(p,q)
    for (int q = first_[p]; q < p; ++q) {
      const double* Lq = env_.data() + off_[q] - first_[q];
      double s = Lp[q];
      for (int k = std::max(first_[p], first_[q]); k < q; ++k) s -= Lp[k] * Lq[k];
      Lp[q] = s / Lq[q];
    }
    double d = Lp[p];
    for (int k = first_[p]; k < p; ++k) d -= Lp[k] * Lp[k];
    if (!(d > 0))
      throw core::SolverError("Cholesky factorisation: pivot " + std::to_string(d) + " at row " +
                              std::to_string(perm_[p]) + " (the matrix is not positive definite)");
    Lp[p] = std::sqrt(d);
  }
}

void EnvelopeCholesky::solveInPlace(std::vector<double>& X, int m) const {
  const int n = n_;
  SIGNORINI_ASSERT(X.size() == static_cast<size_t>(n) * m, "X must be n x m");
  if (n == 0 || m == 0) return;
  // Columns sorted by their first non-zero position: at position p only the first live[p] are non-zero.
  std::vector<int> start(m, n);
  for (int p = 0; p < n; ++p)
    for (int j = 0; j < m; ++j)
      if (start[j] == n && X[static_cast<size_t>(perm_[p]) * m + j] != 0.0) start[j] = p;
  std::vector<int> colOrder(m);
  std::iota(colOrder.begin(), colOrder.end(), 0);
  std::stable_sort(colOrder.begin(), colOrder.end(), [&](int a, int b) { return start[a] < start[b]; });
  std::vector<int> live(n);
  for (int p = 0, c = 0; p < n; ++p) {
    while (c < m && start[colOrder[c]] <= p) ++c;
    live[p] = c;
  }
  std::vector<double> Y(X.size());
  for (int p = 0; p < n; ++p)
    for (int c = 0; c < m; ++c) Y[static_cast<size_t>(p) * m + c] = X[static_cast<size_t>(perm_[p]) * m + colOrder[c]];
  // L Y = B (rows below a column's start stay zero), then L^T X = Y.
  for (int p = 0; p < n; ++p) {
    const double* Lp = env_.data() + off_[p] - first_[p];
    double* yp = Y.data() + static_cast<size_t>(p) * m;
    for (int k = first_[p]; k < p; ++k) {
      const double l = Lp[k];
      const double* yk = Y.data() + static_cast<size_t>(k) * m;
      for (int c = 0; c < live[k]; ++c) yp[c] -= l * yk[c];
    }
    const double inv = 1.0 / Lp[p];
    for (int c = 0; c < live[p]; ++c) yp[c] *= inv;
  }
  for (int p = n - 1; p >= 0; --p) {
    const double* Lp = env_.data() + off_[p] - first_[p];
    double* yp = Y.data() + static_cast<size_t>(p) * m;
    const double inv = 1.0 / Lp[p];
    for (int c = 0; c < m; ++c) yp[c] *= inv;
    for (int k = first_[p]; k < p; ++k) {
      const double l = Lp[k];
      double* yk = Y.data() + static_cast<size_t>(k) * m;
      for (int c = 0; c < m; ++c) yk[c] -= l * yp[c];
    }
  }
  for (int p = 0; p < n; ++p)
    for (int c = 0; c < m; ++c) X[static_cast<size_t>(perm_[p]) * m + colOrder[c]] = Y[static_cast<size_t>(p) * m + c];
}

}  // namespace signorini::solvers
