#pragma once
/// Coarse meshes of general quadrilaterals for the tests (read through the Exodus reader, as a
/// user's mesh would be): distorted cells and cells whose vertices start at another corner.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "signorini/mesh/CoarseMesh.hpp"
#include "signorini/io/ExodusSeriesWriter.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::test {

/// A coarse mesh of general quadrilaterals from an Exodus file written here (rank 0) and read by
/// every rank; one side set "boundary" holds all boundary sides.
inline std::shared_ptr<mesh::CoarseMesh> exodusCoarseMesh(const std::vector<double>& x, const std::vector<double>& y,
                                                   const std::vector<std::array<int, 4>>& quads, const std::string& tag,
                                                   const RCP<const Comm>& comm = Tpetra::getDefaultComm()) {
  io::QuadMesh m;
  m.x = x;
  m.y = y;
  m.quads = quads;
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : m.quads)
    for (int s = 0; s < 4; ++s) ++uses[{std::min(q[s], q[(s + 1) % 4]), std::max(q[s], q[(s + 1) % 4])}];
  for (int e = 0; e < static_cast<int>(m.quads.size()); ++e)
    for (int s = 0; s < 4; ++s) {
      const auto& q = m.quads[e];
      if (uses[{std::min(q[s], q[(s + 1) % 4]), std::max(q[s], q[(s + 1) % 4])}] == 1)
        m.sideSets["boundary"].push_back({e, s});
    }
  long pid = static_cast<long>(::getpid());
  Teuchos::broadcast(*comm, 0, 1, &pid);
  const std::string base =
      (std::filesystem::path(::testing::TempDir()) / ("signorini_test_" + tag + "_" + std::to_string(pid)))
          .string();
  if (comm->getRank() == 0) {
    io::ExodusSeriesWriter w(base, {}, {}, "boundary", {});
    w.write(0, m, 0.0, {}, {}, {});
    w.close();
  }
  Teuchos::barrier(*comm);
  auto params = mesh::CoarseMesh::getValidParameters();
  params.set("Type", std::string("exodus"));
  params.set("File", base + ".e");
  auto coarse = mesh::CoarseMesh::create(params);
  Teuchos::barrier(*comm);
  if (comm->getRank() == 0) std::filesystem::remove(base + ".e");
  return coarse;
}

/// The four cells of a 2 x 2 grid of vertices v = 3 j + i (counter-clockwise); the right-hand cells
/// list their vertices from another corner, so that neighbouring trees have differently oriented
/// reference frames.
inline std::vector<std::array<int, 4>> twoByTwoQuads() {
  std::vector<std::array<int, 4>> quads;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int v = 3 * j + i;
      if (i == 1 && j == 0)
        quads.push_back({v + 1, v + 4, v + 3, v});
      else if (i == 1 && j == 1)
        quads.push_back({v + 4, v + 3, v, v + 1});
      else
        quads.push_back({v, v + 1, v + 4, v + 3});
    }
  return quads;
}

/// The unit square as 2 x 2 distorted quadrilaterals (interior vertex and side midpoints moved);
/// the second and fourth cells list their vertices from another corner, so that neighbouring
/// trees have differently oriented reference frames.
inline std::shared_ptr<mesh::CoarseMesh> distortedSquare(const RCP<const Comm>& comm = Tpetra::getDefaultComm()) {
  std::vector<double> x = {0, 0.4, 1, 0, 0.6, 1, 0, 0.55, 1};
  std::vector<double> y = {0, 0, 0, 0.45, 0.42, 0.6, 1, 1, 1};
  return exodusCoarseMesh(x, y, twoByTwoQuads(), "distorted", comm);
}
inline const std::vector<std::pair<std::string, std::string>> kDistortedSides = {{"left", "boundary, x < 0.001"},
                                                                          {"right", "boundary, x > 0.999"},
                                                                          {"bottom", "boundary, y < 0.001"},
                                                                          {"top", "boundary, y > 0.999"}};

/// The unit square as 2 x 2 squares from an Exodus file; the right-hand cells list their vertices
/// from another corner (neighbouring trees with differently oriented reference frames).
inline std::shared_ptr<mesh::CoarseMesh> rotatedSquares() {
  std::vector<double> x = {0, 0.5, 1, 0, 0.5, 1, 0, 0.5, 1};
  std::vector<double> y = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
  return exodusCoarseMesh(x, y, twoByTwoQuads(), "rotated");
}

}  // namespace signorini::test
