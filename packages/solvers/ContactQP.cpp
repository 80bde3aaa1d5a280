#include "signorini/solvers/ContactQP.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <mpi.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"

namespace signorini::solvers {
namespace {

/// Cholesky factor (lower, in place) of a dense SPD matrix; returns false if not positive definite.
bool cholesky(std::vector<double>& a, int n) {
  for (int j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (int k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
    if (!(d > 0)) return false;
    d = std::sqrt(d);
    a[j * n + j] = d;
    for (int i = j + 1; i < n; ++i) {
      double s = a[i * n + j];
      for (int k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / d;
    }
  }
  return true;
}

void choleskySolve(const std::vector<double>& L, int n, std::vector<double>& x) {
  for (int i = 0; i < n; ++i) {
    double s = x[i];
    for (int k = 0; k < i; ++k) s -= L[i * n + k] * x[k];
    x[i] = s / L[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {
    double s = x[i];
    for (int k = i + 1; k < n; ++k) s -= L[k * n + i] * x[k];
    x[i] = s / L[i * n + i];
  }
}

}  // namespace

core::ParameterList ContactQP::getValidParameters() {
  core::ParameterList p("Contact");
  core::addChoice(p, "Multiplier Segments", "H = 2h",
                  "Piecewise constant multipliers on segments of two sibling fine edges, the halves of a coarser "
                  "edge (stable, the paper's choice; a lone edge beside finer ones joins them) or of one edge "
                  "(unstable, paper Fig. 3.1)",
                  {"H = 2h", "H = h"});
  core::addDouble(p, "KKT Tolerance", 1e-9,
                  "Tolerance of the KKT conditions relative to the domain diameter: mean gap G_j/|E_j| >= -tol*L, "
                  "and the multiplier sign and complementarity measured by the gap they cause",
                  1e-14, 1e-2);
  core::addInt(p, "Maximum Active Set Iterations", 50, "Semismooth Newton steps per time step", 1);
  core::addInt(p, "Maximum CG Iterations", 500, "CG iterations on the Schur complement per Newton step", 1);
  core::addChoice(p, "Newton Step Solver", "auto",
                  "How each active-set step solves Q_AA d = G_A: \"CG\" (one A-solve per iteration), or \"cached "
                  "columns\": from the second step on one mesh the columns A^{-1} B e_j of the segments that were "
                  "active are kept (one vector each, at most 'Cached Columns') and Q_AA is exact, so a step costs "
                  "one A-solve plus one per newly active segment; \"auto\": cached columns when A^{-1} reaches "
                  "further than the strip (the same test as the coarse Schur correction), else CG",
                  {"auto", "CG", "cached columns"});
  core::addInt(p, "Cached Columns", 256, "At most this many cached columns per mesh (memory: one vector each)", 1);
  core::addChoice(p, "Boundary Mass", "consistent",
                  "Mass matrix on the contact boundary: consistent (the paper), or lumped at the nodes of Gamma_C "
                  "(does not remove the chattering of impacting nodes, DESIGN 1.6: see Time Integration/Contact Stabilisation)",
                  {"consistent", "lumped"});
  core::addChoice(p, "Schur Preconditioner", "auto",
                  "Preconditioner of CG on Q_AA: B^T A_s^{-1} B with A on a strip along Gamma_C (factored once per "
                  "mesh, sparse Cholesky); \"strip + coarse\" adds B^T P A_c^{-1} P^T B from a coarse mesh (the far "
                  "field; see 'Coarse Correction Cells'); \"auto\": strip + coarse when the strip would need more than 40 "
                  "node layers, else strip; the lumped B^T diag(A)^{-1} B; or none",
                  {"auto", "strip", "strip + coarse", "lumped", "none"});
  core::addInt(p, "Coarse Correction Cells", 4096,
               "Mesh of the coarse correction A_c (factored once per run, on every rank): the finest uniform refinement "
               "of the deck's coarse mesh, at most at Mesh/Refinement Level, with at most this many cells (the coarse "
               "mesh's own cells, or its blocks of 2^o x 2^o rectangle cells that form one tree, when even those are "
               "more). Memory and set-up time grow with it (65536 cells: about 1 GB per rank); the far field "
               "needs few cells",
               1, 65536);
  core::addDouble(p, "Strip Width", 6.0,
                  "Width of the strip in units of c k (wave speed times time step; Q decays like exp(-1.4 d/k)): "
                  "segment j gets ceil(width (c k / h_min) h_f / h_j) node layers (h_j its edge length, h_f that "
                  "of the finest contact edge, h_min the mesh's finest cell; at least 2, at most 40): the width "
                  "c k where h_f = h_min, narrower where the finest cells lie away from the contact boundary",
                  0.1, 1000.0);
  return p;
}

std::string ContactQP::checkParameters(const core::ParameterList& params) {
  const std::string preconditioner = params.get<std::string>("Schur Preconditioner");
  const bool coarse = preconditioner == "auto" || preconditioner == "strip + coarse";
  const bool strip = coarse || preconditioner == "strip";
  const std::string unused = core::keysSetOtherThanDefaults(params, getValidParameters(), "Contact", [&](const std::string& k) {
    return (k == "Coarse Correction Cells" && !coarse) || (k == "Strip Width" && !strip);
  });
  const std::string newton = params.get<std::string>("Newton Step Solver");
  const std::string noCache = core::keysSetOtherThanDefaults(params, getValidParameters(), "Contact",
                                                             [&](const std::string& k) { return k == "Cached Columns" && newton == "CG"; });
  std::string warning = unused.empty() ? "" : "Contact/Schur Preconditioner = " + preconditioner + "; without effect: " + unused;
  if (!noCache.empty())
    warning += (warning.empty() ? "" : "; ") + std::string("Contact/Newton Step Solver = CG; without effect: ") + noCache;
  return warning;
}

ContactQP::ContactQP(const core::ParameterList& params, double lengthScale)
    : params_(params),
      gapTol_(params.get<double>("KKT Tolerance") * lengthScale),
      preconditioner_(params.get<std::string>("Schur Preconditioner")) {}

ContactQP::~ContactQP() = default;

namespace {
constexpr int kMaxStripLayers = 40;
int stripLayers(const core::ParameterList& p, double courant) {
  // The tolerance keeps an integral width from gaining a layer through rounding of courant.
  // Capped before the conversion: a Courant number of 1e9 overflowed int (and dropped the coarse correction).
  return static_cast<int>(std::ceil(std::min(p.get<double>("Strip Width") * courant, 1e6) - 1e-9));
}

}  // namespace

std::vector<int> ContactQP::segmentLayers(const fem::ContactCoupling& coupling, double courant) const {
  // The finest segments get the layers of the mesh's Courant number, a segment of h_j (its edge
  // length) the same physical width: courant * hFinest / h_j.
  const int m = coupling.numSegments();
  std::vector<double> h(static_cast<size_t>(m));
  for (int j = 0; j < m; ++j) h[j] = coupling.segmentLength()[j] / coupling.segmentEdges()[j];
  const double hFinest = m > 0 ? *std::min_element(h.begin(), h.end()) : 1.0;
  std::vector<int> layers(static_cast<size_t>(m));
  for (int j = 0; j < m; ++j) layers[j] = std::clamp(stripLayers(params_, courant * (hFinest / h[j])), 2, kMaxStripLayers);
  return layers;
}

void ContactQP::checkMemory(const CrsMatrix& A, const fem::ContactCoupling& coupling, double courant,
                            double bytesPerRank, double coarseUnknowns) const {
  const double m = coupling.numSegments();
  double strip = 0;  // node layers times the edges of each segment: at least the strip's nodes
  if (preconditioner_ == "strip" || preconditioner_ == "strip + coarse" || preconditioner_ == "auto") {
    const std::vector<int> layers = segmentLayers(coupling, courant);
    for (size_t j = 0; j < layers.size(); ++j) strip += static_cast<double>(layers[j]) * coupling.segmentEdges()[j];
    strip = std::min(strip, static_cast<double>(A.getGlobalNumRows()));  // a narrow mesh
  }
  std::ostringstream what;  // both messages' subject
  what << "Problem/Contact Segments: " << m << " contact multiplier segments";
  if (strip > 0) what << " and a Schur strip of at least " << std::lround(strip) << " nodes";
  // 32-bit counts: the m x m arrays and the strip's block are sized and sent with int counts.
  if (m * m > std::numeric_limits<int>::max() || strip * m > std::numeric_limits<int>::max())
    SIGNORINI_USER_ERROR(what.str() << " give the contact QP dense arrays of more entries than 32-bit counts hold; "
                                       "choose a mesh with fewer edges along the contact boundary");
  // At least two m x m arrays on every rank (the Schur approximation and its factor) and the coarse
  // correction's loads and solutions (n_c x m each), and on rank 0 the strip's B_s and W (strip x m).
  const double everyRank = 8.0 * m * (2.0 * m + 2.0 * coarseUnknowns), rankZero = everyRank + 8.0 * m * 2.0 * strip;
  if (bytesPerRank <= 0 && rankZero < 2.5e8) return;  // no collective for the small QPs
  double have = bytesPerRank, need = rankZero;  // the deck's budget per rank, or rank 0's node in full
  if (bytesPerRank <= 0) {
    const core::NodeMemory node = core::nodeMemory(*A.getComm());
    double nodeOfRankZero[2] = {node.bytes, static_cast<double>(node.ranksOnNode)};
    MPI_Bcast(nodeOfRankZero, 2, MPI_DOUBLE, 0, core::rawMpiComm(*A.getComm()));
    have = nodeOfRankZero[0];
    need = rankZero + (nodeOfRankZero[1] - 1) * everyRank;
  }
  if (need <= have) return;
  SIGNORINI_USER_ERROR(what.str() << " need at least " << std::setprecision(3) << need / 1e9
                       << " GB for the contact QP's dense matrices, more than the " << have / 1e9 << " GB "
                       << (bytesPerRank > 0 ? "per rank of Parallel/Memory Per Rank" : "of the machine of rank 0")
                       << "; choose a mesh with fewer edges along the contact boundary");
}

bool ContactQP::usesCoarseCorrection(double courant) const {
  return preconditioner_ == "strip + coarse" ||
         (preconditioner_ == "auto" && stripLayers(params_, courant) > kMaxStripLayers);
}

void ContactQP::setSystem(const CrsMatrix& A, const fem::ContactCoupling& coupling, double courant,
                          const std::vector<double>& coarseQ) {
  const int m = coupling.numSegments();
  segLen_ = coupling.segmentLength();
  strip_.reset();
  segmentStripLayers_.clear();
  columns_.clear();
  solvesOnSystem_ = 0;
  const std::string method = params_.get<std::string>("Newton Step Solver");
  cachedColumns_ = method == "cached columns" || (method == "auto" && usesCoarseCorrection(courant));
  if (preconditioner_ == "strip" || preconditioner_ == "strip + coarse" || preconditioner_ == "auto") {
    const std::vector<int> layers = segmentLayers(coupling, courant);
    strip_ = std::make_unique<StripSchurApproximation>(A, coupling, layers);
    segmentStripLayers_ = layers;
    approxQ_ = strip_->matrix();
    if (usesCoarseCorrection(courant)) {
      SIGNORINI_ASSERT(coarseQ.size() == approxQ_.size(), "the coarse Schur correction is missing");
      for (size_t i = 0; i < approxQ_.size(); ++i) approxQ_[i] += coarseQ[i];
    }
  } else {
    // The lumped approximation also scales the active-set test and the multiplier tolerance.
    Vector d(A.getRowMap());
    A.getLocalDiagCopy(d);
    approxQ_ = coupling.lumpedSchurComplement(d);
  }
  for (int j = 0; j < m; ++j) {
    const double q = approxQ_[static_cast<size_t>(j) * m + j];
    if (q == 0.0)
      SIGNORINI_USER_ERROR("Problem/Contact Segments: the contact segment around ("
                           << coupling.segmentMidpoint()[j][0] << ", " << coupling.segmentMidpoint()[j][1]
                           << ") has no free unknown (every node under it is a Dirichlet node)");
    if (!(q > 0))  // B^T A^{-1} B is positive for an SPD A: the approximation of a (nearly) singular A is not
      throw core::SolverError("the contact Schur preconditioner (Contact/Schur Preconditioner) has the diagonal entry " +
                              core::shortestText(q) + " at the segment around (" +
                              core::shortestText(coupling.segmentMidpoint()[j][0]) + ", " +
                              core::shortestText(coupling.segmentMidpoint()[j][1]) +
                              "), not a positive number: the step matrix is singular or nearly so (a body without "
                              "Dirichlet conditions at a time step this large?); lower Time Integration/Time Step");
  }
}

double ContactQP::lambdaTolerance(int j) const {
  const int m = static_cast<int>(segLen_.size());
  return gapTol_ * segLen_[j] / approxQ_[static_cast<size_t>(j) * m + j];
}

bool ContactQP::solveWithColumns(LinearSolver& solver, const fem::ContactCoupling& B, const Vector& F,
                                 const std::vector<double>& gbar, std::vector<double>& lambda, Vector& u,
                                 std::vector<double>& G, ContactQPResult& res) {
  const int m = B.numSegments();
  const size_t cap = static_cast<size_t>(params_.get<int>("Cached Columns"));
  auto column = [&](int j) -> const Column& {  // A^{-1} B e_j and B^T A^{-1} B e_j, computed once per mesh
    auto it = columns_.find(j);
    if (it != columns_.end()) return it->second;
    std::vector<double> e(m, 0.0);
    e[j] = 1.0;
    Vector rhs(F.getMap());
    B.apply(e, rhs);
    Column c{Teuchos::rcp(new Vector(F.getMap())), {}};
    if (strip_)
      strip_->applyStripInverse(e, *c.w);
    else
      c.w->putScalar(0.0);
    solver.solve(rhs, *c.w);
    ++res.linearSolves;
    c.q = B.applyTranspose(*c.w);
    return columns_.emplace(j, std::move(c)).first->second;
  };
  // u_f = A^{-1} F and G_f = B^T u_f - gbar; then G = G_f - Q lambda, u = u_f - sum_j lambda_j W_j.
  solver.solve(F, u);
  ++res.linearSolves;
  std::vector<double> Gf = B.applyTranspose(u);
  for (int j = 0; j < m; ++j) Gf[j] -= gbar[j];
  auto gapOf = [&](const std::vector<double>& l) {
    std::vector<double> g = Gf;
    for (int j = 0; j < m; ++j)
      if (l[j] != 0.0) {
        const auto& q = column(j).q;
        for (int i = 0; i < m; ++i) g[i] -= q[i] * l[j];
      }
    return g;
  };
  size_t warmMissing = 0;  // the warm start's columns must fit into the cache too
  for (int j = 0; j < m; ++j) warmMissing += lambda[j] != 0.0 && !columns_.count(j) ? 1 : 0;
  if (columns_.size() + warmMissing > cap) return false;
  G = gapOf(lambda);
  std::vector<double> c(m);
  for (int j = 0; j < m; ++j) c[j] = 1.0 / approxQ_[static_cast<size_t>(j) * m + j];
  // With exact Q_AA the active-set method has converged when the set its solution implies is the
  // set it was computed on (then lambda_A < 0 and G_I >= 0: the KKT conditions).
  std::vector<char> active(m, 0);
  for (int j = 0; j < m; ++j) active[j] = lambda[j] + c[j] * G[j] < 0 ? 1 : 0;
  const int maxNewton = params_.get<int>("Maximum Active Set Iterations");
  for (int it = 1;; ++it) {
    res.activeSetIterations = it;
    std::vector<int> idx;
    for (int j = 0; j < m; ++j)
      if (active[j]) idx.push_back(j);
    const int nA = static_cast<int>(idx.size());
    size_t missing = 0;
    for (int j : idx) missing += columns_.count(j) ? 0 : 1;
    if (columns_.size() + missing > cap) return false;
    // Q_AA lambda_A = G_f,A (the gap vanishes on the active set), lambda = 0 elsewhere.
    std::vector<double> Q(static_cast<size_t>(nA) * nA), l(m, 0.0), rhsA(nA);
    for (int b = 0; b < nA; ++b) {
      const auto& q = column(idx[b]).q;
      for (int a = 0; a < nA; ++a) Q[a * nA + b] = q[idx[a]];
    }
    for (int a = 0; a < nA; ++a) {
      rhsA[a] = Gf[idx[a]];
      for (int b = 0; b < a; ++b) Q[a * nA + b] = Q[b * nA + a] = 0.5 * (Q[a * nA + b] + Q[b * nA + a]);
    }
    if (nA > 0 && !cholesky(Q, nA)) return false;  // redundant constraints: CG copes with them
    if (nA > 0) choleskySolve(Q, nA, rhsA);
    for (int a = 0; a < nA; ++a) l[idx[a]] = rhsA[a];
    lambda = l;
    G = gapOf(lambda);
    int changes = 0;
    for (int j = 0; j < m; ++j) {
      const char next = lambda[j] + c[j] * G[j] < 0 ? 1 : 0;
      changes += next != active[j];
      active[j] = next;
    }
    if (changes == 0) break;
    if (it == maxNewton) return false;
  }
  // The set is consistent, so the KKT conditions hold up to rounding; the result is returned only
  // if they hold to the tolerance the CG path accepts (else CG takes over, and reports if it fails).
  for (int j = 0; j < m; ++j) {
    const bool onActive = active[j] && std::abs(G[j]) > 0.1 * gapTol_ * segLen_[j];
    if (onActive || -G[j] > gapTol_ * segLen_[j] || lambda[j] > lambdaTolerance(j)) return false;
  }
  for (int j = 0; j < m; ++j)
    if (lambda[j] != 0.0) u.update(-lambda[j], *column(j).w, 1.0);
  return true;
}

ContactQPResult ContactQP::solve(LinearSolver& solver, const fem::ContactCoupling& B, const Vector& F,
                                 const std::vector<double>& gbar, std::vector<double>& lambda, Vector& u,
                                 std::vector<double>& G) {
  const int m = B.numSegments();
  SIGNORINI_ASSERT(static_cast<int>(lambda.size()) == m && static_cast<int>(gbar.size()) == m, "size mismatch");
  SIGNORINI_ASSERT(static_cast<int>(segLen_.size()) == m, "setSystem() not called for this coupling");
  ContactQPResult res;
  const long its0 = solver.totalIterations();
  if (solvesOnSystem_++ > 0 && cachedColumns_) {
    const std::vector<double> lambda0 = lambda;
    Vector u0(u, Teuchos::Copy);
    if (solveWithColumns(solver, B, F, gbar, lambda, u, G, res)) return finish(res, solver, its0, lambda, G);
    lambda = lambda0;  // the cache is full or Q_AA is singular: CG below
    u.assign(u0);
  }
  Vector rhs(F.getMap()), w(F.getMap());
  auto solveA = [&](const Vector& b, Vector& x) {
    solver.solve(b, x);
    ++res.linearSolves;
  };
  // Initial guess of A^{-1} B p: the strip solution, else zero.
  auto guess = [&](const std::vector<double>& p, Vector& x) {
    if (strip_)
      strip_->applyStripInverse(p, x);
    else
      x.putScalar(0.0);
  };
  // u = A^{-1}(F - B lambda), G = B^T u - gbar.
  rhs.assign(F);
  B.apply(lambda, rhs, -1.0, true);
  solveA(rhs, u);  // u holds the caller's initial guess
  auto updateGap = [&]() {
    G = B.applyTranspose(u);
    for (int j = 0; j < m; ++j) G[j] -= gbar[j];
  };
  updateGap();

  // c_j = 1/Q_jj (lumped): lambda_j and c_j G_j have the same units.
  std::vector<double> c(m);
  for (int j = 0; j < m; ++j) c[j] = 1.0 / approxQ_[static_cast<size_t>(j) * m + j];
  std::vector<char> active(m, 0), previous(m, 2);
  std::ostringstream history;
  const int maxNewton = params_.get<int>("Maximum Active Set Iterations");
  const int maxCG = params_.get<int>("Maximum CG Iterations");
  for (int it = 1; it <= maxNewton; ++it) {
    res.activeSetIterations = it;
    int nA = 0;
    for (int j = 0; j < m; ++j) nA += (active[j] = (lambda[j] + c[j] * G[j] < 0) ? 1 : 0);
    // Zero the multipliers off the active set (one A-solve if any was non-zero).
    std::vector<double> delta(m, 0.0);
    bool anyInactive = false;
    for (int j = 0; j < m; ++j)
      if (!active[j] && lambda[j] != 0.0) delta[j] = -lambda[j], anyInactive = true;
    if (anyInactive) {
      B.apply(delta, rhs);
      guess(delta, w);
      solveA(rhs, w);
      u.update(-1.0, w, 1.0);
      const auto q = B.applyTranspose(w);
      for (int j = 0; j < m; ++j) {
        G[j] -= q[j];
        if (!active[j]) lambda[j] = 0.0;
      }
    }
    // CG on Q_AA d = G_A (the residual of G_A = 0), preconditioned by the lumped Q_AA.
    std::vector<int> idx;
    for (int j = 0; j < m; ++j)
      if (active[j]) idx.push_back(j);
    std::vector<double> L;
    bool havePrec = false;
    if (preconditioner_ != "none" && nA > 0) {
      L.resize(static_cast<size_t>(nA) * nA);
      for (int a = 0; a < nA; ++a)
        for (int b = 0; b < nA; ++b) L[a * nA + b] = approxQ_[static_cast<size_t>(idx[a]) * m + idx[b]];
      havePrec = cholesky(L, nA);
    }
    auto converged = [&]() {
      for (int a = 0; a < nA; ++a)
        if (std::abs(G[idx[a]]) > 0.1 * gapTol_ * segLen_[idx[a]]) return false;
      return true;
    };
    std::vector<double> r(nA), z(nA), p(nA, 0.0), full(m, 0.0);
    for (int a = 0; a < nA; ++a) r[a] = G[idx[a]];
    double rz = 0;
    int cg = 0;
    while (nA > 0 && !converged()) {
      if (cg == maxCG) break;
      z = r;
      if (havePrec) choleskySolve(L, nA, z);
      double rzNew = 0;
      for (int a = 0; a < nA; ++a) rzNew += r[a] * z[a];
      const double beta = cg == 0 ? 0.0 : rzNew / rz;
      rz = rzNew;
      for (int a = 0; a < nA; ++a) p[a] = z[a] + beta * p[a];
      for (int a = 0; a < nA; ++a) full[idx[a]] = p[a];
      B.apply(full, rhs);
      guess(full, w);
      solveA(rhs, w);
      const auto q = B.applyTranspose(w);  // Q p
      double pq = 0;
      for (int a = 0; a < nA; ++a) pq += p[a] * q[idx[a]];
      if (!(pq > 0)) break;  // Q_AA singular on this direction (redundant constraints)
      const double alpha = rz / pq;
      for (int a = 0; a < nA; ++a) lambda[idx[a]] += alpha * p[a];
      u.update(-alpha, w, 1.0);
      for (int j = 0; j < m; ++j) G[j] -= alpha * q[j];
      for (int a = 0; a < nA; ++a) r[a] = G[idx[a]];
      ++cg;
    }
    res.cgIterations += cg;
    // KKT check.
    double maxViolation = 0;
    bool ok = true;
    for (int j = 0; j < m; ++j) {
      const double gapViolation = -G[j] / segLen_[j];
      const double lamViolation = lambda[j] / lambdaTolerance(j) * gapTol_;
      maxViolation = std::max({maxViolation, gapViolation, lamViolation});
      if (gapViolation > gapTol_ || lamViolation > gapTol_) ok = false;
    }
    double activeGap = 0;  // what converged() tests: |G_j| / |E_j| on the active set
    for (int a = 0; a < nA; ++a) activeGap = std::max(activeGap, std::abs(G[idx[a]]) / segLen_[idx[a]]);
    if (!converged()) ok = false;
    int changes = 0;
    for (int j = 0; j < m; ++j) changes += active[j] != previous[j];
    history << "  iteration " << it << ": " << nA << " active (" << changes << " changed), " << cg
            << " CG iterations, largest KKT violation " << maxViolation << " (tolerance " << gapTol_
            << "), largest gap on the active set " << activeGap << " (tolerance " << 0.1 * gapTol_ << ")\n";
    previous = active;
    if (ok) {
      // G was updated alongside lambda and u. On a singular Q_AA (more active segments than free
      // unknowns under them: H = h on a boundary between two Dirichlet ends) CG lets lambda diverge
      // and the updated G drift from the gap of u; a result is only returned if they agree.
      auto uGap = B.applyTranspose(u);
      double drift = 0;
      for (int j = 0; j < m; ++j) drift = std::max(drift, std::abs(uGap[j] - gbar[j] - G[j]) / segLen_[j]);
      if (!(drift <= gapTol_)) {
        std::ostringstream os;
        os << std::setprecision(3) << "contact QP: the multipliers diverged (the gaps updated with them "
           << "differ from those of the displacement by " << drift
           << ", more than the KKT tolerance " << gapTol_ << "): ";
        if (params_.get<std::string>("Multiplier Segments") == "H = h")
          os << "Q_AA is singular. With Contact/Multiplier Segments = H = h a contact boundary between two "
                "Dirichlet ends has more segments than free nodes; use H = 2h";
        else
          os << "Q_AA is singular or nearly so, or the A-solves are not accurate enough for the KKT tolerance (a "
                "step matrix close to singular, as for a body held by nothing but the contact at a large time step): "
                "lower Linear Solver/Relative Tolerance or Time Integration/Time Step, or raise Contact/KKT Tolerance";
        throw core::SolverError(os.str());
      }
      break;
    }
    if (it == maxNewton)
      throw core::SolverError("contact QP: the active set method did not satisfy the KKT conditions within "
                              "Contact/Maximum Active Set Iterations = " + std::to_string(maxNewton) +
                              "; history:\n" + history.str());
  }
  return finish(res, solver, its0, lambda, G);
}

ContactQPResult ContactQP::finish(ContactQPResult res, const LinearSolver& solver, long its0,
                                  const std::vector<double>& lambda, const std::vector<double>& G) const {
  const int m = static_cast<int>(lambda.size());
  res.linearIterations = static_cast<int>(solver.totalIterations() - its0);
  res.maxLambda = -1e300;
  res.minLambda = 0.0;
  res.minGap = 1e300;
  for (int j = 0; j < m; ++j) {
    res.active += lambda[j] < 0 ? 1 : 0;
    res.maxLambda = std::max(res.maxLambda, lambda[j]);
    res.minLambda = std::min(res.minLambda, lambda[j]);
    res.minGap = std::min(res.minGap, G[j] / segLen_[j]);
    res.maxComplementarity = std::max(res.maxComplementarity, std::abs(lambda[j] * G[j]) / segLen_[j]);
  }
  if (m == 0) res.maxLambda = res.minGap = 0;
  return res;
}

}  // namespace signorini::solvers
