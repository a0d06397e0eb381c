/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: inserting scans (polar SourceGrid, bilinear transform
 * to the cells, decay, fusion). */

#include <mrpt/core/Clock.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace mrpt_evidential;

namespace
{
/** Where a scan's sensor lies in the map's plane. */
struct PlanarSensorPose
{
	double x, y, yaw;
	/** True for a sensor mounted upside down: its angles turn clockwise in
	 * the map. */
	bool mirrored;
};

/** The sensor pose in the plane, or nothing when the sensor's x and y axes
 * tilt more than `tolerance` out of the horizontal plane. */
std::optional<PlanarSensorPose> planarSensorPose(
	const mrpt::poses::CPose3D& sensor, double tolerance)
{
	const auto& R = sensor.getRotationMatrix();
	const double maxTilt = std::sin(tolerance) + 1e-9;
	if (std::abs(R(2, 0)) > maxTilt || std::abs(R(2, 1)) > maxTilt)
		return std::nullopt;
	return PlanarSensorPose{
		sensor.x(), sensor.y(), std::atan2(R(1, 0), R(0, 0)),
		R(0, 0) * R(1, 1) - R(0, 1) * R(1, 0) < 0.0};
}

/** Axis-aligned box that grows to hold points. */
struct Box
{
	double xMin = HUGE_VAL, xMax = -HUGE_VAL, yMin = HUGE_VAL, yMax = -HUGE_VAL;
	void add(double x, double y)
	{
		xMin = std::min(xMin, x), xMax = std::max(xMax, x);
		yMin = std::min(yMin, y), yMax = std::max(yMax, y);
	}
	/** Adds the arc of radius r around (cx, cy) between angles a0 < a1: its
	 * ends, and the points where it crosses an axis direction. */
	void addArc(double cx, double cy, double r, double a0, double a1)
	{
		add(cx + r * std::cos(a0), cy + r * std::sin(a0));
		add(cx + r * std::cos(a1), cy + r * std::sin(a1));
		for (int k = static_cast<int>(std::ceil(a0 / (M_PI / 2)));
			 k * (M_PI / 2) <= a1; ++k)
			add(cx + r * std::cos(k * M_PI / 2), cy + r * std::sin(k * M_PI / 2));
	}
};

/** Interpolation coordinate along one axis of the polar grid: the two
 * neighbours and the weight of the second. Outside the first and last centres
 * the nearest one is used alone. */
struct Neighbours
{
	std::size_t lo, hi;
	double wHi;
};

Neighbours neighbours(double position, std::size_t count, bool wraps)
{
	const double f = std::floor(position);
	const double w = position - f;
	if (f < 0.0)
		return wraps ? Neighbours{count - 1, 0, w} : Neighbours{0, 0, 0.0};
	const auto lo = static_cast<std::size_t>(f);
	if (lo + 1 >= count)
		return wraps && lo + 1 == count ? Neighbours{lo, 0, w}
										: Neighbours{count - 1, count - 1, 0.0};
	return {lo, lo + 1, w};
}

void accumulate(Mass& sum, const Mass& m, double w)
{
	sum.conflict += w * m.conflict;
	sum.free += w * m.free;
	sum.occupied += w * m.occupied;
	sum.unknown += w * m.unknown;
}

Mass applyConflictHandling(Mass m, ConflictHandling handling)
{
	switch (handling)
	{
		case ConflictHandling::Keep: break;
		case ConflictHandling::ToUnknown:
			m.unknown += m.conflict;
			m.conflict = 0.0;
			break;
		case ConflictHandling::Normalize:
		{
			const double k = m.free + m.occupied + m.unknown;
			if (k <= kTotalConflictTolerance) return Mass::vacuous();
			m = {0.0, m.free / k, m.occupied / k, m.unknown / k};
			break;
		}
	}
	return m;
}
}  // namespace

bool CEvidentialGridMap2D::internal_insertObservation(
	const mrpt::obs::CObservation& obs,
	const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	// Other observation types are not for this map: not an error.
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan) return false;
	return insertScan(*scan, robotPose ? *robotPose : mrpt::poses::CPose3D());
}

bool CEvidentialGridMap2D::insertScan(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const mrpt::poses::CPose3D& robotPose)
{
	insertionOptions.validate();
	const mrpt::poses::CPose3D sensorPose3D = robotPose + scan.sensorPose;
	for (const double v : {sensorPose3D.x(), sensorPose3D.y(), sensorPose3D.z(),
						   sensorPose3D.yaw(), sensorPose3D.pitch(), sensorPose3D.roll()})
		if (!std::isfinite(v))
			throw std::invalid_argument(
				"CEvidentialGridMap2D: the scan's pose is not finite: " +
				sensorPose3D.asString());
	const auto sensor =
		planarSensorPose(sensorPose3D, insertionOptions.horizontalTolerance);
	if (!sensor)
	{
		if (!m_tiltNoticeShown)
			std::cerr << "[CEvidentialGridMap2D] note: scans whose sensor tilts "
						 "beyond horizontalTolerance are ignored (shown once)\n";
		m_tiltNoticeShown = true;
		return false;
	}

	const GridGeometry& g0 = geometry();
	m_sourceGrid.build(scan, insertionOptions.sourceGridOptions(g0.resolution));
	m_grid.setDecayRate(insertionOptions.decayRate);
	m_grid.beginInsertion(mrpt::Clock::toDouble(scan.timestamp));
	invalidateLikelihoodCache();

	const CPolarSourceGrid& polar = m_sourceGrid;
	const std::size_t nSectors = polar.sectorCount();
	if (nSectors == 0 || polar.maxInformedBins() == 0) return true;

	// Angles measured in the sensor's frame, from the start of sector 0's
	// span; a full turn wraps from the last sector to the first.
	const double spacing = polar.sectorSpacing();
	const double spanStart = polar.firstSectorAngle() - 0.5 * spacing;
	const double span = static_cast<double>(nSectors) * spacing;
	const bool fullTurn = span >= 2 * M_PI - 1e-6;
	const double binSize = polar.binSize();
	// Interpolation reaches half a bin past the last informed bin's centre.
	const auto reachOf = [binSize](std::size_t informedBins) {
		return (static_cast<double>(informedBins) + 0.5) * binSize;
	};
	const double reach = reachOf(polar.maxInformedBins());

	// The cells the scan can inform: the bounding box of its sectors' arcs.
	Box box;
	box.add(sensor->x, sensor->y);
	const double dir = sensor->mirrored ? -1.0 : 1.0;
	for (std::size_t s = 0; s < nSectors; ++s)
	{
		if (polar.informedBins(s) == 0) continue;
		const double r = reachOf(polar.informedBins(s));
		const double a = sensor->yaw + dir * polar.sectorAngle(s);
		box.addArc(sensor->x, sensor->y, r, a - 0.5 * spacing, a + 0.5 * spacing);
	}
	if (!m_grid.growToInclude(
			box.xMin, box.xMax, box.yMin, box.yMax, insertionOptions.growthMargin,
			m_maxCells) &&
		!m_budgetWarningShown)
	{
		m_budgetWarningShown = true;
		std::cerr << "[CEvidentialGridMap2D] warning: the grid cannot grow to "
					 "hold a scan at ("
				  << sensor->x << ", " << sensor->y << ") within its budget of "
				  << m_maxCells
				  << " cells (creationOpts maxCells); such scans are inserted "
					 "only where they overlap the grid. Shown once.\n";
	}

	const GridGeometry& g = geometry();
	const int cx0 = std::max(0, g.cellX(box.xMin));
	const int cx1 = std::min(g.sizeX - 1, g.cellX(box.xMax));
	const int cy0 = std::max(0, g.cellY(box.yMin));
	const int cy1 = std::min(g.sizeY - 1, g.cellY(box.yMax));
	const FusionRule rule = insertionOptions.fusionRule;
	const ConflictHandling handling = insertionOptions.conflictHandling;
	const std::size_t nBins = polar.binCount();

	for (int cy = cy0; cy <= cy1; ++cy)
	{
		const double dy = g.cellCenterY(cy) - sensor->y;
		for (int cx = cx0; cx <= cx1; ++cx)
		{
			const double dx = g.cellCenterX(cx) - sensor->x;
			const double r = std::hypot(dx, dy);
			if (r >= reach) continue;
			double angle = dir * (std::atan2(dy, dx) - sensor->yaw) - spanStart;
			angle -= 2 * M_PI * std::floor(angle / (2 * M_PI));  // [0, 2 pi)
			if (angle >= span) continue;  // outside the field of view

			const Neighbours ns = neighbours(angle / spacing - 0.5, nSectors, fullTurn);
			const Neighbours nb = neighbours(r / binSize - 0.5, nBins, false);
			Mass observed{0.0, 0.0, 0.0, 0.0};
			const Mass* rowLo = polar.sectorRow(ns.lo);
			const Mass* rowHi = polar.sectorRow(ns.hi);
			accumulate(observed, rowLo[nb.lo], (1 - ns.wHi) * (1 - nb.wHi));
			accumulate(observed, rowLo[nb.hi], (1 - ns.wHi) * nb.wHi);
			accumulate(observed, rowHi[nb.lo], ns.wHi * (1 - nb.wHi));
			accumulate(observed, rowHi[nb.hi], ns.wHi * nb.wHi);
			// A cell the scan says nothing about is left alone: fusing the
			// vacuous mass would still renormalize it under some rules.
			if (observed.unknown >= 1.0 - 1e-12) continue;
			// A cell touched by an impact's bin holds (part of) what the beam
			// hit, so the beam does not prove it free: its share of free
			// evidence from the bin before the impact becomes ignorance.
			// Without this, walls collect free and occupied evidence from
			// scan to scan and end up as conflict.
			if (rowLo[nb.lo].occupied > 0.0 || rowLo[nb.hi].occupied > 0.0 ||
				rowHi[nb.lo].occupied > 0.0 || rowHi[nb.hi].occupied > 0.0)
			{
				observed.unknown += observed.free;
				observed.free = 0.0;
			}

			const std::size_t idx = g.index(cx, cy);
			m_grid.write(
				idx,
				applyConflictHandling(
					combine(rule, m_grid.read(idx), observed), handling));
		}
	}
	return true;
}
