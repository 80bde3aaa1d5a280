#pragma once
/// Helpers shared by the tests: small meshes, with and without hanging nodes.
#include <cmath>
#include <functional>
#include <memory>

#include <Tpetra_Core.hpp>

#include "signorini/mesh/BoundarySegments.hpp"
#include "signorini/mesh/CoarseMesh.hpp"
#include "signorini/mesh/Forest.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::test {

/// Refines, `times` times, the cells of tree 0 whose closure contains the point (s, r) of the
/// tree's reference square (not balanced).
inline void refineAt(mesh::Forest& f, double s, double r, int times) {
  for (int i = 0; i < times; ++i)
    f.refineIf([&](int tree, const p4est_quadrant_t& q) {
      const double len = static_cast<double>(P4EST_QUADRANT_LEN(q.level)) / P4EST_ROOT_LEN;
      const double x = q.x / static_cast<double>(P4EST_ROOT_LEN), y = q.y / static_cast<double>(P4EST_ROOT_LEN);
      return tree == 0 && s >= x && s <= x + len && r >= y && r <= y + len;
    });
}

/// Refines, once, the cells of \p f whose centre (in physical coordinates) satisfies \p where, then balances.
inline void refineWhere(mesh::Forest& f, const mesh::CoarseMesh& coarse, const std::function<bool(double, double)>& where) {
  f.refineIf([&](int tree, const p4est_quadrant_t& q) {
    const double root = P4EST_ROOT_LEN, half = 0.5 * P4EST_QUADRANT_LEN(q.level);
    const auto p = coarse.mapPoint(tree, (q.x + half) / root, (q.y + half) / root);
    return where(p[0], p[1]);
  });
  f.balance();
}

/// A forest on the rectangle with segments "left", "right", "bottom", "top" (one per side).
struct TestMesh {
  RCP<const Comm> comm = Tpetra::getDefaultComm();
  std::shared_ptr<mesh::CoarseMesh> coarse;
  std::unique_ptr<mesh::BoundarySegments> segments;
  std::unique_ptr<mesh::Forest> forest;
  std::unique_ptr<mesh::Q1Mesh> mesh;

  /// On \p comm (all ranks by default; MPI_COMM_SELF gives every rank the whole mesh).
  TestMesh(double x0, double x1, double y0, double y1, int nx, int ny, int level,
           RCP<const Comm> onComm = Tpetra::getDefaultComm())
      : comm(std::move(onComm)) {
    coarse = mesh::CoarseMesh::rectangle(x0, x1, y0, y1, nx, ny);
    segments = std::make_unique<mesh::BoundarySegments>(
        std::vector<std::pair<std::string, std::string>>{{"left", "left"}, {"right", "right"}, {"bottom", "bottom"}, {"top", "top"}},
        *coarse);
    forest = std::make_unique<mesh::Forest>(coarse, core::rawMpiComm(*comm), level);
  }
  /// A forest on any coarse mesh, with the given segments (name, specification).
  TestMesh(std::shared_ptr<mesh::CoarseMesh> coarseMesh,
           const std::vector<std::pair<std::string, std::string>>& segmentSpecs, int level,
           RCP<const Comm> onComm = Tpetra::getDefaultComm())
      : comm(std::move(onComm)), coarse(std::move(coarseMesh)) {
    segments = std::make_unique<mesh::BoundarySegments>(segmentSpecs, *coarse);
    forest = std::make_unique<mesh::Forest>(coarse, core::rawMpiComm(*comm), level);
  }
  /// Refines the cells whose reference lower-left corner lies in the lower-left quarter of tree 0
  /// twice (then balances and partitions): hanging nodes on several edges.
  void refineCorner() {
    for (int pass = 0; pass < 2; ++pass) {
      forest->refineIf([](int tree, const p4est_quadrant_t& q) {
        return tree == 0 && q.x < P4EST_ROOT_LEN / 2 && q.y < P4EST_ROOT_LEN / 2;
      });
      forest->balance();
    }
    forest->partition();
  }
  /// Refines tree 0 deeply inside (four times around (0.4, 0.6)) and at a corner (three times at
  /// (0.999, 0.001)), then balances (no partition): hanging nodes on faces of all four
  /// orientations, at three levels.
  void refineGraded() {
    refineAt(*forest, 0.4, 0.6, 4);
    refineAt(*forest, 0.999, 0.001, 3);
    forest->balance();
  }
  /// Refines the cells whose centre lies within \p radius of (px, py), then balances; \p passes times.
  void refineWithin(double px, double py, double radius, int passes) {
    for (int pass = 0; pass < passes; ++pass) {
      forest->refineIf([&](int tree, const p4est_quadrant_t& q) {
        const double len = static_cast<double>(P4EST_QUADRANT_LEN(q.level)) / P4EST_ROOT_LEN;
        const auto c = coarse->mapPoint(tree, q.x / static_cast<double>(P4EST_ROOT_LEN) + 0.5 * len,
                                        q.y / static_cast<double>(P4EST_ROOT_LEN) + 0.5 * len);
        return std::hypot(c[0] - px, c[1] - py) < radius;
      });
      forest->balance();
    }
  }
  const mesh::Q1Mesh& build() {
    mesh = std::make_unique<mesh::Q1Mesh>(*forest, *segments, comm);
    return *mesh;
  }
};

/// Sets core::reproducibleArithmetic() for its lifetime (off again afterwards, also on a throw).
struct ReproducibleScope {
  explicit ReproducibleScope(bool on) { core::setReproducibleArithmetic(on); }
  ~ReproducibleScope() { core::setReproducibleArithmetic(false); }
  ReproducibleScope(const ReproducibleScope&) = delete;
  ReproducibleScope& operator=(const ReproducibleScope&) = delete;
};

}  // namespace signorini::test
