/* evgrid compare: how our map's decisions agree with MRPT's occupancy grid,
 * cell by cell. */
#pragma once

#include <cstddef>

namespace mrpt::maps
{
class COccupancyGridMap2D;
}
namespace mrpt_evidential
{
class CEvidentialGridMap2D;
}

namespace evgrid
{
/** MRPT's cells hold the probability of being free (0 occupied, 1 free):
 * a cell below kMrptOccupiedBelow is occupied, above kMrptFreeAbove free,
 * anything between uncertain (0.5: never seen). */
constexpr double kMrptOccupiedBelow = 0.4;
constexpr double kMrptFreeAbove = 0.6;

/** Our map's decisions over a set of cells. */
struct TDecisionTally
{
	std::size_t occupied = 0, free = 0, unknown = 0, conflict = 0;
	std::size_t total() const { return occupied + free + unknown + conflict; }
};

struct TMapAgreement
{
	/** Every cell of MRPT's grid = occupied + free + uncertain. */
	std::size_t mrptCells = 0, mrptUncertain = 0;
	/** Our decisions at the centres of MRPT's occupied and free cells. */
	TDecisionTally mrptOccupied, mrptFree;
	/** MRPT's occupied cells that ours calls occupied at their centre or
	 * at the centre of one of their eight neighbours: a wall both maps hold,
	 * in rows a cell apart where the poses' error moved it between visits. */
	std::size_t mrptOccupiedNearOurs = 0;
};

/** Visits every cell of `mrpt` and, for its occupied and free ones, reads
 * `ours`' getCellDecision() at the cell's centre (Unknown outside ours);
 * for an occupied one that ours does not call occupied, also at its eight
 * neighbours' centres. */
TMapAgreement compareCells(
	const mrpt::maps::COccupancyGridMap2D& mrpt,
	const mrpt_evidential::CEvidentialGridMap2D& ours);

}  // namespace evgrid
