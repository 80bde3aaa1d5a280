#include "signorini/fem/DirichletRowSums.hpp"

#include <array>
#include <string>

#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/fem/Q1Kernels.hpp"

namespace signorini::fem {

std::vector<double> sumDirichletRows(const DirichletRowsInput& in, const Vector& uOverlap, const Vector& aOverlap,
                                     double t) {
  const auto& mesh = *in.mesh;
  const int nc = in.components;
  const auto& held = *in.held;
  SIGNORINI_ASSERT(nc == 1 || nc == 2, "one or two unknowns per node");
  SIGNORINI_ASSERT(held.size() == uOverlap.getLocalLength() && held.size() == aOverlap.getLocalLength(),
                   "u, a and the Dirichlet flags on the overlap unknowns");
  const auto lumped = [&](LO unknown) { return in.lumped && !in.lumped->empty() && (*in.lumped)[unknown]; };
  const auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto ah = aOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& X = mesh.cornerCoordsHost;
  const auto& dofs = mesh.cornerDofsHost;
  const auto& wts = mesh.cornerWeightsHost;
  bool loaded = false;  // a body force that is not the constant 0
  for (int c = 0; c < nc; ++c)
    loaded |= !((*in.bodyForce)[c].isConstant() && (*in.bodyForce)[c](0, 0, 0) == 0.0);
  std::vector<std::array<double, 2>> terms;  // one per cell or edge with a Dirichlet unknown
  std::string bad;                           // the first load sample that is not a finite number
  for (LO e = 0; e < mesh.numLocalCells(); ++e) {
    bool touches = false;
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < nc; ++i)
          touches |= dofs(e, a, k) >= 0 && held[nc * dofs(e, a, k) + i];
    if (!touches) continue;
    double Xe[4][2], Me[4][4], Ke[8][8], be[4][2] = {};
    for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
    in.element(Xe, Me, Ke);
    if (loaded)  // as the assemblers' load kernels
      for (int q = 0; q < 4; ++q) {
        double N[4], gx[4], gy[4];
        const double w = kGauss2Weight * kGauss2Weight * q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, gx, gy);
        double x = 0, y = 0;
        for (int c = 0; c < 4; ++c) x += N[c] * Xe[c][0], y += N[c] * Xe[c][1];
        for (int c = 0; c < nc; ++c) {
          const double f = (*in.bodyForce)[c].sample(x, y, t, bad);
          for (int a = 0; a < 4; ++a) be[a][c] += w * f * N[a];
        }
      }
    std::array<double, 2> term = {0.0, 0.0};
    for (int a = 0; a < 4; ++a)
      for (int ka = 0; ka < 2; ++ka) {
        const LO na = dofs(e, a, ka);
        if (na < 0) continue;
        for (int i = 0; i < nc; ++i) {
          const LO row = nc * na + i;
          if (!held[row]) continue;
          double sum = -be[a][i];
          for (int b = 0; b < 4; ++b)
            for (int kb = 0; kb < 2; ++kb) {
              const LO nb = dofs(e, b, kb);
              if (nb < 0) continue;
              double v = 0;
              for (int j = 0; j < nc; ++j) {
                const LO col = nc * nb + j;
                v += Ke[nc * a + i][nc * b + j] * uh(col, 0);
                // A mass coupling of a lumped unknown sits on the diagonal, where a is 0.
                if (i == j && (row == col || !(lumped(row) || lumped(col)))) v += Me[a][b] * ah(col, 0);
              }
              sum += wts(e, b, kb) * v;
            }
          term[i] += wts(e, a, ka) * sum;
        }
      }
    terms.push_back(term);
  }
  if (in.neumannMask)
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & in.neumannMask)) continue;
      bool touches = false;
      for (int p = 0; p < 2; ++p)
        for (int i = 0; i < nc; ++i) touches |= held[nc * be.node[p] + i] != 0;
      if (!touches) continue;
      std::array<double, 2> term = {0.0, 0.0};
      for (int g = 0; g < 2; ++g) {  // as the assemblers' traction kernels
        const double s = gauss2Point(g);
        for (int c = 0; c < nc; ++c) {
          const double q = (*in.neumann)[c].sample((1 - s) * be.x[0][0] + s * be.x[1][0],
                                                   (1 - s) * be.x[0][1] + s * be.x[1][1], t, bad);
          const double v = kGauss2Weight * be.length() * q;
          if (held[nc * be.node[0] + c]) term[c] -= v * (1 - s);
          if (held[nc * be.node[1] + c]) term[c] -= v * s;
        }
      }
      terms.push_back(term);
    }
  core::throwFirstUserError(*mesh.comm(), bad);
  std::vector<double> sums(nc, 0.0);
  core::reproducibleSums(*mesh.comm(), nc, terms.size(),
                         [&](std::size_t k, double* out) {
                           for (int c = 0; c < nc; ++c) out[c] = terms[k][c];
                         },
                         sums.data());
  return sums;
}

}  // namespace signorini::fem
