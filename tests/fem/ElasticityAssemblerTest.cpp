// Plane strain elasticity with vector Q1 elements: rigid body motions produce no stress, a linear
// displacement field passes the patch test (K u = the tractions of its constant stress, every node,
// hanging nodes included), the mass matrix holds the mass twice (two components), the error norms
// of a known error are exact.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "../TestMesh.hpp"
#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/core/Expression.hpp"

using namespace signorini;

namespace {

constexpr unsigned kLeft = 1, kRight = 2, kBottom = 4, kTop = 8;
constexpr double kLambda = 2.5, kMu = 1.25;

/// Owned nodal values of the field (fx, fy).
void interpolate(const fem::ElasticityAssembler& a, double (*fx)(double, double), double (*fy)(double, double),
                 Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto& X = a.mesh().nodeCoords();
  for (size_t i = 0; i < h.extent(0) / 2; ++i) {
    h(2 * i, 0) = fx(X[i][0], X[i][1]);
    h(2 * i + 1, 0) = fy(X[i][0], X[i][1]);
  }
}

class ElasticityAssembly : public ::testing::TestWithParam<bool> {};  // with hanging nodes or not

TEST_P(ElasticityAssembly, RigidBodyMotionsProduceNoStress) {
  test::TestMesh tm(-1.0, 2.0, 0.0, 1.0, 3, 1, 1);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  fem::ElasticityAssembler asmb(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), kLambda, kMu);
  const auto K = asmb.assembleOperator(0.0, 1.0, 1.0);
  const auto modes = asmb.rigidBodyModes();
  MultiVector Kr(asmb.ownedMap(), 3);
  K->apply(*modes, Kr);
  std::vector<double> norms(3), scale(3);
  Kr.normInf(norms);
  modes->normInf(scale);
  for (int k = 0; k < 3; ++k) EXPECT_LT(norms[k], 1e-12 * scale[k] * (kLambda + 2 * kMu)) << "mode " << k;
  // The modes span the rigid motions built here independently, (1, 0), (0, 1) and (-y, x): each is
  // a combination of the modes (least squares through the modes' 3 x 3 Gram matrix, residual at
  // rounding), so a wrong mode (e.g. a second translation) cannot pass K r = 0 alone.
  double G[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) G[i][j] = modes->getVector(i)->dot(*modes->getVector(j));
  const double det = G[0][0] * (G[1][1] * G[2][2] - G[1][2] * G[2][1]) -
                     G[0][1] * (G[1][0] * G[2][2] - G[1][2] * G[2][0]) +
                     G[0][2] * (G[1][0] * G[2][1] - G[1][1] * G[2][0]);
  ASSERT_GT(std::abs(det), 1e-8 * G[0][0] * G[1][1] * G[2][2]) << "the modes are not independent";
  double (*const motions[3][2])(double, double) = {
      {[](double, double) { return 1.0; }, [](double, double) { return 0.0; }},
      {[](double, double) { return 0.0; }, [](double, double) { return 1.0; }},
      {[](double, double y) { return -y; }, [](double x, double) { return x; }}};
  for (const auto& motion : motions) {
    Vector r(asmb.ownedMap()), residual(asmb.ownedMap());
    interpolate(asmb, motion[0], motion[1], r);
    double b[3], c[3];
    for (int i = 0; i < 3; ++i) b[i] = modes->getVector(i)->dot(r);
    for (int i = 0; i < 3; ++i) {  // Cramer's rule
      double M[3][3];
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) M[p][q] = q == i ? b[p] : G[p][q];
      c[i] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
              M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
             det;
    }
    residual.assign(r);
    for (int i = 0; i < 3; ++i) residual.update(-c[i], *modes->getVector(i), 1.0);
    EXPECT_LT(residual.norm2(), 1e-10 * r.norm2());
  }
  // The rotation's stress vanishes pointwise too.
  Vector rot(asmb.overlapMap());
  asmb.toOverlap(*modes->getVector(2), rot);
  for (LO e = 0; e < m.numLocalCells(); e += 3)
    for (double s : {0.0, 0.3, 1.0})
      for (double sxy : asmb.stressAt(rot, e, s, 1.0 - s)) EXPECT_NEAR(sxy, 0.0, 1e-12);
}

TEST_P(ElasticityAssembly, LinearFieldPassesThePatchTest) {
  test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, 1);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  fem::ElasticityAssembler asmb(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), kLambda, kMu);
  const auto K = asmb.assembleOperator(0.0, 1.0, 1.0);
  // u = (0.1 + 0.3 x - 0.2 y, -0.4 + 0.5 x + 0.7 y): constant strain and stress.
  const double a1 = 0.3, a2 = -0.2, b1 = 0.5, b2 = 0.7;
  const double sxx = kLambda * (a1 + b2) + 2 * kMu * a1, syy = kLambda * (a1 + b2) + 2 * kMu * b2,
               sxy = kMu * (a2 + b1);
  Vector u(asmb.ownedMap()), Ku(asmb.ownedMap()), F(asmb.ownedMap());
  interpolate(asmb, [](double x, double y) { return 0.1 + 0.3 * x - 0.2 * y; },
              [](double x, double y) { return -0.4 + 0.5 * x + 0.7 * y; }, u);
  K->apply(u, Ku);
  auto traction = [](double qx, double qy) {
    std::ostringstream text;  // every digit of the tractions
    text << std::setprecision(17) << qx << ", " << qy;
    return core::ExpressionList(text.str(), "test", 2);
  };
  F.putScalar(0.0);
  asmb.addBoundaryLoad(traction(-sxx, -sxy), 0.0, kLeft, 1.0, F);
  asmb.addBoundaryLoad(traction(sxx, sxy), 0.0, kRight, 1.0, F);
  asmb.addBoundaryLoad(traction(-sxy, -syy), 0.0, kBottom, 1.0, F);
  asmb.addBoundaryLoad(traction(sxy, syy), 0.0, kTop, 1.0, F);
  Ku.update(-1.0, F, 1.0);
  EXPECT_LT(Ku.normInf(), 1e-12 * F.normInf());
  // Energy: u^T K u = |Omega| sigma : eps.
  K->apply(u, Ku);
  const double area = 2.0 * 1.5;
  EXPECT_NEAR(Ku.dot(u), area * (sxx * a1 + syy * b2 + 2 * sxy * 0.5 * (a2 + b1)), 1e-10);
  // Stress at points of the cells.
  Vector uo(asmb.overlapMap());
  asmb.toOverlap(u, uo);
  for (LO e = 0; e < m.numLocalCells(); ++e) {
    const auto s = asmb.stressAt(uo, e, 0.25, 0.75);
    EXPECT_NEAR(s[0], sxx, 1e-12);
    EXPECT_NEAR(s[1], syy, 1e-12);
    EXPECT_NEAR(s[2], sxy, 1e-12);
  }
  // Point values reproduce the field.
  EXPECT_NEAR(asmb.evaluateComponent(uo, 1.3, 0.2, 0), 0.1 + 0.3 * 1.3 - 0.2 * 0.2, 1e-12);
  EXPECT_NEAR(asmb.evaluateComponent(uo, 1.3, 0.2, 1), -0.4 + 0.5 * 1.3 + 0.7 * 0.2, 1e-12);
}

TEST_P(ElasticityAssembly, CellCentreStressesOfUniformStrains) {
  // Two uniform strains whose plane strain stresses are known in closed form, on a mesh with
  // hanging nodes when the parameter says so: uniaxial strain u = (e x, 0) gives sigma_xx =
  // (lambda + 2 mu) e, sigma_yy = sigma_zz = lambda e, von Mises 2 mu |e|; simple shear
  // u = (g y, 0) gives sigma_xy = mu g, no normal stress, von Mises sqrt(3) mu |g|.
  test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, 1);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  fem::ElasticityAssembler asmb(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), kLambda, kMu);
  auto stressesOf = [&](double (*ux)(double, double)) {
    Vector u(asmb.ownedMap()), uo(asmb.overlapMap());
    interpolate(asmb, ux, [](double, double) { return 0.0; }, u);
    asmb.toOverlap(u, uo);
    return asmb.cellCentreStresses(uo);
  };
  const double e = -2e-3, g = 3e-3;
  const auto uniaxial = stressesOf([](double x, double) { return -2e-3 * x; });
  const auto shear = stressesOf([](double, double y) { return 3e-3 * y; });
  ASSERT_EQ(uniaxial[0].size(), static_cast<size_t>(m.numLocalCells()));
  const double tol = 1e-12 * (kLambda + 2 * kMu);
  for (LO c = 0; c < m.numLocalCells(); ++c) {
    EXPECT_NEAR(uniaxial[0][c], (kLambda + 2 * kMu) * e, tol);
    EXPECT_NEAR(uniaxial[1][c], kLambda * e, tol);
    EXPECT_NEAR(uniaxial[2][c], 0.0, tol);
    EXPECT_NEAR(uniaxial[3][c], kLambda * e, tol);
    EXPECT_NEAR(uniaxial[4][c], 2 * kMu * std::abs(e), tol);
    for (int q : {0, 1, 3}) EXPECT_NEAR(shear[q][c], 0.0, tol);
    EXPECT_NEAR(shear[2][c], kMu * g, tol);
    EXPECT_NEAR(shear[4][c], std::sqrt(3.0) * kMu * g, tol);
  }
}

TEST_P(ElasticityAssembly, MassHoldsTheMassOncePerComponent) {
  test::TestMesh tm(0.0, 2.0, -1.0, 0.5, 2, 1, 2);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  fem::ElasticityAssembler asmb(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), kLambda, kMu);
  const double rho = 3.0;
  const auto M = asmb.assembleOperator(1.0, 0.0, rho);
  const auto modes = asmb.rigidBodyModes();
  Vector Mx(asmb.ownedMap());
  M->apply(*modes->getVector(0), Mx);  // translation in x: e_x^T M e_x = rho |Omega|, no y part
  EXPECT_NEAR(Mx.dot(*modes->getVector(0)), rho * 3.0, 1e-12);
  EXPECT_NEAR(Mx.dot(*modes->getVector(1)), 0.0, 1e-14);
  // int f . phi for a constant body force (1, -2): the sum of the load is f |Omega|.
  Vector b(asmb.ownedMap());
  asmb.assembleLoad(core::ExpressionList("1, -2", "test", 2), 0.0, 1.0, b);
  EXPECT_NEAR(b.dot(*modes->getVector(0)), 3.0, 1e-12);
  EXPECT_NEAR(b.dot(*modes->getVector(1)), -6.0, 1e-12);
}

TEST_P(ElasticityAssembly, DirichletUnknownsPerComponent) {
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  // Rollers on the left (u_x = 0) and a clamp at the bottom.
  std::vector<char> flags(2 * m.overlapMap()->getNodeNumElements(), 0);
  const auto left = m.nodesOnSegments(kLeft), bottom = m.nodesOnSegments(kBottom);
  for (size_t i = 0; i < left.size(); ++i) {
    flags[2 * i] = left[i] || bottom[i];
    flags[2 * i + 1] = bottom[i];
  }
  fem::ElasticityAssembler asmb(m, flags, kLambda, kMu);
  const auto A = asmb.assembleOperator(1.0, 1.0, 1.0);
  // Identity rows on the Dirichlet unknowns, symmetric elsewhere: A e_i = e_i for them.
  Vector x(asmb.ownedMap()), y(asmb.ownedMap()), z(asmb.ownedMap());
  x.randomize();
  y.randomize();
  asmb.zeroDirichlet(x);
  Vector Ax(asmb.ownedMap()), Ay(asmb.ownedMap());
  A->apply(x, Ax);
  A->apply(y, Ay);
  z.assign(y);
  asmb.zeroDirichlet(z);
  EXPECT_NEAR(Ax.dot(z), Ay.dot(x), 1e-12 * Ax.norm2() * z.norm2());  // x^T A z = z^T A x
  auto h = Ax.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (size_t i = 0; i < h.extent(0); ++i)
    if (flags[i]) { EXPECT_EQ(h(i, 0), 0.0); }
  // Row by row: each flagged unknown's row is the identity row; every other row (the rollers' free
  // u_y among them) keeps its coupling to the neighbours.
  const auto local = A->getLocalMatrixHost();
  int rollers = 0;
  for (LO i = 0; i < static_cast<LO>(local.numRows()); ++i) {
    double diagonal = 0, offDiagonal = 0;
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      (A->getColMap()->getGlobalElement(local.graph.entries(k)) == A->getRowMap()->getGlobalElement(i)
           ? diagonal
           : offDiagonal) += std::abs(local.values(k));
    if (flags[i]) {
      EXPECT_EQ(diagonal, 1.0) << "row " << i;
      EXPECT_EQ(offDiagonal, 0.0) << "row " << i;
    } else {
      EXPECT_GT(offDiagonal, 0.0) << "row " << i;
    }
    rollers += i % 2 == 1 && flags[i - 1] && !flags[i];
  }
  int allRollers = 0;
  Teuchos::reduceAll(*m.comm(), Teuchos::REDUCE_SUM, rollers, Teuchos::outArg(allRollers));
  EXPECT_GT(allRollers, 0);  // u_x fixed, u_y free
}

TEST_P(ElasticityAssembly, ErrorNormsOfAKnownErrorAreExact) {
  // errorNorms returns the L2 norm and the H1 seminorm of u_h - u summed over both components
  // (Assembler.hpp). On the unit square with the error e = -(x y, 2 x):
  //   ||e||_0^2 = int x^2 y^2 + int 4 x^2 = 1/9 + 4/3 = 13/9,                 L2 = sqrt(13/9);
  //   |e|_1^2  = int (y^2 + x^2) + int (2^2 + 0^2) = 2/3 + 4 = 14/3,           H1 seminorm = sqrt(14/3).
  // 3 x 3 Gauss points integrate these polynomials exactly on rectangles; the exact gradient comes
  // from central differences, exact for x y and 2 x up to rounding.
  test::TestMesh tm(0.0, 1.0, 0.0, 1.0, 2, 2, 1);
  if (GetParam()) tm.refineCorner();
  const auto& m = tm.build();
  fem::ElasticityAssembler asmb(m, std::vector<char>(2 * m.overlapMap()->getNodeNumElements(), 0), kLambda, kMu);
  Vector u(asmb.ownedMap());
  // u_h = 0 against (x y, 2 x).
  u.putScalar(0.0);
  auto [l2, h1] = asmb.errorNorms(u, core::ExpressionList("x*y, 2*x", "test", 2), 0.0);
  EXPECT_NEAR(l2, std::sqrt(13.0 / 9), 1e-14);
  EXPECT_NEAR(h1, std::sqrt(14.0 / 3), 1e-8);
  // u_h = the interpolant of (1 + x, 3 - y) (in the space, hanging nodes included) against
  // (1 + x + x y, 3 - y + 2 x): the same error, through the hanging nodes' weights of each component.
  interpolate(asmb, [](double x, double) { return 1 + x; }, [](double, double y) { return 3 - y; }, u);
  std::tie(l2, h1) = asmb.errorNorms(u, core::ExpressionList("1 + x + x*y, 3 - y + 2*x", "test", 2), 0.0);
  EXPECT_NEAR(l2, std::sqrt(13.0 / 9), 1e-14);
  EXPECT_NEAR(h1, std::sqrt(14.0 / 3), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Meshes, ElasticityAssembly, ::testing::Values(false, true));

}  // namespace

// Poisson's ratio near 1/2: a note naming the key from lambda / mu = 100 (nu = 100/202) on
// (the solves' iterations grow with lambda / mu; the bar's CG + MueLu fails from
// nu = 0.4999997 on with the default Maximum Iterations).
TEST(ElasticityMaterial, NearIncompressibilityIsNamedFromLambdaOverMu100On) {
  auto material = [](double nu) {
    const double E = 7.3e10;
    return fem::ProblemData::nearIncompressibility(E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu)));
  };
  EXPECT_EQ(material(0.33), "");
  EXPECT_EQ(material(0.495), "");  // lambda / mu = 99
  const std::string note = material(0.4951);
  EXPECT_NE(note.find("Problem/Poisson's Ratio = 0.4951 is close to 1/2 (lambda / mu = 101)"), std::string::npos)
      << note;
  EXPECT_NE(material(0.4999999).find("lambda / mu = 4999999)"), std::string::npos);
}
