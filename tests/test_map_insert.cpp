/* Inserting scans into CEvidentialGridMap2D: simulated scans with known
 * answers, and decay at extreme rates and time jumps. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <functional>

#include "support/bad_input.h"
#include "support/map_assertions.h"
#include "support/maps.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;
using test::arcScan;
using test::kDeg;
using test::mapIsValid;
using test::scanByAngle;
using test::smallMap;
using test::wall;

namespace
{
constexpr double kMuF = 0.7, kMuO = 0.9, kRes = 0.05;
/** Stored masses are 16-bit fixed point: two steps of slack. */
constexpr double kStoreTol = 2.0 / kMassScale;

/** Where the MapInsert tests mount the sensor: 0.3 m ahead of the robot,
 * 0.1 m to its left, 0.2 m up, turned 10 degrees. */
const CPose3D kSensorPose(0.3, 0.1, 0.2, 10 * M_PI / 180, 0, 0);
/** How they take scans: 181 beams over 180 degrees, beam i at angle
 * -90 + i degrees, maxRange 30 m, at time 0 s unless a test sets another. */
const test::ScanSetup kSetup = test::ScanSetup().maxRange(30.0).at(0.0).sensorPose(kSensorPose);
constexpr std::size_t kBeams = 181;

CEvidentialGridMap2D makeMap(SensorModel model = SensorModel::MultiEcho)
{
	CEvidentialGridMap2D map(-10, 10, -10, 10, kRes);
	map.insertionOptions.sensorModel = model;
	map.insertionOptions.muF = kMuF;
	map.insertionOptions.muO = kMuO;
	// The seed's geometry: free evidence up to the impacts.
	map.insertionOptions.freeMargin = 0.0;
	return map;
}

const CPose3D kRobot(2.0, -1.0, 0.0, 30 * M_PI / 180, 0, 0);

/** Calls f(mass, range, angle) for every cell of the map, with the cell's
 * centre in polar coordinates of the sensor. */
void forEachCell(
	const CEvidentialGridMap2D& map, const CPose3D& sensor,
	const std::function<void(const Mass&, double, double)>& f)
{
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
		{
			double lx, ly, lz;
			sensor.inverseComposePoint(
				map.geometry().cellCenterX(cx), map.geometry().cellCenterY(cy), 0.0,
				lx, ly, lz);
			f(map.getCellMassesByIndex(cx, cy), std::hypot(lx, ly),
			  std::atan2(ly, lx));
		}
}

/** The cell holding the point at (range, angle) of the sensor. */
Mass massAtPolar(
	const CEvidentialGridMap2D& map, const CPose3D& sensor, double range,
	double angle)
{
	double gx, gy, gz;
	sensor.composePoint(range * std::cos(angle), range * std::sin(angle), 0.0, gx, gy, gz);
	return map.getCellMasses(gx, gy);
}
/** Of the cells a ray of the sensor crosses between ranges r0 - 0.05 and
 * r0 + 0.1, the one with the most occupied evidence: where the bilinear
 * transform puts a wall at r0. */
Mass strongestOccupiedNear(
	const CEvidentialGridMap2D& map, const CPose3D& sensor, double angle, double r0)
{
	Mass strongest;
	for (double r = r0 - 0.05; r <= r0 + 0.1; r += 0.005)
	{
		const Mass m = massAtPolar(map, sensor, r, angle);
		if (m.occupied > strongest.occupied) strongest = m;
	}
	return strongest;
}
}  // namespace

TEST(MapInsert, OneScanAtARotatedTranslatedPose)
{
	CEvidentialGridMap2D map = makeMap();
	const auto scan = arcScan(kBeams, 4.0, kSetup);
	ASSERT_TRUE(map.insertObservation(scan, kRobot));
	EXPECT_FALSE(map.isEmpty());
	const CPose3D sensor = kRobot + scan.sensorPose;

	std::size_t freeCells = 0, behind = 0, outside = 0;
	forEachCell(map, sensor, [&](const Mass& m, double r, double a) {
		ASSERT_TRUE(m.isValid(1e-9)) << m;
		if (r < 3.9 && std::abs(a) < 89 * kDeg)
		{
			// All four polar neighbours are free: exactly muF.
			ASSERT_MASS_NEAR_AT(m, Mass::simpleFree(kMuF), kStoreTol, r, a);
			++freeCells;
		}
		else if (r > 4.1 && std::abs(a) < 89 * kDeg)
		{
			ASSERT_EQ(m, Mass::vacuous()) << "behind the wall at " << r << ", " << a;
			++behind;
		}
		else if (std::abs(a) > 92 * kDeg)
		{
			ASSERT_EQ(m, Mass::vacuous()) << "outside the field of view";
			++outside;
		}
	});
	EXPECT_GT(freeCells, 9000u);  // half a disc of 3.9 m at 5 cm
	EXPECT_GT(behind, 1000u);
	EXPECT_GT(outside, 1000u);

	// Occupied evidence at the impacts. The bilinear transform spreads the
	// impacts' bin [4.0, 4.05) over the cells whose centres lie within a bin
	// of its centre: every ray crosses a cell with clear occupied evidence,
	// though with bins as long as the cells, some rays only cross cells that
	// straddle the wall, where free or unknown evidence weighs as much.
	std::size_t rays = 0, decidedOccupied = 0;
	for (double a = -88 * kDeg; a <= 88 * kDeg; a += 0.5 * kDeg, ++rays)
	{
		const Mass strongest = strongestOccupiedNear(map, sensor, a, 4.0);
		EXPECT_GT(strongest.occupied, 0.35) << "angle " << a / kDeg << " " << strongest;
		if (decide(strongest) == Decision::Occupied) ++decidedOccupied;
	}
	EXPECT_GT(decidedOccupied, rays * 8 / 10);
	// Reading outside the map gives the vacuous mass.
	EXPECT_EQ(map.getCellMasses(100.0, 0.0), Mass::vacuous());
	EXPECT_EQ(map.getCellMassesByIndex(-1, 3), Mass::vacuous());
	EXPECT_EQ(map.getCellBetP(100.0, 0.0), 0.5);
}

TEST(MapInsert, ImpreciseModelDrawsSolidWalls)
{
	// An imprecision of one cell widens the occupied band to three bins:
	// every ray then crosses a cell that decides occupied.
	CEvidentialGridMap2D map = makeMap(SensorModel::ImpreciseMultiEcho);
	map.insertionOptions.imprecision = kRes;
	const auto scan = arcScan(kBeams, 4.0, kSetup);
	map.insertObservation(scan, kRobot);
	const CPose3D sensor = kRobot + scan.sensorPose;
	for (double a = -88 * kDeg; a <= 88 * kDeg; a += 0.5 * kDeg)
	{
		const Mass strongest = strongestOccupiedNear(map, sensor, a, 4.0);
		EXPECT_GT(strongest.occupied, 0.75) << "angle " << a / kDeg << " " << strongest;
		EXPECT_EQ(decide(strongest), Decision::Occupied);
	}
}

TEST(MapInsert, TwoIdenticalScansReinforceConjunctively)
{
	CEvidentialGridMap2D map = makeMap();
	const auto scan = arcScan(kBeams, 4.0, kSetup);
	map.insertObservation(scan, kRobot);
	map.insertObservation(scan, kRobot);
	const CPose3D sensor = kRobot + scan.sensorPose;
	const double twice = 1 - (1 - kMuF) * (1 - kMuF);
	std::size_t checked = 0;
	forEachCell(map, sensor, [&](const Mass& m, double r, double a) {
		ASSERT_TRUE(m.isValid(1e-9));
		if (r < 3.9 && std::abs(a) < 89 * kDeg)
		{
			ASSERT_MASS_NEAR_AT(m, Mass::simpleFree(twice), kStoreTol, r, a);
			++checked;
		}
	});
	EXPECT_GT(checked, 9000u);
	EXPECT_NEAR(map.getCellBetP(sensor.x(), sensor.y()), (1 - twice) / 2, kStoreTol);
	EXPECT_EQ(map.insertionCount(), 2u);
}

TEST(MapInsert, CellsStoreWithinQuantization)
{
	// Cells are fused and stored once per scan: the exact mass after one scan
	// differs from muF by at most the fixed-point step.
	CEvidentialGridMap2D map = makeMap();
	map.insertObservation(arcScan(kBeams, 4.0, kSetup), kRobot);
	const CPose3D sensor = kRobot + kSensorPose;
	EXPECT_NEAR(massAtPolar(map, sensor, 2.0, 0.3).free, kMuF, 1e-5);
}

TEST(MapInsert, BulkCellsTrackDoublePrecisionOverManyScans)
{
	// The bulk of a scan is fused in integer arithmetic. A cell that first
	// holds a wall's occupied evidence, then lies deep in free space for a
	// thousand scans with decay (every tenth scan looking away), stays within
	// 1e-3 of the double-precision algebra, and within two steps after one.
	CEvidentialGridMap2D map = makeMap(SensorModel::ReinforcedMultiEcho);
	map.insertionOptions.conflictHandling = ConflictHandling::Keep;
	const double rate = 0.05;
	map.insertionOptions.decayRate = rate;
	const CPose3D sensor = kRobot + kSensorPose;
	double t = 0.0;
	for (int i = 0; i < 20; ++i)
		map.insertObservation(arcScan(kBeams, 2.0, kSetup.at(t += 0.1)), kRobot);
	Mass reference = massAtPolar(map, sensor, 2.0, 0.3);
	ASSERT_GT(reference.occupied, 0.1);
	const CPose3D away = kRobot + CPose3D(0, 0, 0, M_PI, 0, 0);
	double lastSeen = t;
	for (int i = 1; i <= 1000; ++i)
	{
		const bool looksAway = i % 10 == 0;
		map.insertObservation(arcScan(kBeams, 4.0, kSetup.at(t += 0.1)), looksAway ? away : kRobot);
		if (looksAway) continue;
		reference = conjunctive(
			discount(reference, 1.0 - std::exp(-rate * (t - lastSeen))),
			Mass::simpleFree(kMuF));
		lastSeen = t;
		const Mass m = massAtPolar(map, sensor, 2.0, 0.3);
		ASSERT_MASS_NEAR_AT(m, reference, i == 1 ? kStoreTol : 1e-3, i, t);
	}
}

TEST(MapInsert, ObstacleThatAppearsGivesConflict)
{
	for (const ConflictHandling handling :
		 {ConflictHandling::Keep, ConflictHandling::ToUnknown,
		  ConflictHandling::Normalize})
	{
		CEvidentialGridMap2D map = makeMap();
		map.insertionOptions.conflictHandling = handling;
		map.insertObservation(arcScan(kBeams, 4.0, kSetup), kRobot);
		// Something now stands at 3 m in front of the sensor.
		const auto scan =
			scanByAngle(kBeams, kSetup, [](double a) { return std::abs(a) < 0.3 ? 3.0 : 4.0; });
		map.insertObservation(scan, kRobot);
		const CPose3D sensor = kRobot + scan.sensorPose;
		const Mass m = massAtPolar(map, sensor, 3.025, 0.0);
		ASSERT_TRUE(m.isValid(1e-9));
		if (handling == ConflictHandling::Keep)
		{
			// Free 0.7 before, occupied about 0.9 now: about 0.63 conflict.
			EXPECT_GT(m.conflict, 0.5) << m;
			EXPECT_EQ(decide(m), Decision::Conflict);
		}
		else
			EXPECT_EQ(m.conflict, 0.0) << m;
		if (handling == ConflictHandling::Normalize)
		{
			EXPECT_GT(m.occupied, m.free) << m;
		}
	}
}

TEST(MapInsert, EveryFusionRuleKeepsCellsValid)
{
	for (const FusionRule rule :
		 {FusionRule::Conjunctive, FusionRule::Dempster, FusionRule::Yager,
		  FusionRule::DuboisPrade, FusionRule::Cautious})
		for (const SensorModel model :
			 {SensorModel::MultiEcho, SensorModel::ReinforcedMultiEcho,
			  SensorModel::ImpreciseMultiEcho})
		{
			CEvidentialGridMap2D map = makeMap(model);
			map.insertionOptions.fusionRule = rule;
			map.insertionOptions.imprecision = 0.12;
			for (int k = 0; k < 4; ++k)
				map.insertObservation(
					scanByAngle(
						kBeams, kSetup.at(k),
						[k](double a) { return 2.5 + 0.5 * std::sin(3 * a + k); }),
					CPose3D(0.1 * k, 0.05 * k, 0, 0.2 * k, 0, 0));
			EXPECT_EQ(test::mapDefect(map), "");
			const auto counts = map.countDecisions();
			EXPECT_GT(counts.free, 1000u);
			EXPECT_GT(counts.occupied, 50u);
		}
}

TEST(MapInsert, CautiousRuleIgnoresRepeatedEvidence)
{
	CEvidentialGridMap2D map = makeMap();
	map.insertionOptions.fusionRule = FusionRule::Cautious;
	const auto scan = arcScan(kBeams, 4.0, kSetup);
	for (int k = 0; k < 3; ++k) map.insertObservation(scan, kRobot);
	const CPose3D sensor = kRobot + scan.sensorPose;
	EXPECT_MASS_NEAR(
		massAtPolar(map, sensor, 2.0, 0.2), Mass::simpleFree(kMuF), 3 * kStoreTol);
}

TEST(MapInsert, DecayFollowsDataTime)
{
	CEvidentialGridMap2D map = makeMap();
	const double rate = 0.3;
	map.insertionOptions.decayRate = rate;
	const auto first = arcScan(kBeams, 4.0, kSetup.at(1000.0));
	map.insertObservation(first, kRobot);
	const CPose3D sensor = kRobot + first.sensorPose;
	// Later scans look the other way: the first scan's cells are not seen.
	const CPose3D turned = kRobot + CPose3D(0, 0, 0, M_PI, 0, 0);
	for (const double t : {1000.5, 1002.0, 1005.0})
	{
		map.insertObservation(arcScan(kBeams, 4.0, kSetup.at(t)), turned);
		const double expectedFree = kMuF * std::exp(-rate * (t - 1000.0));
		const Mass m = massAtPolar(map, sensor, 2.0, 0.3);
		EXPECT_NEAR(m.free, expectedFree, kStoreTol) << "t " << t;
		EXPECT_NEAR(m.unknown, 1 - expectedFree, kStoreTol);
		EXPECT_NEAR(map.latestTime(), t, 1e-6);
	}
	// Decay follows the scans' timestamps alone, nothing of the run (no wall
	// clock): the same sequence inserted again gives the same map, cell for
	// cell.
	CEvidentialGridMap2D again = makeMap();
	again.insertionOptions.decayRate = rate;
	again.insertObservation(first, kRobot);
	for (const double t : {1000.5, 1002.0, 1005.0})
		again.insertObservation(arcScan(kBeams, 4.0, kSetup.at(t)), turned);
	EXPECT_TRUE(test::sameCells(map, again));
}

TEST(MapInsert, UpsideDownSensorMirrorsTheScan)
{
	CEvidentialGridMap2D map = makeMap(SensorModel::ImpreciseMultiEcho);
	map.insertionOptions.imprecision = kRes;  // solid walls, see above
	// Beams to the sensor's left return at 2 m, to its right at 4 m. Mounted
	// upside down (roll 180 degrees), its left is the robot's right.
	const auto scan = scanByAngle(
		kBeams, kSetup.sensorPose(CPose3D(0, 0, 0, 0, 0, M_PI)),
		[](double a) { return a > 0 ? 2.0 : 4.0; });
	ASSERT_TRUE(map.insertObservation(scan, CPose3D()));
	const CPose3D robot;
	EXPECT_EQ(decide(strongestOccupiedNear(map, robot, -45 * kDeg, 2.0)), Decision::Occupied);
	EXPECT_EQ(decide(massAtPolar(map, robot, 2.0, 45 * kDeg)), Decision::Free);
	EXPECT_EQ(decide(strongestOccupiedNear(map, robot, 45 * kDeg, 4.0)), Decision::Occupied);
	EXPECT_EQ(decide(massAtPolar(map, robot, 3.0, -45 * kDeg)), Decision::Unknown);
}

TEST(MapInsert, IgnoresWhatItCannotUse)
{
	CEvidentialGridMap2D map = makeMap();
	mrpt::obs::CObservationOdometry odometry;
	EXPECT_FALSE(map.insertObservation(odometry, CPose3D()));
	// A sensor pitched 5 degrees is not a planar scan.
	const auto tilted =
		arcScan(kBeams, 4.0, kSetup.sensorPose(CPose3D(0, 0, 0, 0, 5 * M_PI / 180, 0)));
	EXPECT_FALSE(map.insertObservation(tilted, CPose3D()));
	EXPECT_TRUE(map.isEmpty());
	map.insertionOptions.horizontalTolerance = 10 * M_PI / 180;
	EXPECT_TRUE(map.insertObservation(tilted, CPose3D()));
}

TEST(MapInsert, GridGrowsToHoldScansWithinItsBudget)
{
	CEvidentialGridMap2D map(-1, 1, -1, 1, kRes);
	map.insertionOptions.growthMargin = 1.0;
	const auto scan = arcScan(kBeams, 4.0, kSetup);
	map.insertObservation(scan, kRobot);
	const CPose3D sensor = kRobot + scan.sensorPose;
	// The whole fan, walls included, now lies inside the grid.
	for (double a = -90 * kDeg; a <= 90 * kDeg; a += 5 * kDeg)
	{
		double gx, gy, gz;
		sensor.composePoint(4.1 * std::cos(a), 4.1 * std::sin(a), 0, gx, gy, gz);
		EXPECT_TRUE(gx > map.getXMin() && gx < map.getXMax() && gy > map.getYMin() &&
					gy < map.getYMax())
			<< "angle " << a / kDeg;
	}
	EXPECT_EQ(decide(strongestOccupiedNear(map, sensor, 0.0, 4.0)), Decision::Occupied);

	// Far away and over budget: no growth, nothing inserted outside.
	CEvidentialGridMap2D small(-1, 1, -1, 1, kRes);
	small.setMaxCells(2000);
	ASSERT_TRUE(small.insertObservation(scan, CPose3D(500, 0, 0, 0, 0, 0)));
	EXPECT_EQ(small.getSizeX(), 40);
	EXPECT_EQ(test::informedCells(small), 0u);
}

TEST(MapInsert, ClearForgetsEverything)
{
	CEvidentialGridMap2D map = makeMap();
	map.insertObservation(arcScan(kBeams, 4.0, kSetup), kRobot);
	map.clear();
	EXPECT_TRUE(map.isEmpty());
	EXPECT_EQ(map.countDecisions().unknown, map.geometry().cellCount());
}

// ---------------------------------------------------------------------------
// Decay at extreme rates and time jumps
// ---------------------------------------------------------------------------

TEST(Numbers, MapWithExtremeDecayAndTimeJumpsStaysValid)
{
	// Through the map's own insertion: a scan without a time stamp (it reads
	// as time 0, 1970), then scans from now, some going back in time, with
	// decay rates from tiny to absurd.
	for (const double rate : {1e-12, 0.1, 1e6, 1e300})
		for (const FusionRule rule : {FusionRule::Conjunctive, FusionRule::Dempster})
		{
			CEvidentialGridMap2D map = smallMap();
			map.insertionOptions.decayRate = rate;
			map.insertionOptions.fusionRule = rule;
			auto first = wall(3.0);
			first.timestamp = mrpt::Clock::time_point();
			ASSERT_TRUE(map.insertObservation(first, CPose3D()));
			double t = 1.7e9;
			for (const double step : {0.0, 0.1, 1e-6, -10.0, 5.0, 1e5})
			{
				t += step;
				ASSERT_TRUE(map.insertObservation(wall(2.5, t), CPose3D()));
				ASSERT_TRUE(mapIsValid(map)) << "rate " << rate << " step " << step;
			}
			EXPECT_GT(map.countDecisions().free, 100u) << "rate " << rate;
		}
}
