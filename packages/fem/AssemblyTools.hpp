#pragma once
/// \file AssemblyTools.hpp
/// Pieces the assemblers share (internal to the fem package): flags as device views, the node
/// couplings of Q1 cells, and (Q1Pattern.hpp) the sparsity pattern of the assembled matrices.
#include <algorithm>
#include <string>
#include <vector>

#include <Tpetra_Map.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/fem/Q1Pattern.hpp"

namespace signorini::fem {

/// 1/0 flags as a device view (an empty vector gives zeros of length n).
inline Kokkos::View<int*, DeviceType> deviceFlags(const std::vector<char>& flags, size_t n, const char* label) {
  Kokkos::View<int*, DeviceType> v(std::string(label), n);
  auto h = Kokkos::create_mirror_view(v);
  for (size_t i = 0; i < n; ++i) h(i) = flags.empty() ? 0 : flags[i];
  Kokkos::deep_copy(v, h);
  return v;
}

/// Node-to-node couplings of Q1 cells (hanging corners coupled through their constraints): the
/// neighbours of overlap node n (itself included) are adjacent[offset[n] .. offset[n] + count[n]),
/// sorted and distinct (here count[n] = offset[n + 1] - offset[n]).
struct Q1NodeAdjacency {
  /// \var offset
  /// start of node n's neighbours in adjacent (nNodes + 1 entries)
  /// \var count
  /// number of node n's neighbours
  std::vector<size_t> offset, count;
  std::vector<LO> adjacent;  ///< the neighbours of all nodes, node by node (overlap ids)
};

/// The Q1NodeAdjacency of the local cells of \p mesh; \p nNodes: overlap nodes (more than any id the cells use).
inline Q1NodeAdjacency q1NodeAdjacency(const mesh::Q1Mesh& mesh, size_t nNodes) {
  const auto& dofs = mesh.cornerDofsHost;
  const LO nc = mesh.numLocalCells();
  // The distinct nodes of every cell (at most 8: 4 corners, each with up to 2 constraint nodes),
  // and the cells of every node.
  std::vector<LO> cellNodes(8 * static_cast<size_t>(nc));
  std::vector<unsigned char> cellCount(nc, 0);
  std::vector<size_t> cellsAt(nNodes + 1, 0);
  for (LO e = 0; e < nc; ++e) {
    LO* nodes = &cellNodes[8 * static_cast<size_t>(e)];
    int count = 0;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 2; ++k) {
        const LO n = dofs(e, c, k);
        if (n >= 0 && std::find(nodes, nodes + count, n) == nodes + count) nodes[count++] = n;
      }
    cellCount[e] = static_cast<unsigned char>(count);
    for (int i = 0; i < count; ++i) ++cellsAt[nodes[i] + 1];
  }
  for (size_t n = 0; n < nNodes; ++n) cellsAt[n + 1] += cellsAt[n];
  std::vector<LO> cells(cellsAt[nNodes]);
  {
    std::vector<size_t> fill(cellsAt.begin(), cellsAt.end() - 1);
    for (LO e = 0; e < nc; ++e)
      for (int i = 0; i < cellCount[e]; ++i) cells[fill[cellNodes[8 * static_cast<size_t>(e) + i]]++] = e;
  }
  // Each node's neighbours: the nodes of its cells, each taken once (marked with the node), sorted.
  Q1NodeAdjacency adj;
  adj.offset.resize(nNodes + 1);
  adj.count.resize(nNodes);
  adj.adjacent.reserve(10 * nNodes);
  std::vector<LO> seenBy(nNodes, -1);
  for (size_t n = 0; n < nNodes; ++n) {
    adj.offset[n] = adj.adjacent.size();
    for (size_t c = cellsAt[n]; c < cellsAt[n + 1]; ++c) {
      const LO e = cells[c];
      for (int i = 0; i < cellCount[e]; ++i) {
        const LO m = cellNodes[8 * static_cast<size_t>(e) + i];
        if (seenBy[m] != static_cast<LO>(n)) seenBy[m] = static_cast<LO>(n), adj.adjacent.push_back(m);
      }
    }
    std::sort(adj.adjacent.begin() + adj.offset[n], adj.adjacent.end());
    adj.count[n] = adj.adjacent.size() - adj.offset[n];
  }
  adj.offset[nNodes] = adj.adjacent.size();
  return adj;
}

}  // namespace signorini::fem
