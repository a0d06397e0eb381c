/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "insert/ScanImpacts.h"

#include <algorithm>
#include <cmath>

namespace mrpt_evidential
{
void CScanImpacts::build(
	const CPolarSourceGrid& polar, const CPolarToCartesian& transform,
	const PlanarSensorPose& sensor, const GridGeometry& grid)
{
	m_cells.clear();
	m_rowOf.clear();
	if (transform.box().empty()) return;
	const double reach = static_cast<double>(polar.binCount()) * polar.binSize();
	for (std::size_t s = 0; s < polar.sectorCount(); ++s)
	{
		const std::vector<double>& ranges = polar.impacts(s);
		if (ranges.empty() || !(ranges.front() < reach)) continue;
		const auto [c, sn] = transform.sectorDirection(s);
		for (const double r : ranges)
		{
			if (!(r < reach)) break;  // sorted: the rest lie beyond too
			const double occupied = polar.massAt(s, polar.binOfRange(r)).occupied;
			if (!(occupied > 0.0)) continue;
			const double x = sensor.x + r * c, y = sensor.y + r * sn;
			const double fx = std::floor((x - grid.xMin) / grid.resolution);
			const double fy = std::floor((y - grid.yMin) / grid.resolution);
			if (!(fx >= 0 && fy >= 0 && fx < grid.sizeX && fy < grid.sizeY)) continue;
			const std::size_t idx = grid.index(static_cast<int>(fx), static_cast<int>(fy));
			// A sector's impacts in one cell (a cloud's layers on one wall)
			// are one entry: the sort below has that much less to do.
			if (!m_cells.empty() && m_cells.back().index == idx)
				m_cells.back().occupied = std::max(m_cells.back().occupied, occupied);
			else
			{
				m_cells.push_back({idx, occupied, false});
				m_rowOf.push_back(static_cast<int>(fy));
			}
		}
	}
	sortByIndex();
	// Of a cell's entries, the first holds the largest occupied mass.
	m_cells.erase(
		std::unique(
			m_cells.begin(), m_cells.end(),
			[](const auto& a, const auto& b) { return a.index == b.index; }),
		m_cells.end());
}

void CScanImpacts::sortByIndex()
{
	const auto before = [](const TImpactCell& a, const TImpactCell& b) {
		return a.index < b.index || (a.index == b.index && a.occupied > b.occupied);
	};
	if (m_cells.size() < 2) return;
	// Bucketed by row (a linear pass: a cloud lists thousands of cells over
	// a few hundred rows), then each row's few cells sorted.
	const auto [low, high] = std::minmax_element(m_rowOf.begin(), m_rowOf.end());
	const int lowRow = *low;
	m_rowStart.assign(static_cast<std::size_t>(*high - lowRow) + 2, 0);
	for (const int row : m_rowOf) ++m_rowStart[static_cast<std::size_t>(row - lowRow) + 1];
	for (std::size_t k = 1; k < m_rowStart.size(); ++k) m_rowStart[k] += m_rowStart[k - 1];
	m_sorted.resize(m_cells.size());
	for (std::size_t i = 0; i < m_cells.size(); ++i)
		m_sorted[m_rowStart[static_cast<std::size_t>(m_rowOf[i] - lowRow)]++] = m_cells[i];
	// Each row's end is now where the next row began.
	for (std::size_t from = 0, k = 0; k + 1 < m_rowStart.size(); ++k)
	{
		const std::size_t to = m_rowStart[k];
		std::sort(m_sorted.begin() + static_cast<std::ptrdiff_t>(from),
				  m_sorted.begin() + static_cast<std::ptrdiff_t>(to), before);
		from = to;
	}
	m_cells.swap(m_sorted);
}

}  // namespace mrpt_evidential
