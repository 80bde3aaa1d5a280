#pragma once
/// \file LoadQuadrature.hpp
/// The loads' quadrature as the assemblers' load kernels take it, on the host, moments in the plane,
/// and the sum of per-cell or per-edge terms over the ranks (internal to the fem package:
/// sumDirichletRows, loadResultant and ContactCoupling's moments).
#include <array>
#include <string>
#include <vector>

#include "signorini/core/Expression.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

/// Whether every component of \p f is the constant 0.
inline bool isZeroField(const core::ExpressionList& f) {
  for (int c = 0; c < f.size(); ++c)
    if (!(f[c].isConstant() && f[c](0, 0, 0) == 0.0)) return false;
  return true;
}

/// The 2 x 2 Gauss points of the cell with corners \p Xe: weights w[q] (|det J| included), shape
/// values N[q][a], the points xq[q] and the first \p nc components of \p f there (fq[q][c]); the
/// first sample that is not a finite number goes to \p bad.
inline void cellLoadPoints(const double Xe[4][2], const core::ExpressionList& f, int nc, double t, std::string& bad,
                           double w[4], double N[4][4], double fq[4][2], double xq[4][2]) {
  for (int q = 0; q < 4; ++q) {
    double gx[4], gy[4];
    w[q] = kGauss2Weight * kGauss2Weight * q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N[q], gx, gy);
    double x = 0, y = 0;
    for (int c = 0; c < 4; ++c) x += N[q][c] * Xe[c][0], y += N[q][c] * Xe[c][1];
    xq[q][0] = x, xq[q][1] = y;
    for (int c = 0; c < nc; ++c) fq[q][c] = f[c].sample(x, y, t, bad);
  }
}

/// The 2 Gauss points of boundary edge \p be: their place s[g] along it (0 at node[0]) and
/// weight times \p q's component c there, wq[g][c] (the edge's length included).
inline void edgeLoadPoints(const mesh::BoundaryEdge& be, const core::ExpressionList& q, int nc, double t,
                           std::string& bad, double s[2], double wq[2][2]) {
  for (int g = 0; g < 2; ++g) {
    s[g] = gauss2Point(g);
    for (int c = 0; c < nc; ++c)
      wq[g][c] = kGauss2Weight * be.length() *
                 q[c].sample((1 - s[g]) * be.x[0][0] + s[g] * be.x[1][0], (1 - s[g]) * be.x[0][1] + s[g] * be.x[1][1],
                             t, bad);
  }
}

/// The moment about \p p of a force \p f [force] acting at \p x (plane: the z component of
/// (x - p) x f), or equally the weight r_c(x) of the rigid rotation r(x) = (-(y - p_y), x - p_x)
/// for component c of a force.
inline double momentAbout(const std::array<double, 2>& p, double x, double y, double fx, double fy) {
  return (x - p[0]) * fy - (y - p[1]) * fx;
}

/// The first \p count (at most 3) sums over all ranks of \p terms (one per cell or edge), after the
/// first bad sample of any rank (\p bad) is thrown as a user error. Collective; partition-independent bits.
inline std::vector<double> sumTermsOverRanks(const mesh::Q1Mesh& mesh, int count,
                                             const std::vector<std::array<double, 3>>& terms, const std::string& bad) {
  core::throwFirstUserError(*mesh.comm(), bad);
  std::vector<double> sums(count, 0.0);
  core::reproducibleSums(*mesh.comm(), count, terms.size(),
                         [&](std::size_t k, double* out) {
                           for (int c = 0; c < count; ++c) out[c] = terms[k][c];
                         },
                         sums.data());
  return sums;
}

}  // namespace signorini::fem
