/* evgrid score-motion: the cells of the truth's grid that a scan observed. */

#include "CObservedCells.h"

#include <cmath>

namespace evgrid
{
CObservedCells::CObservedCells(const TTruthGrid& grid)
	: m_grid(grid), m_flags(grid.cellCount(), 0)
{
}

void CObservedCells::mark(int cell, std::uint8_t flag)
{
	if (cell < 0 || (m_flags[cell] & flag)) return;
	if (!m_flags[cell]) m_observed.push_back(cell);
	m_flags[cell] |= flag;
	(flag == kHit ? m_hit : m_crossed).push_back(cell);
}

void CObservedCells::trace(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const mrpt::poses::CPose3D& robotPose, double maxRange)
{
	for (const int cell : m_observed)
		m_flags[cell] = 0;
	m_hit.clear();
	m_crossed.clear();
	m_observed.clear();

	const mrpt::poses::CPose3D sensor = robotPose + scan.sensorPose;
	const double x = sensor.x(), y = sensor.y();
	const double step = m_grid.resolution / 4;
	for (std::size_t i = 0; i < scan.getScanSize(); ++i)
	{
		if (!scan.getScanRangeValidity(i)) continue;
		const double range = scan.getScanRange(i);
		if (!std::isfinite(range) || !(range > 0)) continue;
		const double angle = sensor.yaw() + scan.getScanAngle(i);
		const double dx = std::cos(angle), dy = std::sin(angle);
		const bool ends = range < maxRange;
		const double length = ends ? range : maxRange;
		const int end = ends
			? m_grid.cellAt(x + range * dx, y + range * dy)
			: -1;
		// Counting the steps keeps the samples exact multiples of `step`.
		const auto steps = static_cast<long>(std::ceil(length / step));
		for (long s = 0; s < steps; ++s)
		{
			const double d = static_cast<double>(s) * step;
			if (d >= length) break;
			const int cell = m_grid.cellAt(x + d * dx, y + d * dy);
			if (cell != end) mark(cell, kCrossed);
		}
		if (ends) mark(end, kHit);
	}
}

}  // namespace evgrid
