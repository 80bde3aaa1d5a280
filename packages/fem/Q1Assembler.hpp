#pragma once
/// \file Q1Assembler.hpp
/// Kokkos assembly of the scalar wave's bilinear finite element matrices and vectors (Q1Assembler).
#include <memory>
#include <utility>
#include <vector>

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>

#include "signorini/fem/Assembler.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::fem {

struct DirichletRowsInput;

class Q1Pattern;
class EntrySums;
struct Contribution;

/// Kokkos assembly on one Q1Mesh into Tpetra objects, one unknown per node: c_M M + c_K K (mass and stiffness, paper
/// (3.7)), loads, Neumann loads, error norms and point evaluation (probes). Hanging nodes are eliminated through the
/// mesh's corner constraints; homogeneous Dirichlet nodes get identity rows and zero columns.
class Q1Assembler : public Assembler {
 public:
  /// Collective (builds the matrices' sparsity pattern).
  /// \param mesh       the mesh; the assembler keeps references to it and its transfers: it must outlive the assembler.
  /// \param dirichlet  flags on the mesh's overlap map (from Q1Mesh::nodesOnSegments); copied.
  Q1Assembler(const mesh::Q1Mesh& mesh, std::vector<char> dirichlet);
  ~Q1Assembler() override;

  const mesh::Q1Mesh& mesh() const override { return mesh_; }
  int components() const override { return 1; }
  RCP<const Map> ownedMap() const override { return mesh_.ownedMap(); }
  RCP<const Map> overlapMap() const override { return mesh_.overlapMap(); }
  /// massCoeff * M_rho + stiffCoeff * K_kappa with the problem's rho and kappa (the Assembler interface;
  /// assembleOperator()).
  RCP<CrsMatrix> assembleSystem(double massCoeff, double stiffCoeff, const ProblemData& problem,
                                const std::vector<char>& lumpAt = {}) const override {
    return assembleOperator(massCoeff, stiffCoeff, problem.density, problem.stiffness, lumpAt);
  }
  void assembleLoad(const core::ExpressionList& f, double t, double scale, Vector& out,
                    bool accumulate = false) const override {
    assembleLoad(f.scalar(), t, scale, out, accumulate);
  }
  void addBoundaryLoad(const core::ExpressionList& q, double t, unsigned mask, double scale,
                       Vector& out) const override {
    addBoundaryLoad(q.scalar(), t, mask, scale, out);
  }
  std::pair<double, double> errorNorms(const Vector& uOwned, const core::ExpressionList& exact,
                                       double t) const override {
    return errorNorms(uOwned, exact.scalar(), t);
  }
  double evaluateComponent(const Vector& uOverlap, double x, double y, int) const override {
    return evaluate(uOverlap, x, y);
  }
  void elementStiffness(const ProblemData& problem, const double X[4][2], double Ke[8][8]) const override;
  std::vector<double> dirichletRowSums(const Vector& uOverlap, const Vector& aOverlap, const ProblemData& problem,
                                       double t, const std::vector<char>& lumpAt,
                                       const std::array<double, 2>* momentPoint = nullptr,
                                       const std::vector<char>* rows = nullptr) const override;
  void massBeforeElimination(const Vector& wOverlap, const ProblemData& problem, const std::vector<char>& lumpAt,
                             Vector& out) const override;
  /// massCoeff * M_rho + stiffCoeff * K_kappa with M_ij = int rho phi_i phi_j and
  /// K_ij = int kappa grad phi_i . grad phi_j; Dirichlet rows/columns replaced by the identity.
  /// With \p lumpMassAt (overlap flags, optional), mass couplings of the flagged nodes are moved to
  /// the diagonal (row sums kept, couplings to Dirichlet nodes included: lumped before the elimination):
  /// lumped mass on the contact boundary against chattering (DESIGN 1.6).
  RCP<CrsMatrix> assembleOperator(double massCoeff, double stiffCoeff, double rho, double kappa,
                                  const std::vector<char>& lumpMassAt = {}) const;
  /// M_rho (lumped at \p lumpAt) and K_kappa in one pass over the cells (same values as
  /// assembleOperator(1, 0, ...) and assembleOperator(0, 1, ...)).
  std::pair<RCP<CrsMatrix>, RCP<CrsMatrix>> assembleMassAndStiffness(const ProblemData& problem,
                                                                     const std::vector<char>& lumpAt) const override;
  /// out (owned) = scale * int f(., t) phi_i dx, or += if \p accumulate.
  void assembleLoad(const core::Expression& f, double t, double scale, Vector& out, bool accumulate = false) const;
  /// out (owned) += scale * int_{edges in mask} q(., t) phi_i ds.
  void addBoundaryLoad(const core::Expression& q, double t, unsigned mask, double scale, Vector& out) const;
  /// Sets the Dirichlet entries of an owned vector to zero.
  void zeroDirichlet(Vector& v) const override;
  /// Values on the overlap map (owned + shared) of an owned vector.
  void toOverlap(const Vector& owned, Vector& overlap) const override;
  /// L2 norm and H1 seminorm of u_h - u_exact(., t) (3x3 Gauss; gradient of u_exact by central differences).
  std::pair<double, double> errorNorms(const Vector& uOwned, const core::Expression& exact, double t) const;
  /// u_h at a point (every rank gets the value); NaN if the point is outside the mesh.
  double evaluate(const Vector& uOverlap, double x, double y) const;
  /// Total area of the mesh (sum over all ranks).
  double area() const;

  const std::vector<char>& dirichletFlags() const override { return dirichlet_; }

  // Public only because nvcc refuses a KOKKOS_LAMBDA in a private or protected member function.
  /// The device-side CRS matrix the kernels sum into.
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  /// Cell kernel shared by assembleOperator and assembleMassAndStiffness: mass part times cm summed
  /// into \p first, stiffness part times ck into \p second (the same matrix for a combined
  /// operator); both opened by pattern_. Dirichlet rows and columns stay empty.
  void assembleInto(const LocalMatrix& first, const LocalMatrix& second, double cm, double ck,
                    const std::vector<char>& lumpMassAt) const;

 private:
  /// What sumDirichletRows() and massTimesField() read of this discretisation and \p problem.
  DirichletRowsInput rowsInput(const ProblemData& problem, const std::vector<char>& lumpAt) const;
  const mesh::Q1Mesh& mesh_;
  std::vector<char> dirichlet_;
  Kokkos::View<int*, DeviceType> dirichletView_;
  std::unique_ptr<Q1Pattern> pattern_;  ///< the matrices' sparsity; creates and finishes them
  /// Reproducible arithmetic (core::reproducibleArithmetic()): the cells' contributions to M
  /// (times cm, lumped at \p lumpMassAt) and K (times ck), one per pair of corner unknowns of each
  /// cell (several per entry and cell at hanging corners), in the kernel's order, Dirichlet rows
  /// and columns left out, for EntrySums; \p mass and \p stiffness may be the same list. Only the
  /// rows flagged in \p onlyRows (overlap ids), when it is not empty.
  void cellContributions(double cm, double ck, const std::vector<char>& lumpMassAt, std::vector<Contribution>* mass,
                         std::vector<Contribution>* stiffness, const std::vector<char>& onlyRows = {}) const;
  /// Reproducible arithmetic on several ranks with the Serial execution space: the overlap rows that
  /// other ranks' cells also touch (shared nodes). Only they need EntrySums; the ordinary kernel
  /// adds every other row's contributions in cell order already. Empty where EntrySums give all
  /// rows (threads) or none are needed.
  std::vector<char> exchangedRows() const;
  /// The owned rows EntrySums must leave alone: Dirichlet rows, and those not in \p exchanged
  /// (empty: none of them).
  std::vector<char> keptRows(const std::vector<char>& exchanged) const;
  EntrySums canonicalSums(const std::vector<Contribution>& contributions) const;
  /// Reproducible arithmetic: rows of matrices on the pattern summed in the order of the nodes'
  /// canonical keys (core::registerCanonicalRowOrder; one order serves M, K and the step matrix).
  void registerCanonicalRowOrder(const CrsMatrix& A) const;
  RCP<const Tpetra::Export<LO, GO, Node>> exporter_;
  RCP<const Tpetra::Import<LO, GO, Node>> importer_;
};

}  // namespace signorini::fem
