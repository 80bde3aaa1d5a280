#include "signorini/dynamics/Newmark.hpp"

#include <cmath>

#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"

namespace signorini::dynamics {

core::ParameterList Newmark::getValidParameters() {
  core::ParameterList p("Time Integration");
  core::addDouble(p, "Time Step", 0.0025, "k [time], constant; at least 1e-150, so that beta k^2 is a normal double", 1e-150,
                  core::kInf);
  core::addDouble(p, "Final Time", 1.0, "T [time], a whole number of Time Steps (to 1e-6 relative): the run takes T / k steps", 1e-300, core::kInf);
  core::addDouble(p, "Alpha", 0.5, "Newmark alpha (= gamma); second order needs 1/2; 2 beta >= alpha >= 1/2", 0.0, 2.0);
  core::addDouble(p, "Beta", 0.5, "Newmark beta; with alpha = 1/2 the scheme conserves the Newmark energy (energy + (beta - 1/4) k^2/2 a^T M a, the steps table's newmark_energy; paper Sec. 3.1) without contact; with contact the scheme gains energy where contact is released (the steps table's contact_work; README, Known behaviour), the more the less the Time Step resolves the impact: beta = 1/4 0.25 to 2.35 on the membrane, the paper's 1/2 0.28% on membrane-level2.xml, up to 3.9% on a 16 x 16 membrane mesh, 0.1-0.3% on a bar's impact, 43% on a block whose impact lasts two steps", 0.0, 2.0);
  core::addChoice(p, "Contact Stabilisation", "none",
                  "\"predictor projection\": project the Newmark predictor onto the admissible set in the mass "
                  "norm before each step (after Deuflhard, Krause, Ertel; not in the paper) against the chattering "
                  "of impacting nodes (DESIGN 1.6); \"none\": the paper's scheme",
                  {"none", "predictor projection"});
  core::addChoice(p, "Contact Force", "trapezoidal",
                  "\"trapezoidal\": the contact force acts in a step, like every force, averaged over the step's two "
                  "ends (the paper's; it gains energy where contact is released, README Known behaviour); "
                  "\"implicit\": only the step's new contact force acts in it, the previous one is left out of the "
                  "predictors (Deuflhard, Krause, Ertel's contact-implicit Newmark step, with the predictor projection "
                  "their contact-stabilised one; needs Alpha = 1/2 and Beta = 1/4, with which a fixed obstacle never "
                  "adds energy); the multiplier is then alpha times the step equation's, a the physical acceleration; "
                  "costs a mass solve per step in contact",
                  {"trapezoidal", "implicit"});
  return p;
}

Newmark::Newmark(const core::ParameterList& p)
    : timeStep(p.get<double>("Time Step")),
      finalTime(p.get<double>("Final Time")),
      alpha(p.get<double>("Alpha")),
      beta(p.get<double>("Beta")),
      stabilised(p.get<std::string>("Contact Stabilisation") == "predictor projection"),
      implicitContact(p.get<std::string>("Contact Force") == "implicit") {
  if (alpha < 0.5)
    SIGNORINI_USER_ERROR("Time Integration/Alpha = " << alpha << " violates 2 Beta >= Alpha >= 1/2 (Alpha < 1/2)");
  if (2 * beta < alpha)
    SIGNORINI_USER_ERROR("Time Integration/Beta = " << beta << " violates 2 Beta >= Alpha >= 1/2 with Alpha = " << alpha);
  if (implicitContact && (alpha != 0.5 || beta != 0.25))
    SIGNORINI_USER_ERROR("Time Integration/Contact Force = implicit needs Alpha = 1/2 and Beta = 1/4 (the trapezoidal "
                         "rule, as Deuflhard, Krause and Ertel's step; with other values the acceleration left out "
                         "of the predictors adds energy), not Alpha = "
                         << alpha << " and Beta = " << beta);
  if (finalTime / timeStep > 1e8)
    SIGNORINI_USER_ERROR("Time Integration/Time Step = " << timeStep << " gives more than 1e8 steps to Final Time");
  if (numSteps() < 1)
    SIGNORINI_USER_ERROR("Time Integration/Final Time = " << finalTime << " is shorter than half a Time Step");
  const double steps = finalTime / timeStep;  // a whole number up to the rounding of decimal inputs
  if (std::fabs(steps - numSteps()) > 1e-6 * steps)
    SIGNORINI_USER_ERROR("Time Integration/Final Time = " << finalTime << " is not a whole number of Time Steps "
                                                          << timeStep << " (" << steps << " steps; the run would end at t = "
                                                          << numSteps() * timeStep << ")");
}

int Newmark::numSteps() const { return static_cast<int>(std::llround(finalTime / timeStep)); }

void Newmark::predictor(const Vector& u, const Vector& v, const Vector& a, Vector& out) const {
  const double k = timeStep;
  out.update(1.0, u, k, v, 0.0);
  out.update((0.5 - beta) * k * k, a, 1.0);
}

void Newmark::velocityPredictor(const Vector& v, const Vector& a, Vector& out) const {
  out.update(1.0, v, (1 - alpha) * timeStep, a, 0.0);
}

void Newmark::update(const Vector& predictor, const Vector& velocityPredictor, const Vector& uNew, Vector& v,
                     Vector& a) const {
  const double k = timeStep;
  a.update(1.0 / (beta * k * k), uNew, -1.0 / (beta * k * k), predictor, 0.0);
  v.update(1.0, velocityPredictor, alpha * k, a, 0.0);
}

const Vector& Newmark::recoveryField(const Vector& v, const Vector& a) const { return alpha < 1 ? v : a; }

void Newmark::stateFromPredictors(const Vector& predictor, const Vector& velocityPredictor, const Vector& recovery,
                                  Vector& u, Vector& v) const {
  const double k = timeStep;
  if (alpha < 1) {  // v given; k^2 (1/2 - beta) a = k (1/2 - beta) / (1 - alpha) (velocityPredictor - v)
    v.assign(recovery);
    const double c = k * (0.5 - beta) / (1 - alpha);
    u.update(1.0, predictor, -c, velocityPredictor, 0.0);
    u.update(c - k, v, 1.0);
  } else {  // a given; v = velocityPredictor - (1 - alpha) k a
    v.update(1.0, velocityPredictor, -(1 - alpha) * k, recovery, 0.0);
    u.update(1.0, predictor, -k, v, 0.0);
    u.update(-(0.5 - beta) * k * k, recovery, 1.0);
  }
}


}  // namespace signorini::dynamics
