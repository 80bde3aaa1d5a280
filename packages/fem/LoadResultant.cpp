#include "signorini/fem/LoadResultant.hpp"

#include <array>
#include <string>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/fem/Q1Kernels.hpp"

namespace signorini::fem {

namespace {
bool isZero(const core::ExpressionList& f) {
  for (int c = 0; c < f.size(); ++c)
    if (!(f[c].isConstant() && f[c](0, 0, 0) == 0.0)) return false;
  return true;
}
}  // namespace

bool appliesLoads(const ProblemData& problem) {
  return !isZero(problem.bodyForce) || (problem.neumannMask != 0 && !isZero(problem.neumannData));
}

std::vector<double> loadResultant(const mesh::Q1Mesh& mesh, int components, const ProblemData& problem, double t) {
  const int nc = components;
  SIGNORINI_ASSERT(nc == 1 || nc == 2, "one or two unknowns per node");
  std::vector<std::array<double, 2>> terms;  // one per cell or Neumann edge
  std::string bad;                           // the first load sample that is not a finite number
  if (!isZero(problem.bodyForce)) {
    const auto& X = mesh.cornerCoordsHost;
    terms.reserve(static_cast<size_t>(mesh.numLocalCells()));
    for (LO e = 0; e < mesh.numLocalCells(); ++e) {
      double Xe[4][2];
      for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
      std::array<double, 2> term = {0.0, 0.0};
      for (int q = 0; q < 4; ++q) {  // as the assemblers' load kernels
        double N[4], gx[4], gy[4];
        const double w = kGauss2Weight * kGauss2Weight * q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, gx, gy);
        double x = 0, y = 0;
        for (int c = 0; c < 4; ++c) x += N[c] * Xe[c][0], y += N[c] * Xe[c][1];
        for (int c = 0; c < nc; ++c) term[c] += w * problem.bodyForce[c].sample(x, y, t, bad);
      }
      terms.push_back(term);
    }
  }
  if (problem.neumannMask && !isZero(problem.neumannData))
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & problem.neumannMask)) continue;
      std::array<double, 2> term = {0.0, 0.0};
      for (int g = 0; g < 2; ++g) {  // as the assemblers' traction kernels
        const double s = gauss2Point(g);
        for (int c = 0; c < nc; ++c)
          term[c] += kGauss2Weight * be.length() *
                     problem.neumannData[c].sample((1 - s) * be.x[0][0] + s * be.x[1][0],
                                                   (1 - s) * be.x[0][1] + s * be.x[1][1], t, bad);
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
