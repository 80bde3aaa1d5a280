#include "signorini/solvers/JacobiCG.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::solvers {

namespace {

/// A tolerance as written in a deck (1e-14, not std::to_string's 0.000000).
std::string toleranceText(double tolerance) {
  std::ostringstream text;
  text << tolerance;
  return text.str();
}

/// Fields solved together by one kernel sweep; more are solved in groups of this size.
constexpr int kMaxFields = 3;

/// Per-field flags and scalars of a group of NF fields, captured by value by the kernels (NF is a
/// compile-time constant so that the loops over the fields unroll and the sums stay in registers).
template <int NF>
struct Fields {
  bool active[NF] = {};
  double value[NF] = {};
};

/// Local sums of body(i, sums) over i < n into 2 NF accumulators, in blocks whose partial sums stay
/// in registers (a reduction into Kokkos' accumulators element by element went through memory and
/// was as slow as the matrix apply). Within a field the additions come in the same order for any NF.
template <int NF, class Body>
struct BlockedSums {
  using value_type = double[];
  static constexpr LO kBlock = 256;
  unsigned value_count;
  LO n;
  Body body;
  KOKKOS_INLINE_FUNCTION void operator()(const LO block, value_type sums) const {
    double local[2 * NF] = {};
    const LO end = (block + 1) * kBlock < n ? (block + 1) * kBlock : n;
    for (LO i = block * kBlock; i < end; ++i) body(i, local);
    for (int k = 0; k < 2 * NF; ++k) sums[k] += local[k];
  }
};

template <int NF, class Body>
void blockedSums(const char* label, LO n, const Body& body, double (&sums)[2 * NF]) {
  const BlockedSums<NF, Body> functor{2 * NF, n, body};
  const LO blocks = (n + functor.kBlock - 1) / functor.kBlock;
  Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(sums, 2 * NF);
  Kokkos::parallel_reduce(label, Kokkos::RangePolicy<ExecSpace>(0, blocks), functor, result);
}

/// Sum over all ranks of the local partial sums.
template <int N>
void sumAll(const Comm& comm, double (&values)[N]) {
  double global[N];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, N, values, global);
  for (int k = 0; k < N; ++k) values[k] = global[k];
}

/// Y(:, c) = A X(:, c) for the NC columns c in \p columns, one sweep over the local rows that reads
/// each matrix entry once. The sums are ordered as in the serial spmv of KokkosKernels that Tpetra's
/// apply uses (four partial sums over the entries of a row in groups of four, the rest into the
/// first, added left to right), so on a serial build each column gets exactly the bits of Tpetra's
/// apply. (Tpetra's own multi-vector apply orders differently.)
template <int NC>
void applyLocal(const CrsMatrix::local_matrix_device_type& matrix, const int (&columns)[NC], const MultiVector& X,
                MultiVector& Y) {
  auto xv = X.getLocalViewDevice(Tpetra::Access::ReadOnly);
  auto yv = Y.getLocalViewDevice(Tpetra::Access::ReadWrite);
  int col[NC];
  for (int c = 0; c < NC; ++c) col[c] = columns[c];
  Kokkos::parallel_for(
      "signorini::jacobiCG::apply", Kokkos::RangePolicy<ExecSpace>(0, matrix.numRows()), KOKKOS_LAMBDA(const LO i) {
        double s0[NC] = {}, s1[NC] = {}, s2[NC] = {}, s3[NC] = {};
        const auto end = matrix.graph.row_map(i + 1);
        auto k = matrix.graph.row_map(i);
        for (; k + 4 <= end; k += 4) {
          const LO j0 = matrix.graph.entries(k), j1 = matrix.graph.entries(k + 1), j2 = matrix.graph.entries(k + 2),
                   j3 = matrix.graph.entries(k + 3);
          for (int c = 0; c < NC; ++c) {
            s0[c] += matrix.values(k) * xv(j0, col[c]);
            s1[c] += matrix.values(k + 1) * xv(j1, col[c]);
            s2[c] += matrix.values(k + 2) * xv(j2, col[c]);
            s3[c] += matrix.values(k + 3) * xv(j3, col[c]);
          }
        }
        for (; k < end; ++k)
          for (int c = 0; c < NC; ++c) s0[c] += matrix.values(k) * xv(matrix.graph.entries(k), col[c]);
        for (int c = 0; c < NC; ++c) yv(i, col[c]) = s0[c] + s1[c] + s2[c] + s3[c];
      });
}

/// How the fields are applied: locally (no importer and the domain map as column map), after one
/// import of all fields to A's column map (several ranks: Tpetra's apply imports each field by
/// itself), or by Tpetra's apply per field (a matrix with an exporter).
enum class ApplyPath { local, imported, tpetra };
ApplyPath applyPath(const CrsMatrix& A) {
  if (!A.getGraph()->getExporter().is_null()) return ApplyPath::tpetra;
  if (!A.getGraph()->getImporter().is_null()) return ApplyPath::imported;
  return A.getColMap()->isSameAs(*A.getDomainMap()) ? ApplyPath::local : ApplyPath::tpetra;
}

/// Y_f = A X_f for the active fields f, along \p path (\p onColumns: NF columns on A's column map
/// for ApplyPath::imported). Tpetra's apply imports and then applies as applyLocal does, so every
/// path gives each field the bits of Tpetra's apply.
template <int NF>
void applyActive(const CrsMatrix& A, ApplyPath path, const Fields<NF>& fields, const MultiVector& X, MultiVector& Y,
                 MultiVector* onColumns) {
  int columns[NF], nc = 0;
  for (int f = 0; f < NF; ++f)
    if (fields.active[f]) columns[nc++] = f;
  if (path == ApplyPath::tpetra) {
    for (int c = 0; c < nc; ++c) A.apply(*X.getVector(columns[c]), *Y.getVectorNonConst(columns[c]));
    return;
  }
  if (path == ApplyPath::imported) onColumns->doImport(X, *A.getGraph()->getImporter(), Tpetra::INSERT);
  const MultiVector& in = path == ApplyPath::imported ? *onColumns : X;
  const auto matrix = A.getLocalMatrixDevice();
  if (nc == 1) applyLocal<1>(matrix, {columns[0]}, in, Y);
  if constexpr (NF >= 2)
    if (nc == 2) applyLocal<2>(matrix, {columns[0], columns[1]}, in, Y);
  if constexpr (NF >= 3)
    if (nc == 3) applyLocal<3>(matrix, {columns[0], columns[1], columns[2]}, in, Y);
  static_assert(NF <= 3, "applyActive dispatches up to three fields");
}

template <int NF>
std::vector<int> solveGroup(const CrsMatrix& A, const std::vector<const Vector*>& b, const std::vector<Vector*>& x,
                            double relativeTolerance, int maxIterations) {
  const auto map = A.getRangeMap();
  const Comm& comm = *map->getComm();
  const LO n = static_cast<LO>(map->getNodeNumElements());
  Vector inverseDiagonal(A.getRowMap());
  MultiVector X(map, NF, false), B(map, NF, false), R(map, NF, false), P(map, NF, false), Q(map, NF, false);
  for (int f = 0; f < NF; ++f) {
    X.getVectorNonConst(f)->assign(*x[f]);
    B.getVectorNonConst(f)->assign(*b[f]);
  }
  A.getLocalDiagCopy(inverseDiagonal);
  const ApplyPath path = applyPath(A);
  std::unique_ptr<MultiVector> onColumns;
  if (path == ApplyPath::imported) onColumns = std::make_unique<MultiVector>(A.getColMap(), NF, false);
  Fields<NF> fields;
  for (int f = 0; f < NF; ++f) fields.active[f] = true;
  applyActive(A, path, fields, X, Q, onColumns.get());
  double start[2 * NF] = {};  // per field ||b||^2, r.z
  {
    auto bv = B.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto dv = inverseDiagonal.getLocalViewDevice(Tpetra::Access::ReadWrite);
    auto qv = Q.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto rv = R.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    auto pv = P.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    blockedSums<NF>(
        "signorini::jacobiCG::start", n,
        KOKKOS_LAMBDA(const LO i, double* s) {
          const double d = 1.0 / dv(i, 0);
          dv(i, 0) = d;
          for (int f = 0; f < NF; ++f) {
            const double ri = bv(i, f) - qv(i, f);
            rv(i, f) = ri;
            pv(i, f) = ri * d;
            s[2 * f] += bv(i, f) * bv(i, f);
            s[2 * f + 1] += ri * pv(i, f);
          }
        },
        start);
  }
  sumAll(comm, start);
  std::vector<int> iterations(NF, 0);
  double target[NF] = {}, rz[NF] = {};
  int active = 0;
  for (int f = 0; f < NF; ++f) {
    fields.active[f] = false;
    if (start[2 * f] == 0.0) {
      x[f]->putScalar(0.0);
      continue;
    }
    target[f] = relativeTolerance * std::sqrt(start[2 * f]);
    rz[f] = start[2 * f + 1];
    if (R.getVector(f)->norm2() <= target[f]) continue;  // the initial residual may already be small enough
    fields.active[f] = true;
    ++active;
  }
  auto dv = inverseDiagonal.getLocalViewDevice(Tpetra::Access::ReadOnly);
  for (int it = 1; it <= maxIterations && active > 0; ++it) {
    applyActive(A, path, fields, P, Q, onColumns.get());
    double pq[2 * NF] = {};
    {
      auto pv = P.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto qv = Q.getLocalViewDevice(Tpetra::Access::ReadOnly);
      blockedSums<NF>(
          "signorini::jacobiCG::pq", n,
          KOKKOS_LAMBDA(const LO i, double* s) {
            for (int f = 0; f < NF; ++f)
              if (fields.active[f]) s[2 * f] += pv(i, f) * qv(i, f);
          },
          pq);
    }
    sumAll(comm, pq);
    Fields<NF> alpha = fields;
    for (int f = 0; f < NF; ++f)
      if (fields.active[f]) alpha.value[f] = rz[f] / pq[2 * f];
    double sums[2 * NF] = {};  // per field r.r, r.z after the update
    {
      auto pv = P.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto qv = Q.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto xv = X.getLocalViewDevice(Tpetra::Access::ReadWrite);
      auto rv = R.getLocalViewDevice(Tpetra::Access::ReadWrite);
      blockedSums<NF>(
          "signorini::jacobiCG::update", n,
          KOKKOS_LAMBDA(const LO i, double* s) {
            for (int f = 0; f < NF; ++f)
              if (alpha.active[f]) {
                xv(i, f) += alpha.value[f] * pv(i, f);
                const double ri = rv(i, f) - alpha.value[f] * qv(i, f);
                rv(i, f) = ri;
                s[2 * f] += ri * ri;
                s[2 * f + 1] += ri * ri * dv(i, 0);
              }
          },
          sums);
    }
    sumAll(comm, sums);
    Fields<NF> beta = fields;
    for (int f = 0; f < NF; ++f) {
      if (!fields.active[f]) continue;
      if (std::sqrt(sums[2 * f]) <= target[f]) {
        iterations[f] = it;
        x[f]->assign(*X.getVector(f));
        fields.active[f] = beta.active[f] = false;
        --active;
        continue;
      }
      beta.value[f] = sums[2 * f + 1] / rz[f];
      rz[f] = sums[2 * f + 1];
    }
    if (active == 0) break;
    auto rv = R.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto pv = P.getLocalViewDevice(Tpetra::Access::ReadWrite);
    Kokkos::parallel_for(
        "signorini::jacobiCG::direction", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const LO i) {
          for (int f = 0; f < NF; ++f)
            if (beta.active[f]) pv(i, f) = rv(i, f) * dv(i, 0) + beta.value[f] * pv(i, f);
        });
  }
  if (active > 0)
    throw core::SolverError("Jacobi CG: no convergence to " + toleranceText(relativeTolerance) + " in " +
                            std::to_string(maxIterations) + " iterations");
  return iterations;
}

}  // namespace

namespace {

/// Jacobi CG with partition-independent applies and sums for NF fields (right-hand sides) of one
/// matrix: each field takes the operations of its own solve (NF = 1), in the same order, so it gets
/// the same iterates, bits and iteration count; the fields share the sweeps over the matrix
/// (core::applyCanonicalColumns) and the diagonal. Each x_f is updated in place: it holds the last
/// iterate if the solve throws.
template <int NF>
std::vector<int> solveReproducibleGroup(const CrsMatrix& A, const Vector& diagonal, const std::vector<const Vector*>& b,
                                        const std::vector<Vector*>& x, double relativeTolerance, int maxIterations) {
  SIGNORINI_ASSERT(b.size() == NF && x.size() == NF, "solveReproducibleGroup: NF right-hand sides and guesses");
  const Comm& comm = *A.getRangeMap()->getComm();
  const size_t n = A.getRangeMap()->getNodeNumElements();
  const size_t global = A.getRangeMap()->getGlobalNumElements();  // the same on any partition
  SIGNORINI_ASSERT(diagonal.getLocalLength() == n, "solveReproducibleJacobiCG: the diagonal is not on A's rows");
  MultiVector R(A.getRangeMap(), NF, false), P(A.getRangeMap(), NF, false), Q(A.getRangeMap(), NF, false),
      Z(A.getRangeMap(), NF, false);
  std::vector<int> all(NF), running, iterations(NF, 0);
  for (int f = 0; f < NF; ++f) all[f] = f, P.getVectorNonConst(f)->assign(*x[f]);
  core::applyCanonicalColumns(A, P, Q, all);  // A x
  auto dv = diagonal.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto rv = R.getLocalViewHost(Tpetra::Access::OverwriteAll);
  auto pv = P.getLocalViewHost(Tpetra::Access::ReadWrite);
  auto zv = Z.getLocalViewHost(Tpetra::Access::OverwriteAll);  // z = D^-1 r
  using HostView = decltype(x[0]->getLocalViewHost(Tpetra::Access::ReadWrite));
  using ConstHostView = decltype(b[0]->getLocalViewHost(Tpetra::Access::ReadOnly));
  std::vector<ConstHostView> bv;
  std::vector<HostView> xv;
  for (int f = 0; f < NF; ++f)
    bv.push_back(b[f]->getLocalViewHost(Tpetra::Access::ReadOnly)), xv.push_back(x[f]->getLocalViewHost(Tpetra::Access::ReadWrite));
  {
    auto qv = Q.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (int f = 0; f < NF; ++f)
      for (size_t i = 0; i < n; ++i) rv(i, f) = bv[f](i, 0) - qv(i, f), pv(i, f) = rv(i, f) / dv(i, 0);
  }
  // Each field's sums are summed by themselves (their bits would not depend on the other fields',
  // but one field per call keeps the accumulators in registers).
  double target[NF], rz[NF];
  for (int f = 0; f < NF; ++f) {
    double start[3];  // ||b||^2, r.z, ||r||^2
    core::reproducibleSums(
        comm, 3, n,
        [&](size_t i, double* t) {
          t[0] = bv[f](i, 0) * bv[f](i, 0);
          t[1] = rv(i, f) * pv(i, f);
          t[2] = rv(i, f) * rv(i, f);
        },
        start, global);
    target[f] = relativeTolerance * std::sqrt(start[0]);
    rz[f] = start[1];
    if (start[0] == 0.0) {  // x = 0
      for (size_t i = 0; i < n; ++i) xv[f](i, 0) = 0.0;
    } else if (!(std::sqrt(start[2]) <= target[f])) {  // a nan iterates, and fails
      running.push_back(f);
    }
  }
  for (int it = 1; it <= maxIterations && !running.empty(); ++it) {
    core::applyCanonicalColumns(A, P, Q, running);
    auto qv = Q.getLocalViewHost(Tpetra::Access::ReadOnly);
    std::vector<int> still;
    for (const int f : running) {
      double pq;
      core::reproducibleSums(comm, 1, n, [&](size_t i, double* t) { t[0] = pv(i, f) * qv(i, f); }, &pq, global);
      const double alpha = rz[f] / pq;
      // The update also finds the local largest terms of the sums below (their first pass).
      constexpr int kLanes = 4;
      double largestOf[kLanes][2] = {};
      auto update = [&](size_t i, double* largest) {
        xv[f](i, 0) += alpha * pv(i, f), rv(i, f) -= alpha * qv(i, f);
        zv(i, f) = rv(i, f) / dv(i, 0);
        largest[0] = std::max(largest[0], std::fabs(rv(i, f) * rv(i, f)));
        largest[1] = std::max(largest[1], std::fabs(rv(i, f) * zv(i, f)));
      };
      size_t i = 0;
      for (; i + kLanes <= n; i += kLanes)
        for (int l = 0; l < kLanes; ++l) update(i + l, largestOf[l]);
      for (; i < n; ++i) update(i, largestOf[0]);
      double sums[2], largest[2];  // r.r, r.z
      for (int k = 0; k < 2; ++k)
        largest[k] = std::max({largestOf[0][k], largestOf[1][k], largestOf[2][k], largestOf[3][k]});
      core::reproducibleSumsGivenLargest(
          comm, 2, n,
          [&](size_t i, double* t) {
            t[0] = rv(i, f) * rv(i, f);
            t[1] = rv(i, f) * zv(i, f);
          },
          largest, sums, global);
      if (std::sqrt(sums[0]) <= target[f]) {
        iterations[f] = it;
        continue;
      }
      const double beta = sums[1] / rz[f];
      rz[f] = sums[1];
      for (size_t i = 0; i < n; ++i) pv(i, f) = zv(i, f) + beta * pv(i, f);
      still.push_back(f);
    }
    running = still;
  }
  if (!running.empty())
    throw core::SolverError("Jacobi CG: no convergence to " + toleranceText(relativeTolerance) + " in " +
                            std::to_string(maxIterations) + " iterations");
  return iterations;
}

}  // namespace

int solveReproducibleJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance,
                              int maxIterations) {
  Vector diagonal(A.getRowMap());
  A.getLocalDiagCopy(diagonal);
  return solveReproducibleJacobiCG(A, diagonal, b, x, relativeTolerance, maxIterations);
}

int solveReproducibleJacobiCG(const CrsMatrix& A, const Vector& diagonal, const Vector& b, Vector& x,
                              double relativeTolerance, int maxIterations) {
  return solveReproducibleGroup<1>(A, diagonal, {&b}, {&x}, relativeTolerance, maxIterations)[0];
}

std::vector<int> solveJacobiCG(const CrsMatrix& A, const std::vector<const Vector*>& b, const std::vector<Vector*>& x,
                               double relativeTolerance, int maxIterations) {
  SIGNORINI_ASSERT(b.size() == x.size(), "one initial guess per right-hand side");
  const bool reproducible = core::reproducibleArithmetic();
  Vector diagonal(A.getRowMap());  // once for all groups (reproducible arithmetic)
  if (reproducible) A.getLocalDiagCopy(diagonal);
  std::vector<int> iterations;
  for (size_t first = 0; first < b.size(); first += kMaxFields) {
    const size_t count = std::min<size_t>(b.size() - first, kMaxFields);
    const std::vector<const Vector*> groupB(b.begin() + first, b.begin() + first + count);
    const std::vector<Vector*> groupX(x.begin() + first, x.begin() + first + count);
    std::vector<int> group;
    if (reproducible) {
      if (count == 1) group = solveReproducibleGroup<1>(A, diagonal, groupB, groupX, relativeTolerance, maxIterations);
      if (count == 2) group = solveReproducibleGroup<2>(A, diagonal, groupB, groupX, relativeTolerance, maxIterations);
      if (count == 3) group = solveReproducibleGroup<3>(A, diagonal, groupB, groupX, relativeTolerance, maxIterations);
    } else if (count == 1)
      group = solveGroup<1>(A, groupB, groupX, relativeTolerance, maxIterations);
    else if (count == 2)
      group = solveGroup<2>(A, groupB, groupX, relativeTolerance, maxIterations);
    else
      group = solveGroup<3>(A, groupB, groupX, relativeTolerance, maxIterations);
    iterations.insert(iterations.end(), group.begin(), group.end());
  }
  return iterations;
}

int solveJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance, int maxIterations) {
  return solveJacobiCG(A, std::vector<const Vector*>{&b}, std::vector<Vector*>{&x}, relativeTolerance, maxIterations)[0];
}

}  // namespace signorini::solvers
