#include "signorini/dynamics/Simulation.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <map>
#include <limits>
#include <sstream>
#include <tuple>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/solvers/CoarseSchurCorrection.hpp"
#include "signorini/fem/ContactCoupling.hpp"
#include "signorini/fem/LoadResultant.hpp"
#include "signorini/solvers/ContactQP.hpp"
#include "signorini/io/CsvWriter.hpp"
#include "signorini/io/OutputStaging.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/core/Interrupt.hpp"
#include "signorini/solvers/JacobiCG.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/solvers/LinearSolver.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/dynamics/Newmark.hpp"
#include "signorini/core/PhaseTimers.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/fem/ElasticityAssembler.hpp"
#include "signorini/fem/Q1Assembler.hpp"
#include "signorini/fem/MeshTransfer.hpp"
#include "signorini/dynamics/ResultWriter.hpp"

namespace signorini::dynamics {
namespace {
/// An elastic deck's obstacle that slopes across Contact Direction by more than this at the contact
/// boundary draws a warning: the contact force acts along the direction, not normal to the obstacle.
constexpr double kObstacleSlopeWarningDegrees = 5.0;

/// The largest of the ranks' \p worst[0], with the point \p worst[1], \p worst[2] that comes with it,
/// on every rank (the lowest rank's among equal values). Collective.
void largestWithPoint(const Comm& comm, double worst[3]) {
  struct {
    double value;
    int rank;
  } mine{worst[0], comm.getRank()}, first{};
  MPI_Allreduce(&mine, &first, 1, MPI_DOUBLE_INT, MPI_MAXLOC, core::rawMpiComm(comm));
  MPI_Bcast(worst, 3, MPI_DOUBLE, first.rank, core::rawMpiComm(comm));
}

/// For each point of \p to, the index of the nearest point of \p from (Euclidean distance, the
/// lowest index among equally near ones; -1 when \p from is empty). Sorted along the coordinate
/// of larger spread, so a contact boundary (a line) costs O(log n) per point instead of O(n).
std::vector<int> nearestPoints(const std::vector<std::array<double, 2>>& from, const std::vector<std::array<double, 2>>& to) {
  std::vector<int> result(to.size(), -1);
  if (from.empty()) return result;
  double lo[2] = {from[0][0], from[0][1]}, hi[2] = {lo[0], lo[1]};
  for (const auto& p : from)
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
  const int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  std::vector<int> order(from.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return from[a][axis] < from[b][axis]; });
  for (size_t j = 0; j < to.size(); ++j) {
    const auto& p = to[j];
    double best = std::numeric_limits<double>::infinity();
    int bestIndex = -1;
    auto consider = [&](int i) {  // false once every further point along the axis is farther
      if (std::abs(from[i][axis] - p[axis]) > best) return false;
      const double d = std::hypot(from[i][0] - p[0], from[i][1] - p[1]);
      if (d < best || (d == best && i < bestIndex)) best = d, bestIndex = i;
      return true;
    };
    const auto split = std::lower_bound(order.begin(), order.end(), p[axis],
                                        [&](int i, double v) { return from[i][axis] < v; }) - order.begin();
    for (auto k = split; k < static_cast<long>(order.size()) && consider(order[k]); ++k) {
    }
    for (auto k = split - 1; k >= 0 && consider(order[k]); --k) {
    }
    result[j] = bestIndex;
  }
  return result;
}

core::ParameterList outputParameters() {
  core::ParameterList p("Output");
  core::addString(p, "Directory", ".", "Folder for all output files (created if missing); --output-dir overrides it");
  core::addString(p, "Basename", "", "Prefix of the output files; empty: the deck's file name without .xml");
  core::addBool(p, "Write Exodus", true, "Write <basename>.e (Exodus II time series for ParaView)");
  core::addInt(p, "Exodus Interval", 1, "Write every n-th step to Exodus (the first and last step always; no Exodus file: Write Exodus = false)", 1);
  core::addInt(p, "Progress Interval", 0, "Print a progress line every n steps (0: about 20 lines per run)", 0);
  core::addBool(p, "Measure Contact Overhead", false,
                "Also solve each step without contact (same A, preconditioner and initial guess) and report its "
                "time as time_unconstrained: the contact solve costs time_contact / time_unconstrained of it");
  core::addNamedStrings(p, "Probes",
                        "Named points \"x, y\" of the undeformed body (numbers or constant expressions, e.g. \"0.2, "
                        "0.05/2\"): u interpolated there becomes the CSV column probe:<name> (elasticity: "
                        "probe:<name>:x and probe:<name>:y); a name holds no comma, quote or line break");
  core::addString(p, "Probe Fields", "u",
                  "The fields sampled at each probe, a list of u, v, a, sigma (in any order; u always): u "
                  "(displacement) gives probe:<name>, v (velocity) probe:<name>:v, a (acceleration) probe:<name>:a "
                  "(elasticity: each with :x and :y appended); sigma (elasticity) the stress probe:<name>:sigma_xx, "
                  ":sigma_yy, :sigma_xy, :sigma_zz and :von_mises [force / area], the mean over the cells that hold "
                  "the point");
  core::addString(p, "Stress Region", "1",
                  "Elasticity: where the step table's max_von_mises looks, an expression of x and y that is not 0 "
                  "at the centres of the cells that count (e.g. \"(x > 0.05) * (0.95 > x)\" leaves out the "
                  "clamped ends' singular corners; \"1\": every cell)");
  core::addString(p, "Moment Point", "0, 0",
                  "Elasticity: the point \"x, y\" (numbers or constant expressions) about which the step table's "
                  "moments are taken: reaction_moment, applied_moment, contact_moment [force length / length], "
                  "counterclockwise positive, and angular_momentum");
  return p;
}

/// A point "x, y" of the deck: numbers or constant expressions ("0.05/2, pi/8"; commas inside
/// parentheses belong to calls), finite; \p key names the entry and \p whose the point in messages.
std::array<double, 2> parsePoint(const std::string& spec, const std::string& key, const std::string& whose) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (const char c : spec) {
    depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    if (c == ',' && depth == 0)
      parts.emplace_back();
    else
      parts.back() += c;
  }
  if (parts.size() != 2 || parts[0].find_first_not_of(" \t") == std::string::npos ||
      parts[1].find_first_not_of(" \t") == std::string::npos)
    SIGNORINI_USER_ERROR(key << ": expected \"x, y\", got \"" << spec << "\"");
  std::array<double, 2> xy;
  for (int c = 0; c < 2; ++c) {
    // A plain number (nan and inf too, refused below with the point) as the whole text, else an expression.
    const char* text = parts[c].c_str();
    char* end = nullptr;
    xy[c] = std::strtod(text, &end);
    if (end != text && std::string(end).find_first_not_of(" \t") == std::string::npos) continue;
    const core::Expression coordinate(core::trim(parts[c]), key + (c ? " (y)" : " (x)"), "none, a coordinate is constant");
    if (!coordinate.isConstant())
      SIGNORINI_USER_ERROR(key << ": \"" << spec << "\": " << whose
                               << " coordinates are numbers or constant expressions, not functions of x, y or t");
    xy[c] = coordinate(0, 0, 0);
  }
  if (!std::isfinite(xy[0]) || !std::isfinite(xy[1]))
    SIGNORINI_USER_ERROR(key << ": \"" << spec << "\" is not a point (a coordinate is not a finite number)");
  return xy;
}

/// The suffix of a probe's column for field \p field (0 u, 1 v, 2 a) and component \p c of \p nc.
std::string probeSuffix(int field, int c, int nc) {
  static const char* const fieldSuffix[] = {"", ":v", ":a"};
  return std::string(fieldSuffix[field]) + (nc == 1 ? "" : c == 0 ? ":x" : ":y");
}

/// The suffixes of a probe's stress columns (Output/Probe Fields with sigma), in
/// ElasticityAssembler::stressAtPoint's order.
const std::array<const char*, 5> kProbeStressSuffixes = {":sigma_xx", ":sigma_yy", ":sigma_xy", ":sigma_zz", ":von_mises"};

/// Output/Probe Fields read: the fields among u (0), v (1), a (2), in that order (u always), and
/// whether the stress is sampled. A name other than u, v, a, sigma, or one given twice, is a user error.
std::pair<std::vector<int>, bool> parseProbeFields(const std::string& text, bool elasticity) {
  static const char* const names[] = {"u", "v", "a", "sigma"};
  bool chosen[4] = {true, false, false, false};
  bool named[4] = {false, false, false, false};
  std::vector<std::string> items(1);
  for (const char c : text) {
    if (c == ',')
      items.emplace_back();
    else
      items.back() += c;
  }
  for (const auto& item : items) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    const std::string name = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    if (name.empty())
      SIGNORINI_USER_ERROR("Output/Probe Fields: \"" << text << "\" has an empty item: list u, v, a or sigma, "
                                                      "separated by commas");
    const auto at = std::find(std::begin(names), std::end(names), name) - std::begin(names);
    if (at == 4)
      SIGNORINI_USER_ERROR("Output/Probe Fields: \"" << name << "\" in \"" << text
                                                     << "\" is not a field: list u, v, a or sigma, separated by commas");
    if (named[at]) SIGNORINI_USER_ERROR("Output/Probe Fields: \"" << name << "\" is listed twice in \"" << text << "\"");
    named[at] = chosen[at] = true;
  }
  if (chosen[3] && !elasticity)
    SIGNORINI_USER_ERROR("Output/Probe Fields: sigma is the stress of plane strain elasticity (Problem/Type); the "
                         "scalar wave has none");
  std::vector<int> fields;
  for (int f = 0; f < 3; ++f)
    if (chosen[f]) fields.push_back(f);
  return {fields, chosen[3]};
}

/// The longest probe name: "probe:<name>" and its longest suffix (":v:x") must fit the 256 bytes
/// of a netCDF name. At least two bytes are kept for the suffix, so that the names of a deck's
/// probes of u fit both a scalar problem and elasticity.
size_t maxProbeNameLength(const std::vector<int>& fields, bool stress, int nc) {
  size_t longest = 2;
  for (const int f : fields) longest = std::max(longest, probeSuffix(f, nc - 1, nc).size());
  if (stress)
    for (const char* suffix : kProbeStressSuffixes) longest = std::max(longest, std::string(suffix).size());
  return 256 - 6 - longest;
}

bool isFileDescriptorPath(const std::string& path);

/// The folder a deck's relative paths are taken from: the deck's own, or the working directory for
/// a deck read from a stream (/dev/stdin, /dev/fd/N, /proc/self/fd/N), whose "folder" is /dev.
std::string directoryOf(const std::string& path) {
  if (path == "/dev/stdin" || isFileDescriptorPath(path)) return ".";
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

/// An output folder or basename with a control character (a newline splits the "wrote" lines and
/// every listing of the files), or a folder that begins with a blank (the Exodus library drops the
/// leading blanks of its path, so its file went to another folder than the CSV tables: "   /membrane.e"
/// became "/membrane.e"), is a user error naming \p key.
void refuseUnusablePathText(const std::string& text, const std::string& key, bool folder) {
  for (const char c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      SIGNORINI_USER_ERROR(key << ": contains a control character (byte " << int(static_cast<unsigned char>(c))
                               << "); output names must be printable");
  if (folder && !text.empty() && text.front() == ' ')
    SIGNORINI_USER_ERROR(key << " '" << text << "': begins with a blank, which the Exodus library would drop from the "
                             "path (its file would go to another folder than the tables); remove the leading blanks");
}

std::string stemOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (core::endsWith(name, ".xml")) name.resize(name.size() - 4);
  return name;
}

/// Whether \p path names a file descriptor (/dev/fd/N, /proc/self/fd/N, /proc/PID/fd/N), as bash's
/// process substitution <(...) passes a deck.
bool isFileDescriptorPath(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos || slash + 1 == path.size() ||
      path.find_first_not_of("0123456789", slash + 1) != std::string::npos)
    return false;
  const std::string dir = path.substr(0, slash);
  return dir == "/dev/fd" || (dir.rfind("/proc/", 0) == 0 && core::endsWith(dir, "/fd"));
}

/// Whether a file can be created in the existing directory \p dir (a probe with a name of this
/// process, created exclusively and removed again).
bool canCreateIn(const std::string& dir, int* error = nullptr) {
  const std::string probe = dir + "/.signorini-write-test-" + std::to_string(::getpid());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    if (error) *error = errno;
    return false;
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

/// Checks on rank 0 that \p dir (named by \p key in messages) can hold the run's files. With
/// \p create false (set-up, --check) nothing is created: every existing part of the path must be
/// a directory and a file must be creatable in the deepest one (so another run's fresh folder is
/// never touched). With \p create true (the run) the missing folders are made and handed to the
/// open staging scope, which removes them if the run fails (io::removeOnFailure). The verdict is
/// shared so every rank fails together.
void ensureWritableDirectory(const std::string& dir, const std::string& key, const Comm& comm, bool create) {
  core::onRootCollectively(comm, [&] {
    std::vector<std::string> created;
    std::string partial, deepest = ".", why;
    bool ok = true;
    std::stringstream ss(dir);
    if (!dir.empty() && dir[0] == '/') partial = deepest = "/";
    for (std::string part; ok && std::getline(ss, part, '/');) {
      if (part.empty()) continue;
      partial += part + "/";
      struct stat info;
      if (::stat(partial.c_str(), &info) == 0) {
        ok = S_ISDIR(info.st_mode);
        deepest = partial;
      } else if (errno != ENOENT) {
        ok = false;  // e.g. ENOTDIR: a file on the way
        why = " (" + std::string(std::strerror(errno)) + ")";
      } else if (!create) {
        break;  // the rest would be created in `deepest`
      } else if (::mkdir(partial.c_str(), 0755) == 0) {
        created.push_back(partial);
        deepest = partial;
      } else if (errno == EEXIST && ::stat(partial.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
        deepest = partial;  // another process made it since the stat above (runs started together)
      } else {
        ok = false;
        why = " (" + std::string(std::strerror(errno)) + ")";
      }
    }
    if (int error = 0; ok && !canCreateIn(deepest, &error))
      ok = false, why = " (no file can be created in '" + deepest + "': " + std::strerror(error) + ")";
    if (ok)
      io::removeOnFailure(created);
    else
      for (auto it = created.rbegin(); it != created.rend(); ++it) ::rmdir(it->c_str());
    if (!ok) SIGNORINI_USER_ERROR(key << ": cannot write to '" << dir << "'" << why);
  });
}

/// Component c of a vector with nc unknowns per node, as a vector on the node map \p nodes (owned
/// or overlap: the unknowns follow the nodes' local order).
RCP<Vector> component(const Vector& x, int c, int nc, const RCP<const Map>& nodes) {
  auto out = Teuchos::rcp(new Vector(nodes));
  auto xh = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto oh = out->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (size_t i = 0; i < oh.extent(0); ++i) oh(i, 0) = xh(nc * i + c, 0);
  return out;
}

/// The inverse of component(): one vector of parts.size() unknowns per node.
RCP<Vector> interleave(const std::vector<RCP<Vector>>& parts, const RCP<const Map>& unknowns) {
  auto out = Teuchos::rcp(new Vector(unknowns));
  auto oh = out->getLocalViewHost(Tpetra::Access::OverwriteAll);
  const size_t nc = parts.size();
  for (size_t c = 0; c < nc; ++c) {
    auto ph = parts[c]->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (size_t i = 0; i < ph.extent(0); ++i) oh(nc * i + c, 0) = ph(i, 0);
  }
  return out;
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
  core::ParameterList parallel("Parallel");
  core::addBool(parallel, "Reproducible Arithmetic", false,
                "Order every sum so that the results have the same bits on any number of ranks (docs/reproducibility.md; "
                "scalar problems with the Jacobi preconditioner; the paper deck takes about 1.1 times as long)");
  core::addDouble(parallel, "Memory Per Rank", 0.0,
                  "Memory each rank may use [GB] for the checks that a mesh, and the contact QP's dense arrays on "
                  "the deck's mesh, fit before they are built; 0: the machine's memory divided by the ranks on it "
                  "(for the contact QP, all memory of rank 0's machine; set it where a job gets a share of a node)",
                  0.0);
  p.set("Parallel", parallel, "How the work is shared between MPI ranks");
  return p;
}

/// Everything that depends on one mesh: numbering, matrices, solvers, contact coupling.
struct Discretisation {
  std::shared_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;
  std::unique_ptr<fem::Assembler> assembler;
  RCP<CrsMatrix> M, K, A;
  /// M unlumped, for the L2 projections, when M is lumped at the contact nodes (else M itself)
  RCP<CrsMatrix> consistentM;
  std::unique_ptr<solvers::LinearSolver> solver, massSolver, projectionSolver;
  std::unique_ptr<fem::ContactCoupling> coupling;
  std::unique_ptr<solvers::ContactQP> qp;
  std::unique_ptr<solvers::ContactQP> projection;  ///< predictor projection (contact stabilisation)
  double courant = 0;
  bool lumpedMass = false;
  std::vector<char> lumpAt;  ///< the unknowns whose mass couplings M holds on its diagonal (empty: none)
  /// Per support (Simulation::Impl::supports): flags on the overlap unknowns it holds (built at the first output).
  std::vector<std::vector<char>> supportRows;
  /// Output/Stress Region: flags of the local cells whose centre lies in it (built at the first output).
  std::vector<char> stressCells;
  bool stressCellsBuilt = false;
  long builtAtStep = 0;  ///< identifies the mesh in the Exodus series
  long id = 0;           ///< unique among all discretisations of the run (StepView::meshId)
};

/// A coarse mesh held whole on every rank, for the far-field part of the Schur preconditioner
/// (solvers::CoarseSchurCorrection); built once per run when needed.
struct CoarseProblem {
  int level = 0;  ///< its refinement level (negative: blocks of a rectangle's cells, the p4est trees)
  std::shared_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;
  std::unique_ptr<fem::Assembler> assembler;
  std::unique_ptr<solvers::CoarseSchurCorrection> schur;
};

struct Simulation::Impl {
  RCP<const Comm> comm;
  core::ParameterList deck;
  std::string deckPath, outDir, basename, outputBase;
  std::string outDirKey;  ///< where outDir comes from: "Output/Directory" or "--output-dir"
  std::shared_ptr<mesh::CoarseMesh> coarse;
  int components = 1;  // unknowns per node (1 scalar wave, 2 elasticity)
  std::unique_ptr<mesh::BoundarySegments> segments;
  std::unique_ptr<fem::ProblemData> problem;
  std::unique_ptr<Newmark> newmark;
  std::shared_ptr<mesh::Forest> initialForest;
  std::unique_ptr<Discretisation> initialDiscretisation;  ///< built for the set-up checks; used by the first pass
  std::vector<std::pair<std::string, std::array<double, 2>>> probes;
  std::vector<int> probeFields = {0};  ///< the fields sampled at each probe: 0 u, 1 v, 2 a (Output/Probe Fields)
  bool probeStress = false;            ///< and the stress (elasticity)
  std::vector<std::string> probeColumns;  ///< the steps table's probe columns, probe by probe, field by field
  std::array<double, 2> momentPoint = {0, 0};  ///< Output/Moment Point (elasticity's moments)
  /// Output/Stress Region (elasticity), null for every cell: where max_von_mises looks.
  std::unique_ptr<core::Expression> stressRegion;
  /// The flags of d's local cells whose centre lies in stressRegion (null without one; built once per mesh).
  const std::vector<char>* stressCells(Discretisation& d) const {
    if (!stressRegion) return nullptr;
    if (!d.stressCellsBuilt) {  // collective: a value that is no number (nan) is a user error on every rank
      d.stressCellsBuilt = true;  // (a flag: a rank without cells has an empty list)
      const auto& X = d.mesh->cornerCoordsHost;
      d.stressCells.resize(static_cast<size_t>(d.mesh->numLocalCells()));
      std::string bad;
      for (LO e = 0; e < d.mesh->numLocalCells(); ++e) {
        double x = 0, y = 0;
        for (int c = 0; c < 4; ++c) x += 0.25 * X(e, c, 0), y += 0.25 * X(e, c, 1);
        d.stressCells[e] = stressRegion->sample(x, y, 0.0, bad) != 0;
      }
      core::throwFirstUserError(*comm, bad);
    }
    return &d.stressCells;
  }
  /// The Dirichlet segments (Mesh/Boundary Segments index, name) whose reactions the step table
  /// gives one by one, in the order of Mesh/Boundary Segments: empty unless two or more hold unknowns.
  std::vector<std::pair<int, std::string>> supports;
  /// The centre of each support (the mean of its boundary edges' points, the centre of a straight
  /// clamped section), about which its reaction:<segment>:moment is taken (elasticity).
  std::vector<std::array<double, 2>> supportCentres;
  /// Flags on d's overlap unknowns per support: each Dirichlet unknown belongs to the first support
  /// in supports that holds it (that component of it: a roller and a clamp may share a node's two).
  const std::vector<std::vector<char>>& supportRows(Discretisation& d) const {
    if (d.supportRows.empty() && !supports.empty()) {
      const int nc = problem->components();
      const auto& held = d.assembler->dirichletFlags();
      std::vector<char> taken(held.size(), 0);
      for (const auto& [segment, name] : supports) {
        const unsigned bit = 1u << segment;
        const auto on = d.mesh->nodesOnSegments(bit);
        std::vector<char> rows(held.size(), 0);
        for (size_t n = 0; n < on.size(); ++n)
          for (int c = 0; c < nc; ++c) {
            const size_t row = nc * n + c;
            const bool holds = (problem->dirichletMask & bit) || (nc == 2 && (problem->componentDirichletMask[c] & bit));
            if (on[n] && holds && held[row] && !taken[row]) rows[row] = taken[row] = 1;
          }
        d.supportRows.push_back(std::move(rows));
      }
    }
    return d.supportRows;
  }
  core::PhaseTimers timers;
  std::map<std::string, double> setupSeconds;  // the phases of the constructor's set-up
  std::unique_ptr<CoarseProblem> coarseProblem;
  long discretisations = 0;  ///< built so far (their ids)
  int currentStep = 0;       ///< the step runPass is at (0: the initial state)
  bool segmentsChecked = false;  ///< checkSegmentsHaveEdges ran (on the run's first mesh, the deck's)
  bool directionChecked = false;  ///< the Contact Direction was checked against the contact edges

  std::unique_ptr<fem::Assembler> makeAssembler(const mesh::Q1Mesh& m) const {
    if (problem->components() == 1) return std::make_unique<fem::Q1Assembler>(m, m.nodesOnSegments(problem->dirichletMask));
    return std::make_unique<fem::ElasticityAssembler>(m, fem::ElasticityAssembler::dirichletUnknowns(m, *problem),
                                                      problem->lameLambda, problem->lameMu);
  }
  std::vector<char> lumpedUnknowns(const fem::Assembler& a) const {
    return lumpsMass() ? a.unknownsOnSegments(problem->contactMask) : std::vector<char>{};
  }
  bool lumpsMass() const {
    return problem->hasObstacle && deck.sublist("Contact").get<std::string>("Boundary Mass") == "lumped";
  }
  /// On the deck's mesh: a Neumann edge where every component is held (under segment names of their
  /// own; the same name in both lists is refused with the deck) is a user error, the Dirichlet
  /// condition would drop the load; a traction component that is not 0 at t = 0 on an edge whose
  /// component is held by a roller (Dirichlet X/Y Segments) draws a warning (it has no effect there).
  void checkNeumannAgainstDirichlet(const mesh::Q1Mesh& mesh) {
    int flags[3] = {0, 0, 0}, any[3];  // every component held; x held and qx != 0; y held and qy != 0
    for (const auto& be : mesh.boundaryEdges()) {
      if (!(be.segments & problem->neumannMask)) continue;
      flags[0] |= (be.segments & problem->dirichletMask) || ((be.segments & problem->componentDirichletMask[0]) &&
                                                            (be.segments & problem->componentDirichletMask[1]));
      if (problem->components() == 2)
        for (int c = 0; c < 2; ++c)
          if (be.segments & problem->componentDirichletMask[c])
            for (double w : {0.0, 0.5, 1.0}) {
              const auto x = be.at(w);
              flags[1 + c] |= problem->neumannData[c](x[0], x[1], 0.0) != 0.0;
            }
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 3, flags, any);
    if (any[0])
      SIGNORINI_USER_ERROR("Problem: a boundary edge belongs to both a Neumann segment and a Dirichlet segment "
                           "(Problem/Neumann Segments against Dirichlet Segments; the Dirichlet condition fixes u there, "
                           "so the load would be dropped)");
    for (int c = 0; c < 2; ++c)
      if (any[1 + c] && comm->getRank() == 0)
        std::cerr << "signorini: warning: " << deckPath << ": Problem/Neumann Data's " << (c ? "y" : "x")
                  << " component is not 0 on edges where Problem/Dirichlet " << (c ? "Y" : "X")
                  << " Segments hold u_" << (c ? "y" : "x") << " = 0: that part of the load has no effect there"
                  << std::endl;
  }

  /// Throws a user error naming the Problem key and the segment if a segment that a boundary
  /// condition uses contains no boundary edge of \p mesh (e.g. "top, x >= 3" on a unit square).
  /// For the deck's mesh: edges belong to segments by their midpoints, so a segment narrower than
  /// an edge may have edges on some refinements and none on others.
  void checkSegmentsHaveEdges(const mesh::Q1Mesh& mesh) const {
    const std::pair<const char*, unsigned> uses[] = {{"Dirichlet Segments", problem->dirichletMask},
                                                     {"Dirichlet X Segments", problem->componentDirichletMask[0]},
                                                     {"Dirichlet Y Segments", problem->componentDirichletMask[1]},
                                                     {"Neumann Segments", problem->neumannMask},
                                                     {"Contact Segments", problem->contactMask}};
    unsigned local = 0, global = 0;
    for (const auto& be : mesh.boundaryEdges()) local |= be.segments;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_BOR, local, Teuchos::outArg(global));
    for (const auto& [key, mask] : uses)
      for (int i = 0; i < segments->size(); ++i)
        if ((mask >> i & 1u) && !(global >> i & 1u))
          SIGNORINI_USER_ERROR("Problem/" << key << ": the segment '" << segments->name(i)
                                          << "' contains no boundary edge of the mesh (see Mesh/Boundary Segments/"
                                          << segments->name(i) << ")");
  }
  /// Level of the coarse correction's mesh: the finest uniform one at most at Mesh/Refinement
  /// Level with at most Contact/Coarse Correction Cells cells, else the p4est trees themselves.
  int coarseCorrectionLevel() const {
    const double maxCells = deck.sublist("Contact").get<int>("Coarse Correction Cells");
    int level = -coarse->levelOffset();
    while (level < deck.sublist("Mesh").get<int>("Refinement Level") &&
           coarse->numTrees() * std::pow(4.0, level + 1 + coarse->levelOffset()) <= maxCells)
      ++level;
    return level;
  }
  /// The coarse step matrix, factored (once per run).
  const CoarseProblem& coarseCorrection() {
    if (!coarseProblem) {
      auto c = std::make_unique<CoarseProblem>();
      RCP<const Comm> self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
      c->level = coarseCorrectionLevel();
      c->forest = std::make_shared<mesh::Forest>(coarse, MPI_COMM_SELF, c->level);
      c->mesh = std::make_unique<mesh::Q1Mesh>(*c->forest, *segments, self);
      c->assembler = makeAssembler(*c->mesh);
      const double k = newmark->timeStep;
      std::string userError, failure;  // each rank factors its own copy: a failure on some ranks is every rank's
      try {
        c->schur = std::make_unique<solvers::CoarseSchurCorrection>(
            c->assembler->assembleSystem(1.0, newmark->beta * k * k, *problem, lumpedUnknowns(*c->assembler)));
      } catch (core::UserError& e) {
        userError = e.what();
      } catch (std::exception& e) {  // KLU2 out of memory on a fine initial mesh, typically
        failure = "the coarse Schur correction (Contact/Schur Preconditioner = auto or strip + coarse) could not "
                  "factor its mesh of " + std::to_string(c->forest->numGlobalCells()) + " cells, " +
                  std::to_string(c->assembler->ownedMap()->getGlobalNumElements()) + " unknowns on each rank (" +
                  core::withoutSourceLocation(e.what()) +
                  "); choose a smaller Contact/Coarse Correction Cells, Contact/Schur Preconditioner = strip, or a "
                  "coarse mesh of fewer cells";
      }
      core::throwFirstUserError(*comm, userError);
      core::throwFirstSolverError(*comm, failure);
      coarseProblem = std::move(c);
    }
    return *coarseProblem;
  }

  std::unique_ptr<Discretisation> build(std::shared_ptr<mesh::Forest> forest, long step) {
    auto d = std::make_unique<Discretisation>();
    d->forest = forest;
    d->builtAtStep = step;
    d->id = ++discretisations;
    {
      auto scope = timers.scope("mesh");
      d->mesh = std::make_unique<mesh::Q1Mesh>(*forest, *segments, comm);
    }
    {
      auto scope = timers.scope("assembly");
      d->assembler = makeAssembler(*d->mesh);
      const double k = newmark->timeStep;
      d->lumpAt = lumpedUnknowns(*d->assembler);
      d->lumpedMass = lumpsMass();  // the same on every rank, with or without contact nodes
      auto matrices = d->assembler->assembleStepMatrices(newmark->beta * k * k, *problem, d->lumpAt);
      d->M = matrices.M;
      d->K = matrices.K;
      d->A = matrices.A;
    }
    d->courant = problem->waveSpeed() * newmark->timeStep / d->mesh->hMin();
    auto scope = timers.scope("preconditioner");
    d->solver = std::make_unique<solvers::LinearSolver>(deck.sublist("Linear Solver"));
    d->solver->setSystemName("the step matrix A = M + beta k^2 K");
    if (auto* elasticity = dynamic_cast<const fem::ElasticityAssembler*>(d->assembler.get()))
      d->solver->setNearNullspace(elasticity->rigidBodyModes(), 2);
    d->solver->setOperator(d->A, d->courant);
    if (!segmentsChecked) {  // on the deck's mesh only: edges belong to segments by their midpoints
      checkSegmentsHaveEdges(*d->mesh);
      checkNeumannAgainstDirichlet(*d->mesh);
      segmentsChecked = true;
    }
    if (problem->hasObstacle) {
      // Contact where the constrained unknown is fixed (also under another segment name, or by a
      // Dirichlet X/Y segment on the contact component): a user error, on every mesh.
      const unsigned fixed = problem->dirichletMask |
                             (problem->components() == 2 ? problem->componentDirichletMask[problem->contactComponent] : 0u);
      int overlapLocal = 0, overlapGlobal = 0;
      unsigned intoBodyLocal = 0, intoBodyGlobal = 0;  // the contact segments with an edge that d points into
      const auto& corners = d->mesh->cornerCoordsHost;
      for (const auto& be : d->mesh->boundaryEdges())
        if (be.segments & problem->contactMask) {
          if (be.segments & fixed) overlapLocal |= 1;
          if (be.segments & problem->neumannMask) overlapLocal |= 2;
          if (problem->components() == 2 && !directionChecked) {
            // d = Contact Direction points into the body (d . n < 0, n the outward normal from the
            // edge and its cell's centre), so that d . u >= g keeps the body off an obstacle outside it.
            const double tx = be.x[1][0] - be.x[0][0], ty = be.x[1][1] - be.x[0][1];
            double cx = 0, cy = 0;
            for (int c = 0; c < 4; ++c) cx += 0.25 * corners(be.cell, c, 0), cy += 0.25 * corners(be.cell, c, 1);
            double nx = ty, ny = -tx;
            if (nx * (0.5 * (be.x[0][0] + be.x[1][0]) - cx) + ny * (0.5 * (be.x[0][1] + be.x[1][1]) - cy) < 0) nx = -nx, ny = -ny;
            const double dn = problem->contactSign * (problem->contactComponent == 0 ? nx : ny);
            if (dn < -1e-3 * std::hypot(nx, ny)) overlapLocal |= 4, intoBodyLocal |= be.segments;  // into the body here
            if (dn > 1e-3 * std::hypot(nx, ny)) overlapLocal |= 8;   // out of it: the obstacle is inside
          }
        }
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_BOR, overlapLocal, Teuchos::outArg(overlapGlobal));
      if (problem->components() == 2 && !directionChecked)
        Teuchos::reduceAll(*comm, Teuchos::REDUCE_BOR, intoBodyLocal, Teuchos::outArg(intoBodyGlobal));
      if (overlapGlobal & 1)
        SIGNORINI_USER_ERROR("Problem: a boundary edge belongs to both a contact segment and a Dirichlet segment "
                             "that fixes the constrained component (Problem/Contact Segments against Dirichlet Segments"
                             << (problem->components() == 2 ? ", Dirichlet X Segments, Dirichlet Y Segments" : "") << ")");
      // Along an edge (d . n = 0) the constraint is a valid one; pointing out of the body on every
      // contact edge, or along them all, the obstacle could never be touched from outside. The
      // edges' directions do not change under refinement: checked on the deck's mesh.
      if (problem->components() == 2 && !directionChecked) {
        if (!(overlapGlobal & 4))
          SIGNORINI_USER_ERROR("Problem/Contact Direction: on no contact edge does it point into the body (d is "
                               "minus the outward normal, e.g. +y on a bottom edge; otherwise d . u >= g puts the "
                               "obstacle inside the body or along its boundary)");
        if ((overlapGlobal & 8) && comm->getRank() == 0)
          std::cerr << "signorini: warning: " << deckPath << ": Problem/Contact Direction points out of the body on "
                    << "some contact edges (d . u >= g puts the obstacle inside the body there)" << std::endl;
        // A named contact segment on none of whose edges d points into the body (it runs along them
        // all, e.g. +y on a left side): its constraint is no obstacle met from outside, most likely
        // a segment named by mistake (a user review found one acting as an invisible obstacle).
        for (int i = 0; i < segments->size() && comm->getRank() == 0; ++i)
          if ((problem->contactMask & (1u << i)) && !(intoBodyGlobal & (1u << i)))
            std::cerr << "signorini: warning: " << deckPath << ": Problem/Contact Segments: on no edge of '"
                      << segments->name(i) << "' does Problem/Contact Direction point into the body (it runs along "
                      << "or out of them), so d . u >= g there is no obstacle met from outside" << std::endl;
        directionChecked = true;
      }
      if (overlapGlobal & 2)
        SIGNORINI_USER_ERROR("Problem: a boundary edge belongs to both a contact segment and a Neumann segment "
                             "(Problem/Contact Segments against Neumann Segments; on Gamma_C the traction is the multiplier)");
      const auto size = deck.sublist("Contact").get<std::string>("Multiplier Segments") == "H = h"
                            ? fem::ContactCoupling::SegmentSize::OneEdge
                            : fem::ContactCoupling::SegmentSize::TwoEdges;
      fem::ContactUnknowns unknowns{d->assembler->ownedMap(), d->assembler->overlapMap(), problem->components(),
                                    problem->components() == 1 ? 0 : problem->contactComponent,
                                    problem->components() == 1 ? 1.0 : problem->contactSign};
      {  // B and the segments are assembled; the QP's set-up below is the Schur preconditioner's
        auto assembly = timers.scope("assembly");
        d->coupling = std::make_unique<fem::ContactCoupling>(*d->mesh, problem->contactMask, size,
                                                             d->assembler->dirichletFlags(), unknowns);
      }
      if (d->coupling->numSegments() == 0)
        SIGNORINI_USER_ERROR("Problem/Contact Segments: the named segments contain no boundary edge of the mesh");
      d->qp = std::make_unique<solvers::ContactQP>(deck.sublist("Contact"), coarse->diameter());
      const CoarseProblem* correction = d->qp->usesCoarseCorrection(d->courant) ? &coarseCorrection() : nullptr;
      if (step == 0) {  // the deck's mesh, before the coarse correction's m x m product (--check too)
        const double coarseUnknowns =
            correction ? static_cast<double>(correction->assembler->ownedMap()->getGlobalNumElements()) : 0.0;
        d->qp->checkMemory(*d->A, *d->coupling, d->courant,
                           1e9 * deck.sublist("Parallel").get<double>("Memory Per Rank"), coarseUnknowns);
      }
      std::vector<double> coarseQ;
      if (correction)
        coarseQ = correction->schur->schur(d->coupling->coarseLoads(*correction->assembler), d->coupling->numSegments());
      d->qp->setSystem(*d->A, *d->coupling, d->courant, coarseQ);
      if (newmark->stabilised) {
        d->projection = std::make_unique<solvers::ContactQP>(deck.sublist("Contact"), coarse->diameter());
        d->projection->setSystem(*d->M, *d->coupling, 0.0);
      }
    }
    return d;
  }

  /// Belos CG + Jacobi with the deck's tolerance on the mass matrix \p M.
  std::unique_ptr<solvers::LinearSolver> massSolverOn(RCP<const CrsMatrix> M) {
    auto scope = timers.scope("preconditioner");
    auto massParams = deck.sublist("Linear Solver");
    massParams.set("Preconditioner", "Jacobi");
    auto solver = std::make_unique<solvers::LinearSolver>(massParams);
    solver->setSystemName("the mass matrix M (initial data, contact stabilisation, the implicit contact force's "
                          "acceleration; always with Jacobi)");
    solver->setOperator(M, 0.0);
    return solver;
  }
  /// The mass solver of d, set up on first use: an adaptive step needs none (the transfer runs
  /// its own Jacobi CG) unless the contact stabilisation or the implicit contact force asks for it.
  solvers::LinearSolver& massSolver(Discretisation& d) {
    if (!d.massSolver) d.massSolver = massSolverOn(d.M);
    return *d.massSolver;
  }
  /// The consistent M_rho of the L2 projections (initial data, I_h between meshes): M itself unless
  /// Contact/Boundary Mass = lumped, whose M would miss fields that lie in both spaces; then
  /// assembled once per mesh.
  RCP<const CrsMatrix> projectionMass(Discretisation& d) {
    if (!d.lumpedMass) return d.M;
    if (!d.consistentM) {
      auto scope = timers.scope("assembly");
      d.consistentM = d.assembler->assembleSystem(1.0, 0.0, *problem);
    }
    return d.consistentM;
  }
  /// The solver on projectionMass(d): the mass solver unless the mass is lumped.
  solvers::LinearSolver& projectionSolver(Discretisation& d) {
    if (!d.lumpedMass) return massSolver(d);
    if (!d.projectionSolver) d.projectionSolver = massSolverOn(projectionMass(d));
    return *d.projectionSolver;
  }

  /// L2 projection of an expression at t = 0 (M_rho x = int rho f phi). A field of the space, e.g.
  /// a constant velocity, is its own projection: when its nodal interpolant satisfies the equations
  /// to the solver's tolerance it is taken as it is, to rounding (a solve from 0 erred by the
  /// tolerance, a deformation of a rigid motion that the estimator showed). Other fields are solved
  /// from 0, as always, so their projections keep their bits.
  void projectL2(Discretisation& d, const core::ExpressionList& f, Vector& out) {
    Vector b(d.assembler->ownedMap());
    d.assembler->assembleLoad(f, 0.0, problem->density, b);
    {
      auto x = out.getLocalViewHost(Tpetra::Access::OverwriteAll);
      const auto& owned = *d.assembler->ownedMap();
      const auto& overlap = *d.assembler->overlapMap();
      const auto& held = d.assembler->dirichletFlags();
      const auto& coords = d.mesh->nodeCoords();
      const int nc = problem->components();
      for (size_t i = 0; i < x.extent(0); ++i) {
        const LO o = overlap.getLocalElement(owned.getGlobalElement(static_cast<LO>(i)));
        const auto& at = coords[static_cast<size_t>(o / nc)];
        const double value = held[static_cast<size_t>(o)] ? 0.0 : f[o % nc](at[0], at[1], 0.0);
        x(i, 0) = std::isfinite(value) ? value : 0.0;
      }
    }
    auto& solver = projectionSolver(d);
    Vector r(d.assembler->ownedMap());
    core::apply(*projectionMass(d), out, r);
    r.update(1.0, b, -1.0);
    const double tolerance = solver.relativeTolerance();
    if (core::dot(r, r) <= tolerance * tolerance * core::dot(b, b)) return;
    out.putScalar(0.0);
    solver.solve(b, out);
  }

  /// out = scale (f(t), phi) + scale (Neumann data at t, phi): the loads on d [force, times scale].
  void assembleLoads(const Discretisation& d, double t, double scale, Vector& out) const {
    d.assembler->assembleLoad(problem->bodyForce, t, scale, out);
    d.assembler->addBoundaryLoad(problem->neumannData, t, problem->neumannMask, scale, out);
  }

  /// Initial state on d: u0, v0 projected, a0 from (rho a0, phi) + a(u0, phi) = (f(0), phi) + Neumann.
  void initialState(Discretisation& d, Vector& u, Vector& v, Vector& a) {
    projectL2(d, problem->initialDisplacement, u);
    projectL2(d, problem->initialVelocity, v);
    Vector rhs(d.assembler->ownedMap()), Ku(d.assembler->ownedMap());
    assembleLoads(d, 0.0, 1.0, rhs);
    core::apply(*d.K, u, Ku);
    rhs.update(-1.0, Ku, 1.0);
    a.putScalar(0.0);
    massSolver(d).solve(rhs, a);
  }

  /// Throws a user error if u penetrates the obstacle at t = 0; returns the largest mean gap (0
  /// without contact).
  double checkInitialGap(Discretisation& d, const Vector& u) {
    if (!d.coupling) return 0.0;
    auto gap = d.coupling->applyTranspose(u);
    const auto gbar = d.coupling->weightedObstacle(problem->obstacle, 0.0);
    const auto& len = d.coupling->segmentLength();
    double largest = 0;
    int worst = -1, penetrating = 0;  // the deepest penetration is named, so that lifting it is enough
    for (int j = 0; j < d.coupling->numSegments(); ++j) {
      const double mean = (gap[j] - gbar[j]) / len[j];
      if (mean < -d.qp->gapTolerance()) {
        ++penetrating;
        if (worst < 0 || mean < (gap[worst] - gbar[worst]) / len[worst]) worst = j;
      }
      largest = std::max(largest, mean);
    }
    if (worst >= 0) {
      const auto& mp = d.coupling->segmentMidpoint()[worst];
      SIGNORINI_USER_ERROR("Problem/Initial Displacement penetrates the obstacle at t = 0 on "
                           << penetrating << " of " << d.coupling->numSegments()
                           << " contact segments: the deepest, the mean gap on the segment at (" << mp[0] << ", "
                           << mp[1] << "), is " << (gap[worst] - gbar[worst]) / len[worst]
                           << "; the constraint holds in the means over the segments of the initial state on the mesh "
                              "(one that follows a concave obstacle exactly lies below it between the nodes): lift it "
                              "there by at least that much");
    }
    return largest;
  }

  /// Kinetic energy 1/2 v^T M v and strain energy 1/2 u^T K u.
  std::pair<double, double> energies(const Discretisation& d, const Vector& u, const Vector& v) const {
    Vector tmp(d.assembler->ownedMap());
    core::apply(*d.M, v, tmp);
    const double kin = 0.5 * core::dot(tmp, v);
    core::apply(*d.K, u, tmp);
    return {kin, 0.5 * core::dot(tmp, u)};
  }
  double energy(const Discretisation& d, const Vector& u, const Vector& v) const {
    const auto [kin, strain] = energies(d, u, v);
    return kin + strain;
  }
  /// The energy the Newmark scheme with alpha = 1/2 conserves without contact and loads:
  /// kinetic + strain (\p energy, from energy()) + (beta - 1/4) k^2 / 2 a^T M a.
  double newmarkEnergy(const Discretisation& d, double energy, const Vector& a) const {
    Vector tmp(d.assembler->ownedMap());
    core::apply(*d.M, a, tmp);
    const double k = newmark->timeStep;
    return energy + (newmark->beta - 0.25) * 0.5 * k * k * core::dot(tmp, a);
  }

  /// Moves \p fields (owned vectors on the old mesh; here the step's two Newmark predictors,
  /// which by linearity of I_h equal the predictors of I_h u, I_h v, I_h a) to the new
  /// discretisation: the L2 projection M x = int u_old phi, each field by Jacobi CG started
  /// from their interpolants, or the interpolants alone. The multipliers follow the segment
  /// midpoints (they only warm-start the next QP).
  /// \p carried (scalar fields on the old mesh's owned nodes) are interpolated along.
  /// With PassOptions::Transfer::ritzProjection, fields[0] is u, moved by the Ritz projection
  /// (K + mu M_rho) x = a(u_old, phi) + mu (rho u_old, phi), mu = 10^-3 (c / L)^2 (c the fastest
  /// wave speed, L the domain's diameter; the mass term makes it definite on a free body and weighs
  /// little against K on the mesh's scales), from its L2 projection; the other fields as above.
  void transfer(const Discretisation& from, Discretisation& to, PassOptions::Transfer method,
                std::vector<RCP<Vector>>& fields, std::vector<double>& lambda, std::vector<RCP<Vector>>& carried) {
    const bool interpolate = method == PassOptions::Transfer::interpolation;
    auto scope = timers.scope("transfer");
    const int nc = problem->components();
    const int nf = static_cast<int>(fields.size());
    // Vector fields move component by component (the transfer is the scalar one per component).
    std::vector<RCP<Vector>> parts;
    for (const auto& f : fields)
      for (int c = 0; c < nc; ++c) parts.push_back(nc == 1 ? f : component(*f, c, nc, from.mesh->ownedMap()));
    const int nParts = static_cast<int>(parts.size());
    for (const auto& c : carried) parts.push_back(c);
    std::vector<const Vector*> raw;
    for (const auto& p : parts) raw.push_back(p.get());
    fem::MeshTransfer t(*from.forest, *from.mesh, raw, *to.forest, *to.mesh);
    auto byField = [&](const std::vector<RCP<Vector>>& moved, int f) {
      return nc == 1 ? moved[f] : interleave({moved.begin() + nc * f, moved.begin() + nc * (f + 1)}, to.assembler->ownedMap());
    };
    const auto interpolants = t.interpolate();
    for (size_t c = 0; c < carried.size(); ++c) carried[c] = interpolants[nParts + c];
    std::vector<RCP<Vector>> loads;
    if (!interpolate) {
      const auto* scalar = dynamic_cast<const fem::Q1Assembler*>(to.assembler.get());
      std::unique_ptr<fem::Q1Assembler> nodal;  // vector problems: loads per component, no Dirichlet rows
      if (!scalar) {
        nodal = std::make_unique<fem::Q1Assembler>(*to.mesh, std::vector<char>(to.mesh->overlapMap()->getNodeNumElements(), 0));
        scalar = nodal.get();
      }
      loads = t.projectionLoads(*scalar, nParts);
    }
    std::vector<RCP<Vector>> rhs;
    for (int f = 0; f < nf; ++f) {
      fields[f] = byField(interpolants, f);
      to.assembler->zeroDirichlet(*fields[f]);
      if (!interpolate) {
        rhs.push_back(byField(loads, f));
        rhs.back()->scale(problem->density);
        to.assembler->zeroDirichlet(*rhs.back());
      }
    }
    if (!interpolate) {  // M_rho x = rho int u_old phi by Jacobi CG (M is well conditioned: no Belos set-up per
                         // call), the fields side by side
      const auto& solverParams = deck.sublist("Linear Solver");
      std::vector<const Vector*> b;
      std::vector<Vector*> x;
      for (int f = 0; f < nf; ++f) b.push_back(rhs[f].get()), x.push_back(fields[f].get());
      try {
        solvers::solveJacobiCG(*projectionMass(to), b, x, solverParams.get<double>("Relative Tolerance"),
                               solverParams.get<int>("Maximum Iterations"));
      } catch (core::SolverError& e) {
        throw core::SolverError(std::string("the L2 projection to the new mesh (Linear Solver/Relative Tolerance, "
                                            "Maximum Iterations): ") + e.what());
      }
    }
    if (method == PassOptions::Transfer::ritzProjection) {
      // The mass term only makes the operator definite (a free body's rigid motions): the strain
      // energy may rise by mu's share, mu (||u_old||_M^2 - ||R u_old||_M^2) / 2, so mu is 10^-3 of
      // the scale of the body's lowest modes (10^-6 left a free bracket's K + mu M too near singular
      // for MueLu with Chebyshev).
      const double mu = 1e-3 * std::pow(problem->waveSpeed() / coarse->diameter(), 2);
      const auto stiffness = [&](const double X[4][2], double Ke[8][8]) { to.assembler->elementStiffness(*problem, X, Ke); };
      const auto parts = t.stiffnessLoads(stiffness, 0, nc);
      auto b = nc == 1 ? parts[0] : interleave(parts, to.assembler->ownedMap());
      b->update(mu, *rhs[0], 1.0);  // rhs[0]: the L2 projection's rho int u_old phi
      to.assembler->zeroDirichlet(*b);
      // From the values of the new mesh's M and K (one graph); assembled where they share none (the
      // consistent mass of a lumped boundary mass).
      RCP<const CrsMatrix> ritz =
          fem::combineOnGraph(*projectionMass(to), mu, *to.K, 1.0, to.assembler->dirichletFlags());
      if (ritz.is_null()) ritz = to.assembler->assembleSystem(mu, 1.0, *problem);
      // CG from the L2 projection; "auto" takes MueLu (Jacobi in reproducible arithmetic): Jacobi took
      // a third to a fifth of MueLu's time on meshes of 500-3,000 unknowns (a bracket, the bar's
      // cycle 1) but twice as long on the bar's last cycle (20,000). MueLu with symmetric
      // Gauss-Seidel, not the deck's smoother: Chebyshev's estimate of the largest eigenvalue fell
      // short on a free body's K + mu M, and its keys are refused by the relaxation.
      auto params = deck.sublist("Linear Solver");
      params.set("MueLu", core::ParameterList());
      params.sublist("MueLu").set("smoother: type", "RELAXATION");
      params.sublist("MueLu").sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
      solvers::LinearSolver solver(params);
      solver.setSystemName("the Ritz projection's K + mu M on the new mesh (Adaptivity/Transfer)");
      if (auto* elasticity = dynamic_cast<const fem::ElasticityAssembler*>(to.assembler.get()))
        solver.setNearNullspace(elasticity->rigidBodyModes(), 2);
      solver.setOperator(ritz, core::kInf);  // "auto": MueLu (K dominates)
      try {
        solver.solve(*b, *fields[0]);  // from the L2 projection
      } catch (const core::SolverError& e) {
        throw core::SolverError(std::string(e.what()) + "; the Ritz projection's system does not depend on the "
                                "time step: Adaptivity/Transfer = L2 projection avoids it");
      }
    }
    if (from.coupling && to.coupling) {
      // The QP's warm start on the new segments: the multiplier of the nearest old segment. It is a
      // force per unit length (B's columns integrate over the segment), so a segment split in two
      // starts both halves from the old value, not from a share by length.
      const auto nearest = nearestPoints(from.coupling->segmentMidpoint(), to.coupling->segmentMidpoint());
      std::vector<double> next(to.coupling->numSegments(), 0.0);
      for (int j = 0; j < to.coupling->numSegments(); ++j)
        if (nearest[j] >= 0) next[j] = lambda[nearest[j]];
      lambda = next;
    } else {
      lambda.assign(to.coupling ? to.coupling->numSegments() : 0, 0.0);
    }
  }
};

namespace {
/// The most levels of refinement whose edge pieces, 2^level for each of \p localEdges edges summed
/// over the ranks, stay within 2^22 (the set-up checks below test them one by one). Collective.
int levelsWithinWork(const Comm& comm, long long localEdges) {
  long long edges = 0;
  MPI_Allreduce(&localEdges, &edges, 1, MPI_LONG_LONG, MPI_SUM, core::rawMpiComm(comm));
  int levels = 0;
  while (levels < 30 && (edges << (levels + 1)) <= (1LL << 22)) ++levels;
  return levels;
}
}  // namespace

void Simulation::checkInitialGapOnRefinements(int finerLevels, const std::string& cause) const {
  const auto& I = *impl_;
  const auto& d = *I.initialDiscretisation;
  if (!d.coupling || finerLevels <= 0) return;
  {
    long long contactEdges = 0;
    for (const auto& be : d.mesh->boundaryEdges()) contactEdges += (be.segments & I.problem->contactMask) != 0;
    finerLevels = std::min(finerLevels, levelsWithinWork(*I.comm, contactEdges));
    if (finerLevels <= 0) return;
  }
  // The finest segments are pairs of edges 2^-finerLevels of a deck edge (one such edge with H = h):
  // means over 2^(finerLevels - 1) (2^finerLevels) pieces of each deck edge, by the 3-point Gauss
  // rule on each finest edge, as the coupling integrates.
  const bool single = I.deck.sublist("Contact").get<std::string>("Multiplier Segments") == "H = h";
  const int pieces = 1 << (single ? finerLevels : finerLevels - 1), edgesPerPiece = single ? 1 : 2;
  const int nc = I.problem->components();
  const auto& u0 = I.problem->initialDisplacement[nc == 1 ? 0 : I.problem->contactComponent];
  const double sign = nc == 1 ? 1.0 : I.problem->contactSign;
  const auto& gauss = fem::kGauss3Point;
  const auto& weight = fem::kGauss3Weight;
  // The deepest penetration over all ranks is named, so that lifting the obstacle by it is enough.
  struct {
    double mean;
    int rank;
  } mine{core::kInf, I.comm->getRank()}, deepest{};
  std::array<double, 3> where{};  // the segment's midpoint and length
  for (const auto& be : d.mesh->boundaryEdges()) {
    if (!(be.segments & I.problem->contactMask)) continue;
    for (int p = 0; p < pieces; ++p) {
      double mean = 0;
      for (int e = 0; e < edgesPerPiece; ++e)
        for (int q = 0; q < 3; ++q) {
          const auto x = be.at((p * edgesPerPiece + e + gauss[q]) / (pieces * edgesPerPiece));
          mean += weight[q] / edgesPerPiece * (sign * u0(x[0], x[1], 0.0) - I.problem->obstacle(x[0], x[1], 0.0));
        }
      if (mean < mine.mean) {
        const auto mid = be.at((p + 0.5) / pieces);
        mine.mean = mean, where = {mid[0], mid[1], be.length() / (pieces * edgesPerPiece)};
      }
    }
  }
  MPI_Allreduce(&mine, &deepest, 1, MPI_DOUBLE_INT, MPI_MINLOC, core::rawMpiComm(*I.comm));
  std::ostringstream error;
  if (deepest.mean < -d.qp->gapTolerance() && deepest.rank == I.comm->getRank())
    error << std::setprecision(6) << "Problem/Initial Displacement penetrates the obstacle at t = 0 on the finer "
          << "meshes that " << cause << " can make: the mean gap on the deepest contact segment, of " << edgesPerPiece
          << " edge(s) of length " << where[2] << " at (" << where[0] << ", " << where[1] << "), would be "
          << deepest.mean << " (the deck's mesh averages it away, and that cycle would stop at its start)";
  core::throwFirstUserError(*I.comm, error.str());
}

void Simulation::checkSegmentsOnRefinements(int finerLevels, const std::string& cause) const {
  const auto& I = *impl_;
  const auto& p = *I.problem;
  const unsigned used = p.dirichletMask | p.contactMask | p.neumannMask | p.componentDirichletMask[0] |
                        p.componentDirichletMask[1];
  const auto& edges = I.initialDiscretisation->mesh->boundaryEdges();
  finerLevels = std::min(finerLevels, levelsWithinWork(*I.comm, static_cast<long long>(edges.size())));
  std::vector<unsigned> mine(static_cast<size_t>(finerLevels) + 1, 0u), all(mine.size());
  for (const auto& be : edges) {
    mine[0] |= be.segments;
    for (int level = 1; level <= finerLevels; ++level)
      for (int piece = 0; piece < (1 << level); ++piece) {
        const auto mid = be.at((piece + 0.5) / (1 << level));
        mine[static_cast<size_t>(level)] |= I.segments->match(*I.coarse, be.tree, be.face, mid[0], mid[1]);
      }
  }
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(mine.size()), MPI_UNSIGNED, MPI_BOR, core::rawMpiComm(*I.comm));
  for (int level = 1; level <= finerLevels; ++level) {
    const unsigned changed = (all[0] ^ all[static_cast<size_t>(level)]) & used;
    for (int s = 0; s < I.segments->size(); ++s)
      if (changed & (1u << s))
        SIGNORINI_USER_ERROR("Mesh/Boundary Segments/" << I.segments->name(s) << ": holds "
                             << ((all[0] & (1u << s)) ? "boundary edges on the deck's mesh but none"
                                                      : "no boundary edge on the deck's mesh but some")
                             << " on the meshes refined " << level << " level(s) further, which " << cause
                             << " can make (its coordinate conditions select less than an edge, tested at the "
                                "edges' midpoints): the later cycles would change the problem; widen the conditions");
  }
}

Simulation::Simulation(const core::ParameterList& deck, const std::string& deckPath, const std::string& outputDir,
                       RCP<const Comm> comm)
    : impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.comm = comm;
  I.deck = deck;
  I.deckPath = deckPath;
  auto meshParams = deck.sublist("Mesh");
  const std::string file = meshParams.get<std::string>("File");
  if (!file.empty() && file[0] != '/') {
    meshParams.set("File", directoryOf(deckPath) + "/" + file);
    // The deck recorded in the output files names the file wherever it is read again.
    I.deck.sublist("Mesh").set("File",
                               std::filesystem::absolute(meshParams.get<std::string>("File")).lexically_normal().string());
  }
  const int level = meshParams.get<int>("Refinement Level");
  I.components = deck.sublist("Problem").get<std::string>("Type") == "scalar wave" ? 1 : 2;
  const bool reproducible = deck.sublist("Parallel").get<bool>("Reproducible Arithmetic");
  if (reproducible && I.components != 1)
    SIGNORINI_USER_ERROR("Parallel/Reproducible Arithmetic: available for Problem/Type = \"scalar wave\" only "
                         "(the elasticity assembler and estimator do not order their sums yet)");
  const std::string solverWarning = solvers::LinearSolver::checkParameters(deck.sublist("Linear Solver"), reproducible);
  if (!solverWarning.empty() && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": " << solverWarning << std::endl;
  core::setReproducibleArithmetic(reproducible);
  if (file.empty())
    checkMeshFits(meshParams.get<int>("Cells X") * std::pow(4.0, level) * meshParams.get<int>("Cells Y"),
                  "Mesh/Cells X = " + std::to_string(meshParams.get<int>("Cells X")) + ", Cells Y = " +
                      std::to_string(meshParams.get<int>("Cells Y")) + ", Refinement Level = " + std::to_string(level));
  {  // every rank reads a mesh file itself: one rank's error (another node's file) is every rank's
    std::string error;
    try {
      I.coarse = mesh::CoarseMesh::create(meshParams);
    } catch (const core::UserError& e) {
      error = e.what();
    } catch (const std::exception& e) {  // a library's or the file system's failure, maybe on one node only
      error = "Mesh/File: cannot read the mesh: " + core::withoutSourceLocation(e.what());
    }
    core::throwFirstUserError(*comm, error);
  }
  if (!file.empty())
    checkMeshFits(I.coarse->numTrees() * std::pow(4.0, level + I.coarse->levelOffset()),
                  "Mesh/File with " + std::to_string(I.coarse->numTrees()) + " cells, Refinement Level = " +
                      std::to_string(level));
  // Reproducible arithmetic orders its sums by the nodes' coordinates (Q1Mesh::canonicalKey), which
  // do not tell apart the nodes on either side of a crack: the order, and so the bits, would be
  // left to the partition (and the contact strip asserted distinct keys).
  if (!I.coarse->crackNote().empty() && reproducible)
    SIGNORINI_USER_ERROR("Parallel/Reproducible Arithmetic = true orders every sum by the nodes' coordinates, which "
                         "cannot tell apart nodes at one point: "
                         << I.coarse->crackNote() << "; or set Parallel/Reproducible Arithmetic = false");
  if (!I.coarse->crackNote().empty() && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": " << I.coarse->crackNote() << std::endl;
  if (!I.coarse->interiorSidesNote().empty() && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": " << I.coarse->interiorSidesNote() << std::endl;
  I.segments = std::make_unique<mesh::BoundarySegments>(meshParams.sublist("Boundary Segments"), *I.coarse);
  I.problem = std::make_unique<fem::ProblemData>(deck.sublist("Problem"), *I.segments);
  if (const auto note = I.problem->nearIncompressibility(); !note.empty() && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": " << note << std::endl;
  if (!I.problem->hasObstacle && I.problem->contactMask != 0 && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": Problem/Contact Segments without Problem/Obstacle: no contact"
              << std::endl;
  if (const auto keys = core::keysSetOtherThanDefaults(deck.sublist("Contact"), solvers::ContactQP::getValidParameters(),
                                                       "Contact");
      !I.problem->hasObstacle && !keys.empty() && comm->getRank() == 0)
    std::cerr << "signorini: warning: " << deckPath << ": no Problem/Obstacle; without effect: " << keys << std::endl;
  if (I.problem->hasObstacle) {
    const std::string contactWarning = solvers::ContactQP::checkParameters(deck.sublist("Contact"));
    if (!contactWarning.empty() && comm->getRank() == 0)
      std::cerr << "signorini: warning: " << deckPath << ": " << contactWarning << std::endl;
  }
  I.newmark = std::make_unique<Newmark>(deck.sublist("Time Integration"));

  const auto& out = deck.sublist("Output");
  std::tie(I.probeFields, I.probeStress) = parseProbeFields(out.get<std::string>("Probe Fields"), I.problem->components() == 2);
  const size_t maxNameLength = maxProbeNameLength(I.probeFields, I.probeStress, I.problem->components());
  for (auto it = out.sublist("Probes").begin(); it != out.sublist("Probes").end(); ++it) {
    const std::string name = out.sublist("Probes").name(it);
    const std::string spec = Teuchos::any_cast<std::string>(out.sublist("Probes").entry(it).getAny());
    // The name becomes a CSV header field, which a comma, a quote or a line break would split, and
    // an Exodus global variable "probe:<name>[:x]" (netCDF names: at most 256 bytes).
    if (name.find_first_of(",\"\n\r") != std::string::npos || name.find_first_not_of(" \t") == std::string::npos)
      SIGNORINI_USER_ERROR("Output/Probes/" << name << ": a probe's name is a CSV column header; it must not be "
                                               "blank or hold a comma, a quote or a line break");
    if (name.size() > maxNameLength)
      SIGNORINI_USER_ERROR("Output/Probes/" << name.substr(0, 40) << "...: a probe's name has at most "
                                            << maxNameLength << " bytes (it has " << name.size()
                                            << "; the Exodus files name a variable after it)");
    const auto [x, y] = parsePoint(spec, "Output/Probes/" + name, "a probe's");
    I.probes.push_back({name, {x, y}});
  }
  I.momentPoint = parsePoint(out.get<std::string>("Moment Point"), "Output/Moment Point", "the moment point's");
  if (const std::string region = out.get<std::string>("Stress Region"); core::trim(region) != "1") {
    if (I.problem->components() == 1)
      SIGNORINI_USER_ERROR("Output/Stress Region: stresses are those of plane strain elasticity (Problem/Type); the "
                           "scalar wave equation has none");
    I.stressRegion = std::make_unique<core::Expression>(region, "Output/Stress Region", "x, y");
    if (!I.stressRegion->isTimeIndependent())
      SIGNORINI_USER_ERROR("Output/Stress Region: \"" << region << "\" depends on t; the region is one of the body (x, y)");
  }
  if (I.problem->components() == 1 && (I.momentPoint[0] != 0 || I.momentPoint[1] != 0))
    SIGNORINI_USER_ERROR("Output/Moment Point: moments are reported for plane strain elasticity (Problem/Type); the "
                         "scalar wave equation has none");
  {  // supports reported one by one: two or more Dirichlet segments
    const unsigned held = I.problem->dirichletMask | I.problem->componentDirichletMask[0] |
                          (I.problem->components() == 2 ? I.problem->componentDirichletMask[1] : 0u);
    for (int i = 0; i < I.segments->size(); ++i)
      if (held >> i & 1u) I.supports.emplace_back(i, I.segments->name(i));
    if (I.supports.size() < 2) I.supports.clear();
    for (const auto& [segment, name] : I.supports)  // a CSV header and an Exodus variable name
      if (name.find_first_of("\"\n\r") != std::string::npos || name.size() > 240)
        SIGNORINI_USER_ERROR("Mesh/Boundary Segments/" << name.substr(0, 40) << ": with several Dirichlet segments "
                             "each names the step table's columns reaction:<segment>; a name must not hold a quote "
                             "or a line break and has at most 240 bytes");
  }
  // Two probes must not name one column (a probe "p" with its velocity and a probe "p:v").
  std::map<std::string, std::string> probeOfColumn;
  for (const auto& [name, point] : I.probes) {
    std::vector<std::string> columns;
    for (const int field : I.probeFields)
      for (int c = 0; c < I.problem->components(); ++c)
        columns.push_back("probe:" + name + probeSuffix(field, c, I.problem->components()));
    if (I.probeStress)
      for (const char* suffix : kProbeStressSuffixes) columns.push_back("probe:" + name + suffix);
    for (const auto& column : columns) {
      const auto [it, added] = probeOfColumn.emplace(column, name);
      if (!added)
        SIGNORINI_USER_ERROR("Output/Probes/" << name << " and Output/Probes/" << it->second
                                              << " both give the column '" << column << "'; rename one of them");
      I.probeColumns.push_back(column);
    }
  }

  I.initialForest = std::make_shared<mesh::Forest>(I.coarse, core::rawMpiComm(*comm), meshParams.get<int>("Refinement Level"));
  // Set-up checks on the initial mesh, before any output exists.
  auto d = I.build(I.initialForest, 0);
  if (const auto* cells = I.stressCells(*d)) {  // a region that holds no cell centre of the deck's mesh
    int mine = std::count(cells->begin(), cells->end(), 1) > 0 ? 1 : 0, any = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(any));
    if (!any)
      SIGNORINI_USER_ERROR("Output/Stress Region: \"" << I.stressRegion->text()
                                                      << "\" is 0 at every cell centre of the deck's mesh: max_von_mises "
                                                         "would look nowhere");
  }
  for (const auto& [segment, name] : I.supports) {  // each support's centre: the mean of its edges' points
    double sums[3];
    const auto& edges = d->mesh->boundaryEdges();
    core::reproducibleSums(*comm, 3, edges.size(),
                           [&](std::size_t k, double* out) {
                             const auto& be = edges[k];
                             const bool on = be.segments >> segment & 1u;
                             const double length = on ? be.length() : 0.0;
                             const auto mid = be.at(0.5);
                             out[0] = length * mid[0], out[1] = length * mid[1], out[2] = length;
                           },
                           sums);
    I.supportCentres.push_back({sums[0] / sums[2], sums[1] / sums[2]});
  }
  for (auto& [name, p] : I.probes) {
    double s, r;
    const LO cell = d->mesh->locate(p[0], p[1], s, r);
    int found = cell >= 0 ? 1 : 0;
    int any = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, found, Teuchos::outArg(any));
    // A point outside every cell by more than rounding but within the locator's tolerance (1e-10 of
    // the cell) would be outside every cell of finer meshes: it moves onto the boundary of the first
    // rank's cell. Points inside a cell (to rounding), the same on any partition, stay.
    const double rounding = 1e-13;
    int inside = found && s >= -rounding && s <= 1 + rounding && r >= -rounding && r <= 1 + rounding, anyInside = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, inside, Teuchos::outArg(anyInside));
    double moved[3] = {0, p[0], p[1]};  // {moved?, x, y}
    if (found && !anyInside) {
      const double sc = std::clamp(s, 0.0, 1.0), rc = std::clamp(r, 0.0, 1.0);
      moved[0] = 1, moved[1] = moved[2] = 0;
      for (int c = 0; c < 4; ++c) {
        const double N = ((c & 1) ? sc : 1 - sc) * ((c & 2) ? rc : 1 - rc);
        moved[1] += N * d->mesh->cornerCoordsHost(cell, c, 0), moved[2] += N * d->mesh->cornerCoordsHost(cell, c, 1);
      }
    }
    int mover = found && moved[0] ? comm->getRank() : comm->getSize(), first = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, mover, Teuchos::outArg(first));
    if (first < comm->getSize()) {
      Teuchos::broadcast(*comm, first, 3, moved);
      p = {moved[1], moved[2]};
    }
    if (!any) {  // name the mesh's extent (its corners' bounding box; an Exodus mesh need not fill it)
      double x0 = core::kInf, x1 = -core::kInf, y0 = core::kInf, y1 = -core::kInf;
      for (int t = 0; t < I.coarse->numTrees(); ++t)
        for (int c = 0; c < 4; ++c) {
          const auto& x = I.coarse->treeCorner(t, c);
          x0 = std::min(x0, x[0]), x1 = std::max(x1, x[0]), y0 = std::min(y0, x[1]), y1 = std::max(y1, x[1]);
        }
      const bool inBox = p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1;
      SIGNORINI_USER_ERROR("Output/Probes/" << name << ": point (" << std::setprecision(15) << p[0] << ", " << p[1]
                                            << ") is outside the mesh, which lies in [" << x0 << ", " << x1 << "] x ["
                                            << y0 << ", " << y1 << "]"
                                            << (inBox ? " but does not fill it: the point is in no cell" : "")
                                            << " (probes are points of the undeformed body)");
    }
  }
  {
    Vector u(d->assembler->ownedMap()), v(d->assembler->ownedMap()), a(d->assembler->ownedMap());
    I.initialState(*d, u, v, a);
    // The exact solution where the errors are measured, at t = 0 (so that --check finds it too).
    if (I.problem->exactSolution) d->assembler->errorNorms(u, *I.problem->exactSolution, 0.0);
    // Initial data that is not 0 where the body is held (homogeneous Dirichlet conditions): the held
    // unknowns stay 0, and the L2 projection of the rest oscillates next to them.
    const auto& held = d->assembler->dirichletFlags();
    const auto& coords = d->mesh->nodeCoords();
    const int nc = I.problem->components();
    for (const auto& [key, field] : {std::pair<const char*, const core::ExpressionList*>{"Initial Displacement",
                                                                                         &I.problem->initialDisplacement},
                                     {"Initial Velocity", &I.problem->initialVelocity}}) {
      double local[2] = {0, 0}, global[2];  // largest |value| at held unknowns, anywhere
      for (size_t i = 0; i < held.size(); ++i) {
        const auto& x = coords[i / nc];
        const double value = std::abs((*field)[static_cast<int>(i % nc)](x[0], x[1], 0.0));
        local[1] = std::max(local[1], value);
        if (held[i]) local[0] = std::max(local[0], value);
      }
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 2, local, global);
      if (global[0] > 1e-12 * global[1] && global[0] > 0 && comm->getRank() == 0)
        std::cerr << std::setprecision(3) << "signorini: warning: " << deckPath << ": Problem/" << key
                  << " is not 0 on the Dirichlet segments (up to " << global[0]
                  << "): there the body is held at 0, and the projected initial state oscillates next to them"
                  << std::endl;
    }
    // The constraint holds in the means over the segments (checkInitialGap); an obstacle above the
    // initial displacement at points of the contact boundary is most likely a mistake in the deck.
    if (d->coupling) {
      double worst[3] = {0, 0, 0};  // the largest penetration g - d . u0 and its point
      const auto& u0 = I.problem->initialDisplacement[nc == 1 ? 0 : I.problem->contactComponent];
      const double sign = nc == 1 ? 1.0 : I.problem->contactSign;
      std::string bad;  // the obstacle at a node (the estimator's s1 and the Exodus gaps take it there)
      for (const auto& be : d->mesh->boundaryEdges())
        if (be.segments & I.problem->contactMask)
          for (double w : {0.0, 0.5, 1.0}) {
            const auto x = be.at(w);
            const double penetration = I.problem->obstacle.sample(x[0], x[1], 0.0, bad) - sign * u0(x[0], x[1], 0.0);
            if (penetration > worst[0]) worst[0] = penetration, worst[1] = x[0], worst[2] = x[1];
          }
      core::throwFirstUserError(*comm, bad.empty() ? bad : bad + " on the contact boundary");
      largestWithPoint(*comm, worst);
      if (worst[0] > d->qp->gapTolerance()) {
        if (comm->getRank() == 0)
          std::cerr << std::setprecision(3) << "signorini: warning: " << deckPath
                    << ": Problem/Obstacle lies above Problem/Initial Displacement at points of the contact boundary "
                    << "(by up to " << worst[0] << " at (" << worst[1] << ", " << worst[2]
                    << ")); the discrete constraint holds only in the means over the segments, so the run starts "
                       "there in penetration"
                    << std::endl;
      }
    }
    // A constant obstacle under an elastic body's contact boundary that is not straight across the
    // contact direction: d . u >= g holds point by point, so the obstacle takes the body's shape (a
    // user study's arched base rested on all of it). A flat obstacle is a function of the coordinate.
    if (d->coupling && nc == 2 && I.problem->obstacle.isConstant()) {
      const int c = I.problem->contactComponent;
      double range[2] = {core::kInf, core::kInf}, global[2];  // min of x_c and of -x_c
      for (const auto& be : d->mesh->boundaryEdges())
        if (be.segments & I.problem->contactMask)
          for (double w : {0.0, 1.0}) {
            const auto x = be.at(w);
            range[0] = std::min(range[0], x[c]), range[1] = std::min(range[1], -x[c]);
          }
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 2, range, global);
      const double low = global[0], high = -global[1];
      if (high - low > 1e-9 * I.coarse->diameter() && comm->getRank() == 0) {
        // The flat obstacle at the deck's gap from the boundary's extreme point: d . u >= g with g the
        // constant there is d (x + u) >= d y0, y0 = edge + d g.
        const char* coordinate = c == 0 ? "x" : "y";
        const double sign = I.problem->contactSign, edge = sign > 0 ? low : high;
        const double y0 = edge + sign * I.problem->obstacle(0.0, 0.0, 0.0);
        std::ostringstream flat;
        flat << std::setprecision(6);
        if (sign > 0) flat << y0 << " - " << coordinate;
        else flat << coordinate << " - " << y0;
        std::cerr << std::setprecision(6) << "signorini: warning: " << deckPath << ": Problem/Obstacle is the constant "
                  << I.problem->obstacle.text() << " while the contact boundary is not straight across the contact "
                  << "direction (" << coordinate << " from " << low << " to " << high << "): the constraint holds "
                  << "point by point, so the obstacle takes the body's shape; the flat obstacle at " << coordinate
                  << " = " << y0 << " (that gap from the boundary's " << (sign > 0 ? "lowest" : "highest")
                  << " point) is \"" << flat.str() << "\"" << std::endl;
      }
    }
    // d . u >= g constrains one component, and the contact force acts along d: where the obstacle's
    // surface slopes across d, the force is not normal to it (a user study's disc on a 10 degree
    // slope rebounded without the sideways push a frictionless slope gives, and spun). The surface
    // that the contact boundary meets is h = x_c + sign g at its points (g = y0 - y is the flat floor
    // y0 under any boundary shape); its slope across d between points 1/8 of an edge apart, where the
    // boundary runs within 45 degrees of the across direction.
    if (d->coupling && nc == 2 && !I.problem->obstacle.isConstant()) {
      const int c = I.problem->contactComponent, across = 1 - c;
      const double sign = I.problem->contactSign;
      constexpr int pieces = 8;
      double steepest[3] = {0, 0, 0};  // |dh / dx_across| and its point
      std::string bad;
      const auto surface = [&](const std::array<double, 2>& x) {
        return x[c] + sign * I.problem->obstacle.sample(x[0], x[1], 0.0, bad);
      };
      for (const auto& be : d->mesh->boundaryEdges())
        if (be.segments & I.problem->contactMask) {
          auto x0 = be.at(0.0);
          double h0 = surface(x0);
          for (int k = 1; k <= pieces; ++k) {
            const auto x1 = be.at(static_cast<double>(k) / pieces);
            const double h1 = surface(x1), run = std::abs(x1[across] - x0[across]);
            // Pieces steeper than 45 degrees to the obstacle (the body's sides) do not rest on it.
            if (run > std::sqrt(0.5) * be.length() / pieces) {
              const double slope = std::abs(h1 - h0) / run;
              if (std::isfinite(slope) && slope > steepest[0])
                steepest[0] = slope, steepest[1] = 0.5 * (x0[0] + x1[0]), steepest[2] = 0.5 * (x0[1] + x1[1]);
            }
            x0 = x1, h0 = h1;
          }
        }
      largestWithPoint(*comm, steepest);
      if (steepest[0] > std::tan(kObstacleSlopeWarningDegrees * M_PI / 180)) {
        const char* along = c == 0 ? "x" : "y";
        if (comm->getRank() == 0)
          std::cerr << std::setprecision(3) << "signorini: warning: " << deckPath << ": the obstacle's surface under "
                    << "the contact boundary (" << along << (sign > 0 ? " + " : " - ") << "Problem/Obstacle) slopes "
                    << "across Contact Direction by up to " << std::atan(steepest[0]) * 180 / M_PI << " degrees (slope "
                    << steepest[0] << " near (" << steepest[1] << ", " << steepest[2] << ") at t = 0): the constraint "
                    << "is on u_" << along << " and the contact force acts along Contact Direction, not normal to "
                       "the obstacle, so where the body touches it there it also acts like friction; for a "
                       "frictionless slope give the mesh in coordinates in which Contact Direction is the "
                       "obstacle's normal where the body touches it (README, Known behaviour)"
                    << std::endl;
      }
    }
    // Boundary segments that no Problem list names are free edges: most likely a list left out.
    {
      const unsigned used = I.problem->dirichletMask | I.problem->componentDirichletMask[0] |
                            I.problem->componentDirichletMask[1] | I.problem->neumannMask | I.problem->contactMask;
      std::string unused;
      for (int i = 0; i < I.segments->size(); ++i)
        if (!(used & (1u << i))) unused += (unused.empty() ? "'" : ", '") + I.segments->name(i) + "'";
      if (!unused.empty() && comm->getRank() == 0)
        std::cerr << "signorini: warning: " << deckPath << ": Mesh/Boundary Segments " << unused
                  << " named by no Problem/Dirichlet, Dirichlet X, Dirichlet Y, Neumann or Contact Segments: "
                     "free edges (no support, no load, no contact)"
                  << std::endl;
    }
    // A time step in which the fastest wave crosses the whole body resolves none of its dynamics
    // (e.g. a density in g/cm^3 with the rest in SI units): the run tends to the static solution.
    if (const double crossings = I.problem->waveSpeed() * I.newmark->timeStep / I.coarse->diameter();
        crossings > 1 && comm->getRank() == 0)
      std::cerr << std::setprecision(3) << "signorini: warning: " << deckPath << ": in one Time Step "
                << I.newmark->timeStep << " the fastest wave (speed " << I.problem->waveSpeed()
                << ") crosses the body (diameter " << I.coarse->diameter() << ") " << crossings
                << " times, so the steps resolve none of its waves and the run tends to the static solution (are "
                   "the units of Problem/Density and the moduli consistent?)"
                << std::endl;
    // Data that turn into NaN or inf later in the run stop it at set-up rather than in that step.
    I.problem->checkFiniteOverTime(*d->mesh, I.newmark->timeStep, I.newmark->numSteps());
    // The KKT tolerance is absolute (Contact/KKT Tolerance times the domain diameter): a warning when
    // even the largest initial gap is within 1000 tolerances, so that the contact would be resolved
    // to fewer than three digits (a problem whose motion is tiny against the domain). Not for gaps
    // that no tolerance could resolve (1000 times the smallest, 1e-14 of the diameter): the body
    // starts on the obstacle, to rounding.
    const double largest = I.checkInitialGap(*d, u);
    if (d->qp && largest >= 1e-11 * I.coarse->diameter() && largest < 1000 * d->qp->gapTolerance() && comm->getRank() == 0)
      std::cerr << std::setprecision(3) << "signorini: warning: " << deckPath << ": the largest initial gap, " << largest
                << ", is within 1000 times the contact tolerance " << d->qp->gapTolerance()
                << " (Contact/KKT Tolerance times the domain diameter): the contact is resolved to fewer than "
                   "three digits; lower Contact/KKT Tolerance"
                << std::endl;
  }
  I.initialDiscretisation = std::move(d);
  I.setupSeconds = I.timers.all();  // the deck's mesh, its matrices and solvers: run() reports them
  I.outDir = outputDir.empty() ? out.get<std::string>("Directory") : outputDir;
  I.outDirKey = outputDir.empty() ? "Output/Directory" : "--output-dir";
  if (I.outDir.empty()) SIGNORINI_USER_ERROR(I.outDirKey << ": empty (\".\" is the working directory)");
  refuseUnusablePathText(I.outDir, I.outDirKey, true);
  while (I.outDir.size() > 1 && I.outDir.back() == '/') I.outDir.pop_back();  // "out/" writes "out/x", not "out//x"
  const std::string& basename = out.get<std::string>("Basename");
  refuseUnusablePathText(basename, "Output/Basename", false);
  if (basename.find('/') != std::string::npos || basename == "." || basename == ".." ||
      (!basename.empty() && basename.find_first_not_of(" \t") == std::string::npos))
    SIGNORINI_USER_ERROR("Output/Basename '" << basename
                                             << "': must be a plain file name (no '/', not '.', '..' or blank); "
                                                "Output/Directory or --output-dir chooses the folder");
  I.basename = basename.empty() ? stemOf(deckPath) : basename;
  if (basename.empty() && (I.basename.empty() || I.basename[0] == '.'))
    SIGNORINI_USER_ERROR("the deck's file name '" << deckPath << "' gives the output basename '" << I.basename
                                                 << "' (hidden or empty files); set Output/Basename");
  if (basename.empty() && isFileDescriptorPath(deckPath))
    SIGNORINI_USER_ERROR("a deck read through a file descriptor (a pipe or a process substitution) gives no "
                         "name for the outputs; set Output/Basename");
  {  // "<name>.cycle<l>" is the pattern of an adaptive run's cycle files: a run under <name> would retire them
    const auto dot = I.basename.rfind(".cycle");
    const std::string tail = dot == std::string::npos ? "" : I.basename.substr(dot + 6);
    if (dot != std::string::npos && dot > 0 && !tail.empty() && tail.find_first_not_of("0123456789") == std::string::npos)
      SIGNORINI_USER_ERROR((basename.empty() ? "the deck's file name gives the output basename '"
                                             : "Output/Basename '")
                           << I.basename << "', which ends like the cycle files of a run under the basename '"
                           << I.basename.substr(0, dot) << "' (<basename>.cycle<l>.*): such a run would replace "
                                                          "its results; choose another basename");
  }
  I.outputBase = I.outDir + "/" + I.basename;
  ensureWritableDirectory(I.outDir, I.outDirKey, *comm, false);
}

std::unique_ptr<io::OutputLock> Simulation::createOutputDirectory() const {
  ensureWritableDirectory(impl_->outDir, impl_->outDirKey, *impl_->comm, true);
  // One run at a time per output base: a second one would retire this run's files in progress.
  std::unique_ptr<io::OutputLock> lock;
  core::onRootCollectively(*impl_->comm, [&] { lock = std::make_unique<io::OutputLock>(outputBase()); });
  return lock;
}

Simulation::~Simulation() = default;

std::shared_ptr<mesh::Forest> Simulation::initialForest() const { return impl_->initialForest; }
int Simulation::numSteps() const { return impl_->newmark->numSteps(); }
long long Simulation::initialUnknowns() const {
  if (impl_->initialDiscretisation)
    return static_cast<long long>(impl_->initialDiscretisation->assembler->ownedMap()->getGlobalNumElements());
  return 0;
}
int Simulation::unknownsPerNode() const { return impl_->problem->components(); }
const fem::ProblemData& Simulation::problem() const { return *impl_->problem; }
std::string Simulation::coarseCorrectionMesh() const {
  const auto& c = impl_->coarseProblem;
  if (!c) return "";
  const int cap = impl_->deck.sublist("Contact").get<int>("Coarse Correction Cells");
  return std::to_string(c->forest->numGlobalCells()) + " cells (Refinement Level " + std::to_string(c->level) + "), " +
         std::to_string(c->assembler->ownedMap()->getGlobalNumElements()) + " unknowns" +
         (c->forest->numGlobalCells() > cap ? ", the coarse mesh's trees: more than Contact/Coarse Correction Cells = " +
                                                  std::to_string(cap)
                                            : "");
}
std::string Simulation::linearSolverPlan(int finerLevels) const {
  const auto& d = impl_->initialDiscretisation;
  if (!d || !d->solver) return "";
  const auto& params = impl_->deck.sublist("Linear Solver");
  std::ostringstream os;
  os << std::setprecision(3) << "linear solver: " << params.get<std::string>("Method") << " + "
     << d->solver->preconditioner();
  if (params.get<std::string>("Preconditioner") == "auto" && !core::reproducibleArithmetic()) {
    const double threshold = params.get<double>("Auto MueLu Courant Number");
    const double finest = d->courant * std::ldexp(1.0, std::max(0, finerLevels));
    os << " on the initial mesh (Preconditioner = auto: c k / h_min = " << d->courant;
    if (finerLevels > 0) os << ", up to " << finest << " on meshes " << finerLevels << " levels finer";
    os << "; MueLu above " << threshold << (finest > threshold && d->courant <= threshold ? ", so on the finer meshes" : "")
       << ")";
  }
  return os.str();
}
int Simulation::currentStep() const { return impl_->currentStep; }
double Simulation::timeStep() const { return impl_->newmark->timeStep; }
RCP<const Comm> Simulation::comm() const { return impl_->comm; }
const std::string& Simulation::outputBase() const { return impl_->outputBase; }
const std::vector<std::pair<std::string, std::array<double, 2>>>& Simulation::probes() const { return impl_->probes; }
const std::array<double, 2>* Simulation::momentPoint() const {
  return impl_->problem->components() == 2 ? &impl_->momentPoint : nullptr;
}
std::vector<std::pair<std::string, std::array<double, 2>>> Simulation::supports() const {
  std::vector<std::pair<std::string, std::array<double, 2>>> out;
  for (size_t g = 0; g < impl_->supports.size(); ++g) out.emplace_back(impl_->supports[g].second, impl_->supportCentres[g]);
  return out;
}
const core::Expression* Simulation::stressRegion() const { return impl_->stressRegion.get(); }
const core::ParameterList& Simulation::deck() const { return impl_->deck; }

namespace {
/// core::memoryPerRank() of the rank that has the least (nodes may differ, or hold different
/// numbers of ranks), so that every rank decides alike. Collective.
double smallestMemoryPerRank(const Comm& comm) {
  const double mine = core::memoryPerRank(comm);
  double least = mine;
  MPI_Allreduce(&mine, &least, 1, MPI_DOUBLE, MPI_MIN, core::rawMpiComm(comm));
  return least;
}
}  // namespace

void Simulation::checkMeshFits(double globalCells, const std::string& cause, double storedCells) const {
  const double perRank = globalCells / impl_->comm->getSize();
  const int nc = impl_->components;
  const double need = perRank * 750.0 * nc * nc + storedCells / impl_->comm->getSize(),
               budget = impl_->deck.sublist("Parallel").get<double>("Memory Per Rank"),
               have = budget > 0 ? budget * 1e9 : smallestMemoryPerRank(*impl_->comm);
  const double indexLimit = std::numeric_limits<int>::max() / 9.0;  // 32-bit local indices, 9 entries per row
  std::ostringstream why;
  why << std::setprecision(3);
  if (perRank > indexLimit)
    why << perRank << " cells per rank, more than the " << indexLimit << " that 32-bit local indices allow";
  else if (need > have)
    why << "at least " << need / 1e9 << " GB per rank, more than " << (budget > 0 ? "Parallel/Memory Per Rank = " : "this machine's ")
        << have / 1e9 << " GB per rank";
  if (why.str().empty()) return;
  std::ostringstream remedy;
  if (perRank > indexLimit) {  // the ranks the indices need, and what each of them then needs
    const double ranks = std::ceil(globalCells / indexLimit);
    remedy << "at least " << std::setprecision(12) << ranks << " ranks (32-bit local indices), each with "
           << std::setprecision(3) << (globalCells * 750.0 * nc * nc + storedCells) / ranks / 1e9 << " GB";
  } else {
    remedy << "more memory (ranks on more machines, Parallel/Memory Per Rank)";
  }
  SIGNORINI_USER_ERROR(cause << ": a mesh of " << std::setprecision(4) << globalCells << " cells on "
                             << impl_->comm->getSize() << " rank(s): " << why.str() << "; choose a coarser mesh, or "
                             << remedy.str());
}

RunSummary Simulation::run() {
  // The run's files appear when it has succeeded and replace every file an earlier run left under
  // this base; a failed run leaves them as they were (io::OutputStaging).
  io::OutputStaging staging;
  const auto lock = createOutputDirectory();  // released before a failed run's folders are removed
  io::retireOnCommit(outputBase(), io::isRunOutputSuffix);
  std::vector<std::shared_ptr<mesh::Forest>> meshes(numSteps(), impl_->initialForest);
  auto summary = runPass(meshes, StepHook(), PassOptions());
  for (const auto& [phase, seconds] : impl_->setupSeconds) summary.phaseSeconds[phase] += seconds;
  core::throwIfInterrupted(*impl_->comm);  // a signal during the last step: the files go
  core::onRootCollectively(*impl_->comm, [&] { staging.commit(); });
  return summary;
}

std::vector<std::string> Simulation::stepColumns(const PassOptions& options) const {
  const auto& I = *impl_;
  std::vector<std::string> columns = {"step", "t", "dofs", "active", "qp_iterations", "cg_iterations",
                                      "linear_solves", "linear_iterations", "energy", "kinetic_energy", "newmark_energy",
                                      "contact_force", "max_lambda", "min_lambda", "min_gap", "max_complementarity",
                                      "time_assembly", "time_contact", "time_output", "time_unconstrained",
                                      "time_remesh", "time_estimate", "cells"};
  const int nc = I.problem->components();
  // After contact_force: the supports' force on the body (the rows that the Dirichlet elimination
  // drops) and the applied loads' resultant.
  // Elasticity: each with its moment about Output/Moment Point, the contact force's too.
  std::vector<std::string> forces;
  if (nc == 2 && I.problem->hasObstacle) forces.push_back("contact_moment");
  struct Resultant {
    std::string force, moment;
    bool reported;
  };
  for (const auto& [force, moment, reported] :
       {Resultant{"reaction_force", "reaction_moment", I.problem->hasDirichletConditions()},
        Resultant{"applied_load", "applied_moment", fem::appliesLoads(*I.problem)}})
    if (reported) {
      if (nc == 1) {
        forces.push_back(force);
      } else {
        for (const char* c : {"_x", "_y"}) forces.push_back(force + c);
        forces.push_back(moment);
      }
      if (force == "reaction_force")  // each support's share: reaction:<segment>[:x, :y, :moment]
        for (const auto& support : I.supports) {
          if (nc == 1)
            forces.push_back("reaction:" + support.second);
          else
            for (const char* c : {":x", ":y", ":moment"}) forces.push_back("reaction:" + support.second + c);
        }
    }
  // Elasticity: the largest von Mises stress at the cell centres and where it occurs.
  if (nc == 2)
    // (_at_: ParaView's IOSS reader takes globals x_x, x_y for a vector x, which the scalar would clash with)
    for (const char* c : {"max_von_mises", "max_von_mises_at_x", "max_von_mises_at_y"}) forces.push_back(c);
  columns.insert(std::find(columns.begin(), columns.end(), "contact_force") + 1, forces.begin(), forces.end());
  if (I.deck.sublist("Output").get<bool>("Measure Contact Overhead"))
    columns.push_back("unconstrained_iterations");  // the benchmark unit's iterations
  columns.insert(columns.end(), I.probeColumns.begin(), I.probeColumns.end());
  if (I.problem->exactSolution) {
    columns.push_back("error_l2");
    columns.push_back("error_h1");
  }
  if (options.reportWork)
    for (const char* c : {"external_work", "contact_work"}) columns.push_back(c);
  if (options.reportMomentum) {
    if (nc == 1)
      columns.push_back("momentum");
    else
      for (const char* c : {"momentum_x", "momentum_y", "angular_momentum"}) columns.push_back(c);
  }
  if (options.reportTransferEnergy)
    for (const char* c : {"energy_transferred", "kinetic_energy_transferred"}) columns.push_back(c);
  columns.insert(columns.end(), options.extraColumns.begin(), options.extraColumns.end());
  return columns;
}

RunSummary Simulation::runPass(const std::vector<std::shared_ptr<mesh::Forest>>& meshes, const StepHook& hook,
                               const PassOptions& options) {
  auto& I = *impl_;
  const int rank = I.comm->getRank();
  const auto& outParams = I.deck.sublist("Output");
  const std::string base = I.outDir + "/" + (options.basename.empty() ? I.basename : options.basename);
  const int nSteps = I.newmark->numSteps();
  SIGNORINI_ASSERT(static_cast<int>(meshes.size()) == nSteps, "one mesh per time step");
  I.currentStep = 0;
  const double k = I.newmark->timeStep, beta = I.newmark->beta;
  const int exodusInterval = outParams.get<int>("Exodus Interval");
  int progress = outParams.get<int>("Progress Interval");
  if (progress == 0) progress = std::max(1, nSteps / 20);
  I.timers.clear();

  const std::vector<std::string> columns = stepColumns(options);
  const int nc = I.problem->components();
  const bool reportReaction = I.problem->hasDirichletConditions(), reportLoad = fem::appliesLoads(*I.problem);
  const size_t forceColumn = std::find(columns.begin(), columns.end(), "contact_force") - columns.begin() + 1;
  const bool measureOverhead = outParams.get<bool>("Measure Contact Overhead");
  const size_t timeOutputColumn = std::find(columns.begin(), columns.end(), "time_output") - columns.begin();
  std::unique_ptr<io::CsvWriter> csv;
  if (options.writeCsv)
    core::onRootCollectively(*I.comm, [&] { csv = std::make_unique<io::CsvWriter>(base + ".steps.csv", columns); });
  std::unique_ptr<ResultWriter> exodus;
  std::vector<std::string> cellNames = {"level"};
  if (!options.cellFieldName.empty()) cellNames.push_back(options.cellFieldName);
  // Elasticity: the stress and the strain at the cell centres (ElasticityAssembler::cellCentreStresses, cellCentreStrains).
  if (nc == 2)
    for (const char* name : {"sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz", "von_mises", "eps_xx", "eps_yy", "eps_xy"})
      cellNames.push_back(name);
  // The step table's columns but the step, the time and the timings are the Exodus files' global variables.
  std::vector<size_t> globalColumns;
  for (size_t c = 0; c < columns.size(); ++c)
    if (columns[c] != "step" && columns[c] != "t" && columns[c].rfind("time_", 0) != 0) globalColumns.push_back(c);
  if (outParams.get<bool>("Write Exodus") && options.writeExodus) {
    io::ExodusDescription description;
    description.title = "signorini: " + I.basename;  // also for a cycle's files that become the run's
    for (const size_t c : globalColumns) description.globalNames.push_back(columns[c]);
    description.info = {"deck: " + I.deckPath, "ranks: " + std::to_string(I.comm->getSize()),
                        "the deck as run (defaults and command-line overrides included):"};
    std::istringstream lines(core::deckAsXml(I.deck));
    for (std::string line; std::getline(lines, line);) description.info.push_back(line);
    // Each boundary segment of the deck is a side set named after it (ParaView shows supports and
    // loads), in every file of the series, also where a mesh gives it no edge.
    std::vector<std::string> segmentNames;
    for (int i = 0; i < I.segments->size(); ++i) segmentNames.push_back(I.segments->name(i));
    auto segmentSets = segmentSideSetNames(segmentNames, I.problem->contactMask);
    exodus = std::make_unique<ResultWriter>(base, nc == 1 ? std::vector<std::string>{"u", "v", "a"}
                                                          : std::vector<std::string>{"u_x", "u_y", "v_x", "v_y", "a_x", "a_y"},
                                            cellNames, std::vector<std::string>{"lambda", "gap"}, std::move(description),
                                            I.comm, std::move(segmentSets));
  }

  RunSummary summary;
  const auto start = std::chrono::steady_clock::now();
  // The QP multiplier is beta k^2 times the step equation's (toPhysical); the physical one (kappa du/dn =
  // -lambda on Gamma_C) is that, or alpha times that when only the new contact force acts in a step
  // (Newmark::implicitContact: v gains alpha k of its acceleration).
  const double toPhysical = 1.0 / (beta * k * k);
  const bool implicitContact = I.newmark->implicitContact;
  const double lambdaToPhysical = (implicitContact ? I.newmark->alpha : 1.0) * toPhysical;

  std::unique_ptr<Discretisation> d;
  if (I.initialDiscretisation && meshes[0] == I.initialDiscretisation->forest) {
    d = std::move(I.initialDiscretisation);  // built by the constructor: nothing to rebuild
    d->builtAtStep = 1;
  } else {
    meshes[0]->expand();
    d = I.build(meshes[0], 1);
  }
  RCP<Vector> u = Teuchos::rcp(new Vector(d->assembler->ownedMap())),
              v = Teuchos::rcp(new Vector(d->assembler->ownedMap())),
              a = Teuchos::rcp(new Vector(d->assembler->ownedMap()));
  I.initialState(*d, *u, *v, *a);
  RCP<Vector> aCarried = a;  // the acceleration the next step's predictors take (Newmark::implicitContact)
  I.checkInitialGap(*d, *u);
  std::vector<double> lambda(d->coupling ? d->coupling->numSegments() : 0, 0.0), gap;
  if (d->coupling) {
    gap = d->coupling->applyTranspose(*u);
    const auto gbar = d->coupling->weightedObstacle(I.problem->obstacle, 0.0);
    for (size_t j = 0; j < gap.size(); ++j) gap[j] -= gbar[j];
  }

  // The work done on the body since t = 0 (PassOptions::reportWork): u^{n-1}, the loads f(t_{n-1}) [force],
  // B^T u^{n-1} and the QP multiplier of step n-1 (contact force -B lambda / (beta k^2); 0 at t = 0, where
  // the initial acceleration has no contact force).
  double workExternal = 0, workContact = 0, largestEnergy = 0, initialEnergy = 0;
  std::unique_ptr<Vector> uPrevious, loadPrevious;
  std::vector<double> contactPrevious, lambdaPrevious;
  // The momentum sum_j m_j v_j of each component, m_j = int rho phi_j, and elasticity's angular
  // momentum (PassOptions::reportMomentum), with weights of the current mesh.
  std::vector<std::unique_ptr<Vector>> momentumWeights;
  const auto buildMomentumWeights = [&] {
    momentumWeights.clear();
    if (!options.reportMomentum) return;
    for (int c = 0; c < nc; ++c) {
      std::ostringstream density;
      density << std::setprecision(17);
      for (int i = 0; i < nc; ++i) density << (i ? ", " : "") << (i == c ? I.problem->density : 0.0);
      momentumWeights.push_back(std::make_unique<Vector>(d->assembler->ownedMap()));
      d->assembler->assembleLoad(core::ExpressionList(density.str(), "Problem/Density", nc), 0.0, 1.0,
                                 *momentumWeights.back());
    }
    if (nc == 2) {  // the angular momentum about Output/Moment Point: (M r) . v, r the rigid rotation about it
      Vector rotation(d->assembler->overlapMap());
      {
        auto h = rotation.getLocalViewHost(Tpetra::Access::OverwriteAll);
        const auto& X = d->mesh->nodeCoords();
        for (size_t n = 0; n < X.size(); ++n)
          for (int c = 0; c < 2; ++c)
            h(2 * n + c, 0) = c == 0 ? -(X[n][1] - I.momentPoint[1]) : X[n][0] - I.momentPoint[0];
      }
      momentumWeights.push_back(std::make_unique<Vector>(d->assembler->ownedMap()));
      d->assembler->massBeforeElimination(rotation, *I.problem, d->lumpAt, *momentumWeights.back());
    }
  };
  buildMomentumWeights();
  if (options.reportWork) {
    for (const auto& m : meshes)
      SIGNORINI_ASSERT(m == meshes[0], "PassOptions::reportWork needs one mesh for every step");
    uPrevious = std::make_unique<Vector>(d->assembler->ownedMap());
    loadPrevious = std::make_unique<Vector>(d->assembler->ownedMap());
    I.assembleLoads(*d, 0.0, 1.0, *loadPrevious);
    if (d->coupling) contactPrevious = d->coupling->applyTranspose(*u);
  }

  double tRemesh = 0, tEstimate = 0;  // of the current step
  std::pair<double, double> written;      // (kinetic, strain) of the state last written
  std::pair<double, double> transferred;  // (kinetic, strain) of the previous step's state on the current mesh
  std::vector<RCP<Vector>> carried;   // StepExtras::carry of the previous step
  std::shared_ptr<mesh::Forest> writtenForest;  // the mesh of the Exodus file being written, and its id
  long writtenId = 0;
  auto writeOutputs = [&](int step, double t, const solvers::ContactQPResult& qr, double tAssembly, double tContact,
                          double tFree, int freeIterations, const StepExtras& extras) {
    auto scope = I.timers.scope("output");
    const auto t0 = std::chrono::steady_clock::now();
    const auto dofs = static_cast<double>(d->assembler->ownedMap()->getGlobalNumElements());
    double force = 0;
    if (d->coupling)
      for (int j = 0; j < d->coupling->numSegments(); ++j) force -= lambdaToPhysical * lambda[j] * d->coupling->segmentLength()[j];
    Vector uOverlap(d->assembler->overlapMap());
    d->assembler->toOverlap(*u, uOverlap);
    const bool writeExodus = exodus && (step % exodusInterval == 0 || step == nSteps);
    std::unique_ptr<Vector> vOverlap, aOverlap;  // for the Exodus file and the probes of v and a
    if (writeExodus || (I.probeFields.size() > 1 && !I.probes.empty()) || reportReaction) {
      vOverlap = std::make_unique<Vector>(d->assembler->overlapMap());
      aOverlap = std::make_unique<Vector>(d->assembler->overlapMap());
      d->assembler->toOverlap(*v, *vOverlap);
      if (implicitContact) {  // the physical acceleration: the contact force alpha times the equation's
        const double alpha = I.newmark->alpha;
        Vector physical(a->getMap());
        physical.update(alpha, *a, 1 - alpha, *aCarried, 0.0);
        d->assembler->toOverlap(physical, *aOverlap);
      } else {
        d->assembler->toOverlap(*a, *aOverlap);
      }
    }
    written = I.energies(*d, *u, *v);
    if (step == 0) transferred = written;  // the initial state: nothing moved
    const auto [kinetic, strain] = written;
    summary.largestEnergy = std::max(summary.largestEnergy, kinetic + strain);
    const double energy = kinetic + strain, newmarkEnergy = I.newmarkEnergy(*d, energy, *a);
    if (step == 0) summary.initialNewmarkEnergy = newmarkEnergy;
    if (step == 0 || newmarkEnergy > summary.largestNewmarkEnergy) {
      summary.largestNewmarkEnergy = newmarkEnergy;
      summary.largestNewmarkEnergyStep = step;
    }
    summary.stepsInContact += qr.active > 0;
    std::vector<double> row = {double(step), t, dofs, double(qr.active), double(qr.activeSetIterations),
                               double(qr.cgIterations), double(qr.linearSolves), double(qr.linearIterations),
                               energy, kinetic, newmarkEnergy, force,
                               lambdaToPhysical * qr.maxLambda, lambdaToPhysical * qr.minLambda, qr.minGap,
                               lambdaToPhysical * qr.maxComplementarity, tAssembly,
                               tContact, 0.0, tFree, tRemesh, tEstimate, double(d->forest->numGlobalCells())};
    std::vector<double> forces;  // the columns after contact_force
    const std::array<double, 2>* momentPoint = nc == 2 ? &I.momentPoint : nullptr;  // elasticity's moments
    if (momentPoint && d->coupling)  // (+ 0.0: no -0 in the table)
      forces.push_back(-lambdaToPhysical * d->coupling->moment(lambda, *momentPoint) + 0.0);
    if (reportReaction) {  // sum_d (M a + K u - f + B lambda)_d over the Dirichlet rows, per component (and moment)
      auto reaction = d->assembler->dirichletRowSums(uOverlap, *aOverlap, *I.problem, t, d->lumpAt, momentPoint);
      if (d->coupling) {
        reaction[nc == 1 ? 0 : I.problem->contactComponent] += lambdaToPhysical * d->coupling->heldShare(lambda);
        if (momentPoint) reaction[2] += lambdaToPhysical * d->coupling->heldMoment(lambda, *momentPoint);
      }
      forces.insert(forces.end(), reaction.begin(), reaction.end());
      const auto& supportRows = I.supportRows(*d);
      for (size_t g = 0; g < supportRows.size(); ++g) {  // the same, support by support, each about its centre
        const auto& rows = supportRows[g];
        const std::array<double, 2>* centre = nc == 2 ? &I.supportCentres[g] : nullptr;
        auto share = d->assembler->dirichletRowSums(uOverlap, *aOverlap, *I.problem, t, d->lumpAt, centre, &rows);
        if (d->coupling) {
          share[nc == 1 ? 0 : I.problem->contactComponent] += lambdaToPhysical * d->coupling->heldShare(lambda, &rows);
          if (centre) share[2] += lambdaToPhysical * d->coupling->heldMoment(lambda, *centre, &rows);
        }
        forces.insert(forces.end(), share.begin(), share.end());
      }
    }
    if (reportLoad) {
      const auto load = fem::loadResultant(*d->mesh, nc, *I.problem, t, momentPoint);
      forces.insert(forces.end(), load.begin(), load.end());
    }
    std::array<std::vector<double>, 5> cellStresses;  // elasticity, in a step written to Exodus
    if (nc == 2) {
      const auto& elastic = dynamic_cast<const fem::ElasticityAssembler&>(*d->assembler);
      if (writeExodus) cellStresses = elastic.cellCentreStresses(uOverlap);
      const auto* region = I.stressCells(*d);
      const auto peak =
          writeExodus ? elastic.largestVonMises(cellStresses[4], region) : elastic.largestVonMises(uOverlap, region);
      forces.insert(forces.end(), peak.begin(), peak.end());
    }
    row.insert(row.begin() + static_cast<std::ptrdiff_t>(forceColumn), forces.begin(), forces.end());
    if (measureOverhead) row.push_back(freeIterations);
    const Vector* const fields[] = {&uOverlap, vOverlap.get(), aOverlap.get()};  // u, v, a (v, a may be null)
    for (const auto& p : I.probes) {
      for (const int field : I.probeFields)
        for (int c = 0; c < nc; ++c)
          row.push_back(d->assembler->evaluateComponent(*fields[field], p.second[0], p.second[1], c));
      if (I.probeStress)
        for (const double value : dynamic_cast<const fem::ElasticityAssembler&>(*d->assembler)
                                      .stressAtPoint(uOverlap, p.second[0], p.second[1]))
          row.push_back(value);
    }
    if (I.problem->exactSolution) {
      const auto [l2, h1] = d->assembler->errorNorms(*u, *I.problem->exactSolution, t);
      if (!std::isfinite(l2) || !std::isfinite(h1))  // the norms are sums over all ranks: every rank stops
        SIGNORINI_USER_ERROR("Problem/Exact Solution: the error norms of step " << step << " (t = " << t
                                                                              << ") are not finite numbers (l2 " << l2
                                                                              << ", h1 " << h1
                                                                              << "): is the exact solution within the range of doubles?");
      row.push_back(l2);
      row.push_back(h1);
    }
    if (options.reportWork) {
      largestEnergy = std::max(largestEnergy, newmarkEnergy);
      if (step == 0) initialEnergy = newmarkEnergy;
      row.push_back(workExternal);
      row.push_back(workContact);
    }
    for (const auto& m : momentumWeights) row.push_back(core::dot(*m, *v));
    if (options.reportTransferEnergy) {
      row.push_back(transferred.first + transferred.second);
      row.push_back(transferred.first);
    }
    for (size_t c = 0; c < options.extraColumns.size(); ++c)
      row.push_back(c < extras.columns.size() ? extras.columns[c] : 0.0);
    if (writeExodus) {
      std::vector<std::vector<double>> cell = {std::vector<double>(d->mesh->cellLevel().begin(), d->mesh->cellLevel().end())};
      if (!options.cellFieldName.empty())
        cell.push_back(extras.cellField.empty() ? std::vector<double>(d->mesh->numLocalCells(), 0.0) : extras.cellField);
      if (nc == 2) {
        const auto& elastic = dynamic_cast<const fem::ElasticityAssembler&>(*d->assembler);
        for (auto& quantity : cellStresses) cell.push_back(std::move(quantity));
        for (auto& quantity : elastic.cellCentreStrains(uOverlap)) cell.push_back(std::move(quantity));
      }
      std::vector<int> contactEdges;
      std::vector<std::vector<double>> contact(2);
      if (d->coupling)
        for (size_t i = 0; i < d->coupling->localEdgeSegment().size(); ++i) {
          const int j = d->coupling->localEdgeSegment()[i];
          if (j < 0) continue;
          contactEdges.push_back(static_cast<int>(i));
          contact[0].push_back(lambdaToPhysical * lambda[j]);
          contact[1].push_back(gap[j] / d->coupling->segmentLength()[j]);
        }
      std::vector<RCP<Vector>> parts;
      for (const Vector* f : fields)
        for (int c = 0; c < nc; ++c)
          parts.push_back(nc == 1 ? Teuchos::rcpFromRef(const_cast<Vector&>(*f)) : component(*f, c, nc, d->mesh->overlapMap()));
      std::vector<const Vector*> nodal;
      for (const auto& p : parts) nodal.push_back(p.get());
      std::vector<double> globals;
      for (const size_t c : globalColumns) globals.push_back(row[c]);
      // A mesh that changed and came back between two outputs stays in the current file.
      long meshId = d->builtAtStep;
      if (writtenForest && meshId != writtenId && (writtenForest == d->forest || writtenForest->sameCells(*d->forest)))
        meshId = writtenId;
      writtenForest = d->forest;
      writtenId = meshId;
      exodus->write(meshId, *d->mesh, t, nodal, cell, contactEdges, contact, globals);
    }
    row[timeOutputColumn] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (csv) csv->row(row);
  };

  try {
    solvers::ContactQPResult initial;  // no QP at t = 0; the initial state's gap
    if (d->coupling) {
      initial.minGap = gap.empty() ? 0.0 : 1e300;
      for (size_t j = 0; j < gap.size(); ++j) initial.minGap = std::min(initial.minGap, gap[j] / d->coupling->segmentLength()[j]);
    }
    writeOutputs(0, 0.0, initial, 0.0, 0.0, 0.0, 0, StepExtras());
    for (int n = 1; n <= nSteps; ++n) {
      core::throwIfInterrupted(*I.comm);
      I.currentStep = n;
      const double t = n * k;
      const auto tR0 = std::chrono::steady_clock::now();
      if (options.reportWork) {
        uPrevious->assign(*u);
        lambdaPrevious = lambda;
      }
      // The step's Newmark predictors, formed on the mesh of step n-1 and moved with it.
      std::vector<RCP<Vector>> predictors = {Teuchos::rcp(new Vector(u->getMap())), Teuchos::rcp(new Vector(u->getMap()))};
      I.newmark->predictor(*u, *v, *aCarried, *predictors[0]);
      I.newmark->velocityPredictor(*v, *aCarried, *predictors[1]);
      // The implicit contact force with the predictor projection (Deuflhard, Krause, Ertel's contact-
      // stabilised step) projects u + k v only and adds (1/2 - beta) k^2 a back after the projection:
      // projected, that term would be lost where the predictor meets the obstacle.
      RCP<Vector> accelerationTerm;
      if (implicitContact && I.newmark->stabilised) {
        accelerationTerm = Teuchos::rcp(new Vector(u->getMap()));
        accelerationTerm->update((0.5 - beta) * k * k, *aCarried, 0.0);
      }
      if (n > 1 && meshes[n - 1] != d->forest && !meshes[n - 1]->sameCells(*d->forest)) {
        meshes[n - 1]->expand();
        auto next = I.build(meshes[n - 1], n);
        const bool ritz = options.transfer == PassOptions::Transfer::ritzProjection;
        std::vector<RCP<Vector>> state;  // Ritz: u, v, a move (u by another projection than v and a)
        if (ritz) {
          for (const auto& f : {u, v, aCarried}) state.push_back(Teuchos::rcp(new Vector(*f, Teuchos::Copy)));
          I.transfer(*d, *next, options.transfer, state, lambda, carried);
          for (auto& p : predictors) p = Teuchos::rcp(new Vector(next->assembler->ownedMap()));
          I.newmark->predictor(*state[0], *state[1], *state[2], *predictors[0]);
          I.newmark->velocityPredictor(*state[1], *state[2], *predictors[1]);
          if (accelerationTerm) {
            accelerationTerm = Teuchos::rcp(new Vector(predictors[0]->getMap()));
            accelerationTerm->update((0.5 - beta) * k * k, *state[2], 0.0);
          }
        } else {
          if (options.reportTransferEnergy)  // only to recover I_h u and I_h v
            predictors.push_back(Teuchos::rcp(new Vector(I.newmark->recoveryField(*v, *aCarried), Teuchos::Copy)));
          if (accelerationTerm) predictors.push_back(accelerationTerm);  // moved along (I_h is linear), last
          I.transfer(*d, *next, options.transfer, predictors, lambda, carried);
          if (accelerationTerm) {
            accelerationTerm = predictors.back();
            predictors.pop_back();
          }
        }
        const auto previous = d->forest;
        d = std::move(next);
        if (options.compactMeshes && previous.use_count() > 1) previous->compact();  // still stored by the caller
        buildMomentumWeights();
        u = Teuchos::rcp(new Vector(d->assembler->ownedMap()));
        v = Teuchos::rcp(new Vector(d->assembler->ownedMap()));
        a = Teuchos::rcp(new Vector(d->assembler->ownedMap()));
        if (options.reportTransferEnergy && ritz) {
          transferred = I.energies(*d, *state[0], *state[1]);
        } else if (options.reportTransferEnergy) {
          Vector uMoved(d->assembler->ownedMap()), vMoved(d->assembler->ownedMap());
          I.newmark->stateFromPredictors(*predictors[0], *predictors[1], *predictors[2], uMoved, vMoved);
          transferred = I.energies(*d, uMoved, vMoved);
          predictors.resize(2);
        }
        if (options.reportTransferEnergy) {
          const double change = transferred.first + transferred.second - written.first - written.second;
          summary.transferEnergyChange += change;
          summary.transferEnergyRise += std::max(change, 0.0);
        }
        ++summary.meshChanges;
      } else {
        transferred = written;  // nothing moved
      }
      tRemesh = std::chrono::duration<double>(std::chrono::steady_clock::now() - tR0).count();
      const auto owned = d->assembler->ownedMap();
      summary.totalDofs += static_cast<long long>(owned->getGlobalNumElements());
      Vector& pred = *predictors[0];
      Vector F(owned), load(owned);
      double projectionSeconds = 0;  // contact work, booked as such
      if (accelerationTerm) pred.update(-1.0, *accelerationTerm, 1.0);
      if (d->projection) {  // the predictor projected onto the admissible set in the mass norm
        auto& massSolver = I.massSolver(*d);  // its set-up on a new mesh is the preconditioner's phase
        const auto tP0 = std::chrono::steady_clock::now();
        auto scope = I.timers.scope("contact");
        Vector Mpred(owned);
        core::apply(*d->M, pred, Mpred);
        d->assembler->zeroDirichlet(Mpred);
        std::vector<double> mu(d->coupling->numSegments(), 0.0), gapPred;
        d->projection->solve(massSolver, *d->coupling, Mpred, d->coupling->weightedObstacle(I.problem->obstacle, t),
                             mu, pred, gapPred);
        projectionSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tP0).count();
      }
      if (accelerationTerm) pred.update(1.0, *accelerationTerm, 1.0);
      const auto tA0 = std::chrono::steady_clock::now();
      {
        auto scope = I.timers.scope("assembly");
        // F^n = beta k^2 (f(t_n) + Neumann) + M (u + k v + (1/2 - beta) k^2 a)
        core::apply(*d->M, pred, F);
        I.assembleLoads(*d, t, beta * k * k, load);
        F.update(1.0, load, 1.0);
        d->assembler->zeroDirichlet(F);
      }
      const auto tA1 = std::chrono::steady_clock::now();
      solvers::ContactQPResult qr;
      try {
        auto scope = I.timers.scope("contact");
        u->assign(pred);
        d->assembler->zeroDirichlet(*u);
        if (d->coupling) {
          const auto gbar = d->coupling->weightedObstacle(I.problem->obstacle, t);
          qr = d->qp->solve(*d->solver, *d->coupling, F, gbar, lambda, *u, gap);
        } else {
          const long its0 = d->solver->totalIterations();
          d->solver->solve(F, *u);
          qr.linearSolves = 1;
          qr.linearIterations = static_cast<int>(d->solver->totalIterations() - its0);
        }
      } catch (const core::SolverError& e) {  // the step's system A: near incompressibility is a likely cause
        const std::string note = I.problem->nearIncompressibility();
        if (note.empty() || std::string(e.what()).rfind("linear solver ", 0) != 0) throw;
        throw core::SolverError(e.what() + ("; " + note));
      }
      const auto tA2 = std::chrono::steady_clock::now();
      double tFree = 0;
      int freeIterations = 0;
      if (measureOverhead) {  // the same solve without contact, for the ratio time_contact / time_unconstrained
        Vector x(owned);
        x.assign(pred);
        d->assembler->zeroDirichlet(x);
        const auto t0 = std::chrono::steady_clock::now();
        auto scope = I.timers.scope("unconstrained");  // the measurement's own time, in no other phase
        const long its0 = d->solver->totalIterations();
        d->solver->solve(F, x);
        tFree = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        freeIterations = static_cast<int>(d->solver->totalIterations() - its0);
      }
      StepExtras extras;
      const auto tE0 = std::chrono::steady_clock::now();
      if (hook) {
        auto scope = I.timers.scope("estimator");
        extras = hook(StepView{n, t, k, beta, *d->forest, *d->mesh, *d->assembler, d->coupling.get(), *I.problem, *u,
                               pred, lambda, d->id, carried,
                               d->lumpedMass ? Teuchos::null : RCP<const CrsMatrix>(d->M), d->K});
        carried = extras.carry;
      }
      tEstimate = std::chrono::duration<double>(std::chrono::steady_clock::now() - tE0).count();
      I.newmark->update(pred, *predictors[1], *u, *v, *a);
      double accelerationSeconds = 0;  // the implicit contact force's mass solve, booked as contact
      if (!implicitContact) {
        aCarried = a;
      } else {  // M^{-1} (f^n - K u^n) = a^n + M^{-1} B lambda / (beta k^2): without the step's contact force
        auto scope = I.timers.scope("contact");
        const auto tM0 = std::chrono::steady_clock::now();
        aCarried = Teuchos::rcp(new Vector(a->getMap()));
        aCarried->assign(*a);
        if (d->coupling && std::any_of(lambda.begin(), lambda.end(), [](double l) { return l != 0.0; })) {
          Vector contactForce(owned), x(owned);
          d->coupling->apply(lambda, contactForce, toPhysical);
          d->assembler->zeroDirichlet(contactForce);
          I.massSolver(*d).solve(contactForce, x);
          aCarried->update(1.0, x, 1.0);
        }
        accelerationSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tM0).count();
      }
      if (options.reportWork) {  // (u^n - u^{n-1}) . (f^{n-1} + f^n) / 2, f^n = load / (beta k^2)
        Vector du(owned), mean(owned);
        du.update(1.0, *u, -1.0, *uPrevious, 0.0);
        mean.update(0.5 * toPhysical, load, 0.5, *loadPrevious, 0.0);
        workExternal += core::dot(du, mean);
        loadPrevious->update(toPhysical, load, 0.0);
        if (d->coupling) {
          auto contact = d->coupling->applyTranspose(*u);
          double w = 0;
          // The contact force acting in the step: the mean of its two ends, or the new one alone.
          for (size_t j = 0; j < contact.size(); ++j)
            w += (contact[j] - contactPrevious[j]) * (implicitContact ? lambda[j] : 0.5 * (lambdaPrevious[j] + lambda[j]));
          workContact -= (implicitContact ? lambdaToPhysical : toPhysical) * w;
          contactPrevious = std::move(contact);
        }
      }
      writeOutputs(n, t, qr, std::chrono::duration<double>(tA1 - tA0).count(),
                   std::chrono::duration<double>(tA2 - tA1).count() + projectionSeconds + accelerationSeconds, tFree,
                   freeIterations, extras);
      if (n % progress == 0 || n == nSteps) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        core::rootOut(rank) << std::defaultfloat << std::setprecision(6) << "  step " << n << "/" << nSteps
                            << "  t = " << t << "  dofs = " << d->assembler->ownedMap()->getGlobalNumElements() << "  active = " << qr.active
                            << "  qp it = " << qr.activeSetIterations << "  lin it = " << qr.linearIterations
                            << std::fixed << std::setprecision(1) << "  elapsed " << elapsed << " s  remaining ~"
                            << elapsed / n * (nSteps - n) << " s" << std::endl;
      }
    }
    // The time-discrete contact gains energy where contact is released (README, Known behaviour); an
    // obstacle that moves does work of its own.
    const double supplied = initialEnergy + workExternal;  // by the initial state and the loads
    const bool fromSupplied = supplied > 0.1 * largestEnergy;
    const double scale = fromSupplied ? supplied : largestEnergy;
    if (options.reportWork && I.problem->obstacle.isTimeIndependent() && scale > 0 && workContact > 0.05 * scale &&
        rank == 0)
      std::cerr << "signorini: warning: " << I.deckPath << ": the contact did work " << workContact
                << " on the body by t = " << nSteps * k << ", " << std::fixed
                << std::setprecision(100 * workContact < 10 * scale ? 1 : 0) << 100 * workContact / scale
                << std::defaultfloat << std::setprecision(6) << "% of the " << (fromSupplied ? "energy supplied by the initial state and the loads, "
                                                                            : "largest newmark_energy, ")
                << scale
                << ": the time-discrete contact gains energy where contact is released; a smaller Time Step reduces "
                   "it (README, Known behaviour; the step table's contact_work)"
                << std::endl;
    // Inside the try: if either fails (on rank 0), every rank throws and neither output is left.
    core::onRootCollectively(*I.comm, [&] {
      if (csv) csv->commit();
    });
    if (exodus) summary.files = exodus->close();
    if (csv) summary.files.insert(summary.files.begin(), csv->path());
  } catch (...) {
    if (csv) csv->remove();
    if (exodus) exodus->abandon();
    throw;
  }
  summary.steps = nSteps;
  summary.dofsPerStep = static_cast<long long>(d->assembler->ownedMap()->getGlobalNumElements());
  summary.phaseSeconds = I.timers.all();
  summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace signorini::dynamics
