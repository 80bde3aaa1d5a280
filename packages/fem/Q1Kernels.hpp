#pragma once
/// \file Q1Kernels.hpp
/// Bilinear shape functions on the reference square [0,1]^2 (corners in z-order) and the
/// isoparametric map of a quadrilateral cell; device functions for the assembly kernels.
#include <Kokkos_Core.hpp>

namespace signorini::fem {

/// Gauss points on [0,1]: 2-point rule (exact for cubics).
KOKKOS_INLINE_FUNCTION double gauss2Point(int i) { return i == 0 ? 0.21132486540518713 : 0.78867513459481287; }
constexpr double kGauss2Weight = 0.5;  ///< weight of each gauss2Point()
/// Gauss points and weights on [0,1]: 3-point rule (exact for quintics), for host loops (edges,
/// error norms, the mean gaps of the contact segments).
constexpr double kGauss3Point[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
constexpr double kGauss3Weight[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};  ///< weights of kGauss3Point (sum 1)

/// Shape function values N_c(s, r) and reference gradients.
KOKKOS_INLINE_FUNCTION void q1Shape(double s, double r, double N[4], double dNds[4], double dNdr[4]) {
  for (int c = 0; c < 4; ++c) {
    const double fs = (c & 1) ? s : 1 - s, fr = (c & 2) ? r : 1 - r;
    const double ds = (c & 1) ? 1 : -1, dr = (c & 2) ? 1 : -1;
    N[c] = fs * fr;
    dNds[c] = ds * fr;
    dNdr[c] = fs * dr;
  }
}

/// Physical gradients of the shape functions at (s, r) of the cell with corners X[c][d];
/// returns det J (positive for a valid cell).
KOKKOS_INLINE_FUNCTION double q1Gradients(const double X[4][2], double s, double r, double N[4], double gx[4],
                                          double gy[4]) {
  double dNds[4], dNdr[4];
  q1Shape(s, r, N, dNds, dNdr);
  double J00 = 0, J01 = 0, J10 = 0, J11 = 0;  // J = d(x,y)/d(s,r)
  for (int c = 0; c < 4; ++c) {
    J00 += X[c][0] * dNds[c];
    J01 += X[c][0] * dNdr[c];
    J10 += X[c][1] * dNds[c];
    J11 += X[c][1] * dNdr[c];
  }
  const double det = J00 * J11 - J01 * J10;
  for (int c = 0; c < 4; ++c) {
    gx[c] = (J11 * dNds[c] - J10 * dNdr[c]) / det;
    gy[c] = (-J01 * dNds[c] + J00 * dNdr[c]) / det;
  }
  return det;
}

/// Whether the cell with corners X (z-order) is a parallelogram (every rectangle is): then its map
/// is affine, gradients of Q1 fields are linear along each face and the element matrices have
/// closed forms.
KOKKOS_INLINE_FUNCTION bool isParallelogram(const double X[4][2]) {
  using Kokkos::Experimental::fabs;
  const double dx = X[0][0] + X[3][0] - X[1][0] - X[2][0];
  const double dy = X[0][1] + X[3][1] - X[1][1] - X[2][1];
  const double size = fabs(X[3][0] - X[0][0]) + fabs(X[3][1] - X[0][1]);
  return fabs(dx) + fabs(dy) <= 1e-13 * size;
}

/// 36 times the Q1 mass matrix of the unit square (z-order): 4 on the diagonal, 2 along an edge,
/// 1 across the diagonal.
KOKKOS_INLINE_FUNCTION double q1Mass36(int a, int b) { return a == b ? 4.0 : (a ^ b) == 3 ? 1.0 : 2.0; }

/// Exact mass (int phi_a phi_b) and stiffness (int grad phi_a . grad phi_b) matrices of the
/// parallelogram with corners X. With x_s = X1 - X0, x_r = X2 - X0 and the reference matrices
/// S_ss, S_rr, S_sr of the derivative pairs: K = (|x_r|^2 S_ss - x_s.x_r (S_sr + S_sr^T) + |x_s|^2 S_rr) / |det J|.
KOKKOS_INLINE_FUNCTION void q1ParallelogramMatrices(const double X[4][2], double M[4][4], double K[4][4]) {
  const double xs0 = X[1][0] - X[0][0], xs1 = X[1][1] - X[0][1];
  const double xr0 = X[2][0] - X[0][0], xr1 = X[2][1] - X[0][1];
  const double det = Kokkos::Experimental::fabs(xs0 * xr1 - xs1 * xr0);
  const double ss = xs0 * xs0 + xs1 * xs1, rr = xr0 * xr0 + xr1 * xr1, sr = xs0 * xr0 + xs1 * xr1;
  // Both matrices are symmetric (each term below is symmetric in a and b, bit for bit).
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      // signs of d phi / ds and d phi / dr (constant up to a factor 1 - r or r, 1 - s or s)
      const double sa = (a & 1) ? 1.0 : -1.0, sb = (b & 1) ? 1.0 : -1.0;
      const double ra = (a & 2) ? 1.0 : -1.0, rb = (b & 2) ? 1.0 : -1.0;
      const double Sss = sa * sb * (((a & 2) == (b & 2)) ? 2.0 : 1.0) / 6;
      const double Srr = ra * rb * (((a & 1) == (b & 1)) ? 2.0 : 1.0) / 6;
      const double SsrSym = (sa * rb + sb * ra) / 4;
      M[a][b] = M[b][a] = det * q1Mass36(a, b) / 36;
      K[a][b] = K[b][a] = (rr * Sss - sr * SsrSym + ss * Srr) / det;
    }
}

/// Mass (times cm) and stiffness (times ck) matrices of the cell with corners X: closed forms on
/// parallelograms (2x2 Gauss is exact there too), 2x2 Gauss otherwise.
KOKKOS_INLINE_FUNCTION void q1ElementMatrices(const double X[4][2], double cm, double ck, double M[4][4], double K[4][4]) {
  if (isParallelogram(X)) {
    q1ParallelogramMatrices(X, M, K);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) M[a][b] *= cm, K[a][b] *= ck;
    return;
  }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) M[a][b] = K[a][b] = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double N[4], gx[4], gy[4];
      const double w = kGauss2Weight * kGauss2Weight * q1Gradients(X, gauss2Point(i), gauss2Point(j), N, gx, gy);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          M[a][b] += w * cm * N[a] * N[b];
          K[a][b] += w * ck * (gx[a] * gx[b] + gy[a] * gy[b]);
        }
    }
}

}  // namespace signorini::fem
