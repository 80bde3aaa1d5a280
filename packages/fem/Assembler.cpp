#include "Assembler.hpp"

#include <Tpetra_CrsMatrix.hpp>


namespace signorini::fem {

Assembler::StepMatrices Assembler::assembleStepMatrices(double stiffCoeff, const ProblemData& problem,
                                                        const std::vector<char>& lumpAt) const {
  StepMatrices s;
  s.M = assembleSystem(1.0, 0.0, problem, lumpAt);
  s.K = assembleSystem(0.0, 1.0, problem);
  const auto m = s.M->getLocalMatrixDevice();
  const auto k = s.K->getLocalMatrixDevice();
  if (m.graph.entries.data() != k.graph.entries.data() || m.graph.row_map.data() != k.graph.row_map.data()) {
    s.A = assembleSystem(1.0, stiffCoeff, problem, lumpAt);  // no common graph (not the case for our assemblers)
    return s;
  }
  const auto rowMap = s.M->getRowMap(), colMap = s.M->getColMap();
  const LO nRows = static_cast<LO>(rowMap->getNodeNumElements());
  // Dirichlet rows keep their identity row (M and K have 1 on the diagonal there).
  Kokkos::View<LO*, DeviceType> dirichletColumn("stepDirichletColumn", nRows);
  {
    auto h = Kokkos::create_mirror_view(dirichletColumn);
    const auto& dirichlet = dirichletFlags();  // owned unknowns come first in the overlap order
    for (LO i = 0; i < nRows; ++i) h(i) = dirichlet[i] ? colMap->getLocalElement(rowMap->getGlobalElement(i)) : -1;
    Kokkos::deep_copy(dirichletColumn, h);
  }
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  LocalMatrix::values_type values(Kokkos::view_alloc("stepValues", Kokkos::WithoutInitializing), m.values.extent(0));
  const auto rowPtr = m.graph.row_map;
  const auto cols = m.graph.entries;
  const auto mv = m.values, kv = k.values;
  Kokkos::parallel_for(
      "signorini::stepMatrix", Kokkos::RangePolicy<ExecSpace>(0, nRows), KOKKOS_LAMBDA(const LO i) {
        for (auto e = rowPtr(i); e < rowPtr(i + 1); ++e)
          values(e) = dirichletColumn(i) < 0 ? mv(e) + stiffCoeff * kv(e) : (cols(e) == dirichletColumn(i) ? 1.0 : 0.0);
      });
  LocalMatrix a("stepMatrix", m.numRows(), m.numCols(), m.nnz(), values, rowPtr, cols);
  const auto graph = s.M->getCrsGraph();
  s.A = Teuchos::rcp(new CrsMatrix(a, rowMap, colMap, s.M->getDomainMap(), s.M->getRangeMap(), graph->getImporter(),
                                   graph->getExporter()));
  return s;
}

}  // namespace signorini::fem
