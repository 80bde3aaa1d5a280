#pragma once
/// \file Simulation.hpp
/// One run of a deck: the dynamic Signorini problem stepped by Newmark with a contact QP per
/// step (paper Algorithm 3.3 on a uniform mesh), with per-step CSV and Exodus output.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ParameterTools.hpp"
#include "Types.hpp"

namespace signorini::dynamics {

/// What a finished run reports back (rank 0 has the file names).
struct RunSummary {
  int steps = 0;
  long long dofsPerStep = 0;
  double wallSeconds = 0;
  std::vector<std::string> files;
  /// Wall seconds per phase (mesh, assembly, preconditioner, contact, output) over the whole run.
  std::map<std::string, double> phaseSeconds;
};

class Simulation {
 public:
  /// The whole deck: sublists Problem, Mesh, Time Integration, Contact, Linear Solver, Output.
  static core::ParameterList getValidParameters();

  /// \param deck      validated deck (core::validateDeck with getValidParameters()).
  /// \param deckPath  the deck's file (for messages, relative mesh files and the default basename).
  /// \param outputDir overrides Output/Directory when not empty.
  /// Builds the mesh and checks the problem set-up (segments, initial state against the obstacle)
  /// without writing anything; throws core::UserError on bad input.
  Simulation(const core::ParameterList& deck, const std::string& deckPath, const std::string& outputDir,
             RCP<const Comm> comm);
  ~Simulation();

  /// Runs all time steps and writes the outputs; on failure no output file is left under a final name.
  RunSummary run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini::dynamics
