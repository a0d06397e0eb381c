/* Likelihood of scans in CEvidentialGridMap2D: the likelihood field
 * against a brute-force one, pose discrimination on synthetic and real data,
 * cache invalidation and concurrent first use. */
#include <gtest/gtest.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/scans.h"
#include "support/test_helpers.h"

using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;
using mrpt_evidential::CEvidentialGridMap2D;
namespace test = mrpt_evidential::test;

namespace
{
using Options = CEvidentialGridMap2D::TLikelihoodOptions;

double deg(double d) { return d * M_PI / 180.0; }

// ---------------------------------------------------------------------------
// Synthetic world: a room with obstacles, scans ray-cast against it
// ---------------------------------------------------------------------------

struct Segment
{
	double x0, y0, x1, y1;
};

void addBox(std::vector<Segment>& w, double x0, double y0, double x1, double y1)
{
	w.push_back({x0, y0, x1, y0});
	w.push_back({x1, y0, x1, y1});
	w.push_back({x1, y1, x0, y1});
	w.push_back({x0, y1, x0, y0});
}

/** An asymmetric room, so that every shift and turn changes what fits. */
std::vector<Segment> room()
{
	std::vector<Segment> w;
	addBox(w, -4.0, -3.0, 5.0, 3.5);
	addBox(w, 1.0, 0.5, 2.0, 1.2);
	addBox(w, -2.0, -1.5, -1.6, -1.1);
	w.push_back({-4.0, 1.5, -2.5, 3.5});
	w.push_back({3.0, -3.0, 3.0, -1.8});
	return w;
}

/** Range along a ray to the nearest segment, +inf if none. */
double castRay(
	const std::vector<Segment>& walls, double x, double y, double angle)
{
	const double dx = std::cos(angle), dy = std::sin(angle);
	double best = std::numeric_limits<double>::infinity();
	for (const Segment& s : walls)
	{
		const double ex = s.x1 - s.x0, ey = s.y1 - s.y0;
		const double den = dx * ey - dy * ex;
		if (std::abs(den) < 1e-12) continue;
		const double wx = s.x0 - x, wy = s.y0 - y;
		const double t = (wx * ey - wy * ex) / den;  // along the ray
		const double u = (wx * dy - wy * dx) / den;  // along the segment
		if (t > 1e-9 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
	}
	return best;
}

/** A 270-degree, 541-ray scan of `walls` taken by a robot at `robot` whose
 * sensor sits 0.2 m ahead of it; rays beyond 30 m have no return. */
CObservation2DRangeScan castScan(
	const std::vector<Segment>& walls, const CPose2D& robot, double time)
{
	constexpr float kMaxRange = 30.0f;
	const CPose2D sensor = robot + CPose2D(0.2, 0.0, 0.0);
	const auto setup = test::ScanSetup()
							.aperture(deg(270))
							.maxRange(kMaxRange)
							.sensorPose(CPose3D(0.2, 0.0, 0.3, 0.0, 0.0, 0.0))
							.at(time);
	return test::scanByAngle(541, setup, [&](double angle) {
		const double r = castRay(walls, sensor.x(), sensor.y(), sensor.phi() + angle);
		const bool valid = r < kMaxRange;
		return test::Beam{valid ? static_cast<float>(r) : kMaxRange, valid};
	});
}

const std::vector<CPose2D>& mappingPoses()
{
	static const std::vector<CPose2D> poses{
		{0.0, 0.0, 0.0},
		{2.5, -1.5, deg(90)},
		{-2.5, 0.5, deg(200)},
		{3.5, 2.2, deg(-100)},
		{-1.0, 2.5, deg(-60)}};
	return poses;
}

/** A map of the room built from every mapping pose. */
void buildRoomMap(CEvidentialGridMap2D& map)
{
	const auto walls = room();
	double t = 1.0;
	for (const CPose2D& p : mappingPoses())
		ASSERT_TRUE(map.insertObservation(castScan(walls, p, t++), CPose3D(p)));
}

double score(
	const CEvidentialGridMap2D& map, const CObservation2DRangeScan& scan,
	const CPose2D& pose)
{
	return map.computeObservationLikelihood(scan, CPose3D(pose));
}

/** The six perturbed poses of the pose-discrimination tests. */
std::vector<std::pair<std::string, CPose2D>> perturbations(const CPose2D& p)
{
	return {
		{"x+0.3", {p.x() + 0.3, p.y(), p.phi()}},
		{"x-0.3", {p.x() - 0.3, p.y(), p.phi()}},
		{"y+0.3", {p.x(), p.y() + 0.3, p.phi()}},
		{"y-0.3", {p.x(), p.y() - 0.3, p.phi()}},
		{"yaw+5", {p.x(), p.y(), p.phi() + deg(5)}},
		{"yaw-5", {p.x(), p.y(), p.phi() - deg(5)}}};
}

/** log of the per-ray likelihood at distance d, straight from the model. */
double rayLogLikelihood(const Options& o, double d)
{
	return std::log(
		o.zRandom / o.maxRange +
		o.zHit * std::exp(-d * d / (2.0 * o.sigma * o.sigma)));
}

TEST(Likelihood, ScanScoresBestAtItsOwnPose)
{
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	const auto walls = room();
	// Poses that were not used for mapping, and one that was.
	for (const CPose2D& truth :
		 {CPose2D(0.5, -1.0, deg(30)), CPose2D(-1.0, 0.8, deg(135)),
		  mappingPoses()[1]})
	{
		const auto scan = castScan(walls, truth, 100.0);
		const double own = score(map, scan, truth);
		EXPECT_TRUE(std::isfinite(own));
		for (const auto& [name, moved] : perturbations(truth))
			EXPECT_GT(own, score(map, scan, moved))
				<< "at " << truth.asString() << " moved " << name;
	}
}

TEST(Likelihood, ALongCutKeepsTheOwnPoseBest)
{
	// Cuts past 16 cells code distances coarser far from the obstacles; a
	// ray ending on one must still score as on it, and a shift still cost.
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	const CPose2D truth(0.5, -1.0, deg(30));
	const auto scan = castScan(room(), truth, 100.0);
	const double nearCut = score(map, scan, truth);
	for (const double cut : {3.0, 30.0, 100.0, 1000.0})
	{
		map.likelihoodOptions.maxCorrsDistance = cut;
		const double own = score(map, scan, truth);
		EXPECT_NEAR(own, nearCut, 0.05 * std::abs(nearCut)) << "cut " << cut;
		for (const auto& [name, moved] : perturbations(truth))
			EXPECT_GT(own, score(map, scan, moved)) << "cut " << cut << " moved " << name;
	}
}

TEST(Likelihood, OccupiedMassOfOneFindsTheSurestCells)
{
	// No cell holds more than 0.9999: occupiedMass 1 takes the cells at
	// that ceiling (walls seen from each pose four times, without decay,
	// reach it), not none, so that a scan still scores best at its own pose.
	CEvidentialGridMap2D map;
	double t = 1.0;
	for (int round = 0; round < 4; ++round)
		for (const CPose2D& p : mappingPoses())
			ASSERT_TRUE(map.insertObservation(castScan(room(), p, t++), CPose3D(p)));
	map.likelihoodOptions.occupiedMass = 1.0;
	const CPose2D truth(0.5, -1.0, deg(30));
	const auto scan = castScan(room(), truth, 1.0);
	const double own = score(map, scan, truth);
	for (const auto& [name, moved] : perturbations(truth))
		EXPECT_GT(own, score(map, scan, moved)) << "moved " << name;
}

TEST(Likelihood, OnlyScansCanBeScored)
{
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	mrpt::obs::CObservationOdometry odometry;
	odometry.odometry = CPose2D(1.0, 0.0, 0.0);
	EXPECT_FALSE(map.canComputeObservationLikelihood(odometry));
	EXPECT_EQ(map.computeObservationLikelihood(odometry, CPose3D()), 0.0);
	const auto scan = castScan(room(), CPose2D(), 1.0);
	EXPECT_TRUE(map.canComputeObservationLikelihood(scan));
}

TEST(Likelihood, ScansInsertionIgnoresAreNotScored)
{
	// A scan whose sensor tilts beyond horizontalTolerance (insertion
	// ignores it), whether mounted so or carried by a tilted robot, scores 0,
	// and canComputeObservationLikelihood says so for the mounting it sees.
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	const CPose2D pose(0.5, -1.0, deg(30));
	const auto level = castScan(room(), pose, 1.0);
	ASSERT_NE(score(map, level, pose), 0.0);
	auto pitched = level;
	pitched.sensorPose = CPose3D(0, 0, 0.3, 0, deg(30), 0);
	EXPECT_FALSE(map.canComputeObservationLikelihood(pitched));
	EXPECT_EQ(score(map, pitched, pose), 0.0);
	EXPECT_TRUE(map.canComputeObservationLikelihood(level));
	const CPose3D tiltedRobot(pose.x(), pose.y(), 0, pose.phi(), 0, deg(25));
	EXPECT_EQ(map.computeObservationLikelihood(level, tiltedRobot), 0.0);
	map.insertionOptions.horizontalTolerance = deg(40);
	EXPECT_TRUE(map.canComputeObservationLikelihood(pitched));
	EXPECT_NE(map.computeObservationLikelihood(level, tiltedRobot), 0.0);
}

TEST(Likelihood, RaysOfADenseScanEndWhereInsertionPutsThem)
{
	// 100,001 beams over half a turn, only the last valid, ending 20 m out
	// near an obstacle that a one-beam scan placed along that beam's
	// direction (+90 degrees counterclockwise, -90 clockwise): it scores as
	// the same beam does in a scan of three; no drift over the rays before
	// it (a float step turned 100,000 times put it 16 cm off).
	for (const bool counterclockwise : {true, false})
	{
		CEvidentialGridMap2D map(-25.0, 25.0, -25.0, 25.0, 0.05);
		map.insertionOptions.maxRange = 30.0;
		map.likelihoodOptions.maxRange = 30.0;
		map.likelihoodOptions.decimation = 1;
		const double side = counterclockwise ? 1.0 : -1.0;
		map.insertObservation(
			test::arcScan(1, 20.0, test::ScanSetup().maxRange(30.0)),
			CPose3D(0, 0, 0, side * M_PI / 2, 0, 0));
		const auto lastBeamOnly = [&](std::size_t n) {
			return test::scanByIndex(
				n, test::ScanSetup().maxRange(30.0).rightToLeft(counterclockwise),
				[n](std::size_t i) { return test::Beam{20.0, i == n - 1}; });
		};
		const double alone = score(map, lastBeamOnly(3), CPose2D());
		EXPECT_NEAR(score(map, lastBeamOnly(100001), CPose2D()), alone, 1e-9)
			<< (counterclockwise ? "counterclockwise" : "clockwise");
	}
}

TEST(Likelihood, ScanWithoutValidRaysScoresZero)
{
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	auto scan = castScan(room(), CPose2D(), 1.0);
	for (std::size_t i = 0; i < scan.getScanSize(); ++i)
		scan.setScanRangeValidity(i, false);
	EXPECT_EQ(score(map, scan, CPose2D()), 0.0);
	// Rays at or beyond likelihoodOptions.maxRange are not scored either.
	const auto valid = castScan(room(), CPose2D(), 1.0);
	map.likelihoodOptions.maxRange = 0.1;
	EXPECT_EQ(score(map, valid, CPose2D()), 0.0);
}

TEST(Likelihood, NeverSeenCellsAndDecimation)
{
	// Nothing inserted: every ray ends in a never-seen cell, far from any
	// obstacle, so every scored ray gives the same, known value.
	CEvidentialGridMap2D map;
	const auto scan = castScan(room(), CPose2D(), 1.0);
	std::size_t validRays = 0, validDecimated = 0;
	for (std::size_t i = 0; i < scan.getScanSize(); ++i)
		if (scan.getScanRangeValidity(i))
		{
			++validRays;
			if (i % 5 == 0) ++validDecimated;
		}
	ASSERT_GT(validDecimated, 50u);
	Options& o = map.likelihoodOptions;
	o.decimation = 5;
	EXPECT_NEAR(
		score(map, scan, CPose2D()),
		validDecimated * rayLogLikelihood(o, 0.5 * o.maxCorrsDistance), 1e-9);
	o.decimation = 1;
	EXPECT_NEAR(
		score(map, scan, CPose2D()),
		validRays * rayLogLikelihood(o, 0.5 * o.maxCorrsDistance), 1e-9);
	// Not neutral: scored as a miss.
	o.unknownAsNeutral = false;
	EXPECT_NEAR(
		score(map, scan, CPose2D()),
		validRays * rayLogLikelihood(o, o.maxCorrsDistance), 1e-9);
}

TEST(Likelihood, TinySigmaStaysFinite)
{
	// The Gaussian term underflows to 0 for rays that end a cell or more
	// from an obstacle (the scan scored 0.2 m from where it was taken); the
	// random term keeps the log finite, and without it the log of the
	// Gaussian is exact.
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	const CPose2D pose(0.5, -1.0, deg(30)), off(0.7, -1.0, deg(30));
	const auto scan = castScan(room(), pose, 100.0);
	map.likelihoodOptions.sigma = 1e-4;
	EXPECT_TRUE(std::isfinite(score(map, scan, off)));
	map.likelihoodOptions.zRandom = 0.0;
	const double s = score(map, scan, off);
	EXPECT_TRUE(std::isfinite(s));
	EXPECT_LT(s, -1e3);
}

/** The field against a brute-force one: single-ray scans ending at random
 * points, each scored alone, must give the model's value for the distance
 * from the point's cell to the nearest obstacle cell. */
void checkFieldAgainstBruteForce(CEvidentialGridMap2D& map)
{
	const Options& o = map.likelihoodOptions;
	const auto& g = map.geometry();
	std::vector<std::pair<int, int>> obstacles;
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
		{
			const auto m = map.getCellMassesByIndex(cx, cy);
			const double rest = m.free + m.occupied + m.unknown;
			if (rest > 1e-12 && m.occupied / rest >= o.occupiedMass &&
				map.storage().heldImpact(g.index(cx, cy)))
				obstacles.emplace_back(cx, cy);
		}
	ASSERT_GT(obstacles.size(), 100u);

	const CObservation2DRangeScan ray =
		test::arcScan(1, 1.0, test::ScanSetup().aperture(0.0));

	std::mt19937 rng(7);
	// Some probes land outside the map, in the field's margin and beyond.
	std::uniform_real_distribution<double> ux(g.xMin - 1.0, g.xMax() + 1.0);
	std::uniform_real_distribution<double> uy(g.yMin - 1.0, g.yMax() + 1.0);
	std::size_t near = 0, unseenFar = 0;
	for (int probe = 0; probe < 3000; ++probe)
	{
		// Mostly near the walls, where the distances are not all cut.
		double x, y;
		if (probe % 4 != 0)
		{
			const auto& [ox, oy] = obstacles[rng() % obstacles.size()];
			std::uniform_real_distribution<double> jitter(-0.6, 0.6);
			x = g.cellCenterX(ox) + jitter(rng);
			y = g.cellCenterY(oy) + jitter(rng);
		}
		else
			x = ux(rng), y = uy(rng);
		const int px = g.cellX(x), py = g.cellY(y);
		double best = std::numeric_limits<double>::infinity();
		for (const auto& [ox, oy] : obstacles)
			best = std::min(best, std::hypot(px - ox, py - oy) * g.resolution);
		double d = std::min(best, o.maxCorrsDistance);
		const bool unseen = !g.inside(px, py) ||
			decide(map.getCellMassesByIndex(px, py)) ==
				mrpt_evidential::Decision::Unknown;
		if (unseen && best >= o.maxCorrsDistance && o.unknownAsNeutral)
			d = 0.5 * o.maxCorrsDistance, ++unseenFar;
		if (best < o.maxCorrsDistance) ++near;
		// The ray starts 1 m behind the probe, along +x.
		const double got = score(map, ray, CPose2D(x - 1.0, y, 0.0));
		ASSERT_NEAR(got, rayLogLikelihood(o, d), 1e-5)
			<< "probe (" << x << ", " << y << "), cell (" << px << ", " << py
			<< "), nearest obstacle " << best << " m";
	}
	EXPECT_GT(near, 1000u);
	if (o.unknownAsNeutral)
	{
		EXPECT_GT(unseenFar, 10u);
	}
}

TEST(Likelihood, FieldMatchesBruteForce)
{
	CEvidentialGridMap2D map;
	buildRoomMap(map);
	checkFieldAgainstBruteForce(map);
	// A cut that is not a whole number of cells, and a coarser threshold:
	// changing the options rebuilds the field without any call.
	map.likelihoodOptions.maxCorrsDistance = 0.45;
	map.likelihoodOptions.occupiedMass = 0.6;
	checkFieldAgainstBruteForce(map);
	map.likelihoodOptions.unknownAsNeutral = false;
	checkFieldAgainstBruteForce(map);
}

/** A scan of 181 rays over 90 degrees facing a wall x = wallX, taken from
 * the origin at time t. */
CObservation2DRangeScan wallScan(double wallX, double t)
{
	return test::flatWallScan(
		181, wallX, test::ScanSetup().aperture(deg(90)).at(t));
}

TEST(Likelihood, ConflictIsSetAsideToFindObstacles)
{
	// A wall seen at x = 5.02, then at 5.12: the cell [5, 5.05) is hit once
	// and passed through once, and holds mostly conflict.
	CEvidentialGridMap2D map(-10, 10, -10, 10, 0.05);
	map.insertionOptions.conflictHandling = mrpt_evidential::ConflictHandling::Keep;
	map.insertionOptions.sensorModel = mrpt_evidential::SensorModel::ReinforcedMultiEcho;
	map.insertionOptions.freeMargin = 0.0;
	ASSERT_TRUE(map.insertObservation(wallScan(5.02, 1.0), CPose3D()));
	ASSERT_TRUE(map.insertObservation(wallScan(5.12, 2.0), CPose3D()));
	const auto m = map.getCellMasses(5.025, 0.0);
	ASSERT_GT(m.conflict, 0.5) << "conflict " << m.conflict;
	ASSERT_LT(m.occupied, map.likelihoodOptions.occupiedMass);
	const double share = m.occupied / (m.free + m.occupied + m.unknown);
	ASSERT_GT(share, map.likelihoodOptions.occupiedMass);

	const CObservation2DRangeScan ray = test::arcScan(1, 1.0);
	const Options& o = map.likelihoodOptions;
	// Its occupied share wins: a ray ending there is a hit.
	EXPECT_NEAR(
		score(map, ray, CPose2D(4.025, 0.0, 0.0)), rayLogLikelihood(o, 0.0),
		1e-6);
	// Passed through again and again, the free evidence takes over: the
	// nearest obstacle is the wall's cell [5.1, 5.15), two cells away.
	for (int k = 0; k < 4; ++k)
		ASSERT_TRUE(map.insertObservation(wallScan(5.12, 3.0 + k), CPose3D()));
	EXPECT_NEAR(
		score(map, ray, CPose2D(4.025, 0.0, 0.0)), rayLogLikelihood(o, 0.1),
		1e-6);
}

TEST(Likelihood, InsertionInvalidatesTheCache)
{
	// Map only what the robot sees from the origin, looking along +x.
	CEvidentialGridMap2D map;
	const auto walls = room();
	ASSERT_TRUE(
		map.insertObservation(castScan(walls, CPose2D(), 1.0), CPose3D()));
	// A scan looking the other way mostly ends in cells not seen yet.
	const CPose2D behind(-2.5, 0.5, deg(200));
	const auto scan = castScan(walls, behind, 2.0);
	const double before = score(map, scan, behind);
	EXPECT_EQ(before, score(map, scan, behind));  // cached, same answer
	ASSERT_TRUE(map.insertObservation(scan, CPose3D(behind)));
	const double after = score(map, scan, behind);
	EXPECT_NE(before, after);
	EXPECT_GT(after, before) << "the scan's own walls are now in the map";
	// clear() drops the field too: back to a map that has seen nothing.
	map.clear();
	const auto& o = map.likelihoodOptions;
	std::size_t scored = 0;
	for (std::size_t i = 0; i < scan.getScanSize(); i += o.decimation)
		if (scan.getScanRangeValidity(i)) ++scored;
	EXPECT_NEAR(
		score(map, scan, behind),
		scored * rayLogLikelihood(o, 0.5 * o.maxCorrsDistance), 1e-9);
}

TEST(Likelihood, ConcurrentFirstUseGivesIdenticalResults)
{
	const auto walls = room();
	const CPose2D pose(0.5, -1.0, deg(30));
	const auto scan = castScan(walls, pose, 100.0);
	const CPose2D moved = perturbations(pose)[0].second;
	for (int round = 0; round < 5; ++round)
	{
		CEvidentialGridMap2D map;
		buildRoomMap(map);  // the field is not built yet
		constexpr int kThreads = 4;
		std::vector<double> results(kThreads * 3);
		test::runTogether(kThreads, [&](int t) {
			results[t * 3] = score(map, scan, pose);
			results[t * 3 + 1] = score(map, scan, moved);
			results[t * 3 + 2] = score(map, scan, pose);
		});
		const double serial = score(map, scan, pose);
		const double serialMoved = score(map, scan, moved);
		for (int t = 0; t < kThreads; ++t)
		{
			EXPECT_EQ(results[t * 3], serial) << "thread " << t;
			EXPECT_EQ(results[t * 3 + 1], serialMoved) << "thread " << t;
			EXPECT_EQ(results[t * 3 + 2], serial) << "thread " << t;
		}
	}
}

// ---------------------------------------------------------------------------
// Real data: MRPT's Malaga CS faculty simple map (99 SICK scans, SLAM poses)
// ---------------------------------------------------------------------------

TEST(LikelihoodRealData, MalagaScansScoreBestAtTheirPoses)
{
	mrpt::maps::CSimpleMap simpleMap;
	const std::string file =
		std::string(MRPT_DATASETS_DIR) + "/malaga-cs-fac-building.simplemap.gz";
	ASSERT_TRUE(simpleMap.loadFromFile(file)) << file;
	ASSERT_GT(simpleMap.size(), 50u);

	CEvidentialGridMap2D map(-10, 10, -10, 10, 0.05);
	map.loadFromSimpleMap(simpleMap);
	ASSERT_GT(map.insertionCount(), 0u);
	const auto counts = map.countDecisions();
	ASSERT_GT(counts.occupied, 1000u) << map.asString();
	std::cout << map.asString() << "\n";

	std::size_t checked = 0;
	for (std::size_t k = 0; k < simpleMap.size(); k += 10)
	{
		// Iterated, a keyframe has `pose` and `sf` in MRPT 2.5 and 2.14
		// alike (get() returns a tuple in 2.5, a Keyframe in 2.14).
		const auto& keyframe =
			*std::next(simpleMap.begin(), static_cast<std::ptrdiff_t>(k));
		const auto scan =
			keyframe.sf->getObservationByClass<CObservation2DRangeScan>();
		if (!scan) continue;
		const CPose2D pose(keyframe.pose->getMeanVal());
		const double own = score(map, *scan, pose);
		std::cout << "scan " << k << " at " << pose.asString()
				  << ": own pose " << own;
		for (const auto& [name, moved] : perturbations(pose))
		{
			const double other = score(map, *scan, moved);
			std::cout << ", " << name << " " << other;
			EXPECT_GT(own, other) << "scan " << k << " moved " << name;
		}
		std::cout << "\n";
		++checked;
	}
	EXPECT_GE(checked, 8u);
}

}  // namespace
