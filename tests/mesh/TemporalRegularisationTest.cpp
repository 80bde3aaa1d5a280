// Refinement, balance (Algorithm 5.2) and temporal regularisation (Algorithm 5.3) on forests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include <p4est_algorithms.h>
#include <p4est_bits.h>
#include <p4est_lnodes.h>

#include "../TestMesh.hpp"
#include "BruteForceMeshChecks.hpp"
#include "signorini/mesh/ForestOverlap.hpp"
#include "signorini/mesh/TemporalRegularisation.hpp"

using namespace signorini;

namespace {

using test::refineAt;

TEST(Balance, LeavesAtMostOneHangingNodePerEdge) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 1, 1, 1);
  refineAt(*tm.forest, 0.3, 0.3, 6);  // a deep local refinement: multiple hanging nodes before balancing
  const mesh::Forest unbalanced(*tm.forest);
  EXPECT_GT(test::maxHangingNodesPerEdge(unbalanced), 1);
  tm.forest->balance();
  tm.forest->partition();
  // Counted by brute force over all cell corners: one hanging node (at the midpoint) at most, and
  // balancing only refined.
  EXPECT_EQ(test::maxHangingNodesPerEdge(*tm.forest), 1);
  EXPECT_TRUE(test::containsRefinement(*tm.forest, unbalanced));
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
  ASSERT_EQ(a.coarse->numTrees(), 1);
  std::vector<std::unique_ptr<mesh::Forest>> steps;
  for (int n = 0; n < 4; ++n) steps.push_back(std::make_unique<mesh::Forest>(*a.forest));
  // Step 1 is refined deeply near a point, step 3 near another: steps 0, 2 are coarse there.
  refineAt(*steps[1], 0.2, 0.7, 4);
  refineAt(*steps[3], 0.8, 0.1, 3);
  for (auto& f : steps) {
    f->balance();
    f->partition();
  }
  std::vector<std::unique_ptr<mesh::Forest>> before;
  for (auto& f : steps) before.push_back(std::make_unique<mesh::Forest>(*f));
  // Violations in both directions: step 2 is coarse where step 1 is fine (forward), steps 0 and 2
  // are coarse where steps 1 and 3 are fine (backward).
  EXPECT_GE(test::maxCoarserThanOverlapping(*steps[2], *steps[1]), 2);
  EXPECT_GE(test::maxCoarserThanOverlapping(*steps[0], *steps[1]), 2);
  EXPECT_GE(test::maxCoarserThanOverlapping(*steps[2], *steps[3]), 2);
  EXPECT_EQ(mesh::maxLevelExcess(*steps[1], *steps[2]), test::maxCoarserThanOverlapping(*steps[2], *steps[1]));
  std::vector<mesh::Forest*> seq;
  for (auto& f : steps) seq.push_back(f.get());
  mesh::regulariseSequence(seq);
  for (size_t n = 0; n + 1 < steps.size(); ++n) {
    EXPECT_LE(test::maxCoarserThanOverlapping(*steps[n + 1], *steps[n]), 1) << "forward " << n;
    EXPECT_LE(test::maxCoarserThanOverlapping(*steps[n], *steps[n + 1]), 1) << "backward " << n;
  }
  // Regularising refines only and keeps the 2:1 balance.
  for (size_t n = 0; n < steps.size(); ++n) {
    EXPECT_TRUE(test::containsRefinement(*steps[n], *before[n])) << "step " << n;
    EXPECT_LE(test::maxHangingNodesPerEdge(*steps[n]), 1) << "step " << n;
  }
}

// Six steps of one tree, each refined deeply around a point that moves from step to step (with
// extra refinements chosen by a hash of the cell, the same on any partition), then balanced:
// neighbouring steps violate Algorithm 5.3's condition both ways. After regulariseSequence, every
// step contains its own refinement, is 2:1 balanced, and no cell is more than one level coarser
// than an overlapping cell of either neighbouring step (all by brute force).
TEST(TemporalRegularisation, MovingRefinementOverSixStepsIsRegularisedBothWays) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 4, 4, 1);
  ASSERT_EQ(a.coarse->numTrees(), 1);
  auto refineAround = [](double px, double py, unsigned seed) {
    return [=](int, const p4est_quadrant_t& q) {
      const double len = static_cast<double>(P4EST_QUADRANT_LEN(q.level)) / P4EST_ROOT_LEN;
      const double x = q.x / static_cast<double>(P4EST_ROOT_LEN), y = q.y / static_cast<double>(P4EST_ROOT_LEN);
      const double distance = std::hypot(std::max({x - px, 0.0, px - x - len}), std::max({y - py, 0.0, py - y - len}));
      unsigned h = seed * 2654435761u ^ (static_cast<unsigned>(q.x) * 73856093u) ^ (static_cast<unsigned>(q.y) * 19349663u) ^
                   static_cast<unsigned>(q.level);
      h ^= h >> 13;
      h *= 0x5bd1e995u;
      h ^= h >> 15;
      return q.level < 9 && (distance == 0.0 || (h % 3 == 0 && distance < 2 * len));
    };
  };
  constexpr int numSteps = 6;
  std::vector<std::unique_ptr<mesh::Forest>> steps;
  for (int n = 0; n < numSteps; ++n) {
    auto f = std::make_unique<mesh::Forest>(*a.forest);
    const double px = 0.12 + 0.15 * n, py = 0.5 + 0.25 * std::sin(1.3 * n);
    for (int round = 0; round < 6; ++round) f->refineIf(refineAround(px, py, 7u * n + round));
    f->balance();
    f->partition();
    ASSERT_LE(test::maxHangingNodesPerEdge(*f), 1) << "step " << n;
    steps.push_back(std::move(f));
  }
  std::vector<std::unique_ptr<mesh::Forest>> before;
  for (auto& f : steps) before.push_back(std::make_unique<mesh::Forest>(*f));
  for (int n = 0; n + 1 < numSteps; ++n) {
    const int forward = test::maxCoarserThanOverlapping(*steps[n + 1], *steps[n]);
    const int backward = test::maxCoarserThanOverlapping(*steps[n], *steps[n + 1]);
    EXPECT_GE(forward, 2) << "forward " << n;
    EXPECT_GE(backward, 2) << "backward " << n;
    // The project's overlap-based measure agrees with the brute force.
    EXPECT_EQ(mesh::maxLevelExcess(*steps[n], *steps[n + 1]), forward) << "forward " << n;
    EXPECT_EQ(mesh::maxLevelExcess(*steps[n + 1], *steps[n]), backward) << "backward " << n;
  }
  std::vector<mesh::Forest*> seq;
  for (auto& f : steps) seq.push_back(f.get());
  mesh::regulariseSequence(seq);
  for (int n = 0; n < numSteps; ++n) {
    EXPECT_TRUE(test::containsRefinement(*steps[n], *before[n])) << "step " << n;
    // Each step was coarse where a neighbour was fine, so regularising had to refine it.
    EXPECT_FALSE(test::containsRefinement(*before[n], *steps[n])) << "step " << n;
    EXPECT_LE(test::maxHangingNodesPerEdge(*steps[n]), 1) << "step " << n;
    if (n > 0) { EXPECT_LE(test::maxCoarserThanOverlapping(*steps[n], *steps[n - 1]), 1) << "against step " << n - 1; }
    if (n + 1 < numSteps) { EXPECT_LE(test::maxCoarserThanOverlapping(*steps[n], *steps[n + 1]), 1) << "against step " << n + 1; }
  }
}

// regulariseSequence checks a directed pair of steps again only when one of its meshes has been
// refined since its last check. It must give exactly the meshes of the plain algorithm, which
// checks every pair in every sweep until a round refines nothing (here by regulariseInTime):
// on eight steps refined deeply at scattered points (a hash of the step), whose pairs violate the
// condition in both directions, and on two equal fine steps before the initial mesh, where only
// the first check of the last pair refines anything; with fewer checks. (In these cases, as in
// the decks measured, the plain algorithm's second round refines nothing, so a rule that checked
// pairs too rarely after their first check would not show here.)
TEST(TemporalRegularisation, SkippingCheckedPairsGivesThePlainAlgorithmsMeshes) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 4, 4, 1);
  auto hash = [](unsigned v) {
    v ^= v >> 16, v *= 0x7feb352du, v ^= v >> 15, v *= 0x846ca68bu, v ^= v >> 16;
    return v;
  };
  auto scattered = [&](int n, mesh::Forest& f) {
    for (unsigned k = 0; k < 3; ++k) {
      const unsigned h = hash(1000u + 10u * static_cast<unsigned>(n) + k);
      refineAt(f, (h % 1000) / 1000.0, ((h / 1000) % 1000) / 1000.0, 1 + static_cast<int>((h / 1000000) % 7));
    }
  };
  auto twoFineThenCoarse = [&](int n, mesh::Forest& f) {
    if (n < 2) refineAt(f, 0.3, 0.6, 5);
  };
  for (const auto& [numSteps, refine] :
       {std::pair<int, std::function<void(int, mesh::Forest&)>>{8, scattered}, {3, twoFineThenCoarse}}) {
    std::vector<std::unique_ptr<mesh::Forest>> skipping, plain;
    for (int n = 0; n < numSteps; ++n) {
      auto f = std::make_unique<mesh::Forest>(*a.forest);
      refine(n, *f);
      f->balance();
      f->partition();
      plain.push_back(std::make_unique<mesh::Forest>(*f));
      skipping.push_back(std::move(f));
    }
    EXPECT_GE(test::maxCoarserThanOverlapping(*plain[numSteps - 1], *plain[numSteps - 2]), 2);
    int forward = 0, backward = 0, plainChecks = 0;
    for (int changed = 1; changed; plainChecks += 2 * (numSteps - 1)) {
      changed = 0;
      for (int n = 1; n < numSteps; ++n) {
        const int passes = mesh::regulariseInTime(*plain[n - 1], *plain[n]);
        changed += passes, forward += passes;
      }
      for (int n = numSteps - 1; n-- > 0;) {
        const int passes = mesh::regulariseInTime(*plain[n + 1], *plain[n]);
        changed += passes, backward += passes;
      }
    }
    EXPECT_GE(forward, 1) << numSteps << " steps";
    if (numSteps == 8) { EXPECT_GE(backward, 3); }
    std::vector<mesh::Forest*> seq;
    for (auto& f : skipping) seq.push_back(f.get());
    const int checks = mesh::regulariseSequence(seq);
    for (int n = 0; n < numSteps; ++n) EXPECT_TRUE(skipping[n]->sameCells(*plain[n])) << numSteps << " steps, step " << n;
    // Every pair is checked once, the pairs whose meshes changed again: fewer than the plain checks.
    EXPECT_GE(checks, 2 * (numSteps - 1));
    EXPECT_LT(checks, plainChecks);
    if (numSteps == 3) {
      // M0 = M1, and regularising M2 against M1 refines a cell of M2 only where M1 is finer inside
      // it (marked, or by the 2:1 balance that M1 also satisfies): M2 stays nowhere finer than M1,
      // so only the forward check (M1, M2) refines. It records M2's new version, so the second
      // round finds all four pairs at the versions they were checked at: one check per pair.
      EXPECT_EQ(backward, 0);
      EXPECT_EQ(checks, 2 * (numSteps - 1));
    }
  }
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
    if (from != to) { EXPECT_GT(positive, 0); }
    if (from != to) { EXPECT_GT(negative, 0); }
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

// The compact form (levels in curve order) of a graded forest of several trees, partitioned over
// the ranks: the same cells and partition as the p4est, about one byte per cell, and expanded
// again exactly the p4est it was (every leaf, in order, on every rank), usable as before.
TEST(Forest, CompactFormKeepsTheCellsAndThePartition) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 3, 2, 1);
  ASSERT_EQ(a.coarse->numTrees(), 6);  // 3 x 2 cells share no power of two: a tree each
  refineAt(*a.forest, 0.999, 0.999, 5);
  refineAt(*a.forest, 0.3, 0.6, 3);
  a.forest->balance();
  a.forest->partition();
  const auto leaves = test::gatherLeaves(*a.forest);
  mesh::Forest f(*a.forest);
  const size_t expandedBytes = f.bytes();
  f.compact();
  ASSERT_TRUE(f.isCompact());
  EXPECT_EQ(f.numGlobalCells(), a.forest->numGlobalCells());
  EXPECT_EQ(f.numLocalCells(), a.forest->numLocalCells());
  EXPECT_LE(f.bytes(), static_cast<size_t>(f.numLocalCells()) + 512);  // levels, partition, tree offsets
  EXPECT_GT(expandedBytes, 20 * static_cast<size_t>(f.numLocalCells()));
  EXPECT_TRUE(f.sameCells(*a.forest));
  EXPECT_TRUE(a.forest->sameCells(f));
  mesh::Forest copy(f);  // a copy of a compact forest is compact
  EXPECT_TRUE(copy.isCompact());
  EXPECT_TRUE(copy.sameCells(f));
  mesh::Forest other(*a.forest);  // one cell more refined: not the same, in either form
  refineAt(other, 0.01, 0.01, 1);
  other.partition();
  other.compact();
  EXPECT_FALSE(other.sameCells(f));
  f.expand();
  ASSERT_FALSE(f.isCompact());
  const auto again = test::gatherLeaves(f);
  ASSERT_EQ(again.size(), leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i)
    ASSERT_TRUE(again[i].tree == leaves[i].tree && again[i].level == leaves[i].level && again[i].x0 == leaves[i].x0 &&
                again[i].y0 == leaves[i].y0)
        << "leaf " << i;
  EXPECT_EQ(f.numLocalCells(), a.forest->numLocalCells());  // the same partition
  EXPECT_TRUE(p4est_is_valid(f.p4est()));
  f.refineMarked(std::vector<char>(f.numLocalCells(), 1));  // and usable like any forest
  EXPECT_EQ(f.numGlobalCells(), 4 * a.forest->numGlobalCells());
}

// Algorithm 5.3 on compact meshes (expanded two at a time by the sweeps) refines exactly as on
// expanded ones, and leaves the meshes compact.
TEST(TemporalRegularisation, CompactMeshesAreRegularisedLikeExpandedOnes) {
  test::TestMesh a(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  std::vector<std::unique_ptr<mesh::Forest>> expanded, compact;
  for (int n = 0; n < 5; ++n) {
    auto f = std::make_unique<mesh::Forest>(*a.forest);
    refineAt(*f, 0.1 + 0.2 * n, 0.3, n % 2 ? 4 : 1);
    f->balance();
    f->partition();
    compact.push_back(std::make_unique<mesh::Forest>(*f));
    compact.back()->compact();
    expanded.push_back(std::move(f));
  }
  std::vector<mesh::Forest*> e, c;
  for (int n = 0; n < 5; ++n) e.push_back(expanded[n].get()), c.push_back(compact[n].get());
  const long long before = expanded[0]->numGlobalCells() + expanded[2]->numGlobalCells();
  mesh::regulariseSequence(e);
  mesh::regulariseSequence(c);
  EXPECT_GT(expanded[0]->numGlobalCells() + expanded[2]->numGlobalCells(), before);  // something was refined
  for (int n = 0; n < 5; ++n) {
    EXPECT_TRUE(compact[n]->isCompact()) << "step " << n;
    EXPECT_TRUE(compact[n]->sameCells(*expanded[n])) << "step " << n;
  }
}

}  // namespace
