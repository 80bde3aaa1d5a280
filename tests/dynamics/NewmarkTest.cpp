// Newmark's predictors and their inverse (paper (3.1)-(3.2)): the state moved to a new mesh is
// recovered from the two moved predictors and one moved field, for every admissible alpha, beta.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "Newmark.hpp"

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

}  // namespace
