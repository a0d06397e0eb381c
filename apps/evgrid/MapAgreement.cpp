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
			add(*tally,
				ours.getCellDecision(
					mrpt.idx2x(static_cast<std::size_t>(cx)), y));
		}
	}
	return result;
}

}  // namespace evgrid
