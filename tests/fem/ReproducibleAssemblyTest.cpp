// Partition-independent assembly (EntrySums under core::reproducibleArithmetic()): the mass and
// stiffness matrices, a combined operator with lumped mass on a boundary, and body and boundary
// loads, assembled on a graded mesh with hanging nodes distributed over all ranks, have exactly
// the bits of the same assembly on one rank (the same forest, built on MPI_COMM_SELF on every
// rank). Entries are matched through the nodes' coordinates (dyadic, so exact). Likewise the L2
// projection's right-hand sides between two graded meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/fem/MeshTransfer.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"
#include "signorini/core/ReproducibleSum.hpp"

using namespace signorini;

namespace {

using Point = std::pair<double, double>;

/// One discretisation of the graded test mesh on \p comm.
struct Discretisation {
  test::TestMesh tm;
  const mesh::Q1Mesh* mesh;
  std::unique_ptr<fem::Q1Assembler> assembler;
  const mesh::BoundarySegments* segments;
  /// \p oneTree: the domain as one tree (the direct Q1 numbering on any number of ranks), else 3 x 2 trees.
  explicit Discretisation(const RCP<const Comm>& comm, bool oneTree = false)
      : tm(0.0, 1.5, 0.0, 1.0, oneTree ? 1 : 3, oneTree ? 1 : 2, oneTree ? 4 : 2, comm) {
    test::refineAt(*tm.forest, 0.4, 0.6, 3);
    test::refineAt(*tm.forest, 0.999, 0.001, 2);
    tm.forest->balance();
    tm.forest->partition();
    mesh = &tm.build();
    segments = tm.segments.get();
    assembler = std::make_unique<fem::Q1Assembler>(*mesh, mesh->nodesOnSegments(1u << segments->index("left", "test")));
  }
  /// Coordinates of the owned unknowns, imported to \p map.
  std::vector<Point> coordinates(const RCP<const Map>& map) const {
    Vector x(mesh->ownedMap()), y(mesh->ownedMap()), xm(map), ym(map);
    {
      auto xh = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
      auto yh = y.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (size_t i = 0; i < xh.extent(0); ++i) xh(i, 0) = mesh->nodeCoords()[i][0], yh(i, 0) = mesh->nodeCoords()[i][1];
    }
    Tpetra::Import<LO, GO, Node> importer(mesh->ownedMap(), map);
    xm.doImport(x, importer, Tpetra::INSERT);
    ym.doImport(y, importer, Tpetra::INSERT);
    auto xh = xm.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto yh = ym.getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<Point> points(xh.extent(0));
    for (size_t i = 0; i < points.size(); ++i) points[i] = {xh(i, 0), yh(i, 0)};
    return points;
  }
};

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Entries of A by (row point, column point).
std::map<std::pair<Point, Point>, double> entries(const Discretisation& d, const CrsMatrix& A) {
  const auto rows = d.coordinates(A.getRowMap()), columns = d.coordinates(A.getColMap());
  std::map<std::pair<Point, Point>, double> out;
  const auto local = A.getLocalMatrixHost();
  for (LO r = 0; r < local.numRows(); ++r)
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      out[{rows[r], columns[local.graph.entries(k)]}] = local.values(k);
  return out;
}

std::map<Point, double> entries(const Discretisation& d, const Vector& v) {
  const auto rows = d.coordinates(v.getMap());
  std::map<Point, double> out;
  auto h = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (size_t r = 0; r < h.extent(0); ++r) out[rows[r]] = h(r, 0);
  return out;
}

/// Number of this rank's entries of \p distributed whose bits differ from \p serial's (all present there).
template <class Key>
int differing(const std::map<Key, double>& distributed, const std::map<Key, double>& serial) {
  int count = 0;
  for (const auto& [key, value] : distributed) {
    const auto it = serial.find(key);
    if (it == serial.end() || !sameBits(value, it->second)) ++count;
  }
  return count;
}

struct Assembled {
  std::map<std::pair<Point, Point>, double> M, K, A;
  std::map<Point, double> load;
};

Assembled assemble(const Discretisation& d) {
  auto p = fem::ProblemData::getValidParameters();
  p.set("Density", 1.3);
  p.set("Stiffness", 0.7);
  const fem::ProblemData problem(p, *d.segments);
  const auto lump = d.mesh->nodesOnSegments(1u << d.segments->index("right", "test"));
  const auto [M, K] = d.assembler->assembleMassAndStiffness(problem, {});
  const auto A = d.assembler->assembleOperator(1.0, 1.7e-3, 1.3, 0.7, lump);
  Vector load(d.mesh->ownedMap());
  d.assembler->assembleLoad(core::Expression("sin(3*x) * cos(2*y) + x*y", "test"), 0.0, 1.0, load);
  d.assembler->addBoundaryLoad(core::Expression("exp(y)", "test"), 0.0, 1u << d.segments->index("top", "test"), 0.37, load);
  return {entries(d, *M), entries(d, *K), entries(d, *A), entries(d, load)};
}

int sumOverRanks(int local) {
  int global = 0;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

}  // namespace

namespace {
/// The reproducible assembly on all ranks has the bits of the one on one rank.
void expectTheBitsOfOneRank(bool oneTree) {
  const auto world = Tpetra::getDefaultComm();
  const RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const Discretisation distributed(world, oneTree), serial(self, oneTree);
  ASSERT_EQ(distributed.mesh->numbering() == mesh::Q1Mesh::Numbering::direct, oneTree);
  Assembled d, s;
  {
    const test::ReproducibleScope scope(true);
    d = assemble(distributed), s = assemble(serial);
  }
  EXPECT_GT(sumOverRanks(static_cast<int>(d.M.size())), 1000);
  EXPECT_EQ(sumOverRanks(differing(d.M, s.M)), 0);
  EXPECT_EQ(sumOverRanks(differing(d.K, s.K)), 0);
  EXPECT_EQ(sumOverRanks(differing(d.A, s.A)), 0);
  EXPECT_EQ(sumOverRanks(differing(d.load, s.load)), 0);
  // Every row has the serial row's length (no entry lost or added).
  EXPECT_EQ(sumOverRanks(static_cast<int>(d.A.size())), static_cast<int>(s.A.size()));
}
}  // namespace

TEST(ReproducibleAssembly, DistributedEntriesHaveTheBitsOfTheOneRankAssembly) { expectTheBitsOfOneRank(false); }

// One tree: the direct Q1 numbering on several ranks, with the matrices' own pattern exchange.
TEST(ReproducibleAssembly, OneTreeEntriesHaveTheBitsOfTheOneRankAssembly) { expectTheBitsOfOneRank(true); }

TEST(ReproducibleAssembly, SameValuesAsTheOrdinaryAssemblyToRounding) {
  const auto world = Tpetra::getDefaultComm();
  for (const bool oneTree : {false, true}) {
    const Discretisation d(world, oneTree);
    const Assembled plain = assemble(d);
    Assembled canonical;
    {
      const test::ReproducibleScope scope(true);
      canonical = assemble(d);
    }
    auto close = [](const auto& a, const auto& b) {
      int bad = 0;
      for (const auto& [key, value] : a) {
        const auto it = b.find(key);
        if (it == b.end() || std::fabs(value - it->second) > 1e-14 * (1.0 + std::fabs(value))) ++bad;
      }
      return bad;
    };
    EXPECT_EQ(sumOverRanks(close(plain.M, canonical.M)), 0);
    EXPECT_EQ(sumOverRanks(close(plain.K, canonical.K)), 0);
    EXPECT_EQ(sumOverRanks(close(plain.A, canonical.A)), 0);
    EXPECT_EQ(sumOverRanks(close(plain.load, canonical.load)), 0);
  }
}

TEST(ReproducibleAssembly, OrdinaryAssemblyDiffersOnSeveralRanks) {  // the control
  const auto world = Tpetra::getDefaultComm();
  const RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const Discretisation distributed(world), serial(self);
  const Assembled d = assemble(distributed), s = assemble(serial);
  const int differ = sumOverRanks(differing(d.M, s.M) + differing(d.K, s.K) + differing(d.A, s.A) + differing(d.load, s.load));
  if (world->getRank() == 0) std::cout << "ordinary assembly: " << differ << " entries differ from one rank's\n";
  if (world->getSize() > 1) { EXPECT_GT(differ, 0); }
}

namespace {

/// Rows of A x by row point, x(p) = a smooth function of mixed signs and magnitudes; \p canonical:
/// core::applyCanonical, otherwise Tpetra's apply (rows summed in the local column order).
std::map<Point, double> product(const Discretisation& d, const CrsMatrix& A, bool canonical) {
  Vector x(A.getDomainMap()), y(A.getRangeMap());
  {
    auto h = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < h.extent(0); ++i) {
      const auto& p = d.mesh->nodeCoords()[i];
      h(i, 0) = 1e3 * std::sin(7 * p[0] + 3 * p[1]) + 1.0 / (1.0 + p[0] * p[1]) - 0.5;
    }
  }
  if (canonical)
    core::applyCanonical(A, x, y);
  else
    A.apply(x, y);
  return entries(d, y);
}

}  // namespace

// The assembler registers a canonical row order (rows summed in the order of the column nodes'
// coordinates) for its matrices under reproducible arithmetic; M, K and the combined operator
// applied to one vector then give the one-rank result bit for bit, with plain ordered row sums.
TEST(ReproducibleAssembly, RegisteredRowOrderAppliesWithTheBitsOfOneRank) {
  const auto world = Tpetra::getDefaultComm();
  const RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const Discretisation distributed(world), serial(self);
  const test::ReproducibleScope scope(true);
  auto p = fem::ProblemData::getValidParameters();
  p.set("Density", 1.3);
  p.set("Stiffness", 0.7);
  const fem::ProblemData problem(p, *distributed.segments);
  const auto lump = [](const Discretisation& d) { return d.mesh->nodesOnSegments(1u << d.segments->index("right", "test")); };
  const auto [Md, Kd] = distributed.assembler->assembleMassAndStiffness(problem, {});
  const auto [Ms, Ks] = serial.assembler->assembleMassAndStiffness(problem, {});
  const auto Ad = distributed.assembler->assembleOperator(1.0, 1.7e-3, 1.3, 0.7, lump(distributed));
  const auto As = serial.assembler->assembleOperator(1.0, 1.7e-3, 1.3, 0.7, lump(serial));
  int differ = 0, ordinaryDiffer = 0, unregistered = 0, inaccurate = 0;
  for (const auto& [dm, sm] : {std::pair{Md, Ms}, std::pair{Kd, Ks}, std::pair{Ad, As}}) {
    unregistered += !core::hasCanonicalRowOrder(*dm) + !core::hasCanonicalRowOrder(*sm);
    const auto canonical = product(distributed, *dm, true), ordinary = product(distributed, *dm, false);
    differ += differing(canonical, product(serial, *sm, true));
    ordinaryDiffer += differing(ordinary, product(serial, *sm, false));
    for (const auto& [point, value] : canonical)  // the same product, to rounding (|x| <= 1e3)
      inaccurate += !(std::fabs(value - ordinary.at(point)) <= 1e-9);
  }
  EXPECT_EQ(sumOverRanks(unregistered), 0);
  EXPECT_EQ(sumOverRanks(inaccurate), 0);
  EXPECT_EQ(sumOverRanks(differ), 0);
  // The control: the same matrices summed in their local column order differ in some rows.
  const int ordinary = sumOverRanks(ordinaryDiffer);
  if (world->getRank() == 0) std::cout << "ordinary apply: " << ordinary << " rows differ from one rank's\n";
  if (world->getSize() > 1) { EXPECT_GT(ordinary, 0); }
}

namespace {

/// The L2 projection's right-hand sides (fem::MeshTransfer::projectionLoads) of a field moved from
/// one graded mesh to another (refined elsewhere; Dirichlet rows on the left), by node point.
std::map<Point, double> projectionLoads(const RCP<const Comm>& comm) {
  const Discretisation to(comm);
  test::TestMesh from(0.0, 1.5, 0.0, 1.0, 3, 2, 2, comm);
  test::refineAt(*from.forest, 0.7, 0.3, 3);
  test::refineAt(*from.forest, 0.2, 0.9, 2);
  from.forest->balance();
  from.forest->partition();
  const auto& oldMesh = from.build();
  Vector field(oldMesh.ownedMap());
  {
    auto h = field.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < h.extent(0); ++i) {
      const auto& p = oldMesh.nodeCoords()[i];
      h(i, 0) = 1e3 * std::sin(7 * p[0] + 3 * p[1]) + 1.0 / (1.0 + p[0] * p[1]) - 0.5;
    }
  }
  fem::MeshTransfer transfer(*from.forest, oldMesh, {&field}, *to.tm.forest, *to.mesh);
  return entries(to, *transfer.projectionLoads(*to.assembler)[0]);
}

}  // namespace

// The projection's right-hand sides on 1-3 ranks equal one rank's bit for bit under reproducible
// arithmetic (the rows of shared nodes by EntrySums, the others in cell order), and differ in
// ordinary arithmetic (the control).
TEST(ReproducibleAssembly, ProjectionLoadsHaveTheBitsOfOneRank) {
  const auto world = Tpetra::getDefaultComm();
  const RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  {
    const test::ReproducibleScope scope(true);
    const auto distributed = projectionLoads(world), serial = projectionLoads(self);
    EXPECT_GT(sumOverRanks(static_cast<int>(distributed.size())), 100);
    EXPECT_EQ(sumOverRanks(differing(distributed, serial)), 0);
  }
  const int ordinary = sumOverRanks(differing(projectionLoads(world), projectionLoads(self)));
  if (world->getRank() == 0) std::cout << "ordinary projection loads: " << ordinary << " rows differ from one rank's\n";
  if (world->getSize() > 1) { EXPECT_GT(ordinary, 0); }
}
