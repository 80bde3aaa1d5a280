#include "signorini/fem/MeshTransfer.hpp"

#include <algorithm>
#include <cmath>

#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/fem/EntrySums.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::fem {
namespace {

/// The determinant of tree t's map if it is constant (parallelogram trees, every rectangle), else NaN.
double constantJacobianDeterminant(const mesh::CoarseMesh& coarse, int t) {
  const double d = coarse.jacobianDeterminant(t, 0, 0);
  double spread = 0;  // det J is bilinear in (s, r): constant if equal at the corners
  for (int c = 1; c < 4; ++c) spread += std::abs(coarse.jacobianDeterminant(t, c & 1, c >> 1) - d);
  return spread <= 1e-13 * std::abs(d) ? d : std::nan("");
}
}  // namespace

MeshTransfer::MeshTransfer(const mesh::Forest& oldForest, const mesh::Q1Mesh& oldMesh,
                           const std::vector<const Vector*>& fields, const mesh::Forest& newForest,
                           const mesh::Q1Mesh& newMesh)
    : newMesh_(newMesh), coarse_(newForest.coarse()), numFields_(static_cast<int>(fields.size())) {
  // Payload of each old cell: the corner values (z-order, hanging constraints resolved) of each field.
  const LO nc = oldMesh.numLocalCells();
  std::vector<double> payload(static_cast<size_t>(nc) * 4 * numFields_);
  const auto& D = oldMesh.cornerDofsHost;
  const auto& W = oldMesh.cornerWeightsHost;
  for (int f = 0; f < numFields_; ++f) {
    Vector overlap(oldMesh.overlapMap());
    overlap.doImport(*fields[f], oldMesh.ownedToOverlap(), Tpetra::INSERT);
    auto h = overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO e = 0; e < nc; ++e)
      for (int c = 0; c < 4; ++c) {
        double v = 0;
        for (int k = 0; k < 2; ++k)
          if (D(e, c, k) >= 0) v += W(e, c, k) * h(D(e, c, k), 0);
        payload[(static_cast<size_t>(e) * numFields_ + f) * 4 + c] = v;
      }
  }
  overlap_ = std::make_unique<mesh::ForestOverlap>(oldForest, newForest, payload, 4 * numFields_);
}

double MeshTransfer::valueAt(const mesh::OverlapCell& q, int field, double s, double r) const {
  const double ls = (s - q.s0) / q.size, lr = (r - q.r0) / q.size;
  const double* c = q.payload + 4 * field;
  return (1 - ls) * (1 - lr) * c[0] + ls * (1 - lr) * c[1] + (1 - ls) * lr * c[2] + ls * lr * c[3];
}

std::vector<RCP<Vector>> MeshTransfer::assembleLoads(int nf, const std::vector<char>* skip,
                                                    const std::function<void(int e, double be[8][4])>& cellLoads) const {
  SIGNORINI_ASSERT(nf <= 8, "too many fields");
  const auto& D = newMesh_.cornerDofsHost;
  const auto& W = newMesh_.cornerWeightsHost;
  std::vector<Vector> overlap;
  for (int f = 0; f < nf; ++f) {
    overlap.emplace_back(newMesh_.overlapMap());
    overlap.back().putScalar(0.0);
  }
  std::vector<decltype(overlap[0].getLocalViewHost(Tpetra::Access::ReadWrite))> views;
  for (auto& o : overlap) views.push_back(o.getLocalViewHost(Tpetra::Access::ReadWrite));
  // Reproducible arithmetic on several ranks: the rows of shared nodes are summed by EntrySums;
  // every other row adds this rank's cells in their order below, as one rank would.
  const bool reproducible = needEntrySums(*newMesh_.comm());
  const auto shared = reproducible ? sharedRows(*newMesh_.overlapMap(), newMesh_.ownedToOverlap()) : std::vector<char>();
  std::vector<std::vector<Contribution>> contributions(reproducible ? nf : 0);
  for (int e = 0; e < overlap_->numTargetCells(); ++e) {
    double be[8][4] = {};  // [field][corner]
    cellLoads(e, be);
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 2; ++k) {
          const LO d = D(e, c, k);
          if (d < 0 || (skip && (*skip)[d])) continue;
          if (reproducible && shared[d])
            contributions[f].push_back({d, 0, W(e, c, k) * be[f][c]});
          else
            views[f](d, 0) += W(e, c, k) * be[f][c];
        }
  }
  views.clear();
  std::vector<RCP<Vector>> loads;
  for (int f = 0; f < nf; ++f) {
    auto b = Teuchos::rcp(new Vector(newMesh_.ownedMap()));
    if (reproducible)  // each node's contributions added in the order of the cells, on its owner (EntrySums)
      EntrySums(*newMesh_.ownedMap(), *newMesh_.overlapMap(), newMesh_.ownedToOverlap(), contributions[f])
          .writeInto(*b, false, shared, &overlap[f]);
    else
      b->doExport(overlap[f], newMesh_.overlapToOwned(), Tpetra::ADD);
    loads.push_back(b);
  }
  return loads;
}

std::vector<RCP<Vector>> MeshTransfer::projectionLoads(const Q1Assembler& newAssembler, int numFields) const {
  const int nf = numFields < 0 ? numFields_ : std::min(numFields, numFields_);
  std::vector<double> treeDeterminant(coarse_.numTrees());
  for (int t = 0; t < coarse_.numTrees(); ++t) treeDeterminant[t] = constantJacobianDeterminant(coarse_, t);
  return assembleLoads(nf, &newAssembler.dirichletFlags(), [&](int e, double be[8][4]) {
    const auto& K = overlap_->target(e);
    const double det = treeDeterminant[K.tree];
    if (!std::isnan(det)) {  // u and the basis are bilinear on each cell of the common refinement: exact
      for (const auto& Q : overlap_->overlapping(e)) {
        if (Q.size >= K.size) {  // K inside Q: be = M_K (u at K's corners)
          const double area36 = det * K.size * K.size / 36;
          for (int f = 0; f < nf; ++f) {
            double u[4];
            for (int c = 0; c < 4; ++c)
              u[c] = valueAt(Q, f, K.s0 + ((c & 1) ? K.size : 0), K.r0 + ((c & 2) ? K.size : 0));
            for (int a = 0; a < 4; ++a)
              for (int b = 0; b < 4; ++b) be[f][a] += area36 * q1Mass36(a, b) * u[b];
          }
        } else {  // Q inside K: be_c = (phi^K_c at Q's corners) . M_Q u_Q
          const double area36 = det * Q.size * Q.size / 36;
          double N[4][4];  // [corner of Q][basis function of K]
          for (int a = 0; a < 4; ++a) {
            const double ks = (Q.s0 + ((a & 1) ? Q.size : 0) - K.s0) / K.size;
            const double kr = (Q.r0 + ((a & 2) ? Q.size : 0) - K.r0) / K.size;
            double dNds[4], dNdr[4];
            q1Shape(ks, kr, N[a], dNds, dNdr);
          }
          for (int f = 0; f < nf; ++f) {
            const double* u = Q.payload + 4 * f;
            for (int a = 0; a < 4; ++a) {
              double Mu = 0;
              for (int b = 0; b < 4; ++b) Mu += q1Mass36(a, b) * u[b];
              for (int c = 0; c < 4; ++c) be[f][c] += area36 * N[a][c] * Mu;
            }
          }
        }
      }
    } else {  // 3 x 3 Gauss points on each cell of the common refinement
      for (const auto& Q : overlap_->overlapping(e)) {
        const auto& R = Q.size < K.size ? Q : K;  // the cell of the common refinement
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const double s = R.s0 + kGauss3Point[i] * R.size, r = R.r0 + kGauss3Point[j] * R.size;
            const double w = kGauss3Weight[i] * kGauss3Weight[j] * R.size * R.size * coarse_.jacobianDeterminant(K.tree, s, r);
            double N[4], dNds[4], dNdr[4];
            q1Shape((s - K.s0) / K.size, (r - K.r0) / K.size, N, dNds, dNdr);
            for (int f = 0; f < nf; ++f) {
              const double u = valueAt(Q, f, s, r);
              for (int c = 0; c < 4; ++c) be[f][c] += w * u * N[c];
            }
          }
      }
    }
  });
}

std::vector<RCP<Vector>> MeshTransfer::stiffnessLoads(const ElementStiffness& stiffness, int first, int nc) const {
  SIGNORINI_ASSERT(nc >= 1 && nc <= 2 && first >= 0 && first + nc <= numFields_, "fields out of range");
  return assembleLoads(nc, nullptr, [&](int e, double be[8][4]) {
    const auto& K = overlap_->target(e);
    for (const auto& Q : overlap_->overlapping(e)) {
      const auto& R = Q.size < K.size ? Q : K;  // the cell of the common refinement
      double X[4][2], N[4][4], u[8];  // R's corners; the new basis at them [corner of R][basis of K]; u_old there
      for (int a = 0; a < 4; ++a) {
        const double s = R.s0 + ((a & 1) ? R.size : 0), r = R.r0 + ((a & 2) ? R.size : 0);
        const auto x = coarse_.mapPoint(K.tree, s, r);
        X[a][0] = x[0], X[a][1] = x[1];
        double dNds[4], dNdr[4];
        q1Shape((s - K.s0) / K.size, (r - K.r0) / K.size, N[a], dNds, dNdr);
        for (int i = 0; i < nc; ++i) u[nc * a + i] = valueAt(Q, first + i, s, r);
      }
      double Ke[8][8];
      stiffness(X, Ke);
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < nc; ++i) {
          double Ku = 0;  // (K_R u)_(a, i)
          for (int b = 0; b < nc * 4; ++b) Ku += Ke[nc * a + i][b] * u[b];
          for (int c = 0; c < 4; ++c) be[i][c] += N[a][c] * Ku;
        }
    }
  });
}

std::vector<RCP<Vector>> MeshTransfer::interpolate() const {
  const auto& D = newMesh_.cornerDofsHost;
  const LO owned = static_cast<LO>(newMesh_.ownedMap()->getNodeNumElements());
  std::vector<RCP<Vector>> out;
  std::vector<char> set(owned, 0);
  for (int f = 0; f < numFields_; ++f) out.push_back(Teuchos::rcp(new Vector(newMesh_.ownedMap())));
  std::vector<decltype(out[0]->getLocalViewHost(Tpetra::Access::ReadWrite))> views;
  for (auto& o : out) views.push_back(o->getLocalViewHost(Tpetra::Access::ReadWrite));
  const double tol = 1e-12;
  // A node shared by several cells takes its value from the last of them in cell order: visited
  // backwards, the first visit sets it.
  for (int e = overlap_->numTargetCells() - 1; e >= 0; --e) {
    const auto& K = overlap_->target(e);
    const auto cells = overlap_->overlapping(e);
    for (int c = 3; c >= 0; --c) {
      const LO d = D(e, c, 0);
      if (D(e, c, 1) >= 0 || d >= owned || set[d]) continue;  // hanging, not owned or done
      const double s = K.s0 + ((c & 1) ? K.size : 0), r = K.r0 + ((c & 2) ? K.size : 0);
      for (const auto& Q : cells)
        if (s >= Q.s0 - tol && s <= Q.s0 + Q.size + tol && r >= Q.r0 - tol && r <= Q.r0 + Q.size + tol) {
          for (int f = 0; f < numFields_; ++f) views[f](d, 0) = valueAt(Q, f, s, r);
          set[d] = 1;
          break;
        }
    }
  }
  for (LO i = 0; i < owned; ++i) SIGNORINI_ASSERT(set[i], "owned node " << i << " not reached by interpolation");
  return out;
}

}  // namespace signorini::fem
