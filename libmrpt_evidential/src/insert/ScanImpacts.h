/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The grid cells that hold a scan's impacts. */
#pragma once

#include <mrpt_evidential/grid/GridGeometry.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "insert/PolarToCartesian.h"

namespace mrpt_evidential
{
/** The cells of a grid that hold at least one impact of a scan, each with
 * the largest occupied mass its impacts' bins carry.
 *
 * The bilinear mix samples the polar grid at cell centres only. Where
 * sectors are narrower than cells (near the sensor), a cell that a beam ends
 * in may sit between two other beams that reach past it, and would read
 * free; where the wall is oblique, the cell at its surface mixes a free bin
 * with an occupied one. The cells listed here read the impact's occupied
 * evidence instead, whatever the mix (as COccupancyGridMap2D marks the cell
 * a beam ends in). An impact lies along its sector's centre line, where the
 * polar grid puts it. */
class CScanImpacts
{
   public:
	struct TImpactCell
	{
		std::size_t index;
		double occupied;
		/** The transform's visit reached the cell (CCursor found it). */
		bool visited = false;
	};

	/** Lists the impact cells of `polar` as `transform` (set up for it)
	 * places it in `grid`, sorted by index. Impacts outside the grid are left
	 * out. */
	void build(
		const CPolarSourceGrid& polar, const CPolarToCartesian& transform,
		const PlanarSensorPose& sensor, const GridGeometry& grid);

	const std::vector<TImpactCell>& cells() const { return m_cells; }

	/** Walks the list along increasing cell indices, as the transform visits
	 * cells: each call's index must be >= the previous one's. The cells it
	 * finds are marked visited. */
	class CCursor
	{
	   public:
		CCursor(
			std::vector<TImpactCell>::iterator from, std::vector<TImpactCell>::iterator end)
			: m_it(from), m_end(end)
		{
		}
		/** The occupied mass of the impacts in cell idx, 0 if it holds none. */
		double occupiedAt(std::size_t idx)
		{
			while (m_it != m_end && m_it->index < idx) ++m_it;
			if (m_it == m_end || m_it->index != idx) return 0.0;
			m_it->visited = true;
			return m_it->occupied;
		}
		/** The index of the first impact cell at or after idx, or SIZE_MAX. */
		std::size_t nextFrom(std::size_t idx)
		{
			while (m_it != m_end && m_it->index < idx) ++m_it;
			return m_it != m_end ? m_it->index : static_cast<std::size_t>(-1);
		}

		/** Cuts the run of cells [first, first + count) around the impact
		 * cells it holds (near the sensor a beam may end inside the region its
		 * neighbours prove free): run(from, n) for each piece without one,
		 * impact(idx, occupied) for each impact cell, in order. */
		template <typename Run, typename Impact>
		void splitRun(std::size_t first, std::size_t count, Run&& run, Impact&& impact)
		{
			const std::size_t end = first + count;
			while (first < end)
			{
				const std::size_t hit = std::min(nextFrom(first), end);
				if (hit > first) run(first, hit - first);
				if (hit == end) break;
				impact(hit, occupiedAt(hit));
				first = hit + 1;
			}
		}

	   private:
		std::vector<TImpactCell>::iterator m_it, m_end;
	};
	/** Clears the visited marks of an earlier walk. */
	void clearVisits()
	{
		for (TImpactCell& c : m_cells) c.visited = false;
	}
	/** A cursor from the first impact cell at or after `index`, the visited
	 * marks kept: one for each band of rows that threads walk at once. */
	CCursor cursorFrom(std::size_t index)
	{
		const auto from = std::lower_bound(
			m_cells.begin(), m_cells.end(), index,
			[](const TImpactCell& c, std::size_t i) { return c.index < i; });
		return CCursor(from, m_cells.end());
	}
	/** fn(index, occupied) for each impact cell the walk did not visit: a
	 * cloud's farther impacts, beyond the transform's reach. */
	template <typename Fn>
	void forEachUnvisited(Fn&& fn) const
	{
		for (const TImpactCell& c : m_cells)
			if (!c.visited) fn(c.index, c.occupied);
	}

   private:
	/** Sorts m_cells by index, a cell's largest occupied mass first (by
	 * m_rowOf, then within each row). */
	void sortByIndex();

	std::vector<TImpactCell> m_cells;
	/** The grid row of each entry of m_cells, as build() lists them: known
	 * there, where an index would need a division to give it back. */
	std::vector<int> m_rowOf;
	/** sortByIndex()'s buffers, kept between scans. */
	std::vector<TImpactCell> m_sorted;
	std::vector<std::size_t> m_rowStart;
	/** build()'s buffer: the bin, column and row of each sector's nearest
	 * impact (three blocks of one value a sector). */
	std::vector<double> m_nearestPlaces;
};

/** The observed mass of a cell that holds impacts: the mix with its free
 * evidence taken away and its occupied evidence raised to the impacts'. */
inline Mass withImpact(Mass observed, double impactOccupied)
{
	const double occupied = std::max(observed.occupied, impactOccupied);
	return {observed.conflict, 0.0, occupied, 1.0 - observed.conflict - occupied};
}

}  // namespace mrpt_evidential
