#pragma once
/// \file ElasticityAssembler.hpp
/// Kokkos assembly of plane strain linear elasticity with vector Q1 elements (two unknowns per
/// node, interleaved: unknown c of node i is 2 i + c) into Tpetra objects: the mass
/// M_(a i)(b j) = int rho phi_a phi_b delta_ij and the stiffness
/// K_(a i)(b j) = int lambda d_i phi_a d_j phi_b + mu (d_j phi_a d_i phi_b + delta_ij grad phi_a . grad phi_b),
/// i.e. a(u, v) = int sigma(u) : eps(v) with sigma = lambda tr(eps) I + 2 mu eps (paper Sec. 6.2);
/// body forces, surface tractions, error norms and point values. Hanging nodes are eliminated
/// through the mesh's corner constraints; Dirichlet unknowns (per component) get identity rows.
#include <array>
#include <memory>
#include <vector>

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>

#include "signorini/fem/Assembler.hpp"

namespace signorini::fem {

struct DirichletRowsInput;

class Q1Pattern;

/// Plane strain elasticity's operators, loads and point values on one Q1Mesh (two interleaved
/// unknowns per node). Keeps a reference to the mesh, which must outlive it.
class ElasticityAssembler : public Assembler {
 public:
  /// \param mesh       the Q1 numbering (kept by reference)
  /// \param dirichlet  flags on the overlap unknowns (2 per overlap node), e.g. from dirichletUnknowns().
  /// \param lambda     first Lame parameter [force / area]
  /// \param mu         shear modulus, the second Lame parameter [force / area]
  ElasticityAssembler(const mesh::Q1Mesh& mesh, std::vector<char> dirichlet, double lambda, double mu);
  ~ElasticityAssembler() override;

  /// The Dirichlet unknowns of a problem: every component on "Dirichlet Segments", component c on
  /// "Dirichlet X/Y Segments".
  static std::vector<char> dirichletUnknowns(const mesh::Q1Mesh& mesh, const ProblemData& problem);

  const mesh::Q1Mesh& mesh() const override { return mesh_; }
  int components() const override { return 2; }
  RCP<const Map> ownedMap() const override { return ownedMap_; }
  RCP<const Map> overlapMap() const override { return overlapMap_; }
  const std::vector<char>& dirichletFlags() const override { return dirichlet_; }

  /// massCoeff * M_rho + stiffCoeff * K with the constructor's Lame parameters.
  RCP<CrsMatrix> assembleOperator(double massCoeff, double stiffCoeff, double rho,
                                  const std::vector<char>& lumpAt = {}) const;
  RCP<CrsMatrix> assembleSystem(double massCoeff, double stiffCoeff, const ProblemData& problem,
                                const std::vector<char>& lumpAt = {}) const override {
    return assembleOperator(massCoeff, stiffCoeff, problem.density, lumpAt);
  }
  void assembleLoad(const core::ExpressionList& f, double t, double scale, Vector& out,
                    bool accumulate = false) const override;
  void addBoundaryLoad(const core::ExpressionList& q, double t, unsigned mask, double scale,
                       Vector& out) const override;
  void zeroDirichlet(Vector& v) const override;
  void toOverlap(const Vector& owned, Vector& overlap) const override;
  std::pair<double, double> errorNorms(const Vector& uOwned, const core::ExpressionList& exact,
                                       double t) const override;
  double evaluateComponent(const Vector& uOverlap, double x, double y, int c) const override;
  void elementStiffness(const ProblemData& problem, const double X[4][2], double Ke[8][8]) const override;
  std::vector<double> dirichletRowSums(const Vector& uOverlap, const Vector& aOverlap, const ProblemData& problem,
                                       double t, const std::vector<char>& lumpAt,
                                       const std::array<double, 2>* momentPoint = nullptr,
                                       const std::vector<char>* rows = nullptr) const override;
  void massBeforeElimination(const Vector& wOverlap, const ProblemData& problem, const std::vector<char>& lumpAt,
                             Vector& out) const override;

  /// The three rigid body modes (translations in x and y, rotation about the origin of the
  /// coordinates' centroid) as an owned multivector: MueLu's near-nullspace for elasticity.
  RCP<MultiVector> rigidBodyModes() const;
  /// Nodal stress sigma_xx, sigma_yy, sigma_xy at a point of a local cell (reference
  /// coordinates s, r) for overlap values \p uOverlap; for tests and output.
  std::array<double, 3> stressAt(const Vector& uOverlap, LO cell, double s, double r) const;
  /// The strain eps_xx, eps_yy, eps_xy (the tensor's components: eps_xy = (d_y u_x + d_x u_y) / 2,
  /// half the engineering shear strain) at a point of a local cell, as stressAt() [dimensionless].
  std::array<double, 3> strainAt(const Vector& uOverlap, LO cell, double s, double r) const;
  /// The strain at the centre of every local cell, one vector per component (eps_xx, eps_yy,
  /// eps_xy as strainAt()), for output.
  std::array<std::vector<double>, 3> cellCentreStrains(const Vector& uOverlap) const;
  /// The stress at the centre of every local cell, in the unit of the Lame parameters, one vector
  /// per quantity (for output): sigma_xx, sigma_yy, sigma_xy, sigma_zz = lambda (eps_xx + eps_yy) (plane
  /// strain: eps_zz = 0) and the von Mises stress
  /// sqrt(((sigma_xx - sigma_yy)^2 + (sigma_yy - sigma_zz)^2 + (sigma_zz - sigma_xx)^2) / 2 + 3 sigma_xy^2).
  std::array<std::vector<double>, 5> cellCentreStresses(const Vector& uOverlap) const;
  /// The stress at the point (x, y): sigma_xx, sigma_yy, sigma_xy, sigma_zz and von Mises as in
  /// cellCentreStresses(), of the mean of sigma_xx, sigma_yy, sigma_xy over the cells whose closure
  /// holds the point (one inside a cell; two, three or four on edges, hanging nodes and corners, where
  /// the stress of Q1 elements jumps), on all ranks; NaN outside the mesh. Collective; the bits do not
  /// depend on the partition.
  std::array<double, 5> stressAtPoint(const Vector& uOverlap, double x, double y) const;
  /// The largest von Mises stress at the cell centres of all ranks (cellCentreStresses()) and the
  /// centre where it occurs, {value, x, y}: of the cells within 1e-6 of the largest value, the centre
  /// with the smallest x, then y (so that rounding does not move it between mirror cells). Collective.
  /// With \p region (one flag per local cell), only the flagged cells count; NaN for all three
  /// where no cell of any rank is flagged.
  std::array<double, 3> largestVonMises(const Vector& uOverlap, const std::vector<char>* region = nullptr) const;
  /// The same from the cells' von Mises stresses \p vonMises (cellCentreStresses()[4]). Collective.
  std::array<double, 3> largestVonMises(const std::vector<double>& vonMises,
                                        const std::vector<char>* region = nullptr) const;

 private:
  /// What sumDirichletRows() and massTimesField() read of this discretisation and \p problem.
  DirichletRowsInput rowsInput(const ProblemData& problem, const std::vector<char>& lumpAt) const;
  /// {sigma_xx, sigma_yy, sigma_xy} completed by sigma_zz (plane strain) and the von Mises stress.
  std::array<double, 5> withOutOfPlaneAndVonMises(double sxx, double syy, double sxy) const;
  const mesh::Q1Mesh& mesh_;
  std::vector<char> dirichlet_;
  double lambda_, mu_;
  RCP<const Map> ownedMap_, overlapMap_;
  Kokkos::View<int*, DeviceType> dirichletView_;
  std::unique_ptr<Q1Pattern> pattern_;  ///< the matrix's sparsity; creates and finishes it
  RCP<const Tpetra::Export<LO, GO, Node>> exporter_;
  RCP<const Tpetra::Import<LO, GO, Node>> importer_;
};

}  // namespace signorini::fem
