#pragma once
/// \file BoundarySegments.hpp
/// Named boundary segments of the deck's "Mesh/Boundary Segments" sublist (BoundarySegments).
#include <string>
#include <utility>
#include <vector>

#include "signorini/mesh/CoarseMesh.hpp"

namespace signorini::mesh {

/// Named boundary segments: a side set of the coarse mesh restricted by coordinate ranges, e.g. "bottom, x >= 0.15",
/// tested at the midpoint of each fine boundary edge. Segment i is bit i of a segment mask (at most 32 segments).
/// Keeps no reference to the coarse mesh.
class BoundarySegments {
 public:
  /// Parses the "Mesh/Boundary Segments" sublist. Throws core::UserError naming the key for a
  /// spec that does not parse or a side set the mesh does not have (listing the ones it has).
  BoundarySegments(const core::ParameterList& namedSpecs, const CoarseMesh& coarse);
  /// Segments with the given (name, spec) pairs.
  BoundarySegments(const std::vector<std::pair<std::string, std::string>>& specs, const CoarseMesh& coarse);

  /// Number of segments.
  int size() const { return static_cast<int>(segments_.size()); }
  /// Name of segment \p i (its key in the sublist).
  const std::string& name(int i) const { return segments_[i].name; }
  /// Index of the named segment; throws core::UserError naming \p key and the closest name.
  int index(const std::string& name, const std::string& key) const;
  /// Bit mask of the segments that contain the fine edge on face f of tree t with midpoint (mx, my).
  unsigned match(const CoarseMesh& coarse, int tree, int face, double mx, double my) const;

 private:
  struct Condition {
    int coord;   // 0: x, 1: y
    int op;      // 0: >=, 1: <=, 2: >, 3: <
    double value;
  };
  struct Segment {
    std::string name, set;
    std::vector<Condition> conditions;
  };
  void add(const std::string& name, const std::string& spec, const CoarseMesh& coarse);
  std::vector<Segment> segments_;
};

}  // namespace signorini::mesh
