#include "Simulation.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "ContactCoupling.hpp"
#include "ContactQP.hpp"
#include "CsvWriter.hpp"
#include "Error.hpp"
#include "Forest.hpp"
#include "LinearSolver.hpp"
#include "MpiComm.hpp"
#include "Newmark.hpp"
#include "PhaseTimers.hpp"
#include "ProblemData.hpp"
#include "Q1Assembler.hpp"
#include "ResultWriter.hpp"

namespace signorini::dynamics {
namespace {

core::ParameterList outputParameters() {
  core::ParameterList p("Output");
  core::addString(p, "Directory", ".", "Folder for all output files (created if missing); --output-dir overrides it");
  core::addString(p, "Basename", "", "Prefix of the output files; empty: the deck's file name without .xml");
  core::addBool(p, "Write Exodus", true, "Write <basename>.e (Exodus II time series for ParaView)");
  core::addInt(p, "Exodus Interval", 1, "Write every n-th step to Exodus (the first and last step always)", 1);
  core::addInt(p, "Progress Interval", 0, "Print a progress line every n steps (0: about 20 lines per run)", 0);
  core::addBool(p, "Measure Contact Overhead", false,
                "Also solve each step without contact (same A, preconditioner and initial guess) and report its "
                "time as time_unconstrained: the contact solve costs time_contact / time_unconstrained of it");
  core::addNamedStrings(p, "Probes", "Named points \"x, y\": u interpolated there becomes the CSV column probe:<name>");
  return p;
}

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::string stemOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.rfind(".xml");
  return dot == std::string::npos ? name : name.substr(0, dot);
}

/// Creates \p dir (and parents) on rank 0 and checks that a file can be written there; the
/// verdict is shared so every rank fails together.
void ensureWritableDirectory(const std::string& dir, const Comm& comm) {
  int ok = 1;
  std::string why;
  if (comm.getRank() == 0) {
    std::string partial;
    std::stringstream ss(dir);
    if (!dir.empty() && dir[0] == '/') partial = "/";
    for (std::string part; std::getline(ss, part, '/');) {
      if (part.empty()) continue;
      partial += part + "/";
      ::mkdir(partial.c_str(), 0755);
    }
    const std::string probe = dir + "/.signorini-write-test";
    FILE* f = std::fopen(probe.c_str(), "w");
    if (!f) {
      ok = 0;
    } else {
      std::fclose(f);
      std::remove(probe.c_str());
    }
  }
  Teuchos::broadcast(comm, 0, 1, &ok);
  if (!ok) SIGNORINI_USER_ERROR("Output/Directory: cannot write to '" << dir << "'");
}

}  // namespace

core::ParameterList Simulation::getValidParameters() {
  core::ParameterList p("signorini");
  p.set("Problem", fem::ProblemData::getValidParameters(), "Problem data (DESIGN 1.1)");
  p.set("Mesh", mesh::CoarseMesh::getValidParameters(), "Coarse mesh, refinement and boundary segments");
  p.set("Time Integration", Newmark::getValidParameters(), "Newmark time stepping (paper 3.1)");
  p.set("Contact", solvers::ContactQP::getValidParameters(), "Contact multipliers and the per-step QP");
  p.set("Linear Solver", solvers::LinearSolver::getValidParameters(), "A^{-1}: Belos + MueLu/Jacobi");
  p.set("Output", outputParameters(), "Files and progress reports");
  return p;
}

struct Simulation::Impl {
  RCP<const Comm> comm;
  core::ParameterList deck;
  std::string deckPath, outDir, basename;
  std::shared_ptr<mesh::CoarseMesh> coarse;
  std::unique_ptr<mesh::BoundarySegments> segments;
  std::unique_ptr<fem::ProblemData> problem;
  std::unique_ptr<Newmark> newmark;
  std::unique_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;
  std::unique_ptr<fem::Q1Assembler> assembler;
  RCP<CrsMatrix> M, K, A;
  std::unique_ptr<solvers::LinearSolver> solver, massSolver;
  std::unique_ptr<fem::ContactCoupling> coupling;
  std::unique_ptr<solvers::ContactQP> qp;
  RCP<Vector> u, v, a;
  std::vector<double> lambda, gap;
  std::vector<std::pair<std::string, std::array<double, 2>>> probes;
  core::PhaseTimers timers;
  double courant = 0;

  void projectL2(const core::Expression& f, Vector& out) {
    Vector b(mesh->ownedMap());
    assembler->assembleLoad(f, 0.0, 1.0, b);
    out.putScalar(0.0);
    massSolver->solve(b, out);
  }
  /// The energy the Newmark scheme with alpha = 1/2 conserves without contact and loads:
  /// kinetic + strain + (beta - 1/4) k^2 / 2 a^T M a.
  double newmarkEnergy() const {
    Vector tmp(mesh->ownedMap());
    M->apply(*a, tmp);
    const double k = newmark->timeStep;
    return energy(*u, *v) + (newmark->beta - 0.25) * 0.5 * k * k * tmp.dot(*a);
  }
  double energy(const Vector& uu, const Vector& vv) const {
    Vector tmp(mesh->ownedMap());
    M->apply(vv, tmp);
    const double kin = 0.5 * tmp.dot(vv);
    K->apply(uu, tmp);
    return kin + 0.5 * tmp.dot(uu);
  }
};

Simulation::Simulation(const core::ParameterList& deck, const std::string& deckPath, const std::string& outputDir,
                       RCP<const Comm> comm)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.comm = comm;
  I.deck = deck;
  I.deckPath = deckPath;
  auto meshParams = deck.sublist("Mesh");
  const std::string file = meshParams.get<std::string>("File");
  if (!file.empty() && file[0] != '/') meshParams.set("File", directoryOf(deckPath) + "/" + file);
  I.coarse = mesh::CoarseMesh::create(meshParams);
  I.segments = std::make_unique<mesh::BoundarySegments>(meshParams.sublist("Boundary Segments"), *I.coarse);
  I.problem = std::make_unique<fem::ProblemData>(deck.sublist("Problem"), *I.segments);
  I.newmark = std::make_unique<Newmark>(deck.sublist("Time Integration"));

  const auto& out = deck.sublist("Output");
  for (auto it = out.sublist("Probes").begin(); it != out.sublist("Probes").end(); ++it) {
    const std::string name = out.sublist("Probes").name(it);
    const std::string spec = Teuchos::any_cast<std::string>(out.sublist("Probes").entry(it).getAny());
    double x, y;
    char extra;
    if (std::sscanf(spec.c_str(), " %lf , %lf %c", &x, &y, &extra) != 2)
      SIGNORINI_USER_ERROR("Output/Probes/" << name << ": expected \"x, y\", got \"" << spec << "\"");
    I.probes.push_back({name, {x, y}});
  }

  I.forest = std::make_unique<mesh::Forest>(I.coarse, core::rawMpiComm(*comm), meshParams.get<int>("Refinement Level"));
  {
    auto scope = I.timers.scope("mesh");
    I.mesh = std::make_unique<mesh::Q1Mesh>(*I.forest, *I.segments, comm);
  }
  int overlapLocal = 0, overlapGlobal = 0;
  for (const auto& be : I.mesh->boundaryEdges())
    if ((be.segments & I.problem->dirichletMask) && (be.segments & I.problem->contactMask)) overlapLocal = 1;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, overlapLocal, Teuchos::outArg(overlapGlobal));
  if (overlapGlobal)
    SIGNORINI_USER_ERROR("Problem: a boundary edge belongs to both a Dirichlet and a contact segment");
  for (const auto& [name, p] : I.probes) {
    double s, r;
    int found = I.mesh->locate(p[0], p[1], s, r) >= 0 ? 1 : 0;
    int any = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, found, Teuchos::outArg(any));
    if (!any) SIGNORINI_USER_ERROR("Output/Probes/" << name << ": point (" << p[0] << ", " << p[1] << ") is outside the mesh");
  }

  {
    auto scope = I.timers.scope("assembly");
    I.assembler = std::make_unique<fem::Q1Assembler>(*I.mesh, I.mesh->nodesOnSegments(I.problem->dirichletMask));
    const double rho = I.problem->density, kappa = I.problem->stiffness, k = I.newmark->timeStep;
    std::vector<char> lump;
    if (I.problem->hasObstacle && deck.sublist("Contact").get<std::string>("Boundary Mass") == "lumped")
      lump = I.mesh->nodesOnSegments(I.problem->contactMask);
    I.M = I.assembler->assembleOperator(1.0, 0.0, rho, kappa, lump);
    I.K = I.assembler->assembleOperator(0.0, 1.0, rho, kappa);
    I.A = I.assembler->assembleOperator(1.0, I.newmark->beta * k * k, rho, kappa, lump);
  }
  I.courant = I.problem->waveSpeed() * I.newmark->timeStep / I.mesh->hMin();
  {
    auto scope = I.timers.scope("preconditioner");
    I.solver = std::make_unique<solvers::LinearSolver>(deck.sublist("Linear Solver"), comm);
    I.solver->setOperator(I.A, I.courant);
    auto massParams = deck.sublist("Linear Solver");
    massParams.set("Preconditioner", "Jacobi");
    I.massSolver = std::make_unique<solvers::LinearSolver>(massParams, comm);
    I.massSolver->setOperator(I.M, 0.0);
  }
  if (I.problem->hasObstacle) {
    const auto size = deck.sublist("Contact").get<std::string>("Multiplier Segments") == "H = h"
                          ? fem::ContactCoupling::SegmentSize::OneEdge
                          : fem::ContactCoupling::SegmentSize::TwoEdges;
    I.coupling = std::make_unique<fem::ContactCoupling>(*I.mesh, I.problem->contactMask, size,
                                                        I.assembler->dirichletFlags());
    if (I.coupling->numSegments() == 0)
      SIGNORINI_USER_ERROR("Problem/Contact Segments: the named segments contain no boundary edge of the mesh");
    I.qp = std::make_unique<solvers::ContactQP>(deck.sublist("Contact"), I.coarse->diameter());
    auto scope = I.timers.scope("preconditioner");  // the Schur preconditioner (strip factorisation)
    I.qp->setSystem(*I.A, *I.coupling, I.courant);
    I.lambda.assign(I.coupling->numSegments(), 0.0);
  }

  // Initial state: L2 projections of u0, v0 (paper Algorithm 3.3) and a0 from
  // (rho a0, phi) + a(u0, phi) = (f(0), phi) + Neumann load.
  const auto owned = I.mesh->ownedMap();
  I.u = Teuchos::rcp(new Vector(owned));
  I.v = Teuchos::rcp(new Vector(owned));
  I.a = Teuchos::rcp(new Vector(owned));
  I.projectL2(I.problem->initialDisplacement, *I.u);
  I.projectL2(I.problem->initialVelocity, *I.v);
  {
    Vector rhs(owned), Ku(owned);
    I.assembler->assembleLoad(I.problem->bodyForce, 0.0, 1.0, rhs);
    I.assembler->addBoundaryLoad(I.problem->neumannData, 0.0, I.problem->neumannMask, 1.0, rhs);
    I.K->apply(*I.u, Ku);
    rhs.update(-1.0, Ku, 1.0);
    I.a->putScalar(0.0);
    I.massSolver->solve(rhs, *I.a);
  }
  if (I.coupling) {
    I.gap = I.coupling->applyTranspose(*I.u);
    const auto gbar = I.coupling->weightedObstacle(I.problem->obstacle, 0.0);
    const auto& len = I.coupling->segmentLength();
    for (int j = 0; j < I.coupling->numSegments(); ++j) {
      I.gap[j] -= gbar[j];
      if (I.gap[j] / len[j] < -I.qp->gapTolerance()) {
        const auto& mp = I.coupling->segmentMidpoint()[j];
        SIGNORINI_USER_ERROR("Problem/Initial Displacement penetrates the obstacle at t = 0: the mean gap on the contact "
                             "segment at (" << mp[0] << ", " << mp[1] << ") is " << I.gap[j] / len[j]);
      }
    }
  }

  I.outDir = outputDir.empty() ? out.get<std::string>("Directory") : outputDir;
  I.basename = out.get<std::string>("Basename").empty() ? stemOf(deckPath) : out.get<std::string>("Basename");
  ensureWritableDirectory(I.outDir, *comm);
}

Simulation::~Simulation() = default;

RunSummary Simulation::run() {
  auto& I = *impl_;
  const int rank = I.comm->getRank();
  const auto owned = I.mesh->ownedMap();
  const auto& outParams = I.deck.sublist("Output");
  const std::string base = I.outDir + "/" + I.basename;
  const int nSteps = I.newmark->numSteps();
  const double k = I.newmark->timeStep, beta = I.newmark->beta;
  const int exodusInterval = outParams.get<int>("Exodus Interval");
  int progress = outParams.get<int>("Progress Interval");
  if (progress == 0) progress = std::max(1, nSteps / 20);

  std::vector<std::string> columns = {"step", "t", "dofs", "active", "qp_iterations", "cg_iterations",
                                      "linear_solves", "linear_iterations", "energy", "newmark_energy",
                                      "contact_force",
                                      "max_lambda", "min_gap", "max_complementarity", "time_assembly",
                                      "time_contact", "time_output", "time_unconstrained"};
  for (const auto& p : I.probes) columns.push_back("probe:" + p.first);
  if (I.problem->exactSolution) {
    columns.push_back("error_l2");
    columns.push_back("error_h1");
  }
  std::unique_ptr<io::CsvWriter> csv;
  int csvOk = 1;
  std::string csvError;
  if (rank == 0) {
    try {
      csv = std::make_unique<io::CsvWriter>(base + ".steps.csv", columns);
    } catch (core::UserError& e) {
      csvOk = 0;
      csvError = e.what();
    }
  }
  Teuchos::broadcast(*I.comm, 0, 1, &csvOk);
  if (!csvOk) SIGNORINI_USER_ERROR((rank == 0 ? csvError : std::string("cannot create the CSV output")));
  std::unique_ptr<ResultWriter> exodus;
  if (outParams.get<bool>("Write Exodus"))
    exodus = std::make_unique<ResultWriter>(base, std::vector<std::string>{"u", "v", "a"},
                                            std::vector<std::string>{"level"},
                                            std::vector<std::string>{"lambda", "gap"}, I.comm);
  std::vector<int> contactEdges;
  if (I.coupling)
    for (size_t i = 0; i < I.coupling->localEdgeSegment().size(); ++i)
      if (I.coupling->localEdgeSegment()[i] >= 0) contactEdges.push_back(static_cast<int>(i));

  RunSummary summary;
  summary.dofsPerStep = static_cast<long long>(owned->getGlobalNumElements());
  const auto start = std::chrono::steady_clock::now();
  Vector uOverlap(I.mesh->overlapMap()), vOverlap(I.mesh->overlapMap()), aOverlap(I.mesh->overlapMap());

  const bool measureOverhead = outParams.get<bool>("Measure Contact Overhead");
  auto writeOutputs = [&](int step, double t, const solvers::ContactQPResult& qr, double tAssembly, double tContact,
                          double tFree) {
    auto scope = I.timers.scope("output");
    const auto t0 = std::chrono::steady_clock::now();
    // The QP multiplier is beta k^2 times the physical one (kappa du/dn = -lambda on Gamma_C).
    const double toPhysical = 1.0 / (I.newmark->beta * I.newmark->timeStep * I.newmark->timeStep);
    double force = 0;
    if (I.coupling)
      for (int j = 0; j < I.coupling->numSegments(); ++j)
        force -= toPhysical * I.lambda[j] * I.coupling->segmentLength()[j];
    I.assembler->toOverlap(*I.u, uOverlap);
    std::vector<double> row = {double(step), t, double(summary.dofsPerStep), double(qr.active),
                               double(qr.activeSetIterations), double(qr.cgIterations), double(qr.linearSolves),
                               double(qr.linearIterations), I.energy(*I.u, *I.v), I.newmarkEnergy(), force, toPhysical * qr.maxLambda,
                               qr.minGap, toPhysical * qr.maxComplementarity, tAssembly, tContact, 0.0, tFree};
    for (const auto& p : I.probes) row.push_back(I.assembler->evaluate(uOverlap, p.second[0], p.second[1]));
    if (I.problem->exactSolution) {
      const auto [l2, h1] = I.assembler->errorNorms(*I.u, *I.problem->exactSolution, t);
      row.push_back(l2);
      row.push_back(h1);
    }
    if (exodus && (step % exodusInterval == 0 || step == nSteps)) {
      I.assembler->toOverlap(*I.v, vOverlap);
      I.assembler->toOverlap(*I.a, aOverlap);
      std::vector<double> level(I.mesh->cellLevel().begin(), I.mesh->cellLevel().end());
      std::vector<std::vector<double>> contact(2);
      for (int i : contactEdges) {
        const int j = I.coupling->localEdgeSegment()[i];
        contact[0].push_back(toPhysical * I.lambda[j]);
        contact[1].push_back(I.gap[j] / I.coupling->segmentLength()[j]);
      }
      exodus->write(0, *I.mesh, t, {&uOverlap, &vOverlap, &aOverlap}, {level}, contactEdges, contact);
    }
    row[16] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (csv) csv->row(row);
  };

  try {
    solvers::ContactQPResult none;
    writeOutputs(0, 0.0, none, 0.0, 0.0, 0.0);
    Vector F(owned), pred(owned), load(owned), uOld(owned);
    for (int n = 1; n <= nSteps; ++n) {
      const double t = n * k;
      const auto tA0 = std::chrono::steady_clock::now();
      {
        auto scope = I.timers.scope("assembly");
        // F^n = beta k^2 (f(t_n) + Neumann) + M (u + k v + (1/2 - beta) k^2 a)
        I.newmark->predictor(*I.u, *I.v, *I.a, pred);
        I.M->apply(pred, F);
        I.assembler->assembleLoad(I.problem->bodyForce, t, beta * k * k, load);
        I.assembler->addBoundaryLoad(I.problem->neumannData, t, I.problem->neumannMask, beta * k * k, load);
        F.update(1.0, load, 1.0);
        I.assembler->zeroDirichlet(F);
      }
      const auto tA1 = std::chrono::steady_clock::now();
      uOld.assign(*I.u);
      solvers::ContactQPResult qr;
      {
        auto scope = I.timers.scope("contact");
        I.u->assign(pred);
        I.assembler->zeroDirichlet(*I.u);
        if (I.coupling) {
          const auto gbar = I.coupling->weightedObstacle(I.problem->obstacle, t);
          qr = I.qp->solve(*I.solver, *I.coupling, F, gbar, I.lambda, *I.u, I.gap);
        } else {
          const long its0 = I.solver->totalIterations();
          I.solver->solve(F, *I.u);
          qr.linearSolves = 1;
          qr.linearIterations = static_cast<int>(I.solver->totalIterations() - its0);
        }
      }
      const auto tA2 = std::chrono::steady_clock::now();
      double tFree = 0;
      if (measureOverhead) {  // the same solve without contact, for the ratio time_contact / time_unconstrained
        Vector x(owned);
        x.assign(pred);
        I.assembler->zeroDirichlet(x);
        const auto t0 = std::chrono::steady_clock::now();
        I.solver->solve(F, x);
        tFree = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      I.newmark->update(uOld, *I.u, *I.v, *I.a);
      writeOutputs(n, t, qr, std::chrono::duration<double>(tA1 - tA0).count(),
                   std::chrono::duration<double>(tA2 - tA1).count(), tFree);
      if (n % progress == 0 || n == nSteps) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        core::rootOut(rank) << std::fixed << std::setprecision(4) << "  step " << n << "/" << nSteps << "  t = " << t
                            << "  dofs = " << summary.dofsPerStep << "  active = " << qr.active
                            << "  qp it = " << qr.activeSetIterations << "  lin it = " << qr.linearIterations
                            << std::setprecision(1) << "  elapsed " << elapsed << " s  remaining ~"
                            << elapsed / n * (nSteps - n) << " s" << std::endl;
      }
    }
  } catch (...) {
    if (csv) csv->abandon();
    if (exodus) exodus->abandon();
    throw;
  }
  if (csv) {
    csv->commit();
    summary.files.push_back(csv->path());
  }
  if (exodus)
    for (const auto& f : exodus->close()) summary.files.push_back(f);
  summary.steps = nSteps;
  summary.phaseSeconds = I.timers.all();
  summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace signorini::dynamics
