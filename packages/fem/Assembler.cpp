#include "signorini/fem/Assembler.hpp"

#include <tuple>

#include <Tpetra_CrsMatrix.hpp>

#include "signorini/core/Error.hpp"

namespace signorini::fem {

RCP<CrsMatrix> combineOnGraph(const CrsMatrix& M, double cm, const CrsMatrix& K, double ck,
                              const std::vector<char>& identityRows) {
  const auto m = M.getLocalMatrixDevice();
  const auto k = K.getLocalMatrixDevice();
  if (m.graph.entries.data() != k.graph.entries.data() || m.graph.row_map.data() != k.graph.row_map.data())
    return Teuchos::null;
  const auto rowMap = M.getRowMap(), colMap = M.getColMap();
  const LO nRows = static_cast<LO>(rowMap->getNodeNumElements());
  Kokkos::View<LO*, DeviceType> identityColumn("combinedIdentityColumn", nRows);
  {
    auto h = Kokkos::create_mirror_view(identityColumn);
    for (LO i = 0; i < nRows; ++i) h(i) = identityRows[i] ? colMap->getLocalElement(rowMap->getGlobalElement(i)) : -1;
    Kokkos::deep_copy(identityColumn, h);
  }
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  LocalMatrix::values_type values(Kokkos::view_alloc("combinedValues", Kokkos::WithoutInitializing), m.values.extent(0));
  const auto rowPtr = m.graph.row_map;
  const auto cols = m.graph.entries;
  const auto mv = m.values, kv = k.values;
  Kokkos::parallel_for(
      "signorini::combineOnGraph", Kokkos::RangePolicy<ExecSpace>(0, nRows), KOKKOS_LAMBDA(const LO i) {
        for (auto e = rowPtr(i); e < rowPtr(i + 1); ++e)
          values(e) = identityColumn(i) < 0 ? cm * mv(e) + ck * kv(e) : (cols(e) == identityColumn(i) ? 1.0 : 0.0);
      });
  LocalMatrix a("combinedMatrix", m.numRows(), m.numCols(), m.nnz(), values, rowPtr, cols);
  const auto graph = M.getCrsGraph();
  return Teuchos::rcp(new CrsMatrix(a, rowMap, colMap, M.getDomainMap(), M.getRangeMap(), graph->getImporter(),
                                    graph->getExporter()));
}

Assembler::StepMatrices Assembler::assembleStepMatrices(double stiffCoeff, const ProblemData& problem,
                                                        const std::vector<char>& lumpAt) const {
  StepMatrices s;
  std::tie(s.M, s.K) = assembleMassAndStiffness(problem, lumpAt);
  // Dirichlet rows keep their identity row (M and K have 1 on the diagonal there).
  s.A = combineOnGraph(*s.M, 1.0, *s.K, stiffCoeff, dirichletFlags());  // owned unknowns come first in the overlap order
  SIGNORINI_ASSERT(!s.A.is_null(), "the assembler's matrices share one graph");
  return s;
}

}  // namespace signorini::fem
