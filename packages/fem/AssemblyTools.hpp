#pragma once
/// \file AssemblyTools.hpp
/// Pieces the assemblers share (internal to the fem package): flags as device views, the finite
/// element graph of Q1 cells with any number of unknowns per node, and the translation from
/// overlap unknowns to the columns of the assembled matrices.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <Tpetra_FECrsGraph.hpp>

#include "Q1Mesh.hpp"

namespace signorini::fem {

/// 1/0 flags as a device view (an empty vector gives zeros of length n).
inline Kokkos::View<int*, DeviceType> deviceFlags(const std::vector<char>& flags, size_t n, const char* label) {
  Kokkos::View<int*, DeviceType> v(std::string(label), n);
  auto h = Kokkos::create_mirror_view(v);
  for (size_t i = 0; i < n; ++i) h(i) = flags.empty() ? 0 : flags[i];
  Kokkos::deep_copy(v, h);
  return v;
}

/// The graph of Q1 cells (hanging corners coupled through their constraints) with \p components
/// unknowns per node: unknown c of overlap node i is overlap entry components * i + c of \p overlap.
/// Globally indexed: the owned rows also couple to nodes that only other ranks' cells touch, so the
/// column maps come from the graph, not from the overlap map.
inline RCP<Tpetra::FECrsGraph<LO, GO, Node>> q1Graph(const mesh::Q1Mesh& mesh, int components,
                                                    const RCP<const Map>& owned, const RCP<const Map>& overlap) {
  const auto& dofs = mesh.cornerDofsHost;
  const LO nc = mesh.numLocalCells();
  std::vector<size_t> rowCount(overlap->getNodeNumElements(), 0);
  std::vector<std::vector<GO>> cellUnknowns(nc);
  for (LO e = 0; e < nc; ++e) {
    std::set<LO> nodes;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 2; ++k)
        if (dofs(e, c, k) >= 0) nodes.insert(dofs(e, c, k));
    for (LO n : nodes)
      for (int c = 0; c < components; ++c) {
        cellUnknowns[e].push_back(overlap->getGlobalElement(components * n + c));
        rowCount[components * n + c] += components * nodes.size();
      }
  }
  size_t maxRow = 1;
  for (size_t c : rowCount) maxRow = std::max(maxRow, c);
  auto graph = Teuchos::rcp(new Tpetra::FECrsGraph<LO, GO, Node>(owned, overlap, maxRow));
  graph->beginAssembly();
  for (LO e = 0; e < nc; ++e)
    for (GO r : cellUnknowns[e]) graph->insertGlobalIndices(r, Teuchos::ArrayView<const GO>(cellUnknowns[e]));
  graph->endAssembly();
  return graph;
}

/// Column of the assembled matrix (column map \p colMap) of every overlap unknown.
inline Kokkos::View<LO*, DeviceType> overlapToColumns(const Map& overlap, const Map& colMap) {
  Kokkos::View<LO*, DeviceType> toCol("toCol", overlap.getNodeNumElements());
  auto h = Kokkos::create_mirror_view(toCol);
  for (size_t i = 0; i < h.extent(0); ++i) h(i) = colMap.getLocalElement(overlap.getGlobalElement(static_cast<LO>(i)));
  Kokkos::deep_copy(toCol, h);
  return toCol;
}

}  // namespace signorini::fem
