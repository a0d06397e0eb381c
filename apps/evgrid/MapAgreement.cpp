/* evgrid compare: how our map's decisions agree with MRPT's occupancy grid,
 * cell by cell. */

#include "MapAgreement.h"

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

using mrpt_evidential::Decision;

namespace evgrid
{
namespace
{
void add(TDecisionTally& tally, Decision d)
{
	switch (d)
	{
		case Decision::Occupied: ++tally.occupied; return;
		case Decision::Free: ++tally.free; return;
		case Decision::Conflict: ++tally.conflict; return;
		case Decision::Unknown: break;
	}
	++tally.unknown;
}

/** Whether ours calls a neighbour of the cell at (x, y) occupied. */
bool occupiedAround(
	const mrpt_evidential::CEvidentialGridMap2D& ours, double x, double y, double step)
{
	for (int dy = -1; dy <= 1; ++dy)
		for (int dx = -1; dx <= 1; ++dx)
			if ((dx != 0 || dy != 0) &&
				ours.getCellDecision(x + dx * step, y + dy * step) == Decision::Occupied)
				return true;
	return false;
}
}  // namespace

TMapAgreement compareCells(
	const mrpt::maps::COccupancyGridMap2D& mrpt,
	const mrpt_evidential::CEvidentialGridMap2D& ours)
{
	TMapAgreement result;
	const int sizeX = static_cast<int>(mrpt.getSizeX());
	const int sizeY = static_cast<int>(mrpt.getSizeY());
	for (int cy = 0; cy < sizeY; ++cy)
	{
		const double y = mrpt.idx2y(static_cast<std::size_t>(cy));
		for (int cx = 0; cx < sizeX; ++cx)
		{
			++result.mrptCells;
			const double p = mrpt.getCell(cx, cy);
			TDecisionTally* tally = nullptr;
			if (p < kMrptOccupiedBelow) tally = &result.mrptOccupied;
			else if (p > kMrptFreeAbove) tally = &result.mrptFree;
			if (!tally)
			{
				++result.mrptUncertain;
				continue;
			}
			const double x = mrpt.idx2x(static_cast<std::size_t>(cx));
			const Decision d = ours.getCellDecision(x, y);
			add(*tally, d);
			if (tally == &result.mrptOccupied &&
				(d == Decision::Occupied || occupiedAround(ours, x, y, mrpt.getResolution())))
				++result.mrptOccupiedNearOurs;
		}
	}
	return result;
}

}  // namespace evgrid
