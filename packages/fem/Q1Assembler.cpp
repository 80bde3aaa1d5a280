#include "signorini/fem/Q1Assembler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/fem/AssemblyTools.hpp"
#include "signorini/fem/DirichletRowSums.hpp"
#include "signorini/fem/EntrySums.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/fem/Q1Kernels.hpp"
#include "signorini/core/ReproducibleLinearAlgebra.hpp"
#include "signorini/core/ReproducibleSum.hpp"

namespace signorini::fem {

namespace {
/// Whether overlap row \p row is among \p rows (flags per overlap row; empty: every row).
bool flagged(const std::vector<char>& rows, LO row) { return rows.empty() || rows[row]; }
}  // namespace

Q1Assembler::Q1Assembler(const mesh::Q1Mesh& mesh, std::vector<char> dirichlet)
    : mesh_(mesh), dirichlet_(std::move(dirichlet)) {
  const auto overlap = mesh.overlapMap();
  SIGNORINI_ASSERT(dirichlet_.size() == overlap->getNodeNumElements(), "Dirichlet flags do not match the mesh");
  dirichletView_ = deviceFlags(dirichlet_, dirichlet_.size(), "dirichlet");
  // Unknowns are nodes: the mesh's transfers serve the loads too.
  importer_ = Teuchos::rcpFromRef(mesh.ownedToOverlap());
  exporter_ = Teuchos::rcpFromRef(mesh.overlapToOwned());
  pattern_ = std::make_unique<Q1Pattern>(mesh, 1, mesh.ownedMap(), overlap);
}

Q1Assembler::~Q1Assembler() = default;

void Q1Assembler::elementStiffness(const ProblemData& problem, const double X[4][2], double Ke[8][8]) const {
  double Me[4][4], K[4][4];
  q1ElementMatrices(X, 0.0, problem.stiffness, Me, K);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) Ke[a][b] = K[a][b];
}

RCP<CrsMatrix> Q1Assembler::assembleOperator(double massCoeff, double stiffCoeff, double rho, double kappa,
                                             const std::vector<char>& lumpMassAt) const {
  // Where EntrySums are needed (reproducible arithmetic on several ranks) they give the rows that
  // other ranks' cells touch (all rows with threads); the pattern still gives the matrix (and the
  // identity rows of the Dirichlet unknowns).
  const bool exchange = needEntrySums(*mesh_.comm());
  const auto rows = exchangedRows();
  const bool kernel = !exchange || !rows.empty();  // not when EntrySums give every row (threads)
  auto A = pattern_->begin();
  if (kernel) assembleInto(A.local, A.local, massCoeff * rho, stiffCoeff * kappa, lumpMassAt);
  auto result = pattern_->end(A, dirichlet_);
  if (exchange) {
    std::vector<Contribution> both;
    cellContributions(massCoeff * rho, stiffCoeff * kappa, lumpMassAt, &both, &both, rows);
    canonicalSums(both).writeInto(*result, keptRows(rows));
  }
  if (core::reproducibleArithmetic()) registerCanonicalRowOrder(*result);
  return result;
}

std::pair<RCP<CrsMatrix>, RCP<CrsMatrix>> Q1Assembler::assembleMassAndStiffness(const ProblemData& problem,
                                                                                const std::vector<char>& lumpAt) const {
  const bool exchange = needEntrySums(*mesh_.comm());  // then the exchanged rows come from EntrySums
  const auto rows = exchangedRows();
  const bool kernel = !exchange || !rows.empty();  // not when EntrySums give every row (threads)
  auto M = pattern_->begin(), K = pattern_->begin();
  if (kernel) assembleInto(M.local, K.local, problem.density, problem.stiffness, lumpAt);
  std::pair<RCP<CrsMatrix>, RCP<CrsMatrix>> result{pattern_->end(M, dirichlet_), pattern_->end(K, dirichlet_)};
  if (exchange) {
    std::vector<Contribution> mass, stiffness;
    cellContributions(problem.density, problem.stiffness, lumpAt, &mass, &stiffness, rows);
    const auto keep = keptRows(rows);
    canonicalSums(mass).writeInto(*result.first, keep);
    canonicalSums(stiffness).writeInto(*result.second, keep);
  }
  if (core::reproducibleArithmetic()) registerCanonicalRowOrder(*result.first);  // K shares M's graph
  return result;
}

std::vector<char> Q1Assembler::exchangedRows() const {
  if (!needEntrySums(*mesh_.comm()) || kAtomicScatter) return {};
  return sharedRows(*mesh_.overlapMap(), mesh_.ownedToOverlap());
}

std::vector<char> Q1Assembler::keptRows(const std::vector<char>& exchanged) const {
  const size_t nOwned = mesh_.ownedMap()->getNodeNumElements();
  std::vector<char> keep(dirichlet_.begin(), dirichlet_.begin() + nOwned);
  if (!exchanged.empty())
    for (size_t i = 0; i < nOwned; ++i) keep[i] = keep[i] || !exchanged[i];
  return keep;
}

void Q1Assembler::registerCanonicalRowOrder(const CrsMatrix& A) const {
  std::vector<std::array<long long, 3>> keys(mesh_.ownedMap()->getNodeNumElements());
  for (size_t i = 0; i < keys.size(); ++i) {  // owned nodes come first in the overlap order
    const auto key = mesh_.canonicalKey(static_cast<LO>(i));
    keys[i] = {key[0], key[1], 0};
  }
  core::registerCanonicalRowOrder(A, keys);
}

EntrySums Q1Assembler::canonicalSums(const std::vector<Contribution>& contributions) const {
  return EntrySums(*mesh_.ownedMap(), *mesh_.overlapMap(), mesh_.ownedToOverlap(), contributions);
}

void Q1Assembler::cellContributions(double cm, double ck, const std::vector<char>& lumpMassAt,
                                    std::vector<Contribution>* mass, std::vector<Contribution>* stiffness,
                                    const std::vector<char>& onlyRows) const {
  const auto& X = mesh_.cornerCoordsHost;
  const auto& dofs = mesh_.cornerDofsHost;
  const auto& wts = mesh_.cornerWeightsHost;
  const auto overlap = mesh_.overlapMap();
  const bool anyLump = std::any_of(lumpMassAt.begin(), lumpMassAt.end(), [](char f) { return f != 0; });
  const size_t perCell = mass == stiffness ? 32 : 16;  // 16 couplings per cell without hanging corners
  mass->reserve(mass->size() + perCell * static_cast<size_t>(mesh_.numLocalCells()));
  stiffness->reserve(stiffness->size() + perCell * static_cast<size_t>(mesh_.numLocalCells()));
  auto wanted = [&](LO row) { return row >= 0 && !dirichlet_[row] && flagged(onlyRows, row); };
  for (LO e = 0; e < mesh_.numLocalCells(); ++e) {
    bool any = false;
    for (int a = 0; a < 4; ++a)
      for (int ka = 0; ka < 2; ++ka) any = any || wanted(dofs(e, a, ka));
    if (!any) continue;
    double Xe[4][2], Ke[4][4], Me[4][4];
    for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
    q1ElementMatrices(Xe, cm, ck, Me, Ke);
    for (int a = 0; a < 4; ++a)
      for (int ka = 0; ka < 2; ++ka) {
        const LO row = dofs(e, a, ka);
        if (!wanted(row)) continue;
        for (int b = 0; b < 4; ++b)
          for (int kb = 0; kb < 2; ++kb) {
            const LO dof = dofs(e, b, kb);
            if (dof < 0) continue;
            const double wab = wts(e, a, ka) * wts(e, b, kb);
            const bool lumped = anyLump && row != dof && (lumpMassAt[row] || lumpMassAt[dof]);
            if (dirichlet_[dof]) {  // as assembleInto: a lumped coupling stays on the diagonal
              if (lumped) mass->push_back({row, overlap->getGlobalElement(row), wab * Me[a][b]});
              continue;
            }
            mass->push_back({row, overlap->getGlobalElement(lumped ? row : dof), wab * Me[a][b]});
            stiffness->push_back({row, overlap->getGlobalElement(dof), wab * Ke[a][b]});
          }
      }
  }
}

void Q1Assembler::assembleInto(const LocalMatrix& one, const LocalMatrix& two, double cm, double ck,
                               const std::vector<char>& lumpMassAt) const {
  const auto lump = deviceFlags(lumpMassAt, dirichlet_.size(), "lump");
  const bool anyLump = std::any_of(lumpMassAt.begin(), lumpMassAt.end(), [](char f) { return f != 0; });
  const auto toCol = pattern_->toColumn();
  SIGNORINI_ASSERT(one.graph.entries.data() == two.graph.entries.data(), "both matrices on one pattern");
  const auto rowPtr = one.graph.row_map;
  const auto cols = one.graph.entries;
  const auto v1 = one.values, v2 = two.values;
  const auto X = mesh_.cornerCoords;
  const auto dofs = mesh_.cornerDofs;
  const auto wts = mesh_.cornerWeights;
  const auto dir = dirichletView_;
  Kokkos::parallel_for(
      "signorini::assembleOperator", Kokkos::RangePolicy<ExecSpace>(0, mesh_.numLocalCells()),
      KOKKOS_LAMBDA(const LO e) {
        double Xe[4][2], Ke[4][4], Me[4][4];
        for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
        q1ElementMatrices(Xe, cm, ck, Me, Ke);
        auto add = [&](const decltype(v1)& values, size_t at, double v) {
          if (kAtomicScatter)
            Kokkos::atomic_add(&values(at), v);
          else
            values(at) += v;
        };
        for (int a = 0; a < 4; ++a)
          for (int ka = 0; ka < 2; ++ka) {
            const LO row = dofs(e, a, ka);
            if (row < 0 || dir(row)) continue;
            const auto rowBegin = rowPtr(row), rowEnd = rowPtr(row + 1);
            auto offset = [&](LO col) {
              auto at = rowBegin;
              while (at < rowEnd && cols(at) != col) ++at;
              if (at == rowEnd) Kokkos::abort("signorini::assembleOperator: coupling missing from the Q1 graph");
              return at;
            };
            for (int b = 0; b < 4; ++b)
              for (int kb = 0; kb < 2; ++kb) {
                const LO dof = dofs(e, b, kb);
                if (dof < 0) continue;
                const double wab = wts(e, a, ka) * wts(e, b, kb);
                if (dir(dof)) {  // eliminated; lumped before the elimination, its mass coupling stays on the diagonal
                  if (anyLump && (lump(row) || lump(dof))) add(v1, offset(toCol(row)), wab * Me[a][b]);
                  continue;
                }
                const auto at = offset(toCol(dof));
                const double m = wab * Me[a][b];
                // lumped: the mass coupling moves to the diagonal
                const auto massAt = anyLump && row != dof && (lump(row) || lump(dof)) ? offset(toCol(row)) : at;
                add(v1, massAt, m);
                add(v2, at, wab * Ke[a][b]);
              }
          }
      });
}

namespace {
/// f sampled at the 2x2 Gauss points of every local cell (host evaluation of the expression).
Kokkos::View<double* [4], DeviceType> sampleAtGaussPoints(const mesh::Q1Mesh& mesh, const core::Expression& f, double t) {
  const LO nc = mesh.numLocalCells();
  Kokkos::View<double* [4], DeviceType> fq("fq", nc);
  auto h = Kokkos::create_mirror_view(fq);
  const auto& X = mesh.cornerCoordsHost;
  std::string bad;  // the first sample that is not a finite number (constants were checked when parsed)
  for (LO e = 0; e < nc; ++e)
    for (int q = 0; q < 4; ++q) {
      if (f.isConstant()) {
        h(e, q) = f(0, 0, 0);
        continue;
      }
      double N[4], ds[4], dr[4];
      q1Shape(gauss2Point(q & 1), gauss2Point(q >> 1), N, ds, dr);
      double x = 0, y = 0;
      for (int c = 0; c < 4; ++c) x += N[c] * X(e, c, 0), y += N[c] * X(e, c, 1);
      h(e, q) = f.sample(x, y, t, bad);
    }
  if (!f.isConstant()) core::throwFirstUserError(*mesh.comm(), bad);
  Kokkos::deep_copy(fq, h);
  return fq;
}
}  // namespace

void Q1Assembler::assembleLoad(const core::Expression& f, double t, double scale, Vector& out, bool accumulate) const {
  Vector overlap(mesh_.overlapMap());
  Kokkos::View<double* [4], DeviceType> cellLoads("cellLoads", mesh_.numLocalCells());
  {
    const auto fq = sampleAtGaussPoints(mesh_, f, t);
    auto y = overlap.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(y, 0.0);
    const auto X = mesh_.cornerCoords;
    const auto dofs = mesh_.cornerDofs;
    const auto wts = mesh_.cornerWeights;
    const auto dir = dirichletView_;
    Kokkos::parallel_for(
        "signorini::assembleLoad", Kokkos::RangePolicy<ExecSpace>(0, mesh_.numLocalCells()),
        KOKKOS_LAMBDA(const LO e) {
          double Xe[4][2], be[4] = {};
          for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
          for (int q = 0; q < 4; ++q) {
            double N[4], gx[4], gy[4];
            const double w = kGauss2Weight * kGauss2Weight *
                             q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, gx, gy);
            for (int a = 0; a < 4; ++a) be[a] += w * scale * fq(e, q) * N[a];
          }
          for (int a = 0; a < 4; ++a) {
            cellLoads(e, a) = be[a];
            for (int k = 0; k < 2; ++k) {
              const LO row = dofs(e, a, k);
              if (row >= 0 && !dir(row)) Kokkos::atomic_add(&y(row, 0), wts(e, a, k) * be[a]);
            }
          }
        });
  }
  if (needEntrySums(*mesh_.comm())) {
    const auto loads = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cellLoads);
    const auto shared = exchangedRows();  // empty: EntrySums give every row
    std::vector<Contribution> contributions;
    for (LO e = 0; e < mesh_.numLocalCells(); ++e)
      for (int a = 0; a < 4; ++a)
        for (int k = 0; k < 2; ++k) {
          const LO row = mesh_.cornerDofsHost(e, a, k);
          if (row >= 0 && !dirichlet_[row] && flagged(shared, row))
            contributions.push_back({row, 0, mesh_.cornerWeightsHost(e, a, k) * loads(e, a)});
        }
    canonicalSums(contributions).writeInto(out, accumulate, shared, &overlap);
    return;
  }
  addExported(overlap, *exporter_, out, accumulate);
}

void Q1Assembler::addBoundaryLoad(const core::Expression& q, double t, unsigned mask, double scale, Vector& out) const {
  if (mask == 0) return;
  // Edges of the segments in mask with q sampled at 2 Gauss points (host), integrated by a kernel.
  std::vector<int> ids;
  for (size_t i = 0; i < mesh_.boundaryEdges().size(); ++i)
    if (mesh_.boundaryEdges()[i].segments & mask) ids.push_back(static_cast<int>(i));
  const LO ne = static_cast<LO>(ids.size());
  Kokkos::View<double* [2], DeviceType> qg("qg", ne);
  Kokkos::View<double*, DeviceType> len("len", ne);
  Kokkos::View<LO* [2], DeviceType> nodes("nodes", ne);
  std::string bad;
  {
    auto qh = Kokkos::create_mirror_view(qg);
    auto lh = Kokkos::create_mirror_view(len);
    auto nh = Kokkos::create_mirror_view(nodes);
    for (LO k = 0; k < ne; ++k) {
      const auto& be = mesh_.boundaryEdges()[ids[k]];
      for (int g = 0; g < 2; ++g) {
        const double s = gauss2Point(g);
        qh(k, g) = q.sample((1 - s) * be.x[0][0] + s * be.x[1][0], (1 - s) * be.x[0][1] + s * be.x[1][1], t, bad);
        nh(k, g) = be.node[g];
      }
      lh(k) = be.length();
    }
    core::throwFirstUserError(*mesh_.comm(), bad);
    Kokkos::deep_copy(qg, qh);
    Kokkos::deep_copy(len, lh);
    Kokkos::deep_copy(nodes, nh);
  }
  Vector overlap(mesh_.overlapMap());
  // Per edge, Gauss point and end point: the contribution to the end point's row.
  Kokkos::View<double* [2][2], DeviceType> edgeLoads("edgeLoads", ne);
  {
    auto y = overlap.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(y, 0.0);
    const auto dir = dirichletView_;
    Kokkos::parallel_for(
        "signorini::boundaryLoad", Kokkos::RangePolicy<ExecSpace>(0, ne), KOKKOS_LAMBDA(const LO k) {
          for (int g = 0; g < 2; ++g) {
            const double s = gauss2Point(g), v = scale * kGauss2Weight * len(k) * qg(k, g);
            edgeLoads(k, g, 0) = v * (1 - s);
            edgeLoads(k, g, 1) = v * s;
            if (!dir(nodes(k, 0))) Kokkos::atomic_add(&y(nodes(k, 0), 0), v * (1 - s));
            if (!dir(nodes(k, 1))) Kokkos::atomic_add(&y(nodes(k, 1), 0), v * s);
          }
        });
  }
  if (needEntrySums(*mesh_.comm())) {
    const auto loads = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), edgeLoads);
    const auto nh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), nodes);
    const auto shared = exchangedRows();  // empty: EntrySums give every row
    std::vector<Contribution> contributions;
    for (LO k = 0; k < ne; ++k)
      for (int g = 0; g < 2; ++g)
        for (int end = 0; end < 2; ++end) {
          const LO row = nh(k, end);
          if (!dirichlet_[row] && flagged(shared, row)) contributions.push_back({row, 0, loads(k, g, end)});
        }
    canonicalSums(contributions).writeInto(out, true, shared, &overlap);
    return;
  }
  addExported(overlap, *exporter_, out, true);
}

DirichletRowsInput Q1Assembler::rowsInput(const ProblemData& problem, const std::vector<char>& lumpAt) const {
  DirichletRowsInput in;
  in.mesh = &mesh_;
  in.held = &dirichlet_;
  in.lumped = &lumpAt;
  const double rho = problem.density, kappa = problem.stiffness;
  in.element = [rho, kappa](const double X[4][2], double Me[4][4], double Ke[8][8]) {
    double K4[4][4];
    q1ElementMatrices(X, rho, kappa, Me, K4);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) Ke[a][b] = K4[a][b];
  };
  in.bodyForce = &problem.bodyForce;
  in.neumann = &problem.neumannData;
  in.neumannMask = problem.neumannMask;
  return in;
}

std::vector<double> Q1Assembler::dirichletRowSums(const Vector& uOverlap, const Vector& aOverlap,
                                                  const ProblemData& problem, double t,
                                                  const std::vector<char>& lumpAt,
                                                  const std::array<double, 2>* momentPoint,
                                                  const std::vector<char>* rows) const {
  SIGNORINI_ASSERT(!momentPoint, "the scalar problem has no moments");
  auto in = rowsInput(problem, lumpAt);
  in.rows = rows;
  return sumDirichletRows(in, uOverlap, aOverlap, t);
}

void Q1Assembler::massBeforeElimination(const Vector& wOverlap, const ProblemData& problem,
                                        const std::vector<char>& lumpAt, Vector& out) const {
  Vector contributions(overlapMap());
  massTimesField(rowsInput(problem, lumpAt), wOverlap, contributions);
  addExported(contributions, *exporter_, out, false);
}

void Q1Assembler::zeroDirichlet(Vector& v) const {
  auto h = v.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (size_t i = 0; i < h.extent(0); ++i)
    if (dirichlet_[i]) h(i, 0) = 0.0;
}

void Q1Assembler::toOverlap(const Vector& owned, Vector& overlap) const {
  overlap.doImport(owned, *importer_, Tpetra::INSERT);
}

std::pair<double, double> Q1Assembler::errorNorms(const Vector& uOwned, const core::Expression& exact, double t) const {
  Vector u(mesh_.overlapMap());
  toOverlap(uOwned, u);
  auto uh = u.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& X = mesh_.cornerCoordsHost;
  const auto& dofs = mesh_.cornerDofsHost;
  const auto& wts = mesh_.cornerWeightsHost;
  const auto& gp = kGauss3Point;
  const auto& gw = kGauss3Weight;
  const double eps = 1e-6 * mesh_.hMin();
  double l2 = 0, h1 = 0;
  std::vector<double> cellL2, cellH1;  // per cell, for reproducible sums
  std::string bad;                     // the first sample of the exact solution that is not a finite number
  for (LO e = 0; e < mesh_.numLocalCells(); ++e) {
    const double l2Before = l2, h1Before = h1;
    double Xe[4][2], ue[4];
    for (int c = 0; c < 4; ++c) {
      Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
      ue[c] = 0;
      for (int k = 0; k < 2; ++k)
        if (dofs(e, c, k) >= 0) ue[c] += wts(e, c, k) * uh(dofs(e, c, k), 0);
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double N[4], gx[4], gy[4];
        const double w = gw[i] * gw[j] * q1Gradients(Xe, gp[i], gp[j], N, gx, gy);
        double x = 0, y = 0, v = 0, vx = 0, vy = 0;
        for (int c = 0; c < 4; ++c) {
          x += N[c] * Xe[c][0], y += N[c] * Xe[c][1];
          v += N[c] * ue[c], vx += gx[c] * ue[c], vy += gy[c] * ue[c];
        }
        const double d = v - exact.sample(x, y, t, bad);
        const double dx = vx - (exact.sample(x + eps, y, t, bad) - exact.sample(x - eps, y, t, bad)) / (2 * eps);
        const double dy = vy - (exact.sample(x, y + eps, t, bad) - exact.sample(x, y - eps, t, bad)) / (2 * eps);
        l2 += w * d * d;
        h1 += w * (dx * dx + dy * dy);
      }
    if (core::reproducibleArithmetic()) {  // the cell's own sums, from zero
      cellL2.push_back(l2 - l2Before), cellH1.push_back(h1 - h1Before);
      l2 = h1 = 0;
    }
  }
  core::throwFirstUserError(*mesh_.comm(), bad);
  double local[2] = {l2, h1}, global[2];
  if (core::reproducibleArithmetic())
    core::reproducibleSums(
        *mesh_.comm(), 2, cellL2.size(), [&](size_t e, double* t) { t[0] = cellL2[e], t[1] = cellH1[e]; }, global);
  else
    Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, 2, local, global);
  return {std::sqrt(global[0]), std::sqrt(global[1])};
}

double Q1Assembler::evaluate(const Vector& uOverlap, double x, double y) const {
  double s, r;
  const LO e = mesh_.locate(x, y, s, r);
  double local[2] = {0, 0}, global[2];
  if (e >= 0) {
    auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    double N[4], ds[4], dr[4];
    q1Shape(s, r, N, ds, dr);
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 2; ++k)
        if (mesh_.cornerDofsHost(e, c, k) >= 0)
          local[0] += N[c] * mesh_.cornerWeightsHost(e, c, k) * uh(mesh_.cornerDofsHost(e, c, k), 0);
    local[1] = 1;
  }
  if (core::reproducibleArithmetic()) {  // the value of the lowest rank that has the point, as on one rank
    const int rank = mesh_.comm()->getRank();
    int finder = e >= 0 ? rank : mesh_.comm()->getSize(), first;
    Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_MIN, finder, Teuchos::outArg(first));
    if (first == mesh_.comm()->getSize()) return std::numeric_limits<double>::quiet_NaN();
    double value = rank == first ? local[0] : 0.0;
    Teuchos::broadcast(*mesh_.comm(), first, Teuchos::outArg(value));
    return value;
  }
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, 2, local, global);
  return global[1] > 0 ? global[0] / global[1] : std::numeric_limits<double>::quiet_NaN();
}

double Q1Assembler::area() const {
  double a = 0;
  const auto X = mesh_.cornerCoords;
  Kokkos::parallel_reduce(
      "signorini::area", Kokkos::RangePolicy<ExecSpace>(0, mesh_.numLocalCells()),
      KOKKOS_LAMBDA(const LO e, double& sum) {
        double Xe[4][2];
        for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
        for (int q = 0; q < 4; ++q) {
          double N[4], gx[4], gy[4];
          sum += kGauss2Weight * kGauss2Weight * q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, gx, gy);
        }
      },
      a);
  double g;
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, a, Teuchos::outArg(g));
  return g;
}

}  // namespace signorini::fem
