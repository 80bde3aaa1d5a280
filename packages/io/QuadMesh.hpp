#pragma once
/// \file QuadMesh.hpp
/// Exodus II input: coarse QUAD4 meshes with named side sets. Serial: the caller reads on one
/// rank and distributes.
#include <array>
#include <map>
#include <string>
#include <vector>

namespace signorini::io {

/// A 2D quadrilateral mesh as read from or written to Exodus II.
struct QuadMesh {
  std::vector<double> x, y;                ///< vertex coordinates (length units of the deck)
  std::vector<std::array<int, 4>> quads;   ///< 0-based vertex ids, counter-clockwise (Exodus QUAD4 order)
  /// Named side sets: name -> list of (quad index, local side s), side s joins vertices s and (s+1)%4
  /// (Exodus side numbering minus one).
  std::map<std::string, std::vector<std::array<int, 2>>> sideSets;
};

/// Reads the coarse mesh of an Exodus II file: all element blocks must be QUAD4 (or QUAD),
/// side sets keep their names (unnamed ones become "sideset_<id>").
/// Clockwise quads are reversed to counter-clockwise order (their sides renumbered to match).
/// Throws core::UserError naming the file for a missing/unreadable file, a non-quad block,
/// a 3D mesh (three coordinates are taken when z is one value: a plane z = const), a mesh without
/// elements, a zero-area quad or an invalid side-set entry.
QuadMesh readExodusQuadMesh(const std::string& path);

}  // namespace signorini::io
