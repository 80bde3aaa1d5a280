// The adaptive membrane (paper Algorithm 5.1) on 2 ranks produces the same meshes (unknowns per
// step, total unknowns per cycle) and the same estimates per step as on 1 rank.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "AdaptiveSimulation.hpp"
#include "CsvWriter.hpp"

using namespace signorini;

namespace {

struct Result {
  io::CsvTable cycles, steps;
};

Result runAdaptive(RCP<const Comm> comm, const std::string& name) {
  core::ParameterList deck;
  Teuchos::updateParametersFromXmlFile(std::string(SIGNORINI_SOURCE_DIR) + "/inputs/membrane.xml",
                                       Teuchos::outArg(deck));
  // Past first contact (t ~ 0.05), three cycles.
  deck.sublist("Time Integration").set("Final Time", 0.1);
  deck.sublist("Adaptivity").set("Cycles", 3);
  deck.sublist("Output").set("Write Exodus", false);
  deck.sublist("Output").set("Basename", name);
  deck.sublist("Output").set("Progress Interval", 1000000);
  core::validateDeck(deck, adapt::AdaptiveSimulation::getValidParameters(), "membrane.xml");
  const std::string dir = std::string(SIGNORINI_BINARY_DIR) + "/tests/output/adaptive-agreement";
  adapt::AdaptiveSimulation sim(deck, "membrane.xml", dir, comm);
  sim.run();
  comm->barrier();
  return {io::readCsv(dir + "/" + name + ".cycles.csv"), io::readCsv(dir + "/" + name + ".steps.csv")};
}

TEST(AdaptiveAgreement, TwoRanksGiveTheSameMeshesAndEstimatesAsOne) {
  auto world = Tpetra::getDefaultComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpirun -np 2";
  const auto two = runAdaptive(world, "np2");
  auto self = world->split(world->getRank() == 0 ? 0 : 1, 0);
  if (world->getRank() == 0) {
    const auto one = runAdaptive(self, "np1");
    ASSERT_EQ(one.cycles.rows.size(), 3u);
    ASSERT_EQ(two.cycles.rows.size(), 3u);
    for (size_t l = 0; l < 3; ++l) {
      EXPECT_EQ(one.cycles.rows[l][one.cycles.column("total_dofs")], two.cycles.rows[l][two.cycles.column("total_dofs")]);
      EXPECT_EQ(one.cycles.rows[l][one.cycles.column("total_cells")], two.cycles.rows[l][two.cycles.column("total_cells")]);
      const double e1 = one.cycles.rows[l][one.cycles.column("eta")], e2 = two.cycles.rows[l][two.cycles.column("eta")];
      EXPECT_NEAR(e1, e2, 1e-8 * e1);
    }
    // Adaptivity refines: more unknowns and a smaller estimate from cycle to cycle.
    EXPECT_GT(one.cycles.rows[2][one.cycles.column("total_dofs")], one.cycles.rows[0][one.cycles.column("total_dofs")]);
    EXPECT_LT(one.cycles.rows[2][one.cycles.column("eta")], one.cycles.rows[0][one.cycles.column("eta")]);
    ASSERT_EQ(one.steps.rows.size(), two.steps.rows.size());
    for (size_t n = 0; n < one.steps.rows.size(); ++n) {
      EXPECT_EQ(one.steps.rows[n][one.steps.column("dofs")], two.steps.rows[n][two.steps.column("dofs")]) << n;
      const double e1 = one.steps.rows[n][one.steps.column("eta")], e2 = two.steps.rows[n][two.steps.column("eta")];
      EXPECT_NEAR(e1, e2, 1e-8 * std::max(e1, 1e-300)) << n;
    }
  }
  world->barrier();
}

}  // namespace
