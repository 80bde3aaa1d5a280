// End-to-end facts of plane strain elastodynamics with vector Q1 elements: a manufactured
// solution converges at second order in L2 and first in H1 (h and k halved together), and a
// strip in uniaxial strain hitting a flat obstacle follows the closed-form one-dimensional wave
// solution with speed sqrt((lambda + 2 mu) / rho), in each of the four contact directions.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <Tpetra_Core.hpp>

#include "signorini/io/CsvWriter.hpp"
#include "signorini/dynamics/Simulation.hpp"

using namespace signorini;

namespace {

std::string tempDir(const std::string& name) { return std::string(SIGNORINI_BINARY_DIR) + "/tests/output/" + name; }

io::CsvTable run(core::ParameterList deck, const std::string& name) {
  core::validateDeck(deck, dynamics::Simulation::getValidParameters(), name);
  const std::string dir = tempDir(name);
  deck.sublist("Output").set("Basename", name);
  deck.sublist("Output").set("Write Exodus", false);
  deck.sublist("Output").set("Progress Interval", 1000000);
  auto comm = Tpetra::getDefaultComm();
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

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

TEST(Elasticity, ManufacturedSolutionConvergesAtSecondOrderInL2AndFirstInH1) {
  // u = sin(t) sin(pi x) sin(pi y) (1, 1) on the unit square, clamped all round; the body force is
  // f = rho u_tt - div sigma(u) = rho u_tt - (lambda + mu) grad div u - mu Laplace u.
  const double E = 1.0, nu = 0.3, rho = 1.0;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const std::string s = "sin(pi*x)*sin(pi*y)";
  const std::string f = "-" + number(rho) + "*sin(t)*" + s + " - sin(t)*pi^2*(" + number(lambda + mu) +
                        "*(cos(pi*x)*cos(pi*y) - " + s + ") - " + number(2 * mu) + "*" + s + ")";
  std::vector<double> l2, h1;
  for (int level = 1; level <= 4; ++level) {
    core::ParameterList deck;
    auto& p = deck.sublist("Problem");
    p.set("Type", "plane strain elasticity");
    p.set("Density", rho);
    p.set("Young's Modulus", E);
    p.set("Poisson's Ratio", nu);
    p.set("Body Force", f + ", " + f);
    p.set("Initial Velocity", s + ", " + s);
    p.set("Exact Solution", "sin(t)*" + s + ", sin(t)*" + s);
    p.set("Dirichlet Segments", "left, right, bottom, top");
    auto& m = deck.sublist("Mesh");
    m.set("Cells X", 4);
    m.set("Cells Y", 4);
    m.set("Refinement Level", level);
    for (const char* side : {"left", "right", "bottom", "top"}) m.sublist("Boundary Segments").set(side, side);
    deck.sublist("Time Integration").set("Time Step", 0.08 / (1 << level));
    deck.sublist("Time Integration").set("Final Time", 1.0);
    const auto t = run(deck, "elastic" + std::to_string(level));
    l2.push_back(columnMax(t, "error_l2"));
    h1.push_back(columnMax(t, "error_h1"));
  }
  for (size_t i = 1; i < l2.size(); ++i) {
    const double rateL2 = std::log2(l2[i - 1] / l2[i]), rateH1 = std::log2(h1[i - 1] / h1[i]);
    RecordProperty("rate_l2_" + std::to_string(i), number(rateL2));
    RecordProperty("rate_h1_" + std::to_string(i), number(rateH1));
    EXPECT_GT(rateL2, 1.85) << "level " << i;
    EXPECT_LT(rateL2, 2.15) << "level " << i;
    EXPECT_GT(rateH1, 0.9) << "level " << i;
    EXPECT_LT(rateH1, 1.1) << "level " << i;
  }
}

/// The membrane's one-dimensional solution U(X, T) with the flat obstacle U(1, T) >= G
/// (docs/one-dimensional-obstacle.md), for expressions X and T, valid for T <= 1.
std::string oneDimensional(const std::string& X, const std::string& T, double G) {
  const double t1 = 2.0 / M_PI * std::asin(-M_PI * G / 2.0);
  return "((" + T + ") + (" + X + ") <= " + number(1.0 + t1) + " ? cos(pi*((" + T + ")+(" + X + "))/2)/pi : -cos(pi*((" +
         T + ")+(" + X + "))/2)/pi + (" + number(G) + ")) - cos(pi*((" + T + ")-(" + X + "))/2)/pi";
}

/// The strip in uniaxial strain of the tests below, falling onto a flat obstacle; c = 2 and the
/// obstacle g = -0.25, as U(X, T) of oneDimensional() needs (the deck's material from c and nu).
struct Strip {
  static constexpr double nu = 0.3, rho = 1.0, c = 2.0, g = -0.25;
  const char* direction;        // Contact Direction
  const char* contact;          // the side the obstacle is on
  const char* clamped;          // the opposite side
  const char* rollers;          // the two other sides ...
  const char* rollerKey;        // ... on rollers: Dirichlet X or Y Segments
  double x1, y1;                // the strip [0, x1] x [0, y1]
  int cellsX, cellsY;           // coarse cells
  const char* velocity;         // toward the obstacle
  const char* distance;         // from the clamped side, as an expression
  const char* exactForm;        // the exact solution, U standing for U(distance, c t) / c

  core::ParameterList deck(int level) const {
    const double E = c * c * rho * (1 + nu) * (1 - 2 * nu) / (1 - nu);  // lambda + 2 mu = c^2 rho
    std::string exact = exactForm;
    exact.replace(exact.find('U'), 1, "(" + oneDimensional(distance, "2*t", c * g) + ")/2");
    core::ParameterList d;
    auto& p = d.sublist("Problem");
    p.set("Type", "plane strain elasticity");
    p.set("Density", rho);
    p.set("Young's Modulus", E);
    p.set("Poisson's Ratio", nu);
    p.set("Initial Velocity", velocity);
    p.set("Obstacle", number(g));
    p.set("Contact Direction", direction);
    p.set("Contact Segments", contact);
    p.set("Dirichlet Segments", clamped);
    p.set(rollerKey, rollers);
    p.set("Exact Solution", exact);
    auto& m = d.sublist("Mesh");
    m.set("X1", x1);
    m.set("Y1", y1);
    m.set("Cells X", cellsX);
    m.set("Cells Y", cellsY);
    m.set("Refinement Level", level);
    for (const char* side : {"left", "right", "bottom", "top"}) m.sublist("Boundary Segments").set(side, side);
    // c k / h = 1, as for the membrane's flat obstacle (no chattering of the contact nodes).
    d.sublist("Time Integration").set("Time Step", 0.125 / (1 << level));
    d.sublist("Time Integration").set("Final Time", 0.5);
    return d;
  }
};

// The strip [0, 0.25] x [0, 1] and its turns: the obstacle below, above, left and right of it.
const Strip kStrips[] = {
    {"+y", "bottom", "top", "left, right", "Dirichlet X Segments", 0.25, 1.0, 1, 4, "0, -sin(pi*(1-y)/2)", "1-y", "0, U"},
    {"-y", "top", "bottom", "left, right", "Dirichlet X Segments", 0.25, 1.0, 1, 4, "0, sin(pi*y/2)", "y", "0, -U"},
    {"+x", "left", "right", "bottom, top", "Dirichlet Y Segments", 1.0, 0.25, 4, 1, "-sin(pi*(1-x)/2), 0", "1-x", "U, 0"},
    {"-x", "right", "left", "bottom, top", "Dirichlet Y Segments", 1.0, 0.25, 4, 1, "sin(pi*x/2), 0", "x", "-U, 0"}};

TEST(Elasticity, UniaxialStrainFollowsTheOneDimensionalWaveSolution) {
  // A strip [0, 0.25] x [0, 1] clamped at the top, on rollers at both sides (u_x = 0), falling with
  // v = -sin(pi (1 - y)/2) onto the obstacle u_y >= g at the bottom: u_x = 0 and u_y(y, t) =
  // U(1 - y, c t) / c with c = sqrt((lambda + 2 mu) / rho) = 2 and U the membrane's solution for
  // the obstacle c g (derivation in docs/uniaxial-strain.md). Valid for c t <= 1.
  const Strip& strip = kStrips[0];
  std::vector<double> l2;
  for (int level = 2; level <= 4; ++level) {
    auto deck = strip.deck(level);
    auto& probes = deck.sublist("Output").sublist("Probes");
    probes.set("bottomLeft", "0.02, 0.0");
    probes.set("bottomRight", "0.23, 0.0");
    probes.set("midLeft", "0.02, 0.5");
    probes.set("midRight", "0.23, 0.5");
    const auto t = run(deck, "uniaxial" + std::to_string(level));
    for (const auto& r : t.rows) {
      for (const char* where : {"bottom", "mid"}) {  // independent of x, no sideways motion
        const std::string a = std::string("probe:") + where + "Left", b = std::string("probe:") + where + "Right";
        EXPECT_NEAR(r[t.column(a + ":y")], r[t.column(b + ":y")], 1e-8);
        EXPECT_NEAR(r[t.column(a + ":x")], 0.0, 1e-12);
      }
      EXPECT_GE(r[t.column("probe:bottomLeft:y")], Strip::g - 1e-8);  // never below the obstacle
    }
    EXPECT_GT(columnMax(t, "contact_force"), 0.0);
    l2.push_back(columnMax(t, "error_l2"));
  }
  for (size_t i = 1; i < l2.size(); ++i) {
    const double rate = std::log2(l2[i - 1] / l2[i]);
    RecordProperty("rate_l2_" + std::to_string(i), number(rate));
    EXPECT_GT(rate, 0.9) << "level " << i;  // the solution has a kink, as for the membrane
  }
  EXPECT_LT(l2.back(), 0.01 * 0.25);  // the L2 norm scales by sqrt(width) / c = 0.25 against the membrane
}

// The strip turned so that the obstacle lies below, above, left and right of it (Contact
// Direction +y, -y, +x, -x). The meshes are reflections and rotations of each other, so every step
// must give the same contact force, energy and active set as the original, up to rounding, and the
// same error against the exact solution turned alike (which checks that each falls the right way).
TEST(Elasticity, TheStripGivesTheSameContactInEveryDirection) {
  std::vector<io::CsvTable> tables;
  for (const Strip& strip : kStrips)
    tables.push_back(run(strip.deck(3), std::string("strip") + (strip.direction[0] == '+' ? "plus" : "minus") + strip.direction[1]));
  const auto& reference = tables[0];
  EXPECT_GT(columnMax(reference, "contact_force"), 0.0);  // the strip hits the obstacle
  EXPECT_LT(columnMax(reference, "error_l2"), 0.01);      // and follows the exact solution (as above)
  for (size_t i = 1; i < tables.size(); ++i) {
    const auto& t = tables[i];
    ASSERT_EQ(t.rows.size(), reference.rows.size());
    for (size_t n = 0; n < t.rows.size(); ++n) {
      for (const char* column : {"contact_force", "error_l2", "energy"}) {
        const double a = reference.rows[n][reference.column(column)], b = t.rows[n][t.column(column)];
        EXPECT_NEAR(b, a, 1e-9 * std::abs(a) + 1e-12) << kStrips[i].direction << ", " << column << ", step " << n;
      }
      EXPECT_EQ(t.rows[n][t.column("active")], reference.rows[n][reference.column("active")])
          << kStrips[i].direction << ", step " << n;
    }
  }
}

}  // namespace
