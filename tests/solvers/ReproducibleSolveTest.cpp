// Partition-independent linear algebra (JacobiCG.hpp: applyCanonical, solveReproducibleJacobiCG,
// and LinearSolver under core::reproducibleArithmetic()): one global SPD system, its entries a
// formula of the global indices, distributed over the ranks in three ways (blocks in index order,
// round robin, everything on the last rank in reversed local order, so that every row is stored in
// another order). The matrix apply and the solution must have the same bits in all three; the
// ordinary Jacobi CG of the same system differs between them (the control).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"
#include "signorini/core/ReproducibleSum.hpp"

using namespace signorini;

namespace {

constexpr GO kSide = 60;  // grid of kSide x kSide unknowns

/// Symmetric coupling weight of grid neighbours p < q (a formula of the pair only).
double weight(GO p, GO q) { return 1.0 + 0.3 * std::sin(0.7 * static_cast<double>(p) + 0.013 * static_cast<double>(q)); }

RCP<const Map> distribution(int how, const RCP<const Comm>& comm) {
  const int rank = comm->getRank(), size = comm->getSize();
  std::vector<GO> mine;
  const GO n = kSide * kSide;
  for (GO g = 0; g < n; ++g) {
    const bool take = how == 0 ? static_cast<int>(g * size / n) == rank : how == 1 ? static_cast<int>(g % size) == rank : rank == size - 1;
    if (take) mine.push_back(g);
  }
  if (how == 2) std::reverse(mine.begin(), mine.end());
  return Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), mine.data(), mine.size(), 0, comm));
}

RCP<CrsMatrix> matrix(const RCP<const Map>& map) {
  auto A = Teuchos::rcp(new CrsMatrix(map, 5));
  for (LO i = 0; i < static_cast<LO>(map->getNodeNumElements()); ++i) {
    const GO g = map->getGlobalElement(i), r = g / kSide, c = g % kSide;
    std::vector<GO> cols;
    std::vector<double> vals;
    double diagonal = 0.01 * (1.0 + std::cos(static_cast<double>(g)));
    auto couple = [&](GO h) {
      const double w = weight(std::min(g, h), std::max(g, h));
      cols.push_back(h), vals.push_back(-w), diagonal += 1.0001 * w;
    };
    if (c > 0) couple(g - 1);
    if (c + 1 < kSide) couple(g + 1);
    if (r > 0) couple(g - kSide);
    if (r + 1 < kSide) couple(g + kSide);
    cols.push_back(g), vals.push_back(diagonal);
    A->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

void fill(Vector& v, double (*f)(GO)) {
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = f(v.getMap()->getGlobalElement(static_cast<LO>(i)));
}

/// The global vector indexed by global index (on every rank).
std::vector<double> gathered(const Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> values(h.extent(0));
  std::vector<long long> ids(h.extent(0));
  for (size_t i = 0; i < values.size(); ++i) values[i] = h(i, 0), ids[i] = v.getMap()->getGlobalElement(static_cast<LO>(i));
  const MPI_Comm comm = core::rawMpiComm(*v.getMap()->getComm());
  const auto allValues = core::allGatherv(comm, values);
  const auto allIds = core::allGatherv(comm, ids);
  std::vector<double> out(allValues.size());
  for (size_t i = 0; i < out.size(); ++i) out[allIds[i]] = allValues[i];
  return out;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

double rightHandSide(GO g) { return std::sin(0.05 * static_cast<double>(g)) + 1e-3 * static_cast<double>(g % 7); }
double initialGuess(GO g) { return 0.1 * std::cos(0.3 * static_cast<double>(g)); }

struct Solved {
  std::vector<double> applied, solution;
  int iterations = 0;
};

Solved solve(int how, bool reproducible, bool throughLinearSolver = false) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const test::ReproducibleScope scope(reproducible);
  const auto map = distribution(how, comm);
  const auto A = matrix(map);
  Vector b(map), x(map), y(map);
  fill(b, rightHandSide);
  fill(x, initialGuess);
  Solved s;
  if (reproducible) {
    core::applyCanonical(*A, x, y);
    s.applied = gathered(y);
  }
  if (throughLinearSolver) {
    Teuchos::ParameterList params = solvers::LinearSolver::getValidParameters();
    params.set("Preconditioner", "auto");  // Jacobi under reproducible arithmetic
    params.set("Relative Tolerance", 1e-12);
    params.set("Maximum Iterations", 5000);
    solvers::LinearSolver solver(params);
    solver.setOperator(A, 0.0);
    s.iterations = solver.solve(b, x);
  } else {
    s.iterations = solvers::solveJacobiCG(*A, b, x, 1e-12, 5000);
  }
  s.solution = gathered(x);
  return s;
}

}  // namespace

TEST(ReproducibleSolve, ApplyAndSolutionHaveTheSameBitsForEveryDistribution) {
  const Solved first = solve(0, true);
  EXPECT_GT(first.iterations, 20);
  for (int how = 1; how < 3; ++how) {
    const Solved other = solve(how, true);
    EXPECT_TRUE(sameBits(first.applied, other.applied)) << "apply, distribution " << how;
    EXPECT_TRUE(sameBits(first.solution, other.solution)) << "solution, distribution " << how;
    EXPECT_EQ(first.iterations, other.iterations);
  }
  // The LinearSolver (Belos otherwise; "auto" would pick MueLu above Courant number 5) takes the
  // same path: the same bits.
  const Solved viaSolver = solve(2, true, true);
  EXPECT_EQ(viaSolver.iterations, first.iterations);
  EXPECT_TRUE(sameBits(viaSolver.solution, first.solution));
  // Control: the ordinary Jacobi CG gets other bits in some distribution.
  const Solved plain0 = solve(0, false), plain2 = solve(2, false);
  EXPECT_FALSE(sameBits(plain0.solution, plain2.solution));
}

TEST(ReproducibleSolve, SolvesToTheTolerance) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto map = distribution(0, comm);
  const auto A = matrix(map);
  Vector b(map), x(map), r(map);
  fill(b, rightHandSide);
  x.putScalar(0.0);
  const int its = solvers::solveReproducibleJacobiCG(*A, b, x, 1e-10, 5000);
  EXPECT_GT(its, 0);
  A->apply(x, r);
  r.update(1.0, b, -1.0);
  EXPECT_LE(r.norm2(), 1e-9 * b.norm2());
  b.putScalar(0.0);
  EXPECT_EQ(solvers::solveReproducibleJacobiCG(*A, b, x, 1e-10, 5000), 0);
  EXPECT_EQ(x.norm2(), 0.0);
  fill(b, rightHandSide);
  x.putScalar(0.0);
  EXPECT_THROW(solvers::solveReproducibleJacobiCG(*A, b, x, 1e-10, 3), core::SolverError);
}
