#pragma once
/// \file EstimatorTools.hpp
/// Pieces the residual estimators share (internal to the estimate package): quadrature, cell and
/// face geometry, the positive-part integral of s0, and the iteration over the interior faces of
/// a forest with p4est's face ghost layer (hanging faces split into their fine edges).
#include <algorithm>
#include <utility>
#include <cmath>
#include <vector>

#include <p4est_ghost.h>
#include <p4est_iterate.h>
#include <Teuchos_CommHelpers.hpp>

#include "signorini/mesh/CoordinateTable.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/estimate/ResidualEstimator.hpp"
#include "signorini/core/Expression.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::estimate {

/// 3-point Gauss rule on [0,1] (exact for quintics).
inline constexpr const auto& kG3 = fem::kGauss3Point;
inline constexpr const auto& kW3 = fem::kGauss3Weight;  ///< weights of kG3 (sum 1)

/// Longest diagonal of a cell (h_K).
KOKKOS_INLINE_FUNCTION double cellDiameter(const double X[4][2]) {
  const double d0 = (X[3][0] - X[0][0]) * (X[3][0] - X[0][0]) + (X[3][1] - X[0][1]) * (X[3][1] - X[0][1]);
  const double d1 = (X[2][0] - X[1][0]) * (X[2][0] - X[1][0]) + (X[2][1] - X[1][1]) * (X[2][1] - X[1][1]);
  return Kokkos::Experimental::sqrt(d0 > d1 ? d0 : d1);
}

/// Second derivatives (u_xx, u_yy, u_xy) of the bilinear (isoparametric Q1) field with corner
/// values u on the cell with corners X (z-order) at the reference point (s, r).
///
/// With the map x(s, r) = sum_c X_c N_c and J = dx/d(s,r), the chain rule gives for the reference
/// Hessian H_ref(u) = J^T H(u) J + sum_i u_{x_i} H_ref(x_i). For bilinear u and x only the mixed
/// derivatives are non-zero: u_sr = u0 - u1 - u2 + u3 and x_sr = X0 - X1 - X2 + X3, so
/// J^T H(u) J = [[0, m], [m, 0]] with m = u_sr - grad(u) . x_sr, and H(u) = m (grad s (x) grad r +
/// grad r (x) grad s). On axis-parallel rectangles only u_xy = m / (h_x h_y) remains; for the linear
/// fields the space contains m = 0 on every cell.
KOKKOS_INLINE_FUNCTION void q1Hessian(const double X[4][2], const double u[4], double s, double r, double H[3]) {
  double N[4], dNds[4], dNdr[4];
  fem::q1Shape(s, r, N, dNds, dNdr);
  double a0 = 0, a1 = 0, b0 = 0, b1 = 0;  // a = x_s, b = x_r
  for (int c = 0; c < 4; ++c) {
    a0 += X[c][0] * dNds[c];
    a1 += X[c][1] * dNds[c];
    b0 += X[c][0] * dNdr[c];
    b1 += X[c][1] * dNdr[c];
  }
  const double det = a0 * b1 - b0 * a1;
  double us = 0, ur = 0;
  for (int c = 0; c < 4; ++c) us += u[c] * dNds[c], ur += u[c] * dNdr[c];
  const double ux = (b1 * us - a1 * ur) / det, uy = (-b0 * us + a0 * ur) / det;
  const double usr = u[0] - u[1] - u[2] + u[3];
  const double xsr0 = X[0][0] - X[1][0] - X[2][0] + X[3][0], xsr1 = X[0][1] - X[1][1] - X[2][1] + X[3][1];
  const double m = usr - ux * xsr0 - uy * xsr1;
  const double sx = b1 / det, sy = -b0 / det, rx = -a1 / det, ry = a0 / det;  // grad s, grad r
  H[0] = 2 * m * sx * rx;
  H[1] = 2 * m * sy * ry;
  H[2] = m * (sx * ry + rx * sy);
}

/// Reference point of face f (0:-x 1:+x 2:-y 3:+y) at parameter tau, which runs from corner
/// p4est_face_corners[f][0] (tau = 0) to p4est_face_corners[f][1] (tau = 1).
inline void faceReference(int f, double tau, double& s, double& r) {
  if (f < 2) {
    s = f == 0 ? 0.0 : 1.0;
    r = tau;
  } else {
    s = tau;
    r = f == 2 ? 0.0 : 1.0;
  }
}

/// Unit outward normal of (straight) face f of the cell with corners X.
inline void outwardNormal(const double X[4][2], int f, double n[2]) {
  const double* p0 = X[p4est_face_corners[f][0]];
  const double* p1 = X[p4est_face_corners[f][1]];
  const double tx = p1[0] - p0[0], ty = p1[1] - p0[1], len = std::hypot(tx, ty);
  n[0] = ty / len;
  n[1] = -tx / len;
  double cx = 0, cy = 0;
  for (int k = 0; k < 4; ++k) cx += 0.25 * X[k][0], cy += 0.25 * X[k][1];
  if (n[0] * (0.5 * (p0[0] + p1[0]) - cx) + n[1] * (0.5 * (p0[1] + p1[1]) - cy) < 0) n[0] = -n[0], n[1] = -n[1];
}

/// int_K w^2 dx for the bilinear field w with corner values w (z-order) on the parallelogram K of
/// area \p area (exact: the Q1 element mass matrix).
KOKKOS_INLINE_FUNCTION double bilinearSquareIntegral(const double w[4], double area) {
  double sum = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) sum += w[a] * fem::q1Mass36(a, b) * w[b];
  return area / 36 * sum;
}

/// int_0^1 j(tau)^2 dtau for the linear j with j(0) = j0, j(1) = j1 (exact).
inline double squareOfLinearIntegral(double j0, double j1) { return (j0 * j0 + j0 * j1 + j1 * j1) / 3; }

/// Parameter tau of the physical point P on face f of the cell with corners X (orthogonal projection).
inline double faceParameter(const double X[4][2], int f, const double P[2]) {
  const double* p0 = X[p4est_face_corners[f][0]];
  const double* p1 = X[p4est_face_corners[f][1]];
  const double tx = p1[0] - p0[0], ty = p1[1] - p0[1];
  return ((P[0] - p0[0]) * tx + (P[1] - p0[1]) * ty) / (tx * tx + ty * ty);
}

/// int_0^1 max(d(tau), 0) dtau for a function d on [0, 1] (the edge parameter): four pieces, each
/// split at a sign change of d (regula falsi, then Illinois steps: exact in one step for linear d),
/// 3-point Gauss on every part. Exact when d is linear (g linear along the edge).
template <class F>
double positivePartIntegral(const F& d) {
  constexpr int pieces = 4;
  auto gauss = [&](double a, double b) {
    double s = 0;
    for (int g = 0; g < 3; ++g) s += kW3[g] * std::max(d(a + kG3[g] * (b - a)), 0.0);
    return (b - a) * s;
  };
  double total = 0;
  for (int p = 0; p < pieces; ++p) {
    double a = static_cast<double>(p) / pieces, b = static_cast<double>(p + 1) / pieces;
    double da = d(a), db = d(b);
    if ((da > 0 && db < 0) || (da < 0 && db > 0)) {
      const double a0 = a, b0 = b;
      const bool positiveLeft = da > 0;
      double root = a - da * (b - a) / (db - da);
      for (int it = 0, side = 0; it < 100; ++it) {
        const double dr = d(root);
        if (dr == 0.0 || b - a < 1e-15) break;
        if ((dr > 0) == (da > 0)) {
          a = root, da = dr;
          if (side == -1) db *= 0.5;
          side = -1;
        } else {
          b = root, db = dr;
          if (side == 1) da *= 0.5;
          side = 1;
        }
        const double next = a - da * (b - a) / (db - da);
        if (std::abs(next - root) <= 1e-15) {
          root = next;
          break;
        }
        root = next;
      }
      total += positiveLeft ? gauss(a0, root) : gauss(root, b0);
    } else {
      total += gauss(a, b);  // one sign at the ends; interior bumps are caught by the Gauss points
    }
  }
  return total;
}

/// int_0^1 (g - w)_+ dtau along a boundary edge (tau from be.x[0] to be.x[1]) for w linear between
/// its end values w0, w1: times lambda_j |E| the edge's share of s0^2.
inline double positivePartAlongEdge(const mesh::BoundaryEdge& be, const core::Expression& g, double t, double w0,
                                    double w1) {
  return positivePartIntegral([&](double tau) {
    const double x = be.x[0][0] + tau * (be.x[1][0] - be.x[0][0]);
    const double y = be.x[0][1] + tau * (be.x[1][1] - be.x[0][1]);
    return g(x, y, t) - ((1 - tau) * w0 + tau * w1);
  });
}

/// One cell on one side of a face: its payload, its local index (-1 for a ghost) and its face.
template <class Payload>
struct FaceSide {
  const Payload* data;  ///< the cell's payload (not owned)
  LO local;             ///< local cell index; -1 for a ghost
  int face;             ///< p4est face of the cell: 0:-x 1:+x 2:-y 3:+y
};

namespace detail {
/// The user data of p4est_iterate's face callback in forEachInteriorFace: pointers (not owned) to the payloads of
/// the local cells and of the face ghosts, and to the function called for each pair of cells across a fine edge.
template <class Payload, class OnPair>
struct FaceIteration {
  const std::vector<Payload>* local;   ///< payloads of the local cells (local cell order)
  const std::vector<Payload>* ghosts;  ///< payloads of the face ghost layer (ghost order)
  OnPair* onPair;                      ///< called as onPair(A, B), see forEachInteriorFace

  /// The FaceSide of cell \p quadid of tree \p tree (a ghost index if \p isGhost).
  FaceSide<Payload> side(p4est_t* p4est, p4est_topidx_t tree, int face, int8_t isGhost, p4est_locidx_t quadid) const {
    if (isGhost) {
      SIGNORINI_ASSERT(quadid >= 0 && static_cast<size_t>(quadid) < ghosts->size(),
                       "face neighbour missing from the ghost layer");
      return {&(*ghosts)[quadid], -1, face};
    }
    const p4est_tree_t* t = p4est_tree_array_index(p4est->trees, tree);
    const LO e = static_cast<LO>(t->quadrants_offset + quadid);
    return {&(*local)[e], e, face};
  }

  /// The p4est_iter_face_t callback (\p user: a FaceIteration): skips boundary faces, splits 2:1 faces.
  static void callback(p4est_iter_face_info_t* info, void* user) {
    const auto& it = *static_cast<const FaceIteration*>(user);
    if (info->sides.elem_count != 2) return;  // domain boundary: from Q1Mesh::boundaryEdges()
    const auto* s0 = static_cast<const p4est_iter_face_side_t*>(sc_array_index(&info->sides, 0));
    const auto* s1 = static_cast<const p4est_iter_face_side_t*>(sc_array_index(&info->sides, 1));
    p4est_t* p4est = info->p4est;
    if (!s0->is_hanging && !s1->is_hanging) {
      (*it.onPair)(it.side(p4est, s0->treeid, s0->face, s0->is.full.is_ghost, s0->is.full.quadid),
                   it.side(p4est, s1->treeid, s1->face, s1->is.full.is_ghost, s1->is.full.quadid));
      return;
    }
    // 2:1 face: two half-size cells on one side, one full cell on the other (never both in 2D).
    const auto* fine = s0->is_hanging ? s0 : s1;
    const auto* coarse = s0->is_hanging ? s1 : s0;
    SIGNORINI_ASSERT(!coarse->is_hanging, "both sides of a face are hanging");
    const auto big = it.side(p4est, coarse->treeid, coarse->face, coarse->is.full.is_ghost, coarse->is.full.quadid);
    for (int i = 0; i < 2; ++i) {
      if (fine->is.hanging.quadid[i] < 0) continue;  // not in the ghost layer: touches no local cell here
      (*it.onPair)(it.side(p4est, fine->treeid, fine->face, fine->is.hanging.is_ghost[i], fine->is.hanging.quadid[i]),
                   big);
    }
  }
};
}  // namespace detail

/// How forEachInteriorFace finds the faces: p4est_iterate over a face ghost layer always, or
/// (automatic) on a forest of one tree a walk over the +x and +y faces of every local and ghost
/// cell with a table of the cells' lower-left corners (the same pairs without p4est's general
/// iteration).
enum class FaceWalk { automatic, p4est };

namespace detail {
/// The faces of a 2:1 balanced forest of one tree that touch a local cell: each interior face is
/// the +x or +y face of the cell on its lower side, whose neighbour there has the same size, is one
/// of two finer cells or is one level coarser. \p ghostQuadrants (the face ghost layer, one tree;
/// nullptr on one rank, with \p ghosts empty) and their \p ghosts' payloads join the local cells;
/// a pair is passed on when one of its cells is local. A local cell's neighbours are all local or
/// ghosts. A ghost's neighbour missing from the table is neither, so that face has no local side
/// and is not needed.
template <class Payload, class OnPair>
void walkOneTree(p4est_t* p4est, const std::vector<Payload>& local, const sc_array_t* ghostQuadrants,
                 const std::vector<Payload>& ghosts, OnPair& onPair) {
  p4est_tree_t* tree = p4est_tree_array_index(p4est->trees, 0);
  const LO n = static_cast<LO>(tree->quadrants.elem_count);
  const LO all = n + static_cast<LO>(ghosts.size());
  auto quadrant = [&](LO e) {
    return e < n ? p4est_quadrant_array_index(&tree->quadrants, static_cast<size_t>(e))
                 : p4est_quadrant_array_index(const_cast<sc_array_t*>(ghostQuadrants), static_cast<size_t>(e - n));
  };
  mesh::CoordinateTable cells(static_cast<size_t>(all));
  for (LO e = 0; e < all; ++e) cells.insert(quadrant(e)->x, quadrant(e)->y, e);
  auto side = [&](LO e, int face) {
    return e < n ? FaceSide<Payload>{&local[e], e, face} : FaceSide<Payload>{&ghosts[e - n], -1, face};
  };
  auto pair = [&](LO a, int faceA, LO b, int faceB) {
    if (a < n || b < n) onPair(side(a, faceA), side(b, faceB));
  };
  for (LO e = 0; e < all; ++e) {
    const bool isLocal = e < n;
    const auto* q = quadrant(e);
    const p4est_qcoord_t len = P4EST_QUADRANT_LEN(q->level);
    for (int along = 0; along < 2; ++along) {  // along x: face 1 against the neighbour's face 0; along y: 3 against 2
      const int face = 2 * along + 1;
      const p4est_qcoord_t x = along == 0 ? q->x + len : q->x, y = along == 0 ? q->y : q->y + len;
      if (x >= P4EST_ROOT_LEN || y >= P4EST_ROOT_LEN) continue;  // domain boundary
      const LO m = cells.find(x, y);
      if (m >= 0 && quadrant(m)->level == q->level) {
        pair(e, face, m, face - 1);
      } else if (m >= 0 && quadrant(m)->level == q->level + 1) {  // two finer neighbours
        const LO m2 = cells.find(along == 0 ? x : x + len / 2, along == 0 ? y + len / 2 : y);
        const bool second = m2 >= 0 && quadrant(m2)->level == q->level + 1;
        SIGNORINI_ASSERT(!isLocal || second, "forest not 2:1 balanced next to the cell at (" << q->x << ", " << q->y
                                                                                              << "), level " << int(q->level));
        pair(m, face - 1, e, face);
        if (second) pair(m2, face - 1, e, face);
      } else if (m >= 0) {  // a coarser neighbour starting at the same point
        SIGNORINI_ASSERT(quadrant(m)->level == q->level - 1, "forest not 2:1 balanced at the cell at (" << q->x << ", "
                                                                                                        << q->y << ")");
        pair(e, face, m, face - 1);
      } else {  // a coarser neighbour starting half its size earlier; for a ghost it may be absent
                // from the table, and a cell of another level found there is not a neighbour
        const LO c = cells.find(along == 0 ? x : x - len, along == 0 ? y - len : y);
        SIGNORINI_ASSERT(!isLocal || (c >= 0 && quadrant(c)->level == q->level - 1),
                         "no face neighbour of the cell at (" << q->x << ", " << q->y << "), level " << int(q->level));
        if (c >= 0 && quadrant(c)->level == q->level - 1) pair(e, face, c, face - 1);
      }
    }
  }
}
}  // namespace detail

/// Calls onPair(A, B) for every interior face with a local cell on at least one side: A's face is
/// the whole fine edge, B the (equal or coarser) neighbour; a 2:1 face gives one call per fine
/// half. The payloads of the neighbours on other ranks come from p4est's face ghost layer;
/// onGhosts(ghosts) is called once they have arrived (with none on one rank).
template <class Payload, class OnGhosts, class OnPair>
void forEachInteriorFace(const mesh::Forest& forest, const std::vector<Payload>& local, OnGhosts onGhosts,
                         OnPair onPair, FaceWalk walk = FaceWalk::automatic) {
  p4est_t* p4est = forest.p4est();
  const bool direct = walk == FaceWalk::automatic && p4est->connectivity->num_trees == 1;
  if (direct && p4est->mpisize == 1) {
    const std::vector<Payload> none;
    onGhosts(none);
    detail::walkOneTree(p4est, local, nullptr, none, onPair);
    return;
  }
  p4est_ghost_t* ghost = p4est_ghost_new(p4est, P4EST_CONNECT_FACE);
  std::vector<Payload> ghosts(ghost->ghosts.elem_count);
  std::vector<void*> mirrors(ghost->mirrors.elem_count);
  for (size_t m = 0; m < mirrors.size(); ++m) {
    const auto* q = p4est_quadrant_array_index(&ghost->mirrors, m);
    mirrors[m] = const_cast<Payload*>(&local[q->p.piggy3.local_num]);
  }
  p4est_ghost_exchange_custom(p4est, ghost, sizeof(Payload), mirrors.data(), ghosts.data());
  onGhosts(ghosts);
  if (direct) {
    detail::walkOneTree(p4est, local, &ghost->ghosts, ghosts, onPair);
  } else {
    detail::FaceIteration<Payload, OnPair> it{&local, &ghosts, &onPair};
    p4est_iterate(p4est, ghost, &it, nullptr, &detail::FaceIteration<Payload, OnPair>::callback, nullptr);
  }
  p4est_ghost_destroy(ghost);
}

/// Per-cell sums of edge terms: added as they come, or under reproducible arithmetic collected and
/// added sorted by value, so that the order in which the faces are visited (another on every
/// partition) does not change the bits.
class CellSums {
 public:
  /// Sums for \p n cells, all 0; ordered when core::reproducibleArithmetic() is on now.
  explicit CellSums(size_t n) : sum_(n, 0.0), ordered_(core::reproducibleArithmetic()) {
    if (ordered_) terms_.resize(kSlots * n), count_.assign(n, 0);
  }
  /// Adds \p value to the sum of local cell \p cell.
  void add(LO cell, double value) {
    if (!ordered_) {
      sum_[cell] += value;
    } else if (count_[cell] < kSlots) {
      terms_[kSlots * cell + count_[cell]++] = value;
    } else {
      more_.emplace_back(cell, value);
    }
  }
  /// The sums (call once).
  std::vector<double>& finish() {
    if (!ordered_) return sum_;
    std::sort(more_.begin(), more_.end());  // by cell, then value
    size_t next = 0;
    std::vector<double> terms;
    for (size_t e = 0; e < sum_.size(); ++e) {
      terms.assign(terms_.begin() + kSlots * e, terms_.begin() + kSlots * e + count_[e]);
      for (; next < more_.size() && more_[next].first == static_cast<LO>(e); ++next) terms.push_back(more_[next].second);
      std::sort(terms.begin(), terms.end());
      for (double v : terms) sum_[e] += v;
    }
    return sum_;
  }

 private:
  /// Terms kept in place per cell (a cell has four faces, each with at most two neighbours); any
  /// further ones go to more_.
  static constexpr size_t kSlots = 8;
  std::vector<double> sum_;
  bool ordered_;
  std::vector<double> terms_;
  std::vector<unsigned char> count_;
  std::vector<std::pair<LO, double>> more_;
};

/// eta_*, s0 and the cell indicators eta_K^2 + (s0 share) from the per-cell parts (DESIGN 1.3),
/// eta_* and s0 summed over all ranks. \p volume(e) = h_K^2 ||r||^2_K, \p edgeTerm[e] = h_K ||R||^2_{dK};
/// \p s0Terms the local terms of s0^2 (the sum of these over all ranks).
template <class Volume>
EstimatorResult combineCellTerms(const Volume& volume, const std::vector<double>& edgeTerm,
                                 const std::vector<double>& s0Share, const std::vector<double>& s0Terms,
                                 const Comm& comm) {
  EstimatorResult res;
  res.cellIndicator.resize(edgeTerm.size());
  double etaLocal = 0, s0Local = 0;
  std::vector<double> etaK2(edgeTerm.size());
  for (size_t e = 0; e < edgeTerm.size(); ++e) {
    etaK2[e] = volume(e) + edgeTerm[e];
    etaLocal += etaK2[e];
    res.cellIndicator[e] = etaK2[e] + s0Share[e];
  }
  for (double v : s0Terms) s0Local += v;
  double local2[2] = {etaLocal, s0Local}, global2[2] = {0, 0};
  if (core::reproducibleArithmetic()) {
    global2[0] = core::reproducibleSum(comm, etaK2.size(), etaK2.data());
    global2[1] = core::reproducibleSum(comm, s0Terms.size(), s0Terms.data());
  } else {
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local2, global2);
  }
  res.etaStar = std::sqrt(std::max(global2[0], 0.0));
  res.s0 = std::sqrt(std::abs(global2[1]));
  res.cellEta2 = std::move(etaK2);
  return res;
}

/// The "physical" scaling of the estimate of the step equation: eta_* / s, s0 / sqrt(s), the cell
/// indicators term by term, s = beta k^2 kappa (kappa the stiffness: kappa [force / length] for the
/// scalar wave, lambda + 2 mu [force / area] in elasticity). The residual of the step equation
/// divided by beta k^2 is that of
/// rho u_tt - div(kappa grad u) = f; divided by kappa as well, eta_* estimates the error's gradient
/// and s0^2 = |<lambda, (g - u_h)_+>| / kappa the product of two displacements: eta_*, s0 and s1 all
/// come out in units of the displacement, independent of the units of force (DESIGN 1.3-1.4); s1
/// independent of the unit of length only with Estimator/S1 Length Scale a length of the problem.
inline void scaleToPhysical(EstimatorResult& res, const std::vector<double>& s0Share, double s) {
  res.etaStar /= s;
  res.s0 /= std::sqrt(s);
  for (size_t e = 0; e < res.cellIndicator.size(); ++e) {
    res.cellIndicator[e] = (res.cellIndicator[e] - s0Share[e]) / (s * s) + s0Share[e] / s;
    res.cellEta2[e] /= s * s;
  }
}

}  // namespace signorini::estimate
