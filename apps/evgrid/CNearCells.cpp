/* evgrid score-motion: is a cell of a set within a distance of a cell? */

#include "CNearCells.h"

#include <algorithm>

namespace evgrid
{
CNearCells::CNearCells(const TTruthGrid& grid)
	: m_grid(grid),
	  m_sums(
		  static_cast<std::size_t>(grid.sizeX + 1) *
		  static_cast<std::size_t>(grid.sizeY + 1))
{
}

void CNearCells::assign(const std::vector<int>& cells)
{
	m_empty = cells.empty();
	if (m_empty) return;
	const std::size_t w = static_cast<std::size_t>(m_grid.sizeX) + 1;
	std::fill(m_sums.begin(), m_sums.end(), 0);
	for (const int cell : cells)
		m_sums[static_cast<std::size_t>(cell % m_grid.sizeX + 1) +
			   w * static_cast<std::size_t>(cell / m_grid.sizeX + 1)] = 1;
	for (std::size_t y = 1; y < m_sums.size() / w; ++y)
		for (std::size_t x = 1; x < w; ++x)
			m_sums[x + w * y] += m_sums[x - 1 + w * y] +
				m_sums[x + w * (y - 1)] - m_sums[x - 1 + w * (y - 1)];
}

bool CNearCells::anyWithin(int cell, int distance) const
{
	if (m_empty) return false;
	const int cx = cell % m_grid.sizeX, cy = cell / m_grid.sizeX;
	// Clamped in 64 bits: cx + distance may not fit an int.
	const auto clamp = [](long v, int size) {
		return static_cast<int>(std::clamp<long>(v, 0, size));
	};
	const int x0 = clamp(long(cx) - distance, m_grid.sizeX),
			  x1 = clamp(long(cx) + distance + 1, m_grid.sizeX),
			  y0 = clamp(long(cy) - distance, m_grid.sizeY),
			  y1 = clamp(long(cy) + distance + 1, m_grid.sizeY);
	return below(x1, y1) - below(x0, y1) - below(x1, y0) + below(x0, y0) > 0;
}

}  // namespace evgrid
