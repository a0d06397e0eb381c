/* evgrid score-motion: the truth dated by the physical events. */

#include "CPhysicalTruth.h"

namespace evgrid
{
CPhysicalTruth::CPhysicalTruth(const TTruthGrid& grid, double window)
	: m_window(window + 1e-6),
	  m_lastCovered(grid.cellCount(), -1),
	  m_onsetScan(grid.cellCount(), -1),
	  m_onset(grid.cellCount(), 0.0),
	  m_leftAt(grid.cellCount(), -1.0)
{
}

void CPhysicalTruth::apply(std::size_t k, const TTruthScan& scan)
{
	const long previous = m_scan;
	m_scan = static_cast<long>(k);
	m_time = scan.time;
	for (const int cell : scan.occupied)
	{
		if (m_lastCovered[cell] != previous || previous < 0)
		{
			m_onsetScan[cell] = m_scan;
			m_onset[cell] = m_time;
		}
		m_lastCovered[cell] = m_scan;
		m_leftAt[cell] = -1.0;
	}
	// The writer lists a cell left only when it is free at the scan.
	for (const auto& [cell, time] : scan.left)
		m_leftAt[cell] = time;
}

}  // namespace evgrid
