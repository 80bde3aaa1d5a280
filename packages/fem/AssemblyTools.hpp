#pragma once
/// \file AssemblyTools.hpp
/// Pieces the assemblers share (internal to the fem package): flags as device views, the finite
/// element graph of Q1 cells with any number of unknowns per node, and the translation from
/// overlap unknowns to the columns of the assembled matrices.
#include <algorithm>
#include <string>
#include <vector>

#include <Kokkos_DualView.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_Import.hpp>

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
/// On several ranks globally indexed: the owned rows also couple to nodes that only other ranks'
/// cells touch, so the column maps come from the graph, not from the overlap map; on one rank the
/// overlap map is the column map. \p ownedToOverlap (owned -> overlap) is reused by the graph for
/// its export of the shared rows.
inline RCP<Tpetra::FECrsGraph<LO, GO, Node>> q1Graph(const mesh::Q1Mesh& mesh, int components,
                                                    const RCP<const Map>& owned, const RCP<const Map>& overlap,
                                                    const RCP<const Tpetra::Import<LO, GO, Node>>& ownedToOverlap) {
  const auto& dofs = mesh.cornerDofsHost;
  const LO nc = mesh.numLocalCells();
  const size_t nNodes = overlap->getNodeNumElements() / components;
  // The distinct nodes of every cell (at most 8: 4 corners, each with up to 2 constraint nodes).
  std::vector<LO> cellNodes(8 * static_cast<size_t>(nc));
  std::vector<unsigned char> cellCount(nc, 0);
  std::vector<size_t> offset(nNodes + 1, 0);
  for (LO e = 0; e < nc; ++e) {
    LO* nodes = &cellNodes[8 * static_cast<size_t>(e)];
    int count = 0;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 2; ++k) {
        const LO n = dofs(e, c, k);
        if (n >= 0 && std::find(nodes, nodes + count, n) == nodes + count) nodes[count++] = n;
      }
    cellCount[e] = static_cast<unsigned char>(count);
    for (int i = 0; i < count; ++i) offset[nodes[i] + 1] += count;
  }
  for (size_t n = 0; n < nNodes; ++n) offset[n + 1] += offset[n];
  // Node-to-node adjacency (with repeats), then each node's neighbours sorted and unique.
  std::vector<LO> adjacent(offset[nNodes]);
  std::vector<size_t> fill(offset.begin(), offset.end() - 1);
  for (LO e = 0; e < nc; ++e) {
    const LO* nodes = &cellNodes[8 * static_cast<size_t>(e)];
    for (int i = 0; i < cellCount[e]; ++i)
      for (int j = 0; j < cellCount[e]; ++j) adjacent[fill[nodes[i]]++] = nodes[j];
  }
  std::vector<size_t> unique(nNodes, 0);
  for (size_t n = 0; n < nNodes; ++n) {
    auto first = adjacent.begin() + offset[n], last = adjacent.begin() + offset[n + 1];
    std::sort(first, last);
    unique[n] = std::unique(first, last) - first;
  }
  Kokkos::DualView<size_t*, DeviceType> perRow("q1GraphRowLengths", overlap->getNodeNumElements());
  for (size_t n = 0; n < nNodes; ++n)
    for (int c = 0; c < components; ++c) perRow.h_view(components * n + c) = components * unique[n];
  perRow.modify_host();
  perRow.sync_device();
  const Kokkos::DualView<const size_t*, DeviceType> rowLengths(perRow);
  // One rank: every coupling is local, so the overlap map is the column map and the graph is
  // filled by local indices (no global lookups, no column map to discover).
  const bool local = overlap->getComm()->getSize() == 1;
  using Graph = Tpetra::FECrsGraph<LO, GO, Node>;
  auto graph = local ? Teuchos::rcp(new Graph(owned, overlap, overlap, rowLengths, ownedToOverlap))
                     : Teuchos::rcp(new Graph(owned, overlap, rowLengths, ownedToOverlap));
  graph->beginAssembly();
  // Rows and columns of the overlap unknowns as index(i) (local or global), inserted by insert.
  auto insertRows = [&](auto index, auto insert) {
    std::vector<decltype(index(LO{0}))> columns;
    for (size_t n = 0; n < nNodes; ++n) {
      columns.clear();
      for (size_t k = offset[n]; k < offset[n] + unique[n]; ++k)
        for (int c = 0; c < components; ++c) columns.push_back(index(static_cast<LO>(components * adjacent[k] + c)));
      for (int c = 0; c < components; ++c) insert(index(static_cast<LO>(components * n + c)), columns);
    }
  };
  if (local)
    insertRows([](LO i) { return i; },
               [&](LO row, const std::vector<LO>& cols) { graph->insertLocalIndices(row, Teuchos::ArrayView<const LO>(cols)); });
  else
    insertRows([&](LO i) { return overlap->getGlobalElement(i); },
               [&](GO row, const std::vector<GO>& cols) { graph->insertGlobalIndices(row, Teuchos::ArrayView<const GO>(cols)); });
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
