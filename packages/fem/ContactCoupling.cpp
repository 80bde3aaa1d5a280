#include "signorini/fem/ContactCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/ReproducibleSum.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/fem/LoadQuadrature.hpp"
#include "signorini/fem/Q1Kernels.hpp"

namespace signorini::fem {

ContactCoupling::ContactCoupling(const mesh::Q1Mesh& mesh, unsigned contactMask, SegmentSize size,
                                 const std::vector<char>& dirichlet, const Unknowns& unknowns)
    : comm_(mesh.comm()), unknowns_(unknowns) {
  const auto& bedges = mesh.boundaryEdges();
  std::vector<double> mine;
  std::vector<long long> myPlaces;
  std::vector<int> localIds;
  for (size_t i = 0; i < bedges.size(); ++i)
    if (bedges[i].segments & contactMask) {
      localIds.push_back(static_cast<int>(i));
      for (int k = 0; k < 2; ++k) mine.push_back(bedges[i].x[k][0]), mine.push_back(bedges[i].x[k][1]);
      myPlaces.insert(myPlaces.end(), {bedges[i].tree, bedges[i].face, bedges[i].quadrantLevel, bedges[i].faceIndex});
    }
  // Offset of this rank's edges in the gathered list.
  int myCount = static_cast<int>(localIds.size()), myOffset = 0;
  MPI_Exscan(&myCount, &myOffset, 1, MPI_INT, MPI_SUM, core::rawMpiComm(*comm_));
  if (comm_->getRank() == 0) myOffset = 0;
  const std::vector<double> all = core::allGatherv(core::rawMpiComm(*comm_), mine);
  const std::vector<long long> places = core::allGatherv(core::rawMpiComm(*comm_), myPlaces);
  const int ne = static_cast<int>(all.size() / 4);
  edges_.resize(ne);
  for (int e = 0; e < ne; ++e) edges_[e] = {all[4 * e], all[4 * e + 1], all[4 * e + 2], all[4 * e + 3]};

  // Chains of edges joined at common end points (matched on a grid far finer than any edge).
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& e : edges_)
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], e[2 * k + d]), hi[d] = std::max(hi[d], e[2 * k + d]);
  const double quantum = 1e-10 * std::max(1e-300, std::max(hi[0] - lo[0], hi[1] - lo[1]));
  using Key = std::pair<long long, long long>;
  auto key = [&](double x, double y) { return Key{std::llround(x / quantum), std::llround(y / quantum)}; };
  std::map<Key, std::vector<int>> incident;
  for (int e = 0; e < ne; ++e)
    for (int k = 0; k < 2; ++k) incident[key(edges_[e][2 * k], edges_[e][2 * k + 1])].push_back(e);
  // Start points: chain ends (one incident edge) first, by coordinates; then closed loops.
  std::vector<std::pair<std::array<double, 2>, Key>> starts;
  for (const auto& [k, list] : incident)
    if (list.size() == 1) {
      const auto& e = edges_[list[0]];
      const int end = key(e[0], e[1]) == k ? 0 : 1;
      starts.push_back({{e[2 * end], e[2 * end + 1]}, k});
    }
  std::sort(starts.begin(), starts.end());
  std::vector<char> used(ne, 0);
  std::vector<std::vector<int>> chains;
  std::vector<char> closed;  // per chain: a closed loop
  auto walk = [&](Key p, bool loop) {
    std::vector<int> chain;
    for (;;) {
      int next = -1;
      for (int e : incident[p])
        if (!used[e]) {
          next = e;
          break;
        }
      if (next < 0) break;
      used[next] = 1;
      chain.push_back(next);
      const Key a = key(edges_[next][0], edges_[next][1]), b = key(edges_[next][2], edges_[next][3]);
      p = (a == p) ? b : a;
    }
    if (!chain.empty()) chains.push_back(chain), closed.push_back(loop);
  };
  for (const auto& s : starts) walk(s.second, false);
  for (;;) {  // closed loops: start at the smallest remaining point
    int first = -1;
    for (int e = 0; e < ne; ++e)
      if (!used[e] && (first < 0 || std::make_pair(edges_[e][0], edges_[e][1]) < std::make_pair(edges_[first][0], edges_[first][1])))
        first = e;
    if (first < 0) break;
    walk(key(edges_[first][0], edges_[first][1]), true);
  }

  // Segments follow the local mesh size and the tree's dyadic hierarchy, so that a mesh and its
  // mirror image get mirrored segments: two sibling edges (the halves of one parent edge) form a
  // segment; a lone edge, whose sibling half is refined further, joins the segment of the edge next
  // to it inside that half (which lies inside the lone edge's parent, too). Unrefined trees pair
  // their faces (below). Edges left without a parent edge in the contact set (a contact boundary
  // ending inside a parent edge, the middle tree faces of an odd chain) are paired along their
  // chain, from both ends of each run of them toward its middle (a middle of three edges is one
  // segment; one left over joins the pair before it); a single one joins the neighbouring segment.
  edgeSegment_.assign(ne, -1);
  auto edgeLength = [&](int e) { return std::hypot(edges_[e][2] - edges_[e][0], edges_[e][3] - edges_[e][1]); };
  using Place = std::array<long long, 4>;  // tree, face, p4est level, index along the face
  std::map<Place, int> edgeAt;
  long long finestLevel = 0;
  for (int e = 0; e < ne; ++e) {
    edgeAt[{places[4 * e], places[4 * e + 1], places[4 * e + 2], places[4 * e + 3]}] = e;
    finestLevel = std::max(finestLevel, places[4 * e + 2]);
  }
  constexpr int kNoPartner = -1;
  // partner[e]: the edge whose segment e joins (e itself for the even one of a sibling pair).
  std::vector<int> partner(ne, kNoPartner);
  for (int e = 0; e < ne && size == SegmentSize::TwoEdges; ++e) {
    const long long tree = places[4 * e], face = places[4 * e + 1], level = places[4 * e + 2], i = places[4 * e + 3];
    if (level == 0) continue;
    const auto sibling = edgeAt.find({tree, face, level, i ^ 1});
    if (sibling != edgeAt.end()) {
      partner[e] = (i % 2 == 0) ? e : sibling->second;
      continue;
    }
    // The edge of the sibling half that touches e, on the finer levels.
    const long long s = i ^ 1;
    for (long long d = 1; level + d <= finestLevel && partner[e] == kNoPartner; ++d) {
      const long long j = (i % 2 == 1) ? ((s + 1) << d) - 1 : (s << d);
      const auto next = edgeAt.find({tree, face, level + d, j});
      if (next != edgeAt.end()) partner[e] = next->second;
    }
  }
  // Unrefined trees (an Exodus mesh's cells, a rectangle's when its cell counts share no power of
  // two) have no parent edge. Their faces along each chain pair up once and for all, independent
  // of the refinement, as the two halves of a virtual parent edge: from both ends of an open chain
  // toward its middle (a middle one or three are left to the runs below), from the start of a
  // closed loop. An edge that is a whole tree face then pairs with its partner face's edge like a
  // sibling, or joins the edge next to it when that face is refined: the same segments as the
  // rectangle whose trees hold these cells two by two, where the contact boundary is made of whole
  // faces of that rectangle's trees.
  for (size_t c = 0; c < chains.size() && size == SegmentSize::TwoEdges; ++c) {
    const auto& chain = chains[c];
    const int n = static_cast<int>(chain.size());
    std::vector<std::array<long long, 2>> faces;  // (tree, face) in chain order
    std::vector<int> faceOf(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const std::array<long long, 2> f{places[4 * chain[k]], places[4 * chain[k] + 1]};
      if (faces.empty() || faces.back() != f) faces.push_back(f);
      faceOf[k] = static_cast<int>(faces.size()) - 1;
    }
    if (closed[c] && faces.size() > 1 && faces.front() == faces.back()) {  // a loop walked from inside a face
      for (int k = 0; k < n; ++k)
        if (faceOf[k] == static_cast<int>(faces.size()) - 1) faceOf[k] = 0;
      faces.pop_back();
    }
    const int nf = static_cast<int>(faces.size());
    std::vector<int> partnerFace(static_cast<size_t>(nf), -1);
    auto pairFaces = [&](int a, int b) { partnerFace[a] = b, partnerFace[b] = a; };
    if (closed[c]) {  // from the smallest face, toward its smaller neighbour: the same for any walk
      const int s0 = static_cast<int>(std::min_element(faces.begin(), faces.end()) - faces.begin());
      const int dir = faces[(s0 + 1) % nf] < faces[(s0 + nf - 1) % nf] ? 1 : nf - 1;
      for (int i = 0; i + 1 < nf; i += 2) pairFaces((s0 + i * dir) % nf, (s0 + (i + 1) * dir) % nf);
    } else {
      int lo = 0, hi = nf;
      for (; hi - lo >= 4; lo += 2, hi -= 2) pairFaces(lo, lo + 1), pairFaces(hi - 2, hi - 1);
      if (hi - lo == 2) pairFaces(lo, lo + 1);
    }
    for (int k = 0; k < n; ++k) {
      const int e = chain[k], pf = partnerFace[faceOf[k]];
      if (places[4 * e + 2] != 0 || pf < 0) continue;
      int next = -1;  // e's chain neighbour on the partner face
      for (int j : {k + 1, k - 1}) {
        if (closed[c]) j = (j + n) % n;
        if (next < 0 && j >= 0 && j < n && faceOf[j] == pf) next = chain[j];
      }
      SIGNORINI_ASSERT(next >= 0, "the partner of a tree face is not next to it on its chain");
      if (places[4 * next + 2] == 0)
        partner[e] = std::min(e, next);  // an unrefined pair: one representative
      else
        partner[e] = next;  // a lone edge joins the finer edge next to it
    }
  }
  // The segment's representative edge of e (-1: none, e joins its chain neighbour's segment).
  auto rootOf = [&](int e) {  // lone edges point to strictly finer edges, so this ends
    while (partner[e] != kNoPartner && partner[e] != e) e = partner[e];
    return partner[e] == kNoPartner ? -1 : e;
  };
  int runSegments = ne;  // representatives of the pairs of edges without a parent: ne, ne + 1, ...
  for (size_t c = 0; c < chains.size(); ++c) {
    auto chain = chains[c];
    const int n = static_cast<int>(chain.size());
    std::vector<int> root(n);
    for (int k = 0; k < n; ++k) root[k] = rootOf(chain[k]);
    // A closed loop starts where a segment starts, and not inside a run of edges without a parent.
    for (int shift = 0; shift < n && ((root[0] >= 0 && root[0] == root[n - 1]) || (closed[c] && root[0] < 0 && root[n - 1] < 0));
         ++shift) {
      std::rotate(chain.begin(), chain.begin() + 1, chain.end());
      std::rotate(root.begin(), root.begin() + 1, root.end());
    }
    if (size == SegmentSize::TwoEdges && std::any_of(root.begin(), root.end(), [](int r) { return r >= 0; }))
      for (int k = 0; k < n;) {  // runs [k, end) of edges without a parent
        if (root[k] >= 0) {
          ++k;
          continue;
        }
        int end = k;
        while (end < n && root[end] < 0) ++end;
        int lo = k, hi = end;
        while (hi - lo >= 4) {  // pairs from both ends
          root[lo] = root[lo + 1] = runSegments++;
          root[hi - 1] = root[hi - 2] = runSegments++;
          lo += 2, hi -= 2;
        }
        if (hi - lo >= 2) {
          for (int i = lo; i < hi; ++i) root[i] = runSegments;  // the middle two or three
          ++runSegments;
        } else if (hi - lo == 1 && lo > k) {
          root[lo] = root[lo - 1];  // one left over in a longer run: with the pair before it
        }
        k = end;
      }
    // Edges left without a segment join the previous segment of their chain (the next one at the
    // chain's start); a chain without any sibling pair is paired from its start (an odd count ends
    // in a segment of three edges).
    std::vector<std::vector<int>> merged;
    std::vector<int> leading;
    for (int k = 0; k < n; ++k) {
      if (root[k] < 0) {
        (merged.empty() ? leading : merged.back()).push_back(chain[k]);
        continue;
      }
      if (k == 0 || root[k] != root[k - 1]) {
        merged.emplace_back();
        if (merged.size() == 1) merged.back().swap(leading);
      }
      merged.back().push_back(chain[k]);
    }
    if (merged.empty()) {
      for (int k = 0; k < n;) {
        const int take = (size == SegmentSize::OneEdge) ? 1 : (n - k <= 3 ? n - k : 2);
        merged.emplace_back(chain.begin() + k, chain.begin() + k + take);
        k += take;
      }
    }
    for (const auto& group : merged) {
      const int seg = static_cast<int>(length_.size());
      double len = 0, mx = 0, my = 0;
      for (int e : group) {
        const double l = edgeLength(e);
        len += l;
        mx += l * 0.5 * (edges_[e][0] + edges_[e][2]);
        my += l * 0.5 * (edges_[e][1] + edges_[e][3]);
        edgeSegment_[e] = seg;
      }
      length_.push_back(len);
      midpoint_.push_back({mx / len, my / len});
      edgeCount_.push_back(static_cast<int>(group.size()));
    }
  }

  const int m = numSegments();
  segmentMap_ = Teuchos::rcp(new Map(m, comm_->getRank() == 0 ? m : 0, 0, comm_));
  localEdgeSegment_.assign(bedges.size(), -1);
  for (size_t k = 0; k < localIds.size(); ++k) localEdgeSegment_[localIds[k]] = edgeSegment_[myOffset + static_cast<int>(k)];

  // B as a finite element matrix: rows are unknowns (owned + shared), columns are segments.
  const auto ownedRows = unknowns.owned ? unknowns.owned : mesh.ownedMap();
  const auto overlap = unknowns.overlap ? unknowns.overlap : mesh.overlapMap();
  const int nc = unknowns.components, comp = unknowns.component;
  SIGNORINI_ASSERT(dirichlet.size() == overlap->getNodeNumElements(), "Dirichlet flags do not match the unknowns");
  auto row = [&](LO node) { return static_cast<LO>(nc * node + comp); };
  canonicalKeys_.resize(ownedRows->getNodeNumElements());
  for (size_t r = 0; r < canonicalKeys_.size(); ++r) {
    const auto key = mesh.canonicalKey(static_cast<LO>(r / nc));
    canonicalKeys_[r] = {key[0], key[1], static_cast<long long>(r % nc)};
  }
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  // sign int_E phi_i ds = sign |E| / 2 for both end points of a straight edge.
  auto halfLength = [&](const mesh::BoundaryEdge& be) {
    const double dx = be.x[1][0] - be.x[0][0], dy = be.x[1][1] - be.x[0][1];
    return 0.5 * unknowns.sign * std::sqrt(dx * dx + dy * dy);
  };
  for (size_t k = 0; k < localIds.size(); ++k) {
    const auto& be = bedges[localIds[k]];
    const int seg = localEdgeSegment_[localIds[k]];
    const auto mid = be.at(0.5);
    localEdges_.push_back({seg, 2 * halfLength(be), mid[0], mid[1]});
    for (int p = 0; p < 2; ++p)
      if (dirichlet[row(be.node[p])]) heldEnds_.push_back({seg, halfLength(be), be.x[p][0], be.x[p][1], row(be.node[p])});
  }
  if (comm_->getSize() == 1) {
    // B is summed into local CRS arrays (columns: the segments) and built from them.
    const size_t nRows = overlap->getNodeNumElements();
    std::vector<std::vector<LO>> segmentsOf(nRows);
    for (size_t k = 0; k < localIds.size(); ++k) {
      const auto& be = bedges[localIds[k]];
      const LO seg = localEdgeSegment_[localIds[k]];
      for (int p = 0; p < 2; ++p) {
        auto& cols = segmentsOf[row(be.node[p])];
        if (!dirichlet[row(be.node[p])] && std::find(cols.begin(), cols.end(), seg) == cols.end()) cols.push_back(seg);
      }
    }
    LocalMatrix::row_map_type::non_const_type rowPtr("contactRows", nRows + 1);
    auto rh = Kokkos::create_mirror_view(rowPtr);
    rh(0) = 0;
    for (size_t i = 0; i < nRows; ++i) rh(i + 1) = rh(i) + segmentsOf[i].size();
    LocalMatrix::index_type::non_const_type entries("contactColumns", rh(nRows));
    auto eh = Kokkos::create_mirror_view(entries);
    for (size_t i = 0; i < nRows; ++i) {
      std::sort(segmentsOf[i].begin(), segmentsOf[i].end());
      std::copy(segmentsOf[i].begin(), segmentsOf[i].end(), &eh(rh(i)));
    }
    Kokkos::deep_copy(rowPtr, rh);
    Kokkos::deep_copy(entries, eh);
    LocalMatrix::values_type values("contactValues", rh(nRows));
    LocalMatrix localB("contactCoupling", static_cast<LO>(nRows), m, rh(nRows), values, rowPtr, entries);
    const LO nLocal = static_cast<LO>(localIds.size());
    Kokkos::View<double*, DeviceType> half("edgeHalfLength", nLocal);
    Kokkos::View<LO* [2], DeviceType> rows("edgeRows", nLocal);
    Kokkos::View<LO*, DeviceType> col("edgeCol", nLocal);
    auto halfh = Kokkos::create_mirror_view(half);
    auto rowsh = Kokkos::create_mirror_view(rows);
    auto colh = Kokkos::create_mirror_view(col);
    for (LO k = 0; k < nLocal; ++k) {
      const auto& be = bedges[localIds[k]];
      halfh(k) = halfLength(be);
      for (int p = 0; p < 2; ++p) rowsh(k, p) = dirichlet[row(be.node[p])] ? -1 : row(be.node[p]);
      colh(k) = localEdgeSegment_[localIds[k]];
    }
    Kokkos::deep_copy(half, halfh);
    Kokkos::deep_copy(rows, rowsh);
    Kokkos::deep_copy(col, colh);
    Kokkos::parallel_for(
        "signorini::assembleContactCoupling", Kokkos::RangePolicy<ExecSpace>(0, nLocal), KOKKOS_LAMBDA(const LO k) {
          LO c = col(k);
          double v = half(k);
          for (int p = 0; p < 2; ++p)
            if (rows(k, p) >= 0) localB.sumIntoValues(rows(k, p), &c, 1, &v, false, kAtomicScatter);
        });
    B_ = Teuchos::rcp(new CrsMatrix(localB, ownedRows, segmentMap_, segmentMap_, ownedRows, Teuchos::null, Teuchos::null));
  } else {
    // Several ranks: each local edge end's entry (row, segment, sign |E| / 2); those of rows this
    // rank does not own go to their owners, once. At most two contact edges meet at a node, so an
    // entry is the sum of at most two terms, whose bits do not depend on their order.
    const LO nOwned = static_cast<LO>(ownedRows->getNodeNumElements());
    std::vector<std::vector<std::pair<GO, double>>> ownedEntries(static_cast<size_t>(nOwned));
    std::vector<GO> foreignRows;
    std::vector<std::pair<GO, double>> foreignEntries;
    for (size_t k = 0; k < localIds.size(); ++k) {
      const auto& be = bedges[localIds[k]];
      const GO seg = localEdgeSegment_[localIds[k]];
      for (int p = 0; p < 2; ++p) {
        const LO r = row(be.node[p]);
        if (dirichlet[r]) continue;
        if (r < nOwned) {
          ownedEntries[r].push_back({seg, halfLength(be)});
        } else {
          foreignRows.push_back(overlap->getGlobalElement(r));
          foreignEntries.push_back({seg, halfLength(be)});
        }
      }
    }
    const int size = comm_->getSize();
    Teuchos::Array<int> owner(foreignRows.size());
    ownedRows->getRemoteIndexList(Teuchos::ArrayView<const GO>(foreignRows), owner());
    std::vector<int> sendOff(size + 1, 0);
    for (const int o : owner) sendOff[o + 1] += 3;
    for (int r = 0; r < size; ++r) sendOff[r + 1] += sendOff[r];
    std::vector<double> send(static_cast<size_t>(sendOff[size]));  // row, segment (exact as doubles below 2^53), value
    std::vector<int> fill(sendOff.begin(), sendOff.end() - 1);
    for (size_t j = 0; j < foreignRows.size(); ++j) {
      double* o = &send[static_cast<size_t>(fill[owner[j]])];
      fill[owner[j]] += 3;
      o[0] = static_cast<double>(foreignRows[j]);
      o[1] = static_cast<double>(foreignEntries[j].first);
      o[2] = foreignEntries[j].second;
    }
    const std::vector<double> recv = core::exchange(core::rawMpiComm(*comm_), send, sendOff).values;
    for (size_t j = 0; j < recv.size(); j += 3) {
      const LO r = ownedRows->getLocalElement(static_cast<GO>(recv[j]));
      SIGNORINI_ASSERT(r != Teuchos::OrdinalTraits<LO>::invalid(), "a contact row sent to a rank that does not own it");
      ownedEntries[r].push_back({static_cast<GO>(recv[j + 1]), recv[j + 2]});
    }
    // Columns: the segments of the owned rows, by global id; each row's entries summed per segment.
    std::vector<GO> segments;
    for (auto& entries : ownedEntries) {
      std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      size_t kept = 0;
      for (size_t j = 0; j < entries.size(); ++j) {
        if (kept > 0 && entries[kept - 1].first == entries[j].first) {
          entries[kept - 1].second += entries[j].second;
        } else {
          entries[kept++] = entries[j];
          segments.push_back(entries[j].first);
        }
      }
      entries.resize(kept);
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    const auto colMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                             Teuchos::ArrayView<const GO>(segments), 0, comm_));
    LocalMatrix::row_map_type::non_const_type rowPtr("contactRows", static_cast<size_t>(nOwned) + 1);
    auto rh = Kokkos::create_mirror_view(rowPtr);
    for (LO i = 0; i < nOwned; ++i) rh(i + 1) = rh(i) + ownedEntries[i].size();
    LocalMatrix::index_type::non_const_type entries("contactColumns", rh(nOwned));
    LocalMatrix::values_type values("contactValues", rh(nOwned));
    auto eh = Kokkos::create_mirror_view(entries);
    auto vh = Kokkos::create_mirror_view(values);
    for (LO i = 0; i < nOwned; ++i)
      for (size_t j = 0; j < ownedEntries[i].size(); ++j) {
        eh(rh(i) + j) = static_cast<LO>(std::lower_bound(segments.begin(), segments.end(), ownedEntries[i][j].first) -
                                        segments.begin());
        vh(rh(i) + j) = ownedEntries[i][j].second;
      }
    Kokkos::deep_copy(rowPtr, rh);
    Kokkos::deep_copy(entries, eh);
    Kokkos::deep_copy(values, vh);
    const LocalMatrix localB("contactCoupling", nOwned, static_cast<LO>(segments.size()), rh(nOwned), values, rowPtr,
                             entries);
    const auto importer = Teuchos::rcp(new Tpetra::Import<LO, GO, Node>(segmentMap_, colMap));
    B_ = Teuchos::rcp(new CrsMatrix(localB, ownedRows, colMap, segmentMap_, ownedRows, importer, Teuchos::null));
  }

  // Replicated edge data for the weighted obstacle kernel.
  edgeCoords_ = Kokkos::View<double* [4], DeviceType>("contactEdges", ne);
  edgeSegmentView_ = Kokkos::View<int*, DeviceType>("contactEdgeSegment", ne);
  auto ech = Kokkos::create_mirror_view(edgeCoords_);
  auto esh = Kokkos::create_mirror_view(edgeSegmentView_);
  for (int e = 0; e < ne; ++e) {
    for (int d = 0; d < 4; ++d) ech(e, d) = edges_[e][d];
    esh(e) = edgeSegment_[e];
  }
  Kokkos::deep_copy(edgeCoords_, ech);
  Kokkos::deep_copy(edgeSegmentView_, esh);
}

void ContactCoupling::apply(const std::vector<double>& lambda, Vector& y, double scale, bool accumulate) const {
  Vector l(segmentMap_);
  {
    auto h = l.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (size_t j = 0; j < h.extent(0); ++j) h(j, 0) = lambda[j];
  }
  B_->apply(l, y, Teuchos::NO_TRANS, scale, accumulate ? 1.0 : 0.0);
}

std::vector<double> ContactCoupling::canonicalSums(int n, const std::vector<std::pair<int, double>>& terms) const {
  std::vector<int> index;
  std::vector<double> value;
  for (const auto& [i, v] : terms) index.push_back(i), value.push_back(v);
  const MPI_Comm raw = core::rawMpiComm(*comm_);
  const auto allIndex = core::allGatherv(raw, index);
  const auto allValue = core::allGatherv(raw, value);
  std::vector<std::pair<int, double>> all(allIndex.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = {allIndex[k], allValue[k]};
  std::sort(all.begin(), all.end());
  std::vector<double> out(static_cast<size_t>(n), 0.0);
  for (const auto& [i, v] : all) out[static_cast<size_t>(i)] += v;
  return out;
}


double ContactCoupling::weightedSum(const std::vector<WeightedPoint>& points, const std::vector<double>& lambda,
                                    const std::array<double, 2>* p, const std::vector<char>* rows) const {
  const int c = unknowns_.component;
  SIGNORINI_ASSERT(!p || unknowns_.components == 2, "a moment needs two components");
  double sum = 0;
  core::reproducibleSums(*comm_, 1, points.size(),
                         [&](std::size_t k, double* out) {
                           const auto& q = points[k];
                           out[0] = rows && !(*rows)[q.row]
                                        ? 0.0
                                        : q.weight * lambda[q.segment] * (p ? momentAbout(*p, q.x, q.y, c == 0, c == 1) : 1.0);
                         },
                         &sum);
  return sum;
}

double ContactCoupling::heldShare(const std::vector<double>& lambda, const std::vector<char>* rows) const {
  return weightedSum(heldEnds_, lambda, nullptr, rows);
}

double ContactCoupling::moment(const std::vector<double>& lambda, const std::array<double, 2>& p) const {
  return weightedSum(localEdges_, lambda, &p, nullptr);
}

double ContactCoupling::heldMoment(const std::vector<double>& lambda, const std::array<double, 2>& p,
                                   const std::vector<char>* rows) const {
  return weightedSum(heldEnds_, lambda, &p, rows);
}

std::vector<double> ContactCoupling::applyTranspose(const Vector& u) const {
  if (core::reproducibleArithmetic()) {
    std::vector<std::pair<int, double>> terms;
    const auto local = B_->getLocalMatrixHost();
    const auto colMap = B_->getColMap();
    auto uh = u.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < local.numRows(); ++i)
      for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
        terms.push_back({static_cast<int>(colMap->getGlobalElement(local.graph.entries(k))), local.values(k) * uh(i, 0)});
    return canonicalSums(numSegments(), terms);
  }
  Vector g(segmentMap_);
  B_->apply(u, g, Teuchos::TRANS);
  std::vector<double> out(numSegments(), 0.0);
  if (comm_->getRank() == 0) {
    auto h = g.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (size_t j = 0; j < h.extent(0); ++j) out[j] = h(j, 0);
  }
  if (!out.empty()) Teuchos::broadcast(*comm_, 0, static_cast<int>(out.size()), out.data());
  return out;
}

std::vector<double> ContactCoupling::weightedObstacle(const core::Expression& g, double t) const {
  const int ne = static_cast<int>(edges_.size()), m = numSegments();
  // g sampled at 3 Gauss points per edge on the host, integrated by a kernel.
  Kokkos::View<double* [3], DeviceType> gq("gq", ne);
  auto gqh = Kokkos::create_mirror_view(gq);
  for (int e = 0; e < ne; ++e) {
    const auto& x = edges_[e];
    for (int q = 0; q < 3; ++q) {
      const double px = x[0] + kGauss3Point[q] * (x[2] - x[0]), py = x[1] + kGauss3Point[q] * (x[3] - x[1]);
      std::string bad;  // "<key>: '<text>' evaluates to nan at (x, y), t = ..."
      gqh(e, q) = g.sample(px, py, t, bad);
      // The edges are the same on every rank, so every rank stops here alike.
      if (!bad.empty()) SIGNORINI_USER_ERROR(bad << " on the contact boundary");
    }
  }
  Kokkos::deep_copy(gq, gqh);
  Kokkos::View<double*, DeviceType> gbar("gbar", m);
  const auto X = edgeCoords_;
  const auto seg = edgeSegmentView_;
  Kokkos::parallel_for(
      "signorini::weightedObstacle", Kokkos::RangePolicy<ExecSpace>(0, ne), KOKKOS_LAMBDA(const int e) {
        const double len = Kokkos::Experimental::sqrt((X(e, 2) - X(e, 0)) * (X(e, 2) - X(e, 0)) + (X(e, 3) - X(e, 1)) * (X(e, 3) - X(e, 1)));
        const double sum = (5.0 * gq(e, 0) + 8.0 * gq(e, 1) + 5.0 * gq(e, 2)) / 18.0;
        Kokkos::atomic_add(&gbar(seg(e)), len * sum);
      });
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), gbar);
  return std::vector<double>(h.data(), h.data() + m);
}

std::vector<double> ContactCoupling::smallestGaps(const mesh::Q1Mesh& mesh, const Vector& uOverlap,
                                                 const core::Expression& g, double t) const {
  const auto& bedges = mesh.boundaryEdges();
  SIGNORINI_ASSERT(bedges.size() == localEdgeSegment_.size(), "smallestGaps needs the coupling's own mesh");
  const int nc = unknowns_.components, comp = unknowns_.component;
  std::vector<double> mine(numSegments(), std::numeric_limits<double>::infinity()), smallest(mine.size());
  auto uh = uOverlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::string bad;
  for (size_t i = 0; i < bedges.size() && bad.empty(); ++i) {
    const int j = localEdgeSegment_[i];
    if (j < 0) continue;
    const auto& be = bedges[i];
    const double u0 = unknowns_.sign * uh(nc * be.node[0] + comp, 0), u1 = unknowns_.sign * uh(nc * be.node[1] + comp, 0);
    for (double w : kGauss3Point) {  // the points where the constraint and the input checks sample g
      const auto x = be.at(w);
      mine[j] = std::min(mine[j], (1 - w) * u0 + w * u1 - g.sample(x[0], x[1], t, bad));
    }
  }
  core::throwFirstUserError(*comm_, bad.empty() ? bad : bad + " on the contact boundary");
  if (!mine.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, static_cast<int>(mine.size()), mine.data(), smallest.data());
  return smallest;
}

std::vector<double> ContactCoupling::coarseLoads(const Assembler& coarse) const {
  const auto& cm = coarse.mesh();
  const int nc = coarse.components(), comp = unknowns_.component;
  SIGNORINI_ASSERT(nc == unknowns_.components, "the coarse discretisation has another number of components");
  SIGNORINI_ASSERT(cm.comm()->getSize() == 1, "the coarse discretisation must live on one rank");
  const size_t n = coarse.ownedMap()->getNodeNumElements();
  const int m = numSegments();
  const auto& dirichlet = coarse.dirichletFlags();
  std::vector<double> loads(n * static_cast<size_t>(m), 0.0);
  for (size_t e = 0; e < edges_.size(); ++e) {
    const auto& x = edges_[e];
    const double len = std::hypot(x[2] - x[0], x[3] - x[1]);
    for (int q = 0; q < 3; ++q) {
      double s, r;
      const double px = x[0] + kGauss3Point[q] * (x[2] - x[0]), py = x[1] + kGauss3Point[q] * (x[3] - x[1]);
      const LO cell = cm.locate(px, py, s, r);
      SIGNORINI_ASSERT(cell >= 0, "contact edge point (" << px << ", " << py << ") outside the coarse mesh");
      const double w = (q == 1 ? 8.0 : 5.0) / 18.0 * len * unknowns_.sign;
      for (int a = 0; a < 4; ++a) {
        const double N = ((a & 1) ? s : 1 - s) * ((a & 2) ? r : 1 - r);
        for (int k = 0; k < 2; ++k) {
          const LO node = cm.cornerDofsHost(cell, a, k);
          if (node < 0) continue;
          const size_t i = static_cast<size_t>(nc * node + comp);
          if (dirichlet[i]) continue;
          loads[static_cast<size_t>(edgeSegment_[e]) * n + i] += w * cm.cornerWeightsHost(cell, a, k) * N;
        }
      }
    }
  }
  return loads;
}

std::vector<double> ContactCoupling::lumpedSchurComplement(const Vector& d) const {
  const int m = numSegments();
  if (core::reproducibleArithmetic()) {
    std::vector<std::pair<int, double>> terms;
    auto dh = d.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto local = B_->getLocalMatrixHost();
    const auto colMap = B_->getColMap();
    for (LO i = 0; i < local.numRows(); ++i)
      for (auto a = local.graph.row_map(i); a < local.graph.row_map(i + 1); ++a)
        for (auto b = local.graph.row_map(i); b < local.graph.row_map(i + 1); ++b)
          terms.push_back({static_cast<int>(colMap->getGlobalElement(local.graph.entries(a)) * m +
                                            colMap->getGlobalElement(local.graph.entries(b))),
                           local.values(a) * local.values(b) / dh(i, 0)});
    return canonicalSums(m * m, terms);
  }
  std::vector<double> local(static_cast<size_t>(m) * m, 0.0), global(local.size(), 0.0);
  auto dh = d.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto colMap = B_->getColMap();
  typename CrsMatrix::nonconst_local_inds_host_view_type cols("cols", B_->getNodeMaxNumRowEntries());
  typename CrsMatrix::nonconst_values_host_view_type vals("vals", B_->getNodeMaxNumRowEntries());
  for (LO i = 0; i < static_cast<LO>(B_->getNodeNumRows()); ++i) {
    size_t n = 0;
    B_->getLocalRowCopy(i, cols, vals, n);
    for (size_t a = 0; a < n; ++a)
      for (size_t b = 0; b < n; ++b)
        local[colMap->getGlobalElement(cols(a)) * m + colMap->getGlobalElement(cols(b))] += vals(a) * vals(b) / dh(i, 0);
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

}  // namespace signorini::fem
