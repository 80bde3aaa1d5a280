#include "signorini/estimate/HarmonicContinuation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"

namespace signorini::estimate {

namespace {

/// The matrix \p full with the rows and columns of the \p prescribed nodes (flags on the overlap
/// map, consistent across ranks) replaced by identity rows and zero columns, on the same graph.
/// For a matrix from Q1Assembler::assembleOperator this equals, bit for bit, assembling with those
/// nodes as Dirichlet nodes: that only skips the contributions to prescribed rows and columns, so
/// every other entry receives the same contributions in the same order (and the prescribed set
/// contains the assembler's own Dirichlet nodes, whose rows and columns \p full already
/// eliminates). Saves a second assembly.
RCP<const CrsMatrix> withPrescribedRows(const CrsMatrix& full, const std::vector<char>& prescribed) {
  const auto colMap = full.getColMap();
  const auto rowMap = full.getRowMap();
  const auto graph = full.getCrsGraph();
  const LO nCols = static_cast<LO>(colMap->getNodeNumElements());
  const LO nRows = static_cast<LO>(rowMap->getNodeNumElements());
  // The flags of the columns: after the export to the owned rows, a row may have columns that are
  // not in this rank's overlap map, so the owned flags are imported like a vector.
  Vector rowFlags(full.getDomainMap()), colFlags(colMap);
  {
    SIGNORINI_ASSERT(full.getDomainMap()->isSameAs(*rowMap), "the rows are not the owned nodes");
    auto h = rowFlags.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < nRows; ++i) h(i, 0) = prescribed[i] ? 1.0 : 0.0;  // owned nodes come first in the overlap map
  }
  if (graph->getImporter().is_null())
    colFlags.assign(rowFlags);
  else
    colFlags.doImport(rowFlags, *graph->getImporter(), Tpetra::INSERT);
  Kokkos::View<char*, DeviceType> colFixed("s1PrescribedColumns", nCols), rowFixed("s1PrescribedRows", nRows);
  Kokkos::View<LO*, DeviceType> diagonal("s1DiagonalColumn", nRows);
  {
    auto ch = Kokkos::create_mirror_view(colFixed);
    auto cf = colFlags.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO c = 0; c < nCols; ++c) ch(c) = cf(c, 0) != 0.0;
    Kokkos::deep_copy(colFixed, ch);
    auto rh = Kokkos::create_mirror_view(rowFixed);
    auto dh = Kokkos::create_mirror_view(diagonal);
    for (LO i = 0; i < nRows; ++i) {
      rh(i) = prescribed[i];
      dh(i) = colMap->getLocalElement(rowMap->getGlobalElement(i));
    }
    Kokkos::deep_copy(rowFixed, rh);
    Kokkos::deep_copy(diagonal, dh);
  }
  const auto local = full.getLocalMatrixDevice();
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  LocalMatrix::values_type values(Kokkos::view_alloc("s1Values", Kokkos::WithoutInitializing), local.values.extent(0));
  const auto rowPtr = local.graph.row_map;
  const auto cols = local.graph.entries;
  const auto fullValues = local.values;
  Kokkos::parallel_for(
      "signorini::estimator::prescribedRows", Kokkos::RangePolicy<ExecSpace>(0, nRows), KOKKOS_LAMBDA(const LO i) {
        for (auto k = rowPtr(i); k < rowPtr(i + 1); ++k) {
          const LO c = cols(k);
          values(k) = rowFixed(i) ? (c == diagonal(i) ? 1.0 : 0.0) : (colFixed(c) ? 0.0 : fullValues(k));
        }
      });
  LocalMatrix constrained("s1Operator", local.numRows(), local.numCols(), local.nnz(), values, rowPtr, cols);
  return Teuchos::rcp(new CrsMatrix(constrained, rowMap, colMap, full.getDomainMap(), full.getRangeMap(),
                                    graph->getImporter(), graph->getExporter()));
}

/// ||d||_1 for the continuation d of \p boundary (zero away from the prescribed nodes): A is
/// \p full with the \p prescribed rows made identity rows and their columns zero. \p d holds the
/// initial guess at the free nodes and returns the continuation.
double continuationNorm(const CrsMatrix& full, const RCP<const CrsMatrix>& A, const std::vector<char>& prescribed,
                        const Vector& boundary, Vector& d,
                        const std::function<void(const RCP<const CrsMatrix>&, const Vector&, Vector&)>& solveSPD) {
  const auto owned = boundary.getMap();
  const LO nOwned = static_cast<LO>(owned->getNodeNumElements());
  // Lifting: b = -A_full w on the free nodes, b = w on the prescribed ones (identity rows).
  Vector b(owned), Ad(owned);
  core::apply(full, boundary, b);
  {
    auto bh = b.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto dh = d.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto wh = boundary.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < nOwned; ++i) {
      bh(i, 0) = prescribed[i] ? wh(i, 0) : -bh(i, 0);
      if (prescribed[i]) dh(i, 0) = wh(i, 0);
    }
  }
  solveSPD(A, b, d);
  {
    auto dh = d.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto wh = boundary.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < nOwned; ++i)
      if (prescribed[i]) dh(i, 0) = wh(i, 0);
  }
  core::apply(full, d, Ad);
  return std::sqrt(std::max(core::dot(d, Ad), 0.0));
}

}  // namespace

double geometricContactTerm(const mesh::Q1Mesh& mesh, unsigned contactMask, const core::Expression& g, double t,
                            const std::function<double(LO)>& w, const std::vector<char>& fixed,
                            const fem::Q1Assembler* scalar,
                            const std::function<void(const RCP<const CrsMatrix>&, const Vector&, Vector&)>& solveSPD,
                            ContinuationCache* cache, long meshId, const Vector* guess,
                            const std::function<RCP<const CrsMatrix>()>& h1Operator, double massWeight) {
  const auto owned = mesh.ownedMap();
  const LO nOwned = static_cast<LO>(owned->getNodeNumElements());
  const std::vector<char> contact = mesh.nodesOnSegments(contactMask);
  Vector boundary(owned);
  double maxLocal = 0, maxGlobal = 0;
  std::string bad;  // g not a finite number at a contact node (the constraint samples it between them)
  {
    auto bh = boundary.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < nOwned; ++i) {  // owned nodes come first in the overlap numbering
      bh(i, 0) = 0.0;
      if (!contact[i] || fixed[i]) continue;
      const auto& x = mesh.nodeCoords()[i];
      bh(i, 0) = std::max(g.sample(x[0], x[1], t, bad) - w(i), 0.0);
      maxLocal = std::max(maxLocal, bh(i, 0));
    }
  }
  core::throwFirstUserError(*mesh.comm(), bad.empty() ? bad : bad + " (a node of the contact boundary, where the estimator's s1 takes it)");
  Teuchos::reduceAll(*mesh.comm(), Teuchos::REDUCE_MAX, maxLocal, Teuchos::outArg(maxGlobal));
  if (!(maxGlobal > 0)) return 0.0;
  SIGNORINI_ASSERT(static_cast<bool>(solveSPD), "s1 needs a solver for SPD systems");
  ContinuationCache once;  // without a cache (or mesh id) everything is built for this call only
  if (!cache || meshId < 0) cache = &once;
  if (cache == &once || cache->meshId != meshId) {
    cache->prescribed.resize(fixed.size());
    for (size_t i = 0; i < fixed.size(); ++i) cache->prescribed[i] = (fixed[i] || contact[i]) ? 1 : 0;
    cache->full = h1Operator ? h1Operator() : Teuchos::null;
    if (cache->full.is_null()) {
      std::unique_ptr<fem::Q1Assembler> own;
      if (!scalar) scalar = (own = std::make_unique<fem::Q1Assembler>(mesh, fixed)).get();
      cache->full = scalar->assembleOperator(massWeight, 1.0, 1.0, 1.0);
    }
    cache->constrained = withPrescribedRows(*cache->full, cache->prescribed);
    cache->last = Teuchos::rcp(new Vector(owned));  // zero: the first guess is the data itself
    if (guess) cache->last->assign(*guess);
    cache->meshId = meshId;
  }
  return continuationNorm(*cache->full, cache->constrained, cache->prescribed, boundary, *cache->last, solveSPD);
}

}  // namespace signorini::estimate
