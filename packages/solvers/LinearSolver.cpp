#include "signorini/solvers/LinearSolver.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_MasterList.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::solvers {

using BelosSolver = Belos::SolverManager<Scalar, MultiVector, Operator>;

namespace {

/// Power iterations of the Chebyshev smoother's eigenvalue estimate (Ifpack2's default is 10).
constexpr int kChebyshevEigenIterations = 20;

std::string upperCase(const std::string& text) {
  std::string upper;
  for (char c : text) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return upper;
}

/// Teuchos' message about an invalid parameter without its source location and without the list of
/// valid parameters that follows (hundreds of lines for MueLu).
std::string firstLines(const std::string& message) {
  std::string what = core::withoutSourceLocation(message);
  for (const char* tail : {"The valid parameters", "\nValid parameters"}) {
    const auto at = what.find(tail);
    if (at != std::string::npos) what.resize(at);
  }
  while (!what.empty() && std::isspace(static_cast<unsigned char>(what.back()))) what.pop_back();
  return what;
}

/// The user's MueLu entries with the types of MueLu's master list: a deck or --set writes "0" for a
/// double, "1e3" for an int or "yes" for a bool, which MueLu's validation refuses ("the correct type
/// is double"). Integers become doubles, integral doubles integers, and 0/1 and the bool words bools;
/// anything else is left for MueLu to judge.
Teuchos::ParameterList typedLikeMueLu(const Teuchos::ParameterList& user) {
  Teuchos::ParameterList typed(user);
  const auto master = MueLu::MasterList::List();
  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string& key = user.name(it);
    const auto& e = user.entry(it);
    if (e.isList() || !master->isParameter(key)) continue;
    const auto& want = master->getEntry(key).getAny().type();
    if (want == typeid(double) && e.isType<int>()) {
      typed.set(key, static_cast<double>(e.getValue<int>(nullptr)));
    } else if (want == typeid(int) && e.isType<double>()) {
      const double x = e.getValue<double>(nullptr);
      if (std::isfinite(x) && x == std::floor(x) && std::abs(x) <= std::numeric_limits<int>::max())
        typed.set(key, static_cast<int>(x));
    } else if (want == typeid(bool) && (e.isType<int>() || e.isType<std::string>())) {
      bool b;
      if (e.isType<int>() && (e.getValue<int>(nullptr) == 0 || e.getValue<int>(nullptr) == 1))
        typed.set(key, e.getValue<int>(nullptr) == 1);
      else if (e.isType<std::string>() && core::readBool(e.getValue<std::string>(nullptr), b))
        typed.set(key, b);
    }
  }
  return typed;
}

/// Y = D^{-1} X with D the diagonal of A (one Jacobi sweep from zero, as Ifpack2's RELAXATION
/// computes it, without Ifpack2's parameter validation and set-up on every new mesh).
class JacobiPreconditioner : public Operator {
 public:
  explicit JacobiPreconditioner(const CrsMatrix& A) : inverseDiagonal_(A.getRowMap()) {
    A.getLocalDiagCopy(inverseDiagonal_);
    auto d = inverseDiagonal_.getLocalViewDevice(Tpetra::Access::ReadWrite);
    int zeroLocal = 0;
    Kokkos::parallel_reduce(
        "signorini::jacobi::invert", Kokkos::RangePolicy<ExecSpace>(0, d.extent(0)),
        KOKKOS_LAMBDA(const size_t i, int& zero) {
          if (d(i, 0) == 0.0) ++zero;
          d(i, 0) = 1.0 / d(i, 0);
        },
        zeroLocal);
    int zero = 0;
    Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_SUM, zeroLocal, Teuchos::outArg(zero));
    SIGNORINI_ASSERT(!zero, "Jacobi preconditioner: the matrix has a zero diagonal entry");
  }
  RCP<const Map> getDomainMap() const override { return inverseDiagonal_.getMap(); }
  RCP<const Map> getRangeMap() const override { return inverseDiagonal_.getMap(); }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp = Teuchos::NO_TRANS, Scalar alpha = 1.0,
             Scalar beta = 0.0) const override {
    Y.elementWiseMultiply(alpha, inverseDiagonal_, X, beta);
  }

 private:
  Vector inverseDiagonal_;
};
}  // namespace

struct LinearSolver::Impl {
  core::ParameterList params;
  RCP<const CrsMatrix> A;
  RCP<Operator> prec;
  RCP<BelosSolver> solver;
  RCP<Belos::LinearProblem<Scalar, MultiVector, Operator>> problem;
  std::string precName = "none";
  std::string systemName;  ///< for failure messages; empty: none
  /// "linear solver <method> + <preconditioner>[ for <system>]"
  std::string solverText() const {
    return "linear solver " + params.get<std::string>("Method") + " + " + precName +
           (systemName.empty() ? "" : " for " + systemName);
  }
  long solves = 0, iterations = 0;
  RCP<MultiVector> nullspace;
  int equationsPerNode = 1;
  bool reproducible = false;  ///< core::reproducibleArithmetic() when the operator was set
  RCP<Vector> diagonal;       ///< A's diagonal for the reproducible Jacobi CG
};

core::ParameterList LinearSolver::getValidParameters() {
  core::ParameterList p("Linear Solver");
  core::addString(p, "Method", "CG", "Belos Krylov method for the SPD step systems with a left preconditioner: CG, PSEUDOBLOCK CG, "
                  "BLOCK CG, GMRES, PSEUDOBLOCK GMRES, BLOCK GMRES, MINRES, TFQMR, PSEUDOBLOCK TFQMR or GCRODR (any "
                  "case, Belos' aliases); Parallel/Reproducible Arithmetic: \"CG\" only");
  core::addChoice(p, "Preconditioner", "auto",
                  "\"auto\": Jacobi if c k / h_min is below 'Auto MueLu Courant Number', else MueLu (DESIGN 1.6)",
                  {"auto", "MueLu", "Jacobi", "none"});
  core::addDouble(p, "Auto MueLu Courant Number", 5.0, "Courant number c k / h_min above which \"auto\" uses MueLu", 0.0);
  core::addDouble(p, "Relative Tolerance", 1e-10,
                  "Residual tolerance relative to ||b||; the Newmark update amplifies solver errors by 1/(beta k^2)",
                  1e-16, 0.1);
  core::addInt(p, "Maximum Iterations", 2000, "Maximum Krylov iterations per solve", 1);
  core::addPassThrough(p, "Belos", "Passed to the Belos solver (e.g. \"Verbosity\")");
  core::addPassThrough(p, "MueLu", "Passed to MueLu::CreateTpetraPreconditioner (e.g. \"smoother: type\")");
  return p;
}

const std::vector<std::string>& LinearSolver::supportedMethods() {
  // Belos 13.2's methods that solve our SPD systems with a left preconditioner and our parameters
  // quietly (BICGSTAB and FLEXIBLE GMRES need a right one, FIXED POINT diverges, the polynomial and
  // seed variants refuse "Convergence Tolerance" or print debugging output, LSQR its iterations).
  static const std::vector<std::string> methods = {"CG",    "PSEUDOBLOCK CG", "BLOCK CG",          "GMRES",
                                                   "PSEUDOBLOCK GMRES", "BLOCK GMRES", "MINRES", "TFQMR",
                                                   "PSEUDOBLOCK TFQMR", "GCRODR"};
  return methods;
}

std::string LinearSolver::canonicalMethod(const std::string& method) {
  std::string name = upperCase(method);
  static const std::map<std::string, std::string> aliases = {
      {"PSEUDO BLOCK CG", "PSEUDOBLOCK CG"},
      {"PSEUDOBLOCKCG", "PSEUDOBLOCK CG"},
      {"PSEUDO BLOCK GMRES", "PSEUDOBLOCK GMRES"},
      {"PSEUDOBLOCKGMRES", "PSEUDOBLOCK GMRES"},
      {"TRANSPOSE-FREE QMR", "TFQMR"},
      {"PSEUDO BLOCK TFQMR", "PSEUDOBLOCK TFQMR"},
      {"PSEUDO BLOCK TRANSPOSE-FREE QMR", "PSEUDOBLOCK TFQMR"},
      {"RECYCLING GMRES", "GCRODR"}};
  const auto alias = aliases.find(name);
  if (alias != aliases.end()) name = alias->second;
  const auto& methods = supportedMethods();
  return std::find(methods.begin(), methods.end(), name) == methods.end() ? std::string() : name;
}

std::string LinearSolver::checkParameters(const core::ParameterList& params, bool reproducible) {
  const std::string method = params.get<std::string>("Method");
  const std::string preconditioner = params.get<std::string>("Preconditioner");
  const std::string canonical = canonicalMethod(method);
  if (canonical.empty()) {
    std::ostringstream names;
    for (const auto& name : supportedMethods()) names << (names.tellp() > 0 ? ", " : "") << name;
    // Recycling CG is a Belos method for SPD systems, but Trilinos 13.2's solver factory does not
    // register it for Tpetra ("has not been registered" at run time).
    const bool rcg = upperCase(method) == "RCG" || upperCase(method) == "RECYCLING CG";
    SIGNORINI_USER_ERROR("Linear Solver/Method: \"" << method << "\" is not one of the Krylov methods for these "
                         "symmetric positive definite systems: " << names.str() << " (any case)"
                         << (rcg ? "; RCG (recycling CG) is not registered in this Trilinos's Belos solver factory "
                                   "for Tpetra, GCRODR recycles as well"
                                 : ""));
  }
  // The Belos keys that signorini sets from its own (they would be overridden silently).
  const auto& belos = params.sublist("Belos");
  for (const auto& [key, ours] : {std::pair<const char*, const char*>{"Convergence Tolerance", "Relative Tolerance"},
                                  {"Maximum Iterations", "Maximum Iterations"}})
    if (belos.isParameter(key))
      SIGNORINI_USER_ERROR("Linear Solver/Belos/" << key << ": set by signorini from Linear Solver/" << ours
                                                  << "; set that instead");
  // The MueLu keys that signorini sets from the problem (the rigid body modes of elasticity).
  const auto& muelu = params.sublist("MueLu");
  for (const auto& [key, from] : {std::pair<const char*, const char*>{"number of equations", "the unknowns per node of Problem/Type"},
                                  {"user data", "the rigid body modes of Problem/Type"}})
    if (muelu.isParameter(key))  // a sublist too
      SIGNORINI_USER_ERROR("Linear Solver/MueLu/" << key << ": set by signorini from " << from);
  // MueLu's own validation prints its whole parameter table (hundreds of lines) before it throws.
  const auto valid = MueLu::MasterList::List();
  for (auto it = muelu.begin(); it != muelu.end(); ++it)
    if (!muelu.entry(it).isList() && !valid->isParameter(muelu.name(it)))
      SIGNORINI_USER_ERROR("Linear Solver/MueLu: '" << muelu.name(it) << "' is not a MueLu parameter "
                           "(MueLu's masterList.xml lists them)");
  // Values MueLu takes without a word and then fails on: a level count below 1 (a crash in its
  // set-up) and numbers that are not finite.
  for (const auto* list : {&belos, &muelu})
    for (auto it = list->begin(); it != list->end(); ++it)
      if (list->entry(it).isType<double>() && !std::isfinite(list->entry(it).getValue<double>(nullptr)))
        SIGNORINI_USER_ERROR("Linear Solver/" << (list == &belos ? "Belos/" : "MueLu/") << list->name(it) << ": "
                                              << list->entry(it).getValue<double>(nullptr) << " is not a finite number");
  const auto typedMueLu = typedLikeMueLu(muelu);
  if (typedMueLu.isType<int>("max levels") && typedMueLu.get<int>("max levels") < 1)
    SIGNORINI_USER_ERROR("Linear Solver/MueLu/max levels: " << typedMueLu.get<int>("max levels")
                         << " is below 1 (1: the coarse level alone)");
  // The Courant number that "auto" compares is set to no effect by any other choice (and by
  // reproducible arithmetic, which always solves with Jacobi).
  const std::string courant = core::keysSetOtherThanDefaults(params, getValidParameters(), "Linear Solver",
                                                             [&](const std::string& k) {
                                                               return k == "Auto MueLu Courant Number" &&
                                                                      (reproducible || preconditioner != "auto");
                                                             });
  if (!reproducible) {
    std::string ignored = courant;
    if ((preconditioner == "Jacobi" || preconditioner == "none") && muelu.numParams() > 0)
      ignored += std::string(ignored.empty() ? "" : ", ") + "Linear Solver/MueLu";
    return ignored.empty() ? "" : "Linear Solver/Preconditioner = " + preconditioner + "; without effect: " + ignored;
  }
  if (preconditioner != "auto" && preconditioner != "Jacobi")
    SIGNORINI_USER_ERROR("Linear Solver/Preconditioner: reproducible arithmetic needs \"Jacobi\" (or \"auto\"), not \""
                         << preconditioner << "\"");
  if (canonical != "CG")
    SIGNORINI_USER_ERROR("Linear Solver/Method: reproducible arithmetic solves with its own Jacobi CG and needs "
                         "\"CG\", not \"" << method << "\"");
  std::string ignored = courant;
  for (const char* sublist : {"Belos", "MueLu"})
    if (params.sublist(sublist).numParams() > 0) ignored += std::string(ignored.empty() ? "" : ", ") + "Linear Solver/" + sublist;
  return ignored.empty() ? "" : "reproducible arithmetic solves with its own Jacobi CG; without effect: " + ignored;
}

LinearSolver::LinearSolver(const core::ParameterList& params) : impl_(std::make_unique<Impl>()) {
  impl_->params = params;
}

LinearSolver::~LinearSolver() = default;

void LinearSolver::setNearNullspace(RCP<MultiVector> modes, int equationsPerNode) {
  impl_->nullspace = modes;
  impl_->equationsPerNode = equationsPerNode;
}

void LinearSolver::setOperator(RCP<const CrsMatrix> A, double courant) {
  auto& I = *impl_;
  I.A = A;
  std::string choice = I.params.get<std::string>("Preconditioner");
  if (choice == "auto") choice = courant > I.params.get<double>("Auto MueLu Courant Number") ? "MueLu" : "Jacobi";
  I.reproducible = core::reproducibleArithmetic();  // fixed for this operator
  if (I.reproducible && I.params.get<std::string>("Preconditioner") == "auto") choice = "Jacobi";
  I.precName = choice;
  I.prec = Teuchos::null;
  if (I.reproducible) {
    // Partition-independent solves: our Jacobi CG with ordered sums (JacobiCG.hpp). MueLu's
    // aggregates depend on the partition, so it cannot take part; "auto" means Jacobi here.
    if (choice != "Jacobi")
      SIGNORINI_USER_ERROR("Linear Solver/Preconditioner: reproducible arithmetic needs \"Jacobi\", not \"" << choice
                                                                                                       << "\"");
    I.diagonal = Teuchos::rcp(new Vector(A->getRowMap()));
    A->getLocalDiagCopy(*I.diagonal);
    return;
  }
  auto Anc = Teuchos::rcp_const_cast<CrsMatrix>(A);
  if (choice == "MueLu") {
    Teuchos::ParameterList mueluParams;
    mueluParams.set("verbosity", "none");
    mueluParams.set("smoother: type", "CHEBYSHEV");
    // The coarsest level is small and relaxed, not factored: MueLu 13.2's default KLU2 coarse
    // solve failed to converge on 2 ranks for small problems.
    mueluParams.set("coarse: max size", 200);
    mueluParams.set("coarse: type", "RELAXATION");
    mueluParams.sublist("coarse: params").set("relaxation: type", "Symmetric Gauss-Seidel");
    mueluParams.sublist("coarse: params").set("relaxation: sweeps", 4);
    if (I.equationsPerNode > 1) mueluParams.set("number of equations", I.equationsPerNode);
    if (!I.nullspace.is_null()) mueluParams.sublist("user data").set("Nullspace", I.nullspace);
    mueluParams.setParameters(typedLikeMueLu(I.params.sublist("MueLu")));
    // Chebyshev is positive definite only above the largest eigenvalue of D^{-1} A, which Ifpack2
    // estimates by power iterations: its default 10 fell short on graded meshes of trapezoids
    // (CG then broke down on a "non-positive p^T A p"); 20 held there at every tried time step.
    // Only for Chebyshev (another smoother refuses the key) and unless the deck sets it.
    if (upperCase(mueluParams.get<std::string>("smoother: type")) == "CHEBYSHEV" &&
        !mueluParams.sublist("smoother: params").isParameter("chebyshev: eigenvalue max iterations"))
      mueluParams.sublist("smoother: params").set("chebyshev: eigenvalue max iterations", kChebyshevEigenIterations);
    // MueLu gets its own copy of A (the assemblers' matrices view arrays their pattern shares).
    RCP<Operator> op = Teuchos::rcp(new CrsMatrix(*A, Teuchos::Copy));
    std::string failure;
    try {
      I.prec = MueLu::CreateTpetraPreconditioner(op, mueluParams);
    } catch (const std::exception& e) {
      failure = I.params.sublist("MueLu").numParams() == 0
                    ? "Linear Solver/Preconditioner: MueLu's set-up failed on this operator (Jacobi avoids it): " +
                          firstLines(e.what())
                    : "Linear Solver/MueLu: MueLu cannot be set up with these parameters: " + firstLines(e.what());
    }
    // A set-up that fails on some ranks only leaves the others inside MueLu's collectives.
    core::throwFirstUserErrorOrAbort(*A->getComm(), failure);
  } else if (choice == "Jacobi") {
    I.prec = Teuchos::rcp(new JacobiPreconditioner(*A));
  }
  auto belosParams = Teuchos::rcp(new Teuchos::ParameterList(I.params.sublist("Belos")));
  belosParams->set("Convergence Tolerance", I.params.get<double>("Relative Tolerance"));
  belosParams->set("Maximum Iterations", I.params.get<int>("Maximum Iterations"));
  Belos::SolverFactory<Scalar, MultiVector, Operator> factory;
  const std::string method = canonicalMethod(I.params.get<std::string>("Method"));
  SIGNORINI_ASSERT(!method.empty(), "Linear Solver/Method is checked by checkParameters()");
  I.solver = factory.create(method, Teuchos::null);
  // ||r|| <= tol ||b|| where the method lets us choose the scaling (MINRES, e.g., does not).
  const auto valid = I.solver->getValidParameters();
  for (const char* scaling : {"Implicit Residual Scaling", "Explicit Residual Scaling"})
    if (valid->isParameter(scaling) && !belosParams->isParameter(scaling)) belosParams->set(scaling, "Norm of RHS");
  // A key the method does not know, with its closest valid name (Teuchos' message names neither).
  for (auto it = belosParams->begin(); it != belosParams->end(); ++it)
    if (!valid->isParameter(belosParams->name(it))) {
      std::vector<std::string> names;
      for (auto jt = valid->begin(); jt != valid->end(); ++jt) names.push_back(valid->name(jt));
      const std::string guess = core::closestName(belosParams->name(it), names);
      SIGNORINI_USER_ERROR("Linear Solver/Belos: '" << belosParams->name(it) << "' is not a parameter of Belos' \""
                                                    << method << "\""
                                                    << (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
    }
  try {
    I.solver->setParameters(belosParams);
  } catch (std::exception& e) {
    SIGNORINI_USER_ERROR("Linear Solver/Belos: Belos' \"" << method << "\" refuses its parameters: " << firstLines(e.what()));
  }
  I.problem = Teuchos::rcp(new Belos::LinearProblem<Scalar, MultiVector, Operator>());
  I.problem->setOperator(Anc);
  if (!I.prec.is_null()) I.problem->setLeftPrec(I.prec);
}

int LinearSolver::solve(const Vector& b, Vector& x) {
  auto& I = *impl_;
  SIGNORINI_ASSERT(!I.A.is_null(), "solve() before setOperator()");
  ++I.solves;
  if (I.reproducible) {
    int its = 0;
    try {
      its = solveReproducibleJacobiCG(*I.A, *I.diagonal, b, x, I.params.get<double>("Relative Tolerance"),
                                      I.params.get<int>("Maximum Iterations"));
    } catch (const core::SolverError&) {  // thrown on every rank alike: the norms below are collective
      std::ostringstream os;
      os << "linear solver CG + Jacobi (reproducible)" << (I.systemName.empty() ? "" : " for " + I.systemName);
      if (!std::isfinite(b.norm2()) || !std::isfinite(x.norm2()))  // squares beyond doubles: no residual converges
        os << " stopped: the squares of the right-hand side or of the iterate leave the range of doubles, so no "
              "residual can be measured (are the problem's data within the range of doubles?)";
      else
        os << " did not reach the relative tolerance " << I.params.get<double>("Relative Tolerance") << " in "
           << I.params.get<int>("Maximum Iterations") << " iterations (Linear Solver/Maximum Iterations)";
      throw core::SolverError(os.str());
    }
    I.iterations += its;
    return its;
  }
  if (b.norm2() == 0.0) {
    x.putScalar(0.0);
    return 0;
  }
  I.problem->setLHS(Teuchos::rcpFromRef(x));
  I.problem->setRHS(Teuchos::rcpFromRef(b));
  I.problem->setProblem();
  I.solver->setProblem(I.problem);
  Belos::ReturnType ret = Belos::Unconverged;
  try {
    ret = I.solver->solve();
  } catch (const Belos::StatusTestError& e) {  // Belos 13.2 throws it for a residual norm that is NaN
    std::ostringstream os;
    os << I.solverText() << " stopped: "
       << (std::string(e.what()).find("NaN") != std::string::npos
               ? "a residual is not a number, so the system or its right-hand side is not finite (are the "
                 "problem's data within the range of doubles?)"
               : core::withoutSourceLocation(e.what()));
    throw core::SolverError(os.str());
  } catch (const std::exception& e) {  // e.g. GCRODR's "Num Recycled Blocks" against its "Num Blocks"
    if (I.params.sublist("Belos").numParams() == 0) {  // not the user's settings: the system
      const std::string what = firstLines(e.what());
      throw core::SolverError(
          I.solverText() + " broke down: " + what +
          (what.find("non-positive") == std::string::npos ? std::string()
           : I.precName == "MueLu"
               ? std::string(" (the preconditioner or the system matrix is not positive definite to rounding. MueLu's "
                             "Chebyshev smoother is not when it underestimates the largest eigenvalue: raise 'Linear "
                             "Solver/MueLu/smoother: params/chebyshev: eigenvalue max iterations' (signorini sets ") +
                     std::to_string(kChebyshevEigenIterations) +
                     ") or choose Linear Solver/Preconditioner = Jacobi. The matrix is not when " +
                     kNotPositiveDefiniteHint + ")"
               : std::string(" (the system matrix is not positive definite to rounding: ") + kNotPositiveDefiniteHint +
                     ")"));
    }
    SIGNORINI_USER_ERROR("Linear Solver/Belos: Belos' \"" << canonicalMethod(I.params.get<std::string>("Method"))
                         << "\" cannot solve with these parameters: " << firstLines(e.what()));
  }
  const int its = I.solver->getNumIters();
  I.iterations += its;
  if (ret != Belos::Converged) {
    std::ostringstream os;
    os << I.solverText() << " did not reach "
       << "the relative tolerance " << I.params.get<double>("Relative Tolerance") << " in " << its
       << " iterations (Linear Solver/Maximum Iterations)";
    throw core::SolverError(os.str());
  }
  return its;
}

void LinearSolver::setSystemName(const std::string& name) { impl_->systemName = name; }
const std::string& LinearSolver::preconditioner() const { return impl_->precName; }
double LinearSolver::relativeTolerance() const { return impl_->params.get<double>("Relative Tolerance"); }
long LinearSolver::numSolves() const { return impl_->solves; }
long LinearSolver::totalIterations() const { return impl_->iterations; }

}  // namespace signorini::solvers
