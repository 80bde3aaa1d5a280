#pragma once
/// \file ResidualEstimator.hpp
/// The a posteriori error estimator of paper Sec. 4 for the scalar wave (ResidualEstimator), its input and result.
#include <functional>
#include <vector>

#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/estimate/HarmonicContinuation.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"

namespace signorini::estimate {

/// Everything one evaluation needs. All references must outlive the call.
struct EstimatorInput {
  const mesh::Forest& forest;            ///< the mesh T^n (its local cells in Q1Mesh order)
  const mesh::Q1Mesh& mesh;              ///< Q1 numbering of \p forest (the one \p assembler was built on)
  const fem::Q1Assembler& assembler;     ///< Dirichlet flags on Gamma_D
  const fem::ProblemData& problem;       ///< rho, kappa, f, q, g and the segment masks
  const fem::ContactCoupling* coupling;  ///< null without obstacle
  /// \var time
  /// t_n [time]
  /// \var timeStep
  /// k [time]
  /// \var beta
  /// Newmark beta
  double time, timeStep, beta;
  const Vector& u;                       ///< u_h^n (owned)
  const Vector& predictor;               ///< I_h u^{n-1} + k I_h v^{n-1} + (1/2 - beta) k^2 I_h a^{n-1} (owned)
  const std::vector<double>& lambda;     ///< scaled QP multipliers lambda_H (per segment, replicated)
  /// Solves A x = b for an SPD matrix A (x holds the initial guess); used for s1.
  std::function<void(const RCP<const CrsMatrix>& A, const Vector& b, Vector& x)> solveSPD;
  /// Identifies the mesh among all meshes of the run (>= 0; -1: unknown): s1 then keeps its
  /// operators while the mesh stays the same and starts from the previous continuation.
  long meshId = -1;
  /// A guess of the s1 continuation on this mesh (owned nodes; e.g. the previous step's,
  /// interpolated), used when the mesh is new to the estimator; may be null.
  const Vector* continuationGuess = nullptr;
  /// \var mass
  /// The step's consistent M_rho and K_kappa on this mesh (optional): s1's H^1 operator is then
  /// M / (rho l^2) + K / kappa (l: Estimator/S1 Length Scale), formed from their values instead of assembled.
  /// \var stiffness
  /// K_kappa of the step (optional; see \p mass).
  RCP<const CrsMatrix> mass, stiffness;
};

/// The estimate of one step (Proposition 4.1, Remark 4.1), the same on every rank except the per-cell vectors.
/// With Estimator/Scaling = "physical" (default) eta, etaStar, s0 and s1 are in units of the displacement (a length
/// in the deck's unit; s1 when S1 Length Scale is a length of the problem); with "step" eta_* and s0 carry beta k^2.
struct EstimatorResult {
  /// \var etaStar
  /// eta_*^n = (sum_K eta_K^2)^(1/2), summed over all ranks
  /// \var s0
  /// sqrt(|<lambda_H, (g - u_h)_+>|): complementarity (Remark 4.1 with the root, DESIGN 1.4)
  /// \var s1
  /// ||(g - u_h)_+||_{1/2,Gamma_C}: geometric term; 0 without obstacle or with Compute S1 = false
  /// \var eta
  /// eta^n = etaStar + s0 + s1
  double etaStar = 0, s0 = 0, s1 = 0, eta = 0;
  std::vector<double> cellIndicator;  ///< per local cell: eta_K^2 + s0 share (squared units)
  std::vector<double> cellEta2;       ///< per local cell: eta_K^2 alone (cellIndicator less the s0 share)
};

/// The a posteriori error estimator of paper Sec. 4, Proposition 4.1 (DESIGN 1.3) for one time step:
///   eta^n = eta_*^n + s0 + s1,
///   eta_*^2 = sum_K h_K^2 ||r||_K^2 + h_K ||R||_{dK}^2,
///   r = F_h^n - rho u_h + beta k^2 div(kappa grad u_h),  F_h^n = beta k^2 f(t_n) + rho * predictor,
///   R = -(beta k^2 / 2) [kappa du_h/dn] on interior edges (hanging edges included),
///   R = -beta k^2 (q - kappa du_h/dn) on Neumann edges, R = lambda_H + beta k^2 kappa du_h/dn on
///   contact edges (lambda_H the scaled QP multiplier), nothing on Dirichlet edges;
///   s0 = sqrt(|<lambda_H, (g - u_h)_+>|), s1 = ||(g - u_h)_+||_{1/2,Gamma_C} through the harmonic
///   continuation (one extra linear solve, only when the positive part is non-zero).
/// Cell indicators for marking: eta_K^2 plus the s0^2 share of the cell's contact edges (s1 left
/// out, paper Remark 4.2). Owns a copy of its parameters and a cache of s1's operators and last
/// continuation (ContinuationCache) for one mesh at a time.
class ResidualEstimator {
 public:
  /// The valid "Estimator" sublist (Compute S1, Scaling, S1 Relative Tolerance, S1 Length Scale) with defaults,
  /// doc strings and validators.
  static core::ParameterList getValidParameters();
  /// Copies \p params (an "Estimator" sublist) and validates the copy, filling in defaults; throws
  /// core::UserError for an invalid entry.
  explicit ResidualEstimator(const core::ParameterList& params);
  /// eta^n of one step on in.mesh (Proposition 4.1). Collective over the mesh's communicator. With in.coupling and
  /// Compute S1: one in.solveSPD solve for s1 when (g - u_h)_+ is non-zero somewhere.
  EstimatorResult estimate(const EstimatorInput& in) const;

  /// The last s1 continuation if it lives on mesh \p meshId (else null): a guess for the next step.
  /// Shares the vector of the estimator's cache: the next estimate() on that mesh overwrites it; copy it to keep it.
  RCP<Vector> continuationOn(long meshId) const { return continuation_.lastOn(meshId); }

 private:
  core::ParameterList params_;
  mutable ContinuationCache continuation_;
};

}  // namespace signorini::estimate
