// The membrane deck on 2 MPI ranks gives the same results as on 1 rank to solver tolerance.
// Both runs happen in this 2-rank test: once on all ranks, once on a communicator holding rank 0.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "signorini/io/CsvWriter.hpp"
#include "signorini/adapt/AdaptiveSimulation.hpp"
#include "signorini/dynamics/Simulation.hpp"

using namespace signorini;

namespace {

io::CsvTable runMembrane(RCP<const Comm> comm, const std::string& name, bool stabilised = false) {
  core::ParameterList deck;
  Teuchos::updateParametersFromXmlFile(std::string(SIGNORINI_SOURCE_DIR) + "/inputs/membrane-level2.xml",
                                       Teuchos::outArg(deck));
  // Up to t = 0.25: first contact at t ~ 0.05 and the growing contact zone. The impacting nodes
  // chatter (DESIGN 1.6) and differences at the level of the solver tolerance grow by about 10x
  // per 15 steps once in contact, so the tolerances are tightened here and the run is cut short;
  // over the whole deck the trajectories on different rank counts separate (README).
  if (stabilised) {
    // With the predictor projected onto the admissible set the nodes do not chatter and the whole
    // run agrees at the default tolerances.
    deck.sublist("Time Integration").set("Contact Stabilisation", "predictor projection");
  } else {
    deck.sublist("Time Integration").set("Final Time", 0.25);
    deck.sublist("Linear Solver").set("Relative Tolerance", 1e-14);
    deck.sublist("Contact").set("KKT Tolerance", 1e-14);
  }
  deck.sublist("Output").set("Write Exodus", false);
  deck.sublist("Output").set("Basename", name);
  deck.sublist("Output").set("Progress Interval", 1000000);
  core::validateDeck(deck, dynamics::Simulation::getValidParameters(), "membrane-level2.xml");
  const std::string dir = std::string(SIGNORINI_BINARY_DIR) + "/tests/output/agreement";
  dynamics::Simulation sim(deck, "membrane-level2.xml", dir, comm);
  sim.run();
  comm->barrier();
  return io::readCsv(dir + "/" + name + ".steps.csv");
}

class ParallelAgreement : public ::testing::TestWithParam<bool> {};  // contact stabilisation on/off

TEST_P(ParallelAgreement, MembraneOnTwoRanksMatchesOneRank) {
  auto world = Tpetra::getDefaultComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpirun -np 2";
  const bool stabilised = GetParam();
  const std::string tag = stabilised ? "stabilised" : "paper";
  const auto two = runMembrane(world, tag + "-np2", stabilised);
  auto self = world->split(world->getRank() == 0 ? 0 : 1, 0);
  if (world->getRank() == 0) {
    const auto one = runMembrane(self, tag + "-np1", stabilised);
    if (stabilised) { EXPECT_EQ(one.rows.size(), 401u); }  // the whole deck
    ASSERT_EQ(one.rows.size(), two.rows.size());
    int contactSteps = 0;
    for (size_t i = 0; i < one.rows.size(); ++i) {
      const auto& a = one.rows[i];
      const auto& b = two.rows[i];
      EXPECT_EQ(a[one.column("dofs")], b[two.column("dofs")]);
      EXPECT_EQ(a[one.column("active")], b[two.column("active")]) << "step " << i;
      EXPECT_NEAR(a[one.column("energy")], b[two.column("energy")], 1e-10);
      EXPECT_NEAR(a[one.column("probe:corner")], b[two.column("probe:corner")], 1e-10);
      // The contact force is lambda / (beta k^2): 3e5 times the QP multiplier.
      EXPECT_NEAR(a[one.column("contact_force")], b[two.column("contact_force")], 1e-6);
      contactSteps += a[one.column("active")] > 0;
    }
    EXPECT_GT(contactSteps, 50);
  }
  world->barrier();
}

INSTANTIATE_TEST_SUITE_P(Schemes, ParallelAgreement, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "stabilised" : "paper"); });

}  // namespace

namespace {

io::CsvTable runBar(RCP<const Comm> comm, const std::string& name) {
  core::ParameterList deck;
  Teuchos::updateParametersFromXmlFile(std::string(SIGNORINI_SOURCE_DIR) + "/inputs/bar.xml", Teuchos::outArg(deck));
  // The paper's bar on its initial mesh refined once (2210 unknowns), one pass up to t = 0.4 ms:
  // three impacts on the foundation.
  deck.sublist("Adaptivity").set("Strategy", "none");
  deck.sublist("Mesh").set("Refinement Level", 1);
  deck.sublist("Time Integration").set("Final Time", 4e-4);
  deck.sublist("Linear Solver").set("Relative Tolerance", 1e-13);
  deck.sublist("Contact").set("KKT Tolerance", 1e-13);
  deck.sublist("Output").set("Write Exodus", false);
  deck.sublist("Output").set("Basename", name);
  deck.sublist("Output").set("Progress Interval", 1000000);
  core::validateDeck(deck, adapt::AdaptiveSimulation::getValidParameters(), "bar.xml");
  const std::string dir = std::string(SIGNORINI_BINARY_DIR) + "/tests/output/agreement";
  adapt::AdaptiveSimulation sim(deck, "bar.xml", dir, comm);
  sim.run();
  comm->barrier();
  return io::readCsv(dir + "/" + name + ".steps.csv");
}

TEST(ParallelAgreement, BarOnTwoRanksMatchesOneRank) {
  auto world = Tpetra::getDefaultComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpirun -np 2";
  const auto two = runBar(world, "bar-np2");
  auto self = world->split(world->getRank() == 0 ? 0 : 1, 0);
  if (world->getRank() == 0) {
    const auto one = runBar(self, "bar-np1");
    ASSERT_EQ(one.rows.size(), two.rows.size());
    int contactSteps = 0, impacts = 0, releases = 0;
    double maxTip = 0;
    for (size_t i = 0; i < one.rows.size(); ++i) {
      const auto& a = one.rows[i];
      const auto& b = two.rows[i];
      EXPECT_EQ(a[one.column("dofs")], b[two.column("dofs")]);
      EXPECT_EQ(a[one.column("active")], b[two.column("active")]) << "step " << i;
      EXPECT_NEAR(a[one.column("energy")], b[two.column("energy")], 1e-8 * std::abs(a[one.column("energy")]) + 1e-6);
      for (const char* c : {"probe:tip:x", "probe:tip:y", "probe:foundation:y"})
        EXPECT_NEAR(a[one.column(c)], b[two.column(c)], 1e-12) << c << " step " << i;  // displacements ~ 5e-3 m
      EXPECT_NEAR(a[one.column("contact_force")], b[two.column("contact_force")],
                  1e-6 * std::abs(a[one.column("contact_force")]) + 1e-3)
          << "step " << i;
      contactSteps += a[one.column("active")] > 0;
      if (i > 0) {
        const bool was = one.rows[i - 1][one.column("active")] > 0, is = a[one.column("active")] > 0;
        impacts += !was && is;
        releases += was && !is;
      }
      maxTip = std::max(maxTip, std::abs(a[one.column("probe:tip:y")]));
    }
    // Preconditions, so that the agreement covers what it is meant to: contact is made and lost
    // again (the active set changes both ways, more than once), and the tip, where the foundation
    // ends, travels most of the 5 mm gap.
    EXPECT_GT(contactSteps, 3);
    EXPECT_GE(impacts, 2);
    EXPECT_GE(releases, 1);
    EXPECT_GT(maxTip, 4e-3);
  }
  world->barrier();
}

}  // namespace
