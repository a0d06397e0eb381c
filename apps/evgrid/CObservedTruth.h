/* evgrid score-motion: the truth dated by the scans that observed it. */
#pragma once

#include <cstdint>
#include <vector>

#include "CTruthEvents.h"

namespace evgrid
{
/** The events as the scored scans saw them, since the map can know no
 * more. A covering run of a cell is a run of consecutive scans whose record
 * lists it occupied (a thing that sweeps it between two scans is no run,
 * and no scan can tell it).
 * - An appearance is seen at the first scan of a run that hits the cell, if
 *   a scan crossed the cell between the previous run's end (or the start)
 *   and this run's beginning.
 * - A run's end is seen at the first scan that crosses the cell after the
 *   thing left it, if a scan of the run hit it; it holds until the cell is
 *   covered again. */
class CObservedTruth : public CTruthEvents
{
   public:
	CObservedTruth(const TTruthGrid& grid, double window);

	void apply(std::size_t k, const TTruthScan& scan) override;
	void observe(const CObservedCells& seen) override;

	/** A moving thing covers `cell` and its appearance was seen at most
	 * `window` before the latest scan. */
	bool appeared(int cell) const override
	{
		return covered(cell) && m_appearedAt[cell] >= 0 &&
			m_time - m_appearedAt[cell] <= m_window;
	}
	/** No thing covers `cell` and the end of its last run was seen at most
	 * `window` before the latest scan. */
	bool disappeared(int cell) const override
	{
		return !covered(cell) && m_goneAt[cell] >= 0 &&
			m_time - m_goneAt[cell] <= m_window;
	}

   private:
	/** Per cell: crossed, uncovered, since the previous run ended; hit
	 * during the current (or last) run; its last run was hit and has
	 * ended. */
	static constexpr std::uint8_t kSeenFree = 1, kRunHit = 2, kEnded = 4;

	bool covered(int cell) const { return m_lastCovered[cell] == m_scan; }

	/** The window plus a margin for the times' rounding to 0.01 s. */
	double m_window;
	long m_scan = -1;
	double m_time = 0;
	/** The cells the previous scan's record lists occupied. */
	std::vector<int> m_previous;
	/** Per cell: the latest scan listing it occupied (-1: none), the flags,
	 * and when its appearance and its going were seen (-1: not, or not an
	 * event). */
	std::vector<long> m_lastCovered;
	std::vector<std::uint8_t> m_flags;
	std::vector<double> m_appearedAt, m_goneAt;
};

}  // namespace evgrid
