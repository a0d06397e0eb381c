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
				m_cells.push_back({idx, occupied, false});
		}
	}
	std::sort(m_cells.begin(), m_cells.end(), [](const auto& a, const auto& b) {
		return a.index < b.index || (a.index == b.index && a.occupied > b.occupied);
	});
	m_cells.erase(
		std::unique(
			m_cells.begin(), m_cells.end(),
			[](const auto& a, const auto& b) { return a.index == b.index; }),
		m_cells.end());
}

}  // namespace mrpt_evidential
