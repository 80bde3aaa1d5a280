// A coarse mesh given as quadrilaterals (an Exodus file) is refused, naming the cell or vertex,
// when the forest cannot refine it: a hanging node, a cell that is not convex, a side of length
// zero, a coordinate that is not a number, a cell listed twice, a side of three cells. Conforming
// meshes of convex cells are taken, cracks (duplicate vertices) included, with a note.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "signorini/mesh/BoundarySegments.hpp"
#include "signorini/mesh/CoarseMesh.hpp"
#include "signorini/core/Error.hpp"

using namespace signorini;

namespace {

struct Quads {
  std::vector<double> x, y;
  std::vector<std::array<int, 4>> cells;
};

/// The message of the error fromQuads gives, or "" if it takes the mesh.
std::string errorOf(const Quads& q) {
  try {
    mesh::CoarseMesh::fromQuads(q.x, q.y, q.cells, {}, "mesh.exo");
  } catch (const core::UserError& e) {
    return e.what();
  }
  return "";
}

/// The unit square as 2 x 2 cells (vertices row by row).
Quads square2x2() {
  Quads q;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) q.x.push_back(0.5 * i), q.y.push_back(0.5 * j);
  q.cells = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
  return q;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(CoarseMesh, TakesConformingConvexCellsAndCracks) {
  const Quads square = square2x2();
  EXPECT_EQ(errorOf(square), "");
  EXPECT_EQ(mesh::CoarseMesh::fromQuads(square.x, square.y, square.cells, {}, "mesh.exo")->crackNote(), "");
  Quads distorted = square2x2();
  distorted.x[4] = 0.6, distorted.y[4] = 0.45;  // still convex
  EXPECT_EQ(errorOf(distorted), "");
  Quads crack = square2x2();  // the left cells' shared side split by duplicate vertices
  crack.x.push_back(0.0), crack.y.push_back(0.5);
  crack.x.push_back(0.5), crack.y.push_back(0.5);
  crack.cells[2] = {9, 10, 7, 6};
  crack.cells[3] = {10, 5, 8, 7};
  EXPECT_EQ(errorOf(crack), "");
  // Taken, with a note for the user: nodes that were not merged give the same mesh by mistake.
  const auto note = mesh::CoarseMesh::fromQuads(crack.x, crack.y, crack.cells, {}, "mesh.exo")->crackNote();
  EXPECT_TRUE(contains(note, "mesh.exo: vertices 4 and 10 are at one point (0, 0.5) (and 1 more such pairs): the "
                             "cells on either side are not connected there"))
      << note;
}

TEST(CoarseMesh, RefusesACellListedTwiceAndASideOfThreeCells) {
  Quads twice = square2x2();
  twice.cells.push_back({4, 5, 8, 7});  // cell 4 again, from another corner
  std::rotate(twice.cells.back().begin(), twice.cells.back().begin() + 1, twice.cells.back().end());
  EXPECT_TRUE(contains(errorOf(twice), "mesh.exo: cells 4 and 5 have the same vertices (a cell listed twice)"))
      << errorOf(twice);
  Quads three = square2x2();  // a fifth cell folded over the side from (0.5, 0.5) to (1, 0.5)
  three.x.push_back(0.75), three.y.push_back(0.25);
  three.x.push_back(1.0), three.y.push_back(0.25);
  three.cells.push_back({9, 10, 5, 4});
  EXPECT_TRUE(contains(errorOf(three), "belongs to more than two cells (cell 5 among them)")) << errorOf(three);
}

TEST(CoarseMesh, NamesAnEmptySideSetAsEmpty) {
  const Quads q = square2x2();
  const auto coarse = mesh::CoarseMesh::fromQuads(q.x, q.y, q.cells, {{"right", {}}, {"left", {{0, 3}, {2, 3}}}}, "mesh.exo");
  EXPECT_TRUE(coarse->isEmptySet("right"));
  EXPECT_FALSE(coarse->isEmptySet("left"));
  try {
    mesh::BoundarySegments segments(std::vector<std::pair<std::string, std::string>>{{"contact", "right"}}, *coarse);
    ADD_FAILURE() << "an empty side set was taken";
  } catch (const core::UserError& e) {
    EXPECT_TRUE(contains(e.what(), "Mesh/Boundary Segments/contact: side set 'right' in mesh.exo is empty")) << e.what();
  }
}

TEST(CoarseMesh, RefusesAHangingNodeNamingTheSide) {
  // One cell on the left half beside two on the right: (0.5, 0.5) hangs on the left cell's side.
  Quads q;
  q.x = {0, 0.5, 1, 0, 0.5, 1, 0.5, 1};
  q.y = {0, 0, 0, 1, 1, 1, 0.5, 0.5};
  q.cells = {{0, 1, 4, 3}, {1, 2, 7, 6}, {6, 7, 5, 4}};
  const auto message = errorOf(q);
  EXPECT_TRUE(contains(message, "mesh.exo: the coarse mesh is not conforming: the side of cell 1 from (0.5, 0) to "
                                "(0.5, 1) has the vertex (0.5, 0.5) of other cells inside it"))
      << message;
}

TEST(CoarseMesh, RefusesACellThatIsNotConvexOrHasASideOfLengthZero) {
  Quads reflex = square2x2();
  reflex.x[4] = 0.2, reflex.y[4] = 0.2;  // cell 1's corner at (0.2, 0.2) points into it
  EXPECT_TRUE(contains(errorOf(reflex), "cell 1 is not convex: its corner at (0.2, 0.2)")) << errorOf(reflex);
  Quads straight;  // (0.5, 0) lies on the line from (0, 0) to (1, 0): a corner of 180 degrees
  straight.x = {0, 0.5, 1, 0};
  straight.y = {0, 0, 0, 1};
  straight.cells = {{0, 1, 2, 3}};
  EXPECT_TRUE(contains(errorOf(straight), "cell 1 is not convex: its corner at (0.5, 0)")) << errorOf(straight);
  Quads collapsed;  // a side of length zero: the quad is a triangle
  collapsed.x = {0, 1, 1, 0};
  collapsed.y = {0, 0, 1, 1};
  collapsed.cells = {{0, 1, 2, 2}};
  EXPECT_TRUE(contains(errorOf(collapsed), "cell 1 is not convex")) << errorOf(collapsed);
}

TEST(CoarseMesh, RefusesACoordinateThatIsNotANumber) {
  Quads q = square2x2();
  q.y[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(errorOf(q), "mesh.exo: vertex 8 has a coordinate that is not a finite number")) << errorOf(q);
}

// A side set that lists a side between two cells (a mesh generator's interface set, or a mistake
// in the file): the side is left out of every boundary segment, with a note that names it. The
// crack's sides are boundary sides: no note.
TEST(CoarseMesh, NotesSideSetEntriesBetweenTwoCells) {
  const Quads square = square2x2();
  // Cell 1's side 0 (corners 0-1) is the bottom; its side 1 (corners 1-2) is shared with cell 2.
  const std::map<std::string, std::vector<std::array<int, 2>>> bottom{{"bottom", {{0, 0}, {1, 0}}}};
  EXPECT_EQ(mesh::CoarseMesh::fromQuads(square.x, square.y, square.cells, bottom, "mesh.exo")->interiorSidesNote(), "");
  const std::map<std::string, std::vector<std::array<int, 2>>> mixed{{"bottom", {{0, 0}, {1, 0}, {0, 1}, {2, 0}}}};
  const auto note = mesh::CoarseMesh::fromQuads(square.x, square.y, square.cells, mixed, "mesh.exo")->interiorSidesNote();
  EXPECT_EQ(note, "mesh.exo: side set 'bottom' lists the side from (0.5, 0) to (0.5, 0.5) of cell 1, which lies between "
                  "two cells (and 1 more such sides): a boundary segment takes boundary edges only, so it is left out");
  Quads crack = square2x2();  // cells 3 and 4 apart from cells 1 and 2: the side between them is a boundary
  crack.x.push_back(0.0), crack.y.push_back(0.5);
  crack.x.push_back(0.5), crack.y.push_back(0.5);
  crack.x.push_back(1.0), crack.y.push_back(0.5);
  crack.cells[2] = {9, 10, 7, 6};
  crack.cells[3] = {10, 11, 8, 7};
  const std::map<std::string, std::vector<std::array<int, 2>>> slit{{"slit", {{0, 2}, {2, 0}}}};
  EXPECT_EQ(mesh::CoarseMesh::fromQuads(crack.x, crack.y, crack.cells, slit, "mesh.exo")->interiorSidesNote(), "");
}
