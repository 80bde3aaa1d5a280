#pragma once
/// \file ContactQP.hpp
/// The per-step contact problem (3.7)-(3.8) as a QP (ContactQP) and what its solve reports (ContactQPResult).
#include <string>
#include <vector>

#include <map>
#include <memory>

#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/solvers/StripSchurApproximation.hpp"

namespace signorini::solvers {

/// What ContactQP::solve() did and the KKT quantities of its result (replicated on every rank).
struct ContactQPResult {
  int activeSetIterations = 0;  ///< semismooth Newton steps
  int cgIterations = 0;         ///< CG iterations on Q (one A-solve each)
  int linearSolves = 0;         ///< A-solves in total
  int linearIterations = 0;     ///< Krylov iterations of all A-solves
  int active = 0;               ///< segments in contact
  double maxLambda = 0;         ///< max_j lambda_j (<= 0 by the KKT conditions; 0 while a segment is free)
  double minLambda = 0;         ///< min_j lambda_j (the largest contact pressure, with its sign; 0 without contact)
  double minGap = 0;            ///< min_j G_j / |E_j| [length]
  double maxComplementarity = 0;  ///< max_j |lambda_j G_j| / |E_j|
};

/// The discrete contact system (3.7)-(3.8) of one step in Schur-complement form (DESIGN 1.2, paper Sec. 3.2):
///   min 1/2 l^T Q l - l^T (B^T A^{-1} F - gbar)  s.t.  l <= 0,   Q = B^T A^{-1} B,
/// whose KKT multiplier is the weighted gap G = B^T u - gbar >= 0 with u = A^{-1}(F - B l).
/// Solved by a primal-dual active set (semismooth Newton) method; each Newton step solves
/// Q_AA d = G_A by conjugate gradients (one A-solve per iteration, u accumulated on the way)
/// preconditioned by a local approximation of Q on the active set: B^T A_s^{-1} B with A_s the
/// step matrix on a strip along Gamma_C (default), or the lumped B^T diag(A)^{-1} B. With the strip,
/// A_s^{-1} B p also starts each A-solve, so the exact solves need few iterations.
/// Owns a copy of its parameters and the Schur preconditioner of the current system (setSystem()); keeps no
/// reference to the matrix, the coupling or the linear solver.
class ContactQP {
 public:
  /// The valid "Contact" sublist (multiplier segments, KKT tolerance, iteration limits, Newton step solver, boundary
  /// mass, Schur preconditioner, strip and coarse correction) with defaults, doc strings and validators.
  static core::ParameterList getValidParameters();
  /// A warning (empty if none) for keys of the validated "Contact" sublist \p params that the
  /// chosen Schur preconditioner does not use ("Coarse Correction Cells" without the coarse
  /// correction, "Strip Width" without the strip).
  static std::string checkParameters(const core::ParameterList& params);
  /// \param params      validated "Contact" sublist; copied.
  /// \param lengthScale the domain diameter [length]: makes the relative KKT Tolerance an absolute gap
  ///                    tolerance [length] (gapTolerance()).
  ContactQP(const core::ParameterList& params, double lengthScale);

  ~ContactQP();
  /// Prepares for a new step matrix or contact coupling (the Schur preconditioner).
  /// \p courant = c k / h_min sets the strip width in node layers ("Strip Width" times it) along the
  /// finest segments; a segment of edge length h_j gets those of courant h_f / h_j (h_f the finest).
  /// \p coarseQ: the far-field part B^T P A_c^{-1} P^T B (CoarseSchurCorrection), required when
  /// usesCoarseCorrection(courant).
  void setSystem(const CrsMatrix& A, const fem::ContactCoupling& coupling, double courant,
                 const std::vector<double>& coarseQ = {});
  /// Whether setSystem() at this Courant number needs the coarse correction.
  bool usesCoarseCorrection(double courant) const;
  /// A user error naming Problem/Contact Segments when the contact QP's dense arrays for the
  /// segments of \p coupling on the step matrix \p A certainly cannot fit: at least two m x m arrays
  /// on every rank (8 bytes per entry) and the coarse correction's two of \p coarseUnknowns x m
  /// (its unknowns; 0 when usesCoarseCorrection() is false), and on rank 0 two of the strip's nodes x m; against all memory of rank 0's
  /// node (its other ranks need the every-rank part), or \p bytesPerRank > 0 per rank (Parallel/Memory
  /// Per Rank). Also when they exceed 32-bit counts. A lower bound: the arrays really allocated are
  /// larger (copies, elasticity's two unknowns per node); a contact boundary of 50,000 segments asked
  /// for 80 GB. Collective (m and the strip are the same on every rank).
  void checkMemory(const CrsMatrix& A, const fem::ContactCoupling& coupling, double courant,
                   double bytesPerRank = 0, double coarseUnknowns = 0) const;
  /// Solves the QP for load F (owned) and weighted obstacle gbar. \p lambda is the warm start
  /// on entry and the multiplier on exit; \p u is the initial guess of the first A-solve on entry
  /// and the displacement on exit; \p G returns the weighted gap.
  /// Throws core::SolverError with the iteration history if the KKT tolerance is not reached.
  ContactQPResult solve(LinearSolver& solver, const fem::ContactCoupling& coupling, const Vector& F,
                        const std::vector<double>& gbar, std::vector<double>& lambda, Vector& u,
                        std::vector<double>& G);
  /// Gap tolerance [length] for G_j / |E_j|.
  double gapTolerance() const { return gapTol_; }
  /// Node layers of the strip along each segment after setSystem() (empty without a strip).
  const std::vector<int>& segmentStripLayers() const { return segmentStripLayers_; }
  /// Multiplier tolerance of segment j [force/length]: a multiplier error that moves the gap by gapTolerance.
  double lambdaTolerance(int j) const;

 private:
  /// The strip's node layers under each segment (setSystem()).
  std::vector<int> segmentLayers(const fem::ContactCoupling& coupling, double courant) const;
  core::ParameterList params_;
  double gapTol_;
  std::string preconditioner_;
  std::vector<double> approxQ_;  // the local approximation of Q, dense m x m (identity for "none")
  std::unique_ptr<StripSchurApproximation> strip_;
  std::vector<double> segLen_;
  std::vector<int> segmentStripLayers_;
  struct Column {
    RCP<Vector> w;          ///< A^{-1} B e_j
    std::vector<double> q;  ///< B^T A^{-1} B e_j (replicated)
  };
  std::map<int, Column> columns_;  ///< per mesh (cleared by setSystem)
  long solvesOnSystem_ = 0;
  bool cachedColumns_ = false;

  /// The QP with exact Q_AA from cached columns; false (nothing usable) when the cache would
  /// exceed "Cached Columns", Q_AA is singular or the iterations run out.
  bool solveWithColumns(LinearSolver& solver, const fem::ContactCoupling& B, const Vector& F,
                        const std::vector<double>& gbar, std::vector<double>& lambda, Vector& u,
                        std::vector<double>& G, ContactQPResult& res);
  ContactQPResult finish(ContactQPResult res, const LinearSolver& solver, long its0, const std::vector<double>& lambda,
                         const std::vector<double>& G) const;
};

}  // namespace signorini::solvers
