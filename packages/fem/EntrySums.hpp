#pragma once
/// \file EntrySums.hpp
/// Partition-independent assembly sums (EntrySums) for reproducible arithmetic (docs/reproducibility.md).
#include <vector>

#include <Tpetra_Import.hpp>

#include "signorini/core/Types.hpp"

namespace signorini::fem {

/// One cell's contribution to entry (row, column): row an overlap-map local id, column a global id
/// (0 for vectors).
struct Contribution {
  LO row;        ///< overlap-map local id of the row
  GO column;     ///< global column id (0 for vectors)
  double value;  ///< the cell's contribution
};

/// Whether an assembly on \p comm needs EntrySums for partition-independent sums: under
/// reproducible arithmetic, except on one rank with the Serial execution space, where the ordinary
/// kernels already add every entry's contributions in the order of the cells.
bool needEntrySums(const Comm& comm);

/// Flags, per overlap row, the rows other ranks' cells contribute to as well: the owned rows that
/// other ranks import (export ids of \p ownedToOverlap) and the rows this rank does not own. Only
/// these need EntrySums; every other row gets contributions from this rank's cells alone, and a
/// kernel that adds them in the order of the cells (serial) already sums them as one rank would.
std::vector<char> sharedRows(const Map& overlap, const Tpetra::Import<LO, GO, Node>& ownedToOverlap);

/// Partition-independent assembly sums (reproducible arithmetic, docs/reproducibility.md): each
/// contribution of a cell to an entry (row, column) of a matrix or vector goes to the rank that
/// owns the row, and the contributions of an entry are added in the order one rank would add them:
/// by source rank, each rank's in the order of its list. p4est's partition gives each rank a
/// consecutive piece of the space-filling curve, so when every rank lists its contributions in the
/// order of its cells, that is the order of the cells along the curve, the same on any number of
/// ranks, and the order in which the serial assembly kernels add (Serial execution space). A rank's
/// partial sum, added to the owner's by an export, is not partition-independent.
/// The sums of the owned rows are computed in the constructor and stored; no reference to the arguments is kept.
class EntrySums {
 public:
  /// Collective. \p contributions in the order of this rank's cells (within a cell, in an order
  /// that does not depend on the partition). \p ownedToOverlap tells the owner of every overlap
  /// row that is not owned (the owned rows come first in the overlap order).
  EntrySums(const Map& owned, const Map& overlap, const Tpetra::Import<LO, GO, Node>& ownedToOverlap,
            const std::vector<Contribution>& contributions);

  /// The sum of entry (owned row \p row, global column \p column); 0 without contributions.
  double operator()(LO row, GO column) const;
  /// Overwrites the values of \p A (rows: the owned map) with the sums, except in the rows flagged
  /// in \p keepRows (owned local ids; an empty vector keeps none).
  void writeInto(CrsMatrix& A, const std::vector<char>& keepRows) const;
  /// out = sums (or out + sums when \p accumulate) for the owned rows: for all of them when
  /// \p shared is empty, else for those flagged in \p shared (sharedRows), every other row taking
  /// its sum from \p localSums instead (this rank's contributions summed in cell order, on the
  /// overlap map or the owned map: the owned rows come first).
  void writeInto(Vector& out, bool accumulate, const std::vector<char>& shared = {},
                 const Vector* localSums = nullptr) const;

 private:
  std::vector<size_t> rowStart_;
  std::vector<GO> column_;
  std::vector<double> value_;
};

}  // namespace signorini::fem
