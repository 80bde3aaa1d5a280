#include "signorini/mesh/TemporalRegularisation.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include <p4est_bits.h>

#include "signorini/core/Error.hpp"
#include "signorini/mesh/ForestOverlap.hpp"
#include "signorini/mesh/Morton.hpp"

namespace signorini::mesh {
namespace {

/// Per local target cell: the finest overlapping neighbour level minus its own level.
std::vector<int> levelExcess(const Forest& neighbour, const Forest& target) {
  ForestOverlap overlap(neighbour, target, {}, 0);
  std::vector<int> excess(overlap.numTargetCells());
  for (int e = 0; e < overlap.numTargetCells(); ++e) {
    int finest = 0;
    for (const auto& c : overlap.overlapping(e)) finest = std::max(finest, c.level);
    excess[e] = finest - overlap.target(e).level;
  }
  return excess;
}

}  // namespace

std::vector<int> levelExcessByMerge(const Forest& neighbour, const Forest& target) {
  const p4est_t* src = neighbour.p4est();
  const p4est_t* dst = target.p4est();
  SIGNORINI_ASSERT(src->mpisize == 1 && dst->mpisize == 1, "the merge needs both forests whole on one rank");
  std::vector<int> excess;
  excess.reserve(static_cast<size_t>(dst->local_num_quadrants));
  for (p4est_topidx_t t = dst->first_local_tree; t >= 0 && t <= dst->last_local_tree; ++t) {
    sc_array_t* a = &p4est_tree_array_index(src->trees, t)->quadrants;
    sc_array_t* b = &p4est_tree_array_index(dst->trees, t)->quadrants;
    size_t i = 0;  // first source cell that can still overlap the current target cell
    for (size_t k = 0; k < b->elem_count; ++k) {
      const auto* q = p4est_quadrant_array_index(b, k);
      const auto [f, l] = morton::range(*q);
      while (i < a->elem_count && morton::range(*p4est_quadrant_array_index(a, i)).second < f) ++i;
      SIGNORINI_ASSERT(i < a->elem_count, "target cell without an overlapping source cell");
      int finest = 0;
      for (size_t j = i; j < a->elem_count; ++j) {
        const auto* c = p4est_quadrant_array_index(a, j);
        if (morton::range(*c).first > l) break;
        finest = std::max(finest, static_cast<int>(c->level));
      }
      excess.push_back(finest - q->level);
    }
  }
  return excess;
}

int maxLevelExcess(const Forest& neighbour, const Forest& target) {
  int local = -1000, global;
  for (int x : levelExcess(neighbour, target)) local = std::max(local, x);
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, target.comm());
  return global;
}

int regulariseInTime(const Forest& neighbour, Forest& target) {
  const bool oneRank = target.p4est()->mpisize == 1;
  for (int pass = 0;; ++pass) {
    const auto excess = oneRank ? levelExcessByMerge(neighbour, target) : levelExcess(neighbour, target);
    std::vector<char> flags(excess.size());
    int any = 0, anyGlobal = 0;
    for (size_t e = 0; e < excess.size(); ++e) any |= (flags[e] = excess[e] > 1 ? 1 : 0);
    MPI_Allreduce(&any, &anyGlobal, 1, MPI_INT, MPI_MAX, target.comm());
    if (!anyGlobal) return pass;
    target.refineMarkedBalanced(flags);
    target.partition();
  }
}

int regulariseSequence(std::vector<Forest*>& meshes) {
  if (meshes.empty()) return 0;
  // Compact meshes are expanded only while a sweep passes them (two at a time) and compacted again.
  std::vector<char> compact(meshes.size());
  for (size_t n = 0; n < meshes.size(); ++n) compact[n] = meshes[n]->isCompact();
  auto release = [&](size_t n) {
    if (compact[n]) meshes[n]->compact();
  };
  // Sweep forward and backward until a round refines nothing (in the decks measured the second
  // round has never refined: it confirms). A directed pair that has been checked is checked again
  // only once one of its meshes has been refined since: refining the neighbour can break what was
  // checked; refining the target cannot (the check is conservative there). A skipped check would
  // have refined nothing, so the meshes are the same as with every pair checked every time. The
  // versions count each mesh's refinement passes (the same on every rank).
  std::vector<long> version(meshes.size(), 0);
  std::vector<std::pair<long, long>> checkedForward(meshes.size(), {-1, -1}), checkedBackward(meshes.size(), {-1, -1});
  for (size_t n = 1; n < meshes.size(); ++n)
    SIGNORINI_ASSERT(std::find(meshes.begin(), meshes.begin() + n, meshes[n]) == meshes.begin() + n,
                     "regulariseSequence: one forest twice in the sequence");
  int checks = 0;
  auto check = [&](size_t neighbour, size_t target, std::pair<long, long>& checked) {
    if (checked == std::make_pair(version[neighbour], version[target])) {
      release(neighbour);  // it may still be expanded as the previous pair's target
      return 0;
    }
    ++checks;
    meshes[neighbour]->expand();
    meshes[target]->expand();
    const int passes = regulariseInTime(*meshes[neighbour], *meshes[target]);
    version[target] += passes;
    checked = {version[neighbour], version[target]};
    release(neighbour);
    return passes;
  };
  for (int changed = 1; changed;) {
    changed = 0;
    for (size_t n = 1; n < meshes.size(); ++n) changed += check(n - 1, n, checkedForward[n]);
    release(meshes.size() - 1);
    for (size_t n = meshes.size() - 1; n-- > 0;) changed += check(n + 1, n, checkedBackward[n]);
    release(0);
  }
  // A refined mesh was re-partitioned by regulariseInTime; compact ones stay as they were stored.
  for (size_t n = 0; n < meshes.size(); ++n)
    if (!compact[n]) meshes[n]->partition();
  return checks;
}

void regulariseSteps(std::vector<std::shared_ptr<Forest>>& steps) {
  std::set<const Forest*> seen;
  for (auto& f : steps)
    if (!seen.insert(f.get()).second) f = std::make_shared<Forest>(*f);
  std::vector<Forest*> raw;
  for (auto& f : steps) raw.push_back(f.get());
  regulariseSequence(raw);
  for (size_t n = 1; n < steps.size(); ++n)
    if (steps[n]->sameCells(*steps[n - 1])) steps[n] = steps[n - 1];
}

}  // namespace signorini::mesh
