/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: inserting scans (polar SourceGrid, bilinear transform
 * to the cells, decay, fusion). */

#include <mrpt/core/Clock.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include "insert/PolarToCartesian.h"
#include "insert/ScanImpacts.h"
#include "map/MapWorkspace.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <type_traits>

using namespace mrpt_evidential;

bool CEvidentialGridMap2D::internal_insertObservation(
	const mrpt::obs::CObservation& obs,
	const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	const mrpt::poses::CPose3D pose = robotPose ? *robotPose : mrpt::poses::CPose3D();
	if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs))
		return insertScan(*scan, pose);
	// Clouds; other observation types are not for this map: not an error.
	return insertCloud(obs, pose);
}

void CEvidentialGridMap2D::requireFinitePose(
	const mrpt::poses::CPose3D& sensorPose, const char* what)
{
	for (const double v : {sensorPose.x(), sensorPose.y(), sensorPose.z(), sensorPose.yaw(),
						   sensorPose.pitch(), sensorPose.roll()})
		if (!std::isfinite(v))
			throw std::invalid_argument(
				std::string("CEvidentialGridMap2D: the ") + what + "'s pose is not finite: " +
				sensorPose.asString());
}

bool CEvidentialGridMap2D::insertScan(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const mrpt::poses::CPose3D& robotPose)
{
	// The map's own rules; the polar grid checks the rest when it builds.
	if (const auto bad = insertionOptions.firstInvalidOfTheMap())
		throw std::invalid_argument(bad->describe());
	const mrpt::poses::CPose3D sensorPose3D = robotPose + scan.sensorPose;
	requireFinitePose(sensorPose3D, "scan");
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

	m_workspace->sourceGrid.build(scan, insertionOptions.sourceGridOptions(getResolution()));
	fusePolarGrid(*sensor, scan.timestamp);
	return true;
}

void CEvidentialGridMap2D::fusePolarGrid(
	const PlanarSensorPose& sensor, mrpt::Clock::time_point stamp)
{
	const CPolarSourceGrid& polar = m_workspace->sourceGrid;
	CPolarToCartesian& transform = m_workspace->transform;
	m_grid.setDecayRate(insertionOptions.decayRate);
	m_grid.setKeepsConflict(
		insertionOptions.conflictHandling == ConflictHandling::Keep);
	m_grid.setEventRetention(insertionOptions.motionWindow);
	m_grid.beginInsertion(mrpt::Clock::toDouble(stamp));
	invalidateLikelihoodCache();

	transform.setup(polar, sensor);
	const Box& box = transform.box();
	if (box.empty()) return;
	const bool whole = m_grid.growToInclude(
		box.xMin, box.xMax, box.yMin, box.yMax, insertionOptions.growthMargin, m_maxCells);
	if (!whole && ++m_partlyInserted == 1)
	{
		std::cerr << "[CEvidentialGridMap2D] warning: the grid cannot grow to "
					 "hold a scan at ("
				  << sensor.x << ", " << sensor.y << ") within its budget of "
				  << m_maxCells
				  << " cells (creationOpts maxCells) and 1e9 m of the origin; "
					 "such scans are inserted only where they overlap the grid. "
					 "Shown once.\n";
	}

	CScanImpacts& impacts = m_workspace->impacts;
	impacts.build(polar, transform, sensor, geometry());
	if (m_grid.keepsConflict())
		fuseKeepingConflict(impacts);
	else
		fuseWithMotion(impacts);
}

void CEvidentialGridMap2D::fuseKeepingConflict(CScanImpacts& impacts)
{
	const CPolarToCartesian& transform = m_workspace->transform;
	const FusionRule rule = insertionOptions.fusionRule;
	const ConflictHandling handling = insertionOptions.conflictHandling;
	const Mass& uniform = transform.uniformMass();
	const bool conjunctive =
		rule == FusionRule::Conjunctive && handling == ConflictHandling::Keep;
	const auto single = [&](std::size_t idx, const Mass& observed) {
		if (conjunctive)
			m_grid.fuseConjunctive(idx, observed);
		else
			m_grid.fuse(idx, observed, rule, handling);
	};
	// Each band of rows on its own thread, with its own impact cursor.
	impacts.clearVisits();
	const GridGeometry& g = geometry();
	const auto fuseBand = [&](auto decays, const TWorkspace::TFusionBand& band) {
		auto hits = impacts.cursorFrom(g.index(0, band.firstRow));
		const auto run = [&](std::size_t from, std::size_t n) {
			if (conjunctive)
				m_grid.fuseFreeRunKeepingConflict<decltype(decays)::value>(
					from, n, static_cast<float>(uniform.free));
			else
				for (std::size_t idx = from; idx < from + n; ++idx) single(idx, uniform);
		};
		visitRowsCloned(
			transform, g, band.firstRow, band.lastRow,
			[&](std::size_t idx, const Mass& observed) {
				const double hit = hits.occupiedAt(idx);
				if (hit > 0.0) m_grid.markImpact(idx);
				single(idx, hit > 0.0 ? withImpact(observed, hit) : observed);
			},
			[&](std::size_t first, std::size_t count) {
				hits.splitRun(first, count, run, [&](std::size_t idx, double occupied) {
					m_grid.markImpact(idx);
					single(idx, withImpact(uniform, occupied));
				});
			},
			[&](std::size_t first, std::size_t count) { m_grid.prefetchForWrite(first, count); });
	};
	m_workspace->fuseInBands(
		g, insertionOptions.insertionThreads, m_grid.decayRate() > 0.0, fuseBand);
	// The impact cells the visit did not reach: a cloud's farther impacts.
	impacts.forEachUnvisited([&](std::size_t idx, double occupied) {
		m_grid.markImpact(idx);
		single(idx, withImpact(Mass::vacuous(), occupied));
	});
}
