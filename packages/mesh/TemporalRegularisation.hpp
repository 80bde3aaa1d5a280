#pragma once
/// \file TemporalRegularisation.hpp
/// Paper Algorithm 5.3 (DESIGN 1.3): no cell of a step's mesh may be more than one level coarser
/// than a cell of a neighbouring step's mesh that it overlaps ("multiple hanging nodes in time").
#include <memory>
#include <vector>

#include "signorini/mesh/Forest.hpp"

namespace signorini::mesh {

/// Refines \p target until none of its cells is more than one level coarser than an overlapping
/// cell of \p neighbour, keeping 2:1 balance (\p target must be balanced on entry). Returns the
/// number of refinement passes made.
int regulariseInTime(const Forest& neighbour, Forest& target);

/// Algorithm 5.3 over a sequence of step meshes: forward sweeps (each mesh against its
/// predecessor) and backward sweeps (against its successor), repeated until a round refines
/// nothing, then re-partitioning. A pair is checked again only once one of its meshes has been
/// refined since its last check; the meshes are those of checking every pair in every sweep.
/// Compact meshes (Forest::compact()) are expanded only while a sweep passes them and are compact
/// on return. Returns the number of pairs checked (regulariseInTime calls).
int regulariseSequence(std::vector<Forest*>& meshes);

/// regulariseSequence on the meshes of consecutive steps, which may share one forest (equal
/// meshes of neighbouring steps are stored once): each step is regularised on its own copy, so a
/// refinement one step needs does not refine the steps it shared with; afterwards neighbouring
/// steps with equal meshes share one forest again.
void regulariseSteps(std::vector<std::shared_ptr<Forest>>& steps);

/// Largest level difference (neighbour level - target level) over overlapping cells, all ranks
/// (through ForestOverlap on any partition).
int maxLevelExcess(const Forest& neighbour, const Forest& target);

/// Per cell of \p target (local order): the finest level of the overlapping cells of \p neighbour
/// minus its own level, by one merge of the two cell sequences of each tree in curve order
/// (O(cells), no overlap records; both forests whole on one rank). regulariseInTime uses it on one
/// rank instead of ForestOverlap.
std::vector<int> levelExcessByMerge(const Forest& neighbour, const Forest& target);

}  // namespace signorini::mesh
