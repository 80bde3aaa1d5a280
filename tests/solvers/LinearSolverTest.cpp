// A^{-1} by Belos with each preconditioner: the same solution to the relative tolerance, on 1 and
// 2 ranks, and MueLu needs fewer iterations than Jacobi when the Courant number is large.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "Expression.hpp"
#include "LinearSolver.hpp"
#include "Q1Assembler.hpp"

using namespace signorini;

TEST(LinearSolver, PreconditionersAgreeAndMueLuWinsAtLargeCourantNumber) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 4, 4, 4);  // 64 x 64 cells
  const auto& m = tm.build();
  const auto dir = m.nodesOnSegments(1u << 0);
  fem::Q1Assembler asmb(m, dir);
  const double k = 20.0 / 64;  // Courant number c k / h = 20
  auto A = asmb.assembleOperator(1.0, 0.5 * k * k, 1.0, 1.0);
  Vector b(m.ownedMap()), r(m.ownedMap());
  asmb.assembleLoad(core::Expression("sin(3*x) + y", "test"), 0.0, 1.0, b);
  std::map<std::string, int> iterations;
  std::map<std::string, RCP<Vector>> solutions;
  for (const std::string prec : {"MueLu", "Jacobi", "none"}) {
    core::ParameterList p;
    p.set("Preconditioner", prec);
    core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
    solvers::LinearSolver solver(p, m.comm());
    solver.setOperator(A, 20.0);
    EXPECT_EQ(solver.preconditioner(), prec);
    auto x = Teuchos::rcp(new Vector(m.ownedMap()));
    iterations[prec] = solver.solve(b, *x);
    A->apply(*x, r);
    r.update(1.0, b, -1.0);
    EXPECT_LE(r.norm2(), 1e-10 * b.norm2()) << prec;
    solutions[prec] = x;
  }
  for (const std::string prec : {"Jacobi", "none"}) {
    Vector d(*solutions[prec], Teuchos::Copy);
    d.update(-1.0, *solutions["MueLu"], 1.0);
    EXPECT_LE(d.normInf(), 1e-7 * solutions["MueLu"]->normInf()) << prec;
  }
  EXPECT_LT(iterations["MueLu"], iterations["Jacobi"]);
  EXPECT_LT(iterations["Jacobi"], iterations["none"]);
  // "auto" picks Jacobi below the threshold Courant number and MueLu above it.
  core::ParameterList p;
  core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
  solvers::LinearSolver autoSolver(p, m.comm());
  autoSolver.setOperator(A, 1.0);
  EXPECT_EQ(autoSolver.preconditioner(), "Jacobi");
  autoSolver.setOperator(A, 20.0);
  EXPECT_EQ(autoSolver.preconditioner(), "MueLu");
}
