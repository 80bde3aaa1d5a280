// The contact QP (DESIGN 1.2) against an independent dense solution: Q = B^T A^{-1} B formed
// column by column, every active set enumerated, the unique KKT point kept. Plus the coupling's
// own facts: each column of B sums to its segment length, segments hold two fine edges.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/solvers/CoarseSchurCorrection.hpp"
#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/solvers/ContactQP.hpp"
#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/solvers/StripSchurApproximation.hpp"
#include "signorini/fem/Q1Assembler.hpp"

using namespace signorini;

namespace {

constexpr unsigned kLeft = 1u << 0, kRight = 1u << 1, kBottom = 1u << 2;

core::ParameterList validated(core::ParameterList valid, core::ParameterList given = core::ParameterList()) {
  core::validateDeck(given, valid, "test");
  return given;
}

TEST(ContactCoupling, ColumnsSumToSegmentLengths) {
  for (auto size : {fem::ContactCoupling::SegmentSize::TwoEdges, fem::ContactCoupling::SegmentSize::OneEdge}) {
    test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 2, 1, 3);  // bottom: 16 fine edges of length 1/8
    tm.refineCorner();                              // graded near x = 0
    const auto& m = tm.build();
    fem::ContactCoupling B(m, kBottom, size, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
    double total = 0;
    for (int j = 0; j < B.numSegments(); ++j) {
      total += B.segmentLength()[j];
      if (size == fem::ContactCoupling::SegmentSize::TwoEdges) {
        EXPECT_GE(B.segmentEdges()[j], 2);
        EXPECT_LE(B.segmentEdges()[j], 3);
      } else
        EXPECT_EQ(B.segmentEdges()[j], 1);
    }
    EXPECT_NEAR(total, 2.0, 1e-14);
    Vector one(m.ownedMap());
    one.putScalar(1.0);
    const auto colSums = B.applyTranspose(one);  // (B^T 1)_j = int_{E_j} 1 ds = |E_j|
    for (int j = 0; j < B.numSegments(); ++j) EXPECT_NEAR(colSums[j], B.segmentLength()[j], 1e-14);
    // gbar of a linear obstacle = |E_j| times its value at the midpoint.
    const auto gbar = B.weightedObstacle(core::Expression("3*x - 1", "test"), 0.0);
    for (int j = 0; j < B.numSegments(); ++j)
      EXPECT_NEAR(gbar[j], B.segmentLength()[j] * (3 * B.segmentMidpoint()[j][0] - 1), 1e-13);
    // gbar of x^5 (3-point Gauss per fine edge is exact to degree 5; a lower rule, e.g. Simpson's,
    // is not): the integral over the segment, (x1^6 - x0^6) / 6, from its midpoint and length.
    const auto quintic = B.weightedObstacle(core::Expression("x^5", "test"), 0.0);
    for (int j = 0; j < B.numSegments(); ++j) {
      const double x0 = B.segmentMidpoint()[j][0] - B.segmentLength()[j] / 2, x1 = x0 + B.segmentLength()[j];
      EXPECT_NEAR(quintic[j], (std::pow(x1, 6) - std::pow(x0, 6)) / 6, 1e-12) << "segment " << j;
    }
    // Segments are ordered along the boundary.
    for (int j = 1; j < B.numSegments(); ++j) EXPECT_GT(B.segmentMidpoint()[j][0], B.segmentMidpoint()[j - 1][0]);
  }
}

TEST(ContactCoupling, SmallestGapsAreTheLowestPointsOfEachSegment) {
  // Bottom side of [0, 2] x [0, 1] with edges of 1/8, segments of two: a gap that falls linearly
  // along x, 1 - 2.5 x, is smallest at the last Gauss point of the segment's right edge,
  // x1 - (1 - 0.8873) / 8, where the mean gap is at the midpoint; on 1-3 ranks every rank gets
  // every segment's value. For the scalar wave (u = 0.5 x, g = 3 x - 1) and for plane strain with
  // the constraint -u_y >= g on the second of two components (u_y = -0.5 x beside u_x = 100).
  test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 2, 1, 3);
  const auto& m = tm.build();
  const core::Expression g("3*x - 1", "test");
  fem::ElasticityAssembler plane(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), 1.0, 1.0);
  for (const int components : {1, 2}) {
    const fem::ContactUnknowns unknowns = components == 1 ? fem::ContactUnknowns()
                                                          : fem::ContactUnknowns{plane.ownedMap(), plane.overlapMap(),
                                                                                 2, 1, -1.0};
    fem::ContactCoupling B(m, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges,
                           std::vector<char>(components * m.overlapMap()->getNodeNumElements(), 0), unknowns);
    Vector u(components == 1 ? m.overlapMap() : plane.overlapMap());
    {
      auto h = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (size_t i = 0; i < m.nodeCoords().size(); ++i) {
        const double x = m.nodeCoords()[i][0];
        if (components == 1)
          h(i, 0) = 0.5 * x;
        else
          h(2 * i, 0) = 100.0, h(2 * i + 1, 0) = -0.5 * x;
      }
    }
    const auto smallest = B.smallestGaps(m, u, g, 0.0);
    ASSERT_EQ(static_cast<int>(smallest.size()), B.numSegments());
    ASSERT_EQ(B.numSegments(), 8);
    for (int j = 0; j < B.numSegments(); ++j) {
      const double right = B.segmentMidpoint()[j][0] + B.segmentLength()[j] / 2;
      EXPECT_NEAR(smallest[j], 1 - 2.5 * (right - (1 - 0.88729833462074169) / 8), 1e-14)
          << components << " component(s), segment " << j;
      EXPECT_LT(smallest[j], 1 - 2.5 * B.segmentMidpoint()[j][0] - 0.1) << "segment " << j;  // below the mean gap
    }
  }
  // On a graded side, an obstacle whose peak lies inside a segment: the smallest gap of u = 0 is
  // -g at the peak (the midpoint of an edge of 1/32, x = 3/64, inside the segment [0, 1/16]) in
  // the segment holding it, where the mean gap is positive.
  test::TestMesh graded(0.0, 2.0, 0.0, 1.0, 2, 1, 3);
  graded.refineCorner();
  const auto& mg = graded.build();
  fem::ContactCoupling Bg(mg, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges,
                          std::vector<char>(mg.overlapMap()->getNodeNumElements(), 0));
  Vector zero(mg.overlapMap());
  const core::Expression peak("0.1 - 200*(x - 0.046875)^2", "test");
  const auto smallest = Bg.smallestGaps(mg, zero, peak, 0.0);
  const auto gbar = Bg.weightedObstacle(peak, 0.0);
  bool seen = false;
  for (int j = 0; j < Bg.numSegments(); ++j) {
    const double x0 = Bg.segmentMidpoint()[j][0] - Bg.segmentLength()[j] / 2, x1 = x0 + Bg.segmentLength()[j];
    if (x0 < 3.0 / 64 && 3.0 / 64 < x1) {
      seen = true;
      EXPECT_NEAR(smallest[j], -0.1, 1e-14);
      EXPECT_GT(-gbar[j] / Bg.segmentLength()[j], 0.0);  // the mean gap misses the contact
    }
  }
  EXPECT_TRUE(seen);
}

TEST(ContactCoupling, SegmentsAreParentEdgesAndMirrorInvariant) {
  // Unit square, one tree, h = 1/8, refined three times around x = 0.3 and x = 0.7 of the bottom
  // side and 2:1 balanced: a graded contact boundary, mirror-symmetric about x = 0.5, with runs of
  // equal edges of odd length and lone edges between size changes.
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 1, 1, 3);
  test::refineAt(*tm.forest, 0.3, 0.0, 3);
  test::refineAt(*tm.forest, 0.7, 0.0, 3);
  tm.forest->balance();
  tm.forest->partition();
  const auto& m = tm.build();
  fem::ContactCoupling B(m, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges,
                         std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  const int ns = B.numSegments();
  // Longest edge of each segment and shortest contact edge, over all ranks.
  std::vector<double> longest(ns, 0.0), globalLongest(ns);
  double shortest = 1.0, globalShortest = 0.0;
  for (size_t i = 0; i < m.boundaryEdges().size(); ++i)
    if (const int j = B.localEdgeSegment()[i]; j >= 0) {
      longest[j] = std::max(longest[j], m.boundaryEdges()[i].length());
      shortest = std::min(shortest, m.boundaryEdges()[i].length());
    }
  Teuchos::reduceAll(*m.comm(), Teuchos::REDUCE_MAX, ns, longest.data(), globalLongest.data());
  Teuchos::reduceAll(*m.comm(), Teuchos::REDUCE_MIN, shortest, Teuchos::outArg(globalShortest));
  EXPECT_NEAR(globalShortest, 1.0 / 64, 1e-15);  // graded
  std::set<std::pair<long long, long long>> intervals;  // in units of the finest edge, 1/64
  for (int j = 0; j < ns; ++j) {
    EXPECT_GE(B.segmentEdges()[j], 2) << j;
    // Each segment is exactly the parent edge of its longest edges (dyadic: starts at a multiple
    // of its length), so it follows the local mesh size.
    const double a = B.segmentMidpoint()[j][0] - 0.5 * B.segmentLength()[j], len = B.segmentLength()[j];
    EXPECT_NEAR(len, 2 * globalLongest[j], 1e-14) << j;
    EXPECT_NEAR(a / len, std::round(a / len), 1e-12) << j;
    intervals.insert({std::llround(64 * a), std::llround(64 * (a + len))});
  }
  EXPECT_GT(*std::max_element(B.segmentEdges().begin(), B.segmentEdges().end()), 2);  // lone edges joined
  // The mirror image x -> 1 - x of every segment is a segment.
  for (const auto& [a, b] : intervals) EXPECT_EQ(intervals.count({64 - b, 64 - a}), 1u) << a << " " << b;
}

TEST(ContactCoupling, UnrefinedTreesArePairedAlongTheBoundary) {
  // 8 x 1 coarse cells, one p4est tree each (as an Exodus mesh has), the first and the last tree
  // refined twice at the middle of their bottom side and balanced: the bottom's unrefined trees
  // have no parent edge in the forest. They pair up as the rest do (they used to join one
  // neighbouring segment of six edges), mirror-symmetrically about x = 4.
  test::TestMesh tm(0.0, 8.0, 0.0, 1.0, 8, 1, 0);
  ASSERT_EQ(tm.coarse->numTrees(), 8);
  for (int pass = 0; pass < 2; ++pass)
    tm.forest->refineIf([](int tree, const p4est_quadrant_t& q) {
      const double len = static_cast<double>(P4EST_QUADRANT_LEN(q.level)) / P4EST_ROOT_LEN;
      const double x = q.x / static_cast<double>(P4EST_ROOT_LEN), y = q.y / static_cast<double>(P4EST_ROOT_LEN);
      return (tree == 0 || tree == 7) && x <= 0.5 && 0.5 <= x + len && y == 0.0;
    });
  tm.forest->balance();
  tm.forest->partition();
  const auto& m = tm.build();
  fem::ContactCoupling B(m, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges,
                         std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  std::set<std::pair<long long, long long>> intervals;  // in units of the finest edge, 1/4
  int coarse = 0;
  for (int j = 0; j < B.numSegments(); ++j) {
    EXPECT_GE(B.segmentEdges()[j], 2) << j;
    EXPECT_LE(B.segmentEdges()[j], 3) << j;
    const double a = B.segmentMidpoint()[j][0] - 0.5 * B.segmentLength()[j];
    intervals.insert({std::llround(4 * a), std::llround(4 * (a + B.segmentLength()[j]))});
    coarse += B.segmentLength()[j] == 2.0;
  }
  EXPECT_GE(coarse, 2);  // pairs of unrefined trees
  for (const auto& [a, b] : intervals) EXPECT_EQ(intervals.count({32 - b, 32 - a}), 1u) << a << " " << b;
}

// A column of 1 x N trees of one cell each, some trees refined once: the right side is a chain of
// sibling pairs (the refined trees' faces, whose parent is the tree face) and unrefined tree faces,
// which have no parent in the forest. Every contact edge must belong to a segment of two or three
// edges. The rule (ContactCoupling, README "What is verified"): the tree faces of the chain pair up
// from both ends toward the middle as the halves of a virtual parent edge; an unrefined face whose
// partner face is refined joins the finer edges next to it; the middle face of an odd chain has no
// partner and joins the segment before it, so the result depends on the chain's direction (4m + 1
// faces are not mirror-symmetric), and each expectation admits both directions.
TEST(ContactCoupling, LoneAndOddUnrefinedFacesJoinASegment) {
  struct Case {
    int trees;
    std::function<bool(double)> refined;  // by the tree's centre y
    std::set<std::pair<long long, long long>> up, down;  // segments [a, b] in units of 1/2
  };
  const std::vector<Case> cases{
      // faces (0, 1) and (3, 4) refined: two sibling pairs each; the middle face [2, 3] joins [1, 2] or [3, 4]
      {5, [](double y) { return y < 2 || y > 3; }, {{0, 2}, {2, 6}, {6, 8}, {8, 10}}, {{0, 2}, {2, 4}, {4, 8}, {8, 10}}},
      // faces (0, 1) and (5, 6) pair, 0 and 6 refined: faces 1 and 5 join their partners' fine edges
      // ([0, 2] and [5, 7] of three edges), the middle three faces are one segment
      {7, [](double y) { return y < 1 || y > 6; }, {{0, 4}, {4, 10}, {10, 14}}, {{0, 4}, {4, 10}, {10, 14}}},
      // nothing refined: (0, 1) and (3, 4) pair, the middle face joins the segment before it
      {5, [](double) { return false; }, {{0, 6}, {6, 10}}, {{0, 4}, {4, 10}}},
      // four faces: (0, 1) and (2, 3) pair from both ends; face 0 (or 3) refined: face 1 (or 2)
      // joins its partner's fine edges in a segment of three edges, the other pair is one segment
      {4, [](double y) { return y < 1; }, {{0, 4}, {4, 8}}, {{0, 4}, {4, 8}}},
      {4, [](double y) { return y > 3; }, {{0, 4}, {4, 8}}, {{0, 4}, {4, 8}}},
  };
  for (const auto& c : cases) {
    test::TestMesh tm(0.0, 1.0, 0.0, c.trees, 1, c.trees, 0);
    ASSERT_EQ(tm.coarse->numTrees(), c.trees);  // 1 x 4, 5 or 7 cells: trees of one cell
    tm.forest->refineIf([&](int tree, const p4est_quadrant_t&) { return c.refined(tm.coarse->mapPoint(tree, 0.5, 0.5)[1]); });
    tm.forest->partition();
    const auto& m = tm.build();
    fem::ContactCoupling B(m, kRight, fem::ContactCoupling::SegmentSize::TwoEdges,
                           std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
    std::set<std::pair<long long, long long>> intervals;
    double total = 0;
    for (int j = 0; j < B.numSegments(); ++j) {
      EXPECT_GE(B.segmentEdges()[j], 2) << c.trees << " trees, segment " << j;
      EXPECT_LE(B.segmentEdges()[j], 3) << c.trees << " trees, segment " << j;
      const double a = B.segmentMidpoint()[j][1] - 0.5 * B.segmentLength()[j];
      intervals.insert({std::llround(2 * a), std::llround(2 * (a + B.segmentLength()[j]))});
      total += B.segmentLength()[j];
    }
    EXPECT_NEAR(total, c.trees, 1e-14);  // the segments cover the side once
    std::ostringstream got;
    for (const auto& [a, b] : intervals) got << " [" << a << ", " << b << "]";
    EXPECT_TRUE(intervals == c.up || intervals == c.down) << c.trees << " trees, segments in units of 1/2:" << got.str();
    for (size_t i = 0; i < m.boundaryEdges().size(); ++i)
      if (m.boundaryEdges()[i].x[0][0] == 1.0 && m.boundaryEdges()[i].x[1][0] == 1.0)
        { EXPECT_GE(B.localEdgeSegment()[i], 0) << "a contact edge without a segment"; }
    Vector one(m.ownedMap());
    one.putScalar(1.0);
    const auto colSums = B.applyTranspose(one);
    for (int j = 0; j < B.numSegments(); ++j) EXPECT_NEAR(colSums[j], B.segmentLength()[j], 1e-14);
  }
}

TEST(ContactCoupling, TreesOfOneCellPairLikeTheRectanglesTrees) {
  // The same 8 x 2 cells of [0, 8] x [0, 2], as a rectangle (trees of 2 x 2 cells) and with one tree
  // per cell (as from an Exodus file), refined alike toward two points of the bottom: the bottom's
  // segments are the same intervals. The cells' faces pair up as the rectangle's siblings do, also
  // where the partner face is refined and where unrefined faces sit between refined ones.
  std::vector<double> x, y;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 8; ++i) x.push_back(i), y.push_back(j);
  std::vector<std::array<int, 4>> quads;
  std::map<std::string, std::vector<std::array<int, 2>>> sides;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 8; ++i) {
      const int v = 9 * j + i;
      quads.push_back({v, v + 1, v + 10, v + 9});
      if (j == 0) sides["bottom"].push_back({static_cast<int>(quads.size()) - 1, 0});
      if (i == 0) sides["left"].push_back({static_cast<int>(quads.size()) - 1, 3});
      if (i == 7) sides["right"].push_back({static_cast<int>(quads.size()) - 1, 1});
    }
  const std::vector<std::pair<std::string, std::string>> specs{{"left", "left"}, {"right", "right"}, {"bottom", "bottom"}};
  test::TestMesh rectangle(mesh::CoarseMesh::rectangle(0.0, 8.0, 0.0, 2.0, 8, 2), specs, 0);
  test::TestMesh cells(mesh::CoarseMesh::fromQuads(x, y, quads, sides, "8 x 2 cells"), specs, 0);
  ASSERT_EQ(rectangle.coarse->numTrees(), 4);
  ASSERT_EQ(cells.coarse->numTrees(), 16);
  auto segmentsOf = [](test::TestMesh& tm) {
    tm.refineWithin(2.3, 0.0, 0.8, 3);
    tm.refineWithin(4.6, 0.0, 0.8, 1);
    tm.forest->partition();
    const auto& m = tm.build();
    fem::ContactCoupling B(m, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges,
                           std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
    std::set<std::pair<long long, long long>> intervals;  // in units of the finest edge, 1/8
    for (int j = 0; j < B.numSegments(); ++j) {
      const double a = B.segmentMidpoint()[j][0] - 0.5 * B.segmentLength()[j];
      intervals.insert({std::llround(8 * a), std::llround(8 * (a + B.segmentLength()[j]))});
    }
    return std::make_pair(intervals, m.numGlobalCells());
  };
  const auto [fromRectangle, rectangleCells] = segmentsOf(rectangle);
  const auto [fromCells, cellsCells] = segmentsOf(cells);
  EXPECT_EQ(rectangleCells, cellsCells);  // the same mesh
  EXPECT_EQ(fromRectangle, fromCells);
  EXPECT_EQ(fromCells.count({48, 64}), 1u);  // x in [6, 8]: two unrefined cells, one segment
  EXPECT_GE(fromCells.size(), 8u);
}

TEST(ContactCoupling, HoleBoundaryPairsTheSameOnAnyRanks) {
  // 4 x 4 cells of [0, 4]^2 without the middle 2 x 2, one tree per cell: the contact boundary is
  // the hole's, a closed loop of 8 tree faces. Unrefined, its faces pair from the smallest face
  // (tree 1's top, [1, 2] x {1}) toward its smaller neighbour (tree 2's top): the four sides of the
  // hole. Refined toward a corner of the hole, the segments hold at least two edges, cover the loop
  // once, and are the same whether the mesh is spread over all ranks or held by each one.
  std::vector<double> x, y;
  std::map<std::pair<int, int>, int> vertex;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i)
      if (!(i == 2 && j == 2)) vertex[{i, j}] = static_cast<int>(x.size()), x.push_back(i), y.push_back(j);
  std::vector<std::array<int, 4>> quads;
  std::map<std::string, std::vector<std::array<int, 2>>> sides;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      if ((i == 1 || i == 2) && (j == 1 || j == 2)) continue;
      quads.push_back({vertex[{i, j}], vertex[{i + 1, j}], vertex[{i + 1, j + 1}], vertex[{i, j + 1}]});
      const int c = static_cast<int>(quads.size()) - 1;
      if (j == 0 && (i == 1 || i == 2)) sides["hole"].push_back({c, 2});
      if (j == 3 && (i == 1 || i == 2)) sides["hole"].push_back({c, 0});
      if (i == 0 && (j == 1 || j == 2)) sides["hole"].push_back({c, 1});
      if (i == 3 && (j == 1 || j == 2)) sides["hole"].push_back({c, 3});
      if (i == 0) sides["outer"].push_back({c, 3});
    }
  const auto coarse = mesh::CoarseMesh::fromQuads(x, y, quads, sides, "square with a hole");
  const std::vector<std::pair<std::string, std::string>> specs{{"outer", "outer"}, {"unused", "outer"}, {"hole", "hole"}};
  constexpr unsigned kHole = 1u << 2;
  using Segments = std::set<std::array<long long, 3>>;  // midpoint and length in units of 1/64
  auto segmentsOf = [&](RCP<const Comm> comm, int passes) {
    test::TestMesh tm(coarse, specs, 0, comm);
    tm.refineWithin(1.3, 0.8, 0.6, passes);
    tm.forest->partition();
    const auto& m = tm.build();
    fem::ContactCoupling B(m, kHole, fem::ContactCoupling::SegmentSize::TwoEdges,
                           std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
    Segments out;
    double total = 0;
    for (int j = 0; j < B.numSegments(); ++j) {
      EXPECT_GE(B.segmentEdges()[j], 2) << "segment " << j;
      total += B.segmentLength()[j];
      out.insert({std::llround(64 * B.segmentMidpoint()[j][0]), std::llround(64 * B.segmentMidpoint()[j][1]),
                  std::llround(64 * B.segmentLength()[j])});
    }
    EXPECT_NEAR(total, 8.0, 1e-12);  // the loop once
    return out;
  };
  const RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  EXPECT_EQ(segmentsOf(Tpetra::getDefaultComm(), 0), (Segments{{128, 64, 128}, {192, 128, 128}, {128, 192, 128}, {64, 128, 128}}));
  const auto refined = segmentsOf(Tpetra::getDefaultComm(), 2);
  EXPECT_GT(refined.size(), 4u);
  EXPECT_EQ(refined, segmentsOf(self, 2));
}

/// Q = B^T A^{-1} B formed column by column (one A-solve per segment), row-major.
std::vector<double> denseSchurComplement(solvers::LinearSolver& solver, const fem::ContactCoupling& B,
                                         const Map& map) {
  const int ns = B.numSegments();
  std::vector<double> Q(ns * ns);
  Vector w(Teuchos::rcpFromRef(map)), Be(Teuchos::rcpFromRef(map));
  for (int j = 0; j < ns; ++j) {
    std::vector<double> e(ns, 0.0);
    e[j] = 1.0;
    B.apply(e, Be);
    w.putScalar(0.0);
    solver.solve(Be, w);
    const auto col = B.applyTranspose(w);
    for (int i = 0; i < ns; ++i) Q[i * ns + j] = col[i];
  }
  return Q;
}

TEST(StripSchurApproximation, IsExactWhenTheStripCoversTheDomain) {
  // With enough layers the strip is the whole mesh minus Dirichlet nodes, so B^T A_s^{-1} B = Q.
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 2);  // 8 x 8 cells
  const auto& m = tm.build();
  const auto dir = m.nodesOnSegments(kLeft);
  fem::Q1Assembler asmb(m, dir);
  auto A = asmb.assembleOperator(1.0, 0.02, 1.0, 1.0);
  fem::ContactCoupling B(m, kRight, fem::ContactCoupling::SegmentSize::TwoEdges, dir);
  const int ns = B.numSegments();
  solvers::StripSchurApproximation strip(*A, B, 10);
  EXPECT_EQ(strip.stripSize(), static_cast<long long>(m.numGlobalNodes()));
  solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters()));
  solver.setOperator(A, 1.0);
  const auto Q = denseSchurComplement(solver, B, *m.ownedMap());
  Vector w(m.ownedMap()), Be(m.ownedMap()), ws(m.ownedMap());
  for (int j = 0; j < ns; ++j) {
    for (int i = 0; i < ns; ++i)
      EXPECT_NEAR(strip.matrix()[i * ns + j], Q[i * ns + j], 1e-9 * Q[j * ns + j]) << i << "," << j;
    std::vector<double> e(ns, 0.0);
    e[j] = 1.0;
    B.apply(e, Be);
    w.putScalar(0.0);
    solver.solve(Be, w);
    strip.applyStripInverse(e, ws);  // A_s^{-1} B e_j = A^{-1} B e_j
    ws.update(-1.0, w, 1.0);
    EXPECT_LE(ws.normInf(), 1e-8 * w.normInf());
  }
  // A narrower strip: B^T A_s^{-1} B maximises 2 (B e)^T w - w^T A w over the strip's fields w only,
  // so it is symmetric positive definite and lies below Q in the Loewner order, the narrower the
  // lower: 0 < S_1 <= S_2 <= Q.
  solvers::StripSchurApproximation narrow(*A, B, 1), two(*A, B, 2);
  auto smallestEigenvalue = [&](const std::vector<double>& X) {  // of the symmetric ns x ns matrix X
    Teuchos::LAPACK<int, double> lapack;
    std::vector<double> a(X), w(ns), work(3 * ns);
    int info = 0;
    lapack.SYEV('N', 'U', ns, a.data(), ns, w.data(), work.data(), static_cast<int>(work.size()), &info);
    EXPECT_EQ(info, 0);
    return w[0];
  };
  std::vector<double> gap21(ns * ns), gapQ2(ns * ns);
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < ns; ++j) {
      EXPECT_NEAR(narrow.matrix()[i * ns + j], narrow.matrix()[j * ns + i], 1e-14 * Q[0]) << i << "," << j;
      gap21[i * ns + j] = two.matrix()[i * ns + j] - narrow.matrix()[i * ns + j];
      gapQ2[i * ns + j] = Q[i * ns + j] - two.matrix()[i * ns + j];
    }
  const double scale = 1e-12 * Q[0];
  EXPECT_GT(smallestEigenvalue(narrow.matrix()), 0.0);
  EXPECT_GE(smallestEigenvalue(gap21), -scale);
  EXPECT_GE(smallestEigenvalue(gapQ2), -scale);
  EXPECT_GT(std::abs(gap21[0]), 1e3 * scale);  // the strips differ: the order is not an equality
}

TEST(StripSchurApproximation, WidthFollowsEachSegment) {
  // On a uniform grid the Q1 graph distance between nodes is the grid's Chebyshev distance, so the
  // strip is known in closed form: the nodes within layers[j] of a node of segment j, for some j.
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 2);  // 8 x 8 cells, h = 1/8
  const auto& m = tm.build();
  const auto dir = m.nodesOnSegments(kLeft);
  fem::Q1Assembler asmb(m, dir);
  auto A = asmb.assembleOperator(1.0, 0.02, 1.0, 1.0);
  fem::ContactCoupling B(m, kRight, fem::ContactCoupling::SegmentSize::TwoEdges, dir);
  ASSERT_EQ(B.numSegments(), 4);
  const std::vector<int> layers{3, 1, 1, 2};
  solvers::StripSchurApproximation strip(*A, B, layers);
  long long expected = 0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      bool in = false;
      for (int s = 0; s < 4; ++s) {
        const double y0 = B.segmentMidpoint()[s][1] - 0.5 * B.segmentLength()[s];
        for (int jj = static_cast<int>(std::lround(8 * y0)); jj <= std::lround(8 * y0) + 2; ++jj)
          in = in || std::max(8 - i, std::abs(j - jj)) <= layers[s];
      }
      expected += in;
    }
  EXPECT_EQ(expected, 9 + 9 + 9 + 6);  // by hand: columns x = 1, 7/8, 6/8 whole, x = 5/8 for y <= 5/8
  EXPECT_EQ(strip.stripSize(), expected);
  // Equal layers give the uniform strip, matrix and all.
  solvers::StripSchurApproximation uniform(*A, B, 2), perSegment(*A, B, std::vector<int>(4, 2));
  EXPECT_EQ(perSegment.stripSize(), uniform.stripSize());
  EXPECT_EQ(perSegment.matrix(), uniform.matrix());
  // A wider strip along one segment brings its Schur block closer to the exact one.
  solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters()));
  solver.setOperator(A, 1.0);
  const auto Q = denseSchurComplement(solver, B, *m.ownedMap());
  solvers::StripSchurApproximation wideFirst(*A, B, std::vector<int>{6, 1, 1, 1}), narrow(*A, B, 1);
  EXPECT_LT(std::abs(wideFirst.matrix()[0] - Q[0]), 0.5 * std::abs(narrow.matrix()[0] - Q[0]));
}

// A strip along a boundary layer of fine cells (the contact side refined four times, graded inward
// by the 2:1 balance) is factored in the ordering along Gamma_C: reverse Cuthill-McKee's
// breadth-first levels run through the coarse cells behind the layer, each reaching along many fine
// edges, and hold more than twice the envelope. On the uniform mesh it is declined. Both give the
// strip's exact Schur block where the strip is the whole mesh (against the direct construction).
TEST(StripSchurApproximation, OrdersAGradedStripAlongTheContactBoundary) {
  for (const bool graded : {false, true}) {
    test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 2);  // 8 x 8 cells
    if (graded)
      for (int pass = 0; pass < 4; ++pass) {
        const double h = 1.0 / (8 << pass);
        test::refineWhere(*tm.forest, *tm.coarse, [&](double x, double) { return x > 1.0 - 0.5 * h - 1e-12; });
      }
    tm.forest->partition();
    const auto& m = tm.build();
    const auto dir = m.nodesOnSegments(kLeft);
    fem::Q1Assembler asmb(m, dir);
    auto A = asmb.assembleOperator(1.0, 0.02, 1.0, 1.0);
    fem::ContactCoupling B(m, kRight, fem::ContactCoupling::SegmentSize::TwoEdges, dir);
    solvers::StripSchurApproximation strip(*A, B, 40);
    EXPECT_EQ(strip.ordersAlongContact(), graded) << (graded ? "graded" : "uniform") << " strip of "
                                                  << strip.stripSize() << " nodes";
    ASSERT_EQ(strip.stripSize(), static_cast<long long>(m.numGlobalNodes()));
    solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters()));
    solver.setOperator(A, 1.0);
    const auto Q = denseSchurComplement(solver, B, *m.ownedMap());
    const int ns = B.numSegments();
    for (int i = 0; i < ns * ns; ++i) EXPECT_NEAR(strip.matrix()[i], Q[i], 1e-8 * Q[0]) << i;
  }
  // Contact on two opposite sides, both refined: two pieces of strip, each ordered along its side
  // (one direction for both would cut across them, and was declined).
  test::TestMesh tm(0.0, 2.0, 0.0, 8.0, 4, 16, 2);  // 16 x 64 cells of 1/8
  for (int pass = 0; pass < 4; ++pass) {
    const double h = 1.0 / (8 << pass);
    test::refineWhere(*tm.forest, *tm.coarse,
                      [&](double x, double) { return x > 2.0 - 0.5 * h - 1e-12 || x < 0.5 * h + 1e-12; });
  }
  tm.forest->partition();
  const auto& m = tm.build();
  const auto dir = m.nodesOnSegments(kBottom);
  fem::Q1Assembler asmb(m, dir);
  auto A = asmb.assembleOperator(1.0, 0.02, 1.0, 1.0);
  fem::ContactCoupling B(m, kLeft | kRight, fem::ContactCoupling::SegmentSize::TwoEdges, dir);
  solvers::StripSchurApproximation strip(*A, B, 10);
  EXPECT_LT(strip.stripSize(), static_cast<long long>(m.numGlobalNodes()) - 9) << "the pieces must not meet";
  EXPECT_TRUE(strip.ordersAlongContact()) << "two-sided strip of " << strip.stripSize() << " nodes";
}

// The strip keeps one physical width along a graded boundary: the finest segments get Strip Width
// times the Courant number c k / h_min in node layers, a segment of edge length h_j the fraction
// h_min / h_j of them (at least 2). Bottom edges of 1/32, 1/16 and 1/8 (a corner refined twice on
// 8 x 8 cells), Strip Width 6, Courant number 2: 12 layers along the finest segments, 3 along the
// coarsest.
TEST(ContactQP, StripLayersFollowTheSegmentsEdgeLength) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 2);
  tm.refineCorner();
  const auto& m = tm.build();
  const auto dir = m.nodesOnSegments(kLeft);
  fem::Q1Assembler asmb(m, dir);
  const auto A = asmb.assembleOperator(1.0, 0.02, 1.0, 1.0);
  fem::ContactCoupling B(m, kBottom, fem::ContactCoupling::SegmentSize::TwoEdges, dir);
  core::ParameterList cp;
  cp.set("Schur Preconditioner", "strip");
  cp.set("Strip Width", 6.0);
  solvers::ContactQP qp(validated(solvers::ContactQP::getValidParameters(), cp), 1.0);
  qp.setSystem(*A, B, 2.0, {});
  const auto& layers = qp.segmentStripLayers();
  ASSERT_EQ(layers.size(), static_cast<size_t>(B.numSegments()));
  std::set<int> seen;
  for (int j = 0; j < B.numSegments(); ++j) {
    // h_j: the segment's mean edge length (a segment across a 2:1 face mixes two sizes)
    const double h = B.segmentLength()[j] / B.segmentEdges()[j];
    const int expected = std::max(2, static_cast<int>(std::ceil(12.0 * (1.0 / 32) / h - 1e-9)));
    EXPECT_EQ(layers[j], expected) << "segment " << j << ", h = " << h;
    seen.insert(layers[j]);
  }
  EXPECT_EQ(*seen.rbegin(), 12);  // the finest segments (h = 1/32)
  EXPECT_EQ(*seen.begin(), 3);    // the coarsest (h = 1/8)
}

/// Dense reference: solves the QP by enumerating active sets (m small).
std::vector<double> bruteForce(const std::vector<double>& Q, const std::vector<double>& q, int m) {
  // KKT: lambda_I = 0, (Q lambda - q)_A = 0 (G_A = 0), lambda_A <= 0, G = q - Q lambda >= 0 on I.
  for (unsigned mask = 0; mask < (1u << m); ++mask) {
    std::vector<int> A;
    for (int j = 0; j < m; ++j)
      if (mask & (1u << j)) A.push_back(j);
    const int na = static_cast<int>(A.size());
    std::vector<double> lambda(m, 0.0);
    if (na > 0) {
      Teuchos::SerialDenseMatrix<int, double> QA(na, na);
      Teuchos::SerialDenseMatrix<int, double> rhs(na, 1), x(na, 1);
      for (int a = 0; a < na; ++a) {
        rhs(a, 0) = q[A[a]];
        for (int b = 0; b < na; ++b) QA(a, b) = Q[A[a] * m + A[b]];
      }
      Teuchos::SerialDenseSolver<int, double> solver;
      solver.setMatrix(Teuchos::rcpFromRef(QA));
      solver.setVectors(Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(rhs));
      if (solver.solve() != 0) continue;
      for (int a = 0; a < na; ++a) lambda[A[a]] = x(a, 0);
    }
    bool ok = true;
    for (int j = 0; j < m; ++j) {
      double G = q[j];
      for (int k = 0; k < m; ++k) G -= Q[j * m + k] * lambda[k];
      if (lambda[j] > 1e-12 || G < -1e-12) ok = false;
    }
    if (ok) return lambda;
  }
  ADD_FAILURE() << "no KKT point found by enumeration";
  return {};
}

// (obstacle height, Schur preconditioner, Newton step solver)
class ContactQPTest : public ::testing::TestWithParam<std::tuple<double, std::string, std::string>> {};

/// The unit square of 8 x 8 cells, clamped on the left, contact on the right (4 segments), the
/// step matrix for k = 0.05 and a load that moves the body towards the obstacle u >= g.
struct PushedSquare {
  test::TestMesh tm{0.0, 1.0, 0.0, 1.0, 1, 1, 3};
  const mesh::Q1Mesh& m = tm.build();
  const std::vector<char> dir = m.nodesOnSegments(kLeft);
  const fem::Q1Assembler asmb{m, dir};
  const double k = 0.05;
  const RCP<CrsMatrix> A = asmb.assembleOperator(1.0, 0.5 * k * k, 1.0, 1.0);
  const fem::ContactCoupling B{m, kRight, fem::ContactCoupling::SegmentSize::TwoEdges, dir};
  const int ns = B.numSegments();
  Vector F{m.ownedMap()};
  PushedSquare() { asmb.assembleLoad(core::Expression("-x*(1 + y)", "test"), 0.0, 1.0, F); }
  /// Independent of the QP: u = A^{-1}(F - B lambda) by \p solver into \p u and G = B^T u - gbar.
  std::vector<double> gaps(solvers::LinearSolver& solver, const std::vector<double>& gbar,
                           const std::vector<double>& lambda, Vector& u) const {
    Vector rhs(m.ownedMap());
    rhs.assign(F);
    B.apply(lambda, rhs, -1.0, true);
    solver.solve(rhs, u);
    auto G = B.applyTranspose(u);
    for (int j = 0; j < ns; ++j) G[j] -= gbar[j];
    return G;
  }
};

TEST_P(ContactQPTest, MatchesEnumeratedSolutionAndSatisfiesKKT) {
  const double obstacleHeight = std::get<0>(GetParam());
  const PushedSquare square;
  const auto& m = square.m;
  const auto& A = square.A;
  const auto& B = square.B;
  const auto& F = square.F;
  const double k = square.k;
  const int ns = square.ns;
  ASSERT_EQ(ns, 4);
  solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters()));
  solver.setOperator(A, 1.0);
  // The obstacle is tilted, so some segments touch.
  const auto gbar = B.weightedObstacle(core::Expression(std::to_string(obstacleHeight) + " + 0.3*y", "test"), 0.0);

  // Dense reference.
  std::vector<double> q(ns);
  Vector uf(m.ownedMap());
  solver.solve(F, uf);
  const auto Btuf = B.applyTranspose(uf);
  for (int j = 0; j < ns; ++j) q[j] = Btuf[j] - gbar[j];
  const auto Q = denseSchurComplement(solver, B, *m.ownedMap());
  const auto reference = bruteForce(Q, q, ns);
  ASSERT_EQ(static_cast<int>(reference.size()), ns);
  int activeRef = 0;
  for (double l : reference) activeRef += l < 0;

  core::ParameterList cp;
  cp.set("KKT Tolerance", 1e-12);
  cp.set("Schur Preconditioner", std::get<1>(GetParam()));
  // Cached columns are used from the second solve on; with room for one column only, steps with
  // more active segments fall back to CG.
  const std::string newton = std::get<2>(GetParam());
  cp.set("Newton Step Solver", newton == "CG" ? "CG" : "cached columns");
  if (newton == "cached columns, room for one") cp.set("Cached Columns", 1);
  solvers::ContactQP qp(validated(solvers::ContactQP::getValidParameters(), cp), 1.0);
  std::vector<double> coarseQ;  // "strip + coarse": the far field from a coarser mesh (4 x 4 cells)
  if (std::get<1>(GetParam()) == "strip + coarse") {
    test::TestMesh coarse(0.0, 1.0, 0.0, 1.0, 1, 1, 2, Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF)));
    const auto& mc = coarse.build();
    const fem::Q1Assembler coarseAssembler(mc, mc.nodesOnSegments(kLeft));
    const solvers::CoarseSchurCorrection correction(coarseAssembler.assembleOperator(1.0, 0.5 * k * k, 1.0, 1.0));
    coarseQ = correction.schur(B.coarseLoads(coarseAssembler), ns);
    ASSERT_EQ(coarseQ.size(), static_cast<size_t>(ns * ns));
  }
  qp.setSystem(*A, B, 1.0, coarseQ);
  for (int pass = 0; pass < 3; ++pass) {  // cold start, warm start from the solution, cold again
    const bool warm = pass == 1;
    std::vector<double> lambda = warm ? reference : std::vector<double>(ns, 0.0), G;
    Vector u(m.ownedMap());
    const auto res = qp.solve(solver, B, F, gbar, lambda, u, G);
    double scale = 0;
    for (double l : reference) scale = std::max(scale, std::abs(l));
    for (int j = 0; j < ns; ++j) EXPECT_NEAR(lambda[j], reference[j], 1e-7 * std::max(scale, 1e-300)) << "segment " << j;
    EXPECT_EQ(res.active, activeRef);
    if (warm) { EXPECT_EQ(res.activeSetIterations, 1); }
    // Independent KKT check.
    Vector u2(m.ownedMap());
    const auto G2 = square.gaps(solver, gbar, lambda, u2);
    for (int j = 0; j < ns; ++j) {
      const double gap = G2[j] / B.segmentLength()[j];
      EXPECT_LE(lambda[j], 0.0);
      EXPECT_GE(gap, -1e-9);
      EXPECT_LE(std::abs(lambda[j] * gap), 1e-9 * std::max(scale, 1e-300));
      EXPECT_NEAR(G[j], G2[j], 1e-9 * B.segmentLength()[j]);
    }
    u2.update(-1.0, u, 1.0);
    EXPECT_LT(u2.normInf(), 1e-8);
  }
  // The cases cover no contact, partial contact and full contact.
  if (obstacleHeight < -10) { EXPECT_EQ(activeRef, 0); }
  if (obstacleHeight == -1.6) { EXPECT_TRUE(activeRef > 0 && activeRef < ns); }
  if (obstacleHeight > -1) { EXPECT_EQ(activeRef, ns); }
}

// Whatever the KKT tolerance, down to the smallest allowed, a result that is returned satisfies the
// KKT conditions to that tolerance (checked on u = A^{-1}(F - B lambda) solved here to rounding),
// on either Newton step solver; the QP may instead stop with a SolverError.
TEST(ContactQP, ReturnsOnlyResultsWithinItsTolerance) {
  const PushedSquare square;
  const auto& m = square.m;
  const auto& B = square.B;
  const auto& F = square.F;
  const int ns = square.ns;
  core::ParameterList linear;
  linear.set("Relative Tolerance", 1e-15);
  solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters(), linear));
  solver.setOperator(square.A, 1.0);
  const auto gbar = B.weightedObstacle(core::Expression("-1.6 + 0.3*y", "test"), 0.0);
  // (KKT Tolerance, length scale): the gap tolerance is their product. The last asks for 1e-17 of
  // gaps of order 1, below rounding: no result meets it, so none may be returned.
  for (const char* newton : {"CG", "cached columns"})
    for (const auto& [tol, length] : {std::pair{1e-9, 1.0}, {1e-12, 1.0}, {1e-14, 1.0}, {1e-14, 1e-3}}) {
      core::ParameterList cp;
      cp.set("KKT Tolerance", tol);
      cp.set("Newton Step Solver", newton);
      solvers::ContactQP qp(validated(solvers::ContactQP::getValidParameters(), cp), length);
      qp.setSystem(*square.A, B, 1.0, {});
      const double gapTolerance = tol * length;
      for (int pass = 0; pass < 2; ++pass) {  // cached columns serve from the second solve on
        std::ostringstream what;
        what << newton << ", gap tolerance " << gapTolerance << ", pass " << pass;
        std::vector<double> lambda(ns, 0.0), G;
        Vector u(m.ownedMap());
        try {
          qp.solve(solver, B, F, gbar, lambda, u, G);
        } catch (const core::SolverError&) {
          EXPECT_LT(gapTolerance, 1e-10) << what.str() << ": a tolerance well above rounding must be met";
          continue;
        }
        const auto G2 = square.gaps(solver, gbar, lambda, u);
        for (int j = 0; j < ns; ++j) {
          const double gap = G2[j] / B.segmentLength()[j];
          EXPECT_LE(lambda[j], 0.0) << what.str() << ", segment " << j;
          EXPECT_GE(gap, -gapTolerance) << what.str() << ", segment " << j;
          if (lambda[j] < 0) { EXPECT_LE(std::abs(gap), gapTolerance) << what.str() << ", segment " << j; }
        }
      }
    }
}

// The active set's gaps are closed to a tenth of the gap tolerance (CG on Q_AA stops only at
// |G_j| <= 0.1 tol |E_j|, the margin its history reports), so recomputed from u = A^{-1}(F - B lambda)
// (solved here to relative 1e-15) every segment with lambda_j < 0 has |G_j| / |E_j| <= 0.1 tol, over
// partial and full contact, each CG preconditioner and tolerances 1e-4 ... 1e-9. At tol the margin
// would be lost: the lumped and unpreconditioned CG then stop at 0.12 to 0.18 tol.
TEST(ContactQP, ActiveGapsMeetATenthOfTheTolerance) {
  const PushedSquare square;
  const auto& B = square.B;
  const int ns = square.ns;
  core::ParameterList linear;
  linear.set("Relative Tolerance", 1e-15);
  solvers::LinearSolver solver(validated(solvers::LinearSolver::getValidParameters(), linear));
  solver.setOperator(square.A, 1.0);
  for (const char* obstacle : {"-1.6 + 0.3*y", "-1.3 + 0.3*y", "-0.5 + 0.3*y"}) {
    const auto gbar = B.weightedObstacle(core::Expression(obstacle, "test"), 0.0);
    for (const char* preconditioner : {"strip", "lumped", "none"})
      for (double tol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9}) {
        core::ParameterList cp;
        cp.set("KKT Tolerance", tol);
        cp.set("Schur Preconditioner", preconditioner);
        cp.set("Newton Step Solver", "CG");
        solvers::ContactQP qp(validated(solvers::ContactQP::getValidParameters(), cp), 1.0);
        qp.setSystem(*square.A, B, 1.0, {});
        std::vector<double> lambda(ns, 0.0), G;
        Vector u(square.m.ownedMap());
        qp.solve(solver, B, square.F, gbar, lambda, u, G);
        const auto G2 = square.gaps(solver, gbar, lambda, u);
        for (int j = 0; j < ns; ++j)
          if (lambda[j] < 0) {
            EXPECT_LE(std::abs(G2[j]) / B.segmentLength()[j], 0.1 * tol * (1 + 1e-6))
                << obstacle << ", " << preconditioner << ", tolerance " << tol << ", segment " << j;
          }
      }
  }
}

TEST(CoarseSchurCorrection, IsTheGramMatrixOfTheCoarseLoads) {
  // Q_c = L^T A_c^{-1} L is the Gram matrix of the loads l_j in the inner product of A_c^{-1} (SPD):
  // Q_c,jj = |l_j|^2 > 0 and Cauchy-Schwarz Q_c,ij^2 <= Q_c,ii Q_c,jj, and each entry is l_i^T x_j
  // for x_j = A_c^{-1} l_j solved here independently (Jacobi CG to 1e-14), diagonal included.
  const PushedSquare square;  // 8 x 8 cells, contact on the right: 4 segments (H = 2h)
  const int ns = square.ns;
  ASSERT_EQ(ns, 4);
  test::TestMesh coarse(0.0, 1.0, 0.0, 1.0, 1, 1, 2, Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF)));
  const auto& mc = coarse.build();
  const fem::Q1Assembler ca(mc, mc.nodesOnSegments(kLeft));
  const auto Ac = ca.assembleOperator(1.0, 0.5 * square.k * square.k, 1.0, 1.0);
  const auto loads = square.B.coarseLoads(ca);
  const auto Q = solvers::CoarseSchurCorrection(Ac).schur(loads, ns);
  ASSERT_EQ(Q.size(), static_cast<size_t>(ns * ns));
  const size_t n = Ac->getRowMap()->getNodeNumElements();
  std::vector<Vector> l, x;
  for (int j = 0; j < ns; ++j) {
    l.emplace_back(Ac->getRowMap());
    x.emplace_back(Ac->getRowMap());
    {
      auto h = l[j].getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (size_t i = 0; i < n; ++i) h(i, 0) = loads[j * n + i];
    }
    x[j].putScalar(0.0);
    solvers::solveJacobiCG(*Ac, l[j], x[j], 1e-14, 1000);
  }
  for (int i = 0; i < ns; ++i) {
    EXPECT_GT(Q[i * ns + i], 0.0) << i;
    for (int j = 0; j < ns; ++j) {
      EXPECT_LE(Q[i * ns + j] * Q[i * ns + j], Q[i * ns + i] * Q[j * ns + j] * (1 + 1e-12)) << i << "," << j;
      EXPECT_NEAR(Q[i * ns + j], l[i].dot(x[j]), 1e-10 * std::sqrt(l[i].dot(x[i]) * l[j].dot(x[j]))) << i << "," << j;
    }
  }
}

// Obstacles: far away (no contact), partly touching, pushing everywhere.
INSTANTIATE_TEST_SUITE_P(Obstacles, ContactQPTest,
                         ::testing::Combine(::testing::Values(-100.0, -1.6, -1.3, -0.5),
                                            ::testing::Values("strip", "strip + coarse", "lumped", "none"),
                                            ::testing::Values("CG", "cached columns", "cached columns, room for one")));

}  // namespace
