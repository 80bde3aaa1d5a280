#pragma once
/// \file Simulation.hpp
/// One run of a deck: the dynamic Signorini problem stepped by Newmark with a contact QP per
/// step (paper Algorithm 3.3 on a uniform mesh), with per-step CSV and Exodus output.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <functional>

#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/io/OutputStaging.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::dynamics {

/// What a finished run (or pass over [0, T]) reports back (rank 0 has the file names).
struct RunSummary {
  int steps = 0;               ///< time steps N of the run (of one pass)
  long long dofsPerStep = 0;   ///< unknowns of the last step
  long long totalDofs = 0;     ///< sum over the steps n = 1..N of the unknowns of T^n
  long meshChanges = 0;        ///< steps whose mesh differed from the previous step's
  double wallSeconds = 0;      ///< the whole run (an adaptive run: all cycles)
  std::vector<std::string> files;  ///< every file the run wrote (an adaptive run: also the earlier cycles')
  /// Wall seconds per phase (mesh, assembly, preconditioner, contact, output, ...) over the whole run
  /// (all cycles); the phases are exclusive (core::PhaseTimers). A one-pass run (run()) includes
  /// the set-up on the deck's mesh before it (its solver, set up once), which wallSeconds does not.
  std::map<std::string, double> phaseSeconds;
  /// \var transferEnergyChange
  /// With PassOptions::reportTransferEnergy: the change of the energy (kinetic + strain) by the
  /// transfers between the step meshes, summed over the mesh changes [energy per unit thickness].
  /// \var transferEnergyRise
  /// The same summed over the mesh changes that raised the energy only.
  /// \var largestEnergy
  /// The largest energy (kinetic + strain) of a step [energy per unit thickness].
  double transferEnergyChange = 0, transferEnergyRise = 0, largestEnergy = 0;
  /// \var initialNewmarkEnergy
  /// The step table's newmark_energy in step 0 (the initial state on the pass's first mesh), which
  /// Newmark's scheme conserves without contact, loads and mesh changes (2 beta >= alpha = 1/2).
  /// \var largestNewmarkEnergy
  /// Its largest value over the steps.
  double initialNewmarkEnergy = 0, largestNewmarkEnergy = 0;
  int largestNewmarkEnergyStep = 0;  ///< the step of largestNewmarkEnergy (the first, if several)
  int stepsInContact = 0;            ///< steps with an active contact segment
};

/// What a per-step hook sees right after step n was solved (references valid during the call).
struct StepView {
  int step;                              ///< n (1..N)
  /// \var time
  /// t_n = n k [time].
  /// \var timeStep
  /// k [time].
  /// \var beta
  /// Newmark's beta.
  double time, timeStep, beta;
  const mesh::Forest& forest;            ///< T^n
  const mesh::Q1Mesh& mesh;              ///< T^n's Q1 numbering
  const fem::Assembler& assembler;       ///< fem::Q1Assembler (scalar wave) or fem::ElasticityAssembler
  const fem::ContactCoupling* coupling;  ///< null without obstacle
  const fem::ProblemData& problem;       ///< the deck's data (segments, material, obstacle g)
  const Vector& u;                       ///< u_h^n
  const Vector& predictor;               ///< I_h u^{n-1} + k I_h v^{n-1} + (1/2 - beta) k^2 I_h a^{n-1}
  const std::vector<double>& lambda;     ///< scaled QP multipliers
  long meshId;                           ///< differs between any two meshes of the run
  /// StepExtras::carry of the previous step, on this step's mesh (nodal interpolation when the mesh
  /// changed); empty in the first step.
  const std::vector<RCP<Vector>>& carried;
  /// \var consistentMass
  /// The step's consistent mass matrix M_rho (also where the scheme lumps it).
  /// \var stiffness
  /// The step's stiffness matrix K_kappa.
  RCP<const CrsMatrix> consistentMass, stiffness;
};
/// Extra per-step results from a hook: CSV columns (in the order of PassOptions::extraColumns)
/// and one cell field for Exodus.
struct StepExtras {
  std::vector<double> columns;    ///< the values of PassOptions::extraColumns for this step
  std::vector<double> cellField;  ///< one value per local cell (PassOptions::cellFieldName), or empty
  /// Scalar fields on this step's mesh (owned node map) handed to the next step's hook
  /// (StepView::carried), e.g. a warm start.
  std::vector<RCP<Vector>> carry;
};
/// Runs after each step of a pass (Simulation::runPass): the adaptive driver's estimator.
using StepHook = std::function<StepExtras(const StepView&)>;

/// How a pass writes its outputs.
struct PassOptions {
  std::string basename;                   ///< empty: the deck's basename
  /// \var writeCsv
  /// Write the step table.
  /// \var writeExodus
  /// Write the Exodus series (when Output/Write Exodus is true as well).
  bool writeCsv = true, writeExodus = true;
  std::vector<std::string> extraColumns;  ///< names of StepExtras::columns
  std::string cellFieldName;              ///< name of StepExtras::cellField in Exodus (empty: none)
  /// I_h between the step meshes (Adaptivity/Transfer): the paper's L2 projection of every field,
  /// nodal interpolation, or the Ritz projection of u with the L2 projection of v and a, which
  /// cannot raise the energy (the L2 projection of u raises the strain energy by about that of its
  /// error, a(P u - u, P u - u), where a step's mesh is coarser than its predecessor's).
  enum class Transfer { l2Projection, interpolation, ritzProjection };
  Transfer transfer = Transfer::l2Projection;  ///< how the state moves to a step's new mesh
  /// Step-table columns energy_transferred, kinetic_energy_transferred: the energies
  /// of (I_h u^{n-1}, I_h v^{n-1}) on the mesh of step n (those of step n-1 when the mesh is kept),
  /// so the transfer's effect on the energy is visible. Costs a third projected field (Newmark::recoveryField).
  bool reportTransferEnergy = false;
  /// Step-table columns external_work, contact_work: the work of the loads and of the contact
  /// multipliers on the body since t = 0, summed over the steps as (u^n - u^{n-1}) . (f^{n-1} + f^n) / 2,
  /// so that with Alpha = 1/2 newmark_energy(n) = newmark_energy(0) + external_work + contact_work.
  /// Only for a pass on one mesh (every step's mesh the same).
  bool reportWork = true;
  /// Step-table columns momentum (scalar wave), momentum_x, momentum_y, angular_momentum (elasticity,
  /// about Output/Moment Point): m . v with m_j = int rho phi_j (of a component), (M r) . v with r the
  /// rigid rotation; on any meshes (the weights are built again where the mesh changes).
  bool reportMomentum = true;
  /// Compact a step's forest (mesh::Forest::compact()) once the pass has moved past it; meshes are
  /// expanded when a step needs them either way.
  bool compactMeshes = false;
};

/// One deck's dynamic Signorini problem (Newmark (3.1)-(3.2) with the contact QP (3.7)-(3.8) per
/// step) on the deck's mesh (run()) or on a mesh per step (runPass(), for the adaptive driver).
/// Owns the deck's copy, the mesh hierarchy and every per-mesh discretisation; collective over
/// \p comm, which it keeps.
class Simulation {
 public:
  /// The deck sublists Problem, Mesh, Time Integration, Contact, Linear Solver, Output.
  static core::ParameterList getValidParameters();

  /// \param deck      validated deck (core::validateDeck with getValidParameters()).
  /// \param deckPath  the deck's file (for messages, relative mesh files and the default basename).
  /// \param outputDir overrides Output/Directory when not empty.
  /// \param comm      the ranks that share the run (kept).
  /// Builds the mesh and checks the problem set-up (segments, initial state against the obstacle)
  /// without writing anything; throws core::UserError on bad input.
  Simulation(const core::ParameterList& deck, const std::string& deckPath, const std::string& outputDir,
             RCP<const Comm> comm);
  ~Simulation();

  /// Runs all time steps on the deck's uniform mesh and writes the outputs; on failure no output
  /// file is left under a final name.
  RunSummary run();
  /// One pass over [0, T] with the mesh meshes[n-1] in step n (paper Algorithm 3.3): the initial
  /// values are projected onto meshes[0]; when a step's mesh differs from the previous one, a new
  /// discretisation is built and (u, v, a) are transferred (L2 projection or interpolation);
  /// otherwise nothing mesh-dependent is rebuilt. \p hook (may be empty) runs after each step.
  RunSummary runPass(const std::vector<std::shared_ptr<mesh::Forest>>& meshes, const StepHook& hook,
                     const PassOptions& options);
  /// The deck's initial (uniform) mesh.
  std::shared_ptr<mesh::Forest> initialForest() const;
  int numSteps() const;  ///< N = Final Time / Time Step
  /// The step the current or last runPass() was computing (0: the initial state), for messages.
  int currentStep() const;
  double timeStep() const;  ///< k
  /// Unknowns of the deck's (initial) mesh (before the first pass: it takes the mesh's discretisation; 0 after).
  long long initialUnknowns() const;
  /// Unknowns per node: 1 (membrane), 2 (elasticity).
  int unknownsPerNode() const;
  /// The deck's problem data.
  const fem::ProblemData& problem() const;
  /// "<cells> cells (Refinement Level <l>), <unknowns> unknowns": the mesh of the Schur
  /// preconditioner's coarse correction, if the initial mesh uses it (else empty).
  std::string coarseCorrectionMesh() const;
  /// "CG + Jacobi" and, for Preconditioner = auto, the Courant numbers c k / h_min that choose it:
  /// on the initial mesh and on a mesh refined \p finerLevels more levels (--check's plan).
  std::string linearSolverPlan(int finerLevels) const;
  /// The step table's columns (and, but for step, t and the time_ columns, the Exodus global
  /// variables) of a pass with \p options.
  std::vector<std::string> stepColumns(const PassOptions& options) const;
  RCP<const Comm> comm() const;  ///< the constructor's communicator
  const std::string& outputBase() const;  ///< output folder + "/" + basename
  /// The probes (Output/Probes) by name with their points as the run samples them (expressions
  /// evaluated; a point outside the body by the locator's tolerance moved onto it).
  const std::vector<std::pair<std::string, std::array<double, 2>>>& probes() const;
  /// The point (Output/Moment Point, evaluated) about which elasticity's step tables take the
  /// moments and the angular momentum; null for the scalar wave equation.
  const std::array<double, 2>* momentPoint() const;
  /// The supports whose reactions the step table gives one by one (two or more Dirichlet segments;
  /// else empty): each segment's name and its centre, about which elasticity's
  /// reaction:<segment>:moment is taken.
  std::vector<std::pair<std::string, std::array<double, 2>>> supports() const;
  /// Output/Stress Region, where max_von_mises looks (elasticity); null for every cell.
  const core::Expression* stressRegion() const;
  /// The deck as the run uses it and its output files record it: validated, defaults filled in,
  /// a relative Mesh/File made absolute (--print-parameters DECK prints it).
  const core::ParameterList& deck() const;
  /// Creates the output folder (and its parents) if it is missing; run() does this first, in its
  /// staging scope, so that a failed run removes them again (io::removeOnFailure). The
  /// constructor only checks that it could (and leaves no folder behind). Returns the lock of the
  /// output base for the run (io::OutputLock; on rank 0, null on the others), which the caller holds
  /// until its files are committed and releases before the staging scope ends. Collective.
  [[nodiscard]] std::unique_ptr<io::OutputLock> createOutputDirectory() const;
  /// Throws core::UserError naming \p cause if a step mesh of \p globalCells cells certainly
  /// cannot fit into this machine's memory or exceeds the 32-bit local indices of p4est and Tpetra
  /// on a rank. Collective. The memory is a lower bound: 750 bytes per cell times (unknowns per
  /// node)^2 (measured: 675 bytes per cell on the uniform membrane at 262k cells; peak resident
  /// memory over cells 10.5 kB on the bar at 16k cells and 5.2 kB at 65k, the process's fixed
  /// share and the coarse Schur correction (Contact/Coarse Correction Cells, or the coarse mesh's
  /// trees when they are more; not counted here) included), plus one byte per cell of the \p storedCells that the meshes of all steps hold
  /// (compact; 35-51 bytes as p4est forests).
  void checkMeshFits(double globalCells, const std::string& cause, double storedCells = 0) const;
  /// Throws core::UserError if Problem/Initial Displacement penetrates the obstacle in the mean over
  /// a contact segment of a mesh refined up to \p finerLevels more levels along Gamma_C (the finest
  /// segments that later adaptive cycles can make), which the deck's mesh cannot show: its segment
  /// means average the penetration away. \p cause names the setting. Collective.
  void checkInitialGapOnRefinements(int finerLevels, const std::string& cause) const;
  /// Throws core::UserError if a boundary segment that Problem uses holds boundary edges on the
  /// deck's mesh but none on a mesh refined up to \p finerLevels more levels, or the other way
  /// round (its coordinate conditions select less than an edge, tested at the edges' midpoints):
  /// the later cycles would drop or gain a Dirichlet, Neumann or contact condition. Collective.
  void checkSegmentsOnRefinements(int finerLevels, const std::string& cause) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini::dynamics
