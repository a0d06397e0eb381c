/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: inserting scans (polar SourceGrid, bilinear transform
 * to the cells, decay, fusion). */

#include <mrpt/core/Clock.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/PolarToCartesian.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace mrpt_evidential;

namespace
{
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
/** The default path, taken by nearly every cell: the cell decayed and fused
 * conjunctively with `observed` straight on its stored values (the result of
 * read, conjunctive and write, without their generality). */
inline void fuseConjunctive(
	EvidentialGridStorage& grid, std::size_t idx, const Mass& observed)
{
	QuantizedCell& c = grid.rawCell(idx);
	const double d = grid.decayFactor(c.stamp) / kMassScale;
	const double e = c.conflict * d, f = c.free * d, o = c.occupied * d;
	const double u = 1.0 - e - f - o;
	const double of = observed.free, oo = observed.occupied, ou = observed.unknown;
	encodeMass(
		{e + observed.conflict * (1.0 - e) + f * oo + o * of,
		 f * (of + ou) + u * of, o * (oo + ou) + u * oo, u * ou},
		c);
	c.stamp = grid.currentStamp();
}

/** fuseConjunctive() with a simple free mass, the mass of the bulk of a
 * scan's cells, in integer arithmetic: `w16` is m(F) in 1/65536, and each
 * decayed or fused value is rounded to nearest (at most one step from the
 * double-precision kernel). Every product stays below 2^32, and rounding
 * never lets a value exceed what it is taken from, so the masses keep summing
 * to at most the scale without a check. */
inline void fuseFreeFixedPoint(
	EvidentialGridStorage& grid, std::size_t idx, std::uint32_t w16)
{
	QuantizedCell& c = grid.rawCell(idx);
	const auto d = static_cast<std::uint32_t>(grid.decayFactor(c.stamp) * 65536.0 + 0.5);
	const std::uint32_t e = (c.conflict * d + 32768) >> 16,
						f = (c.free * d + 32768) >> 16,
						o = (c.occupied * d + 32768) >> 16;
	const std::uint32_t u = static_cast<std::uint32_t>(kMassScale) - e - f - o;
	const std::uint32_t t = (o * w16 + 32768) >> 16;
	c.conflict = static_cast<std::uint16_t>(e + t);
	c.free = static_cast<std::uint16_t>(f + ((u * w16 + 32768) >> 16));
	c.occupied = static_cast<std::uint16_t>(o - t);
	c.stamp = grid.currentStamp();
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

	m_transform.setup(m_sourceGrid, *sensor);
	const Box& box = m_transform.box();
	if (box.empty()) return true;
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
				  << " cells (creationOpts maxCells) and 1e9 m of the origin; "
					 "such scans are inserted only where they overlap the grid. "
					 "Shown once.\n";
	}

	const FusionRule rule = insertionOptions.fusionRule;
	const ConflictHandling handling = insertionOptions.conflictHandling;
	const auto fuse = [&](std::size_t idx, const Mass& observed) {
		m_grid.write(
			idx,
			applyConflictHandling(
				combine(rule, m_grid.read(idx), observed), handling));
	};
	const Mass& uniform = m_transform.uniformMass();
	if (rule == FusionRule::Conjunctive && handling == ConflictHandling::Keep)
		m_transform.forEachInformedCell(
			geometry(),
			[&](std::size_t idx, const Mass& observed) {
				fuseConjunctive(m_grid, idx, observed);
			},
			[&, w16 = static_cast<std::uint32_t>(uniform.free * 65536.0 + 0.5)](
				std::size_t idx) { fuseFreeFixedPoint(m_grid, idx, w16); });
	else
		m_transform.forEachInformedCell(
			geometry(), fuse, [&](std::size_t idx) { fuse(idx, uniform); });
	return true;
}
