/* evgrid score-motion: the truth dated by the scans that observed it. */

#include "CObservedTruth.h"

#include "CObservedCells.h"

namespace evgrid
{
CObservedTruth::CObservedTruth(const TTruthGrid& grid, double window)
	: m_window(window + 1e-6),
	  m_lastCovered(grid.cellCount(), -1),
	  m_flags(grid.cellCount(), 0),
	  m_appearedAt(grid.cellCount(), -1.0),
	  m_goneAt(grid.cellCount(), -1.0)
{
}

void CObservedTruth::apply(std::size_t k, const TTruthScan& scan)
{
	const long previous = m_scan;
	m_scan = static_cast<long>(k);
	m_time = scan.time;
	for (const int cell : scan.occupied)
	{
		if (m_lastCovered[cell] != previous || previous < 0)
		{
			// A new run: the map has seen nothing of it yet.
			m_flags[cell] &= static_cast<std::uint8_t>(~(kRunHit | kEnded));
			m_appearedAt[cell] = -1.0;
			m_goneAt[cell] = -1.0;
		}
		m_lastCovered[cell] = m_scan;
	}
	// Runs that ended at this scan (the thing left after the previous one):
	// sightings of the cell free from before them say nothing of the next
	// run, and their end can be seen only if a scan hit them. A thing that
	// sweeps a cell between two scans is invisible to the scans: the `left`
	// items are not needed.
	for (const int cell : m_previous)
		if (!covered(cell))
		{
			std::uint8_t& f = m_flags[cell];
			f = static_cast<std::uint8_t>(f & ~(kSeenFree | kEnded));
			if (f & kRunHit) f |= kEnded;
			m_goneAt[cell] = -1.0;
		}
	m_previous = scan.occupied;
}

void CObservedTruth::observe(const CObservedCells& seen)
{
	for (const int cell : seen.hit())
	{
		std::uint8_t& f = m_flags[cell];
		if (!covered(cell) || (f & kRunHit)) continue;
		f |= kRunHit;
		if (f & kSeenFree) m_appearedAt[cell] = m_time;
	}
	// A beam may cross a covered cell where the thing leaves it free (a
	// thing covers every cell it shares some area with): that is no sight
	// of the cell free.
	for (const int cell : seen.crossed())
	{
		if (covered(cell)) continue;
		std::uint8_t& f = m_flags[cell];
		f |= kSeenFree;
		if ((f & kEnded) && m_goneAt[cell] < 0) m_goneAt[cell] = m_time;
	}
}

}  // namespace evgrid
