#pragma once
/// \file MeshTransfer.hpp
/// The transfer I_h of finite element fields between step meshes (MeshTransfer).
#include <functional>
#include <memory>
#include <vector>

#include "signorini/mesh/ForestOverlap.hpp"
#include "signorini/fem/Q1Assembler.hpp"

namespace signorini::fem {

/// Transfer I_h of finite element fields from the mesh of step n-1 to the mesh of step n (paper Sec. 3.2, DESIGN 1.2):
/// the L2 projection, exact on the common refinement of the two meshes (both refine one coarse mesh), or nodal
/// interpolation; across differently partitioned meshes (mesh::ForestOverlap). Keeps references to the new Q1Mesh and
/// the new forest's CoarseMesh, which must outlive it; the old forest, mesh and fields may go after the constructor.
class MeshTransfer {
 public:
  /// Prepares the transfer of \p fields (owned vectors on the old mesh): copies their values, cell by cell, to
  /// the ranks of the overlapping new cells. Both forests must be expanded. Collective.
  MeshTransfer(const mesh::Forest& oldForest, const mesh::Q1Mesh& oldMesh, const std::vector<const Vector*>& fields,
               const mesh::Forest& newForest, const mesh::Q1Mesh& newMesh);

  /// b_i = int u_old phi_i for each field (owned vectors on the new mesh, Dirichlet rows zeroed by
  /// \p newAssembler): the right-hand sides of the L2 projection M x = b. Exact for Q1 fields:
  /// element mass matrices on each cell of the common refinement in trees with a constant
  /// Jacobian (parallelograms, every rectangle), 3 x 3 Gauss points there in other trees.
  /// Only the first \p numFields fields (all: -1).
  std::vector<RCP<Vector>> projectionLoads(const Q1Assembler& newAssembler, int numFields = -1) const;
  /// The element stiffness matrix of the cell with physical corners X (z-order), unknowns
  /// interleaved: Ke[nc a + i][nc b + j] for corners a, b and components i, j (nc <= 2).
  using ElementStiffness = std::function<void(const double X[4][2], double Ke[8][8])>;
  /// b_(i,c) = a(u_old, phi_i e_c) for the field whose \p nc components are the fields
  /// [first, first + nc): the right-hand sides of its Ritz projection K x = b (one owned vector per
  /// component on the new mesh, Dirichlet rows not zeroed). On each cell R of the common refinement
  /// u_old and the new basis are bilinear, so b is R's element stiffness applied to u_old at R's
  /// corners, weighted by the new basis there: exact wherever \p stiffness is (parallelograms).
  std::vector<RCP<Vector>> stiffnessLoads(const ElementStiffness& stiffness, int first, int nc) const;
  /// Nodal interpolation of each field at the new mesh's nodes (owned vectors).
  std::vector<RCP<Vector>> interpolate() const;

 private:
  const mesh::Q1Mesh& newMesh_;
  const mesh::CoarseMesh& coarse_;
  int numFields_;
  std::unique_ptr<mesh::ForestOverlap> overlap_;
  double valueAt(const mesh::OverlapCell& q, int field, double s, double r) const;
  /// Sums the cell loads be[f][corner] of \p nf fields that \p cellLoads gives for each new cell
  /// into owned vectors (hanging corners by their weights; rows flagged in \p skip left 0).
  std::vector<RCP<Vector>> assembleLoads(int nf, const std::vector<char>* skip,
                                         const std::function<void(int e, double be[8][4])>& cellLoads) const;
};

}  // namespace signorini::fem
