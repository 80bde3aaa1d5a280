// Facts about the elasticity estimator (docs/estimator.md):
//  - it vanishes for a linear displacement (constant stress) with consistent tractions and
//    multipliers, also with hanging nodes, and a wrong traction is detected;
//  - on a roller side only the free component's traction counts;
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

#include "ContactCoupling.hpp"
#include "ElasticityEstimator.hpp"
#include "MpiComm.hpp"
#include "SameEstimate.hpp"
#include "SolveCG.hpp"

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

  Case(int level, bool hanging, RCP<const Comm> cm = Tpetra::getDefaultComm()) : comm(cm) {
    coarse = mesh::CoarseMesh::rectangle(0, 1, 0, 1, 2, 2);
    segments = std::make_unique<mesh::BoundarySegments>(
        std::vector<std::pair<std::string, std::string>>{
            {"left", "left"}, {"right", "right"}, {"bottom", "bottom"}, {"top", "top"}},
        *coarse);
    forest = std::make_unique<mesh::Forest>(coarse, core::rawMpiComm(*comm), level);
    if (hanging)
      for (int pass = 0; pass < 2; ++pass) {
        forest->refineIf([&](int tree, const p4est_quadrant_t& q) {
          const double root = P4EST_ROOT_LEN, half = 0.5 * P4EST_QUADRANT_LEN(q.level);
          const auto p = coarse->mapPoint(tree, (q.x + half) / root, (q.y + half) / root);
          return p[0] < 0.5 && p[1] < 0.5;
        });
        forest->balance();
      }
  }
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
  estimate::EstimatorResult run(const std::string& scaling = "step") const {
    auto params = estimate::ResidualEstimator::getValidParameters();
    params.set("Scaling", scaling);
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
  // u = (0, 0.5 y): sigma_xx = lambda 0.5 != 0 on the left, but u_x is fixed there (roller), so only
  // the shear traction (zero) counts; the other sides carry their tractions.
  auto fx = [](double, double) { return 0.0; };
  auto fy = [](double, double y) { return 0.5 * y; };
  Case probe(1, false);
  probe.finish({});
  const double sxx = probe.lameLambda() * 0.5, syy = (probe.lameLambda() + 2 * probe.lameMu()) * 0.5;
  Case s(2, true);
  s.finish({{"Dirichlet X Segments", "left"},
            {"Neumann Segments", "right, bottom, top"},
            {"Neumann Data", sideTractions(sxx, syy, 0.0)}});
  s.interpolate(fx, fy, *s.u);
  s.interpolate(fx, fy, *s.pred);
  EXPECT_LT(s.run().etaStar, 1e-11 * s.bk2() * syy);
  // Without the roller the left side's missing normal traction sigma_xx shows.
  Case w(2, true);
  w.finish({{"Neumann Segments", "right, bottom, top"}, {"Neumann Data", sideTractions(sxx, syy, 0.0)}});
  w.interpolate(fx, fy, *w.u);
  w.interpolate(fx, fy, *w.pred);
  EXPECT_GT(w.run().etaStar, 0.1 * w.bk2() * sxx);
}

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
  for (const char* direction : {"+y", "-y"}) {
    const double sign = direction[0] == '+' ? 1.0 : -1.0;
    Case s(2, true);
    s.finish({{"Contact Segments", "bottom"},
              {"Contact Direction", direction},
              {"Dirichlet Segments", "top"},
              {"Obstacle", "0.05*sin(pi*x) - 0.01"}});
    auto w = [](double x, double y) { return 0.02 * x * (1 - y) - 0.005; };  // sign u_y
    s.interpolate([](double x, double y) { return x * y; }, [&](double x, double y) { return sign * w(x, y); }, *s.u);
    s.interpolate([](double, double) { return 0.0; }, [](double, double) { return 0.0; }, *s.pred);
    for (size_t j = 0; j < s.lambda.size(); ++j) s.lambda[j] = -0.1 * (1.0 + j);
    const auto r = s.run();
    // The scalar problem on the same mesh.
    auto p = fem::ProblemData::getValidParameters();
    p.set("Contact Segments", "bottom");
    p.set("Dirichlet Segments", "top");
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
    EXPECT_NEAR(r.s0, rs.s0, 1e-12 * rs.s0) << direction;
    EXPECT_NEAR(r.s1, rs.s1, 1e-9 * rs.s1) << direction;
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
