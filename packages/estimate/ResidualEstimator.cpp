/// \file ResidualEstimator.cpp
/// The residual estimator of paper Sec. 4 with the corrections of DESIGN 1.3.
///
/// eta_*^2 = sum_K eta_K^2, eta_K^2 = h_K^2 ||r||_K^2 + h_K ||R||^2_{dK}, h_K = longest diagonal of K:
///  - cell part (Kokkos kernel over the cells): r = beta k^2 f + rho (predictor - u_h)
///    + beta k^2 kappa Laplace(u_h), the Laplacian of the bilinear field through the inverse
///    bilinear map (non-zero on non-rectangular cells); exact from r's corner values where r is
///    bilinear (parallelograms, constant f), else 3x3 Gauss;
///  - interior edges (host, forEachInteriorFace: the direct walk over local and ghost cells on a
///    forest of one tree, else p4est_iterate with the face ghost layer): R = -(beta k^2 / 2) J,
///    J = [kappa du_h/dn] (linear along the edge between parallelograms: integrated exactly from
///    its end values; else 3-point Gauss). Every cell K adjacent to an edge E gets h_K ||R||^2_E =
///    h_K (beta k^2 / 2)^2 ||J||^2_E, so E adds (h_K + h_K') (beta k^2)^2 ||J||^2_E / 4 in total: the jump is shared
///    half and half (the 1/2 in R), each half weighted with its own cell's h_K. A 2:1 face is
///    split into its two fine edges; on each, J uses the coarse cell's flux evaluated on that half,
///    and the coarse cell collects both halves;
///  - boundary edges (Q1Mesh::boundaryEdges()): the whole h_K ||R||^2_E goes to the edge's cell.
/// s0^2 = |sum_j lambda_j int_{E_j} (g - u_h)_+ ds| (each rank its own contact edges, summed), and
/// each fine contact edge's |lambda_j int_E (g - u_h)_+| is added to its cell's indicator (these
/// shares sum to s0^2 because the multipliers are <= 0).
#include "signorini/estimate/ResidualEstimator.hpp"

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


/// Laplacian of the bilinear (isoparametric Q1) field with corner values u on the cell with
/// corners X at the reference point (s, r): the trace of q1Hessian, 2 m grad s . grad r =
/// -2 m (x_s . x_r) / det(J)^2. It vanishes on rectangles (x_s . x_r = 0) and for the linear fields
/// the space contains (m = 0); on other parallelograms it does not, unless u_sr does.
KOKKOS_INLINE_FUNCTION double q1Laplacian(const double X[4][2], const double u[4], double s, double r) {
  double H[3];
  q1Hessian(X, u, s, r, H);
  return H[0] + H[1];
}

/// What the face terms need of one cell: its corners and the corner values of u_h (hanging
/// corners already resolved). Plain data: exchanged as the ghost payload (12 doubles).
struct CellPayload {
  double X[4][2];
  double u[4];
};

/// grad u_h . n at parameter tau of face f of the cell.
double normalDerivative(const CellPayload& c, int f, double tau, const double n[2]) {
  double s, r, N[4], gx[4], gy[4];
  faceReference(f, tau, s, r);
  fem::q1Gradients(c.X, s, r, N, gx, gy);
  double dx = 0, dy = 0;
  for (int k = 0; k < 4; ++k) dx += c.u[k] * gx[k], dy += c.u[k] * gy[k];
  return dx * n[0] + dy * n[1];
}

/// grad u_h . n at the reference point (s, r) of a parallelogram cell: grad u_h = J^{-T} (u_s, u_r)
/// with the constant Jacobian J = [x_s, x_r] (the same as normalDerivative, without the general map).
double affineNormalDerivative(const CellPayload& c, double s, double r, const double n[2]) {
  const double xs0 = c.X[1][0] - c.X[0][0], xs1 = c.X[1][1] - c.X[0][1];
  const double xr0 = c.X[2][0] - c.X[0][0], xr1 = c.X[2][1] - c.X[0][1];
  const double us = (c.u[1] - c.u[0]) * (1 - r) + (c.u[3] - c.u[2]) * r;
  const double ur = (c.u[2] - c.u[0]) * (1 - s) + (c.u[3] - c.u[1]) * s;
  const double det = xs0 * xr1 - xs1 * xr0;
  return ((xr1 * us - xs1 * ur) * n[0] + (xs0 * ur - xr0 * us) * n[1]) / det;
}

/// Whether the face of A is the whole face of B (the cells have one size; a 2:1 face covers half).
bool sameSizeFace(const FaceSide<CellPayload>& A, const FaceSide<CellPayload>& B) {
  const double* P0 = A.data->X[p4est_face_corners[A.face][0]];
  const double* P1 = A.data->X[p4est_face_corners[A.face][1]];
  return std::abs(faceParameter(B.data->X, B.face, P1) - faceParameter(B.data->X, B.face, P0)) > 0.75;
}

/// Lexicographic order of the cells' centroids (a partition-independent order of cells).
bool centroidLess(const CellPayload& a, const CellPayload& b) {
  double ca[2] = {0, 0}, cb[2] = {0, 0};
  for (int c = 0; c < 4; ++c)
    for (int d = 0; d < 2; ++d) ca[d] += a.X[c][d], cb[d] += b.X[c][d];
  return ca[0] < cb[0] || (ca[0] == cb[0] && ca[1] < cb[1]);
}

/// Context of the face callback (forEachInteriorFace).
struct FaceContext {
  const std::vector<CellPayload>* local;
  const std::vector<CellPayload>* ghosts;
  CellSums* edgeTerm;             ///< per local cell: sum over its interior edges of h_K ||R||^2_E
  double kappa, halfBk2;          ///< kappa and beta k^2 / 2
};

/// The jump term of the fine edge that is the whole face of cell A (the finer or equal side)
/// and part (or all) of the face of cell B. With J = [kappa du_h/dn] = kappa (grad u_A - grad u_B) . n_A
/// and R = -(beta k^2 / 2) J, each side's cell K in {A, B} that is local receives h_K ||R||^2_E:
/// the edge contributes (h_A + h_B) (beta k^2 / 2)^2 ||J||^2_E to eta_*^2 in total. On a hanging
/// face the coarse cell B receives this for each of its two halves, with its own flux evaluated
/// on that half.
void addEdgeJump(const FaceContext& ctx, const FaceSide<CellPayload>& A0, const FaceSide<CellPayload>& B0) {
  if (A0.local < 0 && B0.local < 0) return;
  // Two cells of one size: under reproducible arithmetic the one with the smaller centroid is A,
  // whichever way the face walk (another on every partition) found them.
  const bool swap = core::reproducibleArithmetic() && sameSizeFace(A0, B0) && centroidLess(*B0.data, *A0.data);
  const FaceSide<CellPayload>& A = swap ? B0 : A0;
  const FaceSide<CellPayload>& B = swap ? A0 : B0;
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
    double jump[2];
    for (int end = 0; end < 2; ++end) {
      double sa, ra, sb, rb;
      faceReference(A.face, end, sa, ra);
      faceReference(B.face, end == 0 ? b0 : b1, sb, rb);
      jump[end] = ctx.kappa * (affineNormalDerivative(a, sa, ra, n) - affineNormalDerivative(b, sb, rb, n));
    }
    integral = squareOfLinearIntegral(jump[0], jump[1]);
  } else {
    for (int g = 0; g < 3; ++g) {
      const double jump = ctx.kappa * (normalDerivative(a, A.face, kG3[g], n) -
                                       normalDerivative(b, B.face, b0 + kG3[g] * (b1 - b0), n));
      integral += kW3[g] * jump * jump;
    }
  }
  const double rSquared = ctx.halfBk2 * ctx.halfBk2 * integral * len;  // ||R||^2_E
  if (A.local >= 0) ctx.edgeTerm->add(A.local, cellDiameter(a.X) * rSquared);
  if (B.local >= 0) ctx.edgeTerm->add(B.local, cellDiameter(b.X) * rSquared);
}


}  // namespace

core::ParameterList ResidualEstimator::getValidParameters() {
  core::ParameterList p("Estimator");
  core::addBool(p, "Compute S1", true,
                "Evaluate s1 = ||(g - u_h)_+||_{1/2,Gamma_C} through the harmonic continuation of the nodal "
                "positive part (one extra linear solve in steps where it is non-zero); false sets s1 = 0");
  core::addChoice(p, "Scaling", "physical",
                  "\"step\": eta_* and s0 exactly as written for the step equation c(u, phi) + <lambda_H, phi> = "
                  "(F_h, phi), whose residuals carry the factor beta k^2 (on the membrane eta_* is about 1e-6, s0 1e-4 and s1 1e-2: s1 "
                  "dominates eta); \"physical\": the same terms divided by beta k^2 kappa (eta_*) and sqrt(beta k^2 kappa) (s0), "
                  "kappa the stiffness (Problem/Stiffness; elasticity: lambda + 2 mu), i.e. for the equation divided "
                  "by beta k^2 kappa with the step equation's multiplier divided by beta k^2 (the physical one; with Time "
                  "Integration/Contact Force = implicit the reported multiplier is alpha times it): eta_* and s0 in units of the displacement, "
                  "whatever the units of force and length (s1 too, with S1 Length Scale a length of the problem), "
                  "and ordered as in the paper's Fig. 4.1 (s1 smallest)",
                  {"physical", "step"});
  core::addDouble(p, "S1 Relative Tolerance", 1e-2,
                  "Residual tolerance (relative to the right-hand side) of the Jacobi CG that computes the harmonic "
                  "continuation for s1. Every iterate is an extension of the data, so s1 is approached from above; "
                  "1e-2 leaves it at most 0.22% too large on the membrane deck and 0.15% on the bar (1e-3: 4.3e-5, "
                  "3e-2: 1.6%)",
                  1e-14, 0.5);
  core::addDouble(p, "S1 Length Scale", 1.0,
                  "The length l (in the deck's unit of length) in the norm of s1: s1 is the smallest "
                  "(|v|_1^2 + ||v||_0^2 / l^2)^(1/2) over the v with v = (g - u_h)_+ on Gamma_C and v = 0 on Gamma_D. "
                  "The default 1 is the paper's H^1 norm, whose L2 part carries one more power of length than its "
                  "gradient part: s1, and with it eta, then change with the unit of length (metres against "
                  "millimetres) in another proportion than the displacement. A length of the problem (e.g. the "
                  "domain's diameter) makes s1 a length whatever the unit. The marking leaves s1 out",
                  1e-100, 1e100);
  return p;
}

ResidualEstimator::ResidualEstimator(const core::ParameterList& params) : params_(params) {
  core::validateDeck(params_, getValidParameters(), "Estimator");
}

EstimatorResult ResidualEstimator::estimate(const EstimatorInput& in) const {
  const mesh::Q1Mesh& mesh = in.mesh;
  const fem::ProblemData& problem = in.problem;
  const LO nc = mesh.numLocalCells();
  SIGNORINI_ASSERT(in.forest.numLocalCells() == nc, "the forest and the Q1 mesh do not match");
  SIGNORINI_ASSERT(&in.assembler.mesh() == &mesh, "the assembler belongs to another mesh");
  const double bk2 = in.beta * in.timeStep * in.timeStep;
  const double rho = problem.density, kappa = problem.stiffness, t = in.time;
  const auto comm = mesh.comm();

  Vector uOv(mesh.overlapMap()), pOv(mesh.overlapMap());
  in.assembler.toOverlap(in.u, uOv);
  in.assembler.toOverlap(in.predictor, pOv);

  // --- Cell residuals (Kokkos): vol(e) = h_K^2 ||r||_K^2 with
  //     r = beta k^2 f + rho (predictor - u_h) + beta k^2 kappa Laplace(u_h): exact from r's corner
  //     values where r is bilinear (parallelograms, constant f), else 3x3 Gauss points.
  Kokkos::View<double*, DeviceType> vol("estimatorVolume", nc);
  {
    const bool constantForce = problem.bodyForce.isConstant();
    const double fConstant = constantForce ? problem.bodyForce(0, 0, t) : 0.0;
    Kokkos::View<double* [9], DeviceType> fq("estimatorF", constantForce ? 0 : nc);
    if (!constantForce) {
      auto h = Kokkos::create_mirror_view(fq);
      const auto& X = mesh.cornerCoordsHost;
      for (LO e = 0; e < nc; ++e)
        for (int q = 0; q < 9; ++q) {
          double N[4], ds[4], dr[4];
          fem::q1Shape(kG3[q % 3], kG3[q / 3], N, ds, dr);
          double x = 0, y = 0;
          for (int c = 0; c < 4; ++c) x += N[c] * X(e, c, 0), y += N[c] * X(e, c, 1);
          h(e, q) = problem.bodyForce(x, y, t);
        }
      Kokkos::deep_copy(fq, h);
    }
    Kokkos::View<double[9][3], DeviceType> rule("estimatorRule");  // s, r, weight
    {
      auto h = Kokkos::create_mirror_view(rule);
      for (int q = 0; q < 9; ++q) h(q, 0) = kG3[q % 3], h(q, 1) = kG3[q / 3], h(q, 2) = kW3[q % 3] * kW3[q / 3];
      Kokkos::deep_copy(rule, h);
    }
    auto uv = uOv.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto pv = pOv.getLocalViewDevice(Tpetra::Access::ReadOnly);
    const auto X = mesh.cornerCoords;
    const auto dofs = mesh.cornerDofs;
    const auto wts = mesh.cornerWeights;
    Kokkos::parallel_for(
        "signorini::estimator::cellResidual", Kokkos::RangePolicy<ExecSpace>(0, nc), KOKKOS_LAMBDA(const LO e) {
          double Xe[4][2], ue[4], pe[4];
          for (int c = 0; c < 4; ++c) {
            Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
            ue[c] = 0, pe[c] = 0;
            for (int k = 0; k < 2; ++k) {
              const LO d = dofs(e, c, k);
              if (d < 0) continue;
              ue[c] += wts(e, c, k) * uv(d, 0);
              pe[c] += wts(e, c, k) * pv(d, 0);
            }
          }
          double sum = 0;
          if (constantForce && fem::isParallelogram(Xe)) {  // r is bilinear (its Laplacian term constant): exact
            const double L = bk2 * kappa * q1Laplacian(Xe, ue, 0.5, 0.5);
            double rc[4];
            for (int c = 0; c < 4; ++c) rc[c] = bk2 * fConstant + rho * (pe[c] - ue[c]) + L;
            const double area = Kokkos::Experimental::fabs((Xe[1][0] - Xe[0][0]) * (Xe[2][1] - Xe[0][1]) -
                                                           (Xe[1][1] - Xe[0][1]) * (Xe[2][0] - Xe[0][0]));
            sum = bilinearSquareIntegral(rc, area);
          } else {
            for (int q = 0; q < 9; ++q) {
              double N[4], gx[4], gy[4];
              const double s = rule(q, 0), r = rule(q, 1);
              const double det = fem::q1Gradients(Xe, s, r, N, gx, gy);
              double diff = 0;
              for (int c = 0; c < 4; ++c) diff += N[c] * (pe[c] - ue[c]);
              const double f = constantForce ? fConstant : fq(e, q);
              const double res = bk2 * f + rho * diff + bk2 * kappa * q1Laplacian(Xe, ue, s, r);
              sum += rule(q, 2) * det * res * res;
            }
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
      local[e].u[c] = 0;
      for (int k = 0; k < 2; ++k)
        if (mesh.cornerDofsHost(e, c, k) >= 0)
          local[e].u[c] += mesh.cornerWeightsHost(e, c, k) * uh(mesh.cornerDofsHost(e, c, k), 0);
    }

  // --- Interior edges (host): flux jumps over every face with a local cell on at least one side,
  //     the neighbours on other ranks taken from p4est's face ghost layer.
  CellSums edgeSums(static_cast<size_t>(nc));
  {
    FaceContext ctx{&local, nullptr, &edgeSums, kappa, 0.5 * bk2};
    forEachInteriorFace<CellPayload>(
        in.forest, local, [&](const std::vector<CellPayload>& ghosts) { ctx.ghosts = &ghosts; },
        [&](const FaceSide<CellPayload>& a, const FaceSide<CellPayload>& b) { addEdgeJump(ctx, a, b); });
  }

  // --- Boundary edges: R = beta k^2 kappa du_h/dn - beta k^2 q [Neumann] + lambda_j [contact],
  //     i.e. -beta k^2 (q - kappa du_h/dn) on Gamma_N, lambda_j + beta k^2 kappa du_h/dn on Gamma_C,
  //     beta k^2 kappa du_h/dn on the homogeneous Neumann rest, nothing on Gamma_D. The whole
  //     h_K ||R||^2_E goes to the edge's (only) cell. Also s0: sum_j lambda_j int_{E_j} (g - u_h)_+ ds,
  //     each rank over its own contact edges; each edge's |share| goes to its cell.
  const auto& bedges = mesh.boundaryEdges();
  std::vector<double> s0Share(static_cast<size_t>(nc), 0.0), s0Terms;
  const std::vector<int>* edgeSegment = in.coupling ? &in.coupling->localEdgeSegment() : nullptr;
  if (edgeSegment)
    SIGNORINI_ASSERT(edgeSegment->size() == bedges.size(), "the contact coupling belongs to another mesh");
  for (size_t i = 0; i < bedges.size(); ++i) {
    const auto& be = bedges[i];
    if (be.segments & problem.dirichletMask) continue;
    const int seg = edgeSegment ? (*edgeSegment)[i] : -1;
    const bool neumann = (be.segments & problem.neumannMask) != 0;
    if (seg >= 0) SIGNORINI_ASSERT(seg < static_cast<int>(in.lambda.size()), "lambda has fewer entries than segments");
    const double lambda = seg >= 0 ? in.lambda[seg] : 0.0;
    const CellPayload& c = local[be.cell];
    double n[2];
    outwardNormal(c.X, be.face, n);
    const double len = be.length();
    double integral = 0;
    for (int g = 0; g < 3; ++g) {
      double R = bk2 * kappa * normalDerivative(c, be.face, kG3[g], n) + lambda;
      if (neumann) {
        const double x = be.x[0][0] + kG3[g] * (be.x[1][0] - be.x[0][0]);
        const double y = be.x[0][1] + kG3[g] * (be.x[1][1] - be.x[0][1]);
        R -= bk2 * problem.neumannData(x, y, t);
      }
      integral += kW3[g] * R * R;
    }
    edgeSums.add(be.cell, cellDiameter(c.X) * integral * len);

    if (seg >= 0 && lambda != 0.0) {
      const double contribution =
          lambda * len * positivePartAlongEdge(be, problem.obstacle, t, uh(be.node[0], 0), uh(be.node[1], 0));
      s0Terms.push_back(contribution);
      s0Share[be.cell] += std::abs(contribution);
    }
  }

  const std::vector<double>& edgeTerm = edgeSums.finish();
  EstimatorResult res = combineCellTerms(volHost, edgeTerm, s0Share, s0Terms, *comm);

  // --- s1: the harmonic continuation d of the nodal values of (g - u_h)_+ on Gamma_C, i.e. the
  //     minimiser of ||v||_1^2 = int |grad v|^2 + v^2 / l^2 with v = 0 on Gamma_D (first) and
  //     v = (g - u_h)_+ at the other contact nodes; s1 = ||d||_1.
  if (in.coupling && params_.get<bool>("Compute S1")) {
    const double l = params_.get<double>("S1 Length Scale"), massWeight = 1.0 / (l * l);
    auto uo = in.u.getLocalViewHost(Tpetra::Access::ReadOnly);
    res.s1 = geometricContactTerm(mesh, problem.contactMask, problem.obstacle, t, [&](LO i) { return uo(i, 0); },
                                  in.assembler.dirichletFlags(), &in.assembler, in.solveSPD, &continuation_, in.meshId,
                                  in.continuationGuess, [&]() -> RCP<const CrsMatrix> {
                                    if (in.mass.is_null() || in.stiffness.is_null()) return Teuchos::null;
                                    return fem::combineOnGraph(*in.mass, massWeight / rho, *in.stiffness,
                                                               1.0 / kappa, in.assembler.dirichletFlags());
                                  },
                                  massWeight);
  }
  if (params_.get<std::string>("Scaling") == "physical") scaleToPhysical(res, s0Share, bk2 * kappa);
  res.eta = res.etaStar + res.s0 + res.s1;
  return res;
}

}  // namespace signorini::estimate
