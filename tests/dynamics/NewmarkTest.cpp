// Newmark's predictors and their inverse (paper (3.1)-(3.2)): the state moved to a new mesh is
// recovered from the two moved predictors and one moved field, for every admissible alpha, beta;
// one step of a motion with constant acceleration is reproduced exactly by the update.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/dynamics/Newmark.hpp"

using namespace signorini;

namespace {

dynamics::Newmark newmark(double alpha, double beta) {
  core::ParameterList p = dynamics::Newmark::getValidParameters();
  p.set("Time Step", 0.01);
  p.set("Alpha", alpha);
  p.set("Beta", beta);
  return dynamics::Newmark(p);
}

TEST(Newmark, StateFromPredictorsInvertsThePredictors) {
  auto map = Teuchos::rcp(new Map(5, 0, Tpetra::getDefaultComm()));
  Vector u(map), v(map), a(map);
  u.randomize();
  v.randomize();
  a.randomize();
  // alpha = 1 and alpha > 1 recover from a, alpha < 1 from v (recoveryField).
  for (const auto& [alpha, beta] : {std::pair{0.5, 0.25}, {0.5, 0.5}, {0.7, 0.5}, {1.0, 0.5}, {1.5, 0.8}, {2.0, 1.0}}) {
    const auto nm = newmark(alpha, beta);
    Vector predictor(map), velocityPredictor(map), uBack(map), vBack(map);
    nm.predictor(u, v, a, predictor);
    nm.velocityPredictor(v, a, velocityPredictor);
    nm.stateFromPredictors(predictor, velocityPredictor, nm.recoveryField(v, a), uBack, vBack);
    uBack.update(-1.0, u, 1.0);
    vBack.update(-1.0, v, 1.0);
    EXPECT_LT(uBack.normInf(), 1e-14) << "alpha " << alpha << ", beta " << beta;
    EXPECT_LT(vBack.normInf(), 1e-14) << "alpha " << alpha << ", beta " << beta;
  }
}

TEST(Newmark, UpdateReproducesAMotionWithConstantAcceleration) {
  // u(t) = u0 + v0 t + a t^2 / 2: given u(k), the update must give a(k) = a and v(k) = v0 + k a for
  // every alpha and beta (predictor u0 + k v0 + (1/2 - beta) k^2 a, so a^1 = (u(k) - predictor) /
  // (beta k^2) = a, and v^1 = v0 + (1 - alpha) k a + alpha k a).
  auto map = Teuchos::rcp(new Map(5, 0, Tpetra::getDefaultComm()));
  Vector u0(map), v0(map), a0(map);
  u0.randomize();
  v0.randomize();
  a0.randomize();
  for (const auto& [alpha, beta] : {std::pair{0.5, 0.25}, {0.5, 0.5}, {0.7, 0.5}, {1.0, 0.5}, {1.5, 0.8}, {2.0, 1.0}}) {
    const auto nm = newmark(alpha, beta);
    const double k = nm.timeStep;
    Vector predictor(map), velocityPredictor(map), uNew(map), v(map), a(map);
    nm.predictor(u0, v0, a0, predictor);
    nm.velocityPredictor(v0, a0, velocityPredictor);
    uNew.update(1.0, u0, k, v0, 0.0);
    uNew.update(0.5 * k * k, a0, 1.0);
    // v and a on entry are not the answer (an update that kept a0 would pass otherwise).
    v.putScalar(1e30);
    a.putScalar(1e30);
    nm.update(predictor, velocityPredictor, uNew, v, a);
    a.update(-1.0, a0, 1.0);
    Vector vExact(map);
    vExact.update(1.0, v0, k, a0, 0.0);
    v.update(-1.0, vExact, 1.0);
    EXPECT_LT(a.normInf(), 1e-9) << "alpha " << alpha << ", beta " << beta;  // rounding of u / (beta k^2)
    EXPECT_LT(v.normInf(), 1e-12) << "alpha " << alpha << ", beta " << beta;
  }
}

}  // namespace
