// The Q1 numbering: the direct numbering of one tree on one rank against p4est lnodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "../TestMesh.hpp"

using namespace signorini;

namespace {

using Point = std::array<double, 2>;

/// Every cell corner as the sorted coordinates of the nodes it depends on, with their weights.
std::vector<std::vector<std::pair<Point, double>>> cornerTerms(const mesh::Q1Mesh& m) {
  std::vector<std::vector<std::pair<Point, double>>> out;
  for (LO e = 0; e < m.numLocalCells(); ++e)
    for (int c = 0; c < 4; ++c) {
      std::vector<std::pair<Point, double>> terms;
      for (int k = 0; k < 2; ++k)
        if (m.cornerDofsHost(e, c, k) >= 0)
          terms.push_back({m.nodeCoords()[m.cornerDofsHost(e, c, k)], m.cornerWeightsHost(e, c, k)});
      std::sort(terms.begin(), terms.end());
      out.push_back(terms);
    }
  return out;
}

TEST(Q1Mesh, DirectNumberingOfOneTreeEqualsLnodes) {
  if (Tpetra::getDefaultComm()->getSize() > 1) GTEST_SKIP() << "the direct numbering serves one rank";
  test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 1, 1, 2);
  ASSERT_EQ(tm.forest->p4est()->connectivity->num_trees, 1);
  tm.refineGraded();
  const mesh::Q1Mesh direct(*tm.forest, *tm.segments, Tpetra::getDefaultComm());
  const mesh::Q1Mesh lnodes(*tm.forest, *tm.segments, Tpetra::getDefaultComm(), mesh::Q1Mesh::Numbering::lnodes);

  EXPECT_EQ(direct.numGlobalNodes(), lnodes.numGlobalNodes());
  auto sortedNodes = [](const mesh::Q1Mesh& m) {
    auto p = m.nodeCoords();
    std::sort(p.begin(), p.end());
    return p;
  };
  EXPECT_EQ(sortedNodes(direct), sortedNodes(lnodes));  // the same points (bit for bit: same mapping)
  const auto a = cornerTerms(direct), b = cornerTerms(lnodes);
  ASSERT_EQ(a.size(), b.size());
  int hanging = 0;
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k], b[k]) << "cell " << k / 4 << " corner " << k % 4;
    hanging += a[k].size() == 2;
  }
  EXPECT_GT(hanging, 16);
  ASSERT_EQ(direct.boundaryEdges().size(), lnodes.boundaryEdges().size());
  for (size_t i = 0; i < direct.boundaryEdges().size(); ++i) {
    const auto &p = direct.boundaryEdges()[i], &q = lnodes.boundaryEdges()[i];
    EXPECT_EQ(p.segments, q.segments);
    for (int k = 0; k < 2; ++k) EXPECT_EQ(direct.nodeCoords()[p.node[k]], lnodes.nodeCoords()[q.node[k]]);
  }
}

}  // namespace
