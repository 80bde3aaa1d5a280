#pragma once
/// \file ElasticityEstimator.hpp
/// The a posteriori error estimator of paper Sec. 4 for plane strain elasticity (ElasticityEstimator) and its input.
#include <functional>
#include <vector>

#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/estimate/HarmonicContinuation.hpp"
#include "signorini/estimate/ResidualEstimator.hpp"

namespace signorini::estimate {

/// The inputs of one evaluation (as EstimatorInput, with the elasticity assembler).
struct ElasticityEstimatorInput {
  const mesh::Forest& forest;                 ///< the mesh T^n (its local cells in Q1Mesh order)
  const mesh::Q1Mesh& mesh;                   ///< Q1 numbering of \p forest (the one \p assembler was built on)
  const fem::ElasticityAssembler& assembler;  ///< two unknowns per node; Dirichlet flags per component
  const fem::ProblemData& problem;            ///< Lame parameters, rho, f, q, g and the segment masks
  const fem::ContactCoupling* coupling;  ///< null without obstacle
  /// \var time
  /// t_n [time]
  /// \var timeStep
  /// k [time]
  /// \var beta
  /// Newmark beta
  double time, timeStep, beta;
  const Vector& u;          ///< u_h^n (owned unknowns, two per node)
  const Vector& predictor;  ///< the Newmark predictor from the transferred fields (owned unknowns)
  const std::vector<double>& lambda;  ///< scaled QP multipliers (per segment, replicated)
  /// Solves A x = b for an SPD matrix A on the mesh's nodes (x holds the initial guess); for s1.
  std::function<void(const RCP<const CrsMatrix>& A, const Vector& b, Vector& x)> solveSPD;
  /// Identifies the mesh among all meshes of the run (>= 0; -1: unknown): s1 then keeps its
  /// operators while the mesh stays the same and starts from the previous continuation.
  long meshId = -1;
  /// A guess of the s1 continuation on this mesh (owned nodes; e.g. the previous step's,
  /// interpolated), used when the mesh is new to the estimator; may be null.
  const Vector* continuationGuess = nullptr;
};

/// The residual estimator of paper Sec. 4, Proposition 4.1, for plane strain elasticity (DESIGN 1.3, derivation in
/// docs/estimator.md): the scalar estimator's structure with the traction sigma(u_h) n in place of
/// kappa du_h/dn and div sigma(u_h) in the cell residual:
///   eta_*^2 = sum_K h_K^2 ||r||_K^2 + h_K ||R||_{dK}^2,
///   r = beta k^2 f + rho (predictor - u_h) + beta k^2 div sigma(u_h)   (non-zero on rectangles:
///       the mixed second derivatives of bilinear fields remain),
///   R = -(beta k^2 / 2) [sigma(u_h) n] on interior edges (hanging edges included),
///   R = beta k^2 (sigma(u_h) n - q) on Neumann edges, beta k^2 sigma(u_h) n on free edges,
///   R = beta k^2 sigma(u_h) n + sign lambda_H e_c on contact edges (the constraint sign u_c >= g
///       acts on component c; the tangential traction must vanish), the components fixed by a
///       Dirichlet condition left out;
///   s0 = sqrt(|<lambda_H, (g - sign u_c)_+>|), s1 = ||(g - sign u_c)_+||_{1/2,Gamma_C} through the
///   harmonic continuation. Cell indicators: eta_K^2 plus the s0 share of the cell's contact edges.
/// Owns a copy of its parameters and a cache of s1's operators and last continuation (ContinuationCache)
/// for one mesh at a time.
class ElasticityEstimator {
 public:
  /// \param params the validated "Estimator" sublist (ResidualEstimator::getValidParameters()); copied and
  ///               validated again (defaults filled in).
  explicit ElasticityEstimator(const core::ParameterList& params);
  /// eta^n of one step on in.mesh (Proposition 4.1; units as in EstimatorResult, the "physical" scaling dividing by
  /// beta k^2 (lambda + 2 mu)). Collective over the mesh's communicator. With in.coupling and Compute S1: one
  /// in.solveSPD solve for s1 when (g - sign u_c)_+ is non-zero somewhere.
  EstimatorResult estimate(const ElasticityEstimatorInput& in) const;

  /// The last s1 continuation if it lives on mesh \p meshId (else null): a guess for the next step.
  /// Shares the vector of the estimator's cache: the next estimate() on that mesh overwrites it; copy it to keep it.
  RCP<Vector> continuationOn(long meshId) const { return continuation_.lastOn(meshId); }

 private:
  core::ParameterList params_;
  mutable ContinuationCache continuation_;
};

}  // namespace signorini::estimate
