#pragma once
/// \file Newmark.hpp
/// Newmark time stepping, paper (3.1)-(3.2).
#include "signorini/core/ParameterTools.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::dynamics {

/// The Newmark scheme of paper (3.1)-(3.2) (alpha is Newmark's gamma): the parameters of the deck's "Time Integration"
/// sublist and the predictor and velocity/acceleration updates on caller-owned vectors. A plain value type.
struct Newmark {
  /// The valid "Time Integration" sublist (Time Step, Final Time, Alpha, Beta, Contact Stabilisation, Contact Force) with
  /// defaults, doc strings and validators.
  static core::ParameterList getValidParameters();
  /// Reads a validated "Time Integration" sublist; throws core::UserError unless
  /// 2 beta >= alpha >= 1/2 (unconditional stability), naming the keys.
  explicit Newmark(const core::ParameterList& p);

  double timeStep;   ///< k [time]
  double finalTime;  ///< T [time]
  double alpha;      ///< Newmark gamma (paper alpha), in [1/2, 2 beta]
  double beta;       ///< Newmark beta (paper beta); the step matrix is M + beta k^2 K
  bool stabilised = false;  ///< project the predictor onto the admissible set before each step
  /// Contact Force = implicit: the predictors of step n+1 take the acceleration without step n's contact
  /// force, M^{-1} (f^n - K u^n), so only the new step's contact force acts in a step; the physical
  /// contact force is then alpha times the step equation's (-B lambda / (beta k^2)).
  bool implicitContact = false;
  /// Number of steps N = T / k (rounded to the nearest integer).
  int numSteps() const;

  /// Predictor u^{n-1} + k v^{n-1} + (1/2 - beta) k^2 a^{n-1}; F^n = M * predictor + beta k^2 (loads).
  void predictor(const Vector& u, const Vector& v, const Vector& a, Vector& out) const;
  /// Velocity predictor v^{n-1} + (1 - alpha) k a^{n-1}: (3.2) without its a^n term.
  void velocityPredictor(const Vector& v, const Vector& a, Vector& out) const;
  /// Given u^n and the step's two predictors (on the mesh of step n), overwrites (v, a) with
  /// a^n = (u^n - predictor) / (beta k^2) (3.1) and v^n = velocityPredictor + alpha k a^n (3.2).
  /// With a predictor projected onto the admissible set (contact stabilisation) the projection's
  /// correction is not counted as acceleration.
  void update(const Vector& predictor, const Vector& velocityPredictor, const Vector& uNew, Vector& v, Vector& a) const;
  /// The field that, moved to another mesh with the two predictors, determines the moved state
  /// (stateFromPredictors): \p v when alpha < 1 (as smooth as the velocity predictor, so its
  /// projection costs no more iterations), else \p a.
  const Vector& recoveryField(const Vector& v, const Vector& a) const;
  /// Inverts predictor() and velocityPredictor(): overwrites (u, v) with the state that has these
  /// predictors and whose recoveryField() is \p recovery (e.g. I_h u, I_h v from the projected
  /// predictors and the projected recovery field; I_h is linear).
  void stateFromPredictors(const Vector& predictor, const Vector& velocityPredictor, const Vector& recovery, Vector& u,
                           Vector& v) const;
};

}  // namespace signorini::dynamics
