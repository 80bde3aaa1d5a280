#include "signorini/mesh/CoarseMesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "signorini/core/Error.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/io/QuadMesh.hpp"

namespace signorini::mesh {

core::ParameterList CoarseMesh::getValidParameters() {
  core::ParameterList p("Mesh");
  core::addChoice(p, "Type", "rectangle", "Coarse mesh: a rectangle of nx x ny cells or an Exodus II file",
                  {"rectangle", "exodus"});
  core::addString(p, "File", "", "Exodus II file with QUAD4 blocks and named side sets (Type = exodus); "
                                  "relative paths are relative to the deck's folder");
  core::addDouble(p, "X0", 0.0, "Rectangle: left end [length]");
  core::addDouble(p, "X1", 1.0, "Rectangle: right end [length]");
  core::addDouble(p, "Y0", 0.0, "Rectangle: bottom end [length]");
  core::addDouble(p, "Y1", 1.0, "Rectangle: top end [length]");
  core::addInt(p, "Cells X", 1, "Rectangle: number of coarse cells in x", 1, 100000);
  core::addInt(p, "Cells Y", 1, "Rectangle: number of coarse cells in y", 1, 100000);
  core::addInt(p, "Refinement Level", 0, "Uniform refinement level of the coarse mesh (h = h_coarse / 2^level)",
               0, 18);
  core::addNamedStrings(p, "Boundary Segments",
                        "Named boundary segments: name = \"<side set>[, <x|y> <op> <value>]...\", e.g. "
                        "\"bottom, x >= 0.15\"; a rectangle has the side sets left, right, bottom, top; "
                        "op is one of >=, <=, >, <, tested at each fine boundary edge's midpoint");
  return p;
}

std::shared_ptr<CoarseMesh> CoarseMesh::create(const core::ParameterList& p) {
  const bool exodus = p.get<std::string>("Type") == "exodus";
  const std::string otherType = core::keysSetOtherThanDefaults(p, getValidParameters(), "Mesh", [&](const std::string& k) {
    return exodus ? k == "X0" || k == "X1" || k == "Y0" || k == "Y1" || k == "Cells X" || k == "Cells Y" : k == "File";
  });
  if (!otherType.empty())
    SIGNORINI_USER_ERROR(otherType << (exodus ? ": applies to Type = rectangle only (the Exodus file gives the mesh)"
                                              : ": applies to Type = exodus only")
                                   << (otherType.find(", ") == std::string::npos
                                           ? "; remove it from the deck or set it to its default"
                                           : "; remove them from the deck or set them to their defaults")
                                   << " (--print-parameters), e.g. with --set when switching a deck's Mesh/Type");
  if (exodus) {
    const std::string file = p.get<std::string>("File");
    if (file.empty()) SIGNORINI_USER_ERROR("Mesh/File: Type is \"exodus\" but no file is given");
    io::QuadMesh m;
    try {
      m = io::readExodusQuadMesh(file);
    } catch (const core::UserError& e) {
      SIGNORINI_USER_ERROR("Mesh/File: " << e.what());
    }
    return fromQuads(m.x, m.y, m.quads, m.sideSets, file);
  }
  const double x0 = p.get<double>("X0"), x1 = p.get<double>("X1");
  const double y0 = p.get<double>("Y0"), y1 = p.get<double>("Y1");
  if (!(x1 > x0)) SIGNORINI_USER_ERROR("Mesh/X1 (" << x1 << ") must be greater than Mesh/X0 (" << x0 << ")");
  if (!(y1 > y0)) SIGNORINI_USER_ERROR("Mesh/Y1 (" << y1 << ") must be greater than Mesh/Y0 (" << y0 << ")");
  // Areas, squared lengths and the cells' coordinates must stay within doubles: lengths up to
  // 1e100, and cells of the deck's level at least 1e-10 of the coordinates (1e16 + 4 split into
  // cells of 0.5 has vertices doubles cannot tell apart).
  for (const auto& [key, value] : {std::pair<const char*, double>{"X0", x0}, {"X1", x1}, {"Y0", y0}, {"Y1", y1}})
    if (!(std::abs(value) <= 1e100))
      SIGNORINI_USER_ERROR("Mesh/" << key << " = " << value << ": beyond 1e100 in magnitude (areas and squared lengths "
                           "would leave the range of doubles)");
  const double levelCells = std::ldexp(1.0, p.get<int>("Refinement Level"));
  const double hx = (x1 - x0) / (p.get<int>("Cells X") * levelCells), hy = (y1 - y0) / (p.get<int>("Cells Y") * levelCells);
  const double scale = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
  // Shifting helps only a rectangle whose cells are fine against its own size; one whose cells are
  // below 1e-10 of its longer side (Y1 = 1e-300 with X1 = 1) is degenerate wherever it lies.
  const bool farFromOrigin = std::min(hx, hy) >= 1e-10 * std::max(x1 - x0, y1 - y0);
  if (!(std::min(hx, hy) >= 1e-10 * scale))
    SIGNORINI_USER_ERROR("Mesh/X0, X1, Y0, Y1, Cells X, Cells Y, Refinement Level: cells of " << std::min(hx, hy)
                         << " at coordinates of " << scale << " are below 1e-10 of them (doubles resolve 1e-16; "
                         << (farFromOrigin ? "shift the rectangle toward the origin)"
                                           : "the rectangle's sides, " + core::shortestText(x1 - x0) + " and " +
                                                 core::shortestText(y1 - y0) +
                                                 ", or its cells along them differ too much: fewer cells or a "
                                                 "less slender rectangle)"));
  return rectangle(x0, x1, y0, y1, p.get<int>("Cells X"), p.get<int>("Cells Y"));
}

std::shared_ptr<CoarseMesh> CoarseMesh::rectangle(double x0, double x1, double y0, double y1, int cellsX,
                                                  int cellsY) {
  int offset = 0;
  while (offset < kMaxLevelOffset && cellsX % (2 << offset) == 0 && cellsY % (2 << offset) == 0) ++offset;
  const int nx = cellsX >> offset, ny = cellsY >> offset;  // trees
  std::vector<double> x, y;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      x.push_back(x0 + (x1 - x0) * i / nx);
      y.push_back(y0 + (y1 - y0) * j / ny);
    }
  std::vector<std::array<int, 4>> quads;
  std::map<std::string, std::vector<std::array<int, 2>>> sets;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int v = j * (nx + 1) + i, q = static_cast<int>(quads.size());
      quads.push_back({v, v + 1, v + nx + 2, v + nx + 1});
      if (j == 0) sets["bottom"].push_back({q, 0});
      if (i == nx - 1) sets["right"].push_back({q, 1});
      if (j == ny - 1) sets["top"].push_back({q, 2});
      if (i == 0) sets["left"].push_back({q, 3});
    }
  std::ostringstream src;
  src << "rectangle [" << x0 << "," << x1 << "]x[" << y0 << "," << y1 << "] of " << cellsX << "x" << cellsY
      << " cells";
  auto mesh = fromQuads(x, y, quads, sets, src.str());
  mesh->levelOffset_ = offset;
  return mesh;
}

namespace {

/// Refuses a coarse mesh with a hanging node: a side used by one cell only (a boundary side, as
/// far as the vertex numbers tell) that has a vertex of another such side strictly inside it. The
/// forest needs a conforming coarse mesh (p4est's connectivity would treat the side as a crack,
/// and its node numbering fails on several ranks).
/// Also refuses what p4est would reject without naming a cell: two cells on the same vertices (a
/// cell listed twice) and a side shared by more than two cells. Returns a note when two vertices of
/// cells lie at one point: a crack, which the forest takes (a slit in the body), but also what
/// nodes that were not merged (between element blocks meshed apart) give by mistake.
std::string checkConforming(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<std::array<int, 4>>& quads, const std::string& source) {
  std::map<std::array<int, 4>, int> cells;  // sorted vertices -> cell
  for (size_t t = 0; t < quads.size(); ++t) {
    auto key = quads[t];
    std::sort(key.begin(), key.end());
    const auto [it, fresh] = cells.emplace(key, static_cast<int>(t));
    if (!fresh)
      SIGNORINI_USER_ERROR(source << ": cells " << it->second + 1 << " and " << t + 1
                                  << " have the same vertices (a cell listed twice)");
  }
  std::vector<int> used;  // the vertices of cells, by (x, y)
  for (const auto& q : quads) used.insert(used.end(), q.begin(), q.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  double lo[2] = {x[used[0]], y[used[0]]}, hi[2] = {lo[0], lo[1]};
  for (int v : used)
    lo[0] = std::min(lo[0], x[v]), hi[0] = std::max(hi[0], x[v]), lo[1] = std::min(lo[1], y[v]),
    hi[1] = std::max(hi[1], y[v]);
  const double near = 1e-10 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  std::sort(used.begin(), used.end(), [&](int a, int b) { return std::make_pair(x[a], y[a]) < std::make_pair(x[b], y[b]); });
  std::vector<size_t> columnEnd(used.size());  // the first position after the vertices of equal x
  for (size_t i = used.size(); i-- > 0;)
    columnEnd[i] = i + 1 < used.size() && x[used[i + 1]] == x[used[i]] ? columnEnd[i + 1] : i + 1;
  std::ostringstream crack;
  int pairs = 0;
  for (size_t i = 0; i < used.size(); ++i)
    for (size_t j = i + 1; j < used.size() && x[used[j]] - x[used[i]] <= near;) {
      const int a = used[i], b = used[j];
      if (std::abs(y[b] - y[a]) <= near && pairs++ == 0)
        crack << source << ": vertices " << std::min(a, b) + 1 << " and " << std::max(a, b) + 1
              << " are at one point (" << x[a] << ", " << y[a] << ")";
      j = x[b] == x[a] && y[b] > y[a] ? columnEnd[j] : j + 1;  // the rest of a column lies above
    }
  if (pairs > 0)
    crack << (pairs > 1 ? " (and " + std::to_string(pairs - 1) + " more such pairs)" : std::string())
          << ": the cells on either side are not connected there (a crack, taken as two boundaries); merge the "
             "nodes if the body is meant to be whole (e.g. between element blocks meshed apart)";
  std::map<std::pair<int, int>, std::pair<int, int>> sides;  // sorted vertex pair -> (uses, cell)
  for (size_t t = 0; t < quads.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      const int a = quads[t][k], b = quads[t][(k + 1) % 4];
      auto& s = sides[{std::min(a, b), std::max(a, b)}];
      if (s.first == 2)
        SIGNORINI_USER_ERROR(source << ": the side from (" << x[a] << ", " << y[a] << ") to (" << x[b] << ", " << y[b]
                                    << ") belongs to more than two cells (cell " << t + 1
                                    << " among them): cells overlap");
      s = {s.first + 1, static_cast<int>(t)};
    }
  std::vector<int> vertices;  // of the sides used once, by x
  for (const auto& [ab, use] : sides)
    if (use.first == 1) vertices.push_back(ab.first), vertices.push_back(ab.second);
  std::sort(vertices.begin(), vertices.end(), [&](int a, int b) { return x[a] < x[b] || (x[a] == x[b] && a < b); });
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (const auto& [ab, use] : sides) {
    if (use.first != 1) continue;
    const auto [a, b] = ab;
    const double dx = x[b] - x[a], dy = y[b] - y[a], length = std::hypot(dx, dy), tol = 1e-10 * length;
    const double xlo = std::min(x[a], x[b]) - tol, xhi = std::max(x[a], x[b]) + tol;
    auto it = std::lower_bound(vertices.begin(), vertices.end(), xlo, [&](int v, double value) { return x[v] < value; });
    for (; it != vertices.end() && x[*it] <= xhi; ++it) {
      const int p = *it;
      const double along = ((x[p] - x[a]) * dx + (y[p] - y[a]) * dy) / length;
      const double off = ((x[p] - x[a]) * dy - (y[p] - y[a]) * dx) / length;
      if (p == a || p == b || std::abs(off) > tol || along <= tol || along >= length - tol) continue;
      SIGNORINI_USER_ERROR(source << ": the coarse mesh is not conforming: the side of cell " << use.second + 1
                                  << " from (" << x[a] << ", " << y[a] << ") to (" << x[b] << ", " << y[b]
                                  << ") has the vertex (" << x[p] << ", " << y[p]
                                  << ") of other cells inside it (a hanging node); split the cell in the mesh");
    }
  }
  return crack.str();
}

}  // namespace

std::shared_ptr<CoarseMesh> CoarseMesh::fromQuads(
    const std::vector<double>& x, const std::vector<double>& y, const std::vector<std::array<int, 4>>& quadsCcw,
    const std::map<std::string, std::vector<std::array<int, 2>>>& sideSets, const std::string& source) {
  std::shared_ptr<CoarseMesh> m(new CoarseMesh());
  m->source_ = source;
  const auto nv = static_cast<p4est_topidx_t>(x.size());
  const auto nt = static_cast<p4est_topidx_t>(quadsCcw.size());
  if (nt == 0) SIGNORINI_USER_ERROR(source << ": the mesh has no cells");
  for (p4est_topidx_t v = 0; v < nv; ++v)
    if (!std::isfinite(x[v]) || !std::isfinite(y[v]))
      SIGNORINI_USER_ERROR(source << ": vertex " << v + 1 << " has a coordinate that is not a finite number");
  m->conn_ = p4est_connectivity_new(nv, nt, 0, 0);
  for (p4est_topidx_t v = 0; v < nv; ++v) {
    m->conn_->vertices[3 * v] = x[v];
    m->conn_->vertices[3 * v + 1] = y[v];
    m->conn_->vertices[3 * v + 2] = 0.0;
  }
  m->treeCorners_.resize(nt);
  m->faceSets_.resize(nt);
  static const int ccwToZ[4] = {0, 1, 3, 2};
  for (p4est_topidx_t t = 0; t < nt; ++t) {
    const auto& q = quadsCcw[t];
    for (int k = 0; k < 4; ++k) {
      if (q[k] < 0 || q[k] >= nv) SIGNORINI_USER_ERROR(source << ": cell " << t + 1 << " has an invalid vertex id");
      m->conn_->tree_to_vertex[4 * t + ccwToZ[k]] = q[k];
      m->treeCorners_[t][ccwToZ[k]] = {x[q[k]], y[q[k]]};
    }
    // Signed area of the CCW polygon: must be positive (Exodus orders QUAD4 counter-clockwise).
    double area = 0;
    for (int k = 0; k < 4; ++k) {
      const int a = q[k], b = q[(k + 1) % 4];
      area += x[a] * y[b] - x[b] * y[a];
    }
    if (!(area > 0)) SIGNORINI_USER_ERROR(source << ": cell " << t + 1 << " is inverted or degenerate (its vertices are not counter-clockwise)");
    // The bilinear map of the cell is invertible exactly when every corner turns left: a convex
    // cell without a straight or reflex corner.
    for (int k = 0; k < 4; ++k) {
      const int a = q[(k + 3) % 4], b = q[k], c = q[(k + 1) % 4];
      const double turn = (x[b] - x[a]) * (y[c] - y[b]) - (y[b] - y[a]) * (x[c] - x[b]);
      if (!(turn > 1e-12 * area))
        SIGNORINI_USER_ERROR(source << ": cell " << t + 1 << " is not convex: its corner at (" << x[b] << ", " << y[b]
                                    << ") has an angle of 180 degrees or more (or a side of length zero), so "
                                       "its bilinear map is not invertible");
    }
  }
  m->crackNote_ = checkConforming(x, y, quadsCcw, source);
  for (p4est_topidx_t t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f) {
      m->conn_->tree_to_tree[4 * t + f] = t;
      m->conn_->tree_to_face[4 * t + f] = static_cast<int8_t>(f);
    }
  p4est_connectivity_complete(m->conn_);
  if (!p4est_connectivity_is_valid(m->conn_)) SIGNORINI_USER_ERROR(source << ": the cells do not form a valid conforming mesh");
  static const int sideToFace[4] = {2, 1, 3, 0};  // CCW side s joins corners s, s+1
  long interior = 0;
  std::ostringstream firstInterior;
  for (const auto& [name, sides] : sideSets) {
    if (sides.empty()) m->emptySets_.insert(name);
    for (const auto& s : sides) {
      if (s[0] < 0 || s[0] >= nt || s[1] < 0 || s[1] > 3)
        SIGNORINI_USER_ERROR(source << ": side set '" << name << "' names a side that does not exist");
      const int f = sideToFace[s[1]];
      m->faceSets_[s[0]][f].push_back(name);
      const bool boundary = m->conn_->tree_to_tree[4 * s[0] + f] == s[0] && m->conn_->tree_to_face[4 * s[0] + f] == f;
      if (!boundary && interior++ == 0) {
        const auto& q = quadsCcw[s[0]];
        firstInterior << "side set '" << name << "' lists the side from (" << x[q[s[1]]] << ", " << y[q[s[1]]]
                      << ") to (" << x[q[(s[1] + 1) % 4]] << ", " << y[q[(s[1] + 1) % 4]] << ") of cell " << s[0] + 1
                      << ", which lies between two cells";
      }
    }
  }
  if (interior > 0)
    m->interiorSidesNote_ = source + ": " + firstInterior.str() +
                            (interior > 1 ? " (and " + std::to_string(interior - 1) + " more such sides)" : std::string()) +
                            ": a boundary segment takes boundary edges only, so it is left out";
  return m;
}

CoarseMesh::~CoarseMesh() {
  if (conn_) p4est_connectivity_destroy(conn_);
}

std::array<double, 2> CoarseMesh::mapPoint(int t, double s, double r) const {
  const auto& c = treeCorners_[t];
  std::array<double, 2> p;
  for (int d = 0; d < 2; ++d)
    p[d] = (1 - s) * (1 - r) * c[0][d] + s * (1 - r) * c[1][d] + (1 - s) * r * c[2][d] + s * r * c[3][d];
  return p;
}

double CoarseMesh::jacobianDeterminant(int t, double s, double r) const {
  const auto& c = treeCorners_[t];
  double J[2][2];
  for (int d = 0; d < 2; ++d) {
    J[d][0] = (1 - r) * (c[1][d] - c[0][d]) + r * (c[3][d] - c[2][d]);
    J[d][1] = (1 - s) * (c[2][d] - c[0][d]) + s * (c[3][d] - c[1][d]);
  }
  return J[0][0] * J[1][1] - J[0][1] * J[1][0];
}

std::vector<std::string> CoarseMesh::setNames() const {
  std::set<std::string> s;
  for (const auto& t : faceSets_)
    for (const auto& f : t) s.insert(f.begin(), f.end());
  return {s.begin(), s.end()};
}

bool CoarseMesh::hasSet(const std::string& name) const {
  for (const auto& t : faceSets_)
    for (const auto& f : t)
      if (std::find(f.begin(), f.end(), name) != f.end()) return true;
  return false;
}

double CoarseMesh::diameter() const {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& t : treeCorners_)
    for (const auto& c : t)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], c[d]), hi[d] = std::max(hi[d], c[d]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

}  // namespace signorini::mesh
