/// \file ExodusSeriesWriter.cpp
/// Exodus II result-series output on the Exodus II C API (version 6.02).
#include "signorini/io/ExodusSeriesWriter.hpp"

#include "signorini/core/Error.hpp"
#include "signorini/core/Interrupt.hpp"
#include "signorini/io/ExodusCalls.hpp"
#include "signorini/io/OutputStaging.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace signorini::io {

namespace fs = std::filesystem;
using detail::checkExodus;
using detail::silenceExodus;

void removeExodusSeriesTail(const std::string& basePath) {
  retireOnCommit(basePath, isExodusSeriesSuffix);
}

namespace {

/// Pointers to the characters of \p names, for the Exodus calls that take `char*[]`.
std::vector<char*> namePointers(std::vector<std::string>& names) {
  std::vector<char*> pointers;
  pointers.reserve(names.size());
  for (auto& name : names) pointers.push_back(name.data());
  return pointers;
}

std::size_t longestName(const std::vector<std::string>& names) {
  std::size_t longest = 0;
  for (const auto& name : names) longest = std::max(longest, name.size());
  return longest;
}

}  // namespace

struct ExodusSeriesWriter::Impl {
  std::string basePath;
  std::vector<std::string> nodalNames, cellNames;
  std::string sideSetName;
  std::vector<std::string> sideNames;
  ExodusDescription description;

  // The file being written (exoid >= 0 while open).
  int exoid = -1;
  long meshId = 0;
  std::string finalPath, partPath;
  core::RemovedOnSignal partRemovedOnSignal;  ///< the file being written goes with a Ctrl-C at once
  std::size_t numNodes = 0, numCells = 0, numSides = 0;  ///< numSides: of the set carrying the side variables
  std::size_t numSetSides = 0;  ///< of all side sets
  int numSteps = 0;

  long filesStarted = 0;  ///< index of the next file in the series
  bool finished = false;  ///< close() or abandon() was called
  std::vector<std::string> writtenFiles;

  /// "<base>.e" for the first mesh, "<base>.e-s.NNNN" for the following ones.
  std::string seriesFileName(long index) const {
    if (index == 0) return basePath + ".e";
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".e-s.%04ld", index);
    return basePath + suffix;
  }

  void check(int status, const char* call) const { checkExodus(status, call, partPath); }

  /// Creates the next file of the series and writes its mesh and variable definitions.
  void startFile(long id, const QuadMesh& mesh) {
    if (filesStarted == 0) removeExodusSeriesTail(basePath);
    finalPath = seriesFileName(filesStarted);
    partPath = finalPath + ".part";
    ++filesStarted;
    partRemovedOnSignal = core::RemovedOnSignal(partPath);

    int cpuWordSize = 8, ioWordSize = 8;
    errno = 0;
    exoid = ex_create(partPath.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
    if (exoid < 0) {
      const int reason = errno;  // e.g. "File name too long" for a long Output/Basename
      SIGNORINI_USER_ERROR("cannot create Exodus II output file '"
                           << partPath << "' (for '" << finalPath << "'): "
                           << (reason ? std::strerror(reason)
                                      : "check that the output directory exists and is writable"));
    }
    if (core::stopSignal()) {  // the signal's handler may have run before the file existed
      dropFile();
      core::throwIfSignalled();
    }
    meshId = id;
    numSteps = 0;
    numNodes = mesh.x.size();
    numCells = mesh.quads.size();
    const auto sideSet = mesh.sideSets.find(sideSetName);
    numSides = sideSet == mesh.sideSets.end() ? 0 : sideSet->second.size();
    // Side sets of the file: the one carrying the side variables first (id 1, as readers of the
    // series expect; left out when empty), then every other set of the mesh (ids 2, 3, ...), also
    // an empty one, so that every file of a series has the same sets.
    std::vector<std::pair<std::string, const std::vector<std::array<int, 2>>*>> sets;
    if (numSides > 0) sets.emplace_back(sideSetName, &sideSet->second);
    for (const auto& [name, sides] : mesh.sideSets)
      if (name != sideSetName) sets.emplace_back(name, &sides);
    numSetSides = 0;
    for (const auto& set : sets) numSetSides += set.second->size();

    // Definitions first: netCDF classic files rewrite everything written after the header
    // whenever the header grows, so all dimensions and variables are defined before any data.
    std::vector<std::string> allNames = nodalNames;
    allNames.insert(allNames.end(), cellNames.begin(), cellNames.end());
    allNames.insert(allNames.end(), sideNames.begin(), sideNames.end());
    allNames.insert(allNames.end(), description.globalNames.begin(), description.globalNames.end());
    for (const auto& set : sets) allNames.push_back(set.first);
    const auto nameLength = longestName(allNames);
    if (nameLength > static_cast<std::size_t>(MAX_NAME_LENGTH)) {
      check(ex_set_max_name_length(exoid, static_cast<int>(nameLength)), "ex_set_max_name_length");
    }
    check(ex_put_init(exoid, description.title.substr(0, MAX_LINE_LENGTH).c_str(), 2, static_cast<int64_t>(numNodes),
                      static_cast<int64_t>(numCells), 1, 0, static_cast<int64_t>(sets.size())),
          "ex_put_init");
    putRecords();
    std::vector<std::string> coordinateNames{"x", "y"};
    check(ex_put_coord_names(exoid, namePointers(coordinateNames).data()), "ex_put_coord_names");
    check(ex_put_block(exoid, EX_ELEM_BLOCK, 1, "QUAD4", static_cast<int64_t>(numCells), 4, 0, 0,
                       0),
          "ex_put_block");
    check(ex_put_name(exoid, EX_ELEM_BLOCK, 1, "domain"), "ex_put_name(element block)");
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const auto id = static_cast<int64_t>(i + 1);
      check(ex_put_set_param(exoid, EX_SIDE_SET, id, static_cast<int64_t>(sets[i].second->size()), 0),
            "ex_put_set_param");
      check(ex_put_name(exoid, EX_SIDE_SET, id, sets[i].first.c_str()), "ex_put_name(side set)");
    }
    defineVariables(EX_GLOBAL, description.globalNames);
    defineVariables(EX_NODAL, nodalNames);
    defineVariables(EX_ELEM_BLOCK, cellNames);
    if (numSides > 0) defineVariables(EX_SIDE_SET, sideNames, static_cast<int>(sets.size()));

    // Mesh data.
    check(ex_put_coord(exoid, mesh.x.data(), mesh.y.data(), nullptr), "ex_put_coord");
    std::vector<int> connectivity(4 * numCells);
    for (std::size_t q = 0; q < numCells; ++q) {
      for (int k = 0; k < 4; ++k) connectivity[4 * q + k] = mesh.quads[q][k] + 1;
    }
    check(ex_put_conn(exoid, EX_ELEM_BLOCK, 1, connectivity.data(), nullptr, nullptr),
          "ex_put_conn");
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const auto& entries = *sets[i].second;
      if (entries.empty()) continue;
      std::vector<int> elements(entries.size()), sides(entries.size());
      for (std::size_t j = 0; j < entries.size(); ++j) {
        elements[j] = entries[j][0] + 1;
        sides[j] = entries[j][1] + 1;
      }
      check(ex_put_set(exoid, EX_SIDE_SET, static_cast<int64_t>(i + 1), elements.data(), sides.data()), "ex_put_set");
    }
    clearTextBehindNul();
  }

  /// Exodus 6 writes each name into its row of a text variable (names, QA and info records) from a
  /// buffer it does not clear: behind the name's NUL the row held whatever the heap held there,
  /// e.g. pieces of the deck. Clears every row behind its first NUL, so that a file holds only
  /// what the run wrote (ctest exodus_text_padding).
  void clearTextBehindNul() {
    const auto netcdf = [&](int status, const char* call) {
      if (status != NC_NOERR)
        SIGNORINI_USER_ERROR("Exodus II file '" << partPath << "': " << call << " failed (" << nc_strerror(status) << ")");
    };
    int numVars = 0, unlimited = -1;
    netcdf(nc_inq_nvars(exoid, &numVars), "nc_inq_nvars");
    netcdf(nc_inq_unlimdim(exoid, &unlimited), "nc_inq_unlimdim");
    for (int v = 0; v < numVars; ++v) {
      nc_type type;
      int numDims = 0, dims[NC_MAX_VAR_DIMS];
      netcdf(nc_inq_var(exoid, v, nullptr, &type, &numDims, dims, nullptr), "nc_inq_var");
      if (type != NC_CHAR || numDims == 0 || dims[0] == unlimited) continue;
      std::size_t total = 1, row = 1;
      for (int d = 0; d < numDims; ++d) {
        netcdf(nc_inq_dimlen(exoid, dims[d], &row), "nc_inq_dimlen");
        total *= row;
      }
      if (total == 0) continue;
      std::vector<char> text(total);
      netcdf(nc_get_var_text(exoid, v, text.data()), "nc_get_var_text");
      bool changed = false;
      for (std::size_t at = 0; at < total; at += row) {
        const auto begin = text.begin() + static_cast<std::ptrdiff_t>(at), end = begin + static_cast<std::ptrdiff_t>(row);
        for (auto c = std::find(begin, end, '\0'); c != end; ++c) changed |= std::exchange(*c, '\0') != '\0';
      }
      if (changed) netcdf(nc_put_var_text(exoid, v, text.data()), "nc_put_var_text");
    }
  }

  /// The QA record (program, version, date and time in UTC) and the info records (split into lines
  /// of at most MAX_LINE_LENGTH characters).
  void putRecords() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char date[MAX_STR_LENGTH + 1], clock[MAX_STR_LENGTH + 1];
    std::strftime(date, sizeof date, "%Y-%m-%d", &utc);
    std::strftime(clock, sizeof clock, "%H:%M:%S UTC", &utc);
    std::string program = "signorini", version = SIGNORINI_VERSION;
    char* qa[1][4] = {{program.data(), version.data(), date, clock}};
    check(ex_put_qa(exoid, 1, qa), "ex_put_qa");
    std::vector<std::string> lines;
    const std::size_t piece = MAX_LINE_LENGTH - 1;  // and the continuation mark
    for (const auto& line : description.info) {
      std::size_t at = 0;
      for (; line.size() - at > static_cast<std::size_t>(MAX_LINE_LENGTH); at += piece)
        lines.push_back(line.substr(at, piece) + "\\");
      lines.push_back(line.substr(at));
    }
    if (!lines.empty())
      check(ex_put_info(exoid, static_cast<int>(lines.size()), namePointers(lines).data()), "ex_put_info");
  }

  /// Declares result variables of one kind. Of \p numEntities blocks or sets, the first carries
  /// them all (its row of the truth table is true, the others' false).
  void defineVariables(ex_entity_type type, std::vector<std::string> names, int numEntities = 1) {
    if (names.empty()) return;
    const int count = static_cast<int>(names.size());
    check(ex_put_variable_param(exoid, type, count), "ex_put_variable_param");
    check(ex_put_variable_names(exoid, type, count, namePointers(names).data()),
          "ex_put_variable_names");
    if (type != EX_NODAL && type != EX_GLOBAL) {
      std::vector<int> truthTable(names.size() * static_cast<std::size_t>(numEntities), 0);
      std::fill(truthTable.begin(), truthTable.begin() + count, 1);
      check(ex_put_truth_table(exoid, type, numEntities, count, truthTable.data()), "ex_put_truth_table");
    }
  }

  /// Closes the current file and publishes it under its final name (io::publish).
  void finishFile() {
    if (exoid < 0) return;
    const int status = ex_close(exoid);
    exoid = -1;
    checkExodus(status, "ex_close", partPath);
    publish(partPath, finalPath);
    partRemovedOnSignal = {};  // published: renamed, or staged (the staging removes it on a signal)
    writtenFiles.push_back(finalPath);
  }

  /// Closes the current file and deletes it, also when closing or renaming it failed.
  void dropFile() {
    if (exoid >= 0) ex_close(exoid);
    exoid = -1;
    std::error_code ec;
    if (!partPath.empty() && fs::is_regular_file(partPath, ec)) fs::remove(partPath, ec);
    partRemovedOnSignal = {};
  }

  /// Throws std::logic_error unless the data fit \p mesh and the declared variables.
  void checkData(const QuadMesh& mesh, const std::vector<std::vector<double>>& nodal,
                 const std::vector<std::vector<double>>& cell,
                 const std::vector<std::vector<double>>& side) const {
    auto fail = [](const std::string& what) {
      throw std::logic_error("ExodusSeriesWriter::write: " + what);
    };
    if (mesh.x.size() != mesh.y.size()) fail("mesh has different numbers of x and y coordinates");
    if (mesh.x.empty() || mesh.quads.empty()) fail("mesh is empty");
    for (const auto& quad : mesh.quads) {
      for (const int v : quad) {
        if (v < 0 || static_cast<std::size_t>(v) >= mesh.x.size()) fail("quad refers to no vertex");
      }
    }
    const auto sideSet = mesh.sideSets.find(sideSetName);
    const std::size_t sidesInMesh = sideSet == mesh.sideSets.end() ? 0 : sideSet->second.size();
    for (const auto& [name, sides] : mesh.sideSets) {
      if (name.empty()) fail("a side set has no name");
      for (const auto& entry : sides) {
        if (entry[0] < 0 || static_cast<std::size_t>(entry[0]) >= mesh.quads.size() ||
            entry[1] < 0 || entry[1] > 3) {
          fail("side set '" + name + "' has an invalid (quad, side) entry");
        }
      }
    }
    auto checkFields = [&](const std::vector<std::vector<double>>& fields,
                           const std::vector<std::string>& names, std::size_t length,
                           const char* kind) {
      if (fields.size() != names.size()) {
        fail(std::string("expected ") + std::to_string(names.size()) + " " + kind +
             " fields, got " + std::to_string(fields.size()));
      }
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (fields[i].size() != length) {
          fail(std::string(kind) + " field '" + names[i] + "' has " +
               std::to_string(fields[i].size()) + " values, expected " + std::to_string(length));
        }
      }
    };
    checkFields(nodal, nodalNames, mesh.x.size(), "nodal");
    checkFields(cell, cellNames, mesh.quads.size(), "cell");
    if (!(sidesInMesh == 0 && side.empty())) checkFields(side, sideNames, sidesInMesh, "side");
  }

  /// Appends one time step to the open file.
  void appendStep(double time, const std::vector<std::vector<double>>& nodal,
                  const std::vector<std::vector<double>>& cell,
                  const std::vector<std::vector<double>>& side, const std::vector<double>& globals) {
    const int step = numSteps + 1;
    check(ex_put_time(exoid, step, &time), "ex_put_time");
    if (!globals.empty())
      check(ex_put_var(exoid, step, EX_GLOBAL, 1, 0, static_cast<int64_t>(globals.size()), globals.data()),
            "ex_put_var(global)");
    for (std::size_t i = 0; i < nodal.size(); ++i) {
      check(ex_put_var(exoid, step, EX_NODAL, static_cast<int>(i) + 1, 1,
                       static_cast<int64_t>(numNodes), nodal[i].data()),
            "ex_put_var(nodal)");
    }
    for (std::size_t i = 0; i < cell.size(); ++i) {
      check(ex_put_var(exoid, step, EX_ELEM_BLOCK, static_cast<int>(i) + 1, 1,
                       static_cast<int64_t>(numCells), cell[i].data()),
            "ex_put_var(element)");
    }
    if (numSides > 0) {
      for (std::size_t i = 0; i < side.size(); ++i) {
        check(ex_put_var(exoid, step, EX_SIDE_SET, static_cast<int>(i) + 1, 1,
                         static_cast<int64_t>(numSides), side[i].data()),
              "ex_put_var(side set)");
      }
    }
    numSteps = step;
  }
};

ExodusSeriesWriter::ExodusSeriesWriter(std::string basePath, std::vector<std::string> nodalNames,
                                       std::vector<std::string> cellNames, std::string sideSetName,
                                       std::vector<std::string> sideNames, ExodusDescription description)
    : impl_(std::make_unique<Impl>()) {
  impl_->description = std::move(description);
  impl_->basePath = std::move(basePath);
  impl_->nodalNames = std::move(nodalNames);
  impl_->cellNames = std::move(cellNames);
  impl_->sideSetName = std::move(sideSetName);
  impl_->sideNames = std::move(sideNames);
}

ExodusSeriesWriter::~ExodusSeriesWriter() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; the file stays under its ".part" name.
  }
}

void ExodusSeriesWriter::write(long meshId, const QuadMesh& mesh, double time,
                               const std::vector<std::vector<double>>& nodal,
                               const std::vector<std::vector<double>>& cell,
                               const std::vector<std::vector<double>>& side, const std::vector<double>& globals) {
  Impl& w = *impl_;
  if (w.finished) throw std::logic_error("ExodusSeriesWriter::write called after close/abandon");
  silenceExodus();
  w.checkData(mesh, nodal, cell, side);
  if (globals.size() != w.description.globalNames.size())
    throw std::logic_error("ExodusSeriesWriter::write: expected " + std::to_string(w.description.globalNames.size()) +
                           " global values, got " + std::to_string(globals.size()));
  const bool newMesh = w.exoid < 0 || meshId != w.meshId;
  if (!newMesh) {
    const auto sideSet = mesh.sideSets.find(w.sideSetName);
    const std::size_t sidesInMesh = sideSet == mesh.sideSets.end() ? 0 : sideSet->second.size();
    std::size_t setSides = 0;
    for (const auto& set : mesh.sideSets) setSides += set.second.size();
    if (mesh.x.size() != w.numNodes || mesh.quads.size() != w.numCells ||
        sidesInMesh != w.numSides || setSides != w.numSetSides) {
      throw std::logic_error("ExodusSeriesWriter::write: mesh " + std::to_string(meshId) +
                             " changed size without a new mesh id");
    }
  }
  if (newMesh) w.finishFile();
  try {
    if (newMesh) w.startFile(meshId, mesh);
    w.appendStep(time, nodal, cell, side, globals);
  } catch (...) {
    w.dropFile();  // never leave a half-written file that close() would promote
    throw;
  }
}

std::vector<std::string> ExodusSeriesWriter::close() {
  impl_->finished = true;
  silenceExodus();
  impl_->finishFile();
  return impl_->writtenFiles;
}

void ExodusSeriesWriter::abandon() {
  impl_->finished = true;
  silenceExodus();
  impl_->dropFile();
  for (const auto& f : impl_->writtenFiles) unpublish(f);
  impl_->writtenFiles.clear();
}

}  // namespace signorini::io
