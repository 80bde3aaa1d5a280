#pragma once
/// \file Marking.hpp
/// Marking strategies on cell indicators (DESIGN 1.3), global over all MPI ranks and
/// independent of the partition: thresholds are found by bisection on the bit patterns of the
/// (non-negative) indicators with one reduction per bisection step.
///
/// Ties: indicators closer than `tieTolerance` times the largest indicator of all ranks count as
/// equal. A cell that ties with a marked cell is marked too (one that ties with a cell kept from
/// coarsening is kept), so rounding (another number of ranks, another order of summation) cannot
/// decide which of two equal cells is refined. 0 compares the values exactly.
#include <functional>
#include <vector>

#include <mpi.h>

namespace signorini::adapt {

/// The number of cells a fraction of `cells` means: ceil(fraction * cells) (roundUp) or
/// floor(fraction * cells), where a product within rounding of an integer is that integer
/// (0.55 of 100 cells is 55, although 0.55 * 100 evaluates to 55.000000000000007).
long long cellsOfFraction(double fraction, long long cells, bool roundUp);

/// Flags the cells with the largest indicators: at least ceil(fraction * N) cells of the N cells
/// of all ranks (more only when indicators tie with the threshold), but never a cell whose
/// indicator ties with 0 (a step without error refines nothing, a region at rest in a step is not
/// refined, so fewer cells are flagged when fewer have error). The paper's strategy (50%).
std::vector<char> markFixedFraction(const std::vector<double>& indicators, double fraction, double tieTolerance,
                                    MPI_Comm comm);

/// Doerfler/bulk marking: the cells with the largest indicators whose sum reaches
/// fraction * (sum of all indicators); indicators are squared cell contributions eta_K^2. Never a
/// cell whose indicator ties with 0.
std::vector<char> markBulk(const std::vector<double>& indicators, double fraction, double tieTolerance,
                           MPI_Comm comm);

/// Flags the cells with the smallest indicators: at most floor(fraction * N) cells (for coarsening),
/// fewer when indicators tie at the threshold. When more cells than that tie with 0 (no error, as
/// in a region still at rest), the first of them along the space-filling curve are flagged, exactly
/// floor(fraction * N): \p positions holds each local cell's curve position among the cells of all
/// ranks (unique, the same on any number of ranks), so the choice does not depend on the partition,
/// and sibling cells, consecutive on the curve, are chosen together.
std::vector<char> markSmallest(const std::vector<double>& indicators, const std::vector<long long>& positions,
                               double fraction, double tieTolerance, MPI_Comm comm);

/// \p mark applied to the indicators of the cells flagged in \p among only (its fraction counts
/// those cells), as flags for all cells: 0 for the others.
std::vector<char> markAmong(const std::vector<double>& indicators, const std::vector<char>& among,
                            const std::function<std::vector<char>(const std::vector<double>&)>& mark);

/// markSmallest among the cells whose level (\p levels, one per cell) is above \p minLevel, the
/// ones coarsening can merge: the fraction counts those cells only, and no other cell is flagged.
std::vector<char> markSmallestAbove(const std::vector<double>& indicators, const std::vector<long long>& positions,
                                    const std::vector<int>& levels, int minLevel, double fraction,
                                    double tieTolerance, MPI_Comm comm);

}  // namespace signorini::adapt
