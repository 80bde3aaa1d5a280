#include "signorini/adapt/AdaptiveSimulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>

#include <Tpetra_Vector.hpp>

#include "signorini/io/CsvWriter.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"
#include "signorini/core/Interrupt.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/io/OutputStaging.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/adapt/Marking.hpp"
#include "signorini/core/PhaseTimers.hpp"
#include "signorini/estimate/ElasticityEstimator.hpp"
#include "signorini/io/ExodusSeriesWriter.hpp"
#include "signorini/estimate/ResidualEstimator.hpp"
#include "signorini/mesh/TemporalRegularisation.hpp"

namespace signorini::adapt {
namespace {

/// A cycle's estimate above this times the smallest of the earlier cycles' draws a warning: the
/// estimates of chattering contact vary between cycles by a few tenths of a percent (the bar's
/// 20% run: 2.0827e-4 after 2.0805e-4).
constexpr double kEstimateRiseWarning = 1.1;
/// Transfers between the step meshes that raised (or lowered) a cycle's energy by more than this
/// fraction of its largest energy draw a warning (the paper deck's cycles raise it by 0.35-0.5%).
constexpr double kTransferEnergyWarning = 0.05;
/// Without loads, body force or a moving obstacle (fem::ProblemData::suppliesEnergy), a cycle whose
/// Newmark energy rose above its initial value by more than this fraction draws a warning (the paper
/// deck's cycles stay within 0.5%; the 10% deck's cycle 2 reaches 5.4%).
constexpr double kEnergyGainWarning = 0.05;

/// Whether the file \p path is an Exodus file of a series ("<name>.e" or "<name>.e-s.<digits>";
/// only the file name counts, not the directories).
bool isExodusFile(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.size() > 2 && core::endsWith(name, ".e")) return true;
  const auto series = name.rfind(".e-s.");
  return series != std::string::npos && io::isExodusSeriesSuffix(name.substr(series));
}

/// The files of the cycle that turned out to be the last (a stopping criterion other than the
/// number of cycles), written as "<cycleBase>.<rest>", published as "<finalBase>.<rest>" like the
/// files of a run that ends after its planned cycles (io::republish; the tail of an older series
/// under the final name is retired so ParaView does not mix it in). The files live on rank 0 (the
/// writing rank); a failure there is reported on every rank of \p comm.
std::vector<std::string> promoteToFinalName(const std::vector<std::string>& files, const std::string& cycleBase,
                                            const std::string& finalBase, const Comm& comm) {
  std::vector<std::string> renamed;
  core::onRootCollectively(comm, [&] {
    if (std::any_of(files.begin(), files.end(), isExodusFile)) io::removeExodusSeriesTail(finalBase);
    for (const auto& f : files) {
      if (f.compare(0, cycleBase.size() + 1, cycleBase + ".") != 0) {
        renamed.push_back(f);
        continue;
      }
      const std::string target = finalBase + f.substr(cycleBase.size());
      io::republish(f, target);
      renamed.push_back(target);
    }
  });
  return renamed;
}

}  // namespace

core::ParameterList AdaptiveSimulation::getValidParameters() {
  auto p = dynamics::Simulation::getValidParameters();
  core::ParameterList a("Adaptivity");
  core::addChoice(a, "Strategy", "none",
                  "Refinement between cycles: \"fixed fraction\" (the paper's), \"bulk\" (Doerfler), \"uniform\" "
                  "(every cell: the comparison runs), or \"none\" (one pass on the deck's mesh, no estimator)",
                  {"none", "fixed fraction", "bulk", "uniform"});
  core::addDouble(a, "Refinement Fraction", 0.5,
                  "Fixed fraction: share of cells refined; bulk: share of the squared estimate captured (both of the "
                  "cells below Adaptivity/Maximum Level, the ones that can be refined)", 0.0, 1.0);
  core::addDouble(a, "Coarsening Fraction", 0.0,
                  "Share of the cells above the deck's level (the ones that can be coarsened) flagged for "
                  "coarsening, those with the smallest indicators; a family of four coarsens when all four are "
                  "flagged; the paper used none",
                  0.0, 1.0);
  core::addDouble(a, "Tie Tolerance", 1e-8,
                  "Cell indicators of a step closer than this times its largest indicator count as equal when "
                  "marking: all of a tied group are refined (or kept), so rounding, e.g. another number of ranks, "
                  "cannot choose between equal cells; a cell that ties with 0 is never refined (a region at rest), "
                  "and is coarsened first along the space-filling curve when more tie with 0 than the coarsening "
                  "fraction allows; 0: exact comparison",
                  0.0, 0.01);
  core::addDouble(a, "Zero Tolerance", 1e-12,
                  "Cell indicators at or below this times the step's rounding scale count as 0 when marking "
                  "(never refined, coarsened first), compared in the physical scaling (in units of the displacement, "
                  "whatever Estimator/Scaling): the scale is max |u_h| over the step's solution and predictor, times "
                  "1 / (beta C^2) when the Courant number C = c k / h_min is below beta^(-1/2) (the rounding of "
                  "a_h = (u_h - u~) / (beta k^2)). So a step whose indicators are rounding, e.g. of a rigid motion, "
                  "which bilinear elements represent exactly, refines nothing, on any number of ranks; 0: off",
                  0.0, 1e-3);
  core::addDouble(a, "Contact Zone Gap", 0.0,
                  "Length [units of the mesh]: cells with a contact edge whose multiplier segment comes within this of "
                  "the obstacle (its smallest gap at the Gauss points of its fine edges) are refined as well as those the strategy marks (below the Maximum "
                  "Level) and never coarsened, so that the contact zone is resolved before the first contact also "
                  "where the estimate cannot foresee it (e.g. a body in rigid motion, whose estimate is 0); about the "
                  "distance the body moves towards the obstacle in a few steps. 0: off (the paper's method)",
                  0.0, std::numeric_limits<double>::infinity());
  core::addInt(a, "Cycles", 5, "Number of passes over [0, T] (each pass is one cycle of Algorithm 5.1)", 1, 100);
  core::addDouble(a, "Maximum Total Unknowns", 0.0,
                  "Stop after the cycle whose total unknowns (sum over steps) reach this number (see Unknowns Limit); "
                  "0: no limit", 0.0);
  core::addChoice(a, "Unknowns Limit", "stop after reaching",
                  "How Maximum Total Unknowns ends the run: 'stop after reaching' runs cycles until one reaches it (that "
                  "cycle may exceed it by the growth of a cycle); 'do not exceed' runs no cycle whose total unknowns, "
                  "counted on its meshes before it runs, would exceed it: the cycle before is the run's result",
                  {"stop after reaching", "do not exceed"});
  core::addDouble(a, "Tolerance", 0.0, "Stop after the cycle whose estimate max_n eta^n is at or below this; 0: off", 0.0);
  core::addInt(a, "Maximum Level", 14, "Cells are not refined beyond this level; once every cell of every step is at it (and nothing "
               "coarsens), that cycle is the last", 0, 25);
  core::addChoice(a, "Transfer", "L2 projection",
                  "I_h between step meshes: the L2 projection of u, v and a (paper Sec. 3.2), nodal interpolation, "
                  "or the Ritz projection of u (in the energy inner product, with 10^-3 (c / L)^2 times the mass, L the "
                  "domain's diameter) with the L2 projection of v and a: no transfer raises the energy (the L2 "
                  "projection raises the strain energy where a step's mesh is coarser; with Contact/Boundary Mass = lumped "
                  "the energies are measured in another mass than v is projected in; costs a solve with K + mu M per mesh change)",
                  {"L2 projection", "interpolation", "Ritz projection"});
  core::addBool(a, "Report Transfer Energy", true,
                "Step tables gain energy_transferred and kinetic_energy_transferred: the energies of "
                "I_h u^{n-1}, I_h v^{n-1} on the mesh of step n (the transfer's effect; costs one more projected "
                "field, I_h v (I_h a when Alpha >= 1), per mesh change)");
  core::addBool(a, "Compact Meshes", true,
                "Store each step's mesh between its uses as the levels of its cells in curve order (1 byte per cell) "
                "instead of a p4est forest (about 35 bytes per cell); a step expands it when it needs it");
  core::addBool(a, "Write All Cycles", false,
                "Write Exodus results for every cycle (<basename>.cycle<l>.e); else only for the last cycle");
  p.set("Adaptivity", a, "Algorithm 5.1: cycles, marking, stopping");
  p.set("Estimator", estimate::ResidualEstimator::getValidParameters(), "The a posteriori estimator (paper Sec. 4)");
  return p;
}

namespace {

/// The keys of the deck's \p sublist that it sets to other than their defaults, among those
/// \p withoutEffect accepts, as "Sublist/key, Sublist/key2".
std::string keysSetWithoutEffect(const core::ParameterList& deck, const std::string& sublist,
                                 const std::function<bool(const std::string&)>& withoutEffect) {
  return core::keysSetOtherThanDefaults(deck.sublist(sublist), AdaptiveSimulation::getValidParameters().sublist(sublist),
                                        sublist, withoutEffect);
}

/// Settings that are valid one by one but cannot work together: user errors naming the keys. With
/// Strategy = none the Adaptivity and Estimator keys the deck sets have no effect, with Strategy =
/// uniform the marking's and Transfer, with Compute S1 = false s1's tolerance and length scale: a
/// warning lists them.
void checkAdaptivitySettings(const core::ParameterList& deck, const std::string& deckPath, const Comm& comm) {
  const auto& a = deck.sublist("Adaptivity");
  const std::string strategy = a.get<std::string>("Strategy");
  auto warn = [&](const std::string& situation, const std::string& keys) {
    if (!keys.empty() && comm.getRank() == 0)
      std::cerr << "signorini: warning: " << deckPath << ": " << situation << "; without effect: " << keys << std::endl;
  };
  if (strategy == "none") {  // neither the Adaptivity keys nor the estimator's
    const auto adaptivity = keysSetWithoutEffect(deck, "Adaptivity", [](const std::string& k) { return k != "Strategy"; });
    const auto estimator = keysSetWithoutEffect(deck, "Estimator", [](const std::string&) { return true; });
    warn("Adaptivity/Strategy = none runs one pass on the deck's mesh without the estimator",
         adaptivity + (adaptivity.empty() || estimator.empty() ? "" : ", ") + estimator);
    return;
  }
  if (!deck.sublist("Estimator").get<bool>("Compute S1"))
    warn("Estimator/Compute S1 = false",
         keysSetWithoutEffect(deck, "Estimator", [](const std::string& k) {
           return k == "S1 Relative Tolerance" || k == "S1 Length Scale";
         }));
  if (strategy == "uniform")
    warn("Adaptivity/Strategy = uniform refines every cell", keysSetWithoutEffect(deck, "Adaptivity", [](const std::string& k) {
           // (every step of a cycle has the same mesh: nothing is transferred)
           return k == "Refinement Fraction" || k == "Coarsening Fraction" || k == "Tie Tolerance" || k == "Transfer" ||
                  k == "Zero Tolerance" || k == "Contact Zone Gap";
         }));
  if (a.get<double>("Contact Zone Gap") > 0 && deck.sublist("Problem").get<std::string>("Obstacle").empty())
    warn("the deck has no obstacle (Problem/Obstacle)",
         keysSetWithoutEffect(deck, "Adaptivity", [](const std::string& k) { return k == "Contact Zone Gap"; }));
  const int cycles = a.get<int>("Cycles");
  const double fraction = a.get<double>("Refinement Fraction"), coarsen = a.get<double>("Coarsening Fraction");
  const int maxLevel = a.get<int>("Maximum Level"), baseLevel = deck.sublist("Mesh").get<int>("Refinement Level");
  if (a.get<bool>("Write All Cycles") && !deck.sublist("Output").get<bool>("Write Exodus"))
    SIGNORINI_USER_ERROR("Adaptivity/Write All Cycles = true needs Output/Write Exodus = true");
  if (a.get<std::string>("Unknowns Limit") != "stop after reaching" && a.get<double>("Maximum Total Unknowns") == 0)
    warn("Adaptivity/Maximum Total Unknowns = 0 (no limit)",
         keysSetWithoutEffect(deck, "Adaptivity", [](const std::string& k) { return k == "Unknowns Limit"; }));
  if (cycles < 2) return;  // nothing is refined
  if (maxLevel <= baseLevel)
    SIGNORINI_USER_ERROR("Adaptivity/Maximum Level = " << maxLevel << " is not above Mesh/Refinement Level = "
                                                         << baseLevel << ": no cell could be refined");
  if (strategy != "uniform" && fraction == 0)
    SIGNORINI_USER_ERROR("Adaptivity/Refinement Fraction = 0 refines no cell with Strategy = " << strategy
                                                                                            << ": every cycle would repeat the first");
  if (strategy == "fixed fraction" && fraction + coarsen > 1)
    SIGNORINI_USER_ERROR("Adaptivity/Coarsening Fraction = " << core::shortestText(coarsen) << " with Refinement Fraction = "
                                                              << core::shortestText(fraction) << ": together more than all cells");
}

}  // namespace

AdaptiveSimulation::AdaptiveSimulation(const core::ParameterList& deck, const std::string& deckPath,
                                       const std::string& outputDir, RCP<const Comm> comm)
    : deck_(deck) {
  checkAdaptivitySettings(deck, deckPath, *comm);
  sim_ = std::make_unique<dynamics::Simulation>(deck, deckPath, outputDir, comm);
  const auto& a = deck.sublist("Adaptivity");
  if (a.get<std::string>("Strategy") != "none") {  // the segments and the initial gap on the finest meshes the cycles can make
    const int finer = std::min(a.get<int>("Cycles") - 1,
                               a.get<int>("Maximum Level") - deck.sublist("Mesh").get<int>("Refinement Level"));
    const std::string cause = "Adaptivity/Cycles = " + std::to_string(a.get<int>("Cycles"));
    sim_->checkSegmentsOnRefinements(finer, cause);
    sim_->checkInitialGapOnRefinements(finer, cause);
  }
  if (a.get<std::string>("Strategy") != "none" && a.get<std::string>("Unknowns Limit") == "do not exceed")
    if (const double maxDofs = a.get<double>("Maximum Total Unknowns"); maxDofs > 0) {
      const double first = static_cast<double>(sim_->numSteps()) * static_cast<double>(sim_->initialUnknowns());
      if (first > maxDofs)
        SIGNORINI_USER_ERROR("Adaptivity/Maximum Total Unknowns = "
                             << core::shortestText(maxDofs) << " with Unknowns Limit = do not exceed: cycle 0 alone, "
                             << sim_->numSteps() << " steps on the deck's mesh of " << sim_->initialUnknowns()
                             << " unknowns, has " << core::shortestText(first)
                             << " total unknowns; raise the limit, coarsen the deck's mesh, lengthen Time Integration/Time Step "
                                "or shorten Final Time");
    }
  // Uniform refinement: the last cycle's mesh is known in advance (unless a criterion stops earlier).
  if (a.get<std::string>("Strategy") == "uniform" && a.get<double>("Maximum Total Unknowns") == 0 &&
      a.get<double>("Tolerance") == 0) {
    const int refinements = std::min(a.get<int>("Cycles") - 1,
                                     a.get<int>("Maximum Level") - deck.sublist("Mesh").get<int>("Refinement Level"));
    sim_->checkMeshFits(static_cast<double>(sim_->initialForest()->numGlobalCells()) * std::pow(4.0, std::max(refinements, 0)),
                        "Adaptivity/Cycles = " + std::to_string(a.get<int>("Cycles")) + " with Strategy = uniform");
  }
}

AdaptiveSimulation::~AdaptiveSimulation() = default;

const std::string& AdaptiveSimulation::outputBase() const { return sim_->outputBase(); }
const core::ParameterList& AdaptiveSimulation::deck() const { return sim_->deck(); }

template <class Pass>
dynamics::RunSummary AdaptiveSimulation::locatingFailures(int cycle, Pass pass) const {
  try {
    return pass();
  } catch (const core::SolverError& e) {
    throw core::SolverError(whereInRun(cycle) + e.what());
  } catch (const core::UserError& e) {
    throw core::UserError(whereInRun(cycle) + e.what());
  }
}

std::string AdaptiveSimulation::whereInRun(int cycle) const {
  const int n = sim_->currentStep();
  std::ostringstream os;
  os << std::setprecision(6);
  if (deck_.sublist("Adaptivity").get<std::string>("Strategy") != "none") os << "cycle " << cycle << ", ";
  os << (n == 0 ? "the initial state" : "step " + std::to_string(n)) << " (t = " << n * sim_->timeStep() << "): ";
  return os.str();
}

dynamics::PassOptions AdaptiveSimulation::cyclePassOptions() const {
  const auto& ap = deck_.sublist("Adaptivity");
  dynamics::PassOptions options;
  options.extraColumns = {"eta_star", "s0", "s1", "eta"};
  options.cellFieldName = "indicator";
  const std::string transfer = ap.get<std::string>("Transfer");
  options.transfer = transfer == "interpolation"     ? dynamics::PassOptions::Transfer::interpolation
                     : transfer == "Ritz projection" ? dynamics::PassOptions::Transfer::ritzProjection
                                                     : dynamics::PassOptions::Transfer::l2Projection;
  options.reportTransferEnergy = ap.get<bool>("Report Transfer Energy");
  options.reportWork = false;  // the meshes change between steps
  return options;
}

std::string AdaptiveSimulation::plan() const {
  const auto& a = deck_.sublist("Adaptivity");
  const auto& t = deck_.sublist("Time Integration");
  std::ostringstream os;
  os << sim_->numSteps() << " steps of k = " << t.get<double>("Time Step") << " to T = " << t.get<double>("Final Time")
     << "; the initial mesh: " << sim_->initialForest()->numGlobalCells() << " cells, " << sim_->initialUnknowns()
     << " unknowns\n";
  os << "Newmark alpha = " << t.get<double>("Alpha") << ", beta = " << t.get<double>("Beta") << ", contact force "
     << t.get<std::string>("Contact Force")
     << (t.get<std::string>("Contact Force") == "trapezoidal" ? " (the paper's)" : " (Deuflhard, Krause, Ertel)")
     << ", contact stabilisation " << t.get<std::string>("Contact Stabilisation") << "\n";
  {
    const auto& out = deck_.sublist("Output");
    const auto& probes = sim_->probes();
    if (!probes.empty()) {
      os << "probes (" << out.get<std::string>("Probe Fields") << ", points of the undeformed body):";
      for (size_t i = 0; i < probes.size(); ++i)
        os << (i ? ", " : " ") << probes[i].first << " at (" << core::shortestText(probes[i].second[0]) << ", "
           << core::shortestText(probes[i].second[1]) << ")";
      os << "\n";
    }
    if (const auto* p = sim_->momentPoint())
      os << (a.get<std::string>("Strategy") == "none" ? "moments and angular momentum" : "moments") << " about ("
         << core::shortestText((*p)[0]) << ", " << core::shortestText((*p)[1]) << ") (Output/Moment Point)\n";
    if (const auto* region = sim_->stressRegion())
      os << "max_von_mises over the cells whose centre lies in " << region->text() << " (Output/Stress Region)\n";
    if (const auto supports = sim_->supports(); !supports.empty()) {
      const bool moments = sim_->momentPoint() != nullptr;
      os << "supports (reaction:<segment>" << (moments ? "; each moment about the support's centre" : "") << "):";
      for (size_t i = 0; i < supports.size(); ++i) {
        os << (i ? ", " : " ") << supports[i].first;
        if (moments)
          os << " at (" << core::shortestText(supports[i].second[0]) << ", " << core::shortestText(supports[i].second[1])
             << ")";
      }
      os << "\n";
    }
  }
  {
    const int finer = a.get<std::string>("Strategy") == "none"
                          ? 0
                          : std::min(a.get<int>("Cycles") - 1,
                                     a.get<int>("Maximum Level") - deck_.sublist("Mesh").get<int>("Refinement Level"));
    if (const auto solver = sim_->linearSolverPlan(finer); !solver.empty()) os << solver << "\n";
  }
  if (const auto coarse = sim_->coarseCorrectionMesh(); !coarse.empty())
    os << "the contact Schur preconditioner's coarse correction: " << coarse << "\n";
  const std::string strategy = a.get<std::string>("Strategy");
  if (strategy == "none") {
    os << "one pass on the initial mesh";
  } else {
    const int cycles = a.get<int>("Cycles");
    const int levels = a.get<int>("Maximum Level") - deck_.sublist("Mesh").get<int>("Refinement Level");
    os << "Algorithm 5.1: " << cycles << " cycle(s)";
    if (strategy == "uniform" && cycles > levels + 1)
      os << " (" << levels + 1 << ": then every cell is at Maximum Level " << a.get<int>("Maximum Level") << ")";
    os << ", strategy " << strategy;
    if (strategy != "uniform") os << " " << 100 * a.get<double>("Refinement Fraction") << "%";
    if (strategy != "uniform" && a.get<double>("Coarsening Fraction") > 0)
      os << ", coarsening " << 100 * a.get<double>("Coarsening Fraction") << "%";
    if (const double maxDofs = a.get<double>("Maximum Total Unknowns"); maxDofs > 0) {
      os << (a.get<std::string>("Unknowns Limit") == "do not exceed" ? ", no cycle above " : ", stop at ") << maxDofs
         << " total unknowns";
      // Cycle 0 passes over the initial mesh: its total is known now.
      const double first = static_cast<double>(sim_->numSteps()) * static_cast<double>(sim_->initialUnknowns());
      if (cycles > 1 && first >= maxDofs) os << " (cycle 0 alone has " << first << ": the run stops after it)";
    }
    if (a.get<double>("Tolerance") > 0) os << ", stop at eta <= " << a.get<double>("Tolerance");
    if (const double gap = a.get<double>("Contact Zone Gap"); gap > 0 && strategy != "uniform")
      os << ", also refining where the contact boundary comes within " << gap << " of the obstacle (Contact Zone Gap)";
  }
  if (deck_.sublist("Parallel").get<bool>("Reproducible Arithmetic"))
    os << "\nreproducible arithmetic: the same bits on any number of ranks";
  {
    const auto columns = sim_->stepColumns(strategy == "none" ? dynamics::PassOptions() : cyclePassOptions());
    os << "\nstep table " << sim_->outputBase() << ".steps.csv, " << columns.size() << " columns:";
    for (size_t c = 0; c < columns.size(); ++c) os << (c ? ", " : " ") << columns[c];
  }
  os << "\noutput: " << sim_->outputBase() << ".*";
  return os.str();
}

double AdaptiveSimulation::totalUnknowns(const std::vector<std::shared_ptr<mesh::Forest>>& meshes) const {
  const double perNode = sim_->unknownsPerNode();
  std::map<const mesh::Forest*, double> nodes;  // steps that share a mesh share its forest
  double total = 0;
  for (const auto& m : meshes) {
    auto [it, fresh] = nodes.try_emplace(m.get(), 0.0);
    if (fresh) {
      const bool compact = m->isCompact();
      if (compact) m->expand();
      it->second = static_cast<double>(m->numGlobalNodes());
      if (compact) m->compact();
    }
    total += perNode * it->second;
  }
  return total;
}

dynamics::RunSummary AdaptiveSimulation::run() {
  const auto& ap = deck_.sublist("Adaptivity");
  const std::string strategy = ap.get<std::string>("Strategy");
  if (deck_.sublist("Parallel").get<bool>("Reproducible Arithmetic"))
    core::rootOut(sim_->comm()->getRank())
        << "signorini: reproducible arithmetic: the same bits on any number of ranks (slower)" << std::endl;
  if (strategy == "none") return locatingFailures(0, [&] { return sim_->run(); });

  const auto comm = sim_->comm();
  const int rank = comm->getRank();
  MPI_Comm raw = sim_->initialForest()->comm();
  const int nSteps = sim_->numSteps();
  const int cycles = ap.get<int>("Cycles");
  const double maxDofs = ap.get<double>("Maximum Total Unknowns"), tol = ap.get<double>("Tolerance");
  const bool neverAboveMaxDofs = maxDofs > 0 && ap.get<std::string>("Unknowns Limit") == "do not exceed";
  // With these criteria any cycle may be the last: each is written in full under its cycle name,
  // and the one that ends the run gets the final names.
  const bool mayStopEarly = maxDofs > 0 || tol > 0;
  const bool writeAll = ap.get<bool>("Write All Cycles");
  const int maxLevel = ap.get<int>("Maximum Level");
  const int baseLevel = deck_.sublist("Mesh").get<int>("Refinement Level");
  const double fraction = ap.get<double>("Refinement Fraction");
  const double coarsen = ap.get<double>("Coarsening Fraction");
  const double ties = ap.get<double>("Tie Tolerance"), zeroTolerance = ap.get<double>("Zero Tolerance");
  const double contactZoneGap = ap.get<double>("Contact Zone Gap");
  const bool stepScaling = deck_.sublist("Estimator").get<std::string>("Scaling") == "step";
  const bool compactMeshes = ap.get<bool>("Compact Meshes");
  estimate::ResidualEstimator estimator(deck_.sublist("Estimator"));
  estimate::ElasticityEstimator elasticityEstimator(deck_.sublist("Estimator"));
  const std::string base = sim_->outputBase();

  // The run's files appear together when it has succeeded, replacing every file an earlier run
  // left under this base (also cycle tables and series it does not write again); a failed run
  // leaves the earlier files as they were.
  io::OutputStaging staging;
  const auto lock = sim_->createOutputDirectory();  // released before a failed run's folders are removed
  io::retireOnCommit(base, io::isRunOutputSuffix);
  std::unique_ptr<io::CsvWriter> cyclesCsv;
  core::onRootCollectively(*comm, [&] {
    cyclesCsv = std::make_unique<io::CsvWriter>(
        base + ".cycles.csv",
        std::vector<std::string>{"cycle", "total_dofs", "eta", "wall_seconds", "total_cells", "stored_meshes",
                                 "stored_cells", "bytes_per_cell", "mesh_rebuilds", "time_remesh_transfer",
                                 "time_assembly", "time_preconditioner", "time_contact", "time_estimate_mark",
                                 "time_output", "time_regularise", "time_unconstrained", "time_other"});
  });
  std::vector<std::shared_ptr<mesh::Forest>> meshes(nSteps, sim_->initialForest());
  dynamics::RunSummary last;
  std::vector<std::string> earlierFiles;  // kept files of the cycles before the last
  std::vector<std::string> previousFiles;  // the previous cycle's files, until this cycle is known to fit
  bool unchanged = false;  // the last regularised meshes are those of the cycle before: nothing was refined
  bool previousAtRounding = false;  // every cell indicator of the cycle before was 0 (Zero Tolerance)
  std::map<std::string, double> phaseSeconds;  // over all cycles
  const auto runStart = std::chrono::steady_clock::now();
  try {
    for (int l = 0; l < cycles; ++l) {
      // The previous cycle was written in full (it might have been the last): it becomes the run's
      // result, as when a stopping criterion ends the run.
      const auto endWithPreviousCycle = [&] {
        last.files = promoteToFinalName(previousFiles, base + ".cycle" + std::to_string(l - 1), base, *comm);
        previousFiles.clear();
      };
      {  // the largest step mesh of this cycle and the forests of all its steps
        long long largest = 0;
        double stored = 0;
        std::set<const mesh::Forest*> distinct;
        for (const auto& m : meshes) {
          largest = std::max(largest, m->numGlobalCells());
          if (distinct.insert(m.get()).second) stored += static_cast<double>(m->numGlobalCells());
        }
        try {
          sim_->checkMeshFits(static_cast<double>(largest),
                              "Adaptivity: cycle " + std::to_string(l) +
                                  " (Cycles, Maximum Total Unknowns or Tolerance stop earlier)",
                              stored);
        } catch (core::UserError& e) {
          if (l == 0 || !mayStopEarly) throw;
          core::rootOut(rank) << "signorini: warning: the run ends with cycle " << l - 1 << ": " << e.what() << std::endl;
          endWithPreviousCycle();
          break;
        }
        if (l > 0 && neverAboveMaxDofs) {
          const double total = totalUnknowns(meshes);
          if (total > maxDofs) {
            core::rootOut(rank) << "signorini: the run ends with cycle " << l - 1 << ": cycle " << l << " would have "
                                << core::shortestText(total) << " total unknowns, above Adaptivity/Maximum Total Unknowns = "
                                << core::shortestText(maxDofs) << " (Unknowns Limit = do not exceed)" << std::endl;
            endWithPreviousCycle();
            break;
          }
        }
      }
      const bool dropExodus = mayStopEarly && !writeAll;  // the previous cycle's, written in case it was the last
      for (const auto& f : previousFiles)
        if (dropExodus && isExodusFile(f))
          io::unpublish(f);
        else
          earlierFiles.push_back(f);
      previousFiles.clear();
      const auto start = std::chrono::steady_clock::now();
      std::vector<std::shared_ptr<mesh::Forest>> next(nSteps);
      // No next cycle: nothing to mark or refine. Also when every cell of every step is at the
      // Maximum Level and none is coarsened: the next cycle would repeat this one.
      bool atMaximum = l > 0 && (coarsen == 0 || strategy == "uniform");
      for (size_t n = 0; atMaximum && n < meshes.size(); ++n) atMaximum = meshes[n]->minimumLevel() >= maxLevel;
      if (atMaximum && l < cycles - 1)
        core::rootOut(rank) << "signorini: cycle " << l << " is the last: every cell of every step is at Adaptivity/"
                            << "Maximum Level = " << maxLevel << ", so a further cycle would repeat it" << std::endl;
      // The marking of the previous cycle refined nothing (its indicators were 0): this cycle repeats
      // it, written as the run's result, and a further one would repeat it again.
      if (unchanged && l < cycles - 1) {
        std::ostringstream why;
        if (previousAtRounding) {
          why << ": its cell indicators were all 0 at rounding level (Adaptivity/Zero Tolerance)";
          if (const double eta = cycles_.back().eta; eta > 0)
            why << std::setprecision(4) << "; its estimate " << eta << " was s1 alone, which marking leaves out "
                << "(paper, Remark 4.2), e.g. of a body in rigid motion that penetrates the obstacle inside contact "
                   "segments whose mean gap is still positive; Adaptivity/Contact Zone Gap refines the contact zone "
                   "anyway";
        }
        core::rootOut(rank) << "signorini: cycle " << l << " is the last: the marking of cycle " << l - 1
                            << " left every step's mesh as it was (no cell marked" << why.str()
                            << "), so a further cycle would repeat it" << std::endl;
      }
      const bool lastPlanned = l == cycles - 1 || atMaximum || unchanged;
      double etaMax = 0;
      // Every cell indicator of every step of the cycle (this rank's cells) at rounding level.
      bool indicatorsAtRounding = zeroTolerance > 0;
      const double s1Tolerance = deck_.sublist("Estimator").get<double>("S1 Relative Tolerance");
      dynamics::StepHook hook = [&](const dynamics::StepView& s) {
        // Every CG iterate is an extension of the boundary data, so its norm bounds s1 from above and
        // decreases to s1 (Estimator/S1 Relative Tolerance; s1 is not used for marking, so the meshes
        // do not depend on it). The lean Jacobi CG runs the iteration of Belos CG with Jacobi,
        // without their set-up per call. (MueLu here, set up once per mesh, broke down on the
        // membrane deck's second cycle: non-positive p^T A p in Belos CG.)
        auto solveSPD = [&](const RCP<const CrsMatrix>& A, const Vector& b, Vector& x) {
          try {
            solvers::solveJacobiCG(*A, b, x, s1Tolerance, deck_.sublist("Linear Solver").get<int>("Maximum Iterations"));
          } catch (core::SolverError& e) {
            throw core::SolverError(std::string("the estimator's s1 (Estimator/S1 Relative Tolerance, Linear Solver/"
                                                "Maximum Iterations): ") + e.what());
          }
        };
        // The previous step's continuation (interpolated by the time stepper) starts s1 on a new mesh.
        const Vector* guess = s.carried.empty() ? nullptr : s.carried[0].get();
        const auto* scalar = dynamic_cast<const fem::Q1Assembler*>(&s.assembler);
        auto r = scalar ? estimator.estimate(estimate::EstimatorInput{s.forest, s.mesh, *scalar, s.problem,
                                                                      s.coupling, s.time, s.timeStep, s.beta,
                                                                      s.u, s.predictor, s.lambda, solveSPD, s.meshId,
                                                                      guess, s.consistentMass, s.stiffness})
                        : elasticityEstimator.estimate(estimate::ElasticityEstimatorInput{
                              s.forest, s.mesh, dynamic_cast<const fem::ElasticityAssembler&>(s.assembler),
                              s.problem, s.coupling, s.time, s.timeStep, s.beta, s.u, s.predictor, s.lambda,
                              solveSPD, s.meshId, guess});
        {
          // Not finite: beta k^2 (or its square, in the physical scaling's division) left the range
          // of doubles, e.g. for a time step of 1e-100; the marking needs numbers.
          bool finite = std::isfinite(r.eta);
          for (double x : r.cellIndicator) finite = finite && std::isfinite(x);
          std::ostringstream why;
          // The physical scaling divides by beta k^2 kappa and its square (kappa: the stiffness).
          const double bk2 = s.beta * s.timeStep * s.timeStep, kappa = s.problem.waveModulus();
          if (!finite && bk2 * kappa > 1e-100 && bk2 * kappa < 1e100) {  // then the solution itself is out of range
            double largest = 0;  // this rank's: a reduction here would wait for ranks whose numbers are finite
            auto uh = s.u.getLocalViewHost(Tpetra::Access::ReadOnly);
            for (size_t i = 0; i < uh.extent(0); ++i) largest = std::max(largest, std::abs(uh(i, 0)));
            why << "the estimator's indicators are not finite numbers: the squares of its residuals leave the range "
                   "of doubles (the solution reaches "
                << largest
                << "); are the problem's data, e.g. Problem/Body Force, Neumann Data, Initial Displacement and "
                   "Initial Velocity, within a sensible range?";
          } else if (!finite) {
            why << "the estimator's indicators are not finite numbers: Time Integration/Time Step = " << s.timeStep
                << " gives beta k^2 = " << bk2 << " and with the stiffness " << kappa << " beta k^2 kappa = " << bk2 * kappa
                << ", which the estimate (Estimator/Scaling) cannot divide by or square in doubles";
          }
          core::throwFirstUserError(*sim_->comm(), why.str());
        }
        etaMax = std::max(etaMax, r.eta);
        std::vector<double> indicator(r.cellIndicator.size());
        for (size_t e = 0; e < indicator.size(); ++e) indicator[e] = std::sqrt(r.cellIndicator[e]);
        RCP<Vector> continuation =
            scalar ? estimator.continuationOn(s.meshId) : elasticityEstimator.continuationOn(s.meshId);
        if (continuation.is_null() && guess) continuation = s.carried[0];  // no s1 this step: keep the guess
        dynamics::StepExtras extras{{r.etaStar, r.s0, r.s1, r.eta}, indicator, {}};
        if (!continuation.is_null()) extras.carry.push_back(continuation);
        if (zeroTolerance > 0) {  // indicators at rounding level count as 0 (Adaptivity/Zero Tolerance)
          const double courant = s.problem.waveSpeed() * s.timeStep / s.mesh.hMin();
          const double motion = std::max(s.u.normInf(), s.predictor.normInf());
          const double floor = zeroTolerance * motion * std::max(1.0, 1.0 / (s.beta * courant * courant));
          // Compared in the physical scaling, where eta_K and the s0 share are displacements: the step
          // scaling's eta_K^2 carries (beta k^2 kappa)^2, its s0 share beta k^2 kappa.
          const double c = stepScaling ? s.beta * s.timeStep * s.timeStep * s.problem.density *
                                             s.problem.waveSpeed() * s.problem.waveSpeed()
                                       : 1.0;
          for (size_t e = 0; e < r.cellIndicator.size(); ++e) {
            const double physical = r.cellEta2[e] / (c * c) + (r.cellIndicator[e] - r.cellEta2[e]) / c;
            if (physical <= floor * floor) r.cellIndicator[e] = 0.0;
          }
          for (double x : r.cellIndicator) indicatorsAtRounding = indicatorsAtRounding && x == 0.0;
        }
        if (lastPlanned) return extras;
        // T^n_{l+1}: T^n_l refined by the strategy, 2:1 balanced (Algorithm 5.2).
        // Marking among the cells below the Maximum Level: the fraction goes to cells that can be
        // refined (spent on cells at the level, it refined nothing, and the cycles repeated).
        std::vector<char> refinable(r.cellIndicator.size());
        for (size_t e = 0; e < refinable.size(); ++e) refinable[e] = s.mesh.cellLevel()[e] < maxLevel;
        std::vector<char> flags = markAmong(r.cellIndicator, refinable, [&](const std::vector<double>& v) {
          if (strategy == "uniform") return std::vector<char>(v.size(), 1);
          return strategy == "bulk" ? markBulk(v, fraction, ties, raw) : markFixedFraction(v, fraction, ties, raw);
        });
        // Adaptivity/Contact Zone Gap: the cells along segments near contact are refined (below the
        // Maximum Level) and never coarsened.
        std::vector<char> nearContact(r.cellIndicator.size(), 0);
        if (contactZoneGap > 0 && s.coupling) {
          // The smallest gap over each segment, not its mean: inside a segment the body can reach the
          // obstacle by up to the obstacle's variation over it before the mean gap says so.
          Vector uOverlap(s.assembler.overlapMap());
          s.assembler.toOverlap(s.u, uOverlap);
          const std::vector<double> gap = s.coupling->smallestGaps(s.mesh, uOverlap, s.problem.obstacle, s.time);
          const std::vector<int>& segment = s.coupling->localEdgeSegment();
          const auto& edges = s.mesh.boundaryEdges();
          for (size_t e = 0; e < edges.size(); ++e) {
            const int j = segment[e];
            if (j >= 0 && gap[j] <= contactZoneGap) nearContact[edges[e].cell] = 1;
          }
          for (size_t e = 0; e < flags.size(); ++e) flags[e] = flags[e] || (nearContact[e] && refinable[e]);
        }
        auto refined = std::make_shared<mesh::Forest>(s.forest);
        if (coarsen > 0 && strategy != "uniform") {
          // Among the cells above the deck's level, as refinement among those below the Maximum
          // Level: spent on cells at the level, the fraction coarsened nothing.
          std::vector<long long> positions(r.cellIndicator.size());
          std::iota(positions.begin(), positions.end(), s.forest.firstGlobalCell());
          std::vector<char> small =
              markSmallestAbove(r.cellIndicator, positions, s.mesh.cellLevel(), baseLevel, coarsen, ties, raw);
          for (size_t e = 0; e < small.size(); ++e) small[e] = small[e] && !flags[e] && !nearContact[e];
          refined->refineAndCoarsen(flags, small, baseLevel);
          refined->balance();
        } else {
          refined->refineMarked(s.mesh.balanceClosure(flags));  // T^n_l is balanced: adds the cells the balance forces
        }
        refined->partition();
        if (compactMeshes) refined->compact();
        const int n = s.step;
        next[n - 1] = (n > 1 && next[n - 2]->sameCells(*refined)) ? next[n - 2] : refined;
        return extras;
      };
      dynamics::PassOptions options = cyclePassOptions();
      const std::string& outBase = sim_->outputBase();
      options.basename = lastPlanned ? "" : outBase.substr(outBase.find_last_of('/') + 1) + ".cycle" + std::to_string(l);
      options.writeExodus = lastPlanned || writeAll || mayStopEarly;
      options.compactMeshes = compactMeshes;
      last = locatingFailures(l, [&] { return sim_->runPass(meshes, hook, options); });
      for (const auto& [phase, seconds] : last.phaseSeconds) phaseSeconds[phase] += seconds;
      // Memory of the stored meshes of this cycle (steps with equal meshes share one forest).
      std::set<const mesh::Forest*> unique;
      long long cells = 0, storedCells = 0;
      double bytes = 0;
      for (const auto& m : meshes) {
        cells += m->numGlobalCells();
        if (unique.insert(m.get()).second) {
          bytes += static_cast<double>(m->bytes());
          storedCells += m->numGlobalCells();
        }
      }
      double bytesGlobal = 0;
      MPI_Allreduce(&bytes, &bytesGlobal, 1, MPI_DOUBLE, MPI_SUM, raw);
      const double bytesPerCell = bytesGlobal / static_cast<double>(storedCells);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      cycles_.push_back({l, last.totalDofs, etaMax, wall, cells, static_cast<long long>(unique.size()), storedCells,
                         bytesPerCell, last.meshChanges});
      auto phase = [&](const char* name) {
        const auto it = last.phaseSeconds.find(name);
        return it == last.phaseSeconds.end() ? 0.0 : it->second;
      };
      const auto tr0 = std::chrono::steady_clock::now();
      const bool stop = (maxDofs > 0 && last.totalDofs >= maxDofs) || (tol > 0 && etaMax <= tol) || lastPlanned;
      if (!stop) {  // Algorithm 5.3, then the next cycle's meshes.
        mesh::regulariseSteps(next);
        unchanged = true;
        for (size_t n = 0; unchanged && n < next.size(); ++n) unchanged = next[n]->sameCells(*meshes[n]);
        meshes = next;
      }
      const double regularise = std::chrono::duration<double>(std::chrono::steady_clock::now() - tr0).count();
      phaseSeconds["regularise"] += regularise;
      cycles_.back().wallSeconds += regularise;  // the cycle's wall time includes its regularisation
      // The phases are exclusive (core::PhaseTimers); what none of them covers (the predictors, the
      // Newmark update, the transfer energies, a later cycle's initial state) is "other".
      double phases = 0;
      for (const auto& entry : last.phaseSeconds) phases += entry.second;
      if (cyclesCsv)
        cyclesCsv->row({double(l), double(last.totalDofs), etaMax, cycles_.back().wallSeconds, double(cells),
                        double(unique.size()), double(storedCells), bytesPerCell, double(last.meshChanges),
                        phase("mesh") + phase("transfer"), phase("assembly"),
                        phase("preconditioner"), phase("contact"), phase("estimator"), phase("output"), regularise,
                        phase("unconstrained"), std::max(0.0, wall - phases)});
      core::rootOut(rank) << std::scientific << std::setprecision(4) << "signorini: cycle " << l
                          << ": total unknowns " << last.totalDofs << ", eta " << etaMax << std::fixed
                          << ", " << cycles_.back().wallSeconds << " s" << std::endl;
      // Refinement that raised the estimate by more than the estimates of chattering contact vary
      // from cycle to cycle, e.g. through energy injected where a refined step meets an impact (README,
      // Known behaviour): the user should see it before trusting the estimate. Not for estimates
      // that are rounding (every indicator below Adaptivity/Zero Tolerance's floor, a rigid motion).
      int rounding = indicatorsAtRounding ? 1 : 0, roundingEverywhere = 0;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, rounding, Teuchos::outArg(roundingEverywhere));
      previousAtRounding = roundingEverywhere != 0;
      if (const auto best = std::min_element(cycles_.begin(), cycles_.end() - 1,
                                             [](const CycleSummary& a, const CycleSummary& b) { return a.eta < b.eta; });
          best != cycles_.end() - 1 && etaMax > kEstimateRiseWarning * best->eta && !roundingEverywhere) {
        std::ostringstream warning;  // its own format: the console's stays as the run set it
        warning << std::setprecision(4) << std::scientific << "signorini: warning: cycle " << l << "'s estimate "
                << etaMax << " is above cycle " << best->cycle << "'s " << best->eta << " by more than "
                << std::lround(100 * (kEstimateRiseWarning - 1))
                << "%: refinement raised it; where a step refined at an impact injects energy, the step table's "
                   "newmark_energy shows it (README, Known behaviour; Adaptivity/Contact Zone Gap)";
        core::rootOut(rank) << warning.str() << std::endl;
      }
      // The L2 projection never raises the kinetic energy but may raise the strain energy (where a
      // step's mesh is coarser than its predecessor's under a stress wave), interpolation either:
      // a cycle whose transfers moved much energy is not the problem's dynamics. Rises and losses are
      // told apart (summed together they can cancel).
      const double rise = last.transferEnergyRise, loss = rise - last.transferEnergyChange;
      if (last.largestEnergy > 0 && std::max(rise, loss) > kTransferEnergyWarning * last.largestEnergy) {
        const bool raised = rise >= loss;
        const double moved = raised ? rise : loss;
        std::ostringstream warning;
        warning << std::setprecision(4) << "signorini: warning: cycle " << l << ": moving the state to each step's mesh "
                << (raised ? "raised" : "lowered") << " its energy (kinetic + strain) by " << moved
                << " summed over the cycle's mesh changes that " << (raised ? "raised" : "lowered") << " it ("
                << std::fixed << std::setprecision(1) << 100 * moved / last.largestEnergy << std::defaultfloat
                << std::setprecision(4) << "% of its largest energy " << last.largestEnergy << "; net "
                << std::showpos << last.transferEnergyChange << std::noshowpos << " over its " << last.meshChanges
                << " mesh changes), so the cycle's dynamics are not the problem's: "
                << (!raised ? "the coarser parts of the step meshes cannot hold the finer scales of the state"
                    : options.transfer == dynamics::PassOptions::Transfer::l2Projection
                        ? "the L2 projection of u raises the strain energy where a step's mesh is coarser than "
                          "its predecessor's (Adaptivity/Transfer = Ritz projection cannot raise it)"
                    : options.transfer == dynamics::PassOptions::Transfer::interpolation
                        ? "nodal interpolation can raise it (Adaptivity/Transfer = Ritz projection cannot)"
                        : "the Ritz projection raises it only by its mass term's share, or measured in a lumped mass "
                          "(Contact/Boundary Mass = lumped)")
                << "; each mesh change's share is the step table's energy_transferred minus the energy of the step "
                   "before (README, Known behaviour)";
        core::rootOut(rank) << warning.str() << std::endl;
      }
      // Nothing supplies energy, yet the cycle gained some: the step tables' energies are not the
      // problem's. The Newmark energy, which the scheme conserves without contact and mesh changes
      // (kinetic + strain oscillates about it unless beta = 1/4).
      if (!sim_->problem().suppliesEnergy() && last.initialNewmarkEnergy > 0 &&
          last.largestNewmarkEnergy > (1 + kEnergyGainWarning) * last.initialNewmarkEnergy) {
        std::ostringstream warning;
        warning << std::setprecision(4) << "signorini: warning: cycle " << l << ": the Newmark energy (newmark_energy) reaches "
                << last.largestNewmarkEnergy << " in step " << last.largestNewmarkEnergyStep << " (t = "
                << last.largestNewmarkEnergyStep * sim_->timeStep() << "), " << std::fixed << std::setprecision(1)
                << 100 * (last.largestNewmarkEnergy / last.initialNewmarkEnergy - 1) << std::defaultfloat
                << std::setprecision(4) << "% above its initial " << last.initialNewmarkEnergy
                << ", although no load, body force or moving obstacle supplies energy";
        if (last.transferEnergyRise > 0)
          warning << " (the transfers between step meshes raised the energy by " << last.transferEnergyRise << " in all)";
        if (last.stepsInContact > 0)
          warning << ": where a step's finer contact segments meet a penetration that the coarser segments of the "
                     "step before allowed, the step pushes the body out (Adaptivity/Contact Zone Gap refines the "
                     "contact zone before the first contact); where contact is released, the time-discrete contact "
                     "gains energy (a smaller Time Step reduces it)";
        else
          warning << ": without contact only the transfers between the step meshes change it (Adaptivity/Transfer = "
                     "Ritz projection cannot raise the energy)";
        warning << "; see the step table's newmark_energy and energy_transferred, README Known behaviour";
        core::rootOut(rank) << warning.str() << std::endl;
      }
      if (stop) {
        if (!lastPlanned) {
          core::rootOut(rank) << "signorini: cycle " << l << " ends the run: "
                              << (tol > 0 && etaMax <= tol ? "its estimate is at or below Adaptivity/Tolerance"
                                                           : "its total unknowns reach Adaptivity/Maximum Total Unknowns")
                              << std::endl;
          last.files = promoteToFinalName(last.files, base + ".cycle" + std::to_string(l), base, *comm);
        } else if (tol > 0 && etaMax > tol) {  // the last planned cycle, the tolerance not reached
          std::ostringstream note;
          note << std::setprecision(4) << std::scientific << "signorini: the run ends with cycle " << l
               << (l == cycles - 1 ? " (Adaptivity/Cycles)" : "") << " at the estimate " << etaMax
               << ", above Adaptivity/Tolerance " << tol;
          core::rootOut(rank) << note.str() << std::endl;
        }
        break;
      }
      previousFiles = last.files;
    }
    core::throwIfInterrupted(*comm);  // a signal during the last step: the files go
    core::onRootCollectively(*comm, [&] {
      if (cyclesCsv) cyclesCsv->commit();
      staging.commit();
    });
  } catch (...) {
    if (cyclesCsv) cyclesCsv->remove();
    throw;
  }
  last.files.insert(last.files.begin(), earlierFiles.begin(), earlierFiles.end());
  if (cyclesCsv) last.files.push_back(cyclesCsv->path());
  last.phaseSeconds = phaseSeconds;
  last.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
  return last;
}

}  // namespace signorini::adapt
