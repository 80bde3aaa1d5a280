#pragma once
/// \file CoarseMesh.hpp
/// The coarse mesh every adaptive mesh refines: a p4est connectivity (one tree per coarse
/// quadrilateral), the bilinear geometry of each tree, and named boundary sets of tree faces.
#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <p4est_connectivity.h>

#include "signorini/core/ParameterTools.hpp"

namespace signorini::mesh {

/// Coarse mesh from the deck's "Mesh" sublist: (a) a rectangle of nx x ny cells with the side
/// sets "left", "right", "bottom", "top", or (b) an Exodus II file of QUAD4 cells and named side
/// sets. Owns the p4est connectivity. Tree corners use p4est's z-order (0:(0,0) 1:(1,0) 2:(0,1) 3:(1,1)).
class CoarseMesh {
 public:
  /// Valid "Mesh" parameters (type, extent, cells, file, refinement level, boundary segments).
  static core::ParameterList getValidParameters();
  /// Builds the coarse mesh from a validated "Mesh" sublist. Throws core::UserError for an
  /// unreadable file or an inverted cell.
  static std::shared_ptr<CoarseMesh> create(const core::ParameterList& meshParams);
  /// A rectangle [x0,x1] x [y0,y1] of cellsX x cellsY cells. Blocks of 2^o x 2^o cells form one
  /// p4est tree (o = levelOffset(), the largest o <= kMaxLevelOffset with 2^o dividing cellsX and
  /// cellsY): p4est's work at tree boundaries (face and corner transforms) is then spent only where
  /// it must be.
  static std::shared_ptr<CoarseMesh> rectangle(double x0, double x1, double y0, double y1, int cellsX, int cellsY);
  /// Largest level offset of a rectangle: the user's levels (Refinement Level <= 18, Maximum Level
  /// <= 25) plus the offset stay within p4est's P4EST_QMAXLEVEL = 29.
  static constexpr int kMaxLevelOffset = 4;
  /// A coarse mesh of counter-clockwise quadrilaterals (vertex ids into \p x, \p y) with side sets
  /// of (cell, side) pairs, side s joining corners s and s+1. Throws core::UserError naming
  /// \p source and the cell or vertex for a coordinate that is not a number, an inverted cell, a
  /// cell that is not convex (a corner of 180 degrees or more, a side of length zero: its bilinear
  /// map is not invertible) and a hanging node (a mesh that is not conforming).
  static std::shared_ptr<CoarseMesh> fromQuads(const std::vector<double>& x, const std::vector<double>& y,
                                               const std::vector<std::array<int, 4>>& quadsCcw,
                                               const std::map<std::string, std::vector<std::array<int, 2>>>& sideSets,
                                               const std::string& source);

  ~CoarseMesh();
  CoarseMesh(const CoarseMesh&) = delete;
  CoarseMesh& operator=(const CoarseMesh&) = delete;

  /// The p4est connectivity, owned by the coarse mesh (destroyed with it; forests share it).
  p4est_connectivity_t* connectivity() const { return conn_; }
  /// Number of p4est trees.
  int numTrees() const { return static_cast<int>(treeCorners_.size()); }
  /// Physical corner c (z-order) of tree t.
  const std::array<double, 2>& treeCorner(int t, int c) const { return treeCorners_[t][c]; }
  /// Physical point of reference coordinates (s, r) in [0,1]^2 of tree t (bilinear map).
  std::array<double, 2> mapPoint(int t, double s, double r) const;
  /// det of the Jacobian of the tree map at (s, r): physical area per reference area.
  double jacobianDeterminant(int t, double s, double r) const;
  /// Names of the side sets containing face f (0:-x 1:+x 2:-y 3:+y) of tree t.
  const std::vector<std::string>& faceSets(int t, int f) const { return faceSets_[t][f]; }
  /// All side set names, for messages.
  std::vector<std::string> setNames() const;
  /// True if a tree face belongs to the side set \p name.
  bool hasSet(const std::string& name) const;
  /// A warning for the user when vertices of different cells lie at one point (a crack: the forest
  /// leaves the cells unconnected there, as a mesh whose nodes were not merged would); else "".
  const std::string& crackNote() const { return crackNote_; }
  /// A warning for the user when side sets list sides between two cells (not on the boundary: a
  /// boundary segment cannot take them, so they are left out); else "".
  const std::string& interiorSidesNote() const { return interiorSidesNote_; }
  /// Whether the mesh file has a side set of this name without any side (hasSet is false for it).
  bool isEmptySet(const std::string& name) const { return emptySets_.count(name) > 0; }
  /// Where the mesh came from, for messages ("rectangle 16x16" or the file name).
  const std::string& source() const { return source_; }
  /// Bounding box diameter (length units).
  double diameter() const;
  /// p4est level of the coarse cells: a cell of (user) refinement level l is a quadrant of level
  /// l + levelOffset() (0 unless a rectangle's trees hold several coarse cells).
  int levelOffset() const { return levelOffset_; }

 private:
  CoarseMesh() = default;
  p4est_connectivity_t* conn_ = nullptr;
  std::vector<std::array<std::array<double, 2>, 4>> treeCorners_;
  std::vector<std::array<std::vector<std::string>, 4>> faceSets_;
  std::set<std::string> emptySets_;
  std::string crackNote_;
  std::string interiorSidesNote_;
  std::string source_;
  int levelOffset_ = 0;
};

}  // namespace signorini::mesh
