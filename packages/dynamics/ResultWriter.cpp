#include "signorini/dynamics/ResultWriter.hpp"

#include <cctype>
#include <set>
#include <unordered_map>

#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"

namespace signorini::dynamics {
namespace {

template <class T>
std::vector<T> gatherToRoot(const Comm& comm, const std::vector<T>& mine, MPI_Datatype type, std::vector<int>* countsOut = nullptr) {
  MPI_Comm c = core::rawMpiComm(comm);
  int n = static_cast<int>(mine.size()), size, rank;
  MPI_Comm_size(c, &size);
  MPI_Comm_rank(c, &rank);
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, c);
  std::vector<T> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(offsets.back() + counts.back());
  }
  MPI_Gatherv(mine.data(), n, type, all.data(), counts.data(), offsets.data(), type, 0, c);
  if (countsOut) *countsOut = counts;
  return all;
}

}  // namespace

std::vector<std::string> segmentSideSetNames(const std::vector<std::string>& segmentNames, unsigned contactMask) {
  std::set<std::string> taken = {"domain", "contact"};
  std::vector<std::string> names;
  for (size_t i = 0; i < segmentNames.size(); ++i) {
    std::string name = segmentNames[i];
    for (char& ch : name) ch = ch == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (name == "contact" && contactMask == (1u << i)) {
      names.emplace_back();
      continue;
    }
    std::string unique = name;
    for (int k = 2; taken.count(unique); ++k) unique = name + "_" + std::to_string(k);
    taken.insert(unique);
    names.push_back(unique);
  }
  return names;
}

ResultWriter::ResultWriter(const std::string& basePath, std::vector<std::string> nodalNames,
                           std::vector<std::string> cellNames, std::vector<std::string> contactNames,
                           io::ExodusDescription description, RCP<const Comm> comm, std::vector<std::string> segmentSets)
    : comm_(comm),
      numNodal_(nodalNames.size()),
      numCell_(cellNames.size()),
      numContact_(contactNames.size()),
      segmentSets_(std::move(segmentSets)) {
  SIGNORINI_ASSERT(segmentSets_.size() <= 32, "ResultWriter: more segments than bits of a segment mask");
  for (size_t i = 0; i < segmentSets_.size(); ++i)
    if (!segmentSets_[i].empty()) {
      SIGNORINI_ASSERT(segmentSets_[i] != "contact", "ResultWriter: a segment's side set may not be named 'contact'");
      segmentMask_ |= 1u << i;
    }
  if (comm_->getRank() == 0)
    writer_ = std::make_unique<io::ExodusSeriesWriter>(basePath, nodalNames, cellNames, "contact", contactNames,
                                                       std::move(description));
}

void ResultWriter::write(long meshId, const mesh::Q1Mesh& mesh, double time, const std::vector<const Vector*>& nodal,
                         const std::vector<std::vector<double>>& cell, const std::vector<int>& contactEdges,
                         const std::vector<std::vector<double>>& contact, const std::vector<double>& globals) {
  const LO nc = mesh.numLocalCells();
  const GO numGlobal = mesh.numGlobalNodes();
  const auto overlap = mesh.overlapMap();
  std::vector<double> coords, values, cellValues, edgeValues;
  std::vector<long long> keys, edgeInfo;
  coords.reserve(8 * nc);
  keys.reserve(4 * nc);
  values.reserve(4 * nc * nodal.size());
  cellValues.reserve(nc * numCell_);
  std::vector<decltype(nodal[0]->getLocalViewHost(Tpetra::Access::ReadOnly))> views;
  for (const Vector* v : nodal) views.push_back(v->getLocalViewHost(Tpetra::Access::ReadOnly));
  const auto& X = mesh.cornerCoordsHost;
  const auto& D = mesh.cornerDofsHost;
  const auto& W = mesh.cornerWeightsHost;
  for (LO e = 0; e < nc; ++e)
    for (int c = 0; c < 4; ++c) {
      coords.push_back(X(e, c, 0));
      coords.push_back(X(e, c, 1));
      const GO g0 = overlap->getGlobalElement(D(e, c, 0));
      if (D(e, c, 1) < 0) {
        keys.push_back(g0);
      } else {  // hanging node: identified by the two nodes it depends on
        const GO g1 = overlap->getGlobalElement(D(e, c, 1));
        keys.push_back(-1 - (std::min(g0, g1) * numGlobal + std::max(g0, g1)));
      }
      for (const auto& v : views) {
        double s = 0;
        for (int k = 0; k < 2; ++k)
          if (D(e, c, k) >= 0) s += W(e, c, k) * v(D(e, c, k), 0);
        values.push_back(s);
      }
    }
  for (LO e = 0; e < nc; ++e)
    for (size_t f = 0; f < numCell_; ++f) cellValues.push_back(cell[f][e]);
  static const int faceToSide[4] = {3, 1, 0, 2};
  for (size_t i = 0; i < contactEdges.size(); ++i) {
    const auto& be = mesh.boundaryEdges()[contactEdges[i]];
    edgeInfo.push_back(be.cell);
    edgeInfo.push_back(faceToSide[be.face]);
    for (size_t f = 0; f < numContact_; ++f) edgeValues.push_back(contact[f][i]);
  }
  std::vector<long long> segmentEdges;  // (cell, side, segment mask) of the edges of the written segments
  for (const auto& be : mesh.boundaryEdges())
    if (be.segments & segmentMask_) {
      segmentEdges.push_back(be.cell);
      segmentEdges.push_back(faceToSide[be.face]);
      segmentEdges.push_back(be.segments & segmentMask_);
    }
  std::vector<int> cellCounts;
  const auto allCoords = gatherToRoot(*comm_, coords, MPI_DOUBLE, &cellCounts);
  const auto allKeys = gatherToRoot(*comm_, keys, MPI_LONG_LONG);
  const auto allValues = gatherToRoot(*comm_, values, MPI_DOUBLE);
  const auto allCell = gatherToRoot(*comm_, cellValues, MPI_DOUBLE);
  std::vector<int> edgeCounts;
  const auto allEdges = gatherToRoot(*comm_, edgeInfo, MPI_LONG_LONG, &edgeCounts);
  const auto allEdgeValues = gatherToRoot(*comm_, edgeValues, MPI_DOUBLE);
  std::vector<int> segmentEdgeCounts;
  const auto allSegmentEdges = gatherToRoot(*comm_, segmentEdges, MPI_LONG_LONG, &segmentEdgeCounts);
  // Rank 0 writes; a failure there (file not creatable, disk full) ends the run on every rank.
  core::onRootCollectively(*comm_, [&] {
    io::QuadMesh out;
    const size_t totalCells = allKeys.size() / 4;
    // Nodes numbered in the order of first appearance: regular nodes through a table indexed by their
    // global number, hanging nodes (few) through a hash map.
    std::vector<int> regularId(numGlobal, -1);
    std::unordered_map<long long, int> hangingId;
    std::vector<std::vector<double>> nodalOut(numNodal_);
    for (auto& f : nodalOut) f.reserve(totalCells + 64);
    out.x.reserve(totalCells + 64);
    out.y.reserve(totalCells + 64);
    out.quads.reserve(totalCells);
    static const int zToCcw[4] = {0, 1, 3, 2};
    for (size_t e = 0; e < totalCells; ++e) {
      std::array<int, 4> quad;
      for (int k = 0; k < 4; ++k) {
        const int c = zToCcw[k];
        const size_t i = 4 * e + c;
        const int fresh = static_cast<int>(out.x.size());
        int& id = allKeys[i] >= 0 ? regularId[allKeys[i]] : hangingId.try_emplace(allKeys[i], -1).first->second;
        if (id < 0) {
          id = fresh;
          out.x.push_back(allCoords[2 * i]);
          out.y.push_back(allCoords[2 * i + 1]);
          for (size_t f = 0; f < numNodal_; ++f) nodalOut[f].push_back(allValues[numNodal_ * i + f]);
        }
        quad[k] = id;
      }
      out.quads.push_back(quad);
    }
    std::vector<std::vector<double>> cellOut(numCell_, std::vector<double>(totalCells));
    for (size_t e = 0; e < totalCells; ++e)
      for (size_t f = 0; f < numCell_; ++f) cellOut[f][e] = allCell[numCell_ * e + f];
    // Local cell numbers become global through the ranks' cell offsets.
    std::vector<long long> cellOffset(cellCounts.size(), 0);
    for (size_t r = 1; r < cellCounts.size(); ++r) cellOffset[r] = cellOffset[r - 1] + cellCounts[r - 1] / 8;
    std::vector<std::vector<double>> sideOut(numContact_);
    auto& sides = out.sideSets["contact"];
    size_t pos = 0;
    for (size_t r = 0; r < edgeCounts.size(); ++r)
      for (int k = 0; k < edgeCounts[r] / 2; ++k, ++pos) {
        sides.push_back({static_cast<int>(cellOffset[r] + allEdges[2 * pos]), static_cast<int>(allEdges[2 * pos + 1])});
        for (size_t f = 0; f < numContact_; ++f) sideOut[f].push_back(allEdgeValues[numContact_ * pos + f]);
      }
    for (const auto& name : segmentSets_)
      if (!name.empty()) out.sideSets[name];  // in every file, also without edges on this mesh
    pos = 0;
    for (size_t r = 0; r < segmentEdgeCounts.size(); ++r)
      for (int k = 0; k < segmentEdgeCounts[r] / 3; ++k, ++pos) {
        const std::array<int, 2> entry{static_cast<int>(cellOffset[r] + allSegmentEdges[3 * pos]),
                                       static_cast<int>(allSegmentEdges[3 * pos + 1])};
        const auto mask = static_cast<unsigned>(allSegmentEdges[3 * pos + 2]);
        for (size_t i = 0; i < segmentSets_.size(); ++i)
          if (mask & (1u << i)) out.sideSets[segmentSets_[i]].push_back(entry);
      }
    writer_->write(meshId, out, time, nodalOut, cellOut, sideOut, globals);
  });
}

std::vector<std::string> ResultWriter::close() {
  std::vector<std::string> files;
  core::onRootCollectively(*comm_, [&] {
    if (writer_) files = writer_->close();
  });
  return files;
}

void ResultWriter::abandon() {
  if (writer_) writer_->abandon();
}

}  // namespace signorini::dynamics
