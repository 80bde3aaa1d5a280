#pragma once
/// \file ExodusSeriesWriter.hpp
/// Exodus II output: result time series on meshes that may change from one output step to the
/// next. Serial: the caller gathers the data on one rank and writes there.
#include "signorini/io/QuadMesh.hpp"

#include <memory>
#include <string>
#include <vector>

namespace signorini::io {

/// Removes the files "<basePath>.e-s.<digits>" (the tail of a series written earlier with this
/// base) that the run does not write again, so that ParaView does not group them with a new
/// series: at once, or when the run's io::OutputStaging commits (io::retireOnCommit); missing
/// files are no error.
void removeExodusSeriesTail(const std::string& basePath);

/// What each file of a series says about itself besides the fields: its title, info records (for
/// example the deck that made it, one line each) and global variables, one value per output time
/// (energies, estimates: ParaView's "Plot Global Variables Over Time"). Every file also gets a QA
/// record naming signorini, its version and the time the file was made.
struct ExodusDescription {
  std::string title = "signorini results";  ///< at most 80 characters are kept
  /// Lines of more than 80 characters continue on the next record: each piece but the last has
  /// 79 characters and a backslash (so a line that itself ends in a backslash reads as continued;
  /// core::deckAsXml's lines end in '>').
  std::vector<std::string> info;
  std::vector<std::string> globalNames;  ///< names of the global variables (one value each per output time)
};

/// Writes a time series of results in Exodus II that ParaView opens as one series even
/// though the mesh changes: one file per distinct mesh, named so that ParaView groups them.
/// Each file is written under a temporary name and renamed when complete, so an interrupted
/// run never leaves a torn file under a final name.
///
/// File naming (the Exodus "restart" convention):
///   - first mesh:  "<basePath>.e"            (a run that never changes its mesh writes only this)
///   - next meshes: "<basePath>.e-s.0001", "<basePath>.e-s.0002", ... (at least 4 digits)
/// ParaView's legacy Exodus reader (vtkExodusFileSeriesReader::FindRestartedResults) and its
/// IOSS reader (vtkIOSSFilesScanner::GetRelatedFiles) both match file names against
/// "^(.*\.[eg][^-.]*)(-s.[0-9]+)?(\.[0-9]+\.[0-9]+)?$" (restart and partition suffixes
/// optional), group every file that has the same "<name>.e" prefix, the unsuffixed first file
/// included, and order them by their time values. So opening "<basePath>.e" (or any member)
/// shows the whole run as one time series (checked with ParaView 5.11). Files being written
/// are named "<final name>.part", which that pattern ignores. When the first file of a run is
/// started, leftover "<basePath>.e-s.<digits>" files of an earlier run are deleted, so that
/// ParaView does not mix them into this run's series.
class ExodusSeriesWriter {
 public:
  /// \param basePath       output path without extension, e.g. "out/membrane"
  /// \param nodalNames     names of nodal variables (u, v, a, ...)
  /// \param cellNames      names of element variables (level, indicator, ...)
  /// \param sideSetName    name of the one side set that carries side variables (e.g. "contact")
  /// \param sideNames      names of side-set variables (lambda, gap, ...)
  /// \param description    title, info records and global variables of every file
  ExodusSeriesWriter(std::string basePath, std::vector<std::string> nodalNames,
                     std::vector<std::string> cellNames, std::string sideSetName,
                     std::vector<std::string> sideNames, ExodusDescription description = {});
  ~ExodusSeriesWriter();  ///< closes and finalises the current file
  ExodusSeriesWriter(const ExodusSeriesWriter&) = delete;
  ExodusSeriesWriter& operator=(const ExodusSeriesWriter&) = delete;

  /// Appends one output time. When meshId differs from the previous call's, the current file
  /// is finalised and a new one is started with this mesh (mesh.sideSets[sideSetName] gives the
  /// sides carrying the side variables, side set 1 of the file; an absent or empty set means no
  /// sides; the mesh's other side sets, also empty ones, follow as sets 2, 3, ... without
  /// variables, e.g. supports).
  /// nodal[i] has one value per vertex, cell[i] one per quad, side[i] one per side of the set,
  /// globals one value per global variable of the description.
  /// Wrong counts or lengths, or a call after close()/abandon(), throw std::logic_error; a file
  /// that cannot be created or written throws core::UserError naming it.
  void write(long meshId, const QuadMesh& mesh, double time,
             const std::vector<std::vector<double>>& nodal,
             const std::vector<std::vector<double>>& cell,
             const std::vector<std::vector<double>>& side, const std::vector<double>& globals = {});

  /// Finalises the current file (idempotent). Returns the final file names written so far.
  std::vector<std::string> close();

  /// Drops the series (for a failed run): the temporary file and the finished files of the series are removed.
  void abandon();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini::io
