/* evgrid score-motion: the truth dated by the physical events. */
#pragma once

#include <vector>

#include "CTruthEvents.h"

namespace evgrid
{
/** Keeps, per cell, when its current covering by a moving thing began and
 * when a thing last left it, as the simulator says, whether or not a scan
 * saw it happen. */
class CPhysicalTruth : public CTruthEvents
{
   public:
	CPhysicalTruth(const TTruthGrid& grid, double window);

	void apply(std::size_t k, const TTruthScan& scan) override;
	void observe(const CObservedCells&) override {}

	/** A moving thing covers `cell`, its current covering began (at the
	 * first scan of the current run of listings) at most `window` before
	 * the scan, and not at scan 0 (a thing there from the start was never
	 * seen free). */
	bool appeared(int cell) const override
	{
		return m_lastCovered[cell] == m_scan && m_onsetScan[cell] > 0 &&
			m_time - m_onset[cell] <= m_window;
	}
	/** Something left `cell` at most `window` before the latest scan (and
	 * did not cover it again since). */
	bool disappeared(int cell) const override
	{
		return m_leftAt[cell] >= 0 && m_time - m_leftAt[cell] <= m_window;
	}

   private:
	/** The window plus a margin for the times' rounding to 0.01 s. */
	double m_window;
	long m_scan = -1;
	double m_time = 0;
	/** Per cell: the latest scan listing it occupied (-1: none), the scan and
	 * time its current run of listings began, and when it was last left
	 * (-1: not left since last covered). */
	std::vector<long> m_lastCovered, m_onsetScan;
	std::vector<double> m_onset, m_leftAt;
};

}  // namespace evgrid
