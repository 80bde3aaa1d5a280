#include "Q1Mesh.hpp"

#include <algorithm>
#include <cmath>

#include <p4est_ghost.h>
#include <p4est_lnodes.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "Error.hpp"

namespace signorini::mesh {

double BoundaryEdge::length() const { return std::hypot(x[1][0] - x[0][0], x[1][1] - x[0][1]); }

Q1Mesh::Q1Mesh(const Forest& forest, const BoundarySegments& segments, RCP<const Comm> comm) : comm_(comm) {
  p4est_t* p4est = forest.p4est();
  const CoarseMesh& coarse = forest.coarse();
  p4est_ghost_t* ghost = p4est_ghost_new(p4est, P4EST_CONNECT_FULL);
  p4est_lnodes_t* lnodes = p4est_lnodes_new(p4est, ghost, 1);

  // Maps: owned nodes are global_offset + [0, owned_count); overlap = owned then nonlocal.
  const LO numLocalNodes = lnodes->num_local_nodes, owned = lnodes->owned_count;
  std::vector<GO> gids(numLocalNodes);
  for (LO i = 0; i < owned; ++i) gids[i] = static_cast<GO>(lnodes->global_offset + i);
  for (LO i = owned; i < numLocalNodes; ++i) gids[i] = static_cast<GO>(lnodes->nonlocal_nodes[i - owned]);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  // lnodes numbers the owned nodes contiguously by rank: a contiguous map (Amesos2 and MueLu's
  // coarse solver need one).
  ownedMap_ = Teuchos::rcp(new Map(invalid, static_cast<size_t>(owned), 0, comm));
  SIGNORINI_ASSERT(owned == 0 || ownedMap_->getMinGlobalIndex() == gids[0], "lnodes owned nodes are not contiguous");
  overlapMap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids.data(), numLocalNodes), 0, comm));
  importer_ = Teuchos::rcp(new Tpetra::Import<LO, GO, Node>(ownedMap_, overlapMap_));
  exporter_ = Teuchos::rcp(new Tpetra::Export<LO, GO, Node>(*importer_));  // the reverse of importer_

  numCells_ = static_cast<LO>(p4est->local_num_quadrants);
  numGlobalCells_ = static_cast<long long>(p4est->global_num_quadrants);
  cornerCoords = CellCoords("cornerCoords", numCells_);
  cornerDofs = CellDofs("cornerDofs", numCells_);
  cornerWeights = CellWeights("cornerWeights", numCells_);
  cornerCoordsHost = Kokkos::create_mirror_view(cornerCoords);
  cornerDofsHost = Kokkos::create_mirror_view(cornerDofs);
  cornerWeightsHost = Kokkos::create_mirror_view(cornerWeights);
  cellLevel_.resize(numCells_);
  cellTree_.resize(numCells_);
  nodeCoords_.assign(numLocalNodes, {0.0, 0.0});

  double hmin = 1e300, hmax = 0;
  const double root = static_cast<double>(P4EST_ROOT_LEN);
  LO e = 0;
  for (p4est_topidx_t t = p4est->first_local_tree; t <= p4est->last_local_tree; ++t) {
    p4est_tree_t* tree = p4est_tree_array_index(p4est->trees, t);
    for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi, ++e) {
      const auto* q = p4est_quadrant_array_index(&tree->quadrants, qi);
      const p4est_qcoord_t len = P4EST_QUADRANT_LEN(q->level);
      cellLevel_[e] = q->level - coarse.levelOffset();  // the user's level: 0 on the coarse cells
      cellTree_[e] = static_cast<int>(t);
      for (int c = 0; c < 4; ++c) {
        const double s = (q->x + ((c & 1) ? len : 0)) / root, r = (q->y + ((c & 2) ? len : 0)) / root;
        const auto p = coarse.mapPoint(static_cast<int>(t), s, r);
        cornerCoordsHost(e, c, 0) = p[0];
        cornerCoordsHost(e, c, 1) = p[1];
        const LO n = lnodes->element_nodes[4 * e + c];
        cornerDofsHost(e, c, 0) = n;
        cornerWeightsHost(e, c, 0) = 1.0;
        cornerDofsHost(e, c, 1) = -1;
        cornerWeightsHost(e, c, 1) = 0.0;
      }
      // Hanging corners: value = average of the parent face's end nodes (p4est lnodes encoding:
      // the hanging corner lists the parent's node at that corner; the other end is corner cid).
      const p4est_lnodes_code_t fc = lnodes->face_code[e];
      if (fc) {
        const int cid = fc & 3;
        int work = fc >> 2;
        for (int i = 0; i < 2; ++i, work >>= 1) {
          if (!(work & 1)) continue;
          const int k = cid ^ 3 ^ (1 << i);
          cornerWeightsHost(e, k, 0) = 0.5;
          cornerDofsHost(e, k, 1) = lnodes->element_nodes[4 * e + cid];
          cornerWeightsHost(e, k, 1) = 0.5;
        }
      }
      for (int c = 0; c < 4; ++c)
        if (cornerDofsHost(e, c, 1) < 0)
          nodeCoords_[cornerDofsHost(e, c, 0)] = {cornerCoordsHost(e, c, 0), cornerCoordsHost(e, c, 1)};
      static const int edges[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
      for (const auto& ed : edges) {
        const double l = std::hypot(cornerCoordsHost(e, ed[1], 0) - cornerCoordsHost(e, ed[0], 0),
                                    cornerCoordsHost(e, ed[1], 1) - cornerCoordsHost(e, ed[0], 1));
        hmin = std::min(hmin, l);
        hmax = std::max(hmax, l);
      }
      // Boundary edges: faces of the cell on a boundary face of the coarse mesh.
      for (int f = 0; f < 4; ++f) {
        const bool treeBoundary = coarse.connectivity()->tree_to_tree[4 * t + f] == t &&
                                  coarse.connectivity()->tree_to_face[4 * t + f] == f;
        if (!treeBoundary) continue;
        const bool touches = (f == 0 && q->x == 0) || (f == 1 && q->x + len == P4EST_ROOT_LEN) ||
                             (f == 2 && q->y == 0) || (f == 3 && q->y + len == P4EST_ROOT_LEN);
        if (!touches) continue;
        BoundaryEdge be{};
        be.cell = e;
        be.face = f;
        be.level = q->level - coarse.levelOffset();
        for (int k = 0; k < 2; ++k) {
          const int c = p4est_face_corners[f][k];
          SIGNORINI_ASSERT(cornerDofsHost(e, c, 1) < 0, "boundary corner is hanging");
          be.node[k] = cornerDofsHost(e, c, 0);
          be.x[k][0] = cornerCoordsHost(e, c, 0);
          be.x[k][1] = cornerCoordsHost(e, c, 1);
        }
        be.segments = segments.match(coarse, static_cast<int>(t), f, 0.5 * (be.x[0][0] + be.x[1][0]),
                                     0.5 * (be.x[0][1] + be.x[1][1]));
        boundaryEdges_.push_back(be);
      }
    }
  }
  Kokkos::deep_copy(cornerCoords, cornerCoordsHost);
  Kokkos::deep_copy(cornerDofs, cornerDofsHost);
  Kokkos::deep_copy(cornerWeights, cornerWeightsHost);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, hmin, Teuchos::outArg(hMin_));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, hmax, Teuchos::outArg(hMax_));

  // Coordinates of shared nodes that no local cell sees unconstrained are filled from their owner.
  {
    Vector ox(overlapMap_), oy(overlapMap_), cnt(overlapMap_);
    {
      auto hx = ox.getLocalViewHost(Tpetra::Access::OverwriteAll);
      auto hy = oy.getLocalViewHost(Tpetra::Access::OverwriteAll);
      auto hc = cnt.getLocalViewHost(Tpetra::Access::OverwriteAll);
      std::vector<char> seen(numLocalNodes, 0);
      for (LO c = 0; c < numCells_; ++c)
        for (int k = 0; k < 4; ++k)
          if (cornerDofsHost(c, k, 1) < 0) seen[cornerDofsHost(c, k, 0)] = 1;
      for (LO i = 0; i < numLocalNodes; ++i) {
        hx(i, 0) = seen[i] ? nodeCoords_[i][0] : 0.0;
        hy(i, 0) = seen[i] ? nodeCoords_[i][1] : 0.0;
        hc(i, 0) = seen[i] ? 1.0 : 0.0;
      }
    }
    Vector sx(ownedMap_), sy(ownedMap_), sc(ownedMap_);
    sx.doExport(ox, *exporter_, Tpetra::ADD);
    sy.doExport(oy, *exporter_, Tpetra::ADD);
    sc.doExport(cnt, *exporter_, Tpetra::ADD);
    {
      auto hx = sx.getLocalViewHost(Tpetra::Access::ReadWrite);
      auto hy = sy.getLocalViewHost(Tpetra::Access::ReadWrite);
      auto hc = sc.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (size_t i = 0; i < hx.extent(0); ++i) {
        SIGNORINI_ASSERT(hc(i, 0) > 0, "owned node without an unconstrained cell corner");
        hx(i, 0) /= hc(i, 0);
        hy(i, 0) /= hc(i, 0);
      }
    }
    ox.doImport(sx, *importer_, Tpetra::INSERT);
    oy.doImport(sy, *importer_, Tpetra::INSERT);
    auto hx = ox.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto hy = oy.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < numLocalNodes; ++i) nodeCoords_[i] = {hx(i, 0), hy(i, 0)};
  }

  p4est_lnodes_destroy(lnodes);
  p4est_ghost_destroy(ghost);
}

LO Q1Mesh::locate(double x, double y, double& s, double& r) const {
  const auto& X = cornerCoordsHost;
  const double tol = 1e-10;
  for (LO e = 0; e < numCells_; ++e) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    double Xe[4][2];
    for (int c = 0; c < 4; ++c)
      for (int d = 0; d < 2; ++d) {
        Xe[c][d] = X(e, c, d);
        lo[d] = std::min(lo[d], Xe[c][d]), hi[d] = std::max(hi[d], Xe[c][d]);
      }
    const double pad = 1e-9 * (hi[0] - lo[0] + hi[1] - lo[1]);
    if (x < lo[0] - pad || x > hi[0] + pad || y < lo[1] - pad || y > hi[1] + pad) continue;
    s = 0.5, r = 0.5;
    for (int it = 0; it < 30; ++it) {  // Newton on the bilinear map
      double N[4], ds[4], dr[4];
      for (int c = 0; c < 4; ++c) {
        const double fs = (c & 1) ? s : 1 - s, fr = (c & 2) ? r : 1 - r;
        N[c] = fs * fr;
        ds[c] = ((c & 1) ? 1 : -1) * fr;
        dr[c] = fs * ((c & 2) ? 1 : -1);
      }
      double fx = -x, fy = -y, a = 0, b = 0, c = 0, d = 0;
      for (int k = 0; k < 4; ++k) {
        fx += N[k] * Xe[k][0], fy += N[k] * Xe[k][1];
        a += ds[k] * Xe[k][0], b += dr[k] * Xe[k][0], c += ds[k] * Xe[k][1], d += dr[k] * Xe[k][1];
      }
      const double det = a * d - b * c;
      s -= (d * fx - b * fy) / det;
      r -= (-c * fx + a * fy) / det;
      if (std::abs(fx) + std::abs(fy) < 1e-14 * (hi[0] - lo[0] + hi[1] - lo[1])) break;
    }
    if (s >= -tol && s <= 1 + tol && r >= -tol && r <= 1 + tol) return e;
  }
  return -1;
}

std::vector<char> Q1Mesh::nodesOnSegments(unsigned mask) const {
  Vector local(overlapMap_);
  {
    auto h = local.getLocalViewHost(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(h, 0.0);
    for (const auto& be : boundaryEdges_)
      if (be.segments & mask)
        for (int k = 0; k < 2; ++k) h(be.node[k], 0) = 1.0;
  }
  Vector owned(ownedMap_);
  owned.doExport(local, *exporter_, Tpetra::ADD);
  local.doImport(owned, *importer_, Tpetra::INSERT);
  auto h = local.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<char> flags(h.extent(0));
  for (size_t i = 0; i < flags.size(); ++i) flags[i] = h(i, 0) > 0 ? 1 : 0;
  return flags;
}

std::vector<char> Q1Mesh::balanceClosure(const std::vector<char>& flagged) const {
  SIGNORINI_ASSERT(flagged.size() == static_cast<size_t>(numCells_), "one flag per local cell");
  std::vector<char> closure(flagged);
  // At each regular corner node: 1 + the finest level of the flagged cells touching it (0: none).
  // A cell touching a flagged cell one level finer must be refined too; in a balanced forest the
  // cells at a node differ by at most one level, so "coarser than a flagged cell there" is that.
  Vector atNode(overlapMap_), owned(ownedMap_);
  const auto& D = cornerDofsHost;
  for (;;) {
    {
      auto h = atNode.getLocalViewHost(Tpetra::Access::OverwriteAll);
      Kokkos::deep_copy(h, 0.0);
      for (LO e = 0; e < numCells_; ++e)
        if (closure[e])
          for (int c = 0; c < 4; ++c)
            if (D(e, c, 1) < 0) h(D(e, c, 0), 0) = std::max(h(D(e, c, 0), 0), cellLevel_[e] + 1.0);
    }
    owned.putScalar(0.0);
    owned.doExport(atNode, *exporter_, Tpetra::ABSMAX);
    atNode.doImport(owned, *importer_, Tpetra::INSERT);
    long added = 0, addedGlobal = 0;
    {
      auto h = atNode.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (LO e = 0; e < numCells_; ++e) {
        if (closure[e]) continue;
        for (int c = 0; c < 4; ++c)
          if (D(e, c, 1) < 0 && cellLevel_[e] + 1.0 < h(D(e, c, 0), 0)) {
            closure[e] = 1;
            ++added;
            break;
          }
      }
    }
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, added, Teuchos::outArg(addedGlobal));
    if (addedGlobal == 0) break;
  }
  return closure;
}

}  // namespace signorini::mesh
