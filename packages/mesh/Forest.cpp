#include "signorini/mesh/Forest.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

#include <p4est_bits.h>
#include <p4est_communication.h>
#include <p4est_extended.h>
#include <p4est_io.h>
#include <p4est_ghost.h>
#include <p4est_iterate.h>
#include <p4est_lnodes.h>

#include "signorini/core/Error.hpp"
#include "signorini/mesh/Morton.hpp"
#include "signorini/core/MpiComm.hpp"
#include <sc.h>

namespace signorini::mesh {

void initializeP4est(MPI_Comm comm) {
  static bool initialized = false;
  if (initialized) return;
  sc_init(comm, 0, 0, nullptr, SC_LP_ERROR);
  p4est_init(nullptr, SC_LP_ERROR);
  initialized = true;
}

struct Forest::Compact {
  std::vector<unsigned char> levels;             ///< p4est level of every local cell, curve order
  std::vector<p4est_gloidx_t> firstQuadrant;     ///< p4est global_first_quadrant (ranks + 1)
  std::vector<p4est_gloidx_t> cellsBeforeTree;   ///< cumulative global cells per tree (trees + 1)
  p4est_quadrant_t firstPosition;                ///< this rank's first position (p.which_tree set)
};

Forest::Forest(std::shared_ptr<const CoarseMesh> coarse, MPI_Comm comm, int level) : coarse_(std::move(coarse)), comm_(comm) {
  initializeP4est(comm);
  p4est_ = p4est_new_ext(comm, coarse_->connectivity(), 0, level + coarse_->levelOffset(), 1, 0, nullptr, nullptr);
}

Forest::Forest(const Forest& other) : coarse_(other.coarse_), comm_(other.comm_) {
  if (other.p4est_)
    p4est_ = p4est_copy(other.p4est_, 0);
  else
    compact_ = std::make_unique<Compact>(*other.compact_);
}

Forest::~Forest() {
  if (p4est_) p4est_destroy(p4est_);
}

p4est_t* Forest::p4est() const {
  SIGNORINI_ASSERT(p4est_, "the forest is compact: expand() it first");
  return p4est_;
}

long long Forest::numGlobalCells() const {
  return static_cast<long long>(p4est_ ? p4est_->global_num_quadrants : compact_->firstQuadrant.back());
}

long long Forest::numGlobalNodes() const {
  SIGNORINI_ASSERT(!isCompact(), "the forest is compact: expand() it first");
  p4est_ghost_t* ghost = p4est_ghost_new(p4est_, P4EST_CONNECT_FULL);
  p4est_lnodes_t* lnodes = p4est_lnodes_new(p4est_, ghost, 1);
  long long owned = lnodes->owned_count, all = 0;
  p4est_lnodes_destroy(lnodes);
  p4est_ghost_destroy(ghost);
  MPI_Allreduce(&owned, &all, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  return all;
}

long long Forest::firstGlobalCell() const {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  return static_cast<long long>(p4est_ ? p4est_->global_first_quadrant[rank] : compact_->firstQuadrant[rank]);
}

int Forest::numLocalCells() const {
  return p4est_ ? static_cast<int>(p4est_->local_num_quadrants) : static_cast<int>(compact_->levels.size());
}

void Forest::localLevels(std::vector<unsigned char>& levels, p4est_quadrant_t& first) const {
  if (compact_) {
    levels = compact_->levels;
    first = compact_->firstPosition;
    return;
  }
  levels.clear();
  levels.reserve(static_cast<size_t>(p4est_->local_num_quadrants));
  for (p4est_topidx_t t = p4est_->first_local_tree; t >= 0 && t <= p4est_->last_local_tree; ++t) {
    sc_array_t* quadrants = &p4est_tree_array_index(p4est_->trees, t)->quadrants;
    for (size_t i = 0; i < quadrants->elem_count; ++i)
      levels.push_back(static_cast<unsigned char>(p4est_quadrant_array_index(quadrants, i)->level));
  }
  first = p4est_->global_first_position[p4est_->mpirank];
}

int Forest::minimumLevel() const {
  std::vector<unsigned char> levels;
  p4est_quadrant_t first;
  localLevels(levels, first);
  int local = std::numeric_limits<int>::max(), global = 0;
  for (unsigned char l : levels) local = std::min(local, static_cast<int>(l));
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, comm_);
  return global - coarse_->levelOffset();
}

void Forest::compact() {
  if (!p4est_) return;
  auto c = std::make_unique<Compact>();
  localLevels(c->levels, c->firstPosition);
  c->firstQuadrant.assign(p4est_->global_first_quadrant, p4est_->global_first_quadrant + p4est_->mpisize + 1);
  c->cellsBeforeTree.resize(static_cast<size_t>(p4est_->connectivity->num_trees) + 1);
  p4est_comm_count_pertree(p4est_, c->cellsBeforeTree.data());  // collective
  p4est_destroy(p4est_);
  p4est_ = nullptr;
  compact_ = std::move(c);
}

void Forest::expand() {
  if (p4est_) return;
  const Compact& c = *compact_;
  // Each cell starts where the previous one ends along the curve: its Morton id at the finest
  // level gives its (x, y), and the id advances by the cell's size; a tree ends at 4^QMAXLEVEL.
  const uint64_t treeEnd = morton::span(0);
  uint64_t id = morton::firstId(c.firstPosition);
  sc_array_t* coordinates = sc_array_new_count(sizeof(p4est_qcoord_t), 3 * c.levels.size());
  auto* out = reinterpret_cast<p4est_qcoord_t*>(coordinates->array);
  for (unsigned char level : c.levels) {
    if (id == treeEnd) id = 0;
    const auto [x, y] = morton::coordinates(id);
    *out++ = x;
    *out++ = y;
    *out++ = level;
    id += morton::span(level);
  }
  p4est_ = p4est_inflate(comm_, const_cast<p4est_connectivity_t*>(coarse_->connectivity()), c.firstQuadrant.data(),
                         c.cellsBeforeTree.data(), coordinates, nullptr, nullptr);  // collective
  sc_array_destroy(coordinates);
  compact_.reset();
}

namespace {
int refineCallback(p4est_t* p, p4est_topidx_t tree, p4est_quadrant_t* q) {
  const auto& f = *static_cast<const std::function<bool(int, const p4est_quadrant_t&)>*>(p->user_pointer);
  return f(static_cast<int>(tree), *q) ? 1 : 0;
}
}  // namespace

void Forest::refineIf(const std::function<bool(int tree, const p4est_quadrant_t& q)>& refine) {
  void* saved = p4est_->user_pointer;
  p4est_->user_pointer = const_cast<void*>(static_cast<const void*>(&refine));
  p4est_refine(p4est(), 0, refineCallback, nullptr);
  p4est_->user_pointer = saved;
}

namespace {
using CellKey = std::tuple<int, p4est_qcoord_t, p4est_qcoord_t, int>;

std::set<CellKey> flaggedCells(p4est_t* p4est, const std::vector<char>& flags) {
  std::set<CellKey> keys;
  size_t e = 0;
  for (p4est_topidx_t t = p4est->first_local_tree; t <= p4est->last_local_tree; ++t) {
    p4est_tree_t* tree = p4est_tree_array_index(p4est->trees, t);
    for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi, ++e) {
      const auto* q = p4est_quadrant_array_index(&tree->quadrants, qi);
      if (flags.at(e)) keys.insert({static_cast<int>(t), q->x, q->y, q->level});
    }
  }
  return keys;
}

struct CoarsenContext {
  std::set<CellKey> keys;
  int minLevel;
};

int coarsenCallback(p4est_t* p, p4est_topidx_t tree, p4est_quadrant_t* children[]) {
  const auto& ctx = *static_cast<const CoarsenContext*>(p->user_pointer);
  if (children[0]->level <= ctx.minLevel) return 0;
  for (int c = 0; c < P4EST_CHILDREN; ++c)
    if (!ctx.keys.count({static_cast<int>(tree), children[c]->x, children[c]->y, children[c]->level})) return 0;
  return 1;
}

/// Stores the flags (local cell order) in the quadrants' user_int: the forest holds no user data
/// (data_size 0), so the field is free, and a refine callback can read its own quadrant's flag
/// without a search.
void storeFlags(p4est_t* p4est, const std::vector<char>& flags) {
  SIGNORINI_ASSERT(p4est->data_size == 0, "the forest carries user data");
  size_t e = 0;
  for (p4est_topidx_t t = p4est->first_local_tree; t <= p4est->last_local_tree; ++t) {
    p4est_tree_t* tree = p4est_tree_array_index(p4est->trees, t);
    for (size_t qi = 0; qi < tree->quadrants.elem_count; ++qi, ++e)
      p4est_quadrant_array_index(&tree->quadrants, qi)->p.user_int = flags[e] ? 1 : 0;
  }
}

/// Refines, once, the quadrants flagged by storeFlags.
void refineStoredFlags(p4est_t* p4est) {
  p4est_refine(
      p4est, 0, [](p4est_t*, p4est_topidx_t, p4est_quadrant_t* q) { return q->p.user_int; }, nullptr);
}
}  // namespace

void Forest::refineMarked(const std::vector<char>& flags) {
  SIGNORINI_ASSERT(flags.size() == static_cast<size_t>(numLocalCells()), "one flag per local cell");
  storeFlags(p4est(), flags);
  refineStoredFlags(p4est_);
}

namespace {
/// "Refining cell `finer` forces refining cell `coarser`": the two touch (face or corner) and
/// `coarser` is one level coarser. Local cells are numbered 0.., ghosts -1 - (ghost index).
struct BalanceEdge {
  long finer, coarser;
};

long cellNumber(p4est_t* p4est, p4est_topidx_t tree, int8_t isGhost, p4est_locidx_t quadid) {
  if (isGhost) return -1 - static_cast<long>(quadid);
  return static_cast<long>(p4est_tree_array_index(p4est->trees, tree)->quadrants_offset + quadid);
}

void addBalanceEdge(std::vector<BalanceEdge>& edges, long a, int levelA, long b, int levelB) {
  if (levelA == levelB + 1 && b >= 0) edges.push_back({a, b});
  if (levelB == levelA + 1 && a >= 0) edges.push_back({b, a});
}

void balanceFaceEdges(p4est_iter_face_info_t* info, void* user) {
  auto& edges = *static_cast<std::vector<BalanceEdge>*>(user);
  if (info->sides.elem_count != 2) return;
  const auto* s0 = static_cast<const p4est_iter_face_side_t*>(sc_array_index(&info->sides, 0));
  const auto* s1 = static_cast<const p4est_iter_face_side_t*>(sc_array_index(&info->sides, 1));
  if (!s0->is_hanging && !s1->is_hanging) return;  // conforming: same level
  const auto* fine = s0->is_hanging ? s0 : s1;
  const auto* coarse = s0->is_hanging ? s1 : s0;
  const long c = cellNumber(info->p4est, coarse->treeid, coarse->is.full.is_ghost, coarse->is.full.quadid);
  for (int i = 0; i < 2; ++i) {
    if (!fine->is.hanging.quad[i]) continue;  // neither local nor in the ghost layer
    const long f = cellNumber(info->p4est, fine->treeid, fine->is.hanging.is_ghost[i], fine->is.hanging.quadid[i]);
    addBalanceEdge(edges, f, fine->is.hanging.quad[i]->level, c, coarse->is.full.quad->level);
  }
}

void balanceCornerEdges(p4est_iter_corner_info_t* info, void* user) {
  auto& edges = *static_cast<std::vector<BalanceEdge>*>(user);
  const size_t n = info->sides.elem_count;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const auto* a = static_cast<const p4est_iter_corner_side_t*>(sc_array_index(&info->sides, i));
      const auto* b = static_cast<const p4est_iter_corner_side_t*>(sc_array_index(&info->sides, j));
      addBalanceEdge(edges, cellNumber(info->p4est, a->treeid, a->is_ghost, a->quadid), a->quad->level,
                     cellNumber(info->p4est, b->treeid, b->is_ghost, b->quadid), b->quad->level);
    }
}
}  // namespace

void Forest::refineMarkedBalanced(const std::vector<char>& flags) {
  // In a balanced forest, touching cells differ by at most one level. Refining cell B once leaves
  // it unbalanced exactly against the touching cells A one level coarser; those must be refined
  // too, which may force their coarser neighbours, and so on. Every balanced refinement of the
  // refined forest refines this closure, and refining the closure once is balanced: it is the
  // coarsest balanced refinement, i.e. p4est_balance's result.
  SIGNORINI_ASSERT(flags.size() == static_cast<size_t>(numLocalCells()), "one flag per local cell");
  SIGNORINI_ASSERT(!isCompact(), "the forest is compact: expand() it first");
  p4est_ghost_t* ghost = p4est_ghost_new(p4est_, P4EST_CONNECT_FULL);
  std::vector<BalanceEdge> edges;
  p4est_iterate(p4est_, ghost, &edges, nullptr, balanceFaceEdges, balanceCornerEdges);
  // Edges grouped by their finer cell: the local ones by cell, those from ghosts by ghost.
  const long nLocal = numLocalCells(), nGhost = static_cast<long>(ghost->ghosts.elem_count);
  std::sort(edges.begin(), edges.end(), [](const BalanceEdge& a, const BalanceEdge& b) { return a.finer < b.finer; });
  auto forcedBy = [&](long finer) {  // [begin, end) of the edges leaving `finer`
    auto lo = std::lower_bound(edges.begin(), edges.end(), finer,
                               [](const BalanceEdge& e, long v) { return e.finer < v; });
    auto hi = lo;
    while (hi != edges.end() && hi->finer == finer) ++hi;
    return std::make_pair(lo, hi);
  };
  std::vector<char> closure(flags.begin(), flags.end());
  std::vector<long> work;
  for (long e = 0; e < nLocal; ++e)
    if (closure[e]) work.push_back(e);
  std::vector<char> ghostFlags(static_cast<size_t>(nGhost), 0), ghostSeen(static_cast<size_t>(nGhost), 0);
  std::vector<void*> mirrors(ghost->mirrors.elem_count);
  for (int round = 0;; ++round) {
    if (round > 0) {  // flags of the ghosts from their owners; newly flagged ghosts force local cells
      for (size_t m = 0; m < mirrors.size(); ++m)
        mirrors[m] = &closure[p4est_quadrant_array_index(&ghost->mirrors, m)->p.piggy3.local_num];
      p4est_ghost_exchange_custom(p4est_, ghost, sizeof(char), mirrors.data(), ghostFlags.data());
      for (long g = 0; g < nGhost; ++g)
        if (ghostFlags[g] && !ghostSeen[g]) ghostSeen[g] = 1, work.push_back(-1 - g);
    }
    long added = 0;
    while (!work.empty()) {
      const long finer = work.back();
      work.pop_back();
      const auto [lo, hi] = forcedBy(finer);
      for (auto it = lo; it != hi; ++it)
        if (!closure[it->coarser]) closure[it->coarser] = 1, work.push_back(it->coarser), ++added;
    }
    long addedGlobal = 0;
    MPI_Allreduce(&added, &addedGlobal, 1, MPI_LONG, MPI_SUM, p4est_->mpicomm);
    if (round > 0 && addedGlobal == 0) break;
  }
  p4est_ghost_destroy(ghost);
  refineMarked(closure);
}

namespace {
/// The flagged cells of all ranks.
std::set<CellKey> allFlaggedCells(p4est_t* p4est, const std::vector<char>& flags) {
  std::vector<int> mine;
  for (const auto& [t, x, y, l] : flaggedCells(p4est, flags)) mine.insert(mine.end(), {t, x, y, l});
  const std::vector<int> all = core::allGatherv(p4est->mpicomm, mine);
  std::set<CellKey> keys;
  for (size_t i = 0; i + 3 < all.size(); i += 4) keys.insert({all[i], all[i + 1], all[i + 2], all[i + 3]});
  return keys;
}
}  // namespace

void Forest::coarsenMarked(const std::vector<char>& flags, int minLevel) {
  refineAndCoarsen(std::vector<char>(flags.size(), 0), flags, minLevel);
}

void Forest::refineAndCoarsen(const std::vector<char>& refine, const std::vector<char>& coarsen, int minLevel) {
  SIGNORINI_ASSERT(refine.size() == static_cast<size_t>(numLocalCells()) &&
                       coarsen.size() == static_cast<size_t>(numLocalCells()),
                   "one flag per local cell");
  SIGNORINI_ASSERT(!isCompact(), "the forest is compact: expand() it first");
  int coarsenLocal = 0, coarsenAny = 0;
  for (char c : coarsen) coarsenLocal |= c ? 1 : 0;
  MPI_Allreduce(&coarsenLocal, &coarsenAny, 1, MPI_INT, MPI_MAX, p4est_->mpicomm);
  if (!coarsenAny) {  // refinement only: the flags stay with the cells, no exchange needed
    refineMarked(refine);
    return;
  }
  // Families may be split between ranks: share the flagged cells, partition so that families
  // are local, coarsen, then refine by position.
  const auto refineKeys = allFlaggedCells(p4est_, refine);
  CoarsenContext ctx{allFlaggedCells(p4est_, coarsen), minLevel + coarse_->levelOffset()};
  p4est_partition(p4est_, 1, nullptr);
  void* saved = p4est_->user_pointer;
  p4est_->user_pointer = &ctx;
  p4est_coarsen(p4est_, 0, coarsenCallback, nullptr);
  p4est_->user_pointer = saved;
  refineIf([&](int tree, const p4est_quadrant_t& q) { return refineKeys.count({tree, q.x, q.y, q.level}) > 0; });
}

bool Forest::sameCells(const Forest& other) const {
  std::vector<unsigned char> a, b;
  p4est_quadrant_t firstA, firstB;
  localLevels(a, firstA);
  other.localLevels(b, firstB);
  // The same first position and the same levels in curve order: the same cells, cell by cell.
  int same = numGlobalCells() == other.numGlobalCells() && a == b && p4est_quadrant_is_equal_piggy(&firstA, &firstB);
  int all = 0;
  MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_LAND, comm_);
  return all != 0;
}

size_t Forest::bytes() const {
  if (p4est_) return p4est_memory_used(p4est_);
  return sizeof(Compact) + compact_->levels.capacity() +
         (compact_->firstQuadrant.capacity() + compact_->cellsBeforeTree.capacity()) * sizeof(p4est_gloidx_t);
}

void Forest::balance() { p4est_balance(p4est(), P4EST_CONNECT_FULL, nullptr); }

void Forest::partition() { p4est_partition(p4est(), 0, nullptr); }

}  // namespace signorini::mesh
