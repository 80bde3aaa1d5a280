#pragma once
/// \file Q1Kernels.hpp
/// Bilinear shape functions on the reference square [0,1]^2 (corners in z-order) and the
/// isoparametric map of a quadrilateral cell; device functions for the assembly kernels.
#include <Kokkos_Core.hpp>

namespace signorini::fem {

/// Gauss points on [0,1]: 2-point rule (exact for cubics).
KOKKOS_INLINE_FUNCTION double gauss2Point(int i) { return i == 0 ? 0.21132486540518713 : 0.78867513459481287; }
constexpr double kGauss2Weight = 0.5;

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

}  // namespace signorini::fem
