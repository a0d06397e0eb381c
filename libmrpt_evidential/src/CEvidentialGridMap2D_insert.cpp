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
/** Stores conflict, free and occupied masses given in stored units,
 * rounded to nearest without branches (so that loops of it vectorize). The
 * values are fused masses: each within [0, kMassScale] and all three summing
 * to at most kMassScale, up to rounding errors far below half a step. The
 * clamps absorb those errors, so the stored values never exceed the scale
 * together. */
template <typename Real>
inline void storeRounded(QuantizedCell& c, Real conflict, Real free, Real occupied)
{
	constexpr int kScale = static_cast<int>(kMassScale);
	const int e = static_cast<int>(conflict + Real(0.5));
	const int o = std::min(static_cast<int>(occupied + Real(0.5)), kScale - e);
	const int f = std::min(static_cast<int>(free + Real(0.5)), kScale - e - o);
	c.conflict = static_cast<std::uint16_t>(e);
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** The default path, taken by the cells a scan informs: the cell decayed and
 * fused conjunctively with `observed` straight on its stored values (the
 * result of read, conjunctive and write, without their generality). */
inline void fuseConjunctive(
	EvidentialGridStorage& grid, std::size_t idx, const Mass& observed)
{
	QuantizedCell& c = grid.rawCell(idx);
	const double d = grid.decayFactor(c.stamp);
	const double e = c.conflict * d, f = c.free * d, o = c.occupied * d;
	const double u = kMassScale - e - f - o;
	const double of = observed.free, oo = observed.occupied, ou = observed.unknown;
	storeRounded(
		c, e + observed.conflict * (kMassScale - e) + f * oo + o * of,
		f * (of + ou) + u * of, o * (oo + ou) + u * oo);
	c.stamp = grid.currentStamp();
}

/** fuseConjunctive() with a simple free mass `w`, the mass of the bulk of a
 * scan's cells, in single precision (the compiler runs it on four cells at
 * once): a float holds a stored value to 1/256 of a step. */
inline void fuseFreeSinglePrecision(
	EvidentialGridStorage& grid, std::size_t idx, float w)
{
	QuantizedCell& c = grid.rawCell(idx);
	const auto d = static_cast<float>(grid.decayFactor(c.stamp));
	const float e = c.conflict * d, f = c.free * d, o = c.occupied * d;
	const float u = static_cast<float>(kMassScale) - e - f - o;
	storeRounded(c, e + o * w, f + u * w, o - o * w);
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
			[&, w = static_cast<float>(uniform.free)](std::size_t idx) {
				fuseFreeSinglePrecision(m_grid, idx, w);
			});
	else
		m_transform.forEachInformedCell(
			geometry(), fuse, [&](std::size_t idx) { fuse(idx, uniform); });
	return true;
}
