// Facts about the elasticity estimator (docs/estimator.md):
//  - it vanishes for a linear displacement (constant stress) with consistent tractions and
//    multipliers, also with hanging nodes, and a wrong traction is detected;
//  - a kink (|x - 1/2| or |y - 1/2| in either component) gives the exact traction-jump indicators
//    h_K (beta k^2 C)^2 |dK on the kink| (C = lambda + 2 mu or mu) next to the kink and nothing
//    elsewhere, with hanging faces on the kink and on trapezoids (Gauss points on the faces);
//  - div sigma(u_h) of a bilinear field (cross terms, and on parallelograms all second
//    derivatives) enters the cell residual exactly: a matching body force gives eta_* = 0, the
//    opposite one sum_K h_K^2 |K| (2 beta k^2 |div sigma|)^2;
//  - on a roller side only the free component's traction counts, with its exact value;
//  - eta_* decreases like h under uniform refinement of a smooth problem;
//  - s0 and s1 of the constrained component equal the scalar estimator's for the same field,
//    for either sign of the contact direction;
//  - 1, 2 and 3 ranks give the same values as one rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/estimate/ElasticityEstimator.hpp"
#include "signorini/core/MpiComm.hpp"
#include "../QuadMeshes.hpp"
#include "SameEstimate.hpp"
#include "SolveCG.hpp"
#include "../TestMesh.hpp"

using namespace signorini;
using test::solveCG;

namespace {

std::string num(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

constexpr double kE = 2.0, kNu = 0.3;

/// One problem on the unit square (segments left, right, bottom, top) over any communicator.
struct Case {
  RCP<const Comm> comm;
  std::shared_ptr<mesh::CoarseMesh> coarse;
  std::unique_ptr<mesh::BoundarySegments> segments;
  std::unique_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;
  std::unique_ptr<fem::ProblemData> problem;
  std::unique_ptr<fem::ElasticityAssembler> assembler;
  std::unique_ptr<fem::ContactCoupling> coupling;
  RCP<Vector> u, pred;
  std::vector<double> lambda;
  double beta = 0.25, k = 0.1, time = 0.3;
  double forceUnit = 1.0;  ///< Young's modulus and density are kE and 2 in this unit

  /// The unit square as 2 x 2 trees at \p level; \p hanging: the cells with centre in the lower left
  /// quarter refined twice (hanging nodes on x = 1/2 and y = 1/2).
  Case(int level, bool hanging, RCP<const Comm> cm = Tpetra::getDefaultComm())
      : Case(mesh::CoarseMesh::rectangle(0, 1, 0, 1, 2, 2),
             {{"left", "left"}, {"right", "right"}, {"bottom", "bottom"}, {"top", "top"}}, level, cm) {
    if (hanging)
      for (int pass = 0; pass < 2; ++pass) refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
  }
  /// Any coarse mesh with the given segments (name, specification) at \p level.
  Case(std::shared_ptr<mesh::CoarseMesh> c, const std::vector<std::pair<std::string, std::string>>& segs, int level,
       RCP<const Comm> cm = Tpetra::getDefaultComm())
      : comm(cm), coarse(std::move(c)) {
    segments = std::make_unique<mesh::BoundarySegments>(segs, *coarse);
    forest = std::make_unique<mesh::Forest>(coarse, core::rawMpiComm(*comm), level);
  }
  /// Refines (once) the cells whose centre satisfies \p where, then balances.
  void refineWhere(const std::function<bool(double, double)>& where) { test::refineWhere(*forest, *coarse, where); }
  void finish(const std::map<std::string, std::string>& entries) {
    forest->partition();
    mesh = std::make_unique<mesh::Q1Mesh>(*forest, *segments, comm);
    auto p = fem::ProblemData::getValidParameters();
    p.set("Type", "plane strain elasticity");
    p.set("Young's Modulus", kE * forceUnit);
    p.set("Poisson's Ratio", kNu);
    p.set("Density", 2.0 * forceUnit);
    for (const auto& [key, value] : entries) p.set(key, value);
    problem = std::make_unique<fem::ProblemData>(p, *segments);
    assembler = std::make_unique<fem::ElasticityAssembler>(
        *mesh, fem::ElasticityAssembler::dirichletUnknowns(*mesh, *problem), problem->lameLambda, problem->lameMu);
    if (problem->hasObstacle) {
      coupling = std::make_unique<fem::ContactCoupling>(
          *mesh, problem->contactMask, fem::ContactCoupling::SegmentSize::TwoEdges, assembler->dirichletFlags(),
          fem::ContactUnknowns{assembler->ownedMap(), assembler->overlapMap(), 2, problem->contactComponent,
                               problem->contactSign});
      lambda.assign(coupling->numSegments(), 0.0);
    }
    u = Teuchos::rcp(new Vector(assembler->ownedMap()));
    pred = Teuchos::rcp(new Vector(assembler->ownedMap()));
  }
  void interpolate(const std::function<double(double, double)>& fx, const std::function<double(double, double)>& fy,
                   Vector& v) const {
    auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < h.extent(0) / 2; ++i) {
      const auto& X = mesh->nodeCoords()[i];
      h(2 * i, 0) = fx(X[0], X[1]);
      h(2 * i + 1, 0) = fy(X[0], X[1]);
    }
  }
  estimate::EstimatorResult run(const std::string& scaling = "step", double s1LengthScale = 1.0) const {
    auto params = estimate::ResidualEstimator::getValidParameters();
    params.set("Scaling", scaling);
    params.set("S1 Length Scale", s1LengthScale);
    estimate::ElasticityEstimator est(params);
    return est.estimate(estimate::ElasticityEstimatorInput{*forest, *mesh, *assembler, *problem, coupling.get(), time, k,
                                                           beta, *u, *pred, lambda, solveCG});
  }
  double bk2() const { return beta * k * k; }
  double lameLambda() const { return problem->lameLambda; }
  double lameMu() const { return problem->lameMu; }
};

/// The traction sigma n of a constant stress on the four sides, as "qx, qy" expressions.
std::string sideTractions(double sxx, double syy, double sxy) {
  auto side = [&](int c) {
    const double l = c == 0 ? -sxx : -sxy, r = c == 0 ? sxx : sxy, b = c == 0 ? -sxy : -syy, t = c == 0 ? sxy : syy;
    return "(x < 0.001 ? " + num(l) + " : (x > 0.999 ? " + num(r) + " : (y < 0.001 ? " + num(b) + " : " + num(t) + ")))";
  };
  return side(0) + ", " + side(1);
}

/// Corner pairs (z-order) of the faces 0:-x 1:+x 2:-y 3:+y of a cell (as p4est_face_corners).
constexpr int kFaceCorners[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};

/// h_K of local cell e: its longest diagonal (docs/estimator.md, Section 2).
double diameter(const Case& c, LO e) {
  const auto& X = c.mesh->cornerCoordsHost;
  return std::max(std::hypot(X(e, 3, 0) - X(e, 0, 0), X(e, 3, 1) - X(e, 0, 1)),
                  std::hypot(X(e, 2, 0) - X(e, 1, 0), X(e, 2, 1) - X(e, 1, 1)));
}

/// |K| of local cell e (shoelace formula over the corners in cyclic order 0, 1, 3, 2).
double area(const Case& c, LO e) {
  const auto& X = c.mesh->cornerCoordsHost;
  const int cyc[4] = {0, 1, 3, 2};
  double a = 0;
  for (int i = 0; i < 4; ++i) {
    const int p = cyc[i], q = cyc[(i + 1) % 4];
    a += X(e, p, 0) * X(e, q, 1) - X(e, q, 0) * X(e, p, 1);
  }
  return 0.5 * std::abs(a);
}

/// The length of the boundary of local cell e on the line {x_axis = value}.
double lengthOnLine(const Case& c, LO e, int axis, double value) {
  const auto& X = c.mesh->cornerCoordsHost;
  double len = 0;
  for (const auto& f : kFaceCorners)
    if (std::abs(X(e, f[0], axis) - value) < 1e-12 && std::abs(X(e, f[1], axis) - value) < 1e-12)
      len += std::hypot(X(e, f[1], 0) - X(e, f[0], 0), X(e, f[1], 1) - X(e, f[0], 1));
  return len;
}

double sumOverRanks(const Case& c, double local) {
  double global = 0;
  Teuchos::reduceAll(*c.comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

/// Two trees side by side with the common side on x = 1/2: (0,0), (1/2,0), (1/2,6/5), (0,1) and
/// (1/2,0), (1,0), (1,1), (1/2,6/5), the second listed from another corner. Neither is a
/// parallelogram, so neither are their cells (the face terms use Gauss points); one side set
/// "boundary" holds all boundary sides.
std::shared_ptr<mesh::CoarseMesh> twoTrapezoids() {
  return test::exodusCoarseMesh({0, 0.5, 1, 0, 0.5, 1}, {0, 0, 0, 1, 1.2, 1}, {{0, 1, 4, 3}, {2, 5, 4, 1}},
                                "elasticityTrapezoids");
}

/// The parallelogram x = s + a r, y = b s + r (a = 1/2, b = 1/4) of the tree coordinates s, r in
/// [0,1]: corners (0,0), (1,1/4), (3/2,5/4), (1/2,1); one side set "boundary".
constexpr double kShearA = 0.5, kShearB = 0.25;
std::shared_ptr<mesh::CoarseMesh> parallelogram() {
  return test::exodusCoarseMesh({0, 1, 1 + kShearA, kShearA}, {0, kShearB, 1 + kShearB, 1}, {{0, 1, 2, 3}},
                                "elasticityParallelogram");
}

struct ExactCase {
  const char* name;
  bool hanging, contact;
};
class ElasticityExact : public ::testing::TestWithParam<ExactCase> {};

TEST_P(ElasticityExact, LinearFieldWithConsistentTractionsHasZeroEstimate) {
  const auto& c = GetParam();
  // u = (0.1 + 0.3 x - 0.2 y, -0.4 + 0.2 x + 0.7 y): constant strain, no shear stress (so the
  // frictionless contact side at the bottom is consistent too).
  auto fx = [](double x, double y) { return 0.1 + 0.3 * x - 0.2 * y; };
  auto fy = [](double x, double y) { return -0.4 + 0.2 * x + 0.7 * y; };
  Case probe(1, false);
  probe.finish({});
  const double l = probe.lameLambda(), m = probe.lameMu();
  const double sxx = l * 1.0 + 2 * m * 0.3, syy = l * 1.0 + 2 * m * 0.7, sxy = 0.0;
  std::map<std::string, std::string> entries = {{"Neumann Data", sideTractions(sxx, syy, sxy)}};
  if (c.contact) {
    entries["Neumann Segments"] = "left, right, top";
    entries["Contact Segments"] = "bottom";
    entries["Obstacle"] = "-10";
  } else {
    entries["Neumann Segments"] = "left, right, bottom, top";
  }
  Case s(2, c.hanging);
  s.finish(entries);
  s.interpolate(fx, fy, *s.u);
  s.interpolate(fx, fy, *s.pred);
  // On the bottom, beta k^2 (sigma n)_y + lambda_H = 0 with (sigma n)_y = -syy.
  for (auto& v : s.lambda) v = s.bk2() * syy;
  const auto r = s.run();
  const double scale = s.bk2() * (std::abs(sxx) + std::abs(syy));
  EXPECT_LT(r.etaStar, 1e-11 * scale);
  EXPECT_EQ(r.s0, 0.0);
  EXPECT_EQ(r.s1, 0.0);
  for (double v : r.cellIndicator) EXPECT_LT(v, 1e-22 * scale * scale);
  // Control: the top left without its traction is detected.
  entries["Neumann Segments"] = c.contact ? "left, right" : "left, right, bottom";
  Case w(2, c.hanging);
  w.finish(entries);
  w.interpolate(fx, fy, *w.u);
  w.interpolate(fx, fy, *w.pred);
  w.lambda = std::vector<double>(w.lambda.size(), w.bk2() * syy);
  EXPECT_GT(w.run().etaStar, 0.1 * s.bk2() * syy);

  // Inertia and body force: the predictor u_h + delta (delta linear, per component) and
  // f = -rho delta / (beta k^2) cancel in the cell residual; f of the other sign leaves 2 rho delta.
  entries["Neumann Segments"] = c.contact ? "left, right, top" : "left, right, bottom, top";
  const double rho = 2.0;  // the Case's density
  double etaWithForce[2];
  for (int sign : {1, -1}) {
    Case v(2, c.hanging);
    std::ostringstream f;
    f.precision(17);
    f << -sign * rho / v.bk2();
    auto withForce = entries;
    withForce["Body Force"] = f.str() + " * (0.2 + 0.1*x), " + f.str() + " * (-0.3 + 0.2*y)";
    v.finish(withForce);
    v.interpolate(fx, fy, *v.u);
    v.interpolate([&](double x, double y) { return fx(x, y) + 0.2 + 0.1 * x; },
                  [&](double x, double y) { return fy(x, y) - 0.3 + 0.2 * y; }, *v.pred);
    v.lambda = std::vector<double>(v.lambda.size(), v.bk2() * syy);
    etaWithForce[sign > 0 ? 0 : 1] = v.run().etaStar;
  }
  EXPECT_GT(etaWithForce[1], 1e-3 * rho);  // h ||2 rho delta||: far from rounding
  EXPECT_LT(etaWithForce[0], 1e-11 * etaWithForce[1]);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ElasticityExact,
                         ::testing::Values(ExactCase{"rectangles", false, false}, ExactCase{"hanging", true, false},
                                           ExactCase{"hangingContact", true, true}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ElasticityEstimator, RollersCheckOnlyTheFreeComponent) {
  // u = (0, 0.3 x + 0.5 y) satisfies the roller u_x = 0 on the left side. Its gradient is constant
  // (u_y,x = 0.3, u_y,y = 0.5, u_x,x = u_x,y = 0), so tr eps = 0.5 and
  //   sigma_xx = 0.5 lambda, sigma_yy = 0.5 (lambda + 2 mu), sigma_xy = 0.3 mu   (constant);
  // u_h = u (linear), hence no interior jumps and div sigma(u_h) = 0; with predictor = u_h and f = 0
  // there is no cell residual. Right, bottom and top carry the tractions of this stress (R = 0).
  // On the left, n = (-1, 0), sigma n = -(sigma_xx, sigma_xy); u_x is fixed there, so only
  // R_y = beta k^2 (sigma n)_y = -0.3 mu beta k^2 counts (the side carries no datum for u_y): every
  // cell with a face E on x = 0 gets h_K |E| (0.3 mu beta k^2)^2, every other cell 0.
  // The left side of Case(2, true): 16 cells of side 1/32 (y < 1/2, refined twice), 2 of side 1/16
  // (the cell [0,1/8] x [1/2,5/8] touches the twice refined quarter and is refined by the 2:1
  // balance) and 3 of side 1/8; h_K = sqrt 2 |E|, so sum h_K |E| = sqrt 2 (16/32^2 + 2/16^2 + 3/8^2)
  // = 9 sqrt(2) / 128.
  auto fx = [](double, double) { return 0.0; };
  auto fy = [](double x, double y) { return 0.3 * x + 0.5 * y; };
  Case probe(1, false);
  probe.finish({});
  const double l = probe.lameLambda(), m = probe.lameMu();
  const double sxx = l * 0.5, syy = (l + 2 * m) * 0.5, sxy = 0.3 * m;
  auto check = [&](Case& c, double edgeR2) {  // edgeR2 = |R|^2 on the left side
    c.interpolate(fx, fy, *c.u);
    c.interpolate(fx, fy, *c.pred);
    const auto r = c.run();
    double local = 0;
    for (LO e = 0; e < c.mesh->numLocalCells(); ++e) {
      const double expected = diameter(c, e) * lengthOnLine(c, e, 0, 0.0) * edgeR2;
      local += expected;
      if (expected > 0)
        EXPECT_NEAR(r.cellIndicator[e], expected, 1e-12 * expected) << "cell " << e;
      else
        EXPECT_LT(r.cellIndicator[e], 1e-24 * edgeR2) << "cell " << e << " away from the left side";
    }
    const double total = sumOverRanks(c, local);
    EXPECT_NEAR(total, 9 * std::sqrt(2.0) / 128 * edgeR2, 1e-14 * edgeR2);
    EXPECT_NEAR(r.etaStar * r.etaStar, total, 1e-12 * total);
  };
  Case s(2, true);
  s.finish({{"Dirichlet X Segments", "left"},
            {"Neumann Segments", "right, bottom, top"},
            {"Neumann Data", sideTractions(sxx, syy, sxy)}});
  check(s, std::pow(0.3 * m * s.bk2(), 2));
  // Without the roller the left side's whole traction counts: |R|^2 = (beta k^2)^2 (sigma_xx^2 + sigma_xy^2).
  Case w(2, true);
  w.finish({{"Neumann Segments", "right, bottom, top"}, {"Neumann Data", sideTractions(sxx, syy, sxy)}});
  check(w, std::pow(w.bk2(), 2) * (sxx * sxx + sxy * sxy));
}

// ---------------------------------------------------------------------------------------------
// Kinks: exact traction jumps on the interior faces.

struct KinkCase {
  const char* name;
  int mesh;       ///< 0: 2 x 2 trees, 8 x 8 cells; 1: the same with hanging faces on the kink; 2: two trapezoids
  int axis;       ///< the kink |x_axis - 1/2|
  int component;  ///< in this component of u
};
class ElasticityKink : public ::testing::TestWithParam<KinkCase> {};

TEST_P(ElasticityKink, JumpIndicatorsAreLocalisedAndExact) {
  const auto& p = GetParam();
  std::unique_ptr<Case> s;
  if (p.mesh == 2) {
    // Level 2 (4 x 4 cells per tree); the cells with centre x < 1/2, y < 1/2 are the lower two rows
    // of the left tree (their centres have y <= 3/8 * 6/5 < 1/2): refined once, so the kink has 4
    // fine cells and 2 coarse cells on the left and 4 cells on the right.
    s = std::make_unique<Case>(twoTrapezoids(), std::vector<std::pair<std::string, std::string>>{{"wall", "boundary"}}, 2);
    s->refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
    s->finish({{"Dirichlet Segments", "wall"}});
  } else {
    s = std::make_unique<Case>(2, p.mesh == 1);
    s->finish({{"Dirichlet Segments", "left, right, bottom, top"}});
  }
  // u_c = |x_a - 1/2| (a = axis, c = component), u_other = 0, clamped all round, predictor = u_h,
  // f = 0. u is linear on either side of the kink, which is a mesh line, so u_h = u (also at the
  // hanging nodes: u is linear along every face) and its Hessian vanishes on every cell (m = 0 for a
  // linear field on any quadrilateral): the cell residuals are 0 and only the kink's faces carry a
  // jump. The only non-zero gradient entry is du_c/dx_a = +-1 (the sign of x_a - 1/2). With n = e_a:
  //   c = a: sigma_aa = (lambda + 2 mu)(+-1), sigma_ab = 0 (b != a), so [sigma n] = -+2 (lambda + 2 mu) e_a;
  //   c != a: sigma_ac = mu (+-1), the normal stresses lambda tr eps = 0, so [sigma n] = -+2 mu e_c.
  // R = -(beta k^2 / 2)[sigma n] has |R| = beta k^2 C, C = lambda + 2 mu or mu; each side K of a
  // kink face E gets h_K |R|^2 |E| (the coarse side of a hanging face once per fine half), so
  //   eta_K^2 = h_K (beta k^2 C)^2 |dK on the kink|,  and 0 on every other cell.
  const double C = p.axis == p.component ? s->lameLambda() + 2 * s->lameMu() : s->lameMu();
  const double c2 = std::pow(s->bk2() * C, 2);
  const int a = p.axis, comp = p.component;
  auto kink = [a](double x, double y) { return std::abs((a == 0 ? x : y) - 0.5); };
  auto zero = [](double, double) { return 0.0; };
  const std::function<double(double, double)> ux = comp == 0 ? std::function<double(double, double)>(kink) : zero,
                                               uy = comp == 1 ? std::function<double(double, double)>(kink) : zero;
  s->interpolate(ux, uy, *s->u);
  s->interpolate(ux, uy, *s->pred);
  const auto r = s->run();
  double local = 0;
  int touching = 0;
  for (LO e = 0; e < s->mesh->numLocalCells(); ++e) {
    const double onLine = lengthOnLine(*s, e, a, 0.5);
    const double expected = diameter(*s, e) * c2 * onLine;
    local += expected;
    if (onLine > 0) {
      ++touching;
      EXPECT_NEAR(r.cellIndicator[e], expected, 1e-12 * expected) << "cell " << e;
    } else {
      EXPECT_LT(r.cellIndicator[e], 1e-14 * c2) << "cell " << e << " away from the kink";
    }
  }
  const double total = sumOverRanks(*s, local);
  EXPECT_NEAR(r.etaStar * r.etaStar, total, 1e-12 * total);
  EXPECT_EQ(r.s0, 0.0);
  // Square cells touching the line with side a_K: h_K |dK on the line| = sqrt 2 a_K^2.
  //   uniform 8 x 8: 16 cells of side 1/8: sqrt 2 * 16/64 = sqrt(2)/4;
  //   hanging (Case(2, true), symmetric in x and y): along x = 1/2 on the left 16 cells of side 1/32
  //   (y < 1/2), 2 of side 1/16 (the cell above the quarter, refined by the 2:1 balance) and 3 of
  //   side 1/8; on the right 8 of side 1/16 (balance), 2 of side 1/16 (the cell at the corner
  //   (1/2, 1/2), corner balance) and 3 of side 1/8: sqrt 2 (16/1024 + 2/256 + 3/64 + 10/256 + 3/64)
  //   = sqrt 2 * 5/32; 34 cells.
  if (p.mesh == 0) { EXPECT_NEAR(total, std::sqrt(2.0) / 4 * c2, 1e-14 * c2); }
  if (p.mesh == 1) { EXPECT_NEAR(total, std::sqrt(2.0) * 5 / 32 * c2, 1e-14 * c2); }
  const double count = sumOverRanks(*s, touching);
  EXPECT_EQ(count, p.mesh == 0 ? 16 : p.mesh == 1 ? 34 : 10);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ElasticityKink,
                         ::testing::Values(KinkCase{"xKinkInUx", 0, 0, 0}, KinkCase{"xKinkInUy", 0, 0, 1},
                                           KinkCase{"yKinkInUx", 0, 1, 0}, KinkCase{"yKinkInUy", 0, 1, 1},
                                           KinkCase{"xKinkInUxHanging", 1, 0, 0}, KinkCase{"xKinkInUyHanging", 1, 0, 1},
                                           KinkCase{"yKinkInUxHanging", 1, 1, 0}, KinkCase{"yKinkInUyHanging", 1, 1, 1},
                                           KinkCase{"xKinkInUxTrapezoids", 2, 0, 0},
                                           KinkCase{"xKinkInUyTrapezoids", 2, 0, 1}),
                         [](const auto& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------
// div sigma(u_h) of a bilinear field in the cell residual.

struct BilinearCase {
  const char* name;
  bool parallelogram;  ///< else the 2 x 2 trees of the unit square
  bool hanging;
  int component;  ///< u = P e_component
};
class ElasticityBilinear : public ::testing::TestWithParam<BilinearCase> {};

TEST_P(ElasticityBilinear, DivSigmaEntersTheCellResidualExactly) {
  const auto& p = GetParam();
  auto makeCase = [&]() {
    std::unique_ptr<Case> c;
    if (p.parallelogram) {
      c = std::make_unique<Case>(parallelogram(), std::vector<std::pair<std::string, std::string>>{{"wall", "boundary"}},
                                 p.hanging ? 1 : 2);
      if (p.hanging)
        for (int pass = 0; pass < 2; ++pass) c->refineWhere([](double x, double y) { return x < 0.5 && y < 0.5; });
    } else {
      c = std::make_unique<Case>(2, p.hanging);
    }
    return c;
  };
  // P = x y on the square; P = (x - a y)(y - b x) = (1 - a b)^2 s r on the parallelogram x = s + a r,
  // y = b s + r. Either is bilinear in the reference coordinates of every (sub)cell and linear along
  // every face, so u_h = u = P e_c exactly, hanging nodes included. Its Hessian is constant:
  //   square:        P_xx = 0,    P_yy = 0,    P_xy = 1;
  //   parallelogram: P = (1 + a b) x y - b x^2 - a y^2: P_xx = -2b, P_yy = -2a, P_xy = 1 + a b.
  // div sigma (docs/estimator.md, Section 3), for u = (P, 0) and u = (0, P):
  //   (P, 0): ((lambda + 2 mu) P_xx + mu P_yy, (lambda + mu) P_xy),
  //   (0, P): ((lambda + mu) P_xy, mu P_xx + (lambda + 2 mu) P_yy);
  // e.g. (x y, 0) gives (0, lambda + mu). sigma(u) is continuous and u_h = u, so no face has a jump;
  // clamped all round, no boundary terms. With predictor = u_h the cell residual is
  // r = beta k^2 (f + div sigma): f = -div sigma gives eta_* = 0, f = +div sigma gives
  // eta_K^2 = h_K^2 |K| (2 beta k^2 |div sigma|)^2 on every cell.
  const double A = p.parallelogram ? kShearA : 0.0, B = p.parallelogram ? kShearB : 0.0;
  const double Pxx = -2 * B, Pyy = -2 * A, Pxy = 1 + A * B;
  auto P = [=](double x, double y) { return p.parallelogram ? (x - A * y) * (y - B * x) : x * y; };
  auto zero = [](double, double) { return 0.0; };
  Case probe(1, false);
  probe.finish({});
  const double l = probe.lameLambda(), m = probe.lameMu();
  double etaStar[2];
  for (int sign : {1, -1}) {
    auto c = makeCase();
    const double div[2] = {p.component == 0 ? (l + 2 * m) * Pxx + m * Pyy : (l + m) * Pxy,
                           p.component == 0 ? (l + m) * Pxy : m * Pxx + (l + 2 * m) * Pyy};
    c->finish({{"Dirichlet Segments", p.parallelogram ? "wall" : "left, right, bottom, top"},
               {"Body Force", num(-sign * div[0]) + ", " + num(-sign * div[1])}});
    const std::function<double(double, double)> ux = p.component == 0 ? std::function<double(double, double)>(P) : zero,
                                                 uy = p.component == 1 ? std::function<double(double, double)>(P) : zero;
    c->interpolate(ux, uy, *c->u);
    c->interpolate(ux, uy, *c->pred);
    const auto r = c->run();
    etaStar[sign > 0 ? 0 : 1] = r.etaStar;
    const double r2 = std::pow(2 * c->bk2(), 2) * (div[0] * div[0] + div[1] * div[1]);  // |r|^2 for f = +div sigma
    ASSERT_GT(r2, 0.0);
    double local = 0;
    for (LO e = 0; e < c->mesh->numLocalCells(); ++e) {
      const double hh = diameter(*c, e) * diameter(*c, e) * area(*c, e);
      local += hh;
      if (sign > 0)
        EXPECT_LT(r.cellIndicator[e], 1e-24 * r2) << "cell " << e;
      else
        EXPECT_NEAR(r.cellIndicator[e], hh * r2, 1e-12 * hh * r2) << "cell " << e;
    }
    const double sumH2K = sumOverRanks(*c, local);
    // Uniform meshes: the square's 64 cells have h^2 = 2/64, |K| = 1/64: sum = 1/32. The parallelogram
    // at level 2 has 16 copies of itself scaled by 1/4: diagonals^2 (1 + a)^2 + (1 + b)^2 = 3.8125 and
    // (1 - a)^2 + (1 - b)^2 = 0.8125, area 1 - a b = 0.875: sum = 16 * 3.8125/16 * 0.875/16.
    if (!p.hanging) { EXPECT_NEAR(sumH2K, p.parallelogram ? 3.8125 * 0.875 / 16 : 1.0 / 32, 1e-15); }
    if (sign < 0) { EXPECT_NEAR(r.etaStar * r.etaStar, sumH2K * r2, 1e-12 * sumH2K * r2); }
  }
  EXPECT_LT(etaStar[0], 1e-11 * etaStar[1]);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ElasticityBilinear,
                         ::testing::Values(BilinearCase{"squareUx", false, false, 0}, BilinearCase{"squareUy", false, false, 1},
                                           BilinearCase{"squareUxHanging", false, true, 0},
                                           BilinearCase{"squareUyHanging", false, true, 1},
                                           BilinearCase{"parallelogramUx", true, false, 0},
                                           BilinearCase{"parallelogramUy", true, false, 1},
                                           BilinearCase{"parallelogramUxHanging", true, true, 0},
                                           BilinearCase{"parallelogramUyHanging", true, true, 1}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ElasticityEstimator, EtaStarDecreasesLikeH) {
  // u = s (1, 1), s = sin(pi x) sin(pi y), clamped all round; predictor = u_h and f = -div sigma(u),
  // so that r = beta k^2 (div sigma(u_h) - div sigma(u)).
  std::vector<double> eta;
  for (int level = 3; level <= 5; ++level) {
    Case probe(1, false);
    probe.finish({});
    const double l = probe.lameLambda(), m = probe.lameMu();
    const std::string s = "sin(pi*x)*sin(pi*y)";
    const std::string f = "-pi^2*(" + num(l + m) + "*(cos(pi*x)*cos(pi*y) - " + s + ") - " + num(2 * m) + "*" + s + ")";
    Case c(level - 1, false);
    c.finish({{"Dirichlet Segments", "left, right, bottom, top"}, {"Body Force", f + ", " + f}});
    auto field = [](double x, double y) { return std::sin(M_PI * x) * std::sin(M_PI * y); };
    c.interpolate(field, field, *c.u);
    c.interpolate(field, field, *c.pred);
    eta.push_back(c.run().etaStar);
  }
  for (size_t i = 0; i + 1 < eta.size(); ++i) {
    const double rate = std::log2(eta[i] / eta[i + 1]);
    RecordProperty("rate_" + std::to_string(i), num(rate));
    EXPECT_GE(rate, 0.8) << eta[i] << " -> " << eta[i + 1];
    EXPECT_LE(rate, 1.3) << eta[i] << " -> " << eta[i + 1];
  }
}

TEST(ElasticityEstimator, ContactTermsMatchTheScalarEstimator) {
  // The constrained component penetrates a curved obstacle on the bottom; the other component
  // is arbitrary. s0 and s1 must be those of the scalar field sign * u_y (hand-checked there).
  // With rollers on the left (u_y = 0 only) the continuation of s1 is zero on the nodes where u_y is
  // fixed, top and left, as for the scalar problem clamped on both: the fixed nodes of the
  // constrained component, not those of u_x (which is free on the left).
  for (const bool rollers : {false, true})
    for (const char* direction : {"+y", "-y"}) {
      const double sign = direction[0] == '+' ? 1.0 : -1.0;
      Case s(2, true);
      std::map<std::string, std::string> entries{{"Contact Segments", "bottom"},
                                                 {"Contact Direction", direction},
                                                 {"Dirichlet Segments", "top"},
                                                 {"Obstacle", "0.05*sin(pi*x) - 0.01"}};
      if (rollers) entries["Dirichlet Y Segments"] = "left";
      s.finish(entries);
      auto w = [](double x, double y) { return 0.02 * x * (1 - y) - 0.005; };  // sign u_y
      s.interpolate([](double x, double y) { return x * y; }, [&](double x, double y) { return sign * w(x, y); }, *s.u);
      s.interpolate([](double, double) { return 0.0; }, [](double, double) { return 0.0; }, *s.pred);
      for (size_t j = 0; j < s.lambda.size(); ++j) s.lambda[j] = -0.1 * (1.0 + j);
      const auto r = s.run();
      // The scalar problem on the same mesh.
      auto p = fem::ProblemData::getValidParameters();
      p.set("Contact Segments", "bottom");
      p.set("Dirichlet Segments", rollers ? "top, left" : "top");
      p.set("Obstacle", "0.05*sin(pi*x) - 0.01");
      fem::ProblemData scalarProblem(p, *s.segments);
      fem::Q1Assembler scalar(*s.mesh, s.mesh->nodesOnSegments(scalarProblem.dirichletMask));
      fem::ContactCoupling coupling(*s.mesh, scalarProblem.contactMask, fem::ContactCoupling::SegmentSize::TwoEdges,
                                    scalar.dirichletFlags());
      Vector u(s.mesh->ownedMap()), pred(s.mesh->ownedMap());
      {
        auto h = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = w(s.mesh->nodeCoords()[i][0], s.mesh->nodeCoords()[i][1]);
      }
      auto params = estimate::ResidualEstimator::getValidParameters();
      params.set("Scaling", "step");
      const auto rs = estimate::ResidualEstimator(params).estimate(estimate::EstimatorInput{
          *s.forest, *s.mesh, scalar, scalarProblem, &coupling, s.time, s.k, s.beta, u, pred, s.lambda, solveCG});
      EXPECT_GT(rs.s0, 0.0);
      EXPECT_GT(rs.s1, 0.0);
      EXPECT_NEAR(r.s0, rs.s0, 1e-12 * rs.s0) << direction << (rollers ? ", rollers" : "");
      EXPECT_NEAR(r.s1, rs.s1, 1e-9 * rs.s1) << direction << (rollers ? ", rollers" : "");
    }
}

TEST(ElasticityEstimator, PhysicalScalingDoesNotDependOnTheUnitOfForce) {
  // As for the scalar estimator: E, rho, the body force, the traction and the multipliers in a unit
  // 1e6 times smaller give the same physical estimate (divided by beta k^2 (lambda + 2 mu)).
  auto estimateIn = [](double unit) {
    auto s = std::make_unique<Case>(2, true);
    s->forceUnit = unit;
    s->finish({{"Contact Segments", "bottom"},
               {"Contact Direction", "+y"},
               {"Dirichlet Segments", "top"},
               {"Neumann Segments", "right"},
               {"Obstacle", "0.05*sin(pi*x) - 0.01"},
               {"Body Force", num(unit) + " * 1, " + num(unit) + " * x"},
               {"Neumann Data", num(unit) + " * 0.3, " + num(unit) + " * (-0.2 * y)"}});
    s->interpolate([](double x, double y) { return 0.01 * x * y; }, [](double x, double y) { return 0.02 * x * (1 - y) - 0.005; },
                   *s->u);
    s->interpolate([](double, double y) { return 0.001 * y; }, [](double x, double) { return 0.002 * x; }, *s->pred);
    for (size_t j = 0; j < s->lambda.size(); ++j) s->lambda[j] = -0.1 * unit * (1.0 + j);
    return std::make_pair(s->run("physical"), s->run("step"));
  };
  const auto [pa, paStep] = estimateIn(1.0);
  const auto [mpa, mpaStep] = estimateIn(1e-6);
  test::expectSameEstimate(pa, mpa);
  EXPECT_NEAR(mpaStep.etaStar, 1e-6 * paStep.etaStar, 1e-12 * paStep.etaStar);  // control
  // The stiffness is lambda + 2 mu (the P-wave modulus), not E, mu or rho.
  Case s(2, true);
  s.finish({{"Contact Segments", "bottom"}, {"Dirichlet Segments", "top"}, {"Obstacle", "0.05*sin(pi*x) - 0.01"}});
  s.interpolate([](double x, double y) { return 0.01 * x * y; }, [](double x, double y) { return 0.02 * x * (1 - y) - 0.005; },
                *s.u);
  for (size_t j = 0; j < s.lambda.size(); ++j) s.lambda[j] = -0.1 * (1.0 + j);
  const auto step = s.run("step"), physical = s.run("physical");
  const double stiffness = s.bk2() * (s.lameLambda() + 2 * s.lameMu());
  EXPECT_GT(step.s0, 0.0);
  EXPECT_NEAR(physical.etaStar, step.etaStar / stiffness, 1e-12 * physical.etaStar);
  EXPECT_NEAR(physical.s0, step.s0 / std::sqrt(stiffness), 1e-12 * physical.s0);
  EXPECT_NEAR(physical.s1, step.s1, 1e-12 * step.s1);
}

TEST(ElasticityEstimator, S1LengthScaleWeighsTheL2PartOfItsNorm) {
  // s1^2 = |d|_1^2 + ||d||_0^2 / l^2 at the minimiser d: a larger l gives a smaller s1, and the
  // values follow from two of them (the minimiser changes with l, so only bounds hold: with
  // l = 1/2 the L2 part counts four times, so s1 lies between the l = 1 value and twice it).
  Case s(2, true);
  s.finish({{"Contact Segments", "bottom"}, {"Contact Direction", "+y"}, {"Dirichlet Segments", "top"},
            {"Obstacle", "0.05*sin(pi*x) + 0.01"}});
  const double one = s.run("step", 1.0).s1, half = s.run("step", 0.5).s1, two = s.run("step", 2.0).s1;
  ASSERT_GT(two, 0.0);
  EXPECT_GT(half, one);
  EXPECT_GT(one, two);
  EXPECT_LT(half, 2.0 * one);
}

TEST(ElasticityEstimator, AllRanksAgreeWithOneRank) {
  const auto world = Tpetra::getDefaultComm();
  const int rank = world->getRank();
  auto build = [](RCP<const Comm> comm) {
    auto c = std::make_unique<Case>(2, true, comm);
    c->finish({{"Contact Segments", "bottom"},
               {"Dirichlet Segments", "top"},
               {"Dirichlet X Segments", "left"},
               {"Neumann Segments", "right"},
               {"Neumann Data", "0.3*y, -0.1"},
               {"Body Force", "x, y*y"},
               {"Obstacle", "0.05*sin(pi*x) - 0.01"}});
    c->interpolate([](double x, double y) { return 0.01 * x * y; },
                   [](double x, double y) { return 0.02 * x * (1 - y) - 0.005 + 0.01 * y * y; }, *c->u);
    c->interpolate([](double x, double y) { return 0.012 * x * y; }, [](double x, double) { return 0.003 * x; },
                   *c->pred);
    for (size_t j = 0; j < c->lambda.size(); ++j) c->lambda[j] = -0.01 * (1.0 + j);
    return c;
  };
  auto s = build(world);
  const auto r = s->run();
  EXPECT_GT(r.etaStar, 0.0);
  EXPECT_GT(r.s0, 0.0);
  EXPECT_GT(r.s1, 0.0);
  const auto self = world->split(rank == 0 ? 0 : 1, rank);
  if (rank == 0) {
    auto serial = build(self);
    const auto rs = serial->run();
    EXPECT_NEAR(r.etaStar, rs.etaStar, 1e-12 * rs.etaStar);
    EXPECT_NEAR(r.s0, rs.s0, 1e-12 * rs.s0);
    EXPECT_NEAR(r.s1, rs.s1, 1e-9 * rs.s1);
  }
  Teuchos::barrier(*world);
}

}  // namespace
