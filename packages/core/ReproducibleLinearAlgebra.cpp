#include "ReproducibleLinearAlgebra.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "Error.hpp"
#include "ReproducibleSum.hpp"

namespace signorini::core {

void applyCanonical(const CrsMatrix& A, const Vector& X, Vector& Y) {
  SIGNORINI_ASSERT(A.getGraph()->getExporter().is_null(), "applyCanonical: the row map must be the range map");
  const auto importer = A.getGraph()->getImporter();
  Teuchos::RCP<const Vector> columns = Teuchos::rcpFromRef(X);
  if (!importer.is_null()) {
    auto imported = Teuchos::rcp(new Vector(A.getColMap(), false));
    imported->doImport(X, *importer, Tpetra::INSERT);
    columns = imported;
  }
  const auto matrix = A.getLocalMatrixHost();
  auto xv = columns->getLocalViewHost(Tpetra::Access::ReadOnly);
  auto yv = Y.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto* rowMap = matrix.graph.row_map.data();
  const LO* cols = matrix.graph.entries.data();
  const double* values = matrix.values.data();
  const double* x = xv.data();
  double* y = yv.data();
  constexpr size_t kShort = 64;
  double shortRow[kShort];
  std::vector<double> longRow;
  for (LO i = 0; i < matrix.numRows(); ++i) {
    const size_t begin = rowMap[i], n = rowMap[i + 1] - begin;
    double* p = shortRow;
    if (n > kShort) longRow.resize(n), p = longRow.data();
    double largest = 0.0;
    for (size_t k = 0; k < n; ++k) {
      p[k] = values[begin + k] * x[cols[begin + k]];
      largest = std::max(largest, std::fabs(p[k]));
    }
    if (!(largest > 0.0) || !std::isfinite(largest)) {  // zeros, or an inf or nan to pass on
      double sum = 0.0;
      for (size_t k = 0; k < n; ++k) sum += p[k];
      y[i] = sum;
      continue;
    }
    // The row's sum in pre-rounded parts (as reproducibleSums, with the row's largest product as
    // the bound; two parts of 46 bits for rows of up to 64 entries): the same bits in any order.
    const int exponent = detail::boundExponent(largest);  // largest < 2^exponent
    const bool normal = exponent > -1000 && exponent < 1000;
    const double scale = normal ? detail::powerOfTwo(-exponent) : std::ldexp(1.0, -exponent);
    double folds[3] = {0.0, 0.0, 0.0};
    double sum;
    if (n <= detail::kMaxShortTerms) {
      for (size_t k = 0; k < n; ++k) detail::addFoldedShort(p[k] * scale, folds);
      sum = folds[0] + folds[1];
    } else {
      for (size_t k = 0; k < n; ++k) detail::addFolded(p[k] * scale, folds);
      sum = (folds[0] + folds[1]) + folds[2];
    }
    y[i] = normal ? sum * detail::powerOfTwo(exponent) : std::ldexp(sum, exponent);
  }
}

void apply(const CrsMatrix& A, const Vector& x, Vector& y) {
  if (reproducibleArithmetic())
    applyCanonical(A, x, y);
  else
    A.apply(x, y);
}

double dot(const Vector& a, const Vector& b) {
  if (!reproducibleArithmetic()) return a.dot(b);
  auto av = a.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  double sum;
  reproducibleSums(*a.getMap()->getComm(), 1, av.extent(0), [&](size_t i, double* t) { t[0] = av(i, 0) * bv(i, 0); },
                         &sum);
  return sum;
}

}  // namespace signorini::core
