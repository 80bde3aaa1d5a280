#pragma once
/// \file AssemblyTools.hpp
/// Pieces the assemblers share (internal to the fem package): flags as device views, the node
/// couplings of Q1 cells, and the sparsity pattern of the assembled matrices with any number of
/// unknowns per node, which also creates, fills and finishes those matrices (Q1Pattern).
#include <algorithm>
#include <string>
#include <vector>

#include <Kokkos_DualView.hpp>
#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include "Error.hpp"
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

/// Node-to-node couplings of Q1 cells (hanging corners coupled through their constraints): the
/// neighbours of overlap node n (itself included) are adjacent[offset[n] .. offset[n] + count[n]),
/// sorted and distinct (here count[n] = offset[n + 1] - offset[n]).
struct Q1NodeAdjacency {
  std::vector<size_t> offset, count;
  std::vector<LO> adjacent;
};

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

/// Column of the assembled matrix (column map \p colMap) of every overlap unknown.
inline Kokkos::View<LO*, DeviceType> overlapToColumns(const Map& overlap, const Map& colMap) {
  Kokkos::View<LO*, DeviceType> toCol("toCol", overlap.getNodeNumElements());
  auto h = Kokkos::create_mirror_view(toCol);
  for (size_t i = 0; i < h.extent(0); ++i) h(i) = colMap.getLocalElement(overlap.getGlobalElement(static_cast<LO>(i)));
  Kokkos::deep_copy(toCol, h);
  return toCol;
}

/// The sparsity pattern of an assembler's matrices (Q1 cells with \p components unknowns per node:
/// unknown c of overlap node i is overlap entry components * i + c) and the way they are filled.
/// Several ranks: an FECrsGraph, globally indexed (the owned rows also couple to nodes that only
/// other ranks' cells touch, so the column map comes from the graph); its matrices are
/// Tpetra::FECrsMatrix, whose endAssembly adds the shared rows to their owners. One rank: the
/// overlap unknowns are the owned ones, the pattern is a local CRS graph with the overlap map as
/// column map, and each matrix is summed into its local arrays and built from them (no Tpetra graph
/// fill, no assembly mode).
class Q1Pattern {
 public:
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  using FEGraph = Tpetra::FECrsGraph<LO, GO, Node>;
  using FEMatrix = Tpetra::FECrsMatrix<Scalar, LO, GO, Node>;

  /// \p ownedToOverlap (owned -> overlap) is reused for the export of the shared rows.
  Q1Pattern(const mesh::Q1Mesh& mesh, int components, const RCP<const Map>& owned, const RCP<const Map>& overlap,
            const RCP<const Tpetra::Import<LO, GO, Node>>& ownedToOverlap)
      : owned_(owned), overlap_(overlap) {
    const size_t nNodes = overlap->getNodeNumElements() / components;
    const Q1NodeAdjacency adj = q1NodeAdjacency(mesh, nNodes);
    if (overlap->getComm()->getSize() == 1) {
      const size_t nRows = overlap->getNodeNumElements();
      LocalMatrix::row_map_type::non_const_type rowPtr("q1PatternRows", nRows + 1);
      auto rh = Kokkos::create_mirror_view(rowPtr);
      rh(0) = 0;
      for (size_t n = 0; n < nNodes; ++n)
        for (int c = 0; c < components; ++c)
          rh(components * n + c + 1) = rh(components * n + c) + components * adj.count[n];
      LocalMatrix::index_type::non_const_type cols("q1PatternColumns", rh(nRows));
      auto ch = Kokkos::create_mirror_view(cols);
      for (size_t n = 0; n < nNodes; ++n)
        for (int c = 0; c < components; ++c) {
          auto at = rh(components * n + c);
          for (size_t k = adj.offset[n]; k < adj.offset[n] + adj.count[n]; ++k)
            for (int d = 0; d < components; ++d) ch(at++) = static_cast<LO>(components * adj.adjacent[k] + d);
        }
      Kokkos::deep_copy(rowPtr, rh);
      Kokkos::deep_copy(cols, ch);
      rowPtr_ = rowPtr;
      cols_ = cols;
      Kokkos::View<LO*, DeviceType> toCol("toCol", nRows);
      Kokkos::parallel_for(
          "signorini::q1PatternColumns", Kokkos::RangePolicy<ExecSpace>(0, nRows),
          KOKKOS_LAMBDA(const LO i) { toCol(i) = i; });
      toCol_ = toCol;
      SIGNORINI_ASSERT(overlap->isSameAs(*owned), "on one rank every overlap unknown is owned");
      return;
    }
    Kokkos::DualView<size_t*, DeviceType> perRow("q1GraphRowLengths", overlap->getNodeNumElements());
    for (size_t n = 0; n < nNodes; ++n)
      for (int c = 0; c < components; ++c) perRow.h_view(components * n + c) = components * adj.count[n];
    perRow.modify_host();
    perRow.sync_device();
    graph_ = Teuchos::rcp(new FEGraph(owned, overlap, Kokkos::DualView<const size_t*, DeviceType>(perRow), ownedToOverlap));
    graph_->beginAssembly();
    std::vector<GO> columns;
    for (size_t n = 0; n < nNodes; ++n) {
      columns.clear();
      for (size_t k = adj.offset[n]; k < adj.offset[n] + adj.count[n]; ++k)
        for (int c = 0; c < components; ++c)
          columns.push_back(overlap->getGlobalElement(static_cast<LO>(components * adj.adjacent[k] + c)));
      for (int c = 0; c < components; ++c)
        graph_->insertGlobalIndices(overlap->getGlobalElement(static_cast<LO>(components * n + c)),
                                    Teuchos::ArrayView<const GO>(columns));
    }
    graph_->endAssembly();
  }

  /// A matrix being assembled: its kernels sum into local's values (row: overlap unknown; column:
  /// toColumn() of the overlap unknown).
  struct Fill {
    RCP<FEMatrix> fe;  ///< several ranks
    LocalMatrix local;
  };
  /// A new zero matrix on the pattern, open for summing.
  Fill begin() const {
    Fill f;
    if (graph_.is_null()) {
      LocalMatrix::values_type values("q1PatternValues", cols_.extent(0));
      f.local = LocalMatrix("q1Matrix", static_cast<LO>(rowPtr_.extent(0) - 1), static_cast<LO>(overlap_->getNodeNumElements()),
                            cols_.extent(0), values, rowPtr_, cols_);
      return f;
    }
    f.fe = Teuchos::rcp(new FEMatrix(graph_));
    f.fe->beginAssembly();
    if (toCol_.extent(0) != overlap_->getNodeNumElements()) toCol_ = overlapToColumns(*overlap_, *f.fe->getColMap());
    f.local = f.fe->getLocalMatrixDevice();
    return f;
  }
  /// Ends the assembly of \p f and puts 1 on the diagonal of the owned unknowns flagged in
  /// \p identityRows (the kernels leave their rows and columns empty).
  RCP<CrsMatrix> end(Fill& f, const std::vector<char>& identityRows) const {
    const LO nOwned = static_cast<LO>(owned_->getNodeNumElements());
    if (graph_.is_null()) {
      auto values = Kokkos::create_mirror_view(f.local.values);
      Kokkos::deep_copy(values, f.local.values);
      const auto rh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), rowPtr_);
      const auto ch = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cols_);
      for (LO i = 0; i < nOwned; ++i)  // owned unknowns come first in the overlap order
        if (identityRows[i])
          for (auto k = rh(i); k < rh(i + 1); ++k)
            if (ch(k) == i) values(k) = 1.0;
      Kokkos::deep_copy(f.local.values, values);
      // The column map equals the domain map: no importer.
      return Teuchos::rcp(new CrsMatrix(f.local, owned_, overlap_, owned_, owned_, Teuchos::null, Teuchos::null));
    }
    f.fe->endAssembly();
    f.fe->beginModify();
    const auto colMap = f.fe->getColMap();
    for (LO i = 0; i < nOwned; ++i)
      if (identityRows[i]) {
        const LO col = colMap->getLocalElement(owned_->getGlobalElement(i));
        const double one = 1.0;
        f.fe->replaceLocalValues(i, 1, &one, &col);
      }
    f.fe->endModify();
    return f.fe;
  }
  /// Column in the local arrays of every overlap unknown (after the first begin()).
  Kokkos::View<LO*, DeviceType> toColumn() const { return toCol_; }

 private:
  RCP<const Map> owned_, overlap_;
  RCP<FEGraph> graph_;  // several ranks
  LocalMatrix::row_map_type rowPtr_;  // one rank
  LocalMatrix::index_type cols_;
  mutable Kokkos::View<LO*, DeviceType> toCol_;
};

}  // namespace signorini::fem
