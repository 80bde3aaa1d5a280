/// \file QuadMesh.cpp
/// Exodus II mesh input on the Exodus II C API (version 6.02).
#include "signorini/io/QuadMesh.hpp"

#include "signorini/core/Error.hpp"
#include "signorini/io/ExodusCalls.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace signorini::io {

namespace fs = std::filesystem;
using detail::checkExodus;
using detail::silenceExodus;

namespace {

/// Closes an Exodus file id when the scope ends.
class ExodusFileGuard {
 public:
  explicit ExodusFileGuard(int exoid) : exoid_(exoid) {}
  ~ExodusFileGuard() {
    if (exoid_ >= 0) ex_close(exoid_);
  }
  ExodusFileGuard(const ExodusFileGuard&) = delete;
  ExodusFileGuard& operator=(const ExodusFileGuard&) = delete;

 private:
  int exoid_;
};

std::string upperCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

/// Twice the signed area of a quad (positive when counter-clockwise).
double twiceSignedArea(const QuadMesh& mesh, const std::array<int, 4>& quad) {
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int a = quad[k], b = quad[(k + 1) % 4];
    sum += mesh.x[a] * mesh.y[b] - mesh.x[b] * mesh.y[a];
  }
  return sum;
}

/// Added to a message about a 0 where Exodus numbers from 1: netCDF reads the data missing from a
/// cut-off file as zeros.
constexpr const char* kZeroEntry = " (a 0 where Exodus numbers from 1: the file may be truncated or corrupt)";

/// Refuses an id given to two element blocks or two side sets: the Exodus library would read the
/// first one's data for both (a file written without it, by netCDF directly).
void refuseRepeatedIds(const std::vector<int>& ids, const char* what, const std::string& path) {
  std::vector<int> sorted(ids);
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end())
    SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "': two " << what << "s have the id " << *twice
                                                 << " (ids must be unique)");
}

/// Names of the side sets, indexed like \p ids; unnamed ones become "sideset_<id>".
std::vector<std::string> readSideSetNames(int exoid, const std::vector<int>& ids,
                                          const std::string& path) {
  std::vector<std::string> names(ids.size());
  if (ids.empty()) return names;
  const int usedLength = static_cast<int>(ex_inquire_int(exoid, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  const int nameLength = std::max(usedLength, static_cast<int>(MAX_NAME_LENGTH));
  ex_set_max_name_length(exoid, nameLength);
  std::vector<std::vector<char>> buffers(ids.size(), std::vector<char>(nameLength + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& buffer : buffers) pointers.push_back(buffer.data());
  checkExodus(ex_get_names(exoid, EX_SIDE_SET, pointers.data()), "ex_get_names(side sets)", path);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    names[i] = trimmed(std::string(buffers[i].data()));
    if (names[i].empty()) names[i] = "sideset_" + std::to_string(ids[i]);
  }
  return names;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------

QuadMesh readExodusQuadMesh(const std::string& path) {
  silenceExodus();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "' does not exist or is not a file");
  }
  int cpuWordSize = static_cast<int>(sizeof(double));
  int ioWordSize = 0;
  float version = 0.0f;
  const int exoid = ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (exoid < 0) {
    SIGNORINI_USER_ERROR("cannot open '" << path << "' as an Exodus II file (unreadable or not "
                                         << "Exodus II/netCDF)");
  }
  ExodusFileGuard guard(exoid);

  ex_init_params init{};
  checkExodus(ex_get_init_ext(exoid, &init), "ex_get_init_ext", path);
  if (init.num_dim != 2 && init.num_dim != 3) {
    SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "' is " << init.num_dim
                                                 << "-dimensional; a 2D mesh is required");
  }
  if (init.num_nodes <= 0 || init.num_elem <= 0 || init.num_elem_blk <= 0) {
    SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "' contains no elements");
  }

  QuadMesh mesh;
  const auto numNodes = static_cast<std::size_t>(init.num_nodes);
  mesh.x.resize(numNodes);
  mesh.y.resize(numNodes);
  std::vector<double> z(init.num_dim == 3 ? numNodes : 0);
  checkExodus(ex_get_coord(exoid, mesh.x.data(), mesh.y.data(), z.empty() ? nullptr : z.data()), "ex_get_coord", path);
  // Mesh generators often write a 2D mesh with three coordinates: taken when z is one value.
  for (std::size_t v = 1; v < z.size(); ++v)
    if (z[v] != z[0]) {
      SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "' is 3-dimensional and not a plane z = const (node "
                                                   << v + 1 << " has z = " << z[v] << ", node 1 z = " << z[0]
                                                   << "); a 2D mesh is required");
    }

  // Element blocks, concatenated in file order: the position in `quads` is then the Exodus
  // internal element number minus one, which is what side sets refer to.
  std::vector<int> blockIds(static_cast<std::size_t>(init.num_elem_blk));
  checkExodus(ex_get_ids(exoid, EX_ELEM_BLOCK, blockIds.data()), "ex_get_ids(element blocks)",
              path);
  refuseRepeatedIds(blockIds, "element block", path);
  mesh.quads.reserve(static_cast<std::size_t>(init.num_elem));
  for (const int blockId : blockIds) {
    ex_block block{};
    block.id = blockId;
    block.type = EX_ELEM_BLOCK;
    checkExodus(ex_get_block_param(exoid, &block), "ex_get_block_param", path);
    if (block.num_entry == 0) continue;
    const std::string type = upperCase(trimmed(block.topology));
    if (type.compare(0, 4, "QUAD") != 0 || block.num_nodes_per_entry != 4) {
      SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "': element block " << blockId
                                                   << " has element type '" << block.topology
                                                   << "' with " << block.num_nodes_per_entry
                                                   << " nodes; only QUAD4 elements are supported");
    }
    std::vector<int> connectivity(static_cast<std::size_t>(block.num_entry) * 4);
    checkExodus(ex_get_conn(exoid, EX_ELEM_BLOCK, blockId, connectivity.data(), nullptr, nullptr),
                "ex_get_conn", path);
    for (std::size_t e = 0; e < static_cast<std::size_t>(block.num_entry); ++e) {
      std::array<int, 4> quad{};
      for (int k = 0; k < 4; ++k) {
        const int node = connectivity[4 * e + k];
        if (node < 1 || static_cast<std::size_t>(node) > numNodes) {
          SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "': element block " << blockId
                                                       << " refers to node " << node
                                                       << " which does not exist" << (node == 0 ? kZeroEntry : ""));
        }
        quad[k] = node - 1;
      }
      mesh.quads.push_back(quad);
    }
  }

  // Exodus orders QUAD4 nodes counter-clockwise; repair clockwise quads (some 2D generators
  // write them) by reversing them, and remember the side renumbering this implies.
  std::vector<bool> reversed(mesh.quads.size(), false);
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    auto& quad = mesh.quads[q];
    const double area2 = twiceSignedArea(mesh, quad);
    if (area2 < 0.0) {
      std::swap(quad[1], quad[3]);  // (0,1,2,3) -> (0,3,2,1): old side s becomes side 3-s
      reversed[q] = true;
    } else if (area2 == 0.0) {
      SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "': element " << q + 1
                                                   << " has zero area (its corners on one line, or a cell that "
                                                      "crosses itself, as a bowtie whose two halves cancel)");
    }
  }

  std::vector<int> sideSetIds(static_cast<std::size_t>(init.num_side_sets));
  if (!sideSetIds.empty()) {
    checkExodus(ex_get_ids(exoid, EX_SIDE_SET, sideSetIds.data()), "ex_get_ids(side sets)", path);
    refuseRepeatedIds(sideSetIds, "side set", path);
  }
  const auto sideSetNames = readSideSetNames(exoid, sideSetIds, path);
  for (std::size_t s = 0; s < sideSetIds.size(); ++s) {
    const int setId = sideSetIds[s];
    int numSides = 0, numDistFactors = 0;
    checkExodus(ex_get_set_param(exoid, EX_SIDE_SET, setId, &numSides, &numDistFactors),
                "ex_get_set_param", path);
    std::vector<int> elements(static_cast<std::size_t>(numSides));
    std::vector<int> sides(static_cast<std::size_t>(numSides));
    if (numSides > 0) {
      checkExodus(ex_get_set(exoid, EX_SIDE_SET, setId, elements.data(), sides.data()),
                  "ex_get_set", path);
    }
    auto& entries = mesh.sideSets[sideSetNames[s]];  // sets sharing a name are merged
    entries.reserve(entries.size() + elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const int element = elements[i], side = sides[i];
      if (element < 1 || static_cast<std::size_t>(element) > mesh.quads.size() || side < 1 ||
          side > 4) {
        SIGNORINI_USER_ERROR("Exodus II mesh file '" << path << "': side set " << setId << " ('"
                                                     << sideSetNames[s] << "') has invalid entry "
                                                     << "(element " << element << ", side "
                                                     << side << ")"
                                                     << (element == 0 || side == 0 ? kZeroEntry : ""));
      }
      const int quad = element - 1;
      const int localSide = reversed[quad] ? 3 - (side - 1) : side - 1;
      entries.push_back({quad, localSide});
    }
  }
  return mesh;
}

}  // namespace signorini::io
