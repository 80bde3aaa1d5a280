// Assembly facts: mass sums to the area, stiffness annihilates constants and gives the exact
// energy of linear fields, patch tests on meshes with hanging nodes, error norms of a known error.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <tuple>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/fem/Q1Kernels.hpp"

using namespace signorini;

namespace {

/// Nodal interpolant of f(x, y) on the owned nodes.
void interpolate(const mesh::Q1Mesh& m, const std::function<double(double, double)>& f, Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = f(m.nodeCoords()[i][0], m.nodeCoords()[i][1]);
}

/// The assembler of \p problem's type on \p m, its Dirichlet unknowns from the problem.
std::unique_ptr<fem::Assembler> assemblerFor(const mesh::Q1Mesh& m, const fem::ProblemData& problem) {
  if (problem.components() == 1) return std::make_unique<fem::Q1Assembler>(m, m.nodesOnSegments(problem.dirichletMask));
  return std::make_unique<fem::ElasticityAssembler>(m, fem::ElasticityAssembler::dirichletUnknowns(m, problem),
                                                    problem.lameLambda, problem.lameMu);
}

struct Case {
  bool hanging;
  int level;
};

class AssemblyTest : public ::testing::TestWithParam<Case> {};

TEST_P(AssemblyTest, MassSumsToAreaAndStiffnessIsExactOnLinearFields) {
  test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, GetParam().level);
  if (GetParam().hanging) tm.refineCorner();
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  const double area = 2.0 * 1.5;
  EXPECT_NEAR(asmb.area(), area, 1e-13);

  auto M = asmb.assembleOperator(1.0, 0.0, 1.0, 1.0);
  auto K = asmb.assembleOperator(0.0, 1.0, 1.0, 1.0);
  Vector one(m.ownedMap()), tmp(m.ownedMap()), u(m.ownedMap());
  one.putScalar(1.0);
  M->apply(one, tmp);
  EXPECT_NEAR(tmp.dot(one), area, 1e-12);  // 1^T M 1 = |Omega|
  K->apply(one, tmp);
  EXPECT_LT(tmp.normInf(), 1e-12);  // K 1 = 0

  // u = 3x - 2y: u^T K u = |grad u|^2 |Omega| = 13 |Omega| (the space contains u exactly,
  // hanging nodes included).
  interpolate(m, [](double x, double y) { return 3 * x - 2 * y; }, u);
  K->apply(u, tmp);
  EXPECT_NEAR(tmp.dot(u), 13.0 * area, 1e-10);
  // and u^T M u = int u^2
  M->apply(u, tmp);
  const double exactL2sq = [] {  // int_0^2 int_{-1}^{0.5} (3x - 2y)^2 dy dx
    auto F = [](double x, double y) { return -std::pow(3 * x - 2 * y, 3) / 6.0; };  // d/dy = (3x-2y)^2
    auto G = [&](double x) { return F(x, 0.5) - F(x, -1.0); };
    double s = 0;  // Simpson in x is exact for this cubic-in-x integrand
    s = (2.0 / 6.0) * (G(0) + 4 * G(1) + G(2));
    return s;
  }();
  EXPECT_NEAR(tmp.dot(u), exactL2sq, 1e-10);
}

TEST_P(AssemblyTest, PatchTestWithHangingNodes) {
  // -Laplace u = 0 with u linear on the boundary: the discrete solution is u itself.
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, GetParam().level);
  if (GetParam().hanging) tm.refineCorner();
  const auto& m = tm.build();
  const unsigned all = 0xF;
  auto dir = m.nodesOnSegments(all);
  fem::Q1Assembler asmb(m, dir);
  auto K = asmb.assembleOperator(0.0, 1.0, 1.0, 1.0);
  fem::Q1Assembler free(m, std::vector<char>(dir.size(), 0));
  auto Kfree = free.assembleOperator(0.0, 1.0, 1.0, 1.0);
  Vector exact(m.ownedMap()), b(m.ownedMap()), r(m.ownedMap());
  interpolate(m, [](double x, double y) { return 1 + 2 * x - 5 * y; }, exact);
  // b = -K_free,interior-boundary * u_boundary, i.e. the lifted right-hand side; with the
  // identity rows b_i = u_i on the boundary.
  Vector ub(m.ownedMap());
  {
    auto e = exact.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto h = ub.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = dir[i] ? e(i, 0) : 0.0;
  }
  Kfree->apply(ub, b);
  b.scale(-1.0);
  {
    auto h = b.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto e = exact.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (size_t i = 0; i < h.extent(0); ++i)
      if (dir[i]) h(i, 0) = e(i, 0);
  }
  // The exact field satisfies K u = b: residual check (no solver needed).
  K->apply(exact, r);
  r.update(-1.0, b, 1.0);
  EXPECT_LT(r.normInf(), 1e-12);
}

TEST_P(AssemblyTest, LoadOfConstantSumsToArea) {
  test::TestMesh tm(0.0, 1.0, 0.0, 3.0, 1, 3, GetParam().level);
  if (GetParam().hanging) tm.refineCorner();
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  Vector b(m.ownedMap()), one(m.ownedMap());
  one.putScalar(1.0);
  asmb.assembleLoad(core::Expression("2", "test"), 0.0, 1.0, b);
  EXPECT_NEAR(b.dot(one), 6.0, 1e-12);
  // Load of a linear function integrates it exactly: int_Omega y = 4.5
  asmb.assembleLoad(core::Expression("y", "test"), 0.0, 1.0, b);
  EXPECT_NEAR(b.dot(one), 4.5, 1e-12);
  // Boundary load of q = 1 on the right side sums to its length 3.
  b.putScalar(0.0);
  asmb.addBoundaryLoad(core::Expression("1", "test"), 0.0, 1u << 1, 1.0, b);
  EXPECT_NEAR(b.dot(one), 3.0, 1e-12);
  // How a varying boundary load is split between an edge's end nodes: q = y on the right side
  // against v = y (its interpolant) gives int_0^3 y^2 dy = 9 (the 2-point Gauss rule is exact for
  // the quadratic integrand; with each edge's end nodes swapped it is less), and against 1
  // int_0^3 y dy = 4.5.
  b.putScalar(0.0);
  asmb.addBoundaryLoad(core::Expression("y", "test"), 0.0, 1u << 1, 1.0, b);
  Vector v(m.ownedMap());
  interpolate(m, [](double, double y) { return y; }, v);
  EXPECT_NEAR(b.dot(v), 9.0, 1e-12);
  EXPECT_NEAR(b.dot(one), 4.5, 1e-12);
}

TEST_P(AssemblyTest, InterpolantHasZeroErrorForBilinearField) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, GetParam().level);
  if (GetParam().hanging) tm.refineCorner();
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  Vector u(m.ownedMap()), uo(m.overlapMap());
  // Bilinear: in the space also with hanging nodes (along every cell face it is linear).
  interpolate(m, [](double x, double y) { return 2 + x - y + 0.7 * x * y; }, u);
  const auto [l2, h1] = asmb.errorNorms(u, core::Expression("2 + x - y + 0.7*x*y", "test"), 0.0);
  EXPECT_LT(l2, 1e-13);
  EXPECT_LT(h1, 1e-8);  // gradient of the exact field by central differences
  asmb.toOverlap(u, uo);
  EXPECT_NEAR(asmb.evaluate(uo, 0.3, 0.7), 2 + 0.3 - 0.7 + 0.7 * 0.3 * 0.7, 1e-13);
  EXPECT_TRUE(std::isnan(asmb.evaluate(uo, 1.5, 0.7)));
}

TEST_P(AssemblyTest, ErrorNormsOfAKnownErrorAreExact) {
  // errorNorms returns the L2 norm and the H1 seminorm of u_h - u (Q1Assembler.hpp). On the unit
  // square with the error e = -x y (or x y):
  //   ||e||_0^2 = int_0^1 int_0^1 x^2 y^2 = 1/3 * 1/3 = 1/9,          L2 = 1/3;
  //   |e|_1^2  = int_0^1 int_0^1 (y^2 + x^2) = 1/3 + 1/3 = 2/3,      H1 seminorm = sqrt(2/3).
  // 3 x 3 Gauss points integrate x^2 y^2 exactly on every rectangle (degree 2 <= 5 per direction);
  // the exact gradient comes from central differences, exact for x y up to rounding (h_min 1e-6 steps).
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, GetParam().level);
  if (GetParam().hanging) tm.refineCorner();
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  Vector u(m.ownedMap());
  // u_h = 0 against x y.
  u.putScalar(0.0);
  auto [l2, h1] = asmb.errorNorms(u, core::Expression("x*y", "test"), 0.0);
  EXPECT_NEAR(l2, 1.0 / 3, 1e-14);
  EXPECT_NEAR(h1, std::sqrt(2.0 / 3), 1e-8);
  // u_h = the interpolant of 2 + x - y (in the space, hanging nodes included) against 2 + x - y + x y:
  // the error is -x y again, through the hanging nodes' weights.
  interpolate(m, [](double x, double y) { return 2 + x - y; }, u);
  std::tie(l2, h1) = asmb.errorNorms(u, core::Expression("2 + x - y + x*y", "test"), 0.0);
  EXPECT_NEAR(l2, 1.0 / 3, 1e-14);
  EXPECT_NEAR(h1, std::sqrt(2.0 / 3), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Meshes, AssemblyTest,
                         ::testing::Values(Case{false, 1}, Case{false, 3}, Case{true, 1}, Case{true, 2}));

}  // namespace

// Loads accumulate: two boundary loads and an accumulated body load add up (1, 2, 3 ranks).
TEST(Q1Kernels, ParallelogramMatricesEqualGaussQuadrature) {
  // Closed forms against 2x2 Gauss (exact for these integrands on affine cells): a rectangle, a
  // sheared and a rotated parallelogram; a trapezoid is not a parallelogram.
  const double cells[3][4][2] = {{{0, 0}, {2, 0}, {0, 0.5}, {2, 0.5}},
                                 {{1, 1}, {2, 1.2}, {1.3, 2}, {2.3, 2.2}},
                                 {{0, 0}, {0.6, 0.8}, {-0.4, 0.3}, {0.2, 1.1}}};
  for (const auto& X : cells) {
    ASSERT_TRUE(fem::isParallelogram(X));
    double M[4][4], K[4][4], Mg[4][4] = {}, Kg[4][4] = {};
    fem::q1ParallelogramMatrices(X, M, K);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        double N[4], gx[4], gy[4];
        const double w = fem::kGauss2Weight * fem::kGauss2Weight *
                         fem::q1Gradients(X, fem::gauss2Point(i), fem::gauss2Point(j), N, gx, gy);
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) Mg[a][b] += w * N[a] * N[b], Kg[a][b] += w * (gx[a] * gx[b] + gy[a] * gy[b]);
      }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        EXPECT_NEAR(M[a][b], Mg[a][b], 1e-14) << a << "," << b;
        EXPECT_NEAR(K[a][b], Kg[a][b], 1e-13) << a << "," << b;
      }
  }
  const double trapezoid[4][2] = {{0, 0}, {1, 0}, {0.2, 1}, {0.8, 1}};
  EXPECT_FALSE(fem::isParallelogram(trapezoid));
}

// Lumped boundary mass (DESIGN 1.6): every mass coupling with a flagged unknown, in its own row and
// in its neighbours' rows, moves to the row's diagonal, so row sums are those of the consistent mass
// and the matrix stays symmetric; couplings between unflagged unknowns are untouched. Both
// assemblers, with hanging nodes, on 1-3 ranks, in ordinary and reproducible arithmetic (on several
// ranks the latter sums the shared rows' cell contributions by EntrySums, a second code path).
TEST(LumpedBoundaryMass, CouplingsOfFlaggedUnknownsMoveToTheDiagonal) {
  for (const bool reproducible : {false, true})
    for (const char* type : {"scalar wave", "plane strain elasticity"}) {
      const test::ReproducibleScope scope(reproducible);
      test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, 2);
      tm.refineCorner();
      const auto& m = tm.build();
      auto p = fem::ProblemData::getValidParameters();
      p.set("Type", std::string(type));
      p.set("Density", 2.0);
      p.set("Dirichlet Segments", std::string("left"));
      const fem::ProblemData problem(p, *tm.segments);
      const auto asmb = assemblerFor(m, problem);
      const auto lump = asmb->unknownsOnSegments(1u << 1);  // the right side
      const auto consistent = asmb->assembleSystem(1.0, 0.0, problem);
      const auto lumped = asmb->assembleSystem(1.0, 0.0, problem, lump);
      // Flags and Dirichlet flags of every column: owned values imported to the column map.
      const auto colMap = lumped->getColMap();
      Vector flagOwned(asmb->ownedMap()), dirOwned(asmb->ownedMap()), flagCol(colMap), dirCol(colMap);
      {
        auto f = flagOwned.getLocalViewHost(Tpetra::Access::OverwriteAll);
        auto d = dirOwned.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (size_t i = 0; i < f.extent(0); ++i) {
          const LO o = asmb->overlapMap()->getLocalElement(asmb->ownedMap()->getGlobalElement(static_cast<LO>(i)));
          f(i, 0) = lump[o];
          d(i, 0) = asmb->dirichletFlags()[o];
        }
      }
      Tpetra::Import<LO, GO, Node> toCols(asmb->ownedMap(), colMap);
      flagCol.doImport(flagOwned, toCols, Tpetra::INSERT);
      dirCol.doImport(dirOwned, toCols, Tpetra::INSERT);
      auto fc = flagCol.getLocalViewHost(Tpetra::Access::ReadOnly);
      auto dc = dirCol.getLocalViewHost(Tpetra::Access::ReadOnly);
      const auto entries = [](const CrsMatrix& A, GO row) {
        std::map<GO, double> e;
        const size_t n = A.getNumEntriesInGlobalRow(row);
        typename CrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
        typename CrsMatrix::nonconst_values_host_view_type vals("vals", n);
        size_t got = 0;
        A.getGlobalRowCopy(row, cols, vals, got);
        for (size_t k = 0; k < got; ++k) e[cols(k)] += vals(k);
        return e;
      };
      int flaggedRows = 0, neighbourRows = 0;
      for (size_t i = 0; i < asmb->ownedMap()->getNodeNumElements(); ++i) {
        const GO row = asmb->ownedMap()->getGlobalElement(static_cast<LO>(i));
        const LO rowCol = colMap->getLocalElement(row);
        if (dc(rowCol, 0) != 0) continue;  // identity rows
        const auto cons = entries(*consistent, row), lumpedRow = entries(*lumped, row);
        double consSum = 0, lumpedSum = 0;
        for (const auto& [c, v] : cons) consSum += v;
        for (const auto& [c, v] : lumpedRow) lumpedSum += v;
        EXPECT_NEAR(lumpedSum, consSum, 1e-14) << type << ", row " << row;
        const bool rowFlagged = fc(rowCol, 0) != 0;
        bool touchesFlagged = false;
        for (const auto& [c, v] : cons) {
          if (c == row) continue;
          const bool colFlagged = fc(colMap->getLocalElement(c), 0) != 0;
          const double got = lumpedRow.count(c) ? lumpedRow.at(c) : 0.0;
          if (rowFlagged || colFlagged) {
            EXPECT_EQ(got, 0.0) << type << ", coupling " << row << "-" << c;
            touchesFlagged |= colFlagged && v != 0;
          } else {
            EXPECT_EQ(got, v) << type << ", coupling " << row << "-" << c;
          }
        }
        flaggedRows += rowFlagged;
        neighbourRows += !rowFlagged && touchesFlagged;
      }
      // The case is not empty: flagged rows and unflagged rows coupled to them (over all ranks).
      int local[2] = {flaggedRows, neighbourRows}, global[2] = {0, 0};
      Teuchos::reduceAll(*m.comm(), Teuchos::REDUCE_SUM, 2, local, global);
      EXPECT_GT(global[0], 0) << type;
      EXPECT_GT(global[1], 0) << type;
    }
}

TEST(Q1AssemblerLoads, LoadsAccumulate) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, std::vector<char>(m.overlapMap()->getNodeNumElements(), 0));
  Vector b(m.ownedMap()), one(m.ownedMap());
  one.putScalar(1.0);
  const core::Expression q("2", "test"), f("3", "test");
  asmb.assembleLoad(f, 0.0, 1.0, b);                     // 3 |Omega| = 3
  asmb.addBoundaryLoad(q, 0.0, 1u << 0, 1.0, b);         // + 2 |left| = 2
  asmb.addBoundaryLoad(q, 0.0, 1u << 3, 1.0, b);         // + 2 |top| = 2
  asmb.assembleLoad(f, 0.0, 0.5, b, /*accumulate=*/true);  // + 1.5
  EXPECT_NEAR(b.dot(one), 8.5, 1e-12);
}

// A = M + c K formed from the values of M and K equals assembling A directly (up to rounding), with
// Dirichlet rows, lumped boundary mass and hanging nodes, for both assemblers and on 1-3 ranks.
TEST(StepMatrices, EqualSeparateAssembly) {
  for (const char* type : {"scalar wave", "plane strain elasticity"})
    for (bool hanging : {false, true}) {
      test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, 2);
      if (hanging) tm.refineCorner();
      const auto& m = tm.build();
      auto p = fem::ProblemData::getValidParameters();
      p.set("Type", std::string(type));
      p.set("Density", 2.0);
      if (std::string(type) == "scalar wave")
        p.set("Stiffness", 3.0);
      else
        p.set("Young's Modulus", 5.0);
      p.set("Dirichlet Segments", std::string("left"));
      const fem::ProblemData problem(p, *tm.segments);
      const auto asmb = assemblerFor(m, problem);
      const auto lump = asmb->unknownsOnSegments(1u << 1);  // the right side
      const double c = 0.37;
      const auto s = asmb->assembleStepMatrices(c, problem, lump);
      // A was formed from M's and K's values (not assembled a third time): it shares their graph.
      EXPECT_EQ(s.A->getLocalMatrixDevice().graph.entries.data(), s.K->getLocalMatrixDevice().graph.entries.data());
      const auto A = asmb->assembleSystem(1.0, c, problem, lump);
      const auto M = asmb->assembleSystem(1.0, 0.0, problem, lump);
      const auto K = asmb->assembleSystem(0.0, 1.0, problem);
      Vector x(asmb->ownedMap()), y(asmb->ownedMap()), z(asmb->ownedMap());
      x.randomize();
      for (const auto& [mine, reference] : {std::pair{s.A, A}, std::pair{s.M, M}, std::pair{s.K, K}}) {
        mine->apply(x, y);
        reference->apply(x, z);
        z.update(-1.0, y, 1.0);
        EXPECT_LT(z.normInf(), 1e-14 * y.normInf()) << type << (hanging ? ", hanging" : "");
      }
      // Dirichlet rows are identity rows: (A x)_i = x_i there.
      s.A->apply(x, y);
      auto xh = x.getLocalViewHost(Tpetra::Access::ReadOnly);
      auto yh = y.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (size_t i = 0; i < xh.extent(0); ++i)
        if (asmb->dirichletFlags()[i]) { EXPECT_EQ(yh(i, 0), xh(i, 0)); }
    }
}

// Only a body force or Neumann data that is not the constant 0 (on a Neumann segment) or an obstacle
// that moves can supply energy (the warning on a cycle's energy gain relies on it).
TEST(ProblemData, SuppliesEnergyOnlyThroughLoadsOrAMovingObstacle) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 0);
  const auto supplies = [&](const std::vector<std::pair<const char*, const char*>>& settings) {
    auto p = fem::ProblemData::getValidParameters();
    p.set("Type", std::string("plane strain elasticity"));
    p.set("Contact Segments", std::string("right"));
    p.set("Obstacle", std::string("-0.1"));
    for (const auto& [key, value] : settings) p.set(key, std::string(value));
    return fem::ProblemData(p, *tm.segments).suppliesEnergy();
  };
  EXPECT_FALSE(supplies({}));
  EXPECT_FALSE(supplies({{"Body Force", "0, 0"}, {"Initial Velocity", "0, -1"}, {"Obstacle", "-0.1 - x*x"}}));
  EXPECT_FALSE(supplies({{"Neumann Data", "0, -1"}}));  // without Neumann segments: no effect
  EXPECT_TRUE(supplies({{"Body Force", "0, -9.81"}}));
  EXPECT_TRUE(supplies({{"Body Force", "0, 0*x"}}));  // not seen to be 0: counted as a load
  EXPECT_TRUE(supplies({{"Neumann Data", "0, -1"}, {"Neumann Segments", "left"}}));
  EXPECT_FALSE(supplies({{"Neumann Data", "0, 0"}, {"Neumann Segments", "left"}}));
  EXPECT_TRUE(supplies({{"Obstacle", "-0.1 + 0.01 * t"}}));
}
