/// \file exodus_rectangle.cpp
/// Writes a structured rectangle mesh as Exodus II:
///
///   exodus_rectangle OUT.exo X0 X1 Y0 Y1 NX NY
///
/// NX x NY QUAD4 cells (counter-clockwise) in element block 1 ("domain"), and the side sets
/// "left" (id 1), "right" (id 2), "bottom" (id 3) and "top" (id 4).
/// Standalone: needs only the Exodus II C library.
#include <exodusII.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

int usage(FILE* to = stderr) {
  std::fprintf(to,
               "usage: exodus_rectangle OUT.exo X0 X1 Y0 Y1 NX NY\n"
               "  writes the rectangle [X0,X1]x[Y0,Y1] as NX x NY QUAD4 cells with side sets\n"
               "  'left', 'right', 'bottom', 'top' (X0 < X1, Y0 < Y1, NX, NY >= 1)\n");
  return to == stderr ? 2 : 0;
}

bool parseDouble(const char* text, double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text, &end);
  return errno == 0 && end != text && *end == '\0';
}

bool parseCount(const char* text, int& value) {
  char* end = nullptr;
  errno = 0;
  const long parsed = std::strtol(text, &end, 10);
  if (errno != 0 || end == text || *end != '\0' || parsed < 1 || parsed > 100000) return false;
  value = static_cast<int>(parsed);
  return true;
}

/// One side set: 1-based element numbers and Exodus side numbers (1..4).
struct SideSet {
  int id;
  const char* name;
  std::vector<int> elements, sides;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) return usage(stdout);
  if (argc != 8) return usage();
  const std::string outPath = argv[1];
  double x0, x1, y0, y1;
  int nx, ny;
  if (!parseDouble(argv[2], x0) || !parseDouble(argv[3], x1) || !parseDouble(argv[4], y0) ||
      !parseDouble(argv[5], y1) || !parseCount(argv[6], nx) || !parseCount(argv[7], ny) ||
      !(x0 < x1) || !(y0 < y1)) {
    return usage();
  }

  const long numNodes = static_cast<long>(nx + 1) * (ny + 1);
  const long numCells = static_cast<long>(nx) * ny;
  auto node = [nx](int i, int j) { return j * (nx + 1) + i + 1; };  // 1-based
  auto cell = [nx](int i, int j) { return j * nx + i + 1; };        // 1-based

  std::vector<double> x(numNodes), y(numNodes);
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      // Interpolate from both ends so the boundary coordinates are exactly X0, X1, Y0, Y1.
      x[node(i, j) - 1] = (x0 * (nx - i) + x1 * i) / nx;
      y[node(i, j) - 1] = (y0 * (ny - j) + y1 * j) / ny;
    }
  }
  std::vector<int> connectivity;
  connectivity.reserve(4 * numCells);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      for (int n : {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)}) {
        connectivity.push_back(n);
      }
    }
  }
  // Exodus QUAD4 side s joins local nodes s and s+1: 1 bottom, 2 right, 3 top, 4 left.
  std::vector<SideSet> sideSets{{1, "left", {}, {}}, {2, "right", {}, {}},
                                {3, "bottom", {}, {}}, {4, "top", {}, {}}};
  for (int j = 0; j < ny; ++j) {
    sideSets[0].elements.push_back(cell(0, j));
    sideSets[0].sides.push_back(4);
    sideSets[1].elements.push_back(cell(nx - 1, j));
    sideSets[1].sides.push_back(2);
  }
  for (int i = 0; i < nx; ++i) {
    sideSets[2].elements.push_back(cell(i, 0));
    sideSets[2].sides.push_back(1);
    sideSets[3].elements.push_back(cell(i, ny - 1));
    sideSets[3].sides.push_back(3);
  }

  ex_opts(0);  // report errors ourselves, never abort
  int cpuWordSize = 8, ioWordSize = 8;
  const int exoid = ex_create(outPath.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid < 0) {
    std::fprintf(stderr, "exodus_rectangle: cannot create '%s'\n", outPath.c_str());
    return 1;
  }
  bool ok = true;
  auto check = [&ok, &outPath](int status, const char* call) {
    if (status < 0 && ok) {
      std::fprintf(stderr, "exodus_rectangle: %s failed while writing '%s'\n", call,
                   outPath.c_str());
      ok = false;
    }
  };
  check(ex_put_init(exoid, "rectangle", 2, numNodes, numCells, 1, 0,
                    static_cast<int64_t>(sideSets.size())),
        "ex_put_init");
  char xName[] = "x", yName[] = "y";
  char* coordinateNames[] = {xName, yName};
  check(ex_put_coord_names(exoid, coordinateNames), "ex_put_coord_names");
  check(ex_put_block(exoid, EX_ELEM_BLOCK, 1, "QUAD4", numCells, 4, 0, 0, 0), "ex_put_block");
  check(ex_put_name(exoid, EX_ELEM_BLOCK, 1, "domain"), "ex_put_name");
  for (const auto& set : sideSets) {
    check(ex_put_set_param(exoid, EX_SIDE_SET, set.id, static_cast<int64_t>(set.elements.size()),
                           0),
          "ex_put_set_param");
    check(ex_put_name(exoid, EX_SIDE_SET, set.id, set.name), "ex_put_name");
  }
  check(ex_put_coord(exoid, x.data(), y.data(), nullptr), "ex_put_coord");
  check(ex_put_conn(exoid, EX_ELEM_BLOCK, 1, connectivity.data(), nullptr, nullptr), "ex_put_conn");
  for (const auto& set : sideSets) {
    check(ex_put_set(exoid, EX_SIDE_SET, set.id, set.elements.data(), set.sides.data()),
          "ex_put_set");
  }
  check(ex_close(exoid), "ex_close");
  if (!ok) {
    std::remove(outPath.c_str());
    return 1;
  }
  std::printf("wrote %s: %ld nodes, %ld QUAD4 cells, side sets left/right/bottom/top\n",
              outPath.c_str(), numNodes, numCells);
  return 0;
}
