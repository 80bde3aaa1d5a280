// The lean Jacobi CG (s1, the transfer's mass solve) solves K + M (hanging nodes, Dirichlet rows)
// to its tolerance on any number of ranks and reports non-convergence.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"

using namespace signorini;

namespace {

struct System {
  test::TestMesh tm{0.0, 1.0, 0.0, 1.0, 3, 2, 2};
  std::unique_ptr<fem::Q1Assembler> assembler;
  RCP<CrsMatrix> A;
  System() {
    tm.refineCorner();
    const auto& mesh = tm.build();
    assembler = std::make_unique<fem::Q1Assembler>(mesh, mesh.nodesOnSegments(1u << tm.segments->index("left", "test")));
    A = assembler->assembleOperator(1.0, 1.0, 1.0, 1.0);
  }
};

}  // namespace

TEST(JacobiCG, ReachesTheRelativeTolerance) {
  System s;
  const auto map = s.A->getRangeMap();
  Vector exact(map), b(map), x(map), r(map);
  exact.randomize();
  s.assembler->zeroDirichlet(exact);
  s.A->apply(exact, b);
  x.putScalar(0.0);
  const int its = solvers::solveJacobiCG(*s.A, b, x, 1e-10, 1000);
  EXPECT_GT(its, 0);
  s.A->apply(x, r);
  r.update(1.0, b, -1.0);
  // The true residual, not only the recursive one: the two differ by rounding only, so the bound is
  // the tolerance itself with 1% for that drift (a solver stopping at 3 times the tolerance fails).
  EXPECT_LE(r.norm2(), 1.01e-10 * b.norm2());
  x.update(-1.0, exact, 1.0);
  EXPECT_LE(x.norm2(), 1e-6 * exact.norm2());
  // It stops at the first iteration that meets the tolerance: one iteration fewer does not.
  x.putScalar(0.0);
  EXPECT_THROW(solvers::solveJacobiCG(*s.A, b, x, 1e-10, its - 1), core::SolverError);
}

TEST(JacobiCG, ZeroRightHandSideNeedsNoIteration) {  // x = 0 whatever the initial guess
  System s;
  Vector b(s.A->getRangeMap()), x(s.A->getRangeMap());
  b.putScalar(0.0);
  x.putScalar(1.0);
  EXPECT_EQ(solvers::solveJacobiCG(*s.A, b, x, 1e-4, 10), 0);
  EXPECT_EQ(x.norm2(), 0.0);
}

TEST(JacobiCG, ThrowsWithoutConvergence) {
  System s;
  Vector b(s.A->getRangeMap()), x(s.A->getRangeMap());
  b.randomize();
  s.assembler->zeroDirichlet(b);
  x.putScalar(0.0);
  EXPECT_THROW(solvers::solveJacobiCG(*s.A, b, x, 1e-12, 1), core::SolverError);
}

// Several right-hand sides at once (the projection's fields): each field gets exactly the bits of its
// own solve, also when the fields stop after different numbers of iterations (a zero right-hand
// side, an exact initial guess, a field scaled by 1e6) and across groups (five fields: 3 + 2). In
// ordinary arithmetic, and in reproducible arithmetic on a matrix with a registered row order
// (shared sweeps) and on one without (exact row sums, columns one after the other).
namespace {

enum class Arithmetic { ordinary, registeredOrder, exactRowSums };

void expectFieldsTogetherEqualTheirOwnSolves(Arithmetic arithmetic) {
  const bool reproducible = arithmetic != Arithmetic::ordinary;
  // The assembler registers the order when it assembles under reproducible arithmetic.
  std::unique_ptr<System> s;
  {
    const test::ReproducibleScope assembly(arithmetic == Arithmetic::registeredOrder);
    s = std::make_unique<System>();
  }
  const test::ReproducibleScope scope(reproducible);
  if (reproducible) { ASSERT_EQ(core::hasCanonicalRowOrder(*s->A), arithmetic == Arithmetic::registeredOrder); }
  const auto map = s->A->getRangeMap();
  constexpr int kFields = 5;
  std::vector<RCP<Vector>> b, x, single;
  for (int f = 0; f < kFields; ++f) {
    b.push_back(rcp(new Vector(map)));
    x.push_back(rcp(new Vector(map)));
    b[f]->randomize();
    x[f]->randomize();
    s->assembler->zeroDirichlet(*b[f]);
    s->assembler->zeroDirichlet(*x[f]);
  }
  b[1]->putScalar(0.0);
  b[2]->scale(1e6);
  s->A->apply(*x[3], *b[3]);  // x[3] already solves its system (to rounding, far below the tolerance)
  {  // x[4] is near the solution of its system: fewer iterations than field 0
    Vector solution(*x[4], Teuchos::Copy);
    s->A->apply(solution, *b[4]);
    x[4]->update(1.0, solution, 1e-5);
  }
  std::vector<int> singleIterations;
  for (int f = 0; f < kFields; ++f) {
    single.push_back(rcp(new Vector(*x[f], Teuchos::Copy)));
    singleIterations.push_back(solvers::solveJacobiCG(*s->A, *b[f], *single[f], 1e-10, 1000));
  }
  EXPECT_EQ(singleIterations[1], 0);
  EXPECT_EQ(singleIterations[3], 0);
  EXPECT_GT(singleIterations[4], 0);
  EXPECT_GT(singleIterations[0], 0);
  EXPECT_LT(singleIterations[4], singleIterations[0]);  // the fields stop in different iterations
  std::vector<const Vector*> bs;
  std::vector<Vector*> xs;
  for (int f = 0; f < kFields; ++f) bs.push_back(b[f].get()), xs.push_back(x[f].get());
  const auto iterations = solvers::solveJacobiCG(*s->A, bs, xs, 1e-10, 1000);
  EXPECT_EQ(iterations, singleIterations);
  for (int f = 0; f < kFields; ++f) {
    const auto together = x[f]->getData(), alone = single[f]->getData();
    for (long i = 0; i < together.size(); ++i) ASSERT_EQ(together[i], alone[i]) << "field " << f << ", entry " << i;
  }
  // Too few iterations: the group throws as each solve alone does; a nan in a right-hand side
  // iterates and throws too (it is not taken as converged).
  for (auto& guess : x) guess->putScalar(0.0);
  EXPECT_THROW(solvers::solveJacobiCG(*s->A, bs, xs, 1e-10, 1), core::SolverError);
  b[0]->putScalar(std::nan(""));
  EXPECT_THROW(solvers::solveJacobiCG(*s->A, *b[0], *x[0], 1e-10, 50), core::SolverError);
  EXPECT_THROW(solvers::solveJacobiCG(*s->A, bs, xs, 1e-10, 50), core::SolverError);
}

}  // namespace

TEST(JacobiCG, FieldsSolvedTogetherEqualTheirOwnSolvesBitForBit) {
  expectFieldsTogetherEqualTheirOwnSolves(Arithmetic::ordinary);
}

TEST(JacobiCG, FieldsSolvedTogetherInReproducibleArithmeticEqualTheirOwnSolvesBitForBit) {
  expectFieldsTogetherEqualTheirOwnSolves(Arithmetic::registeredOrder);
  expectFieldsTogetherEqualTheirOwnSolves(Arithmetic::exactRowSums);
}
