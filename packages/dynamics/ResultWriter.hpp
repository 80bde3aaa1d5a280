#pragma once
/// \file ResultWriter.hpp
/// Gathers a distributed Q1 solution on rank 0 and appends it to an Exodus II series
/// (io::ExodusSeriesWriter): nodal fields (hanging nodes get their constrained values), cell
/// fields, and per-edge fields on the side set "contact".
#include <memory>
#include <string>
#include <vector>

#include "signorini/io/ExodusSeriesWriter.hpp"
#include "signorini/mesh/Q1Mesh.hpp"

namespace signorini::dynamics {

/// The names of the side sets that show the boundary segments \p segmentNames (bit i of a segment
/// mask: segmentNames[i]) in the result files, for ResultWriter: as ParaView's default (IOSS) reader
/// shows names, in lower case with '_' for blanks, so that both readers show the same; "" for a
/// segment named "contact" that is all of Gamma_C (\p contactMask: its bit alone), which the set
/// "contact" shows. A name taken by the element block "domain", the set "contact" or an earlier
/// segment gets "_2", "_3", ... (the IOSS reader refuses a file with two sets of one name).
std::vector<std::string> segmentSideSetNames(const std::vector<std::string>& segmentNames, unsigned contactMask);

/// The Exodus output of one pass: rank 0 owns the file series, the other ranks send it their parts.
/// Collective over the communicator it keeps.
class ResultWriter {
 public:
  /// \p basePath: output folder and basename ("out/membrane"); the field names of the nodal, cell and
  /// contact side-set variables; \p description: title, info records and global variable names of
  /// every file (rank 0's counts); \p segmentSets: the name of the side set that shows boundary
  /// segment i (mesh::BoundaryEdge::segments bit i; "" for none), written besides "contact"
  /// (supports, loads).
  ResultWriter(const std::string& basePath, std::vector<std::string> nodalNames, std::vector<std::string> cellNames,
               std::vector<std::string> contactNames, io::ExodusDescription description, RCP<const Comm> comm,
               std::vector<std::string> segmentSets = {});
  /// Appends output time \p time [time] on \p mesh; a new \p meshId starts a new file of the series.
  /// \param meshId       differs between any two meshes of the run
  /// \param mesh         the step's Q1 numbering
  /// \param time         t_n
  /// \param nodal        overlap-map vectors, one per nodal field
  /// \param cell         one value per local cell per field
  /// \param contactEdges local boundary-edge indices on Gamma_C
  /// \param contact      one value per entry of \p contactEdges per field
  /// \param globals      one value per global variable (rank 0's are written)
  void write(long meshId, const mesh::Q1Mesh& mesh, double time, const std::vector<const Vector*>& nodal,
             const std::vector<std::vector<double>>& cell, const std::vector<int>& contactEdges,
             const std::vector<std::vector<double>>& contact, const std::vector<double>& globals);
  /// Final file names (rank 0), after finalising.
  std::vector<std::string> close();
  void abandon();  ///< a failed run: removes the series' files (io::ExodusSeriesWriter::abandon)

 private:
  RCP<const Comm> comm_;
  std::unique_ptr<io::ExodusSeriesWriter> writer_;
  size_t numNodal_, numCell_, numContact_;
  std::vector<std::string> segmentSets_;
  unsigned segmentMask_ = 0;  ///< the segments that get a side set
};

}  // namespace signorini::dynamics
