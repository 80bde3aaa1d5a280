#pragma once
/// \file LinearSolver.hpp
/// A^{-1} for the step matrix (LinearSolver). Belos and MueLu headers stay in LinearSolver.cpp (compile time).
#include <memory>
#include <string>
#include <vector>

#include "signorini/core/ParameterTools.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::solvers {

/// Added to a solver failure on a step matrix that is not positive definite to rounding.
inline constexpr const char* kNotPositiveDefiniteHint =
    "its condition number is beyond what doubles hold, as with a time step far above the mesh's Courant limit on "
    "a stiff material; lower Time Integration/Time Step";

/// A^{-1} for the step matrix A = M + beta k^2 K: a Belos Krylov solver (CG by default) with a MueLu (smoothed
/// aggregation) or Jacobi (diagonal) preconditioner, configured from the deck's "Linear Solver" sublist; "Belos" and
/// "MueLu" sublists are passed through unchanged. Keeps the RCPs it is given (A, near-nullspace modes); the
/// communicator is A's.
class LinearSolver {
 public:
  /// The valid "Linear Solver" sublist (Method, Preconditioner, Auto MueLu Courant Number, Relative Tolerance,
  /// Maximum Iterations, pass-through "Belos" and "MueLu") with defaults, doc strings and validators.
  static core::ParameterList getValidParameters();
  /// The Belos methods (canonical names) that solve the SPD systems here with a left preconditioner.
  static const std::vector<std::string>& supportedMethods();
  /// \p method in any case, or one of Belos' aliases ("PSEUDO BLOCK CG"), as its name in
  /// supportedMethods(); empty if it is none of them.
  static std::string canonicalMethod(const std::string& method);
  /// Cross-parameter rules of a validated "Linear Solver" sublist, checked before any output
  /// exists: "Method" is one of supportedMethods(); under reproducible arithmetic (our own Jacobi
  /// CG) it must be "CG" and the preconditioner "Jacobi" or "auto". Throws core::UserError naming
  /// the key. Returns a warning (empty if none): the Belos and MueLu sublists a deck sets have no
  /// effect under reproducible arithmetic.
  static std::string checkParameters(const core::ParameterList& params, bool reproducible);
  /// \param params a validated "Linear Solver" sublist; copied.
  explicit LinearSolver(const core::ParameterList& params);
  ~LinearSolver();

  /// For systems with several unknowns per node (numbered node-major, as fem::Assembler does):
  /// MueLu aggregates nodes of \p equationsPerNode unknowns and interpolates \p modes (e.g. the
  /// rigid body modes of elasticity) exactly. Takes effect at the next setOperator(). Keeps \p modes.
  void setNearNullspace(RCP<MultiVector> modes, int equationsPerNode);
  /// Sets A (kept until the next call) and (re)builds the preconditioner. \p courant = c k / h_min chooses the
  /// preconditioner when "Preconditioner" is "auto" (Jacobi below the threshold, MueLu above).
  /// The preconditioner (under reproducible arithmetic: A's diagonal) is taken from A's values
  /// now: call setOperator again after changing them.
  void setOperator(RCP<const CrsMatrix> A, double courant);
  /// Solves A x = b to the relative tolerance ||b - A x|| <= tol ||b||, starting from x.
  /// Returns the number of iterations; throws core::SolverError if not converged.
  int solve(const Vector& b, Vector& x);
  /// Names the system in failure messages ("linear solver CG + Jacobi for <name> did not reach ..."),
  /// e.g. "the mass matrix M"; empty (the default): no name.
  void setSystemName(const std::string& name);
  /// Name of the preconditioner in use ("MueLu", "Jacobi" or "none").
  const std::string& preconditioner() const;
  /// The "Relative Tolerance" of the parameters.
  double relativeTolerance() const;
  /// Calls of solve() so far.
  long numSolves() const;
  /// Krylov iterations of all solve() calls so far.
  long totalIterations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini::solvers
