#include "signorini/fem/DirichletRowSums.hpp"

#include <array>
#include <string>

#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/fem/LoadQuadrature.hpp"

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
  SIGNORINI_ASSERT(!in.rows || in.rows->size() == held.size(), "row flags on the overlap unknowns");
  const auto summed = [&](LO unknown) { return held[unknown] && (!in.rows || (*in.rows)[unknown]); };
  const auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto ah = aOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& X = mesh.cornerCoordsHost;
  const auto& dofs = mesh.cornerDofsHost;
  const auto& wts = mesh.cornerWeightsHost;
  const bool loaded = !isZeroField(*in.bodyForce);
  const auto* const p = in.momentPoint;
  SIGNORINI_ASSERT(!p || nc == 2, "a moment needs two components");
  const auto& nodeX = mesh.nodeCoords();
  // r_i at overlap node n: the weight of its component i in the moment about p
  const auto rotation = [&](LO n, int i) { return momentAbout(*p, nodeX[n][0], nodeX[n][1], i == 0, i == 1); };
  std::vector<std::array<double, 3>> terms;  // one per cell or edge with a Dirichlet unknown
  std::string bad;                           // the first load sample that is not a finite number
  for (LO e = 0; e < mesh.numLocalCells(); ++e) {
    bool touches = false;
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < nc; ++i)
          touches |= dofs(e, a, k) >= 0 && summed(nc * dofs(e, a, k) + i);
    if (!touches) continue;
    double Xe[4][2], Me[4][4], Ke[8][8], be[4][2] = {};
    for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
    in.element(Xe, Me, Ke);
    if (loaded) {  // as the assemblers' load kernels
      double w[4], N[4][4], fq[4][2], xq[4][2];
      cellLoadPoints(Xe, *in.bodyForce, nc, t, bad, w, N, fq, xq);
      for (int q = 0; q < 4; ++q)
        for (int c = 0; c < nc; ++c)
          for (int a = 0; a < 4; ++a) be[a][c] += w[q] * fq[q][c] * N[q][a];
    }
    std::array<double, 3> term = {0.0, 0.0, 0.0};
    for (int a = 0; a < 4; ++a)
      for (int ka = 0; ka < 2; ++ka) {
        const LO na = dofs(e, a, ka);
        if (na < 0) continue;
        for (int i = 0; i < nc; ++i) {
          const LO row = nc * na + i;
          if (!summed(row)) continue;
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
          if (p) term[2] += wts(e, a, ka) * sum * rotation(na, i);
        }
      }
    terms.push_back(term);
  }
  if (in.neumannMask)
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & in.neumannMask)) continue;
      bool touches = false;
      for (int p = 0; p < 2; ++p)
        for (int i = 0; i < nc; ++i) touches |= summed(nc * be.node[p] + i);
      if (!touches) continue;
      std::array<double, 3> term = {0.0, 0.0, 0.0};
      double s[2], wq[2][2];  // as the assemblers' traction kernels
      edgeLoadPoints(be, *in.neumann, nc, t, bad, s, wq);
      for (int g = 0; g < 2; ++g)
        for (int c = 0; c < nc; ++c)
          for (int end = 0; end < 2; ++end) {
            const LO n = be.node[end];
            if (!summed(nc * n + c)) continue;
            const double share = wq[g][c] * (end ? s[g] : 1 - s[g]);
            term[c] -= share;
            if (p) term[2] -= share * rotation(n, c);
          }
      terms.push_back(term);
    }
  return sumTermsOverRanks(mesh, nc + (p ? 1 : 0), terms, bad);
}

void massTimesField(const DirichletRowsInput& in, const Vector& fieldOverlap, Vector& outOverlap) {
  const auto& mesh = *in.mesh;
  const int nc = in.components;
  SIGNORINI_ASSERT(fieldOverlap.getLocalLength() == in.held->size() && outOverlap.getLocalLength() == in.held->size(),
                   "w and M w on the overlap unknowns");
  const auto lumped = [&](LO unknown) { return in.lumped && !in.lumped->empty() && (*in.lumped)[unknown]; };
  const auto w = fieldOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto out = outOverlap.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (size_t i = 0; i < out.extent(0); ++i) out(i, 0) = 0.0;
  const auto& X = mesh.cornerCoordsHost;
  const auto& dofs = mesh.cornerDofsHost;
  const auto& wts = mesh.cornerWeightsHost;
  for (LO e = 0; e < mesh.numLocalCells(); ++e) {
    double Xe[4][2], Me[4][4], Ke[8][8];
    for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
    in.element(Xe, Me, Ke);
    for (int a = 0; a < 4; ++a)
      for (int ka = 0; ka < 2; ++ka) {
        const LO na = dofs(e, a, ka);
        if (na < 0) continue;
        for (int b = 0; b < 4; ++b)
          for (int kb = 0; kb < 2; ++kb) {
            const LO nb = dofs(e, b, kb);
            if (nb < 0) continue;
            const double m = wts(e, a, ka) * wts(e, b, kb) * Me[a][b];
            for (int i = 0; i < nc; ++i) {
              const LO row = nc * na + i, col = nc * nb + i;
              // A mass coupling of a lumped unknown sits on the diagonal.
              out(row, 0) += m * w(row == col || !(lumped(row) || lumped(col)) ? col : row, 0);
            }
          }
      }
  }
}

}  // namespace signorini::fem
