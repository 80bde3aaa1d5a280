#include "signorini/fem/ProblemData.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/core/StringTools.hpp"

namespace signorini::fem {

core::ParameterList ProblemData::getValidParameters() {
  core::ParameterList p("Problem");
  core::addChoice(p, "Type", "scalar wave",
                  "Problem class (DESIGN 1.1): \"scalar wave\" rho u_tt - div(kappa grad u) = f (one unknown per "
                  "node), or \"plane strain elasticity\" rho u_tt - div sigma(u) = f (two per node)",
                  {"scalar wave", "plane strain elasticity"});
  // The solvers square norms of vectors that scale with these: outside 1e-100..1e100 the squares
  // leave the range of doubles (1e-160 lost the initial velocity altogether).
  core::addDouble(p, "Density", 1.0, "rho [mass/area] (scalar wave) or [mass/volume] (elasticity), in [1e-100, 1e100]",
                  1e-100, 1e100);
  core::addDouble(p, "Stiffness", 1.0, "Scalar wave: kappa [force/length] (a tension); wave speed sqrt(kappa/rho); in [1e-100, 1e100]",
                  1e-100, 1e100);
  core::addDouble(p, "Young's Modulus", 1.0, "Elasticity: E [force/area], in [1e-100, 1e100]", 1e-100, 1e100);
  // Measured on the bar (CG + MueLu, iterations per solve): 19 at nu = 0.33, 71 at 0.49, about 460 at
  // 0.4999, 1500 at 0.499999; beyond 2000 (the default Maximum Iterations) from 0.4999997 on.
  core::addDouble(p, "Poisson's Ratio", 0.3,
                  "Elasticity: nu (plane strain), in [0, 0.5); above about 0.495 (lambda / mu >= 100) a warning: "
                  "bilinear elements lock and the solves slow down",
                  0.0, 0.4999999);
  core::addString(p, "Body Force", "0",
                  "f(x,y,t) [force/area]; elasticity: \"fx, fy\" [force/volume] (\"0\": all components zero)");
  core::addString(p, "Initial Displacement", "0", "u0(x,y) [length] (t = 0); elasticity: \"u0x, u0y\"");
  core::addString(p, "Initial Velocity", "0", "v0(x,y) [length/time] (t = 0); elasticity: \"v0x, v0y\"");
  core::addString(p, "Obstacle", "", "g(x,y,t) [length]: the constraint u >= g (elasticity: d . u >= g with d the "
                                     "Contact Direction) on the contact segments; empty for no obstacle");
  core::addChoice(p, "Contact Direction", "+y",
                  "Elasticity: the displacement component the obstacle constrains, with its sign (\"+y\": u_y >= g, "
                  "an obstacle below the body; \"-x\": -u_x >= g, an obstacle to the right)",
                  {"+x", "-x", "+y", "-y"});
  core::addString(p, "Neumann Data", "0",
                  "q(x,y,t) = kappa du/dn [force/length]; elasticity: the traction \"qx, qy\" = sigma n "
                  "[force/area] on the Neumann segments");
  core::addString(p, "Exact Solution", "", "Optional exact u(x,y,t) (elasticity: \"ux, uy\"): per-step L2 and H1 "
                                           "errors are reported");
  core::addString(p, "Dirichlet Segments", "", "Comma-separated names of boundary segments with u = 0 (every component)");
  core::addString(p, "Dirichlet X Segments", "", "Elasticity: segments with u_x = 0 only (rollers)");
  core::addString(p, "Dirichlet Y Segments", "", "Elasticity: segments with u_y = 0 only (rollers)");
  core::addString(p, "Contact Segments", "", "Comma-separated names of boundary segments where u >= g (Gamma_C)");
  core::addString(p, "Neumann Segments", "", "Comma-separated names of segments with kappa du/dn = q (elasticity: "
                                             "sigma n = q); the rest of the boundary is homogeneous Neumann");
  return p;
}

namespace {
/// The segments the comma-separated \p list names, as a bit mask; a blank list names none. An
/// empty item ("a,,b", "a,") or a name given twice is a user error naming \p key.
unsigned maskOf(const std::string& list, const mesh::BoundarySegments& segments, const std::string& key) {
  if (core::trim(list).empty()) return 0;
  unsigned mask = 0;
  for (const auto& name : core::splitTrimmed(list, ',')) {
    if (name.empty())
      SIGNORINI_USER_ERROR(key << ": empty item in the list '" << list
                               << "' (a comma at the start or the end, or two commas in a row)");
    const unsigned bit = 1u << segments.index(name, key);
    if (mask & bit) SIGNORINI_USER_ERROR(key << ": the segment '" << name << "' is named twice in '" << list << "'");
    mask |= bit;
  }
  return mask;
}

/// The name of the first segment in \p mask.
std::string firstName(unsigned mask, const mesh::BoundarySegments& segments) {
  for (int i = 0; i < segments.size(); ++i)
    if (mask >> i & 1u) return segments.name(i);
  return "";
}
}  // namespace

namespace {
ProblemData::Model modelOf(const core::ParameterList& p) {
  return p.get<std::string>("Type") == "scalar wave" ? ProblemData::Model::ScalarWave
                                                      : ProblemData::Model::PlaneStrainElasticity;
}
int componentsOf(const core::ParameterList& p) { return modelOf(p) == ProblemData::Model::ScalarWave ? 1 : 2; }
}  // namespace

ProblemData::ProblemData(const core::ParameterList& p, const mesh::BoundarySegments& segments)
    : model(modelOf(p)),
      density(p.get<double>("Density")),
      stiffness(p.get<double>("Stiffness")),
      bodyForce(p.get<std::string>("Body Force"), "Problem/Body Force", componentsOf(p)),
      initialDisplacement(p.get<std::string>("Initial Displacement"), "Problem/Initial Displacement", componentsOf(p)),
      initialVelocity(p.get<std::string>("Initial Velocity"), "Problem/Initial Velocity", componentsOf(p)),
      neumannData(p.get<std::string>("Neumann Data"), "Problem/Neumann Data", componentsOf(p)),
      obstacle(p.get<std::string>("Obstacle").empty() ? std::string("0") : p.get<std::string>("Obstacle"),
               "Problem/Obstacle") {
  hasObstacle = !p.get<std::string>("Obstacle").empty();
  // One expression: "a, b" would evaluate to b (the comma operator), e.g. a vector given by mistake.
  if (hasObstacle) core::ExpressionList(p.get<std::string>("Obstacle"), "Problem/Obstacle", 1);
  if (!p.get<std::string>("Exact Solution").empty())
    exactSolution.emplace(p.get<std::string>("Exact Solution"), "Problem/Exact Solution", components());
  dirichletMask = maskOf(p.get<std::string>("Dirichlet Segments"), segments, "Problem/Dirichlet Segments");
  contactMask = maskOf(p.get<std::string>("Contact Segments"), segments, "Problem/Contact Segments");
  neumannMask = maskOf(p.get<std::string>("Neumann Segments"), segments, "Problem/Neumann Segments");
  componentDirichletMask[0] = maskOf(p.get<std::string>("Dirichlet X Segments"), segments, "Problem/Dirichlet X Segments");
  componentDirichletMask[1] = maskOf(p.get<std::string>("Dirichlet Y Segments"), segments, "Problem/Dirichlet Y Segments");
  const std::string direction = p.get<std::string>("Contact Direction");
  contactComponent = direction[1] == 'x' ? 0 : 1;
  contactSign = direction[0] == '+' ? 1.0 : -1.0;
  // The other model's material keys would be ignored: a wrong material without a word.
  const auto defaults = getValidParameters();
  const std::string otherModel = core::keysSetOtherThanDefaults(p, defaults, "Problem", [&](const std::string& k) {
    return model == Model::ScalarWave ? k == "Young's Modulus" || k == "Poisson's Ratio" : k == "Stiffness";
  });
  if (!otherModel.empty())
    SIGNORINI_USER_ERROR(otherModel << (model == Model::ScalarWave
                                            ? ": applies to Type = plane strain elasticity only (the scalar wave's "
                                              "material is Problem/Stiffness)"
                                            : ": applies to Type = scalar wave only (elasticity's material is "
                                              "Problem/Young's Modulus and Poisson's Ratio)"));
  if (model == Model::ScalarWave) {
    for (const char* key : {"Dirichlet X Segments", "Dirichlet Y Segments"})
      if (!p.get<std::string>(key).empty())
        SIGNORINI_USER_ERROR("Problem/" << key << " applies to Type = plane strain elasticity only");
    if (direction != "+y") SIGNORINI_USER_ERROR("Problem/Contact Direction applies to Type = plane strain elasticity only");
  } else {
    const double E = p.get<double>("Young's Modulus"), nu = p.get<double>("Poisson's Ratio");
    lameLambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    lameMu = E / (2 * (1 + nu));
  }
  if (hasObstacle && contactMask == 0)
    SIGNORINI_USER_ERROR("Problem/Obstacle is given but Problem/Contact Segments names no segment");
  if (dirichletMask & contactMask)
    SIGNORINI_USER_ERROR("Problem/Contact Segments and Problem/Dirichlet Segments name the same segment");
  if (neumannMask & contactMask)  // Gamma_N and Gamma_C are disjoint (DESIGN 1.1): q on Gamma_C is -lambda
    SIGNORINI_USER_ERROR("Problem/Contact Segments and Problem/Neumann Segments name the same segment");
  if (componentDirichletMask[contactComponent] & contactMask)
    SIGNORINI_USER_ERROR("Problem/Contact Segments and Problem/Dirichlet " << (contactComponent ? "Y" : "X")
                                                                          << " Segments name the same segment");
  // Gamma_D and Gamma_N are disjoint: the Dirichlet condition replaces the equations of the fixed
  // unknowns, so a load there would have no effect. A segment with every component fixed (also by
  // both Dirichlet X and Y Segments) is refused as a Neumann segment.
  const unsigned allFixed = dirichletMask | (componentDirichletMask[0] & componentDirichletMask[1]);
  if (const unsigned both = allFixed & neumannMask) {
    const std::string name = firstName(both, segments);
    if (dirichletMask & both)
      SIGNORINI_USER_ERROR("Problem/Neumann Segments and Problem/Dirichlet Segments name the same segment '"
                           << name << "': the Dirichlet condition fixes " << (model == Model::ScalarWave ? "u" : "every component of u")
                           << " there, so the load Problem/Neumann Data would have no effect on it");
    SIGNORINI_USER_ERROR("Problem/Neumann Segments names the segment '"
                         << name << "', which Problem/Dirichlet X Segments and Dirichlet Y Segments both name: every "
                                    "component of u is fixed there, so the load Problem/Neumann Data would have no effect on it");
  }
  // A roller under a traction: only where the fixed component's traction is not 0 does it lose
  // load, which depends on the edges (a warning of Simulation on the deck's mesh).
}

std::string ProblemData::checkParameters(const core::ParameterList& p) {
  if (!core::trim(p.get<std::string>("Neumann Segments")).empty()) return "";
  const std::string keys = core::keysSetOtherThanDefaults(p, getValidParameters(), "Problem",
                                                          [](const std::string& k) { return k == "Neumann Data"; });
  return keys.empty() ? "" : "no Problem/Neumann Segments; without effect: " + keys;
}

bool ProblemData::suppliesEnergy() const {
  const auto zero = [](const core::ExpressionList& f) {
    for (int c = 0; c < f.size(); ++c)
      if (!f[c].isConstant() || f[c](0, 0, 0) != 0) return false;
    return true;
  };
  return !zero(bodyForce) || (neumannMask != 0 && !zero(neumannData)) || (hasObstacle && !obstacle.isTimeIndependent());
}

double ProblemData::waveSpeed() const {
  return std::sqrt(waveModulus() / density);
}

void ProblemData::checkFiniteOverTime(const mesh::Q1Mesh& mesh, double timeStep, int steps) const {
  using Points = std::vector<std::array<double, 2>>;
  Points loadPoints, errorPoints, neumannPoints, contactPoints;
  struct Sampled {
    const core::Expression* f;
    Points* points;
    const char* where;  // appended to the message, as the step's sampler does
  };
  std::vector<Sampled> work;
  auto add = [&](const core::ExpressionList& list, Points& points, const char* where) {
    for (int c = 0; c < list.size(); ++c)
      if (!list[c].isTimeIndependent()) work.push_back({&list[c], &points, where});
  };
  add(bodyForce, loadPoints, "");
  if (exactSolution) add(*exactSolution, errorPoints, "");
  if (neumannMask) add(neumannData, neumannPoints, "");
  if (hasObstacle && contactMask && !obstacle.isTimeIndependent())
    work.push_back({&obstacle, &contactPoints, " on the contact boundary"});
  if (work.empty()) return;  // the expressions are the same on every rank
  auto needed = [&](const Points& points) {
    return std::any_of(work.begin(), work.end(), [&](const Sampled& w) { return w.points == &points; });
  };

  // The points of the step's samplers on this mesh: the loads at the cells' 2x2 Gauss points,
  // the error norms at their 3x3 ones with the central differences' neighbours
  // (Assembler::errorNorms), the boundary data at their edges' Gauss points.
  const auto& X = mesh.cornerCoordsHost;
  const auto& gauss3 = kGauss3Point;
  const double eps = 1e-6 * mesh.hMin();
  auto pointOf = [&](LO e, double s, double r) {
    double N[4], ds[4], dr[4];
    q1Shape(s, r, N, ds, dr);
    std::array<double, 2> x{0, 0};
    for (int c = 0; c < 4; ++c) x[0] += N[c] * X(e, c, 0), x[1] += N[c] * X(e, c, 1);
    return x;
  };
  for (LO e = 0; e < mesh.numLocalCells(); ++e) {
    if (needed(loadPoints))
      for (int q = 0; q < 4; ++q) loadPoints.push_back(pointOf(e, gauss2Point(q & 1), gauss2Point(q >> 1)));
    if (needed(errorPoints))
      for (double s : gauss3)
        for (double r : gauss3) {
          const auto x = pointOf(e, s, r);
          for (const auto& d : {std::array<double, 2>{0, 0}, {eps, 0}, {-eps, 0}, {0, eps}, {0, -eps}})
            errorPoints.push_back({x[0] + d[0], x[1] + d[1]});
        }
  }
  for (const auto& be : mesh.boundaryEdges()) {
    if ((be.segments & neumannMask) && needed(neumannPoints))
      for (int g = 0; g < 2; ++g) neumannPoints.push_back(be.at(gauss2Point(g)));
    if ((be.segments & contactMask) && needed(contactPoints))  // and the nodes, where the estimator's s1 takes g
      for (double w : {0.0, gauss3[0], gauss3[1], gauss3[2], 1.0}) contactPoints.push_back(be.at(w));
  }

  // The first sample at step n that is not a finite number, with its key and place ("" if none).
  auto firstBadAt = [&](int n) {
    std::string bad;
    for (const auto& w : work)
      for (const auto& x : *w.points) {
        w.f->sample(x[0], x[1], n * timeStep, bad);
        if (!bad.empty()) return bad + w.where;
      }
    return bad;
  };
  long long local = 0, largest = 0;  // samples per time on this rank, and on the busiest
  for (const auto& w : work) local += static_cast<long long>(w.points->size());
  Teuchos::reduceAll(*mesh.comm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(largest));
  // Every stride-th step (and the last); after a hit, the steps skipped before it, so that the
  // step named is this rank's earliest.
  const long long budget = 20000000;
  const int stride = static_cast<int>(std::min<long long>(steps, std::max(1LL, (steps * largest + budget - 1) / budget)));
  std::string bad;
  int firstBad = steps + 1;
  for (int n = 1, previous = 0; n <= steps && bad.empty(); previous = n, n = n < steps ? std::min(n + stride, steps) : n + 1)
    if (!(bad = firstBadAt(n)).empty()) {
      firstBad = n;
      for (int m = previous + 1; m < n; ++m)
        if (auto earlier = firstBadAt(m); !earlier.empty()) {
          bad = earlier, firstBad = m;
          break;
        }
    }
  int earliest = firstBad;
  Teuchos::reduceAll(*mesh.comm(), Teuchos::REDUCE_MIN, firstBad, Teuchos::outArg(earliest));
  if (earliest > steps) return;
  core::throwFirstUserError(*mesh.comm(),
                            firstBad == earliest ? bad + " (step " + std::to_string(earliest) + " of the run)" : "");
}

std::string ProblemData::nearIncompressibility() const {
  return model == Model::PlaneStrainElasticity ? nearIncompressibility(lameLambda, lameMu) : "";
}

std::string ProblemData::nearIncompressibility(double lameLambda, double lameMu) {
  if (lameLambda < 100 * lameMu) return "";
  const double nu = lameLambda / (2 * (lameLambda + lameMu));
  std::ostringstream os;
  os << std::setprecision(8) << "Problem/Poisson's Ratio = " << nu << " is close to 1/2 (lambda / mu = "
     << std::fixed << std::setprecision(0) << lameLambda / lameMu << std::defaultfloat
     << "): bilinear elements lock (the displacement comes out too small), and the condition number of the "
        "systems grows with lambda / mu, so that the linear solves need more iterations and may reach Linear "
        "Solver/Maximum Iterations";
  return os.str();
}

}  // namespace signorini::fem
