/* evgrid score-motion: what the motion truth says of each cell at a scan. */
#pragma once

#include <cstddef>
#include <memory>

#include "CMotionTruth.h"

namespace evgrid
{
class CObservedCells;

/** When an event of the truth counts as having happened: Observed, at the
 * first scan that saw it, and only if the scans could tell (what the map can
 * know: the default); Physical, when the simulator says it happened. */
enum class TruthTimes
{
	Observed,
	Physical
};

/** Replays the truth's scan records in order, with what the scored scans
 * observed, and tells which cells hold an event as of the latest scan. The
 * scorer asks appeared() of that scan's hit cells only and disappeared() of
 * its crossed cells only. */
class CTruthEvents
{
   public:
	/** `window`: the map's motionWindow, seconds. */
	static std::unique_ptr<CTruthEvents> create(
		TruthTimes times, const TTruthGrid& grid, double window);
	virtual ~CTruthEvents() = default;

	/** Applies scan k's record; scans come in order from 0. */
	virtual void apply(std::size_t k, const TTruthScan& scan) = 0;
	/** What the latest scan observed, when it is scored (after apply()). */
	virtual void observe(const CObservedCells& seen) = 0;

	/** Something appeared in `cell` within the window, as of the latest
	 * scan. */
	virtual bool appeared(int cell) const = 0;
	/** Something left `cell` within the window, as of the latest scan. */
	virtual bool disappeared(int cell) const = 0;
};

}  // namespace evgrid
