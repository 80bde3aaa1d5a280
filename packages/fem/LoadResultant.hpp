#pragma once
/// \file LoadResultant.hpp
/// The resultant of the applied loads (the step tables' applied_load columns).
#include <array>
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
/// depend on the partition. With \p momentPoint (two components) a third entry: the loads' moment
/// about that point, int_Omega (x - p) x f dx + int_{Gamma_N} (x - p) x q ds (z components) [force
/// length / length], with the same quadrature, which makes it r^T(f + q) for the rigid rotation r
/// about p (r lies in the Q1 space).
std::vector<double> loadResultant(const mesh::Q1Mesh& mesh, int components, const ProblemData& problem, double t,
                                  const std::array<double, 2>* momentPoint = nullptr);

}  // namespace signorini::fem
