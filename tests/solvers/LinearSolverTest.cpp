// A^{-1} by Belos with each preconditioner: the same solution to the relative tolerance, on 1 and
// 2 ranks, and MueLu needs fewer iterations than Jacobi when the Courant number is large.
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/fem/Q1Assembler.hpp"

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
    solvers::LinearSolver solver(p);
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
  solvers::LinearSolver autoSolver(p);
  autoSolver.setOperator(A, 1.0);
  EXPECT_EQ(autoSolver.preconditioner(), "Jacobi");
  autoSolver.setOperator(A, 20.0);
  EXPECT_EQ(autoSolver.preconditioner(), "MueLu");
}

#include <Tpetra_MultiVector.hpp>

#include "signorini/fem/ElasticityAssembler.hpp"

// Elasticity: MueLu with two equations per node and the rigid body modes as near-nullspace needs a
// bounded number of CG iterations as the mesh is refined at a fixed time step (the Courant number
// c k / h grows from 8 to 32), and no more than MueLu without that information.
TEST(LinearSolver, ElasticityMueLuIterationsStayBoundedUnderRefinement) {
  const double E = 1.0, nu = 0.33, rho = 1.0;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double c = std::sqrt((lambda + 2 * mu) / rho), k = 1.0 / c, beta = 0.5;
  std::vector<int> withModes, without;
  for (int level = 3; level <= 5; ++level) {
    test::TestMesh tm(0.0, 4.0, 0.0, 1.0, 4, 1, level);  // a bar, clamped at x = 0
    const auto& m = tm.build();
    const auto clamped = m.nodesOnSegments(1u << 0);
    std::vector<char> dir(2 * clamped.size());
    for (size_t i = 0; i < clamped.size(); ++i) dir[2 * i] = dir[2 * i + 1] = clamped[i];
    fem::ElasticityAssembler asmb(m, dir, lambda, mu);
    auto A = asmb.assembleOperator(1.0, beta * k * k, rho);
    Vector b(asmb.ownedMap()), r(asmb.ownedMap());
    asmb.addBoundaryLoad(core::ExpressionList("0, -1", "test", 2), 0.0, 1u << 3, 1.0, b);  // push down on top
    for (bool modes : {true, false}) {
      core::ParameterList p;
      p.set("Preconditioner", "MueLu");
      core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
      solvers::LinearSolver solver(p);
      if (modes) solver.setNearNullspace(asmb.rigidBodyModes(), 2);
      solver.setOperator(A, c * k / m.hMin());
      Vector x(asmb.ownedMap());
      const int its = solver.solve(b, x);
      A->apply(x, r);
      r.update(1.0, b, -1.0);
      EXPECT_LE(r.norm2(), 1e-10 * b.norm2());
      (modes ? withModes : without).push_back(its);
      RecordProperty(std::string(modes ? "iterations_level" : "iterations_scalar_level") + std::to_string(level), its);
    }
  }
  EXPECT_LE(withModes.back(), 1.5 * withModes.front() + 2) << "iterations grow with refinement";
  EXPECT_LE(withModes.back(), without.back());
}

TEST(LinearSolver, EverySupportedMethodSolvesTheStepSystemAndOthersAreRefused) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 4, 4, 2);  // 16 x 16 cells
  const auto& m = tm.build();
  fem::Q1Assembler asmb(m, m.nodesOnSegments(1u << 0));
  auto A = asmb.assembleOperator(1.0, 0.01, 1.0, 1.0);
  Vector b(m.ownedMap()), r(m.ownedMap());
  asmb.assembleLoad(core::Expression("sin(3*x) + y", "test"), 0.0, 1.0, b);
  auto spellings = solvers::LinearSolver::supportedMethods();
  spellings.push_back("pseudo block cg");  // any case, Belos' alias
  for (const auto& spelling : spellings) {
    core::ParameterList p;
    p.set("Method", spelling);
    p.set("Preconditioner", "Jacobi");
    core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
    EXPECT_EQ(solvers::LinearSolver::checkParameters(p, false), "") << spelling;
    solvers::LinearSolver solver(p);
    solver.setOperator(A, 1.0);
    Vector x(m.ownedMap());
    solver.solve(b, x);
    A->apply(x, r);
    r.update(1.0, b, -1.0);
    EXPECT_LE(r.norm2(), 1e-10 * b.norm2()) << spelling;
  }
  EXPECT_EQ(solvers::LinearSolver::canonicalMethod("Transpose-Free QMR"), "TFQMR");
  for (const std::string refused : {"BICGSTAB", "FLEXIBLE GMRES", "LSQR", "CGG", ""}) {
    core::ParameterList p;
    p.set("Method", refused);
    core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
    EXPECT_THROW(solvers::LinearSolver::checkParameters(p, false), core::UserError) << refused;
  }
}
