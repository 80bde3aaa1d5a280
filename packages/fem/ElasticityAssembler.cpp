#include "signorini/fem/ElasticityAssembler.hpp"

#include <cmath>
#include <algorithm>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/fem/AssemblyTools.hpp"
#include "signorini/fem/DirichletRowSums.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/fem/Q1Kernels.hpp"

namespace signorini::fem {

namespace {

/// The map of unknowns (2 g, 2 g + 1) of a node map, in the node map's local order.
RCP<const Map> unknownsOf(const RCP<const Map>& nodes) {
  const LO n = static_cast<LO>(nodes->getNodeNumElements());
  std::vector<GO> gids(2 * static_cast<size_t>(n));
  for (LO i = 0; i < n; ++i) {
    const GO g = nodes->getGlobalElement(i);
    gids[2 * i] = 2 * g;
    gids[2 * i + 1] = 2 * g + 1;
  }
  return Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                              Teuchos::ArrayView<const GO>(gids), nodes->getIndexBase(), nodes->getComm()));
}

/// Corner values of component c of cell e from host overlap values.
template <class View>
void cornerValues(const mesh::Q1Mesh& mesh, const View& uh, LO e, int c, double out[4]) {
  for (int a = 0; a < 4; ++a) {
    out[a] = 0;
    for (int k = 0; k < 2; ++k)
      if (mesh.cornerDofsHost(e, a, k) >= 0)
        out[a] += mesh.cornerWeightsHost(e, a, k) * uh(2 * mesh.cornerDofsHost(e, a, k) + c, 0);
  }
}

/// The element mass (times cm, one block for both components) and stiffness (Lame parameters cl and
/// cmu; Ke[2 a + i][2 b + j]) of the cell with corners Xe, by 2 x 2 Gauss.
KOKKOS_INLINE_FUNCTION void elasticElementMatrices(const double Xe[4][2], double cm, double cl, double cmu,
                                                   double Me[4][4], double Ke[8][8]) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) Me[a][b] = 0.0;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) Ke[a][b] = 0.0;
  for (int q = 0; q < 4; ++q) {
    double N[4], g[2][4];
    const double w =
        kGauss2Weight * kGauss2Weight * q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, g[0], g[1]);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        Me[a][b] += w * cm * N[a] * N[b];
        const double dot = g[0][a] * g[0][b] + g[1][a] * g[1][b];
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            Ke[2 * a + i][2 * b + j] += w * (cl * g[i][a] * g[j][b] + cmu * (g[j][a] * g[i][b] + (i == j ? dot : 0.0)));
      }
  }
}

}  // namespace

void ElasticityAssembler::elementStiffness(const ProblemData&, const double X[4][2], double Ke[8][8]) const {
  double Me[4][4];
  elasticElementMatrices(X, 0.0, lambda_, mu_, Me, Ke);
}

DirichletRowsInput ElasticityAssembler::rowsInput(const ProblemData& problem, const std::vector<char>& lumpAt) const {
  DirichletRowsInput in;
  in.mesh = &mesh_;
  in.components = 2;
  in.held = &dirichlet_;
  in.lumped = &lumpAt;
  const double rho = problem.density, cl = lambda_, cmu = mu_;
  in.element = [rho, cl, cmu](const double X[4][2], double Me[4][4], double Ke[8][8]) {
    elasticElementMatrices(X, rho, cl, cmu, Me, Ke);
  };
  in.bodyForce = &problem.bodyForce;
  in.neumann = &problem.neumannData;
  in.neumannMask = problem.neumannMask;
  return in;
}

std::vector<double> ElasticityAssembler::dirichletRowSums(const Vector& uOverlap, const Vector& aOverlap,
                                                          const ProblemData& problem, double t,
                                                          const std::vector<char>& lumpAt,
                                                          const std::array<double, 2>* momentPoint,
                                                          const std::vector<char>* rows) const {
  auto in = rowsInput(problem, lumpAt);
  in.momentPoint = momentPoint;
  in.rows = rows;
  return sumDirichletRows(in, uOverlap, aOverlap, t);
}

void ElasticityAssembler::massBeforeElimination(const Vector& wOverlap, const ProblemData& problem,
                                                const std::vector<char>& lumpAt, Vector& out) const {
  Vector contributions(overlapMap_);
  massTimesField(rowsInput(problem, lumpAt), wOverlap, contributions);
  addExported(contributions, *exporter_, out, false);
}

std::vector<char> ElasticityAssembler::dirichletUnknowns(const mesh::Q1Mesh& mesh, const ProblemData& problem) {
  const auto all = mesh.nodesOnSegments(problem.dirichletMask);
  const auto onlyX = mesh.nodesOnSegments(problem.componentDirichletMask[0]);
  const auto onlyY = mesh.nodesOnSegments(problem.componentDirichletMask[1]);
  std::vector<char> flags(2 * all.size(), 0);
  for (size_t i = 0; i < all.size(); ++i) {
    flags[2 * i] = all[i] || onlyX[i];
    flags[2 * i + 1] = all[i] || onlyY[i];
  }
  return flags;
}

ElasticityAssembler::ElasticityAssembler(const mesh::Q1Mesh& mesh, std::vector<char> dirichlet, double lambda,
                                         double mu)
    : mesh_(mesh), dirichlet_(std::move(dirichlet)), lambda_(lambda), mu_(mu) {
  ownedMap_ = unknownsOf(mesh.ownedMap());
  overlapMap_ = unknownsOf(mesh.overlapMap());
  SIGNORINI_ASSERT(dirichlet_.size() == overlapMap_->getNodeNumElements(), "Dirichlet flags do not match the mesh");
  dirichletView_ = deviceFlags(dirichlet_, dirichlet_.size(), "dirichlet");
  importer_ = Teuchos::rcp(new Tpetra::Import<LO, GO, Node>(ownedMap_, overlapMap_));
  exporter_ = Teuchos::rcp(new Tpetra::Export<LO, GO, Node>(*importer_));
  pattern_ = std::make_unique<Q1Pattern>(mesh, 2, ownedMap_, overlapMap_);
}

ElasticityAssembler::~ElasticityAssembler() = default;

RCP<CrsMatrix> ElasticityAssembler::assembleOperator(double massCoeff, double stiffCoeff, double rho,
                                                     const std::vector<char>& lumpAt) const {
  const auto lump = deviceFlags(lumpAt, dirichlet_.size(), "lump");
  auto A = pattern_->begin();
  {
    const auto toCol = pattern_->toColumn();
    auto local = A.local;
    const auto X = mesh_.cornerCoords;
    const auto dofs = mesh_.cornerDofs;
    const auto wts = mesh_.cornerWeights;
    const auto dir = dirichletView_;
    const double cm = massCoeff * rho, cl = stiffCoeff * lambda_, cmu = stiffCoeff * mu_;
    Kokkos::parallel_for(
        "signorini::assembleElasticity", Kokkos::RangePolicy<ExecSpace>(0, mesh_.numLocalCells()),
        KOKKOS_LAMBDA(const LO e) {
          double Xe[4][2], Ke[8][8], Me[4][4];
          for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
          elasticElementMatrices(Xe, cm, cl, cmu, Me, Ke);
          for (int a = 0; a < 4; ++a)
            for (int ka = 0; ka < 2; ++ka) {
              const LO na = dofs(e, a, ka);
              if (na < 0) continue;
              for (int i = 0; i < 2; ++i) {
                const LO row = 2 * na + i;
                if (dir(row)) continue;
                for (int b = 0; b < 4; ++b)
                  for (int kb = 0; kb < 2; ++kb) {
                    const LO nb = dofs(e, b, kb);
                    if (nb < 0) continue;
                    const double wab = wts(e, a, ka) * wts(e, b, kb);
                    for (int j = 0; j < 2; ++j) {
                      const LO unknown = 2 * nb + j;
                      if (dir(unknown)) {  // eliminated; lumped before the elimination, its mass coupling stays on the diagonal
                        if (i == j && (lump(row) || lump(unknown))) {
                          LO diag = toCol(row);
                          double m = wab * Me[a][b];
                          local.sumIntoValues(row, &diag, 1, &m, false, kAtomicScatter);
                        }
                        continue;
                      }
                      LO col = toCol(unknown);
                      double v = wab * Ke[2 * a + i][2 * b + j];
                      if (i == j) {
                        double m = wab * Me[a][b];
                        if (row != unknown && (lump(row) || lump(unknown))) {  // mass coupling to the diagonal
                          LO diag = toCol(row);
                          local.sumIntoValues(row, &diag, 1, &m, false, kAtomicScatter);
                        } else {
                          v += m;
                        }
                      }
                      local.sumIntoValues(row, &col, 1, &v, false, kAtomicScatter);
                    }
                  }
              }
            }
        });
  }
  return pattern_->end(A, dirichlet_);
}

void ElasticityAssembler::assembleLoad(const core::ExpressionList& f, double t, double scale, Vector& out,
                                       bool accumulate) const {
  SIGNORINI_ASSERT(f.size() == 2, "elasticity loads have two components");
  const LO nc = mesh_.numLocalCells();
  Kokkos::View<double* [4][2], DeviceType> fq("fq", nc);
  {
    auto h = Kokkos::create_mirror_view(fq);
    const auto& X = mesh_.cornerCoordsHost;
    std::string bad;  // the first sample that is not a finite number
    for (LO e = 0; e < nc; ++e)
      for (int q = 0; q < 4; ++q) {
        double N[4], ds[4], dr[4];
        q1Shape(gauss2Point(q & 1), gauss2Point(q >> 1), N, ds, dr);
        double x = 0, y = 0;
        for (int c = 0; c < 4; ++c) x += N[c] * X(e, c, 0), y += N[c] * X(e, c, 1);
        for (int c = 0; c < 2; ++c) h(e, q, c) = f[c].sample(x, y, t, bad);
      }
    if (!f.isConstant()) core::throwFirstUserError(*mesh_.comm(), bad);
    Kokkos::deep_copy(fq, h);
  }
  Vector overlap(overlapMap_);
  {
    auto y = overlap.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(y, 0.0);
    const auto X = mesh_.cornerCoords;
    const auto dofs = mesh_.cornerDofs;
    const auto wts = mesh_.cornerWeights;
    const auto dir = dirichletView_;
    Kokkos::parallel_for(
        "signorini::assembleElasticityLoad", Kokkos::RangePolicy<ExecSpace>(0, nc), KOKKOS_LAMBDA(const LO e) {
          double Xe[4][2], be[4][2] = {};
          for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
          for (int q = 0; q < 4; ++q) {
            double N[4], gx[4], gy[4];
            const double w = kGauss2Weight * kGauss2Weight *
                             q1Gradients(Xe, gauss2Point(q & 1), gauss2Point(q >> 1), N, gx, gy);
            for (int a = 0; a < 4; ++a)
              for (int c = 0; c < 2; ++c) be[a][c] += w * scale * fq(e, q, c) * N[a];
          }
          for (int a = 0; a < 4; ++a)
            for (int k = 0; k < 2; ++k) {
              const LO n = dofs(e, a, k);
              if (n < 0) continue;
              for (int c = 0; c < 2; ++c)
                if (!dir(2 * n + c)) Kokkos::atomic_add(&y(2 * n + c, 0), wts(e, a, k) * be[a][c]);
            }
        });
  }
  addExported(overlap, *exporter_, out, accumulate);
}

void ElasticityAssembler::addBoundaryLoad(const core::ExpressionList& q, double t, unsigned mask, double scale,
                                          Vector& out) const {
  SIGNORINI_ASSERT(q.size() == 2, "tractions have two components");
  if (mask == 0) return;
  std::vector<int> ids;
  for (size_t i = 0; i < mesh_.boundaryEdges().size(); ++i)
    if (mesh_.boundaryEdges()[i].segments & mask) ids.push_back(static_cast<int>(i));
  const LO ne = static_cast<LO>(ids.size());
  Kokkos::View<double* [2][2], DeviceType> qg("qg", ne);
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
        for (int c = 0; c < 2; ++c)
          qh(k, g, c) = q[c].sample((1 - s) * be.x[0][0] + s * be.x[1][0], (1 - s) * be.x[0][1] + s * be.x[1][1], t, bad);
        nh(k, g) = be.node[g];
      }
      lh(k) = be.length();
    }
    core::throwFirstUserError(*mesh_.comm(), bad);
    Kokkos::deep_copy(qg, qh);
    Kokkos::deep_copy(len, lh);
    Kokkos::deep_copy(nodes, nh);
  }
  Vector overlap(overlapMap_);
  {
    auto y = overlap.getLocalViewDevice(Tpetra::Access::OverwriteAll);
    Kokkos::deep_copy(y, 0.0);
    const auto dir = dirichletView_;
    Kokkos::parallel_for(
        "signorini::elasticityTraction", Kokkos::RangePolicy<ExecSpace>(0, ne), KOKKOS_LAMBDA(const LO k) {
          for (int g = 0; g < 2; ++g) {
            const double s = gauss2Point(g);
            for (int c = 0; c < 2; ++c) {
              const double v = scale * kGauss2Weight * len(k) * qg(k, g, c);
              const LO r0 = 2 * nodes(k, 0) + c, r1 = 2 * nodes(k, 1) + c;
              if (!dir(r0)) Kokkos::atomic_add(&y(r0, 0), v * (1 - s));
              if (!dir(r1)) Kokkos::atomic_add(&y(r1, 0), v * s);
            }
          }
        });
  }
  addExported(overlap, *exporter_, out, true);
}

void ElasticityAssembler::zeroDirichlet(Vector& v) const {
  auto h = v.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (size_t i = 0; i < h.extent(0); ++i)
    if (dirichlet_[i]) h(i, 0) = 0.0;
}

void ElasticityAssembler::toOverlap(const Vector& owned, Vector& overlap) const {
  overlap.doImport(owned, *importer_, Tpetra::INSERT);
}

std::pair<double, double> ElasticityAssembler::errorNorms(const Vector& uOwned, const core::ExpressionList& exact,
                                                          double t) const {
  SIGNORINI_ASSERT(exact.size() == 2, "the exact displacement has two components");
  Vector u(overlapMap_);
  toOverlap(uOwned, u);
  auto uh = u.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& X = mesh_.cornerCoordsHost;
  const auto& gp = kGauss3Point;
  const auto& gw = kGauss3Weight;
  const double eps = 1e-6 * mesh_.hMin();
  double l2 = 0, h1 = 0;
  std::string bad;  // the first sample of the exact solution that is not a finite number
  for (LO e = 0; e < mesh_.numLocalCells(); ++e) {
    double Xe[4][2], ue[2][4];
    for (int c = 0; c < 4; ++c) Xe[c][0] = X(e, c, 0), Xe[c][1] = X(e, c, 1);
    for (int c = 0; c < 2; ++c) cornerValues(mesh_, uh, e, c, ue[c]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double N[4], gx[4], gy[4];
        const double w = gw[i] * gw[j] * q1Gradients(Xe, gp[i], gp[j], N, gx, gy);
        double x = 0, y = 0;
        for (int a = 0; a < 4; ++a) x += N[a] * Xe[a][0], y += N[a] * Xe[a][1];
        for (int c = 0; c < 2; ++c) {
          double v = 0, vx = 0, vy = 0;
          for (int a = 0; a < 4; ++a) v += N[a] * ue[c][a], vx += gx[a] * ue[c][a], vy += gy[a] * ue[c][a];
          const auto& f = exact[c];
          const double d = v - f.sample(x, y, t, bad);
          const double dx = vx - (f.sample(x + eps, y, t, bad) - f.sample(x - eps, y, t, bad)) / (2 * eps);
          const double dy = vy - (f.sample(x, y + eps, t, bad) - f.sample(x, y - eps, t, bad)) / (2 * eps);
          l2 += w * d * d;
          h1 += w * (dx * dx + dy * dy);
        }
      }
  }
  core::throwFirstUserError(*mesh_.comm(), bad);
  double local[2] = {l2, h1}, global[2];
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, 2, local, global);
  return {std::sqrt(global[0]), std::sqrt(global[1])};
}

double ElasticityAssembler::evaluateComponent(const Vector& uOverlap, double x, double y, int c) const {
  double s, r;
  const LO e = mesh_.locate(x, y, s, r);
  double local[2] = {0, 0}, global[2];
  if (e >= 0) {
    auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    double N[4], ds[4], dr[4], ue[4];
    q1Shape(s, r, N, ds, dr);
    cornerValues(mesh_, uh, e, c, ue);
    for (int a = 0; a < 4; ++a) local[0] += N[a] * ue[a];
    local[1] = 1;
  }
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, 2, local, global);
  return global[1] > 0 ? global[0] / global[1] : std::numeric_limits<double>::quiet_NaN();
}

RCP<MultiVector> ElasticityAssembler::rigidBodyModes() const {
  const LO n = static_cast<LO>(mesh_.ownedMap()->getNodeNumElements());
  // Rotation about the centroid of the owned nodes of all ranks keeps the modes well scaled.
  double local[3] = {0, 0, static_cast<double>(n)}, global[3];
  for (LO i = 0; i < n; ++i) local[0] += mesh_.nodeCoords()[i][0], local[1] += mesh_.nodeCoords()[i][1];
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_SUM, 3, local, global);
  const double xc = global[0] / std::max(global[2], 1.0), yc = global[1] / std::max(global[2], 1.0);
  auto modes = Teuchos::rcp(new MultiVector(ownedMap_, 3));
  auto h = modes->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < n; ++i) {
    const double x = mesh_.nodeCoords()[i][0] - xc, y = mesh_.nodeCoords()[i][1] - yc;
    h(2 * i, 0) = 1, h(2 * i + 1, 0) = 0;
    h(2 * i, 1) = 0, h(2 * i + 1, 1) = 1;
    h(2 * i, 2) = -y, h(2 * i + 1, 2) = x;
  }
  return modes;
}

std::array<double, 3> ElasticityAssembler::strainAt(const Vector& uOverlap, LO e, double s, double r) const {
  auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double Xe[4][2], ue[2][4], N[4], gx[4], gy[4];
  for (int c = 0; c < 4; ++c) Xe[c][0] = mesh_.cornerCoordsHost(e, c, 0), Xe[c][1] = mesh_.cornerCoordsHost(e, c, 1);
  for (int c = 0; c < 2; ++c) cornerValues(mesh_, uh, e, c, ue[c]);
  q1Gradients(Xe, s, r, N, gx, gy);
  double du[2][2] = {};  // du[i][j] = d u_i / d x_j
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i) du[i][0] += gx[a] * ue[i][a], du[i][1] += gy[a] * ue[i][a];
  return {du[0][0], du[1][1], 0.5 * (du[0][1] + du[1][0])};
}

std::array<double, 3> ElasticityAssembler::stressAt(const Vector& uOverlap, LO e, double s, double r) const {
  const auto [exx, eyy, exy] = strainAt(uOverlap, e, s, r);
  const double tr = exx + eyy;
  return {lambda_ * tr + 2 * mu_ * exx, lambda_ * tr + 2 * mu_ * eyy, 2 * mu_ * exy};
}

std::array<std::vector<double>, 3> ElasticityAssembler::cellCentreStrains(const Vector& uOverlap) const {
  const LO nc = mesh_.numLocalCells();
  std::array<std::vector<double>, 3> out;
  for (auto& v : out) v.resize(nc);
  for (LO e = 0; e < nc; ++e) {
    const auto strain = strainAt(uOverlap, e, 0.5, 0.5);
    for (int q = 0; q < 3; ++q) out[q][e] = strain[q];
  }
  return out;
}

std::array<double, 5> ElasticityAssembler::withOutOfPlaneAndVonMises(double sxx, double syy, double sxy) const {
  // sigma_xx + sigma_yy = 2 (lambda + mu) tr(eps), so sigma_zz = lambda tr(eps) follows from them.
  const double szz = lambda_ / (2 * (lambda_ + mu_)) * (sxx + syy);
  return {sxx, syy, sxy, szz,
          std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                    3 * sxy * sxy)};
}

std::array<std::vector<double>, 5> ElasticityAssembler::cellCentreStresses(const Vector& uOverlap) const {
  const LO nc = mesh_.numLocalCells();
  std::array<std::vector<double>, 5> out;
  for (auto& v : out) v.resize(nc);
  for (LO e = 0; e < nc; ++e) {
    const auto [sxx, syy, sxy] = stressAt(uOverlap, e, 0.5, 0.5);
    const auto all = withOutOfPlaneAndVonMises(sxx, syy, sxy);
    for (int q = 0; q < 5; ++q) out[q][e] = all[q];
  }
  return out;
}

std::array<double, 3> ElasticityAssembler::largestVonMises(const Vector& uOverlap,
                                                           const std::vector<char>* region) const {
  const LO nc = mesh_.numLocalCells();
  std::vector<double> vm(static_cast<size_t>(nc));
  for (LO e = 0; e < nc; ++e) {
    const auto [sxx, syy, sxy] = stressAt(uOverlap, e, 0.5, 0.5);
    vm[e] = withOutOfPlaneAndVonMises(sxx, syy, sxy)[4];
  }
  return largestVonMises(vm, region);
}

std::array<double, 3> ElasticityAssembler::largestVonMises(const std::vector<double>& vm,
                                                           const std::vector<char>* region) const {
  const LO nc = mesh_.numLocalCells();
  SIGNORINI_ASSERT(vm.size() == static_cast<size_t>(nc), "one von Mises stress per local cell");
  SIGNORINI_ASSERT(!region || region->size() == static_cast<size_t>(nc), "one region flag per local cell");
  const auto counts = [&](LO e) { return !region || (*region)[e]; };
  double largest = -1;  // von Mises stresses are >= 0: -1 where no cell counts
  for (LO e = 0; e < nc; ++e)
    if (counts(e)) largest = std::max(largest, vm[e]);
  double global = 0;
  Teuchos::reduceAll(*mesh_.comm(), Teuchos::REDUCE_MAX, largest, Teuchos::outArg(global));
  if (global < 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  // Values within 1e-6 of the largest are equal (mirror-symmetric states tie up to the solves'
  // rounding, which depends on the ranks): of them the centre with the smallest x, then y.
  std::array<double, 2> place = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (LO e = 0; e < nc; ++e) {
    if (!counts(e) || !(vm[e] >= global * (1 - 1e-6))) continue;
    double x = 0, y = 0;
    for (int c = 0; c < 4; ++c) x += 0.25 * mesh_.cornerCoordsHost(e, c, 0), y += 0.25 * mesh_.cornerCoordsHost(e, c, 1);
    place = std::min(place, std::array<double, 2>{x, y});
  }
  const int size = mesh_.comm()->getSize();
  std::vector<double> all(2 * static_cast<size_t>(size));
  Teuchos::gatherAll(*mesh_.comm(), 2, place.data(), 2 * size, all.data());
  for (int r = 0; r < size; ++r) place = std::min(place, std::array<double, 2>{all[2 * r], all[2 * r + 1]});
  return {global, place[0], place[1]};
}

std::array<double, 5> ElasticityAssembler::stressAtPoint(const Vector& uOverlap, double x, double y) const {
  std::vector<std::array<double, 3>> terms;
  for (const auto& at : mesh_.locateAll(x, y)) terms.push_back(stressAt(uOverlap, at.cell, at.s, at.r));
  double sums[4];
  core::reproducibleSums(*mesh_.comm(), 4, terms.size(),
                         [&](std::size_t k, double* out) {
                           for (int q = 0; q < 3; ++q) out[q] = terms[k][q];
                           out[3] = 1.0;
                         },
                         sums);
  if (sums[3] == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan, nan};
  }
  return withOutOfPlaneAndVonMises(sums[0] / sums[3], sums[1] / sums[3], sums[2] / sums[3]);
}

}  // namespace signorini::fem
