#pragma once
/// \file LoadResultant.hpp
/// The resultant of the applied loads (the step tables' applied_load columns).
#include <vector>

#include "signorini/fem/ProblemData.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

/// Whether \p problem applies loads: a body force or Neumann data (on Neumann segments) other than the constant 0.
bool appliesLoads(const ProblemData& problem);

/// The resultant of the applied loads at time \p t, one entry per component [force, per unit
/// thickness]: int_Omega f(., t) dx + int_{Gamma_N} q(., t) ds with the assembly's quadrature (2 x 2
/// Gauss points per cell, 2 per edge), so that it is the sum of all rows of the load vector before
/// the Dirichlet elimination, up to rounding. Collective over the mesh's ranks; the bits do not
/// depend on the partition.
std::vector<double> loadResultant(const mesh::Q1Mesh& mesh, int components, const ProblemData& problem, double t);

}  // namespace signorini::fem
