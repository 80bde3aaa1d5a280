#pragma once
/// \file AdaptiveSimulation.hpp
/// The adaptive driver of paper Algorithm 5.1 (AdaptiveSimulation) and its per-cycle summary (CycleSummary).
#include <memory>
#include <string>
#include <vector>

#include "signorini/dynamics/Simulation.hpp"

namespace signorini::adapt {

/// The totals of one cycle of Algorithm 5.1: one row of \<basename\>.cycles.csv.
struct CycleSummary {
  int cycle;             ///< cycle index l (0: the deck's mesh)
  long long totalDofs;   ///< sum over the steps of the unknowns of T^n
  double eta;            ///< max_n eta^n
  double wallSeconds;    ///< the cycle's pass with Algorithm 5.3 after it (cycles.csv's wall_seconds) [s]
  long long cells;         ///< sum over the steps of the cells of T^n
  long long storedMeshes;  ///< distinct forests stored for the cycle (equal consecutive meshes share one)
  long long storedCells;   ///< cells of the distinct forests
  double bytesPerCell;     ///< memory of the stored meshes (compact or p4est forests) per stored cell [bytes]
  long meshRebuilds;       ///< steps whose mesh differed from the previous step's (operators rebuilt)
};

/// Paper Algorithm 5.1 (DESIGN 1.3): cycles of whole passes over [0, T]; after step n of cycle l the estimator eta^n_l
/// marks cells of T^n_l, which refined and 2:1 balanced (Algorithm 5.2) become T^n_{l+1}; after each pass the step
/// meshes are regularised in time (Algorithm 5.3). Strategy "uniform" marks every cell (the comparison runs), "none"
/// runs one pass on the deck's mesh without the estimator. Owns a copy of the deck and its dynamics::Simulation.
class AdaptiveSimulation {
 public:
  /// The valid parameter list of the whole deck, with defaults, doc strings and validators: the sublists of
  /// dynamics::Simulation::getValidParameters() plus "Adaptivity" and "Estimator".
  static core::ParameterList getValidParameters();
  /// Checks the settings that conflict (core::UserError naming the keys; a warning on rank 0 for keys without
  /// effect) and builds the dynamics::Simulation, which keeps \p comm; writes nothing.
  /// \param deck      validated deck (core::validateDeck with getValidParameters()); copied.
  /// \param deckPath  the deck's file (messages, relative mesh files, the default basename).
  /// \param outputDir overrides Output/Directory when not empty.
  /// \param comm      the run's communicator. Collective over it.
  AdaptiveSimulation(const core::ParameterList& deck, const std::string& deckPath, const std::string& outputDir,
                     RCP<const Comm> comm);
  ~AdaptiveSimulation();
  /// Runs all cycles; writes \<basename\>.cycles.csv and per-cycle step tables and results.
  dynamics::RunSummary run();
  /// What run() will do, in a few lines (steps, unknowns of the initial mesh, cycles and
  /// strategy, output base): the driver's --check prints it.
  std::string plan() const;
  /// The output folder and basename of the run's files ("<folder>/<basename>").
  const std::string& outputBase() const;
  /// The deck as the run uses it (dynamics::Simulation::deck()).
  const core::ParameterList& deck() const;
  /// The cycles run() has completed, in order (empty before run()).
  const std::vector<CycleSummary>& cycles() const { return cycles_; }

 private:
  /// "cycle l, step n (t = ...): " (no cycle without adaptivity), the start of a failure's message.
  std::string whereInRun(int cycle) const;
  /// The options every cycle's pass shares (the estimate's columns and cell field, the transfer, no work columns:
  /// the meshes change; momentum columns as on one mesh).
  dynamics::PassOptions cyclePassOptions() const;
  /// Sum over the steps of the unknowns of each step's mesh (a cycle's total_dofs before it runs).
  /// Collective; compact forests are expanded for the count and compacted again.
  double totalUnknowns(const std::vector<std::shared_ptr<mesh::Forest>>& meshes) const;
  /// pass() (a pass of cycle \p cycle), its solver and user errors prefixed with whereInRun().
  template <class Pass>
  dynamics::RunSummary locatingFailures(int cycle, Pass pass) const;

  core::ParameterList deck_;
  std::unique_ptr<dynamics::Simulation> sim_;
  std::vector<CycleSummary> cycles_;
};

}  // namespace signorini::adapt
