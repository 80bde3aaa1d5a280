#include "ProblemData.hpp"

#include <cmath>
#include <sstream>

#include "Error.hpp"

namespace signorini::fem {

core::ParameterList ProblemData::getValidParameters() {
  core::ParameterList p("Problem");
  core::addChoice(p, "Type", "scalar wave", "Problem class (DESIGN 1.1): the scalar wave equation rho u_tt - div(kappa grad u) = f",
                  {"scalar wave"});
  core::addDouble(p, "Density", 1.0, "rho [mass/area]", 1e-300, core::kInf);
  core::addDouble(p, "Stiffness", 1.0, "kappa [force]; wave speed sqrt(kappa/rho)", 1e-300, core::kInf);
  core::addString(p, "Body Force", "0", "f(x,y,t) [force/area]");
  core::addString(p, "Initial Displacement", "0", "u0(x,y) [length] (t = 0)");
  core::addString(p, "Initial Velocity", "0", "v0(x,y) [length/time] (t = 0)");
  core::addString(p, "Obstacle", "", "g(x,y,t) [length]: the constraint u >= g on the contact segments; "
                                     "empty for no obstacle");
  core::addString(p, "Neumann Data", "0", "q(x,y,t) = kappa du/dn on the Neumann segments [force/length]");
  core::addString(p, "Exact Solution", "", "Optional exact u(x,y,t): per-step L2 and H1 errors are reported");
  core::addString(p, "Dirichlet Segments", "", "Comma-separated names of boundary segments with u = 0");
  core::addString(p, "Contact Segments", "", "Comma-separated names of boundary segments where u >= g (Gamma_C)");
  core::addString(p, "Neumann Segments", "", "Comma-separated names of segments with kappa du/dn = q; the rest "
                                             "of the boundary is homogeneous Neumann");
  return p;
}

namespace {
unsigned maskOf(const std::string& list, const mesh::BoundarySegments& segments, const std::string& key) {
  unsigned mask = 0;
  std::stringstream ss(list);
  for (std::string name; std::getline(ss, name, ',');) {
    const auto b = name.find_first_not_of(" \t"), e = name.find_last_not_of(" \t");
    if (b == std::string::npos) continue;
    mask |= 1u << segments.index(name.substr(b, e - b + 1), key);
  }
  return mask;
}
}  // namespace

ProblemData::ProblemData(const core::ParameterList& p, const mesh::BoundarySegments& segments)
    : density(p.get<double>("Density")),
      stiffness(p.get<double>("Stiffness")),
      bodyForce(p.get<std::string>("Body Force"), "Problem/Body Force"),
      initialDisplacement(p.get<std::string>("Initial Displacement"), "Problem/Initial Displacement"),
      initialVelocity(p.get<std::string>("Initial Velocity"), "Problem/Initial Velocity"),
      neumannData(p.get<std::string>("Neumann Data"), "Problem/Neumann Data"),
      obstacle(p.get<std::string>("Obstacle").empty() ? std::string("0") : p.get<std::string>("Obstacle"),
               "Problem/Obstacle") {
  hasObstacle = !p.get<std::string>("Obstacle").empty();
  if (!p.get<std::string>("Exact Solution").empty())
    exactSolution.emplace(p.get<std::string>("Exact Solution"), "Problem/Exact Solution");
  dirichletMask = maskOf(p.get<std::string>("Dirichlet Segments"), segments, "Problem/Dirichlet Segments");
  contactMask = maskOf(p.get<std::string>("Contact Segments"), segments, "Problem/Contact Segments");
  neumannMask = maskOf(p.get<std::string>("Neumann Segments"), segments, "Problem/Neumann Segments");
  if (hasObstacle && contactMask == 0)
    SIGNORINI_USER_ERROR("Problem/Obstacle is given but Problem/Contact Segments names no segment");
  if (dirichletMask & contactMask)
    SIGNORINI_USER_ERROR("Problem/Contact Segments and Problem/Dirichlet Segments name the same segment");
}

double ProblemData::waveSpeed() const { return std::sqrt(stiffness / density); }

}  // namespace signorini::fem
