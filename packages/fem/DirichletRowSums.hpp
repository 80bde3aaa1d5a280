#pragma once
/// \file DirichletRowSums.hpp
/// The rows that eliminating the homogeneous Dirichlet unknowns drops, summed per component and
/// weighted by a rigid rotation, and the mass matrix before the elimination times a field
/// (internal to the fem package; Assembler::dirichletRowSums and Assembler::massBeforeElimination
/// give them to the time stepper).
#include <array>
#include <functional>
#include <vector>

#include "signorini/core/Expression.hpp"
#include "signorini/core/Types.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

/// The element matrices of the cell with corners \p X (z-order): the mass Me[a][b] (with rho; one
/// block, the same for every component) and the stiffness Ke[nc a + i][nc b + j] for nc components.
using ElementMatrices = std::function<void(const double X[4][2], double Me[4][4], double Ke[8][8])>;

/// What sumDirichletRows() reads: the discretisation (flags on the overlap unknowns, nc per node)
/// and the problem's loads.
struct DirichletRowsInput {
  const mesh::Q1Mesh* mesh = nullptr;
  int components = 1;                        ///< unknowns per node (unknown c of node n is nc n + c)
  const std::vector<char>* held = nullptr;   ///< the Dirichlet unknowns
  const std::vector<char>* lumped = nullptr; ///< the unknowns whose mass couplings sit on the diagonal (may be empty)
  ElementMatrices element;                   ///< the assembler's element matrices (the same values it assembles)
  const core::ExpressionList* bodyForce = nullptr;  ///< f [force / area], nc expressions
  const core::ExpressionList* neumann = nullptr;    ///< q [force / length] on the edges in neumannMask
  unsigned neumannMask = 0;
  /// With two components: also the moment of the rows about this point (null: none).
  const std::array<double, 2>* momentPoint = nullptr;
  /// Flags on the overlap unknowns: only these Dirichlet unknowns' rows are summed (null: all).
  const std::vector<char>* rows = nullptr;
};

/// For each component c, the sum over the Dirichlet unknowns d of component c of the rows of the
/// full system before elimination, sum_d (M a + K u - f(t) - q(t))_d [force]: with the same
/// element matrices and quadrature (2 x 2 Gauss in the cells, 2 Gauss points on the edges) as
/// the assembly, and a mass coupling to a lumped unknown moved to the diagonal as there.
/// \p uOverlap, \p aOverlap: u and a on the overlap unknowns (0 at the Dirichlet unknowns).
/// With in.momentPoint (two components), a third entry: the rows' moment about that point,
/// sum_d r_d (M a + K u - f(t) - q(t))_d with the rigid rotation r(x) = (-(y - p_y), x - p_x) at
/// the unknown's node [force length / length].
/// Collective; the bits do not depend on the partition (one term per cell or edge, summed by
/// core::reproducibleSums).
std::vector<double> sumDirichletRows(const DirichletRowsInput& in, const Vector& uOverlap, const Vector& aOverlap,
                                     double t);

/// \p outOverlap = the contributions of this rank's cells to M w, M the mass matrix of \p in before
/// the Dirichlet elimination (couplings of lumped unknowns on the diagonal, as assembled) and \p
/// fieldOverlap = w on all overlap unknowns, Dirichlet ones included; summing the ranks' overlap
/// vectors into the owners (Tpetra::ADD) gives M w on the owned unknowns.
void massTimesField(const DirichletRowsInput& in, const Vector& fieldOverlap, Vector& outOverlap);

}  // namespace signorini::fem
