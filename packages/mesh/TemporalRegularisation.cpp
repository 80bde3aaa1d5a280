#include "TemporalRegularisation.hpp"

#include <algorithm>
#include <set>

#include "ForestOverlap.hpp"

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

int maxLevelExcess(const Forest& neighbour, const Forest& target) {
  int local = -1000, global;
  for (int x : levelExcess(neighbour, target)) local = std::max(local, x);
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, target.comm());
  return global;
}

int regulariseInTime(const Forest& neighbour, Forest& target) {
  for (int pass = 0;; ++pass) {
    const auto excess = levelExcess(neighbour, target);
    std::vector<char> flags(excess.size());
    int any = 0, anyGlobal = 0;
    for (size_t e = 0; e < excess.size(); ++e) any |= (flags[e] = excess[e] > 1 ? 1 : 0);
    MPI_Allreduce(&any, &anyGlobal, 1, MPI_INT, MPI_MAX, target.comm());
    if (!anyGlobal) return pass;
    target.refineMarkedBalanced(flags);
    target.partition();
  }
}

void regulariseSequence(std::vector<Forest*>& meshes) {
  // A backward refinement of T^n can, inside the refined cells, leave T^{n+1} two levels coarser
  // than T^n: sweep forward and backward until a round refines nothing.
  for (int changed = 1; changed;) {
    changed = 0;
    for (size_t n = 1; n < meshes.size(); ++n) changed += regulariseInTime(*meshes[n - 1], *meshes[n]);
    for (size_t n = meshes.size() - 1; n-- > 0;) changed += regulariseInTime(*meshes[n + 1], *meshes[n]);
  }
  for (Forest* f : meshes) f->partition();
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
