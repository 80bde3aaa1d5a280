/// \file ElasticityEstimator.cpp
/// The residual estimator for plane strain elasticity; the same layout as ResidualEstimator.cpp
/// (cell kernel, face jumps through p4est's face iteration with a ghost layer, boundary edges,
/// s0, s1) with vector residuals. h_K is the longest diagonal of K.
#include "signorini/estimate/ElasticityEstimator.hpp"

#include <algorithm>
#include <cmath>

#include <p4est_ghost.h>
#include <p4est_iterate.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/estimate/EstimatorTools.hpp"
#include "signorini/estimate/HarmonicContinuation.hpp"
#include "signorini/fem/Q1Kernels.hpp"

namespace signorini::estimate {

namespace {

/// One cell for the face terms: corners and the corner values of both components (hanging
/// corners resolved). Plain data: the ghost payload (16 doubles).
struct CellPayload {
  double X[4][2];
  double u[2][4];
};

/// sigma(u_h) n at parameter tau of face f of a cell.
void traction(const CellPayload& c, int f, double tau, const double n[2], double lambda, double mu, double t[2]) {
  double s, r, N[4], gx[4], gy[4];
  faceReference(f, tau, s, r);
  fem::q1Gradients(c.X, s, r, N, gx, gy);
  double du[2][2] = {};  // du[i][j] = d u_i / d x_j
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 2; ++i) du[i][0] += c.u[i][k] * gx[k], du[i][1] += c.u[i][k] * gy[k];
  const double tr = du[0][0] + du[1][1];
  const double sxx = lambda * tr + 2 * mu * du[0][0], syy = lambda * tr + 2 * mu * du[1][1],
               sxy = mu * (du[0][1] + du[1][0]);
  t[0] = sxx * n[0] + sxy * n[1];
  t[1] = sxy * n[0] + syy * n[1];
}

struct FaceContext {
  const std::vector<CellPayload>* local;
  const std::vector<CellPayload>* ghosts;
  std::vector<double>* edgeTerm;
  double lambda, mu, halfBk2;
};

/// The jump term of the fine edge that is the whole face of cell A and part (or all) of the face
/// of cell B: J = [sigma(u_h) n] = (sigma_A - sigma_B) n_A, R = -(beta k^2 / 2) J; each local side
/// K receives h_K ||R||^2_E (as in ResidualEstimator.cpp).
void addEdgeJump(const FaceContext& ctx, const FaceSide<CellPayload>& A, const FaceSide<CellPayload>& B) {
  if (A.local < 0 && B.local < 0) return;
  const CellPayload& a = *A.data;
  const CellPayload& b = *B.data;
  const double* P0 = a.X[p4est_face_corners[A.face][0]];
  const double* P1 = a.X[p4est_face_corners[A.face][1]];
  const double len = std::hypot(P1[0] - P0[0], P1[1] - P0[1]);
  double n[2];
  outwardNormal(a.X, A.face, n);
  const double b0 = faceParameter(b.X, B.face, P0), b1 = faceParameter(b.X, B.face, P1);
  double integral = 0;
  if (fem::isParallelogram(a.X) && fem::isParallelogram(b.X)) {  // linear jump: exact from its end values
    double ta[2][2], tb[2][2];
    for (int end = 0; end < 2; ++end) {
      traction(a, A.face, end, n, ctx.lambda, ctx.mu, ta[end]);
      traction(b, B.face, end == 0 ? b0 : b1, n, ctx.lambda, ctx.mu, tb[end]);
    }
    for (int k = 0; k < 2; ++k) integral += squareOfLinearIntegral(ta[0][k] - tb[0][k], ta[1][k] - tb[1][k]);
  } else {
    for (int g = 0; g < 3; ++g) {
      double ta[2], tb[2];
      traction(a, A.face, kG3[g], n, ctx.lambda, ctx.mu, ta);
      traction(b, B.face, b0 + kG3[g] * (b1 - b0), n, ctx.lambda, ctx.mu, tb);
      integral += kW3[g] * ((ta[0] - tb[0]) * (ta[0] - tb[0]) + (ta[1] - tb[1]) * (ta[1] - tb[1]));
    }
  }
  const double rSquared = ctx.halfBk2 * ctx.halfBk2 * integral * len;
  if (A.local >= 0) (*ctx.edgeTerm)[A.local] += cellDiameter(a.X) * rSquared;
  if (B.local >= 0) (*ctx.edgeTerm)[B.local] += cellDiameter(b.X) * rSquared;
}

}  // namespace

ElasticityEstimator::ElasticityEstimator(const core::ParameterList& params) : params_(params) {
  core::validateDeck(params_, ResidualEstimator::getValidParameters(), "Estimator");
}

EstimatorResult ElasticityEstimator::estimate(const ElasticityEstimatorInput& in) const {
  const mesh::Q1Mesh& mesh = in.mesh;
  const fem::ProblemData& problem = in.problem;
  const LO nc = mesh.numLocalCells();
  SIGNORINI_ASSERT(in.forest.numLocalCells() == nc, "the forest and the Q1 mesh do not match");
  SIGNORINI_ASSERT(&in.assembler.mesh() == &mesh, "the assembler belongs to another mesh");
  const double bk2 = in.beta * in.timeStep * in.timeStep;
  const double rho = problem.density, lambda = problem.lameLambda, mu = problem.lameMu, t = in.time;
  const auto comm = mesh.comm();

  Vector uOv(in.assembler.overlapMap()), pOv(in.assembler.overlapMap());
  in.assembler.toOverlap(in.u, uOv);
  in.assembler.toOverlap(in.predictor, pOv);

  // --- Cell residuals (Kokkos): h_K^2 ||r||_K^2, 3x3 Gauss points.
  Kokkos::View<double*, DeviceType> vol("elasticityVolume", nc);
  {
    Kokkos::View<double* [9][2], DeviceType> fq("elasticityF", nc);
    {
      auto h = Kokkos::create_mirror_view(fq);
      const auto& X = mesh.cornerCoordsHost;
      for (LO e = 0; e < nc; ++e)
        for (int q = 0; q < 9; ++q) {
          double N[4], ds[4], dr[4];
          fem::q1Shape(kG3[q % 3], kG3[q / 3], N, ds, dr);
          double x = 0, y = 0;
          for (int c = 0; c < 4; ++c) x += N[c] * X(e, c, 0), y += N[c] * X(e, c, 1);
          for (int c = 0; c < 2; ++c) h(e, q, c) = problem.bodyForce[c](x, y, t);
        }
      Kokkos::deep_copy(fq, h);
    }
    auto uv = uOv.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto pv = pOv.getLocalViewDevice(Tpetra::Access::ReadOnly);
    const auto X = mesh.cornerCoords;
    const auto dofs = mesh.cornerDofs;
    const auto wts = mesh.cornerWeights;
    Kokkos::parallel_for(
        "signorini::elasticityEstimator::cellResidual", Kokkos::RangePolicy<ExecSpace>(0, nc),
        KOKKOS_LAMBDA(const LO e) {
          double Xe[4][2], ue[2][4], pe[2][4];
          for (int c = 0; c < 4; ++c) {
            Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
            for (int i = 0; i < 2; ++i) {
              ue[i][c] = 0, pe[i][c] = 0;
              for (int k = 0; k < 2; ++k) {
                const LO d = dofs(e, c, k);
                if (d < 0) continue;
                ue[i][c] += wts(e, c, k) * uv(2 * d + i, 0);
                pe[i][c] += wts(e, c, k) * pv(2 * d + i, 0);
              }
            }
          }
          double sum = 0;
          for (int q = 0; q < 9; ++q) {
            double N[4], gx[4], gy[4], Hx[3], Hy[3];
            const double s = kG3[q % 3], r = kG3[q / 3];
            const double det = fem::q1Gradients(Xe, s, r, N, gx, gy);
            q1Hessian(Xe, ue[0], s, r, Hx);
            q1Hessian(Xe, ue[1], s, r, Hy);
            // div sigma = (lambda + mu) grad div u + mu Laplace u
            const double div[2] = {(lambda + 2 * mu) * Hx[0] + mu * Hx[1] + (lambda + mu) * Hy[2],
                                   (lambda + 2 * mu) * Hy[1] + mu * Hy[0] + (lambda + mu) * Hx[2]};
            double res2 = 0;
            for (int i = 0; i < 2; ++i) {
              double diff = 0;
              for (int c = 0; c < 4; ++c) diff += N[c] * (pe[i][c] - ue[i][c]);
              const double res = bk2 * fq(e, q, i) + rho * diff + bk2 * div[i];
              res2 += res * res;
            }
            sum += kW3[q % 3] * kW3[q / 3] * det * res2;
          }
          const double h = cellDiameter(Xe);
          vol(e) = h * h * sum;
        });
  }
  auto volHost = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vol);

  auto uh = uOv.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<CellPayload> local(static_cast<size_t>(nc));
  for (LO e = 0; e < nc; ++e)
    for (int c = 0; c < 4; ++c) {
      local[e].X[c][0] = mesh.cornerCoordsHost(e, c, 0);
      local[e].X[c][1] = mesh.cornerCoordsHost(e, c, 1);
      for (int i = 0; i < 2; ++i) {
        local[e].u[i][c] = 0;
        for (int k = 0; k < 2; ++k)
          if (mesh.cornerDofsHost(e, c, k) >= 0)
            local[e].u[i][c] += mesh.cornerWeightsHost(e, c, k) * uh(2 * mesh.cornerDofsHost(e, c, k) + i, 0);
      }
    }

  // --- Interior edges: traction jumps over every face with a local cell on at least one side.
  std::vector<double> edgeTerm(static_cast<size_t>(nc), 0.0);
  {
    FaceContext ctx{&local, nullptr, &edgeTerm, lambda, mu, 0.5 * bk2};
    forEachInteriorFace<CellPayload>(in.forest, local, [&](const std::vector<CellPayload>& ghosts) { ctx.ghosts = &ghosts; },
                                     [&](const FaceSide<CellPayload>& a, const FaceSide<CellPayload>& b) {
                                       addEdgeJump(ctx, a, b);
                                     });
  }

  // --- Boundary edges and s0.
  const auto& bedges = mesh.boundaryEdges();
  const int comp = problem.contactComponent;
  const double sign = problem.contactSign;
  std::vector<double> s0Share(static_cast<size_t>(nc), 0.0);
  double s0Local = 0;
  const std::vector<int>* edgeSegment = in.coupling ? &in.coupling->localEdgeSegment() : nullptr;
  if (edgeSegment)
    SIGNORINI_ASSERT(edgeSegment->size() == bedges.size(), "the contact coupling belongs to another mesh");
  for (size_t i = 0; i < bedges.size(); ++i) {
    const auto& be = bedges[i];
    if (be.segments & problem.dirichletMask) continue;
    const bool fixed[2] = {(be.segments & problem.componentDirichletMask[0]) != 0,
                           (be.segments & problem.componentDirichletMask[1]) != 0};
    const int seg = edgeSegment ? (*edgeSegment)[i] : -1;
    const bool neumann = (be.segments & problem.neumannMask) != 0;
    if (seg >= 0) SIGNORINI_ASSERT(seg < static_cast<int>(in.lambda.size()), "lambda has fewer entries than segments");
    const double lambdaJ = seg >= 0 ? in.lambda[seg] : 0.0;
    const CellPayload& c = local[be.cell];
    double n[2];
    outwardNormal(c.X, be.face, n);
    const double len = be.length();
    double integral = 0;
    for (int g = 0; g < 3; ++g) {
      double tr[2], R[2];
      traction(c, be.face, kG3[g], n, lambda, mu, tr);
      const double x = be.x[0][0] + kG3[g] * (be.x[1][0] - be.x[0][0]);
      const double y = be.x[0][1] + kG3[g] * (be.x[1][1] - be.x[0][1]);
      for (int k = 0; k < 2; ++k) {
        R[k] = bk2 * tr[k];
        if (neumann) R[k] -= bk2 * problem.neumannData[k](x, y, t);
        if (seg >= 0 && k == comp) R[k] += sign * lambdaJ;
        if (fixed[k]) R[k] = 0;
      }
      integral += kW3[g] * (R[0] * R[0] + R[1] * R[1]);
    }
    edgeTerm[be.cell] += cellDiameter(c.X) * integral * len;

    if (seg >= 0 && lambdaJ != 0.0) {
      const double u0 = sign * uh(2 * be.node[0] + comp, 0), u1 = sign * uh(2 * be.node[1] + comp, 0);
      const double contribution = lambdaJ * len * positivePartAlongEdge(be, problem.obstacle, t, u0, u1);
      s0Local += contribution;
      s0Share[be.cell] += std::abs(contribution);
    }
  }

  EstimatorResult res = combineCellTerms(volHost, edgeTerm, s0Share, std::vector<double>{s0Local}, *comm);

  // --- s1: the harmonic continuation of (g - sign u_c)_+ from the contact nodes, zero where u_c is fixed.
  if (in.coupling && params_.get<bool>("Compute S1")) {
    const std::vector<char>& dirichlet = in.assembler.dirichletFlags();
    std::vector<char> fixedNodes(dirichlet.size() / 2);
    for (size_t i = 0; i < fixedNodes.size(); ++i) fixedNodes[i] = dirichlet[2 * i + comp];
    auto uo = in.u.getLocalViewHost(Tpetra::Access::ReadOnly);
    const double l = params_.get<double>("S1 Length Scale");
    res.s1 = geometricContactTerm(mesh, problem.contactMask, problem.obstacle, t,
                                  [&](LO i) { return sign * uo(2 * i + comp, 0); }, fixedNodes, nullptr, in.solveSPD,
                                  &continuation_, in.meshId, in.continuationGuess, {}, 1.0 / (l * l));
  }
  if (params_.get<std::string>("Scaling") == "physical") scaleToPhysical(res, s0Share, bk2 * problem.waveModulus());
  res.eta = res.etaStar + res.s0 + res.s1;
  return res;
}

}  // namespace signorini::estimate
