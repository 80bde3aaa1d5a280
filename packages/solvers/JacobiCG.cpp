#include "JacobiCG.hpp"

#include <cmath>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "Error.hpp"

namespace signorini::solvers {

namespace {
/// Sum over all ranks of n local partial sums.
template <int n>
void sumAll(const Comm& comm, double (&values)[n]) {
  double global[n];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, n, values, global);
  for (int k = 0; k < n; ++k) values[k] = global[k];
}

/// Local sums s0 += .., s1 += .. of body(i, a0, a1) over i < n, in blocks whose partial sums stay in
/// registers (a reduction into Kokkos' accumulators element by element went through memory and was
/// as slow as the matrix apply).
template <class Body>
void blockedSum(const char* label, LO n, const Body& body, double& s0, double& s1) {
  constexpr LO kBlock = 256;
  const LO blocks = (n + kBlock - 1) / kBlock;
  Kokkos::parallel_reduce(
      label, Kokkos::RangePolicy<ExecSpace>(0, blocks),
      KOKKOS_LAMBDA(const LO block, double& a0, double& a1) {
        double l0 = 0, l1 = 0;
        const LO end = (block + 1) * kBlock < n ? (block + 1) * kBlock : n;
        for (LO i = block * kBlock; i < end; ++i) body(i, l0, l1);
        a0 += l0;
        a1 += l1;
      },
      s0, s1);
}
}  // namespace

int solveJacobiCG(const CrsMatrix& A, const Vector& b, Vector& x, double relativeTolerance, int maxIterations) {
  const auto map = A.getRangeMap();
  const Comm& comm = *map->getComm();
  const LO n = static_cast<LO>(map->getNodeNumElements());
  Vector inverseDiagonal(A.getRowMap()), r(map), p(map), q(map);
  A.getLocalDiagCopy(inverseDiagonal);
  A.apply(x, q);
  double start[2] = {0, 0};  // ||b||^2, r.z
  {
    auto bv = b.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto dv = inverseDiagonal.getLocalViewDevice(Tpetra::Access::ReadWrite);
    auto qv = q.getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto rv = r.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    auto pv = p.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    blockedSum(
        "signorini::jacobiCG::start", n,
        KOKKOS_LAMBDA(const LO i, double& bb, double& rz) {
          dv(i, 0) = 1.0 / dv(i, 0);
          const double ri = bv(i, 0) - qv(i, 0);
          rv(i, 0) = ri;
          pv(i, 0) = ri * dv(i, 0);
          bb += bv(i, 0) * bv(i, 0);
          rz += ri * pv(i, 0);
        },
        start[0], start[1]);
  }
  sumAll(comm, start);
  if (start[0] == 0.0) {
    x.putScalar(0.0);
    return 0;
  }
  const double target = relativeTolerance * std::sqrt(start[0]);
  double rz = start[1];
  if (r.norm2() <= target) return 0;  // the initial residual may already be small enough
  auto dv = inverseDiagonal.getLocalViewDevice(Tpetra::Access::ReadOnly);
  for (int it = 1; it <= maxIterations; ++it) {
    A.apply(p, q);
    double pq[2] = {0, 0};
    {
      auto pv = p.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto qv = q.getLocalViewDevice(Tpetra::Access::ReadOnly);
      blockedSum(
          "signorini::jacobiCG::pq", n, KOKKOS_LAMBDA(const LO i, double& s, double&) { s += pv(i, 0) * qv(i, 0); },
          pq[0], pq[1]);
    }
    sumAll(comm, pq);
    const double alpha = rz / pq[0];
    double sums[2] = {0, 0};  // r.r, r.z after the update
    {
      auto pv = p.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto qv = q.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto xv = x.getLocalViewDevice(Tpetra::Access::ReadWrite);
      auto rv = r.getLocalViewDevice(Tpetra::Access::ReadWrite);
      blockedSum(
          "signorini::jacobiCG::update", n,
          KOKKOS_LAMBDA(const LO i, double& rr, double& rzNew) {
            xv(i, 0) += alpha * pv(i, 0);
            const double ri = rv(i, 0) - alpha * qv(i, 0);
            rv(i, 0) = ri;
            rr += ri * ri;
            rzNew += ri * ri * dv(i, 0);
          },
          sums[0], sums[1]);
    }
    sumAll(comm, sums);
    if (std::sqrt(sums[0]) <= target) return it;
    const double beta = sums[1] / rz;
    rz = sums[1];
    {
      auto rv = r.getLocalViewDevice(Tpetra::Access::ReadOnly);
      auto pv = p.getLocalViewDevice(Tpetra::Access::ReadWrite);
      Kokkos::parallel_for(
          "signorini::jacobiCG::direction", Kokkos::RangePolicy<ExecSpace>(0, n),
          KOKKOS_LAMBDA(const LO i) { pv(i, 0) = rv(i, 0) * dv(i, 0) + beta * pv(i, 0); });
    }
  }
  throw core::SolverError("Jacobi CG: no convergence to " + std::to_string(relativeTolerance) + " in " +
                          std::to_string(maxIterations) + " iterations");
}

}  // namespace signorini::solvers
