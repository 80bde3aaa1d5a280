#include "signorini/core/ReproducibleLinearAlgebra.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Kokkos_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <Teuchos_CommHelpers.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::core {

namespace {

using LocalEntries = CrsMatrix::local_matrix_host_type::index_type;

/// The canonical order of one local graph: order[k] for k in a row's range is the index of the
/// row's k-th entry by column key. The graph's column indices are kept (a reference that also
/// keeps their address from being reused while the order is registered), and the column map the
/// keys were imported to (a matrix on the same arrays with another column map has no order).
struct RowOrder {
  LocalEntries entries;
  Teuchos::RCP<const Map> columns;
  std::vector<size_t> order;
};

std::vector<RowOrder>& rowOrders() {
  static std::vector<RowOrder> orders;
  static const bool hooked = [] {  // the kept views must go before Kokkos does
    Kokkos::push_finalize_hook([] { orders.clear(); });
    return true;
  }();
  (void)hooked;
  return orders;
}

const RowOrder* findRowOrder(const CrsMatrix& A, const LocalEntries& entries) {
  for (const auto& r : rowOrders())
    if (r.entries.data() == entries.data() && r.entries.extent(0) == entries.extent(0) &&
        r.columns.get() == A.getColMap().get())
      return &r;
  return nullptr;
}

/// \p X (on A's domain map) on A's column map: X itself without an importer, else imported.
Teuchos::RCP<const MultiVector> onColumnMap(const CrsMatrix& A, const MultiVector& X) {
  const auto importer = A.getGraph()->getImporter();
  if (importer.is_null()) return Teuchos::rcpFromRef(X);
  auto imported = Teuchos::rcp(new MultiVector(A.getColMap(), X.getNumVectors(), false));
  imported->doImport(X, *importer, Tpetra::INSERT);
  return imported;
}

}  // namespace

void registerCanonicalRowOrder(const CrsMatrix& A, const std::vector<std::array<long long, 3>>& ownedKeys) {
  SIGNORINI_ASSERT(A.getDomainMap()->isSameAs(*A.getRowMap()), "registerCanonicalRowOrder: the domain map must be the row map");
  SIGNORINI_ASSERT(ownedKeys.size() == A.getDomainMap()->getNodeNumElements(), "registerCanonicalRowOrder: one key per owned row");
  auto& orders = rowOrders();
  // Orders whose graph only the registry still holds are gone with their matrices.
  orders.erase(std::remove_if(orders.begin(), orders.end(), [](const RowOrder& r) { return r.entries.use_count() <= 1; }),
               orders.end());
  const auto matrix = A.getLocalMatrixHost();
  {  // a matrix on already registered arrays (K after M): nothing to do, if so on every rank
    int known = findRowOrder(A, matrix.graph.entries) != nullptr ? 1 : 0, all = 0;
    Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MIN, 1, &known, &all);
    if (all == 1) return;
  }
  // Keys travel as doubles: they are integers far below 2^53.
  MultiVector owned(A.getDomainMap(), 3, false);
  {
    auto v = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t i = 0; i < ownedKeys.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        SIGNORINI_ASSERT(std::fabs(static_cast<double>(ownedKeys[i][c])) < 0x1p53, "registerCanonicalRowOrder: key too large");
        v(i, c) = static_cast<double>(ownedKeys[i][c]);
      }
  }
  const auto columns = onColumnMap(A, owned);
  auto keys = columns->getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto* rowMap = matrix.graph.row_map.data();
  const LO* cols = matrix.graph.entries.data();
  RowOrder r{matrix.graph.entries, A.getColMap(), std::vector<size_t>(matrix.graph.entries.extent(0))};
  auto less = [&](size_t a, size_t b) {
    for (int c = 0; c < 3; ++c)
      if (keys(cols[a], c) != keys(cols[b], c)) return keys(cols[a], c) < keys(cols[b], c);
    return false;
  };
  bool distinct = true;
  for (LO i = 0; i < matrix.numRows(); ++i) {
    const size_t begin = rowMap[i], end = rowMap[i + 1];
    for (size_t k = begin; k < end; ++k) r.order[k] = k;
    std::sort(r.order.begin() + begin, r.order.begin() + end, less);
    for (size_t k = begin + 1; k < end; ++k) distinct = distinct && less(r.order[k - 1], r.order[k]);
  }
  // Every rank registers or none (a rank without an order would sum its rows in another way).
  int allDistinct = distinct ? 1 : 0, global = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MIN, 1, &allDistinct, &global);
  if (global == 1) orders.push_back(std::move(r));
}

bool hasCanonicalRowOrder(const CrsMatrix& A) { return findRowOrder(A, A.getLocalMatrixHost().graph.entries) != nullptr; }

namespace {

/// One column of A X (\p x on A's column map, local) into \p y: each row summed left to right in
/// the registered order \p canonical, or, without one, in exact pre-rounded parts.
void applyColumn(const CrsMatrix::local_matrix_host_type& matrix, const RowOrder* canonical, const double* x, double* y) {
  const auto* rowMap = matrix.graph.row_map.data();
  const LO* cols = matrix.graph.entries.data();
  const double* values = matrix.values.data();
  if (canonical) {
    const size_t* order = canonical->order.data();
    auto product = [&](size_t k) { return values[order[k]] * x[cols[order[k]]]; };
    // Two rows side by side (two dependency chains), each summed in its own order.
    const LO rows = matrix.numRows();
    LO i = 0;
    for (; i + 1 < rows; i += 2) {
      size_t a = rowMap[i], b = rowMap[i + 1];
      const size_t aEnd = rowMap[i + 1], bEnd = rowMap[i + 2];
      double first = 0.0, second = 0.0;
      for (; a < aEnd && b < bEnd; ++a, ++b) first += product(a), second += product(b);
      for (; a < aEnd; ++a) first += product(a);
      for (; b < bEnd; ++b) second += product(b);
      y[i] = first, y[i + 1] = second;
    }
    if (i < rows) {
      double sum = 0.0;
      for (size_t k = rowMap[i]; k < rowMap[i + 1]; ++k) sum += product(k);
      y[i] = sum;
    }
    return;
  }
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

/// NC columns of A X in the registered \p order, each row summed left to right as applyColumn sums
/// it; the NC columns of a row are NC independent dependency chains.
template <int NC>
void applyOrdered(const CrsMatrix::local_matrix_host_type& matrix, const size_t* order, const double* x, size_t xStride,
                  double* y, size_t yStride, const int* columns) {
  const auto* rowMap = matrix.graph.row_map.data();
  const LO* cols = matrix.graph.entries.data();
  const double* values = matrix.values.data();
  const double* xc[NC];
  double* yc[NC];
  for (int c = 0; c < NC; ++c) xc[c] = x + columns[c] * xStride, yc[c] = y + columns[c] * yStride;
  for (LO i = 0; i < matrix.numRows(); ++i) {
    double sum[NC] = {};
    for (size_t k = rowMap[i]; k < rowMap[i + 1]; ++k) {
      const double value = values[order[k]];
      const LO col = cols[order[k]];
      for (int c = 0; c < NC; ++c) sum[c] += value * xc[c][col];
    }
    for (int c = 0; c < NC; ++c) yc[c][i] = sum[c];
  }
}

}  // namespace

void applyCanonical(const CrsMatrix& A, const Vector& X, Vector& Y) {
  SIGNORINI_ASSERT(A.getGraph()->getExporter().is_null(), "applyCanonical: the row map must be the range map");
  const auto columns = onColumnMap(A, X);
  const auto matrix = A.getLocalMatrixHost();
  auto xv = columns->getLocalViewHost(Tpetra::Access::ReadOnly);
  auto yv = Y.getLocalViewHost(Tpetra::Access::OverwriteAll);
  applyColumn(matrix, findRowOrder(A, matrix.graph.entries), xv.data(), yv.data());
}

void applyCanonicalColumns(const CrsMatrix& A, const MultiVector& X, MultiVector& Y, const std::vector<int>& columns) {
  SIGNORINI_ASSERT(A.getGraph()->getExporter().is_null(), "applyCanonicalColumns: the row map must be the range map");
  SIGNORINI_ASSERT(!columns.empty() && columns.size() <= 3, "applyCanonicalColumns: 1 to 3 columns");
  SIGNORINI_ASSERT(&X != &Y && X.getNumVectors() == Y.getNumVectors() && X.isConstantStride() && Y.isConstantStride(),
                   "applyCanonicalColumns: X and Y distinct, with the same columns at a constant stride");
  for (const int c : columns)
    SIGNORINI_ASSERT(c >= 0 && static_cast<size_t>(c) < X.getNumVectors() && std::count(columns.begin(), columns.end(), c) == 1,
                     "applyCanonicalColumns: distinct columns of X");
  // One import of X on every rank, whichever path the rank takes below (an import is collective
  // between neighbours, and whether a rank finds a registered order is its own lookup).
  const auto onColumns = onColumnMap(A, X);
  const auto matrix = A.getLocalMatrixHost();
  if (matrix.numRows() == 0) return;
  const auto* canonical = findRowOrder(A, matrix.graph.entries);
  auto xv = onColumns->getLocalViewHost(Tpetra::Access::ReadOnly);
  auto yv = Y.getLocalViewHost(Tpetra::Access::ReadWrite);
  const size_t xStride = onColumns->getStride(), yStride = Y.getStride();
  if (canonical && columns.size() == 2)
    applyOrdered<2>(matrix, canonical->order.data(), xv.data(), xStride, yv.data(), yStride, columns.data());
  else if (canonical && columns.size() == 3)
    applyOrdered<3>(matrix, canonical->order.data(), xv.data(), xStride, yv.data(), yStride, columns.data());
  else
    for (const int c : columns) applyColumn(matrix, canonical, xv.data() + c * xStride, yv.data() + c * yStride);
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
  reproducibleSums(
      *a.getMap()->getComm(), 1, av.extent(0), [&](size_t i, double* t) { t[0] = av(i, 0) * bv(i, 0); }, &sum,
      a.getMap()->getGlobalNumElements());
  return sum;
}

}  // namespace signorini::core
