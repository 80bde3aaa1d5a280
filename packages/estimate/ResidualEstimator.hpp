#pragma once
/// \file ResidualEstimator.hpp
/// The a posteriori error estimator of paper Sec. 4 (DESIGN 1.3) for one time step:
///   eta^n = eta_*^n + s0 + s1,
///   eta_*^2 = sum_K h_K^2 ||r||_K^2 + h_K ||R||_{dK}^2,
///   r = F_h^n - rho u_h + beta k^2 div(kappa grad u_h),  F_h^n = beta k^2 f(t_n) + rho * predictor,
///   R = -(beta k^2 / 2) [kappa du_h/dn] on interior edges (hanging edges included),
///   R = -beta k^2 (q - kappa du_h/dn) on Neumann edges, R = lambda_H + beta k^2 kappa du_h/dn on
///   contact edges (lambda_H the scaled QP multiplier), nothing on Dirichlet edges;
///   s0 = sqrt(|<lambda_H, (g - u_h)_+>|), s1 = ||(g - u_h)_+||_{1/2,Gamma_C} through the harmonic
///   continuation (one extra linear solve, only when the positive part is non-zero).
/// Cell indicators for marking: eta_K^2 plus the s0^2 share of the cell's contact edges (s1 left
/// out, paper Remark 4.2).
#include <functional>
#include <vector>

#include "ContactCoupling.hpp"
#include "Forest.hpp"
#include "HarmonicContinuation.hpp"
#include "ParameterTools.hpp"
#include "ProblemData.hpp"
#include "Q1Assembler.hpp"

namespace signorini::estimate {

/// Everything one evaluation needs. All references must outlive the call.
struct EstimatorInput {
  const mesh::Forest& forest;            ///< the mesh T^n (its local cells in Q1Mesh order)
  const mesh::Q1Mesh& mesh;
  const fem::Q1Assembler& assembler;     ///< Dirichlet flags on Gamma_D
  const fem::ProblemData& problem;
  const fem::ContactCoupling* coupling;  ///< null without obstacle
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
  /// The step's consistent M_rho and K_kappa on this mesh (optional): s1's H^1 operator is then
  /// M / rho + K / kappa, formed from their values instead of assembled.
  RCP<const CrsMatrix> mass, stiffness;
};

struct EstimatorResult {
  double etaStar = 0, s0 = 0, s1 = 0, eta = 0;
  std::vector<double> cellIndicator;  ///< per local cell: eta_K^2 + s0 share (squared units)
  std::vector<double> cellEta2;       ///< per local cell: eta_K^2 alone (cellIndicator less the s0 share)
};

class ResidualEstimator {
 public:
  static core::ParameterList getValidParameters();  ///< the "Estimator" sublist
  explicit ResidualEstimator(const core::ParameterList& params);
  EstimatorResult estimate(const EstimatorInput& in) const;

  /// The last s1 continuation if it lives on mesh \p meshId (else null): a guess for the next step.
  RCP<Vector> continuationOn(long meshId) const { return continuation_.lastOn(meshId); }

 private:
  core::ParameterList params_;
  mutable ContinuationCache continuation_;
};

}  // namespace signorini::estimate
