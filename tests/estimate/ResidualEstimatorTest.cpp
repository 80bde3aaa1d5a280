// Facts about the residual estimator of paper Sec. 4 / DESIGN 1.3:
//  - it vanishes for a discrete solution that satisfies the step equations exactly (linear
//    fields, consistent Neumann data and multipliers), also with hanging nodes and on general
//    quadrilaterals;
//  - a kink gives jump indicators only next to the kink, with the exact value
//    h_K (beta k^2 kappa)^2 |dK on the kink|;
//  - a bilinear cell residual, a linearly varying jump and a boundary residual are integrated
//    exactly (closed-form integrals per cell);
//  - eta_* decreases like h under uniform refinement of a smooth problem;
//  - the Laplacian of a bilinear field on non-rectangular cells matches hand computations;
//  - s0 matches a hand-integrated complementarity term, s1 the exact H1 norm of the discrete
//    harmonic continuation (a 1D problem), is linear in the amplitude and vanishes without penetration;
//  - 1, 2 and 3 ranks give the same etaStar, s0, s1 and cell indicators as one rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>

#include <unistd.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/core/Error.hpp"
#include "../QuadMeshes.hpp"
#include "../TestMesh.hpp"
#include "signorini/estimate/EstimatorTools.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/estimate/ResidualEstimator.hpp"
#include "SameEstimate.hpp"
#include "SolveCG.hpp"

using namespace signorini;
using test::solveCG;
using test::distortedSquare;
using test::exodusCoarseMesh;
using test::kDistortedSides;
using test::rotatedSquares;

namespace {


std::string num(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

/// One estimator problem: a forest on a coarse mesh (over any communicator), the problem data,
/// u_h, the predictor and the multipliers.
struct EstimatorCase {
  RCP<const Comm> comm;
  std::shared_ptr<mesh::CoarseMesh> coarse;
  std::unique_ptr<mesh::BoundarySegments> segments;
  std::unique_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;
  std::unique_ptr<fem::ProblemData> problem;
  std::unique_ptr<fem::Q1Assembler> assembler;
  std::unique_ptr<fem::ContactCoupling> coupling;
  RCP<Vector> u, pred;
  std::vector<double> lambda;
  double beta = 0.25, k = 0.1, time = 0.3;

  EstimatorCase(std::shared_ptr<mesh::CoarseMesh> c, const std::vector<std::pair<std::string, std::string>>& segs,
                int level, RCP<const Comm> cm = Tpetra::getDefaultComm())
      : comm(cm), coarse(std::move(c)) {
    segments = std::make_unique<mesh::BoundarySegments>(segs, *coarse);
    forest = std::make_unique<mesh::Forest>(coarse, core::rawMpiComm(*comm), level);
  }
  /// Refines (once) the cells whose centre satisfies \p where, then balances.
  void refineWhere(const std::function<bool(double, double)>& where) { test::refineWhere(*forest, *coarse, where); }
  /// Builds the mesh, the problem data (from "Problem" entries) and the operators.
  void finish(const std::map<std::string, std::string>& problemEntries, double rho = 1.0, double kappa = 1.0) {
    forest->partition();
    mesh = std::make_unique<mesh::Q1Mesh>(*forest, *segments, comm);
    auto p = fem::ProblemData::getValidParameters();
    p.set("Density", rho);
    p.set("Stiffness", kappa);
    for (const auto& [key, value] : problemEntries) p.set(key, value);
    problem = std::make_unique<fem::ProblemData>(p, *segments);
    assembler = std::make_unique<fem::Q1Assembler>(*mesh, mesh->nodesOnSegments(problem->dirichletMask));
    if (problem->hasObstacle) {
      coupling = std::make_unique<fem::ContactCoupling>(
          *mesh, problem->contactMask, fem::ContactCoupling::SegmentSize::TwoEdges, assembler->dirichletFlags());
      lambda.assign(coupling->numSegments(), 0.0);
    }
    u = Teuchos::rcp(new Vector(mesh->ownedMap()));
    pred = Teuchos::rcp(new Vector(mesh->ownedMap()));
  }
  /// Nodal interpolant on the owned nodes.
  void interpolate(const std::function<double(double, double)>& f, Vector& v) const {
    auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = f(mesh->nodeCoords()[i][0], mesh->nodeCoords()[i][1]);
  }
  /// The estimator as written for the step equation ("step" scaling) unless told otherwise.
  estimate::EstimatorResult run(bool computeS1 = true, const std::string& scaling = "step") const {
    auto params = estimate::ResidualEstimator::getValidParameters();
    params.set("Compute S1", computeS1);
    params.set("Scaling", scaling);
    estimate::ResidualEstimator est(params);
    estimate::EstimatorInput in{*forest, *mesh, *assembler, *problem, coupling.get(), time, k, beta, *u, *pred, lambda,
                                solveCG};
    return est.estimate(in);
  }
  double bk2() const { return beta * k * k; }
  /// Sum of the cell indicators over all ranks.
  double indicatorSum(const estimate::EstimatorResult& r) const {
    double local = 0, global = 0;
    for (double v : r.cellIndicator) local += v;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    return global;
  }
};

const std::vector<std::pair<std::string, std::string>> kSides = {
    {"left", "left"}, {"right", "right"}, {"bottom", "bottom"}, {"top", "top"}};

// ---------------------------------------------------------------------------------------------
// 1. A discrete solution that satisfies the step equations exactly has eta = 0.

enum class CoarseKind { Rectangle, RotatedSquares, Distorted };

struct ExactCase {
  const char* name;
  CoarseKind coarse;
  bool hanging, contact;
  double d;  ///< u = a + b x + c y + d x y (d != 0 only on rectangular cells, where x y is in the space)
};

std::unique_ptr<EstimatorCase> exactCaseMesh(const ExactCase& c) {
  std::shared_ptr<mesh::CoarseMesh> coarse = c.coarse == CoarseKind::Rectangle
                                                 ? mesh::CoarseMesh::rectangle(0, 1, 0, 1, 2, 2)
                                             : c.coarse == CoarseKind::RotatedSquares ? rotatedSquares()
                                                                                      : distortedSquare();
  auto s = std::make_unique<EstimatorCase>(coarse, c.coarse == CoarseKind::Rectangle ? kSides : kDistortedSides, 2);
  if (c.hanging)
    for (int pass = 0; pass < 2; ++pass) s->refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  return s;
}

class ExactSolutionTest : public ::testing::TestWithParam<ExactCase> {};

TEST_P(ExactSolutionTest, FieldInTheSpaceWithConsistentDataHasZeroEstimate) {
  const auto& c = GetParam();
  auto s = exactCaseMesh(c);
  const double a = 0.7, b = 3.0, cc = -2.0, d = c.d, kappa = 2.0, rho = 3.0;
  // q = kappa grad u . n on every side (n = -x, +x, -y, +y), grad u = (b + d y, c + d x).
  const std::string ux = "(" + num(b) + " + " + num(d) + "*y)", uy = "(" + num(cc) + " + " + num(d) + "*x)";
  const std::string q =
      num(kappa) + " * (x < 0.001 ? -" + ux + " : (x > 0.999 ? " + ux + " : (y < 0.001 ? -" + uy + " : " + uy + ")))";
  std::map<std::string, std::string> entries = {{"Body Force", "0"}, {"Neumann Data", q}};
  if (c.contact) {
    entries["Neumann Segments"] = "left, bottom, top";
    entries["Contact Segments"] = "right";
    entries["Obstacle"] = "-10 + 0*x";  // far below u_h: no positive part
  } else {
    entries["Neumann Segments"] = "left, right, bottom, top";
  }
  s->finish(entries, rho, kappa);
  auto field = [&](double x, double y) { return a + b * x + cc * y + d * x * y; };
  s->interpolate(field, *s->u);
  s->interpolate(field, *s->pred);
  // On Gamma_C (x = 1, d = 0), kappa du/dn = -lambda_phys: the scaled multiplier is -beta k^2 kappa b.
  for (auto& l : s->lambda) l = -s->bk2() * kappa * b;
  const auto r = s->run();
  const double scale = s->bk2() * kappa * (std::abs(b) + std::abs(cc));  // one flux term
  EXPECT_LT(r.etaStar, 1e-11 * scale);
  EXPECT_EQ(r.s0, 0.0);
  EXPECT_EQ(r.s1, 0.0);
  EXPECT_LT(r.eta, 1e-11 * scale);
  ASSERT_EQ(static_cast<LO>(r.cellIndicator.size()), s->mesh->numLocalCells());
  for (double v : r.cellIndicator) EXPECT_LT(v, 1e-22 * scale * scale);

  // Control: the same field with a wrong Neumann datum is detected (R = beta k^2 kappa du/dn on the right side).
  if (!c.contact) {
    auto wrong = entries;
    wrong["Neumann Segments"] = "left, bottom, top";
    auto w = exactCaseMesh(c);
    w->finish(wrong, rho, kappa);
    w->interpolate(field, *w->u);
    w->interpolate(field, *w->pred);
    EXPECT_GT(w->run().etaStar, 0.1 * scale);
  }

  // Inertia and body force: with the predictor u_h + delta (delta affine, in the space on every
  // mesh) and f = -rho delta / (beta k^2), the two cancel in r = beta k^2 f + rho (predictor - u_h)
  // + beta k^2 kappa Laplace(u_h), so eta_* stays zero; f of the other sign leaves r = 2 rho delta.
  double etaWithForce[2];
  for (int sign : {1, -1}) {
    auto w = exactCaseMesh(c);
    auto withForce = entries;
    withForce["Body Force"] = num(-sign * rho / w->bk2()) + " * (0.3 + 0.2*x - 0.1*y)";
    w->finish(withForce, rho, kappa);
    w->interpolate(field, *w->u);
    w->interpolate([&](double x, double y) { return field(x, y) + 0.3 + 0.2 * x - 0.1 * y; }, *w->pred);
    for (auto& l : w->lambda) l = -w->bk2() * kappa * b;
    etaWithForce[sign > 0 ? 0 : 1] = w->run().etaStar;
  }
  EXPECT_GT(etaWithForce[1], 1e-3 * rho);  // h ||2 rho delta||: far from rounding
  EXPECT_LT(etaWithForce[0], 1e-11 * etaWithForce[1]);
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, ExactSolutionTest,
    ::testing::Values(ExactCase{"rectangles", CoarseKind::Rectangle, false, false, 0.0},
                      ExactCase{"rectanglesHanging", CoarseKind::Rectangle, true, false, 0.0},
                      ExactCase{"rectanglesHangingContact", CoarseKind::Rectangle, true, true, 0.0},
                      ExactCase{"rectanglesHangingBilinear", CoarseKind::Rectangle, true, false, 1.5},
                      ExactCase{"rotatedSquaresHangingBilinear", CoarseKind::RotatedSquares, true, false, 1.5},
                      ExactCase{"distortedHanging", CoarseKind::Distorted, true, false, 0.0},
                      ExactCase{"distortedHangingContact", CoarseKind::Distorted, true, true, 0.0}),
    [](const auto& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------
// 2. A kink |x - 0.5| gives jump indicators exactly on the cells next to x = 0.5.

class KinkTest : public ::testing::TestWithParam<bool> {};

TEST_P(KinkTest, JumpIndicatorsAreLocalisedAndExact) {
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
  // Hanging faces on the kink: the cells left of x = 0.5 (y < 0.5) are refined, those right of it not.
  if (GetParam()) s.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  const double kappa = 1.5;
  s.finish({{"Dirichlet Segments", "left, right, bottom, top"}}, 2.0, kappa);
  auto kink = [](double x, double) { return std::abs(x - 0.5); };
  s.interpolate(kink, *s.u);
  s.interpolate(kink, *s.pred);
  const auto r = s.run();
  // [kappa du/dn] = -2 kappa on the line, R = (beta k^2 / 2) 2 kappa: each cell K touching the
  // line gets h_K (beta k^2 kappa)^2 |dK on the line|, every other cell nothing.
  const double c2 = std::pow(s.bk2() * kappa, 2);
  const auto& X = s.mesh->cornerCoordsHost;
  double expectedLocal = 0;
  int touching = 0;
  for (LO e = 0; e < s.mesh->numLocalCells(); ++e) {
    double onLine = 0;
    for (int f = 0; f < 4; ++f) {
      const int a = p4est_face_corners[f][0], b = p4est_face_corners[f][1];
      if (std::abs(X(e, a, 0) - 0.5) < 1e-12 && std::abs(X(e, b, 0) - 0.5) < 1e-12)
        onLine += std::abs(X(e, b, 1) - X(e, a, 1));
    }
    const double h = std::hypot(X(e, 3, 0) - X(e, 0, 0), X(e, 3, 1) - X(e, 0, 1));
    const double expected = h * c2 * onLine;
    expectedLocal += expected;
    if (onLine > 0) {
      ++touching;
      EXPECT_NEAR(r.cellIndicator[e], expected, 1e-12 * expected) << "cell " << e;
    } else {
      EXPECT_LT(r.cellIndicator[e], 1e-14 * c2) << "cell " << e << " away from the kink";
    }
  }
  double expectedGlobal = 0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, expectedLocal, Teuchos::outArg(expectedGlobal));
  EXPECT_NEAR(r.etaStar * r.etaStar, expectedGlobal, 1e-12 * expectedGlobal);
  if (!GetParam()) {  // uniform 8 x 8: 16 cells of diameter sqrt(2)/8, each with 1/8 of the line
    EXPECT_NEAR(expectedGlobal, 2 * std::sqrt(2.0) / 8 * c2, 1e-14);
  }
  int touchingGlobal = 0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, touching, Teuchos::outArg(touchingGlobal));
  // hanging: 8 fine + 4 coarse cells left of the line, 8 coarse cells right of it
  EXPECT_EQ(touchingGlobal, GetParam() ? 20 : 16);
}

INSTANTIATE_TEST_SUITE_P(Meshes, KinkTest, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "hanging" : "uniform"); });

// ---------------------------------------------------------------------------------------------
// 2b. Residuals that vary over a cell or along an edge are integrated exactly (closed-form
//     integrals): a bilinear cell residual, a linear jump, a boundary residual. On 4 x 4 and 8 x 8
//     squares, with hanging faces (the cells x < 0.5, y < 0.5 refined) or without.

class VaryingResidualTest : public ::testing::TestWithParam<bool> {};

/// Every local cell's indicator against \p expected(e) (to 1e-12 relative; below \p zeroFloor where
/// it is 0) and eta_*^2 against the expected values' sum over all ranks, which is returned.
double expectCellIndicators(const EstimatorCase& s, const estimate::EstimatorResult& r,
                            const std::function<double(LO)>& expected, double zeroFloor) {
  double local = 0, global = 0;
  for (LO e = 0; e < s.mesh->numLocalCells(); ++e) {
    const double value = expected(e);
    if (value > 0)
      EXPECT_NEAR(r.cellIndicator[e], value, 1e-12 * value) << "cell " << e;
    else
      EXPECT_LT(r.cellIndicator[e], zeroFloor) << "cell " << e << " without a residual";
    local += value;
  }
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  EXPECT_NEAR(r.etaStar * r.etaStar, global, 1e-12 * global);
  return global;
}

TEST_P(VaryingResidualTest, BilinearCellResidualIsIntegratedExactly) {
  // u_h = 0.4 + x - 2 y (no jumps, Laplace 0) and predictor u_h + c x y, f = 0, Dirichlet all round:
  // r = rho (predictor - u_h) = rho c x y, so each cell [x0,x1] x [y0,y1] gets
  // h_K^2 rho^2 c^2 (x1^3 - x0^3)(y1^3 - y0^3) / 9 (a lumped or one-point rule would not).
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 2);
  if (GetParam()) s.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  const double rho = 2.5, c = 1.7;
  s.finish({{"Dirichlet Segments", "left, right, bottom, top"}}, rho, 1.0);
  auto linear = [](double x, double y) { return 0.4 + x - 2 * y; };
  s.interpolate(linear, *s.u);
  s.interpolate([&](double x, double y) { return linear(x, y) + c * x * y; }, *s.pred);
  const auto r = s.run();
  const auto& X = s.mesh->cornerCoordsHost;
  expectCellIndicators(s, r, [&](LO e) {  // every cell has x y > 0 somewhere: all positive
    const double x0 = X(e, 0, 0), x1 = X(e, 3, 0), y0 = X(e, 0, 1), y1 = X(e, 3, 1);
    const double h2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
    return h2 * rho * rho * c * c * (std::pow(x1, 3) - std::pow(x0, 3)) * (std::pow(y1, 3) - std::pow(y0, 3)) / 9;
  }, 0.0);
}

TEST_P(VaryingResidualTest, LinearJumpIsIntegratedExactly) {
  // u = |x - 1/2| (1 + y), bilinear on every cell (Laplace 0, continuous normal derivatives but
  // on x = 1/2, where [kappa du/dn] = -2 kappa (1 + y)), predictor = u_h, f = 0, Dirichlet all
  // round: R = beta k^2 kappa (1 + y), so each cell with a face [y0,y1] on the line gets
  // h_K (beta k^2 kappa)^2 ((1 + y1)^3 - (1 + y0)^3) / 3 (a rule with equal end weights would not).
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
  if (GetParam()) s.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  const double kappa = 1.5;
  s.finish({{"Dirichlet Segments", "left, right, bottom, top"}}, 2.0, kappa);
  auto kink = [](double x, double y) { return std::abs(x - 0.5) * (1 + y); };
  s.interpolate(kink, *s.u);
  s.interpolate(kink, *s.pred);
  const auto r = s.run();
  const double c2 = std::pow(s.bk2() * kappa, 2);
  const auto& X = s.mesh->cornerCoordsHost;
  const double expected = expectCellIndicators(s, r, [&](LO e) {
    double integral = 0;  // of (1 + y)^2 over the cell's faces on the line
    for (int f = 0; f < 4; ++f) {
      const int a = p4est_face_corners[f][0], b = p4est_face_corners[f][1];
      if (std::abs(X(e, a, 0) - 0.5) < 1e-12 && std::abs(X(e, b, 0) - 0.5) < 1e-12) {
        const double y0 = std::min(X(e, a, 1), X(e, b, 1)), y1 = std::max(X(e, a, 1), X(e, b, 1));
        integral += (std::pow(1 + y1, 3) - std::pow(1 + y0, 3)) / 3;
      }
    }
    return std::hypot(X(e, 3, 0) - X(e, 0, 0), X(e, 3, 1) - X(e, 0, 1)) * c2 * integral;
  }, 1e-14 * c2);
  if (!GetParam()) {  // 16 cells of diameter sqrt(2)/8 along the line: 2 h c2 int_0^1 (1 + y)^2 dy
    EXPECT_NEAR(expected, 2 * std::sqrt(2.0) / 8 * c2 * 7.0 / 3, 1e-14);
  }
}

TEST_P(VaryingResidualTest, BoundaryResidualIsIntegratedExactly) {
  // u_h = 0.7 + 3 x - 2 y with its exact flux on the left, bottom and top sides and none given on
  // the right one (q = 0 there): R = -beta k^2 (0 - kappa du/dx) = 3 beta k^2 kappa on the right
  // edges, so each cell there gets h_K (3 beta k^2 kappa)^2 |edge|, every other cell nothing.
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
  if (GetParam()) s.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  const double kappa = 2.0, b = 3.0, c = -2.0;
  const std::string q = num(kappa) + " * (x < 0.001 ? -" + num(b) + " : (y < 0.001 ? -(" + num(c) + ") : " + num(c) + "))";
  s.finish({{"Neumann Segments", "left, bottom, top"}, {"Neumann Data", q}}, 3.0, kappa);
  auto field = [&](double x, double y) { return 0.7 + b * x + c * y; };
  s.interpolate(field, *s.u);
  s.interpolate(field, *s.pred);
  const auto r = s.run();
  const double R2 = std::pow(s.bk2() * kappa * b, 2);
  const auto& X = s.mesh->cornerCoordsHost;
  const double expected = expectCellIndicators(s, r, [&](LO e) {
    const double h = std::hypot(X(e, 3, 0) - X(e, 0, 0), X(e, 3, 1) - X(e, 0, 1));
    return std::abs(X(e, 3, 0) - 1) < 1e-12 ? h * R2 * (X(e, 3, 1) - X(e, 0, 1)) : 0.0;
  }, 1e-14 * R2);
  EXPECT_NEAR(expected, std::sqrt(2.0) / 8 * R2, 1e-14 * R2);  // 8 cells of diameter sqrt(2)/8, edges 1/8
}

INSTANTIATE_TEST_SUITE_P(Meshes, VaryingResidualTest, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "hanging" : "uniform"); });

// ---------------------------------------------------------------------------------------------
// 3. Rate 1 in h under uniform refinement of a smooth problem.

TEST(ResidualEstimatorRate, EtaStarDecreasesLikeH) {
  // u = sin(pi x) e^y, -Laplace u = (pi^2 - 1) u; predictor = u_h + beta k^2 w_h / rho with w = x y and
  // f = -kappa Laplace u - w, so that u solves rho u - beta k^2 kappa Laplace u = beta k^2 f + rho * predictor.
  const double kappa = 1.3, rho = 1.0;
  std::vector<double> eta;
  for (int level = 3; level <= 5; ++level) {
    EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, level);
    const std::string f = num(kappa) + " * (pi^2 - 1) * sin(pi*x) * exp(y) - x*y";
    const std::string q = num(kappa) + " * (y < 0.5 ? -1 : 1) * exp(y) * sin(pi*x)";
    s.finish({{"Dirichlet Segments", "left, right"},
              {"Neumann Segments", "bottom, top"},
              {"Body Force", f},
              {"Neumann Data", q}},
             rho, kappa);
    s.interpolate([](double x, double y) { return std::sin(M_PI * x) * std::exp(y); }, *s.u);
    const double c = s.bk2() / rho;
    s.interpolate([&](double x, double y) { return std::sin(M_PI * x) * std::exp(y) + c * x * y; }, *s.pred);
    eta.push_back(s.run().etaStar);
  }
  for (size_t i = 0; i + 1 < eta.size(); ++i) {
    const double rate = std::log2(eta[i] / eta[i + 1]);
    EXPECT_GE(rate, 0.8) << "levels " << i + 3 << "/" << i + 4 << ": eta " << eta[i] << " -> " << eta[i + 1];
    EXPECT_LE(rate, 1.3) << "levels " << i + 3 << "/" << i + 4 << ": eta " << eta[i] << " -> " << eta[i + 1];
  }
}

// ---------------------------------------------------------------------------------------------
// 4. The Laplacian of a bilinear field on non-rectangular cells (r = beta k^2 kappa Laplace u_h with
//    predictor = u_h, f = 0, Dirichlet all round so that only cell residuals count).

TEST(ResidualEstimatorLaplacian, ParallelogramHasConstantLaplacian) {
  // x = s + a r, y = r: u = s r = x y - a y^2 lies in the (isoparametric) space of every
  // sub-cell, Laplace u = -2 a exactly; no jumps (u is smooth).
  const double a = 0.5, kappa = 0.8;
  auto coarse = exodusCoarseMesh({0, 1, 1 + a, a}, {0, 0, 1, 1}, {{0, 1, 2, 3}}, "parallelogram");
  for (int level : {0, 2}) {
    EstimatorCase s(coarse, {{"wall", "boundary"}}, level);
    s.finish({{"Dirichlet Segments", "wall"}}, 1.0, kappa);
    auto u = [&](double x, double y) { return x * y - a * y * y; };
    s.interpolate(u, *s.u);
    s.interpolate(u, *s.pred);
    const auto r = s.run();
    // eta^2 = sum_K h_K^2 |K| (beta k^2 kappa 2 a)^2; every cell is the parallelogram scaled by 2^-level.
    const double n = std::pow(2.0, level), h = std::hypot(1 + a, 1) / n, area = 1.0 / (n * n);
    const double expected = n * n * h * h * area * std::pow(s.bk2() * kappa * 2 * a, 2);
    EXPECT_NEAR(r.etaStar * r.etaStar, expected, 1e-12 * expected) << "level " << level;
  }
}

TEST(ResidualEstimatorLaplacian, TrapezoidMatchesHandComputation) {
  // Corners (0,0), (2,0), (1,1), (0,1): x = s (2 - r), y = r. u = s r = x y / (2 - y) is in the space;
  // Laplace u = d^2/dy^2 [x y / (2 - y)] = 4 x / (2 - y)^3 (u_xx = 0).
  // Per sub-cell [s0,s1] x [r0,r1] of the tree: int_K (Laplace u)^2 dx = int 16 s^2 / (2 - r)^3 ds dr
  //   = 16 (s1^3 - s0^3) / 3 * [1 / (2 (2 - r)^2)]_{r0}^{r1}   (dx = (2 - r) ds dr).
  // Level 0: h = sqrt(5), int = 2: eta^2 = 10 (beta k^2 kappa)^2.
  const double kappa = 1.1;
  // With hanging faces (the cells near the corner (0,0) refined once more) u stays smooth and in
  // the space, so its jumps vanish there too, although its normal derivative varies along the faces:
  // a coarse side evaluated at points other than the fine side's would show a jump.
  auto coarse = exodusCoarseMesh({0, 2, 1, 0}, {0, 0, 1, 1}, {{0, 1, 2, 3}}, "trapezoid");
  for (const auto& [level, hanging] : {std::pair{0, false}, {2, false}, {2, true}}) {
    EstimatorCase s(coarse, {{"wall", "boundary"}}, level);
    if (hanging) s.refineWhere([](double x, double y) { return x + y < 0.6; });
    s.finish({{"Dirichlet Segments", "wall"}}, 1.0, kappa);
    auto u = [](double x, double y) { return x * y / (2 - y); };
    s.interpolate(u, *s.u);
    s.interpolate(u, *s.pred);
    const auto r = s.run();
    const double c2 = std::pow(s.bk2() * kappa, 2);
    const auto& X = s.mesh->cornerCoordsHost;
    double local = 0, expected = 0;
    for (LO e = 0; e < s.mesh->numLocalCells(); ++e) {
      const double r0 = X(e, 0, 1), r1 = X(e, 3, 1);
      const double s0 = X(e, 0, 0) / (2 - r0), s1 = X(e, 3, 0) / (2 - r1);
      const double integral =
          16 * (std::pow(s1, 3) - std::pow(s0, 3)) / 3 * (0.5 / std::pow(2 - r1, 2) - 0.5 / std::pow(2 - r0, 2));
      const double h = std::max(std::hypot(X(e, 3, 0) - X(e, 0, 0), X(e, 3, 1) - X(e, 0, 1)),
                                std::hypot(X(e, 2, 0) - X(e, 1, 0), X(e, 2, 1) - X(e, 1, 1)));
      local += h * h * c2 * integral;
    }
    Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(expected));
    if (level == 0) { EXPECT_NEAR(expected, 10 * c2, 1e-14 * c2); }
    // 3x3 Gauss on the rational integrand 1/(2-r)^3: relative error 1e-3 on one cell, 7e-7 on 4 x 4.
    const double tol = level == 0 ? 2e-3 : 2e-6;
    EXPECT_NEAR(r.etaStar * r.etaStar, expected, tol * expected) << "level " << level << (hanging ? ", hanging" : "");
  }
}

// ---------------------------------------------------------------------------------------------
// 5. s0 and s1.

class ContactTermsTest : public ::testing::TestWithParam<bool> {};

TEST_P(ContactTermsTest, S0MatchesHandIntegral) {
  // Contact on the left side (x = 0), Dirichlet on the right; u_h = (1 - x) y is y on Gamma_C,
  // g = 0.3: (g - u_h)_+ = (0.3 - y)_+, which changes sign inside a fine edge.
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 4);
  if (GetParam())
    for (int pass = 0; pass < 2; ++pass) s.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  s.finish({{"Dirichlet Segments", "right"}, {"Contact Segments", "left"}, {"Obstacle", "0.3"}});
  s.interpolate([](double x, double y) { return (1 - x) * y; }, *s.u);
  s.interpolate([](double x, double y) { return (1 - x) * y; }, *s.pred);
  double expected = 0;
  for (int j = 0; j < s.coupling->numSegments(); ++j) {
    s.lambda[j] = -0.01 * (1 + 0.1 * j);
    const double ym = s.coupling->segmentMidpoint()[j][1], len = s.coupling->segmentLength()[j];
    const double y0 = ym - 0.5 * len, top = std::min(ym + 0.5 * len, 0.3);
    if (y0 < 0.3) expected += s.lambda[j] * 0.5 * (std::pow(0.3 - y0, 2) - std::pow(0.3 - top, 2));
  }
  const auto r = s.run(false);
  EXPECT_NEAR(r.s0, std::sqrt(std::abs(expected)), 1e-13);
  EXPECT_GT(r.s0, 0.0);
  EXPECT_EQ(r.s1, 0.0);  // "Compute S1" = false
  EXPECT_NEAR(r.eta, r.etaStar + r.s0, 1e-15);
  // Cell indicators: eta_K^2 plus the s0^2 shares (all lambda_j < 0, so the shares sum to s0^2).
  EXPECT_NEAR(s.indicatorSum(r), r.etaStar * r.etaStar + r.s0 * r.s0, 1e-12 * (r.etaStar * r.etaStar + r.s0 * r.s0));
  // The shares cell by cell. The reference z has the same mesh, u_h and multipliers but the obstacle
  // g = -10 far below u_h: (g - u_h)_+ = 0, so z's s0 is 0, while every edge residual (on Gamma_C
  // R = beta k^2 kappa du_h/dn + lambda_j) and every cell residual is the same as in s. The
  // difference of the two indicators of a cell is therefore exactly its s0 share: for a cell with
  // face E = [y0, y1] on x = 0 in segment j (u_h = y there),
  //   |lambda_j int_E (0.3 - y)_+ dy| = |lambda_j| ((0.3 - y0)_+^2 - (0.3 - y1)_+^2) / 2,
  // which is 0 for y0 >= 0.3; every cell away from x = 0 has the difference 0.
  EstimatorCase z(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 4);
  if (GetParam())
    for (int pass = 0; pass < 2; ++pass) z.refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  z.finish({{"Dirichlet Segments", "right"}, {"Contact Segments", "left"}, {"Obstacle", "-10"}});
  z.interpolate([](double x, double y) { return (1 - x) * y; }, *z.u);
  z.interpolate([](double x, double y) { return (1 - x) * y; }, *z.pred);
  z.lambda = s.lambda;
  const auto r0 = z.run(false);
  EXPECT_EQ(r0.s0, 0.0);
  EXPECT_NEAR(r0.etaStar, r.etaStar, 1e-14 * r.etaStar);  // the same edge and cell residuals
  ASSERT_EQ(r0.cellIndicator.size(), r.cellIndicator.size());
  const auto& X = s.mesh->cornerCoordsHost;
  const auto& mid = s.coupling->segmentMidpoint();
  const auto& segLen = s.coupling->segmentLength();
  int withShare = 0;
  for (LO e = 0; e < s.mesh->numLocalCells(); ++e) {
    ASSERT_EQ(X(e, 0, 0), z.mesh->cornerCoordsHost(e, 0, 0));  // the same cells in the same order
    ASSERT_EQ(X(e, 0, 1), z.mesh->cornerCoordsHost(e, 0, 1));
    double expected = 0;
    if (X(e, 0, 0) < 1e-12) {  // face 0 (corners 0 and 2) lies on x = 0
      const double y0 = X(e, 0, 1), y1 = X(e, 2, 1), ym = 0.5 * (y0 + y1);
      int seg = -1;
      for (size_t j = 0; j < mid.size(); ++j)
        if (std::abs(ym - mid[j][1]) < 0.5 * segLen[j]) seg = static_cast<int>(j);
      ASSERT_GE(seg, 0) << "cell " << e << ": no segment holds its contact edge";
      auto pos = [](double v) { return std::max(v, 0.0); };
      expected = std::abs(s.lambda[seg]) * 0.5 * (std::pow(pos(0.3 - y0), 2) - std::pow(pos(0.3 - y1), 2));
    }
    const double share = r.cellIndicator[e] - r0.cellIndicator[e];
    if (expected > 0) {
      ++withShare;
      EXPECT_NEAR(share, expected, 1e-12 * expected + 1e-15 * r0.cellIndicator[e]) << "cell " << e;
    } else {
      EXPECT_NEAR(share, 0.0, 1e-15 * r0.cellIndicator[e]) << "cell " << e << " at y0 = " << X(e, 0, 1);
    }
  }
  // Cells on x = 0 below y = 0.3: uniform 16 x 16 cells of side 1/16, y0 = 0, ..., 4/16 (5 cells; the
  // fifth, [4/16, 5/16], holds the sign change). Hanging: y < 1/2 refined twice to side 1/64, so
  // y0 = 0, ..., 19/64 (20 cells; the last, [19/64, 20/64], holds 0.3 = 19.2/64).
  int withShareGlobal = 0;
  Teuchos::reduceAll(*s.comm, Teuchos::REDUCE_SUM, withShare, Teuchos::outArg(withShareGlobal));
  EXPECT_EQ(withShareGlobal, GetParam() ? 20 : 5);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ContactTermsTest, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "hanging" : "uniform"); });

/// ||v||_1^2 of the 1D P1 minimiser of int v'^2 + v^2 on n uniform elements of [0,1], v(0) = 0, v(1) = c.
double oneDimensionalEnergy(int n, double c) {
  const double h = 1.0 / n, diag = 2 / h + 4 * h / 6, off = -1 / h + h / 6;
  std::vector<double> v(n + 1, 0.0), cp(n + 1, 0.0), dp(n + 1, 0.0);
  v[n] = c;
  // Thomas algorithm for the interior nodes 1..n-1.
  for (int i = 1; i < n; ++i) {
    const double rhs = i == n - 1 ? -off * c : 0.0;
    const double m = diag - (i > 1 ? off * cp[i - 1] : 0.0);
    cp[i] = off / m;
    dp[i] = (rhs - (i > 1 ? off * dp[i - 1] : 0.0)) / m;
  }
  for (int i = n - 1; i >= 1; --i) v[i] = dp[i] - (i < n - 1 ? cp[i] * v[i + 1] : 0.0);
  double e = 0;
  for (int i = 0; i < n; ++i) {
    const double a = v[i], b = v[i + 1];
    e += ((a - b) * (a - b)) / h + h / 6 * (2 * a * a + 2 * a * b + 2 * b * b);
  }
  return e;
}

TEST(ResidualEstimatorS1, MatchesDiscreteHarmonicContinuation) {
  // Dirichlet at x = 0, contact at x = 1, u_h = 0, g = c: the positive part is c at every contact node;
  // the continuation is the 1D minimiser v(x) (x-only functions are in the space and the
  // problem has natural conditions on top and bottom), ~ c sinh(x) / sinh(1).
  const int level = 3;
  auto s1For = [&](double c, bool compute, double* s0 = nullptr) {
    EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, level);
    s.finish({{"Dirichlet Segments", "left"}, {"Contact Segments", "right"}, {"Obstacle", num(c)}});
    s.u->putScalar(0.0);
    s.pred->putScalar(0.0);
    for (auto& l : s.lambda) l = -0.02;
    const auto r = s.run(compute);
    if (s0) *s0 = r.s0;
    EXPECT_NEAR(r.eta, r.etaStar + r.s0 + r.s1, 1e-15);
    return r.s1;
  };
  const double c = 0.2;
  double s0 = 0;
  const double s1 = s1For(c, true, &s0);
  const double exact = std::sqrt(oneDimensionalEnergy(1 << level, c));
  EXPECT_NEAR(s1, exact, 1e-9 * exact);
  EXPECT_NEAR(s1, c * std::sqrt(std::cosh(1.0) / std::sinh(1.0)), 1e-2 * s1);  // the continuous value
  EXPECT_NEAR(s0, std::sqrt(0.02 * c * 1.0), 1e-14);   // |sum lambda_j c |E_j|| = 0.02 c |Gamma_C|
  EXPECT_NEAR(s1For(3 * c, true), 3 * s1, 1e-9 * s1);  // linear in the amplitude
  EXPECT_EQ(s1For(c, false), 0.0);                     // "Compute S1" = false
  double s0none = 1;
  EXPECT_EQ(s1For(-1.0, true, &s0none), 0.0);  // no penetration: no positive part
  EXPECT_EQ(s0none, 0.0);
}

TEST(ResidualEstimatorS1, LengthScaleMakesS1ALengthInAnyUnit) {
  // One problem in metres and in millimetres (the domain, the obstacle and u_h in a unit 1000 times
  // smaller, rho and kappa as they are: s1 only sees the geometry and the penetration). With
  // S1 Length Scale the domain's side in each unit, s1 is one length, its number 1000 times larger
  // in millimetres, whether its operator is assembled or formed from the step's M and K. The paper's
  // H^1 norm (l = 1 in both units) is not: its L2 part carries one more power of the length.
  auto s1In = [](double unit, double lengthScale, bool fromStepMatrices) {
    EstimatorCase s(mesh::CoarseMesh::rectangle(0, unit, 0, unit, 1, 1), kSides, 2);
    s.refineWhere([&](double x, double y) { return x > 0.5 * unit && y < 0.5 * unit; });
    s.finish({{"Dirichlet Segments", "left"},
              {"Contact Segments", "right"},
              {"Obstacle", num(unit) + " * (0.1 * sin(3 * y / " + num(unit) + ") + 0.05)"}},
             2.0, 3.0);
    s.interpolate([&](double x, double y) { return unit * 0.02 * (x / unit) * (1 + y / unit); }, *s.u);
    auto params = estimate::ResidualEstimator::getValidParameters();
    params.set("Scaling", "step");
    params.set("S1 Length Scale", lengthScale);
    estimate::EstimatorInput in{*s.forest, *s.mesh, *s.assembler, *s.problem, s.coupling.get(), s.time, s.k, s.beta,
                                *s.u, *s.pred, s.lambda, solveCG};
    if (fromStepMatrices) {
      in.meshId = 1;
      in.mass = s.assembler->assembleSystem(1.0, 0.0, *s.problem);
      in.stiffness = s.assembler->assembleSystem(0.0, 1.0, *s.problem);
    }
    return estimate::ResidualEstimator(params).estimate(in).s1;
  };
  for (const bool fromStepMatrices : {false, true}) {
    const double metres = s1In(1.0, 1.0, fromStepMatrices);
    ASSERT_GT(metres, 0.0);
    EXPECT_NEAR(s1In(1e3, 1e3, fromStepMatrices), 1e3 * metres, 1e-9 * 1e3 * metres);
    const double paperNormInMillimetres = s1In(1e3, 1.0, fromStepMatrices);
    EXPECT_GT(std::abs(paperNormInMillimetres - 1e3 * metres), 0.05 * 1e3 * metres);  // control
    // A larger l weighs the L2 part less: s1 falls towards the gradient part alone.
    EXPECT_LT(s1In(1.0, 2.0, fromStepMatrices), metres);
  }
}

TEST(ResidualEstimatorS1, SeesOnlyThePositivePartOfThePenetration) {
  // s1 is the energy of the discrete harmonic continuation of (g - u_h)^+ from the contact boundary:
  // with u_h = 0 the obstacle g = 0.2 (y - 1/2), which penetrates only for y > 1/2, gives the same
  // s1 as max(g, 0) (the negative part must not enter the boundary values).
  auto s1For = [&](const std::string& obstacle) {
    EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
    s.finish({{"Dirichlet Segments", "left"}, {"Contact Segments", "right"}, {"Obstacle", obstacle}});
    s.u->putScalar(0.0);
    s.pred->putScalar(0.0);
    for (auto& l : s.lambda) l = -0.02;
    return s.run(true).s1;
  };
  const double positivePart = s1For("max(0.2*(y - 0.5), 0)");
  ASSERT_GT(positivePart, 0.0);
  EXPECT_NEAR(s1For("0.2*(y - 0.5)"), positivePart, 1e-12 * positivePart);
}

TEST(ResidualEstimatorS1, RefusesAnObstacleThatIsNotFiniteAtAContactNode) {
  // 1 / |y - 1/2| is finite at every Gauss point of the contact edges but inf at the node (1, 1/2),
  // where s1 takes it: a user error that names the obstacle and the point (its CG used to fail).
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 2);
  s.finish({{"Dirichlet Segments", "left"}, {"Contact Segments", "right"}, {"Obstacle", "1/abs(y - 0.5)"}});
  s.u->putScalar(0.0);
  s.pred->putScalar(0.0);
  std::string message;
  try {
    s.run(true);
  } catch (const core::UserError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("Problem/Obstacle: '1/abs(y - 0.5)' evaluates to inf at (1, 0.5)"), std::string::npos) << message;
  EXPECT_NE(message.find("the estimator's s1"), std::string::npos) << message;
}

TEST(ResidualEstimatorS1, OperatorsFromTheStepMatricesAndWarmStartsGiveTheSameValue) {
  // s1 with its H^1 operator formed from the step's M_rho and K_kappa (rho = 2, kappa = 3) and with
  // the continuation cached per mesh (second call on the same mesh starts from the first
  // continuation; a "new" mesh id starts from a guess) equals the plainly assembled, cold-started s1.
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 2);
  s.refineWhere([](double x, double y) { return x > 0.5 && y < 0.5; });
  s.finish({{"Dirichlet Segments", "left"}, {"Contact Segments", "right"}, {"Obstacle", "0.1 * sin(3 * y) + 0.05"}},
           2.0, 3.0);
  s.interpolate([](double x, double y) { return 0.02 * x * (1 + y); }, *s.u);
  auto params = estimate::ResidualEstimator::getValidParameters();
  params.set("Scaling", "step");
  const double plain = estimate::ResidualEstimator(params).estimate(
      estimate::EstimatorInput{*s.forest, *s.mesh, *s.assembler, *s.problem, s.coupling.get(), s.time, s.k, s.beta,
                               *s.u, *s.pred, s.lambda, solveCG}).s1;
  ASSERT_GT(plain, 0.0);
  const RCP<const CrsMatrix> M = s.assembler->assembleSystem(1.0, 0.0, *s.problem);
  const RCP<const CrsMatrix> K = s.assembler->assembleSystem(0.0, 1.0, *s.problem);
  estimate::ResidualEstimator cached(params);
  auto withCache = [&](long meshId, const Vector* guess) {
    return cached.estimate(estimate::EstimatorInput{*s.forest, *s.mesh, *s.assembler, *s.problem, s.coupling.get(),
                                                    s.time, s.k, s.beta, *s.u, *s.pred, s.lambda, solveCG, meshId,
                                                    guess, M, K}).s1;
  };
  EXPECT_NEAR(withCache(7, nullptr), plain, 1e-10 * plain);
  ASSERT_FALSE(cached.continuationOn(7).is_null());
  EXPECT_TRUE(cached.continuationOn(8).is_null());
  EXPECT_NEAR(withCache(7, nullptr), plain, 1e-10 * plain);  // warm start from the first continuation
  Vector guess(s.mesh->ownedMap());
  guess.putScalar(0.3);  // any values: the prescribed ones are reset
  EXPECT_NEAR(withCache(8, &guess), plain, 1e-10 * plain);
}

// ---------------------------------------------------------------------------------------------
// 6. Parallel agreement: the world communicator against rank 0 alone (same mesh and data).

/// A problem with every ingredient: several trees, hanging faces across tree boundaries and
/// across ranks, Dirichlet, Neumann, homogeneous Neumann and contact edges, an active positive part.
std::unique_ptr<EstimatorCase> richProblem(bool distorted, std::shared_ptr<mesh::CoarseMesh> coarse,
                                           RCP<const Comm> comm) {
  auto s = std::make_unique<EstimatorCase>(coarse, distorted ? kDistortedSides : kSides, 2, comm);
  const double x1 = distorted ? 0.5 : 1.0;  // a tree boundary of the rectangle 2 x 1
  for (int pass = 0; pass < 2; ++pass)
    s->refineWhere([&](double x, double y) { return x > x1 - 0.3 && x < x1 && y < 0.6; });
  const double xr = distorted ? 0.8 : 1.8;
  s->refineWhere([&](double x, double y) { return x > xr && y > 0.5; });
  s->finish({{"Dirichlet Segments", "left"},
             {"Contact Segments", "right"},
             {"Neumann Segments", "top"},
             {"Neumann Data", "0.3*x"},
             {"Body Force", "1 + x*y"},
             {"Obstacle", distorted ? "0.15 - 0.2*y" : "0.1 - 0.2*y"}},
            1.7, 0.9);
  auto u = [](double x, double y) { return 0.1 * std::sin(2 * x) * std::cos(3 * y) + 0.05 * x * y; };
  s->interpolate(u, *s->u);
  s->interpolate([&](double x, double y) { return u(x, y) + 0.01 * std::cos(x + y); }, *s->pred);
  for (size_t j = 0; j < s->lambda.size(); ++j) s->lambda[j] = -0.001 * (1 + 0.3 * std::sin(double(j)));
  return s;
}

/// (centroid x, centroid y, indicator) of every local cell.
std::vector<std::array<double, 3>> cellTriples(const EstimatorCase& s, const estimate::EstimatorResult& r) {
  std::vector<std::array<double, 3>> t;
  const auto& X = s.mesh->cornerCoordsHost;
  for (LO e = 0; e < s.mesh->numLocalCells(); ++e) {
    double cx = 0, cy = 0;
    for (int c = 0; c < 4; ++c) cx += 0.25 * X(e, c, 0), cy += 0.25 * X(e, c, 1);
    t.push_back({cx, cy, r.cellIndicator[e]});
  }
  return t;
}

class ParallelTest : public ::testing::TestWithParam<bool> {};

TEST_P(ParallelTest, AllRanksAgreeWithOneRank) {
  const bool distorted = GetParam();
  const auto world = Tpetra::getDefaultComm();
  const int rank = world->getRank();
  // The coarse mesh (connectivity and geometry) does not depend on the communicator.
  auto coarse = distorted ? distortedSquare(world) : mesh::CoarseMesh::rectangle(0, 2, 0, 1, 2, 1);
  auto s = richProblem(distorted, coarse, world);
  const auto r = s->run();
  EXPECT_GT(r.etaStar, 0.0);
  EXPECT_GT(r.s0, 0.0);
  EXPECT_GT(r.s1, 0.0);
  EXPECT_NEAR(s->indicatorSum(r), r.etaStar * r.etaStar + r.s0 * r.s0, 1e-12 * (r.etaStar * r.etaStar + r.s0 * r.s0));
  // Gather the cell indicators on rank 0.
  const auto mine = cellTriples(*s, r);
  std::vector<double> flat;
  for (const auto& t : mine) flat.insert(flat.end(), t.begin(), t.end());
  MPI_Comm raw = core::rawMpiComm(*world);
  int n = static_cast<int>(flat.size());
  std::vector<int> counts(world->getSize()), offsets(world->getSize(), 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, raw);
  for (int p = 1; p < world->getSize(); ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(rank == 0 ? offsets.back() + counts.back() : 0);
  MPI_Gatherv(flat.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, raw);

  // Rank 0 alone, on its own communicator.
  const auto self = world->split(rank == 0 ? 0 : 1, rank);
  if (rank == 0) {
    ASSERT_EQ(self->getSize(), 1);
    auto serial = richProblem(distorted, coarse, self);
    const auto rs = serial->run();
    EXPECT_NEAR(r.etaStar, rs.etaStar, 1e-12 * rs.etaStar);
    EXPECT_NEAR(r.s0, rs.s0, 1e-12 * rs.s0);
    EXPECT_NEAR(r.s1, rs.s1, 1e-12 * rs.s1);
    EXPECT_NEAR(r.eta, rs.eta, 1e-12 * rs.eta);
    auto ref = cellTriples(*serial, rs);
    std::vector<std::array<double, 3>> got;
    for (size_t i = 0; i + 2 < all.size(); i += 3) got.push_back({all[i], all[i + 1], all[i + 2]});
    ASSERT_EQ(got.size(), ref.size());
    // Centroids are computed from identical coordinates in both runs: sort by them exactly.
    auto byCentroid = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
    };
    std::sort(got.begin(), got.end(), byCentroid);
    std::sort(ref.begin(), ref.end(), byCentroid);
    double maxInd = 0;
    for (const auto& t : ref) maxInd = std::max(maxInd, t[2]);
    for (size_t i = 0; i < ref.size(); ++i) {
      ASSERT_EQ(got[i][0], ref[i][0]);
      ASSERT_EQ(got[i][1], ref[i][1]);
      EXPECT_NEAR(got[i][2], ref[i][2], 1e-12 * maxInd) << "cell at (" << ref[i][0] << ", " << ref[i][1] << ")";
    }
  }
  Teuchos::barrier(*world);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ParallelTest, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "distortedQuads" : "rectangles"); });

// ---------------------------------------------------------------------------------------------

TEST(ResidualEstimatorScaling, PhysicalScalingDividesByBetaKSquaredKappa) {
  // eta_* / (beta k^2 kappa), s0 / sqrt(beta k^2 kappa), s1 unchanged; indicators rescaled term by
  // term (kappa = 3: neither 1 nor rho).
  EstimatorCase s(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
  s.finish({{"Dirichlet Segments", "right"}, {"Contact Segments", "left"}, {"Obstacle", "0.3"}}, 1.0, 3.0);
  s.interpolate([](double x, double y) { return std::sin(x) * y; }, *s.u);
  s.interpolate([](double x, double y) { return x * y; }, *s.pred);
  for (int j = 0; j < s.coupling->numSegments(); ++j) s.lambda[j] = -0.01 * (1 + 0.1 * j);
  const auto step = s.run(true, "step"), physical = s.run(true, "physical");
  const double c = s.bk2() * 3.0;
  EXPECT_GT(step.etaStar, 0.0);
  EXPECT_GT(step.s0, 0.0);
  EXPECT_NEAR(s.indicatorSum(physical), physical.etaStar * physical.etaStar + physical.s0 * physical.s0,
              1e-10 * physical.etaStar * physical.etaStar);
  EXPECT_NEAR(physical.etaStar, step.etaStar / c, 1e-12 * physical.etaStar);
  EXPECT_NEAR(physical.s0, step.s0 / std::sqrt(c), 1e-12 * std::max(physical.s0, 1e-300));
  EXPECT_NEAR(physical.s1, step.s1, 1e-12 * std::max(step.s1, 1e-300));
  EXPECT_NEAR(physical.eta, physical.etaStar + physical.s0 + physical.s1, 1e-12 * physical.eta);
}

TEST(ResidualEstimatorScaling, PhysicalScalingDoesNotDependOnTheUnitOfForce) {
  // The same problem with every force-carrying datum (rho, kappa, f, q, lambda) in a unit 1e6 times
  // smaller (Pa against MPa) has the same displacement; the physical estimate, divided by
  // beta k^2 kappa, must be the same too, term by term and cell by cell. The step form is not.
  auto estimateIn = [](double unit) {
    auto s = std::make_unique<EstimatorCase>(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 1, 1), kSides, 3);
    s->refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
    s->finish({{"Dirichlet Segments", "right"},
               {"Contact Segments", "left"},
               {"Neumann Segments", "top"},
               {"Obstacle", "0.3"},
               {"Body Force", num(unit) + " * (1 + x)"},
               {"Neumann Data", num(unit) + " * (x - 0.2)"}},
              2.0 * unit, 3.0 * unit);
    s->interpolate([](double x, double y) { return std::sin(x) * y; }, *s->u);
    s->interpolate([](double x, double y) { return x * y; }, *s->pred);
    for (int j = 0; j < s->coupling->numSegments(); ++j) s->lambda[j] = -0.01 * unit * (1 + 0.1 * j);
    return std::make_pair(s->run(true, "physical"), s->run(true, "step"));
  };
  const auto [pa, paStep] = estimateIn(1.0);
  const auto [mpa, mpaStep] = estimateIn(1e-6);
  test::expectSameEstimate(pa, mpa);
  // Control: the step form scales with the unit (eta_* by it, s0 by its square root).
  EXPECT_NEAR(mpaStep.etaStar, 1e-6 * paStep.etaStar, 1e-12 * paStep.etaStar);
  EXPECT_NEAR(mpaStep.s0, 1e-3 * paStep.s0, 1e-12 * paStep.s0);
}

TEST(FaceWalk, DirectWalkOfOneTreeGivesP4estsFacePairs) {
  // Interior faces of a graded forest of one tree: conforming faces and 2:1 faces with the fine
  // side on either side in both directions; on several ranks also the faces between a local cell
  // and a ghost, found from either side. Cells are named by their global index and level (the
  // payload, which the ghosts carry too).
  test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 1, 1, 2);
  ASSERT_EQ(tm.forest->p4est()->connectivity->num_trees, 1);
  tm.refineGraded();
  tm.forest->partition();
  const auto& level = tm.build().cellLevel();
  const p4est_t* p4est = tm.forest->p4est();
  std::vector<std::array<long long, 2>> payload(level.size());  // global index, level
  for (size_t e = 0; e < payload.size(); ++e)
    payload[e] = {static_cast<long long>(p4est->global_first_quadrant[p4est->mpirank] + static_cast<long long>(e)),
                  static_cast<long long>(level[e])};
  int hangingHalves = 0, withGhost = 0;
  auto pairs = [&](estimate::FaceWalk walk) {
    std::vector<std::array<long long, 4>> out;  // A's cell and face, B's cell and face
    hangingHalves = withGhost = 0;
    estimate::forEachInteriorFace<std::array<long long, 2>>(
        *tm.forest, payload, [](const std::vector<std::array<long long, 2>>&) {},
        [&](const estimate::FaceSide<std::array<long long, 2>>& a, const estimate::FaceSide<std::array<long long, 2>>& b) {
          if (walk == estimate::FaceWalk::automatic) { EXPECT_TRUE(a.local >= 0 || b.local >= 0); }
          if (a.local < 0 && b.local < 0) return;  // p4est_iterate's other half of a 2:1 face (ignored by the callers)
          EXPECT_GE((*a.data)[1], (*b.data)[1]);  // A is the fine side
          std::array<long long, 4> p{(*a.data)[0], a.face, (*b.data)[0], b.face};
          if ((*a.data)[1] == (*b.data)[1] && p[2] < p[0]) p = {p[2], p[3], p[0], p[1]};
          hangingHalves += (*a.data)[1] > (*b.data)[1];
          withGhost += a.local < 0 || b.local < 0;
          out.push_back(p);
        },
        walk);
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto viaP4est = pairs(estimate::FaceWalk::p4est);
  const int hangingViaP4est = hangingHalves, ghostViaP4est = withGhost;
  const auto direct = pairs(estimate::FaceWalk::automatic);
  EXPECT_EQ(direct, viaP4est);
  EXPECT_EQ(std::adjacent_find(direct.begin(), direct.end()), direct.end());  // each face once
  EXPECT_EQ(hangingHalves, hangingViaP4est);
  EXPECT_EQ(withGhost, ghostViaP4est);
  int halves = hangingHalves, ghosts = withGhost;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, 1, &hangingHalves, &halves);
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, 1, &withGhost, &ghosts);
  EXPECT_GT(halves, 16);
  if (Tpetra::getDefaultComm()->getSize() > 1) { EXPECT_GT(ghosts, 0); }
}

TEST(ResidualEstimatorParameters, ValidListIsDocumentedAndChecked) {
  const auto valid = estimate::ResidualEstimator::getValidParameters();
  EXPECT_EQ(valid.name(), "Estimator");
  ASSERT_TRUE(valid.isParameter("Compute S1"));
  EXPECT_TRUE(valid.get<bool>("Compute S1"));
  EXPECT_FALSE(valid.getEntry("Compute S1").docString().empty());
  core::ParameterList bad("Estimator");
  bad.set("Compute S2", true);
  EXPECT_THROW(estimate::ResidualEstimator{bad}, core::UserError);
  core::ParameterList empty("Estimator");
  EXPECT_NO_THROW(estimate::ResidualEstimator{empty});  // defaults filled in
}

}  // namespace

// The per-cell sums of edge terms under reproducible arithmetic: the faces arrive in another order
// on every partition, the sums must not change a bit; two cells with more terms than kept in place
// (11 and 10 here, as no mesh gives), their terms interleaved, and a cell without terms included.
// The control: ordinary sums of the same terms in the two orders differ.
TEST(CellSums, ReproducibleSumsDoNotDependOnTheOrderOfTheTerms) {
  constexpr LO kCells = 5;
  const std::vector<std::pair<LO, double>> terms = {
      {0, 1e16}, {1, 0.5}, {0, 1.0}, {2, 3.0}, {0, -1e16}, {4, 1e16}, {1, 1e-20}, {0, 1.0}, {4, 1.0},
      {1, 0.25}, {0, 2.0}, {4, -1e16}, {0, 1e-3}, {4, 1.0}, {0, 7.0}, {4, 2.0}, {0, 1e15}, {4, 5.0},
      {0, 0.0}, {4, 1e15}, {0, 3.5}, {4, -1e15}, {0, -1e15}, {4, 0.125}, {2, 1e-8}, {4, 9.0}};
  auto sums = [&](bool reproducible, bool reversed) {
    const test::ReproducibleScope scope(reproducible);
    estimate::CellSums cells(kCells);
    for (size_t i = 0; i < terms.size(); ++i) {
      const auto& [cell, value] = terms[reversed ? terms.size() - 1 - i : i];
      cells.add(cell, value);
    }
    return cells.finish();
  };
  const auto forward = sums(true, false), backward = sums(true, true);
  EXPECT_EQ(forward[3], 0.0);
  for (LO e = 0; e < kCells; ++e) {
    std::vector<double> sorted;
    for (const auto& [cell, value] : terms)
      if (cell == e) sorted.push_back(value);
    std::sort(sorted.begin(), sorted.end());
    double expected = 0.0;
    for (double v : sorted) expected += v;
    EXPECT_EQ(std::memcmp(&forward[e], &expected, sizeof(double)), 0) << "cell " << e;
    EXPECT_EQ(std::memcmp(&backward[e], &expected, sizeof(double)), 0) << "cell " << e;
  }
  const auto plainForward = sums(false, false), plainBackward = sums(false, true);
  EXPECT_NE(plainForward[0], plainBackward[0]);  // the control
  EXPECT_NE(plainForward[4], plainBackward[4]);
}
