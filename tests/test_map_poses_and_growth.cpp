/* Scans at poses the map cannot use or hold: poses that are not finite, far
 * and farther away, points read far away; and growth of the grid up to its
 * cell budget and no further. Each gets a clear exception or the documented
 * safe behaviour, and the map stays valid (doc/reliability.md). */
#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/bad_input.h"
#include "support/map_assertions.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using namespace mrpt_evidential::test;
using mrpt::poses::CPose3D;

// ---------------------------------------------------------------------------
// Poses
// ---------------------------------------------------------------------------

TEST(BadPose, NonFinitePoseThrowsAndChangesNothing)
{
	CEvidentialGridMap2D map = smallMap();
	ASSERT_TRUE(map.insertObservation(wall(3.0, 1.0), CPose3D()));
	const CEvidentialGridMap2D before = map;
	const std::vector<std::pair<CPose3D, CPose3D>> cases = {
		{CPose3D(kNaN, 0, 0, 0, 0, 0), CPose3D()},
		{CPose3D(0, kInf, 0, 0, 0, 0), CPose3D()},
		{CPose3D(0, 0, -kInf, 0, 0, 0), CPose3D()},
		{CPose3D(0, 0, 0, kNaN, 0, 0), CPose3D()},
		{CPose3D(0, 0, 0, 0, kNaN, 0), CPose3D()},
		{CPose3D(), CPose3D(0, 0, 0, 0, 0, kNaN)},
		{CPose3D(), CPose3D(kNaN, kNaN, kNaN, 0, 0, 0)}};
	for (const auto& [robot, sensorPose] : cases)
	{
		auto scan = wall(3.0, 2.0);
		scan.sensorPose = sensorPose;
		try
		{
			map.insertObservation(scan, robot);
			ADD_FAILURE() << "pose " << robot.asString() << " accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos)
				<< e.what();
		}
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_TRUE(sameCells(map, before));
		// Scoring at such a pose gives a number, never NaN.
		EXPECT_FALSE(std::isnan(map.computeObservationLikelihood(scan, robot)));
	}
}

TEST(BadPose, FarPoseIsInsertedOnlyWhereItOverlapsTheGrid)
{
	// 1000 km away at 0.1 m cells: growth would exceed the cell budget, so
	// the grid stays and the scan, which does not overlap it, changes nothing.
	for (const double far : {1e6, -1e6})
	{
		CEvidentialGridMap2D map = smallMap();
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, 0, 0, 0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(0, far, 0, 0, 0, 0)));
		EXPECT_EQ(map.getSizeX(), 100);
		EXPECT_EQ(map.getSizeY(), 100);
		EXPECT_EQ(informedCells(map), 0u);
		EXPECT_FALSE(std::isnan(
			map.computeObservationLikelihood(wall(), CPose3D(far, far, 0, 0, 0, 0))));
	}
}

TEST(BadPose, FarAndNaNPointsReadAsOutside)
{
	const CEvidentialGridMap2D map = smallMap();
	const GridGeometry& g = map.geometry();
	for (const double v : {1e300, -1e300, 1e10, kInf, -kInf, kNaN})
	{
		EXPECT_FALSE(g.inside(g.cellX(v), 0)) << v;
		EXPECT_FALSE(g.inside(0, g.cellY(v))) << v;
		EXPECT_EQ(map.getCellMasses(v, 0.0), Mass::vacuous());
		EXPECT_EQ(map.getCellBetP(0.0, v), 0.5);
	}
	EXPECT_EQ(g.cellX(1e300), std::numeric_limits<int>::max());
	EXPECT_EQ(g.cellX(-1e300), std::numeric_limits<int>::min());
	EXPECT_EQ(g.cellX(0.05), 50);
}

TEST(BadPose, PoseAtABillionMetresChangesNothing)
{
	for (const double far : {1e9, -1e9, 1e300})
	{
		CEvidentialGridMap2D map = smallMap();
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, 0, 0, 0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(0, far, 0, 2.0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, far, 0, 0, 0, 0)));
		EXPECT_EQ(map.getSizeX(), 100);
		EXPECT_EQ(informedCells(map), 0u);
	}
}

// ---------------------------------------------------------------------------
// Growth
// ---------------------------------------------------------------------------

TEST(Growth, StopsAtTheCellBudgetWithOneWarning)
{
	CEvidentialGridMap2D map = smallMap();  // 10,000 cells
	map.setMaxCells(40'000);
	map.insertionOptions.growthMargin = 1.0;
	std::size_t largest = 0;
	const std::string err = stderrOf([&] {
		// Farther and farther: the first scans fit, the last ones cannot.
		for (const double x : {4.0, 8.0, 12.0, 50.0, 500.0, 5e4, 5e5})
		{
			ASSERT_TRUE(map.insertObservation(wall(), CPose3D(x, 0, 0, 0, 0, 0)));
			ASSERT_LE(map.geometry().cellCount(), map.maxCells()) << "at " << x;
			largest = std::max(largest, map.geometry().cellCount());
		}
	});
	EXPECT_GT(largest, 10'000u);  // it did grow while it could
	EXPECT_EQ(occurrences(err, "maxCells"), 1u) << err;
	EXPECT_TRUE(mapIsValid(map));
	// Each scan that could not be held whole is counted (500 m and on).
	const std::size_t partly = map.partlyInsertedCount();
	EXPECT_GE(partly, 3u);
	EXPECT_LT(partly, 7u);
	// Scans within the grid still go in, whole.
	const auto counts = map.countDecisions();
	ASSERT_TRUE(map.insertObservation(wall(2.0), CPose3D(0, 0, 0, M_PI, 0, 0)));
	EXPECT_GT(map.countDecisions().free, counts.free);
	EXPECT_EQ(map.partlyInsertedCount(), partly);
	map.clear();
	EXPECT_EQ(map.partlyInsertedCount(), 0u);
	// A grid made anew by setSize() starts its count again too.
	ASSERT_TRUE(map.insertObservation(wall(), CPose3D(5e5, 0, 0, 0, 0, 0)));
	EXPECT_EQ(map.partlyInsertedCount(), 1u);
	map.setSize(-1.0, 1.0, -1.0, 1.0, 0.1);
	EXPECT_EQ(map.partlyInsertedCount(), 0u);
}

TEST(Growth, RandomWalkAwayNeverExceedsTheBudget)
{
	CEvidentialGridMap2D map = smallMap();
	map.setMaxCells(200'000);
	map.insertionOptions.growthMargin = 2.0;
	test::MassGenerator gen(3);
	std::normal_distribution<double> step(3.0, 10.0);
	double x = 0, y = 0;
	stderrOf([&] {
		for (int k = 0; k < 200; ++k)
		{
			x += step(gen.rng());
			y += step(gen.rng());
			ASSERT_TRUE(map.insertObservation(
				wall(1.0 + k % 7, k), CPose3D(x, y, 0, 0.1 * k, 0, 0)));
			ASSERT_LE(map.geometry().cellCount(), map.maxCells());
		}
	});
	EXPECT_TRUE(mapIsValid(map));
}
