// Transfer between the meshes of two time steps: the L2 projection on the common refinement
// reproduces fields that lie in both spaces, is the identity for identical meshes, conserves the
// integral; nodal interpolation reproduces fields of the new space. Meshes partitioned differently;
// rectangles (exact element mass matrices), parallelograms in rotated frames and distorted cells
// (Gauss points). The Ritz projection's right-hand sides a(u_old, phi) equal K u for a field of
// both spaces (scalar and elasticity).
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "../QuadMeshes.hpp"
#include "../TestMesh.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/fem/MeshTransfer.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"

using namespace signorini;

namespace {

void interpolate(const mesh::Q1Mesh& m, const std::function<double(double, double)>& f, Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (size_t i = 0; i < h.extent(0); ++i) h(i, 0) = f(m.nodeCoords()[i][0], m.nodeCoords()[i][1]);
}

/// Solves M x = b on the new mesh (the L2 projection).
RCP<Vector> project(const fem::Q1Assembler& asmb, const Vector& b) {
  auto M = asmb.assembleOperator(1.0, 0.0, 1.0, 1.0);
  core::ParameterList p;
  p.set("Relative Tolerance", 1e-13);
  p.set("Preconditioner", "Jacobi");
  core::validateDeck(p, solvers::LinearSolver::getValidParameters(), "test");
  solvers::LinearSolver solver(p);
  solver.setOperator(M, 0.0);
  auto x = Teuchos::rcp(new Vector(b.getMap()));
  solver.solve(b, *x);
  return x;
}

double maxDiff(const Vector& a, const Vector& b) {
  Vector d(a, Teuchos::Copy);
  d.update(-1.0, b, 1.0);
  return d.normInf();
}

struct Pair {
  test::TestMesh coarseSide{0.0, 2.0, 0.0, 1.0, 2, 1, 2};
  test::TestMesh fineSide{0.0, 2.0, 0.0, 1.0, 2, 1, 2};
  Pair() { fineSide.refineCorner(); }
};

class MeshTransferTest : public ::testing::TestWithParam<bool> {};  // true: coarse -> fine

TEST_P(MeshTransferTest, ReproducesFieldsOfBothSpacesAndConservesTheIntegral) {
  Pair pair;
  auto& from = GetParam() ? pair.coarseSide : pair.fineSide;
  auto& to = GetParam() ? pair.fineSide : pair.coarseSide;
  const auto& oldMesh = from.build();
  const auto& newMesh = to.build();
  auto bilinear = [](double x, double y) { return 1 + 2 * x - 3 * y + 0.5 * x * y; };
  auto smooth = [](double x, double y) { return std::sin(3 * x) * std::cos(2 * y); };
  Vector a(oldMesh.ownedMap()), b(oldMesh.ownedMap()), expected(newMesh.ownedMap());
  interpolate(oldMesh, bilinear, a);
  interpolate(oldMesh, smooth, b);
  fem::MeshTransfer transfer(*from.forest, oldMesh, {&a, &b}, *to.forest, newMesh);
  fem::Q1Assembler newAsmb(newMesh, std::vector<char>(newMesh.overlapMap()->getNodeNumElements(), 0));
  const auto loads = transfer.projectionLoads(newAsmb);
  interpolate(newMesh, bilinear, expected);
  EXPECT_LT(maxDiff(*project(newAsmb, *loads[0]), expected), 1e-10);
  const auto nodal = transfer.interpolate();
  EXPECT_LT(maxDiff(*nodal[0], expected), 1e-13);
  // sum_i b_i = int u_old (the shape functions sum to one): the projection conserves the integral.
  fem::Q1Assembler oldAsmb(oldMesh, std::vector<char>(oldMesh.overlapMap()->getNodeNumElements(), 0));
  auto Mold = oldAsmb.assembleOperator(1.0, 0.0, 1.0, 1.0);
  Vector oneOld(oldMesh.ownedMap()), tmp(oldMesh.ownedMap()), oneNew(newMesh.ownedMap());
  oneOld.putScalar(1.0);
  oneNew.putScalar(1.0);
  Mold->apply(b, tmp);
  EXPECT_NEAR(loads[1]->dot(oneNew), tmp.dot(oneOld), 1e-13);
}

TEST(MeshTransfer, IsTheIdentityBetweenEqualMeshes) {
  test::TestMesh m1(0.0, 1.0, 0.0, 1.0, 2, 2, 2);
  m1.refineCorner();
  const auto& mesh = m1.build();
  mesh::Forest copy(*m1.forest);
  Vector u(mesh.ownedMap());
  interpolate(mesh, [](double x, double y) { return std::exp(x) * std::sin(5 * y); }, u);
  fem::MeshTransfer transfer(*m1.forest, mesh, {&u}, copy, mesh);
  fem::Q1Assembler asmb(mesh, std::vector<char>(mesh.overlapMap()->getNodeNumElements(), 0));
  EXPECT_LT(maxDiff(*project(asmb, *transfer.projectionLoads(asmb)[0]), u), 1e-10);
  EXPECT_LT(maxDiff(*transfer.interpolate()[0], u), 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Directions, MeshTransferTest, ::testing::Values(true, false));

enum class Coarse { Rectangles, RotatedSquares, Distorted };

class TransferOnQuadrilateralsTest : public ::testing::TestWithParam<Coarse> {};

/// The same one-level coarse mesh twice, the second with its lower-left corner refined twice.
std::pair<std::unique_ptr<test::TestMesh>, std::unique_ptr<test::TestMesh>> meshPair(Coarse kind) {
  const std::vector<std::pair<std::string, std::string>> sides = {{"all", "boundary"}};
  const auto coarse = kind == Coarse::Rectangles       ? nullptr
                      : kind == Coarse::RotatedSquares ? test::rotatedSquares()
                                                       : test::distortedSquare();
  auto side = [&]() {
    return coarse ? std::make_unique<test::TestMesh>(coarse, sides, 1)
                  : std::make_unique<test::TestMesh>(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  };
  auto coarseSide = side(), fineSide = side();
  fineSide->refineCorner();
  return {std::move(coarseSide), std::move(fineSide)};
}

TEST_P(TransferOnQuadrilateralsTest, ProjectionReproducesAFieldOfBothSpacesInBothDirections) {
  auto [coarseSide, fineSide] = meshPair(GetParam());
  const auto& coarseMesh = coarseSide->build();
  const auto& fineMesh = fineSide->build();
  Vector uc(coarseMesh.ownedMap());
  interpolate(coarseMesh, [](double x, double y) { return std::exp(x) * std::sin(3 * y) + x * y; }, uc);
  // Coarse -> fine: the field lies in the finer space, so its projection is its nodal interpolant.
  fem::MeshTransfer up(*coarseSide->forest, coarseMesh, {&uc}, *fineSide->forest, fineMesh);
  fem::Q1Assembler fineAsmb(fineMesh, std::vector<char>(fineMesh.overlapMap()->getNodeNumElements(), 0));
  const auto uf = up.interpolate()[0];
  EXPECT_LT(maxDiff(*project(fineAsmb, *up.projectionLoads(fineAsmb)[0]), *uf), 1e-10);
  // Fine -> coarse: the same field (now given on the fine mesh) comes back.
  fem::MeshTransfer down(*fineSide->forest, fineMesh, {uf.get()}, *coarseSide->forest, coarseMesh);
  fem::Q1Assembler coarseAsmb(coarseMesh, std::vector<char>(coarseMesh.overlapMap()->getNodeNumElements(), 0));
  EXPECT_LT(maxDiff(*project(coarseAsmb, *down.projectionLoads(coarseAsmb)[0]), uc), 1e-10);
}

TEST_P(TransferOnQuadrilateralsTest, StiffnessLoadsAreKTimesAFieldOfBothSpaces) {
  // a(u_old, phi_i e_c) on the common refinement: for u_old in the new space too it is (K u)_(i, c),
  // K the new mesh's stiffness as the assemblers build it (kappa = 3; elasticity's Lame parameters).
  // Coarse -> fine on every coarse mesh (each new cell lies in an old one: its own element matrix);
  // fine -> coarse where the element matrices are exact (parallelograms), since on distorted cells
  // the 2 x 2 Gauss rule of a cell is not the sum of its children's.
  auto [coarseSide, fineSide] = meshPair(GetParam());
  const auto& coarseMesh = coarseSide->build();
  const auto& fineMesh = fineSide->build();
  const std::array<std::function<double(double, double)>, 2> field = {
      [](double x, double y) { return std::exp(x) * std::sin(3 * y) + x * y; },
      [](double x, double y) { return std::cos(2 * x) - 0.5 * x * x * y; }};
  for (const char* type : {"scalar wave", "plane strain elasticity"}) {
    auto p = fem::ProblemData::getValidParameters();
    p.set("Type", std::string(type));
    if (std::string(type) == "scalar wave") p.set("Stiffness", 3.0);
    const fem::ProblemData problem(p, *coarseSide->segments);
    const int nc = problem.components();
    auto assemblerOn = [&](const mesh::Q1Mesh& m) -> std::unique_ptr<fem::Assembler> {
      const std::vector<char> none(nc * m.overlapMap()->getNodeNumElements(), 0);
      if (nc == 1) return std::make_unique<fem::Q1Assembler>(m, none);
      return std::make_unique<fem::ElasticityAssembler>(m, none, problem.lameLambda, problem.lameMu);
    };
    for (const bool up : {true, false}) {
      if (!up && GetParam() == Coarse::Distorted) continue;
      auto& from = up ? *coarseSide : *fineSide;
      auto& to = up ? *fineSide : *coarseSide;
      const auto& oldMesh = up ? coarseMesh : fineMesh;
      const auto& newMesh = up ? fineMesh : coarseMesh;
      // The components on the coarse mesh, interpolated to the old mesh (the same field on both).
      std::vector<Vector> onCoarse;
      for (int c = 0; c < nc; ++c) {
        onCoarse.emplace_back(coarseMesh.ownedMap());
        interpolate(coarseMesh, field[c], onCoarse.back());
      }
      std::vector<const Vector*> raw;
      for (const auto& v : onCoarse) raw.push_back(&v);
      fem::MeshTransfer toOld(*coarseSide->forest, coarseMesh, raw, *from.forest, oldMesh);
      const auto oldParts = toOld.interpolate();
      std::vector<const Vector*> oldRaw;
      for (const auto& v : oldParts) oldRaw.push_back(v.get());
      fem::MeshTransfer transfer(*from.forest, oldMesh, oldRaw, *to.forest, newMesh);
      const auto asmb = assemblerOn(newMesh);
      const auto loads = transfer.stiffnessLoads(
          [&](const double X[4][2], double Ke[8][8]) { asmb->elementStiffness(problem, X, Ke); }, 0, nc);
      // K u on the new mesh, u its nodal interpolant (the field lies in the new space).
      const auto nodal = transfer.interpolate();
      Vector u(asmb->ownedMap()), Ku(asmb->ownedMap());
      {
        auto uh = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (int c = 0; c < nc; ++c) {
          auto nh = nodal[c]->getLocalViewHost(Tpetra::Access::ReadOnly);
          for (size_t i = 0; i < nh.extent(0); ++i) uh(nc * i + c, 0) = nh(i, 0);
        }
      }
      asmb->assembleSystem(0.0, 1.0, problem)->apply(u, Ku);
      const double scale = Ku.normInf();
      ASSERT_GT(scale, 0.0);
      auto kh = Ku.getLocalViewHost(Tpetra::Access::ReadOnly);
      double largest = 0;
      for (int c = 0; c < nc; ++c) {
        auto bh = loads[c]->getLocalViewHost(Tpetra::Access::ReadOnly);
        for (size_t i = 0; i < bh.extent(0); ++i) largest = std::max(largest, std::abs(bh(i, 0) - kh(nc * i + c, 0)));
      }
      EXPECT_LT(largest, 1e-12 * scale) << type << (up ? ", coarse -> fine" : ", fine -> coarse");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CoarseMeshes, TransferOnQuadrilateralsTest,
                         ::testing::Values(Coarse::Rectangles, Coarse::RotatedSquares, Coarse::Distorted),
                         [](const auto& info) {
                           return std::string(info.param == Coarse::Rectangles       ? "rectangles"
                                              : info.param == Coarse::RotatedSquares ? "rotatedSquares"
                                                                                     : "distorted");
                         });

}  // namespace
