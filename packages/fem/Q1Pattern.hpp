#pragma once
/// \file Q1Pattern.hpp
/// The sparsity pattern of an assembler's matrices (Q1 cells with any number of unknowns per node),
/// which also creates, fills and finishes those matrices (internal to the fem package).
#include <vector>

#include <Tpetra_Import.hpp>

#include "signorini/mesh/Q1Mesh.hpp"
#include "signorini/core/Types.hpp"

namespace signorini::fem {

/// The matrices of one Q1 mesh (unknown c of overlap node i is overlap entry components * i + c).
/// The assembly kernels sum each local cell's couplings into one local CRS matrix whose rows are the
/// overlap unknowns (owned first) and whose columns are toColumn() of the overlap unknowns.
///
/// One rank: the overlap unknowns are the owned ones, and that matrix is the result.
/// Several ranks: the owned rows also couple to unknowns that only other ranks' cells touch, so the
/// pattern of every row this rank does not own goes to the row's owner once (one exchange when the
/// pattern is made). The owned rows are the first rows of the local arrays, with the result's column
/// map (the owned unknowns first, then the others by global id: Tpetra's order, since the owned
/// global ids are contiguous by rank); the rows this rank does not own follow them. end() sends the
/// values of those rows to their owners, which add them at places found when the pattern was made:
/// no Tpetra graph fill, no global indices, no assembly mode, and one Import shared by all matrices
/// of the pattern. The exchanges are MPI_Alltoall(v) over all ranks (fine for a few ranks; a
/// neighbourhood exchange would scale further). All matrices of a pattern share its row pointers
/// and column indices: none may change its graph.
class Q1Pattern {
 public:
  using LocalMatrix = CrsMatrix::local_matrix_device_type;  ///< the device-side CRS arrays the kernels sum into

  /// \p owned and \p overlap: the assembler's maps of unknowns (owned first in the overlap order;
  /// on one rank the same). Collective.
  Q1Pattern(const mesh::Q1Mesh& mesh, int components, const RCP<const Map>& owned, const RCP<const Map>& overlap);

  /// A matrix being assembled: its kernels sum into local's values (row: overlap unknown; column:
  /// toColumn() of the overlap unknown).
  struct Fill {
    LocalMatrix local;  ///< every overlap row, the owned ones first; shares the pattern's graph
  };
  /// A new zero matrix on the pattern, open for summing.
  Fill begin() const;
  /// Ends the assembly of \p f, once (on several ranks: adds the other ranks' values of the owned
  /// rows; collective) and puts 1 on the diagonal of the owned unknowns flagged in \p identityRows (the
  /// kernels leave their rows and columns empty). The result views f's arrays.
  RCP<CrsMatrix> end(Fill& f, const std::vector<char>& identityRows) const;
  /// Column in the local arrays of every overlap unknown.
  Kokkos::View<LO*, DeviceType> toColumn() const { return toCol_; }

 private:
  RCP<const Map> owned_, overlap_, columns_;
  RCP<const Tpetra::Import<LO, GO, Node>> importer_;  // owned -> columns_ (several ranks)
  LocalMatrix::row_map_type rowPtr_;                 // every overlap row, the owned ones first
  LocalMatrix::index_type cols_;
  size_t ownedEntries_ = 0;  // the owned rows' entries come first
  LO numColumns_ = 0;        // of the local arrays (columns_ and the unknowns only foreign rows couple)
  Kokkos::View<LO*, DeviceType> toCol_;
  // Several ranks: the values of the foreign rows, in the order sent (entries of sendRows_, row by
  // row), go to the ranks in sendCounts_; received values are added at receivedAt_.
  std::vector<LO> sendRows_;
  std::vector<int> sendCounts_, sendOffsets_, recvCounts_, recvOffsets_;
  std::vector<size_t> receivedAt_;
};

}  // namespace signorini::fem
