// Refinement, balance (Algorithm 5.2) and temporal regularisation (Algorithm 5.3) on forests.
#include <gtest/gtest.h>

#include <cmath>

#include <p4est_bits.h>
#include <p4est_lnodes.h>

#include "../TestMesh.hpp"
#include "ForestOverlap.hpp"
#include "TemporalRegularisation.hpp"

using namespace signorini;

namespace {

using test::refineAt;

TEST(Balance, LeavesAtMostOneHangingNodePerEdge) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 1, 1, 1);
  refineAt(*tm.forest, 0.3, 0.3, 6);  // a deep local refinement: multiple hanging nodes before balancing
  tm.forest->balance();
  tm.forest->partition();
  // p4est lnodes (degree 1) accepts only 2:1 balanced forests and encodes one hanging node per
  // face; building the Q1 numbering checks the hanging-corner structure.
  const auto& m = tm.build();
  int hangingCorners = 0;
  for (LO e = 0; e < m.numLocalCells(); ++e)
    for (int c = 0; c < 4; ++c) hangingCorners += m.cornerDofsHost(e, c, 1) >= 0;
  int global = 0;
  MPI_Allreduce(&hangingCorners, &global, 1, MPI_INT, MPI_SUM, tm.forest->comm());
  EXPECT_GT(global, 0);
  // 2:1 balanced: balancing again changes nothing.
  mesh::Forest copy(*tm.forest);
  copy.balance();
  EXPECT_TRUE(copy.sameCells(*tm.forest));
}

TEST(TemporalRegularisation, NoCellIsMoreThanOneLevelCoarserThanItsNeighbourSteps) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  std::vector<std::unique_ptr<mesh::Forest>> steps;
  for (int n = 0; n < 4; ++n) steps.push_back(std::make_unique<mesh::Forest>(*a.forest));
  // Step 1 is refined deeply near a point, step 3 near another: steps 0, 2 are coarse there.
  refineAt(*steps[1], 0.2, 0.7, 4);
  refineAt(*steps[3], 0.8, 0.1, 3);
  for (auto& f : steps) {
    f->balance();
    f->partition();
  }
  EXPECT_GE(mesh::maxLevelExcess(*steps[1], *steps[2]), 2);
  std::vector<mesh::Forest*> seq;
  for (auto& f : steps) seq.push_back(f.get());
  mesh::regulariseSequence(seq);
  for (size_t n = 0; n + 1 < steps.size(); ++n) {
    EXPECT_LE(mesh::maxLevelExcess(*steps[n], *steps[n + 1]), 1) << "forward " << n;
    EXPECT_LE(mesh::maxLevelExcess(*steps[n + 1], *steps[n]), 1) << "backward " << n;
  }
  // Regularising refines only: every step still contains its own refinement.
  EXPECT_GE(steps[1]->numGlobalCells(), a.forest->numGlobalCells());
}

// The one-rank merge that Algorithm 5.3 uses gives, cell by cell, the finest overlapping level
// that ForestOverlap's common refinement gives, on forests of four trees refined differently
// (either one may be the finer one in any place).
TEST(TemporalRegularisation, LevelExcessByMergeEqualsTheOverlap) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  if (a.forest->p4est()->mpisize != 1) GTEST_SKIP() << "the merge is the one-rank path";
  auto scrambled = [](unsigned seed) {
    return [seed](int tree, const p4est_quadrant_t& q) {
      unsigned h = seed * 2654435761u ^ static_cast<unsigned>(tree * 97 + q.level * 31);
      h ^= static_cast<unsigned>(q.x) * 40503u + static_cast<unsigned>(q.y) * 2246822519u;
      h ^= h >> 13;
      h *= 0x5bd1e995u;
      h ^= h >> 15;
      return q.level < 7 && h % 3 == 0;
    };
  };
  mesh::Forest f(*a.forest), g(*a.forest);
  for (int round = 0; round < 5; ++round) {
    f.refineIf(scrambled(11 + round));
    g.refineIf(scrambled(29 + round));
  }
  ASSERT_FALSE(f.sameCells(g));
  for (auto [from, to] : {std::pair{&f, &g}, std::pair{&g, &f}, std::pair{&f, &f}}) {
    const auto merged = mesh::levelExcessByMerge(*from, *to);
    mesh::ForestOverlap overlap(*from, *to, {}, 0);
    ASSERT_EQ(static_cast<int>(merged.size()), overlap.numTargetCells());
    int positive = 0, negative = 0;
    for (int e = 0; e < overlap.numTargetCells(); ++e) {
      int finest = 0;
      for (const auto& c : overlap.overlapping(e)) finest = std::max(finest, c.level);
      ASSERT_EQ(merged[e], finest - overlap.target(e).level) << "cell " << e;
      positive += merged[e] > 0;
      negative += merged[e] < 0;
    }
    if (from != to) EXPECT_GT(positive, 0);
    if (from != to) EXPECT_GT(negative, 0);
  }
}

// Steps with equal meshes share one forest; a refinement that Algorithm 5.3 demands for one of
// them must not reach the other.
TEST(TemporalRegularisation, SharedMeshesAreRegularisedStepByStep) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  auto coarse = std::make_shared<mesh::Forest>(*a.forest);
  auto fine = std::make_shared<mesh::Forest>(*a.forest);
  refineAt(*fine, 0.3, 0.3, 2);  // two levels finer than the coarse mesh near (0.3, 0.3)
  fine->balance();
  fine->partition();
  std::vector<std::shared_ptr<mesh::Forest>> steps{coarse, coarse, coarse, fine};
  mesh::regulariseSteps(steps);
  for (size_t n = 0; n + 1 < steps.size(); ++n) {
    EXPECT_LE(mesh::maxLevelExcess(*steps[n], *steps[n + 1]), 1) << "forward " << n;
    EXPECT_LE(mesh::maxLevelExcess(*steps[n + 1], *steps[n]), 1) << "backward " << n;
  }
  // Only step 2 needed refinement (one level); steps 0 and 1 are unchanged and still share.
  EXPECT_GT(steps[2]->numGlobalCells(), coarse->numGlobalCells());
  EXPECT_TRUE(steps[1]->sameCells(*a.forest));
  EXPECT_EQ(steps[0].get(), steps[1].get());
  EXPECT_NE(steps[1].get(), steps[2].get());
  EXPECT_TRUE(steps[3]->sameCells(*fine));
}

// A rectangle's coarse cells are grouped into trees of up to 16 x 16 cells; the user sees the
// same cells, levels (0 on the coarse cells) and cell sizes as with one tree per cell.
TEST(CoarseMesh, GroupedRectangleKeepsTheCoarseCellsAndLevels) {
  struct Case {
    int nx, ny, offset;
  };
  for (const Case c : {Case{16, 16, 4}, Case{12, 8, 2}, Case{64, 32, 4}, Case{3, 5, 0}}) {
    test::TestMesh tm(0.0, 3.0, 0.0, 1.0, c.nx, c.ny, 1);
    EXPECT_EQ(tm.coarse->levelOffset(), c.offset) << c.nx << "x" << c.ny;
    EXPECT_EQ(tm.coarse->numTrees(), (c.nx >> c.offset) * (c.ny >> c.offset));
    EXPECT_EQ(tm.forest->numGlobalCells(), 4LL * c.nx * c.ny);
    const auto& m = tm.build();
    for (LO e = 0; e < m.numLocalCells(); ++e) {
      ASSERT_EQ(m.cellLevel()[e], 1);
      // Level 1 of a coarse cell of 3/nx x 1/ny: the corners span half of it.
      EXPECT_NEAR(std::abs(m.cornerCoordsHost(e, 1, 0) - m.cornerCoordsHost(e, 0, 0)), 1.5 / c.nx, 1e-14);
      EXPECT_NEAR(std::abs(m.cornerCoordsHost(e, 2, 1) - m.cornerCoordsHost(e, 0, 1)), 0.5 / c.ny, 1e-14);
    }
    // Coarsening stops at the user's level 0: the coarse cells themselves.
    tm.forest->coarsenMarked(std::vector<char>(m.numLocalCells(), 1), 0);
    EXPECT_EQ(tm.forest->numGlobalCells(), static_cast<long long>(c.nx) * c.ny);
    tm.forest->partition();
    tm.forest->coarsenMarked(std::vector<char>(tm.build().numLocalCells(), 1), 0);
    EXPECT_EQ(tm.forest->numGlobalCells(), static_cast<long long>(c.nx) * c.ny);
  }
}

TEST(Forest, MarkedRefinementAndCoarseningAndSameCells) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 2, 2, 2);  // 64 cells
  mesh::Forest f(*a.forest);
  EXPECT_TRUE(f.sameCells(*a.forest));
  std::vector<char> all(f.numLocalCells(), 1);
  f.refineMarked(all);
  EXPECT_EQ(f.numGlobalCells(), 4 * a.forest->numGlobalCells());
  EXPECT_FALSE(f.sameCells(*a.forest));
  f.coarsenMarked(std::vector<char>(f.numLocalCells(), 1), 2);
  EXPECT_EQ(f.numGlobalCells(), a.forest->numGlobalCells());
  f.partition();
  EXPECT_TRUE(f.sameCells(*a.forest));
  f.coarsenMarked(std::vector<char>(f.numLocalCells(), 1), 2);  // not below the minimum level
  EXPECT_EQ(f.numGlobalCells(), a.forest->numGlobalCells());
  EXPECT_GT(f.bytes(), 0u);
  // Same number of cells, different cells (one refined cell at two different places): not the same.
  mesh::Forest g(*a.forest), h(*a.forest);
  refineAt(g, 0.1, 0.1, 3);
  refineAt(h, 0.9, 0.9, 3);
  ASSERT_EQ(g.numGlobalCells(), h.numGlobalCells());
  EXPECT_FALSE(g.sameCells(h));
  EXPECT_FALSE(h.sameCells(g));
  refineAt(g, 0.9, 0.9, 3);
  refineAt(h, 0.1, 0.1, 3);
  g.partition();
  h.partition();
  EXPECT_TRUE(g.sameCells(h));
}

TEST(Forest, BalancedRefinementEqualsRefinementThenP4estBalance) {
  // A graded, balanced forest over several trees (deep refinement near two points), then flags
  // that depend only on the cell (the same on any partition): refining the forced closure, found
  // through p4est's faces and corners (Forest::refineMarkedBalanced) or through the Q1 nodes
  // (Q1Mesh::balanceClosure), must give exactly p4est_balance's forest (also when every cell is
  // flagged).
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 3, 2, 1);
  refineAt(*a.forest, 0.999, 0.999, 4);
  refineAt(*a.forest, 0.3, 0.6, 3);
  a.forest->balance();
  a.forest->partition();
  long long forced = 0;  // cells the balance added beyond the flagged refinement, over all seeds
  for (int seed = 0; seed < 7; ++seed) {  // seed 6: every cell
    mesh::Forest viaP4est(*a.forest), viaClosure(*a.forest);
    std::vector<char> flags;
    p4est_t* p = a.forest->p4est();
    for (p4est_topidx_t t = p->first_local_tree; t <= p->last_local_tree; ++t) {
      p4est_tree_t* tree = p4est_tree_array_index(p->trees, t);
      for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi) {
        const auto* q = p4est_quadrant_array_index(&tree->quadrants, qi);
        const unsigned h = (static_cast<unsigned>(q->x) * 73856093u) ^ (static_cast<unsigned>(q->y) * 19349663u) ^
                           (static_cast<unsigned>(t) * 83492791u) ^ (static_cast<unsigned>(q->level + seed) * 2654435761u);
        flags.push_back(seed == 6 || (h >> 7) % 7 == 0 ? 1 : 0);  // about one cell in seven, scattered over all levels
      }
    }
    viaP4est.refineMarked(flags);
    const long long refinedOnly = viaP4est.numGlobalCells();
    viaP4est.balance();
    forced += viaP4est.numGlobalCells() - refinedOnly;
    viaClosure.refineMarkedBalanced(flags);  // the closure through p4est's faces and corners
    mesh::Forest viaNodes(*a.forest);          // the closure through the Q1 nodes
    const mesh::Q1Mesh q1(*a.forest, *a.segments, Tpetra::getDefaultComm());
    viaNodes.refineMarked(q1.balanceClosure(flags));
    EXPECT_EQ(viaNodes.numGlobalCells(), viaP4est.numGlobalCells()) << "seed " << seed;
    viaP4est.partition();
    viaNodes.partition();
    viaClosure.partition();
    EXPECT_TRUE(viaNodes.sameCells(viaP4est)) << "seed " << seed;
    EXPECT_TRUE(viaClosure.sameCells(viaP4est)) << "seed " << seed;
    mesh::Forest rebalanced(viaNodes);
    rebalanced.balance();
    EXPECT_TRUE(rebalanced.sameCells(viaNodes)) << "seed " << seed;
  }
  EXPECT_GT(forced, 0);  // the flags did force balancing refinements
}

}  // namespace
