#include "signorini/fem/LoadResultant.hpp"

#include <array>
#include <string>

#include "signorini/core/Error.hpp"
#include "signorini/fem/LoadQuadrature.hpp"

namespace signorini::fem {

bool appliesLoads(const ProblemData& problem) {
  return !isZeroField(problem.bodyForce) || (problem.neumannMask != 0 && !isZeroField(problem.neumannData));
}

std::vector<double> loadResultant(const mesh::Q1Mesh& mesh, int components, const ProblemData& problem, double t) {
  const int nc = components;
  SIGNORINI_ASSERT(nc == 1 || nc == 2, "one or two unknowns per node");
  std::vector<std::array<double, 2>> terms;  // one per cell or Neumann edge
  std::string bad;                           // the first load sample that is not a finite number
  if (!isZeroField(problem.bodyForce)) {
    const auto& X = mesh.cornerCoordsHost;
    terms.reserve(static_cast<size_t>(mesh.numLocalCells()));
    for (LO e = 0; e < mesh.numLocalCells(); ++e) {
      double Xe[4][2], w[4], N[4][4], fq[4][2];
      for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
      cellLoadPoints(Xe, problem.bodyForce, nc, t, bad, w, N, fq);
      std::array<double, 2> term = {0.0, 0.0};
      for (int q = 0; q < 4; ++q)
        for (int c = 0; c < nc; ++c) term[c] += w[q] * fq[q][c];
      terms.push_back(term);
    }
  }
  if (problem.neumannMask && !isZeroField(problem.neumannData))
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & problem.neumannMask)) continue;
      double s[2], wq[2][2];
      edgeLoadPoints(be, problem.neumannData, nc, t, bad, s, wq);
      terms.push_back({wq[0][0] + wq[1][0], nc == 2 ? wq[0][1] + wq[1][1] : 0.0});
    }
  return sumTermsOverRanks(mesh, nc, terms, bad);
}

}  // namespace signorini::fem
