// End-to-end facts of the scalar dynamic Signorini problem (paper Example 6.1 and variants):
// second-order convergence without obstacle, the one-dimensional obstacle solution, and the KKT
// conditions at every step, recomputed from u_h (tests/dynamics/ParallelAgreementTest.cpp has the
// agreement between 1 and 2 MPI ranks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/io/CsvWriter.hpp"
#include "signorini/fem/Assembler.hpp"
#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/dynamics/ResultWriter.hpp"
#include "signorini/dynamics/Simulation.hpp"

using namespace signorini;

namespace {

std::string tempDir(const std::string& name) {
  return std::string(SIGNORINI_BINARY_DIR) + "/tests/output/" + name;
}

/// The membrane deck of paper Example 6.1 on a 4 x 4 coarse mesh refined to \p level.
core::ParameterList membraneDeck(int level, double k, double T, const std::string& obstacle) {
  core::ParameterList d;
  auto& p = d.sublist("Problem");
  p.set("Initial Velocity", "-sin(pi*x/2)");
  p.set("Obstacle", obstacle);
  p.set("Dirichlet Segments", "clamped");
  if (!obstacle.empty()) p.set("Contact Segments", "contact");
  auto& m = d.sublist("Mesh");
  m.set("Cells X", 4);
  m.set("Cells Y", 4);
  m.set("Refinement Level", level);
  m.sublist("Boundary Segments").set("clamped", "left");
  m.sublist("Boundary Segments").set("contact", "right");
  d.sublist("Time Integration").set("Time Step", k);
  d.sublist("Time Integration").set("Final Time", T);
  d.sublist("Output").set("Write Exodus", false);
  d.sublist("Output").set("Progress Interval", 1000000);
  return d;
}

/// Runs a deck on \p comm and returns its per-step table (on every rank).
io::CsvTable run(core::ParameterList deck, const std::string& name, RCP<const Comm> comm) {
  core::validateDeck(deck, dynamics::Simulation::getValidParameters(), name);
  const std::string dir = tempDir(name);
  deck.sublist("Output").set("Basename", name);
  dynamics::Simulation sim(deck, name + ".xml", dir, comm);
  sim.run();
  comm->barrier();
  return io::readCsv(dir + "/" + name + ".steps.csv");
}

double columnMax(const io::CsvTable& t, const std::string& c) {
  double m = 0;
  for (const auto& r : t.rows) m = std::max(m, std::abs(r[t.column(c)]));
  return m;
}

TEST(Membrane, NoObstacleConvergesAtSecondOrderInL2AndFirstInH1) {
  // h and k halved together; the exact solution is -(2/pi) sin(pi t/2) sin(pi x/2).
  std::vector<double> l2, h1;
  for (int level = 1; level <= 4; ++level) {
    auto deck = membraneDeck(level, 0.08 / (1 << level), 1.0, "");
    deck.sublist("Problem").set("Exact Solution", "-(2/pi)*sin(pi*t/2)*sin(pi*x/2)");
    const auto t = run(deck, "free" + std::to_string(level), Tpetra::getDefaultComm());
    l2.push_back(columnMax(t, "error_l2"));
    h1.push_back(columnMax(t, "error_h1"));
    // Newmark with alpha = 1/2 conserves kinetic + strain + (beta - 1/4) k^2/2 a^T M a without
    // contact; the mechanical energy itself oscillates by O(k^2).
    const double e0 = t.rows.front()[t.column("newmark_energy")];
    double drift = 0;
    for (const auto& r : t.rows) {
      EXPECT_NEAR(r[t.column("newmark_energy")], e0, 1e-8 * e0);
      drift = std::max(drift, std::abs(r[t.column("energy")] - e0));
    }
    EXPECT_LT(drift, 0.5 * std::pow(0.08 / (1 << level), 2));
  }
  for (size_t i = 1; i < l2.size(); ++i) {
    const double rateL2 = std::log2(l2[i - 1] / l2[i]), rateH1 = std::log2(h1[i - 1] / h1[i]);
    RecordProperty("rate_l2_" + std::to_string(i), std::to_string(rateL2));
    RecordProperty("rate_h1_" + std::to_string(i), std::to_string(rateH1));
    EXPECT_GT(rateL2, 1.85) << "level " << i;
    EXPECT_LT(rateL2, 2.15) << "level " << i;
    EXPECT_GT(rateH1, 0.9) << "level " << i;
    EXPECT_LT(rateH1, 1.1) << "level " << i;
  }
}

/// The one-dimensional solution with the flat obstacle u(1, t) >= g (derivation in
/// docs/one-dimensional-obstacle.md): u = P(t + x) - cos(pi (t - x)/2)/pi, valid for t <= 1, where
/// P(s) = cos(pi s/2)/pi before the reflection of first contact (s <= 1 + t1) and
/// -cos(pi s/2)/pi + g after it; first contact at t1 = (2/pi) asin(-pi g/2).
std::string oneDimensionalSolution(double g) {
  const double t1 = 2.0 / M_PI * std::asin(-M_PI * g / 2.0);
  std::ostringstream s;
  s.precision(17);
  s << "(t + x <= " << 1.0 + t1 << " ? cos(pi*(t+x)/2)/pi : -cos(pi*(t+x)/2)/pi + (" << g
    << ")) - cos(pi*(t-x)/2)/pi";
  return s.str();
}

TEST(Membrane, DensityAndStiffnessScaledTogetherGiveTheSameSolution) {
  // rho u_tt = kappa u_xx depends on kappa / rho only: rho = kappa = 4 must reproduce rho = kappa = 1
  // (initial projections and the contact force scale with rho).
  std::vector<io::CsvTable> runs;
  for (double scale : {1.0, 4.0}) {
    auto deck = membraneDeck(2, 0.01, 0.3, "sin(pi*y) - 1.05");
    deck.sublist("Problem").set("Density", scale);
    deck.sublist("Problem").set("Stiffness", scale);
    deck.sublist("Output").sublist("Probes").set("corner", "1.0, 0.5");
    runs.push_back(run(deck, "scaled" + std::to_string(static_cast<int>(scale)), Tpetra::getDefaultComm()));
  }
  const auto& a = runs[0];
  const auto& b = runs[1];
  ASSERT_EQ(a.rows.size(), b.rows.size());
  double maxProbe = 0;
  for (size_t n = 0; n < a.rows.size(); ++n) {
    EXPECT_NEAR(a.rows[n][a.column("probe:corner")], b.rows[n][b.column("probe:corner")], 1e-8) << "step " << n;
    EXPECT_NEAR(4 * a.rows[n][a.column("energy")], b.rows[n][b.column("energy")], 1e-8) << "step " << n;
    EXPECT_NEAR(4 * a.rows[n][a.column("contact_force")], b.rows[n][b.column("contact_force")],
                1e-6 * std::max(1.0, std::abs(b.rows[n][b.column("contact_force")])))
        << "step " << n;
    maxProbe = std::max(maxProbe, std::abs(a.rows[n][a.column("probe:corner")]));
  }
  EXPECT_GT(maxProbe, 0.05);  // the membrane moves
  EXPECT_GT(columnMax(a, "contact_force"), 0.0);  // and touches the obstacle
}

TEST(Membrane, FlatObstacleGivesTheOneDimensionalSolution) {
  // Courant number k/h = 1: the step matrix M + k^2/2 K has no positive off-diagonal entries, so
  // the contact node does not chatter (with k/h well below 1 it does; DESIGN 1.6).
  const double g = -0.5;
  std::vector<double> l2;
  for (int level = 2; level <= 4; ++level) {
    auto deck = membraneDeck(level, 0.25 / (1 << level), 1.0, std::to_string(g));
    deck.sublist("Problem").set("Exact Solution", oneDimensionalSolution(g));
    auto& probes = deck.sublist("Output").sublist("Probes");
    for (double y : {0.1, 0.5, 0.9}) {
      probes.set("right" + std::to_string(y), "1.0, " + std::to_string(y));
      probes.set("mid" + std::to_string(y), "0.5, " + std::to_string(y));
    }
    const auto t = run(deck, "flat" + std::to_string(level), Tpetra::getDefaultComm());
    // Independent of y to solver tolerance, at every step.
    for (const auto& r : t.rows)
      for (const char* where : {"right", "mid"}) {
        const double a = r[t.column(std::string("probe:") + where + std::to_string(0.1))];
        const double b = r[t.column(std::string("probe:") + where + std::to_string(0.5))];
        const double c = r[t.column(std::string("probe:") + where + std::to_string(0.9))];
        EXPECT_NEAR(a, b, 1e-8);
        EXPECT_NEAR(c, b, 1e-8);
      }
    // The end never penetrates the obstacle (weighted gap >= 0 is exact for y-independent u).
    for (const auto& r : t.rows) EXPECT_GE(r[t.column("probe:right" + std::to_string(0.5))], g - 1e-8);
    l2.push_back(columnMax(t, "error_l2"));
  }
  for (size_t i = 1; i < l2.size(); ++i) {
    const double rate = std::log2(l2[i - 1] / l2[i]);
    RecordProperty("rate_l2_" + std::to_string(i), std::to_string(rate));
    EXPECT_GT(rate, 0.9) << "level " << i;  // the solution has a kink: second order is not expected
  }
  EXPECT_LT(l2.back(), 0.01);
}

TEST(Membrane, StabilisedSchemeKeepsContactAndDoesNotGainEnergy) {
  // Paper's Newmark with the predictor projected onto the admissible set (Time Integration/Contact
  // Stabilisation): on the flat obstacle the end stays on the obstacle after first contact (the
  // 1D solution does), the energy never exceeds its initial value (impacts may only dissipate),
  // and the solution converges to the 1D solution.
  const double g = -0.5, t1 = 2.0 / M_PI * std::asin(-M_PI * g / 2.0);
  std::vector<double> l2;
  for (int level = 2; level <= 4; ++level) {
    auto deck = membraneDeck(level, 0.04 / (1 << level), 1.0, std::to_string(g));
    deck.sublist("Problem").set("Exact Solution", oneDimensionalSolution(g));
    deck.sublist("Time Integration").set("Contact Stabilisation", "predictor projection");
    deck.sublist("Output").sublist("Probes").set("end", "1.0, 0.5");
    const auto t = run(deck, "stabilised" + std::to_string(level), Tpetra::getDefaultComm());
    const double e0 = t.rows.front()[t.column("energy")];
    for (const auto& r : t.rows) {
      EXPECT_LE(r[t.column("energy")], e0 * (1 + 1e-9));
      if (r[t.column("t")] > t1 + 0.1) { EXPECT_NEAR(r[t.column("probe:end")], g, 1e-4); }
    }
    l2.push_back(columnMax(t, "error_l2"));
  }
  for (size_t i = 1; i < l2.size(); ++i) {
    const double rate = std::log2(l2[i - 1] / l2[i]);
    RecordProperty("rate_l2_" + std::to_string(i), std::to_string(rate));
    EXPECT_GT(rate, 0.9) << "level " << i;
  }
}

TEST(Membrane, KKTConditionsHoldAtEveryStep) {
  // Paper Example 6.1 data (obstacle sin(pi y) - 1.05) on 32 x 32 cells, all 400 steps. The mean
  // gap of every segment is recomputed here from u_h and the obstacle (the trapezoidal rule, exact
  // for u_h along an edge, and the exact integral of the obstacle), not taken from the solver.
  auto deck = membraneDeck(3, 0.0025, 1.0, "sin(pi*y) - 1.05");
  const std::string name = "kkt";
  core::validateDeck(deck, dynamics::Simulation::getValidParameters(), name);
  deck.sublist("Output").set("Basename", name);
  const auto comm = Tpetra::getDefaultComm();
  dynamics::Simulation sim(deck, name + ".xml", tempDir(name), comm);
  const double tol = 1e-9 * std::sqrt(2.0);  // Contact/KKT Tolerance times the domain diameter
  int steps = 0, contactSteps = 0, firstContact = -1;
  double lowestGap = 1e300, largestComplementarity = 0, largestActiveGap = 0, largestLambda = -1e300;
  const dynamics::StepHook hook = [&](const dynamics::StepView& s) {
    ++steps;
    Vector uOverlap(s.mesh.overlapMap());
    s.assembler.toOverlap(s.u, uOverlap);
    const auto u = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    const int m = s.coupling->numSegments();
    std::vector<double> local(2 * m, 0.0), sums(2 * m);  // per segment: int (u - g) ds, length
    for (size_t i = 0; i < s.mesh.boundaryEdges().size(); ++i) {
      const int j = s.coupling->localEdgeSegment()[i];
      if (j < 0) continue;
      const auto& e = s.mesh.boundaryEdges()[i];
      const double y0 = std::min(e.x[0][1], e.x[1][1]), y1 = std::max(e.x[0][1], e.x[1][1]);
      EXPECT_EQ(e.x[0][0], 1.0);  // on Gamma_C, x = 1
      const double uMean = 0.5 * (u(e.node[0], 0) + u(e.node[1], 0));
      const double obstacle = (std::cos(M_PI * y0) - std::cos(M_PI * y1)) / M_PI - 1.05 * (y1 - y0);
      local[2 * j] += uMean * (y1 - y0) - obstacle;
      local[2 * j + 1] += y1 - y0;
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2 * m, local.data(), sums.data());
    const double toPhysical = 1.0 / (s.beta * s.timeStep * s.timeStep);
    bool contact = false;
    for (int j = 0; j < m; ++j) {
      const double gap = sums[2 * j] / sums[2 * j + 1], lambda = toPhysical * s.lambda[j];
      lowestGap = std::min(lowestGap, gap);
      largestLambda = std::max(largestLambda, lambda);
      largestComplementarity = std::max(largestComplementarity, std::abs(lambda * gap));
      if (lambda < 0) largestActiveGap = std::max(largestActiveGap, std::abs(gap)), contact = true;
    }
    contactSteps += contact;
    if (contact && firstContact < 0) firstContact = s.step;
    return dynamics::StepExtras{};
  };
  dynamics::PassOptions options;
  options.writeExodus = false;
  const auto lock = sim.createOutputDirectory();  // (run() does this itself; runPass() writes into it)
  sim.runPass(std::vector<std::shared_ptr<mesh::Forest>>(sim.numSteps(), sim.initialForest()), hook, options);
  EXPECT_EQ(steps, 400);
  EXPECT_GE(lowestGap, -tol);           // no segment penetrates the obstacle (in the mean)
  EXPECT_LE(largestLambda, 0.0);        // the multiplier pushes, never pulls
  EXPECT_LE(largestActiveGap, tol);     // a pushing segment touches
  EXPECT_LE(largestComplementarity, 1e-6);
  EXPECT_GT(contactSteps, 0);
  // Before the first contact u = -(2/pi) sin(pi t/2) sin(pi x/2), so the mean gap of the segments
  // beside y = 1/2 (length 1/16) is 0.05641 - (2/pi) sin(pi t/2): it closes at t = 0.05646, so
  // the first step in contact is step 23 (t = 0.0575; README: uniform h = 1/32).
  EXPECT_EQ(firstContact, 23);
  // Step 0 (no QP) reports the initial state's gap in the step table: u = 0 against
  // sin(pi y) - 1.05, smallest on those segments: 1.05 - (16/pi) cos(7 pi/16).
  comm->barrier();
  const auto t = io::readCsv(tempDir(name) + "/" + name + ".steps.csv");
  ASSERT_EQ(t.rows.size(), 401u);
  EXPECT_NEAR(t.rows.front()[t.column("min_gap")], 1.05 - 16 / M_PI * std::cos(7 * M_PI / 16), 1e-9);
}

}  // namespace

// The segments' side sets are named as ParaView's default (IOSS) reader shows names, lower case with
// '_' for blanks, and never twice or as the element block "domain" or the set "contact" (the IOSS
// reader refuses a file with two sets of one name; a review's "Contact" made the file unreadable).
TEST(SegmentSideSetNames, AreUniqueAsParaViewShowsThem) {
  using signorini::dynamics::segmentSideSetNames;
  EXPECT_EQ(segmentSideSetNames({"clamped", "Left Support", "load"}, 0),
            (std::vector<std::string>{"clamped", "left_support", "load"}));
  // A segment named "contact" (in any case) that is all of Gamma_C is the set "contact" itself.
  EXPECT_EQ(segmentSideSetNames({"clamped", "Contact"}, 1u << 1), (std::vector<std::string>{"clamped", ""}));
  // Only part of Gamma_C, or no contact at all: a name of its own.
  EXPECT_EQ(segmentSideSetNames({"contact", "upper"}, 3u), (std::vector<std::string>{"contact_2", "upper"}));
  EXPECT_EQ(segmentSideSetNames({"contact"}, 0), (std::vector<std::string>{"contact_2"}));
  EXPECT_EQ(segmentSideSetNames({"domain", "Domain", "domain_2"}, 0),
            (std::vector<std::string>{"domain_2", "domain_3", "domain_2_2"}));
  EXPECT_EQ(segmentSideSetNames({"a b", "A_B"}, 0), (std::vector<std::string>{"a_b", "a_b_2"}));
}
