// The Q1 numbering: the direct numbering of one tree (on 1-3 ranks) against p4est lnodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include <mpi.h>
#include <Teuchos_CommHelpers.hpp>

#include <p4est_algorithms.h>

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

/// The direct numbering of \p tm's forest (one tree) against lnodes on the same partition;
/// \p acrossRanks: some hanging corner must depend on another rank's node.
void expectDirectNumberingEqualsLnodes(const test::TestMesh& tm, bool acrossRanks) {
  const auto comm = Tpetra::getDefaultComm();
  const mesh::Q1Mesh direct(*tm.forest, *tm.segments, comm);
  const mesh::Q1Mesh lnodes(*tm.forest, *tm.segments, comm, mesh::Q1Mesh::Numbering::lnodes);

  EXPECT_EQ(direct.numGlobalNodes(), lnodes.numGlobalNodes());
  auto sortedNodes = [](const mesh::Q1Mesh& m) {
    auto p = m.nodeCoords();
    std::sort(p.begin(), p.end());
    return p;
  };
  EXPECT_EQ(sortedNodes(direct), sortedNodes(lnodes));  // the same points (bit for bit: same mapping)
  EXPECT_EQ(direct.numbering(), mesh::Q1Mesh::Numbering::direct);  // the automatic choice for one tree
  EXPECT_EQ(lnodes.numbering(), mesh::Q1Mesh::Numbering::lnodes);
  const auto a = cornerTerms(direct), b = cornerTerms(lnodes);
  ASSERT_EQ(a.size(), b.size());
  int hanging = 0, hangingOnOthers = 0;  // hanging corners; of them, with an end node another rank owns
  int orientations = 0;  // bit per side of the fine cell the coarse face lies on: -x, +x, -y, +y
  const LO owned = static_cast<LO>(direct.ownedMap()->getNodeNumElements());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k], b[k]) << "cell " << k / 4 << " corner " << k % 4;
    if (a[k].size() != 2) continue;
    ++hanging;
    const LO e = static_cast<LO>(k / 4);
    const int c = static_cast<int>(k % 4);
    hangingOnOthers += direct.cornerDofsHost(e, c, 0) >= owned || direct.cornerDofsHost(e, c, 1) >= owned;
    // The coarse face through the hanging corner joins its two end nodes; the fine cell's centre
    // lies on one side of it.
    const auto& p = a[k][0].first;
    const auto& q = a[k][1].first;
    double centre[2] = {0, 0};
    for (int i = 0; i < 4; ++i)
      for (int d = 0; d < 2; ++d) centre[d] += 0.25 * direct.cornerCoordsHost(e, i, d);
    const int d = p[0] == q[0] ? 0 : 1;  // the face's normal direction
    orientations |= 1 << (2 * d + (centre[d] > p[d] ? 0 : 1));
  }
  int totals[2] = {hanging, hangingOnOthers}, global[2];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2, totals, global);
  EXPECT_GT(global[0], 16);
  int allOrientations = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_BOR, 1, &orientations, &allOrientations);
  EXPECT_EQ(allOrientations, 0xF) << "hanging corners on coarse faces of all four sides of a fine cell";
  if (acrossRanks) { EXPECT_GT(global[1], 0) << "no hanging corner depends on another rank's node"; }
  ASSERT_EQ(direct.boundaryEdges().size(), lnodes.boundaryEdges().size());
  for (size_t i = 0; i < direct.boundaryEdges().size(); ++i) {
    const auto &p = direct.boundaryEdges()[i], &q = lnodes.boundaryEdges()[i];
    EXPECT_EQ(p.segments, q.segments);
    for (int k = 0; k < 2; ++k) EXPECT_EQ(direct.nodeCoords()[p.node[k]], lnodes.nodeCoords()[q.node[k]]);
  }

  // The global ids: owned first and contiguous by rank; over all ranks, one point per global id
  // and one global id per point.
  const auto& overlap = *direct.overlapMap();
  const GO firstOwned = direct.ownedMap()->getMinGlobalIndex();
  std::vector<double> mine(3 * overlap.getNodeNumElements());
  for (LO i = 0; i < static_cast<LO>(overlap.getNodeNumElements()); ++i) {
    if (i < owned) { EXPECT_EQ(overlap.getGlobalElement(i), firstOwned + i); }
    mine[3 * i] = static_cast<double>(overlap.getGlobalElement(i));
    mine[3 * i + 1] = direct.nodeCoords()[i][0];
    mine[3 * i + 2] = direct.nodeCoords()[i][1];
  }
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(comm->getSize()), offsets(comm->getSize() + 1, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < comm->getSize(); ++r) offsets[r + 1] = offsets[r] + counts[r];
  const int total = offsets.back();
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::map<double, Point> pointOf;
  std::map<Point, double> gidOf;
  for (int j = 0; j + 2 < total; j += 3) {
    const Point x{all[j + 1], all[j + 2]};
    EXPECT_TRUE(pointOf.emplace(all[j], x).first->second == x) << "global id " << all[j] << " names two points";
    EXPECT_EQ(gidOf.emplace(x, all[j]).first->second, all[j]) << "a point with two global ids";
  }
  EXPECT_EQ(static_cast<GO>(pointOf.size()), direct.numGlobalNodes());
}

TEST(Q1Mesh, DirectNumberingOfOneTreeEqualsLnodes) {
  test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 1, 1, 2);
  ASSERT_EQ(tm.forest->p4est()->connectivity->num_trees, 1);
  tm.refineGraded();
  tm.forest->partition();  // the graded cells spread over the ranks: hanging faces across rank boundaries
  expectDirectNumberingEqualsLnodes(tm, Tpetra::getDefaultComm()->getSize() > 1);
}

TEST(Q1Mesh, DirectNumberingOnAnUnevenPartitionWithAnEmptyRank) {
  const int size = Tpetra::getDefaultComm()->getSize();
  if (size == 1) GTEST_SKIP() << "needs several ranks";
  test::TestMesh tm(0.0, 2.0, 0.0, 1.0, 1, 1, 2);
  tm.refineGraded();
  p4est_t* p4est = tm.forest->p4est();
  // The last rank gets no cell; of the others each gets twice the previous one's share (on 2 ranks
  // the first rank gets every cell).
  std::vector<p4est_locidx_t> counts(size, 0);
  const auto total = static_cast<p4est_locidx_t>(p4est->global_num_quadrants);
  p4est_locidx_t weights = 0, given = 0;
  for (int r = 0; r + 1 < size; ++r) weights += 1 << r;
  for (int r = 0; r + 1 < size; ++r) given += counts[r] = r + 2 < size ? total * (1 << r) / weights : total - given;
  p4est_partition_given(p4est, counts.data());
  ASSERT_EQ(p4est->local_num_quadrants, counts[p4est->mpirank]);
  expectDirectNumberingEqualsLnodes(tm, size > 2);  // on 2 ranks every cell is on the first
}

}  // namespace
