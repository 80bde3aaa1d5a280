#pragma once
/// \file ProblemData.hpp
/// The deck's "Problem" sublist, read (ProblemData).
#include <optional>
#include <string>

#include "signorini/mesh/BoundarySegments.hpp"
#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/core/ParameterTools.hpp"

namespace signorini::fem {

/// The deck's "Problem" sublist (DESIGN 1.1): model, material, data functions (muParser expressions in x, y, t) and
/// the roles of the named boundary segments as bit masks (bit i: BoundarySegments index i). A value type: it keeps
/// no reference to the segments.
struct ProblemData {
  /// rho u_tt - div(kappa grad u) = f (one unknown per node) or plane strain elasticity (two per node).
  enum class Model { ScalarWave, PlaneStrainElasticity };
  /// The valid "Problem" sublist with defaults, doc strings and validators.
  static core::ParameterList getValidParameters();
  /// Reads a validated "Problem" sublist; resolves segment names against \p segments.
  /// Throws core::UserError naming the key for an expression that does not parse or an unknown segment.
  /// Throws core::UserError naming the keys for a segment that is both a Dirichlet and a Neumann
  /// segment (for a roller: if the traction acts on its fixed component) and for a segment list
  /// with an empty item or a name given twice.
  ProblemData(const core::ParameterList& p, const mesh::BoundarySegments& segments);
  /// Settings of the validated "Problem" sublist \p p that are valid but have no effect, as a
  /// warning ("no Problem/Neumann Segments; without effect: Problem/Neumann Data"); empty if none.
  static std::string checkParameters(const core::ParameterList& p);

  Model model = Model::ScalarWave;  ///< Problem/Type
  double density = 1.0;    ///< rho [mass / area] (scalar wave) or [mass / volume] (elasticity)
  double stiffness = 1.0;  ///< kappa [force / length] (scalar wave: wave speed sqrt(kappa / rho))
  /// \var lameLambda
  /// plane strain Lame parameter lambda [force / area] from E and nu (0 for the scalar wave)
  double lameLambda = 0.0, lameMu = 0.0;  ///< plane strain Lame parameters [force / area] from E and nu
  /// Fields with one component per unknown of a node (1 for the scalar wave, 2 for elasticity).
  /// \var bodyForce
  /// f [force / area]; elasticity [force / volume]
  /// \var initialDisplacement
  /// u0 [length] at t = 0
  /// \var initialVelocity
  /// v0 [length / time] at t = 0
  /// \var neumannData
  /// q on the Neumann segments: kappa du/dn [force / length]; elasticity: the traction sigma n [force / area]
  core::ExpressionList bodyForce, initialDisplacement, initialVelocity, neumannData;
  core::Expression obstacle;  ///< g: the constraint is d . u >= g with d = contactDirection (scalar: u >= g)
  std::optional<core::ExpressionList> exactSolution;  ///< exact u(x, y, t) for the error norms, if the deck gives one
  bool hasObstacle = true;  ///< whether Problem/Obstacle is set (else \p obstacle is the constant 0)
  /// \var dirichletMask
  /// Gamma_D: segments with every component fixed (only component c: componentDirichletMask, elasticity rollers)
  /// \var contactMask
  /// Gamma_C: the contact segments
  /// \var neumannMask
  /// Gamma_N: the segments with Neumann data (the rest of the boundary is homogeneous Neumann)
  unsigned dirichletMask = 0, contactMask = 0, neumannMask = 0;
  unsigned componentDirichletMask[2] = {0, 0};  ///< segments with only u_x (index 0) or u_y (1) fixed (rollers)
  int contactComponent = 0;    ///< component of u the obstacle constrains (elasticity)
  double contactSign = 1.0;    ///< +1: u_c >= g, -1: -u_c >= g
  /// Unknowns per node: 1 (scalar wave) or 2 (elasticity).
  int components() const { return model == Model::ScalarWave ? 1 : 2; }
  /// Whether the data can supply energy: a body force or Neumann data that is not the constant 0 (on
  /// a Neumann segment), or an obstacle that moves. Without, the energy of the exact solution never
  /// exceeds its initial value (the supports hold at 0, frictionless contact with a fixed obstacle
  /// does no work on the body).
  bool suppliesEnergy() const;
  /// Whether any unknown is held (Dirichlet Segments, Dirichlet X/Y Segments): then the supports exert a reaction.
  bool hasDirichletConditions() const {
    return (dirichletMask | componentDirichletMask[0] | componentDirichletMask[1]) != 0;
  }
  /// The stiffness of the fastest wave: kappa [force / length], or the P-wave modulus lambda + 2 mu
  /// [force / area]; the estimator's physical scaling divides by it.
  double waveModulus() const { return model == Model::ScalarWave ? stiffness : lameLambda + 2 * lameMu; }
  /// Fastest wave speed: sqrt(waveModulus() / rho).
  double waveSpeed() const;
  /// Samples the data that depend on t at the times n k, n = 1..\p steps (\p timeStep k), at the
  /// points where a step on \p mesh samples them (body force at the cells' 2x2 Gauss points, the
  /// exact solution where Assembler::errorNorms does, Neumann data and the obstacle at their
  /// edges' Gauss points), so that a value that is not a finite number later in the run is found
  /// at set-up (and by --check). Throws core::UserError with the message a step would give at the
  /// earliest such step (every rank alike). Beyond 2e7 samples per rank, every m-th step is sampled
  /// (and the last), and after a hit the steps skipped before it. Collective.
  void checkFiniteOverTime(const mesh::Q1Mesh& mesh, double timeStep, int steps) const;
  /// For elasticity with Poisson's ratio near 1/2 (lambda / mu >= 100, nu >= 100/202 = 0.49505): why the
  /// results lock and the linear solves slow down or fail, naming Problem/Poisson's Ratio; empty
  /// otherwise. Printed as a warning at set-up and appended to a failing solve's message.
  std::string nearIncompressibility() const;
  /// The same for the Lame parameters \p lameLambda and \p lameMu [force / area].
  static std::string nearIncompressibility(double lameLambda, double lameMu);
};

}  // namespace signorini::fem
