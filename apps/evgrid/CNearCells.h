/* evgrid score-motion: is a cell of a set within a distance of a cell? */
#pragma once

#include <vector>

#include "CMotionTruth.h"

namespace evgrid
{
/** A set of cells of the truth's grid, asked whether one of them lies within
 * a Chebyshev distance of a cell. A summed-area table answers in constant
 * time whatever the distance, so that a large --tolerance costs no more. */
class CNearCells
{
   public:
	explicit CNearCells(const TTruthGrid& grid);

	/** Replaces the set. */
	void assign(const std::vector<int>& cells);
	/** True when a cell of the set lies within `distance` cells of `cell`
	 * along both axes. */
	bool anyWithin(int cell, int distance) const;

   private:
	/** Cells of the set in [0, cx) x [0, cy), at cx + (sizeX + 1) cy. */
	int below(int cx, int cy) const
	{
		return m_sums[static_cast<std::size_t>(cx) +
			static_cast<std::size_t>(m_grid.sizeX + 1) *
				static_cast<std::size_t>(cy)];
	}

	const TTruthGrid& m_grid;
	std::vector<int> m_sums;
	bool m_empty = true;
};

}  // namespace evgrid
