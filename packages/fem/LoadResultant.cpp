#include "signorini/fem/LoadResultant.hpp"

#include <array>
#include <string>

#include "signorini/core/Error.hpp"
#include "signorini/fem/LoadQuadrature.hpp"

namespace signorini::fem {

bool appliesLoads(const ProblemData& problem) {
  return !isZeroField(problem.bodyForce) || (problem.neumannMask != 0 && !isZeroField(problem.neumannData));
}

std::vector<double> loadResultant(const mesh::Q1Mesh& mesh, int components, const ProblemData& problem, double t,
                                  const std::array<double, 2>* momentPoint) {
  const int nc = components;
  const auto* const p = momentPoint;
  SIGNORINI_ASSERT(nc == 1 || nc == 2, "one or two unknowns per node");
  SIGNORINI_ASSERT(!p || nc == 2, "a moment needs two components");
  std::vector<std::array<double, 3>> terms;  // one per cell or Neumann edge
  std::string bad;                           // the first load sample that is not a finite number
  if (!isZeroField(problem.bodyForce)) {
    const auto& X = mesh.cornerCoordsHost;
    terms.reserve(static_cast<size_t>(mesh.numLocalCells()));
    for (LO e = 0; e < mesh.numLocalCells(); ++e) {
      double Xe[4][2], w[4], N[4][4], fq[4][2], xq[4][2];
      for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
      cellLoadPoints(Xe, problem.bodyForce, nc, t, bad, w, N, fq, xq);
      std::array<double, 3> term = {0.0, 0.0, 0.0};
      for (int q = 0; q < 4; ++q) {
        for (int c = 0; c < nc; ++c) term[c] += w[q] * fq[q][c];
        if (p) term[2] += w[q] * momentAbout(*p, xq[q][0], xq[q][1], fq[q][0], fq[q][1]);
      }
      terms.push_back(term);
    }
  }
  if (problem.neumannMask && !isZeroField(problem.neumannData))
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & problem.neumannMask)) continue;
      double s[2], wq[2][2];
      edgeLoadPoints(be, problem.neumannData, nc, t, bad, s, wq);
      double moment = 0;
      if (p)
        for (int g = 0; g < 2; ++g) {
          const auto x = be.at(s[g]);
          moment += momentAbout(*p, x[0], x[1], wq[g][0], wq[g][1]);
        }
      terms.push_back({wq[0][0] + wq[1][0], nc == 2 ? wq[0][1] + wq[1][1] : 0.0, moment});
    }
  return sumTermsOverRanks(mesh, nc + (p ? 1 : 0), terms, bad);
}

}  // namespace signorini::fem
