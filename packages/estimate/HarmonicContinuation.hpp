#pragma once
/// \file HarmonicContinuation.hpp
/// s1 = ||w||_{1/2, Gamma_C} of the paper's Remark 4.1 for nodal boundary data w on Gamma_C,
/// evaluated as the H^1 norm of the discrete harmonic continuation: the minimiser d of
/// ||v||_1^2 = int |grad v|^2 + m v^2 over the Q1 functions with v = w at the contact nodes and
/// v = 0 at the fixed (Dirichlet) nodes. The paper's norm has m = 1 in the deck's unit of length;
/// m = 1/l^2 for a length l of the problem makes s1 a length whatever that unit
/// (Estimator/S1 Length Scale). Every extension of w bounds s1 from above, so an
/// iterative solve approaches s1 from above.
#include <functional>
#include <vector>

#include "signorini/fem/Q1Assembler.hpp"

namespace signorini::estimate {

/// What s1 keeps between calls on one mesh (the caller names the mesh by an id that no other mesh
/// of the run shares): the H^1 operator, its form with the prescribed rows, and the last
/// continuation, which starts the next solve (the data change little from step to step).
struct ContinuationCache {
  long meshId = -1;                       ///< the mesh the rest belongs to (-1: none yet)
  std::vector<char> prescribed;           ///< overlap flags: contact or fixed nodes
  /// \var full
  /// The H^1 operator K + m M on every node.
  /// \var constrained
  /// The same with the prescribed rows and columns made identity (the solve's matrix).
  RCP<const CrsMatrix> full, constrained;
  RCP<Vector> last;                       ///< the last continuation (owned nodes): the next solve's start

  /// The last continuation if it lives on mesh \p id (else null).
  RCP<Vector> lastOn(long id) const { return id >= 0 && meshId == id ? last : Teuchos::null; }
};

/// s1 = ||(g - w)_+||_{1/2, Gamma_C} for the nodal values w(i) of the constrained quantity at the
/// owned nodes (u_h, or sign u_c for elasticity): the data (g - w)_+ at the contact nodes of
/// \p contactMask that are not \p fixed (overlap node flags), continued harmonically with v = 0 at the
/// fixed nodes; 0 (and no solve) when the positive part vanishes on every rank. \p scalar: a scalar
/// assembler whose Dirichlet nodes are \p fixed, or null to build one when it is needed. With a
/// \p cache and \p meshId >= 0, the operators are built once per mesh and each solve starts from
/// the previous continuation on the same mesh, or from \p guess (owned nodes) on a new mesh.
/// \p h1Operator (optional, may return null) supplies K + m M with unit coefficients and the fixed
/// nodes eliminated instead of an assembly; \p massWeight is m (1/length^2 in the deck's units).
double geometricContactTerm(const mesh::Q1Mesh& mesh, unsigned contactMask, const core::Expression& g, double t,
                            const std::function<double(LO)>& w, const std::vector<char>& fixed,
                            const fem::Q1Assembler* scalar,
                            const std::function<void(const RCP<const CrsMatrix>&, const Vector&, Vector&)>& solveSPD,
                            ContinuationCache* cache = nullptr, long meshId = -1, const Vector* guess = nullptr,
                            const std::function<RCP<const CrsMatrix>()>& h1Operator = {}, double massWeight = 1.0);

}  // namespace signorini::estimate
