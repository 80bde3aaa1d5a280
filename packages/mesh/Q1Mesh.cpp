#include "signorini/mesh/Q1Mesh.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include <p4est_communication.h>
#include <p4est_ghost.h>
#include <p4est_lnodes.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/mesh/CoordinateTable.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"

namespace signorini::mesh {

double BoundaryEdge::length() const { return std::hypot(x[1][0] - x[0][0], x[1][1] - x[0][1]); }

namespace {

/// The Q1 nodes at the corners of the local cells: overlap ids (owned first) with their global
/// ids, and per corner (4 per cell, z-order) the node, or for a hanging corner the two end
/// nodes of the coarser face it halves (second entry -1 at a regular corner).
struct CornerNumbering {
  LO owned = 0;
  std::vector<GO> gids;
  std::vector<std::array<LO, 2>> corner;
};

/// The general numbering: p4est lnodes (any forest, any number of ranks).
CornerNumbering numberWithLnodes(p4est_t* p4est) {
  p4est_ghost_t* ghost = p4est_ghost_new(p4est, P4EST_CONNECT_FULL);
  p4est_lnodes_t* lnodes = p4est_lnodes_new(p4est, ghost, 1);
  CornerNumbering out;
  const LO numLocalNodes = lnodes->num_local_nodes;
  out.owned = lnodes->owned_count;
  out.gids.resize(numLocalNodes);
  for (LO i = 0; i < out.owned; ++i) out.gids[i] = static_cast<GO>(lnodes->global_offset + i);
  for (LO i = out.owned; i < numLocalNodes; ++i) out.gids[i] = static_cast<GO>(lnodes->nonlocal_nodes[i - out.owned]);
  const LO numCells = static_cast<LO>(p4est->local_num_quadrants);
  out.corner.resize(4 * static_cast<size_t>(numCells));
  for (LO e = 0; e < numCells; ++e) {
    for (int c = 0; c < 4; ++c) out.corner[4 * e + c] = {lnodes->element_nodes[4 * e + c], -1};
    // p4est lnodes encoding: the hanging corner lists the parent's node at that corner; the
    // other end of the parent's face is the node at corner cid.
    const p4est_lnodes_code_t fc = lnodes->face_code[e];
    if (!fc) continue;
    const int cid = fc & 3;
    int work = fc >> 2;
    for (int i = 0; i < 2; ++i, work >>= 1)
      if (work & 1) out.corner[4 * e + (cid ^ 3 ^ (1 << i))][1] = lnodes->element_nodes[4 * e + cid];
  }
  p4est_lnodes_destroy(lnodes);
  p4est_ghost_destroy(ghost);
  return out;
}

/// Whether the coarse mesh is one tree whose faces and corners all lie on the boundary (no
/// periodicity, no face or corner joined to another of its own): numberOneTree's case.
bool isolatedSingleTree(const p4est_connectivity_t& c) {
  if (c.num_trees != 1 || c.num_corners != 0) return false;
  for (int f = 0; f < 4; ++f)
    if (c.tree_to_tree[f] != 0 || c.tree_to_face[f] != f) return false;
  return true;
}

/// The same numbering for a forest of one tree, on any number of ranks, without p4est's general
/// iteration over volumes, faces and corners (which cost more than an unconstrained solve per step
/// of the membrane benchmark on one rank, and on two ranks more than the rest of the new mesh): the
/// corner points of the local cells in one hash table of their integer coordinates; a corner point
/// is hanging exactly when it is the midpoint of a face of another cell (2:1 balance: that cell is
/// one level coarser and the face's end points are regular), which is a local cell or in the face
/// ghost layer (it shares a face with the finer cell that has the point as a corner).
///
/// A regular point belongs to the rank that owns the cell with the point as its lower left corner
/// (at the right and upper boundary: the cell of the smallest quadrant inside the tree there), a
/// function of the point and p4est's partition alone, so every rank that sees the point agrees
/// without communication, and the owner has the point as a corner of one of its cells. Each rank
/// numbers its own points in the order its cells first touch them; the global ids of the others
/// come from their owners (one exchange). On one rank: no ghost layer, no exchange.
CornerNumbering numberOneTree(p4est_t* p4est) {
  const int size = p4est->mpisize, rank = p4est->mpirank;
  const size_t numCells = static_cast<size_t>(p4est->local_num_quadrants);
  sc_array_t* cells = numCells > 0 ? &p4est_tree_array_index(p4est->trees, 0)->quadrants : nullptr;
  static_assert(std::is_same_v<GO, long long> && std::is_same_v<p4est_qcoord_t, int>,
                "the exchange sends global ids as long long and coordinates as int");
  const std::unique_ptr<p4est_ghost_t, void (*)(p4est_ghost_t*)> ghostLayer(
      size > 1 ? p4est_ghost_new(p4est, P4EST_CONNECT_FACE) : nullptr, [](p4est_ghost_t* g) {
        if (g) p4est_ghost_destroy(g);
      });
  p4est_ghost_t* ghost = ghostLayer.get();
  const size_t numGhosts = ghost ? ghost->ghosts.elem_count : 0;
  CoordinateTable points(4 * (numCells + numGhosts));
  std::vector<std::array<p4est_qcoord_t, 2>> coords;  // of every point (several ranks)
  if (size > 1) coords.reserve(4 * numCells + 2 * numGhosts);
  LO numPoints = 0;
  auto point = [&](p4est_qcoord_t x, p4est_qcoord_t y) {
    const LO p = points.insert(x, y, numPoints);
    if (p == numPoints) {
      ++numPoints;
      if (size > 1) coords.push_back({x, y});
    }
    return p;
  };
  std::vector<LO> cornerPoint(4 * numCells);
  for (size_t e = 0; e < numCells; ++e) {
    const auto* q = p4est_quadrant_array_index(cells, e);
    const p4est_qcoord_t len = P4EST_QUADRANT_LEN(q->level);
    for (int c = 0; c < 4; ++c) cornerPoint[4 * e + c] = point(q->x + ((c & 1) ? len : 0), q->y + ((c & 2) ? len : 0));
  }
  std::vector<std::array<LO, 2>> ends(numPoints, {-1, -1});  // a hanging point's face end points
  for (size_t e = 0; e < numCells + numGhosts; ++e) {
    const bool local = e < numCells;
    const auto* q = local ? p4est_quadrant_array_index(cells, e) : p4est_quadrant_array_index(&ghost->ghosts, e - numCells);
    const p4est_qcoord_t len = P4EST_QUADRANT_LEN(q->level), half = len / 2;
    SIGNORINI_ASSERT(half > 0, "cell at p4est's finest level");
    const p4est_qcoord_t mid[4][2] = {{q->x, q->y + half}, {q->x + len, q->y + half}, {q->x + half, q->y},
                                      {q->x + half, q->y + len}};
    for (int f = 0; f < 4; ++f) {
      const LO m = points.find(mid[f][0], mid[f][1]);
      if (m < 0) continue;
      std::array<LO, 2> faceEnds;
      for (int k = 0; k < 2; ++k) {  // a ghost's face ends may be new points (no local cell touches the far one)
        const int c = p4est_face_corners[f][k];
        faceEnds[k] = local ? cornerPoint[4 * e + c] : point(q->x + ((c & 1) ? len : 0), q->y + ((c & 2) ? len : 0));
      }
      if (ends.size() < static_cast<size_t>(numPoints)) ends.resize(numPoints, {-1, -1});
      ends[m] = faceEnds;
    }
  }
  ends.resize(numPoints, {-1, -1});
  // The owner of every regular point (several ranks).
  std::vector<int> owner(size > 1 ? numPoints : 0, rank);
  if (size > 1)
    for (LO p = 0; p < numPoints; ++p) {
      if (ends[p][0] >= 0) continue;
      p4est_quadrant_t q;
      P4EST_QUADRANT_INIT(&q);
      q.level = P4EST_QMAXLEVEL;
      const p4est_qcoord_t last = P4EST_ROOT_LEN - P4EST_QUADRANT_LEN(P4EST_QMAXLEVEL);  // the last valid position
      q.x = std::min(coords[p][0], last);
      q.y = std::min(coords[p][1], last);
      owner[p] = p4est_comm_find_owner(p4est, 0, &q, rank);
    }
  auto ownerOf = [&](LO p) { return size > 1 ? owner[p] : rank; };
  std::vector<LO> node(numPoints, -1);
  CornerNumbering out;
  for (size_t k = 0; k < 4 * numCells; ++k) {  // own points in first touch order
    const LO p = cornerPoint[k];
    if (ends[p][0] < 0 && ownerOf(p) == rank && node[p] < 0) node[p] = out.owned++;
  }
  long long first = 0, owned = out.owned;
  if (size > 1) MPI_Exscan(&owned, &first, 1, MPI_LONG_LONG, MPI_SUM, p4est->mpicomm);
  if (rank == 0) first = 0;  // MPI_Exscan leaves rank 0's result undefined
  out.gids.resize(out.owned);
  for (LO i = 0; i < out.owned; ++i) out.gids[i] = static_cast<GO>(first + i);
  if (size > 1) {  // the global ids of the other regular points, from their owners
    std::vector<int> sendOff(size + 1, 0);  // in points
    std::vector<LO> asked;                   // points in the order of the requests
    for (LO p = 0; p < numPoints; ++p)
      if (ends[p][0] < 0 && owner[p] != rank) ++sendOff[owner[p] + 1], asked.push_back(p);
    std::stable_sort(asked.begin(), asked.end(), [&](LO a, LO b) { return owner[a] < owner[b]; });
    for (int r = 0; r < size; ++r) sendOff[r + 1] += sendOff[r];
    std::vector<int> coordinateOff(sendOff);
    for (int& o : coordinateOff) o *= 2;
    std::vector<p4est_qcoord_t> request(2 * asked.size());
    for (size_t j = 0; j < asked.size(); ++j) request[2 * j] = coords[asked[j]][0], request[2 * j + 1] = coords[asked[j]][1];
    const auto received = core::exchange(p4est->mpicomm, request, coordinateOff);
    std::vector<long long> answer(received.values.size() / 2);
    for (size_t j = 0; j < answer.size(); ++j) {
      const LO p = points.find(received.values[2 * j], received.values[2 * j + 1]);
      SIGNORINI_ASSERT(p >= 0 && node[p] >= 0, "a rank asked for a point this rank does not own");
      answer[j] = first + node[p];
    }
    std::vector<int> answerOff(received.offsets);
    for (int& o : answerOff) o /= 2;
    const std::vector<long long> reply = core::exchange(p4est->mpicomm, answer, answerOff).values;  // in request order
    std::vector<size_t> byGid(asked.size());  // the other points follow the own ones in global order
    for (size_t j = 0; j < asked.size(); ++j) byGid[j] = j;
    std::sort(byGid.begin(), byGid.end(), [&](size_t a, size_t b) { return reply[a] < reply[b]; });
    for (const size_t j : byGid) {
      node[asked[j]] = static_cast<LO>(out.gids.size());
      out.gids.push_back(static_cast<GO>(reply[j]));
    }
  }
  out.corner.resize(4 * numCells);
  for (size_t k = 0; k < 4 * numCells; ++k) {
    const LO p = cornerPoint[k];
    if (ends[p][0] < 0) {
      out.corner[k] = {node[p], -1};
    } else {
      out.corner[k] = {node[ends[p][0]], node[ends[p][1]]};
      SIGNORINI_ASSERT(out.corner[k][0] >= 0 && out.corner[k][1] >= 0, "hanging node on a hanging face (forest not 2:1 balanced)");
    }
  }
  return out;
}

}  // namespace

Q1Mesh::Q1Mesh(const Forest& forest, const BoundarySegments& segments, RCP<const Comm> comm, Numbering how)
    : comm_(comm) {
  p4est_t* p4est = forest.p4est();
  const CoarseMesh& coarse = forest.coarse();
  const bool direct = how != Numbering::lnodes && isolatedSingleTree(*p4est->connectivity);
  SIGNORINI_ASSERT(direct || how != Numbering::direct, "the direct Q1 numbering needs one tree joined to nothing");
  numbering_ = direct ? Numbering::direct : Numbering::lnodes;
  const CornerNumbering numbering = direct ? numberOneTree(p4est) : numberWithLnodes(p4est);

  // Maps: owned nodes are contiguous by rank; overlap = owned then nonlocal.
  const LO numLocalNodes = static_cast<LO>(numbering.gids.size()), owned = numbering.owned;
  const auto& gids = numbering.gids;
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  // A contiguous map (Amesos2 and MueLu's coarse solver need one).
  ownedMap_ = Teuchos::rcp(new Map(invalid, static_cast<size_t>(owned), 0, comm));
  SIGNORINI_ASSERT(owned == 0 || ownedMap_->getMinGlobalIndex() == gids[0], "owned nodes are not contiguous");
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
        const auto& nodes = numbering.corner[4 * e + c];
        const bool hanging = nodes[1] >= 0;  // the value is the mean of the face's end nodes
        cornerDofsHost(e, c, 0) = nodes[0];
        cornerWeightsHost(e, c, 0) = hanging ? 0.5 : 1.0;
        cornerDofsHost(e, c, 1) = nodes[1];
        cornerWeightsHost(e, c, 1) = hanging ? 0.5 : 0.0;
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
        be.tree = static_cast<int>(t);
        be.quadrantLevel = q->level;
        be.faceIndex = (f < 2 ? q->y : q->x) / len;
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

}

LO Q1Mesh::locate(double x, double y, double& s, double& r) const {
  for (LO e = 0; e < numCells_; ++e)
    if (cellContains(e, x, y, s, r)) return e;
  return -1;
}

std::vector<Q1Mesh::CellPoint> Q1Mesh::locateAll(double x, double y) const {
  std::vector<CellPoint> found;
  double s, r;
  for (LO e = 0; e < numCells_; ++e)
    if (cellContains(e, x, y, s, r)) found.push_back({e, s, r});
  return found;
}

bool Q1Mesh::cellContains(LO e, double x, double y, double& s, double& r) const {
  const auto& X = cornerCoordsHost;
  const double tol = 1e-10;
  {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    double Xe[4][2];
    for (int c = 0; c < 4; ++c)
      for (int d = 0; d < 2; ++d) {
        Xe[c][d] = X(e, c, d);
        lo[d] = std::min(lo[d], Xe[c][d]), hi[d] = std::max(hi[d], Xe[c][d]);
      }
    const double pad = 1e-9 * (hi[0] - lo[0] + hi[1] - lo[1]);
    if (x < lo[0] - pad || x > hi[0] + pad || y < lo[1] - pad || y > hi[1] + pad) return false;
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
    return s >= -tol && s <= 1 + tol && r >= -tol && r <= 1 + tol;
  }
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

std::array<long long, 2> Q1Mesh::canonicalKey(LO node) const {
  const double grid = hMin_ / 64;
  const auto& x = nodeCoords_[node];
  return {std::llround(x[0] / grid), std::llround(x[1] / grid)};
}

}  // namespace signorini::mesh
