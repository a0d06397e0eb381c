/* Inserting scans the map cannot take as they are: ranges that are no
 * returns, empty and one-beam scans, apertures out of range, ranges beyond
 * maxRange, clockwise and upside-down sensors, tilted sensors. Each gets a
 * clear exception or the documented safe behaviour, and the map stays valid
 * (doc/reliability.md; poses and growth: test_map_poses_and_growth.cpp). */
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "support/bad_input.h"
#include "support/map_assertions.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using namespace mrpt_evidential::test;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;

// ---------------------------------------------------------------------------
// Scans
// ---------------------------------------------------------------------------

TEST(BadScan, NonFiniteNegativeAndZeroRangesAreNoReturn)
{
	// Beams flagged valid whose range is NaN, +-inf, negative or zero count
	// as beams without a return: the map equals the one where they are
	// flagged invalid.
	const std::vector<double> bad = {kNaN, kInf, -kInf, -1.0, -1e-30, 0.0, -0.0};
	auto scan = wall(3.0);
	auto flagged = scan;
	for (std::size_t i = 0; i < scan.getScanSize(); i += 3)
	{
		scan.setScanRange(i, static_cast<float>(bad[(i / 3) % bad.size()]));
		flagged.setScanRangeValidity(i, false);
	}
	for (const bool asFree : {false, true})
	{
		CEvidentialGridMap2D withBad = smallMap(), withFlags = smallMap();
		withBad.insertionOptions.invalidRangesAsFree = asFree;
		withFlags.insertionOptions.invalidRangesAsFree = asFree;
		ASSERT_TRUE(withBad.insertObservation(scan, CPose3D()));
		ASSERT_TRUE(withFlags.insertObservation(flagged, CPose3D()));
		EXPECT_TRUE(mapIsValid(withBad));
		EXPECT_TRUE(sameCells(withBad, withFlags)) << "invalidRangesAsFree " << asFree;
		EXPECT_GT(withBad.countDecisions().occupied, 20u);
	}
}

TEST(BadScan, EveryRayInvalidChangesNoCell)
{
	for (const double r : {kNaN, kInf, -2.0, 0.0})
	{
		CEvidentialGridMap2D map = smallMap();
		const auto scan = wall(r, 10.0);
		ASSERT_TRUE(map.insertObservation(scan, CPose3D()));
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_EQ(informedCells(map), 0u) << "range " << r;
		EXPECT_EQ(map.getSizeX(), 100);  // nothing to grow for
		// Read as free space when asked to: up to maxRange, nothing occupied.
		map.insertionOptions.invalidRangesAsFree = true;
		map.insertionOptions.maxRange = 2.0;
		ASSERT_TRUE(map.insertObservation(scan, CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_EQ(decide(map.getCellMasses(1.5, 0.0)), Decision::Free);
		EXPECT_EQ(map.getCellMasses(2.5, 0.0), Mass::vacuous());
		EXPECT_EQ(map.countDecisions().occupied, 0u);
	}
}

TEST(BadScan, EmptyScanIsInsertedAndChangesNoCell)
{
	CEvidentialGridMap2D map = smallMap();
	map.insertionOptions.decayRate = 0.5;
	ASSERT_TRUE(map.insertObservation(wall(3.0, 100.0), CPose3D()));
	const Mass before = map.getCellMasses(1.5, 0.0);
	const auto empty = scanFromRanges({}, {}, ScanSetup().at(102.0));
	ASSERT_TRUE(map.insertObservation(empty, CPose3D()));
	// Its time counts (data time moves on, older evidence decays), nothing
	// else does.
	EXPECT_EQ(map.insertionCount(), 2u);
	EXPECT_NEAR(map.latestTime(), 102.0, 1e-6);
	EXPECT_MASS_NEAR(
		map.getCellMasses(1.5, 0.0), discount(before, 1.0 - std::exp(-1.0)),
		2.0 / kMassScale);
	EXPECT_TRUE(mapIsValid(map));
}

TEST(BadScan, SingleRayCoversItsAperture)
{
	// One beam covers the scan's aperture, centred straight ahead.
	CEvidentialGridMap2D map = smallMap();
	ASSERT_TRUE(map.insertObservation(
		arcScan(1, 3.0, kBadInputSetup.aperture(10 * kDeg)), CPose3D()));
	EXPECT_TRUE(mapIsValid(map));
	EXPECT_EQ(decide(map.getCellMasses(1.5, 0.0)), Decision::Free);
	EXPECT_EQ(map.getCellMasses(1.5, 1.0), Mass::vacuous());  // 34 degrees off
	EXPECT_EQ(map.getCellMasses(-1.5, 0.0), Mass::vacuous());
	EXPECT_GT(map.countDecisions().occupied, 0u);
}

TEST(BadScan, ApertureOutOfRangeIsRejected)
{
	CEvidentialGridMap2D map = smallMap();
	ASSERT_TRUE(map.insertObservation(wall(3.0, 1.0), CPose3D()));
	const CEvidentialGridMap2D before = map;
	for (const double aperture : {0.0, -1.0, 2 * M_PI + 0.01, 7.0, 1e30, kNaN, kInf})
	{
		auto scan = wall(3.0, 2.0);
		scan.aperture = static_cast<float>(aperture);
		try
		{
			map.insertObservation(scan, CPose3D());
			ADD_FAILURE() << "aperture " << aperture << " was accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("aperture"), std::string::npos)
				<< e.what();
		}
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_EQ(map.latestTime(), before.latestTime());
		EXPECT_TRUE(sameCells(map, before)) << "aperture " << aperture;
	}
	// A full turn is fine.
	auto round = arcScan(360, 3.0, kBadInputSetup.aperture(2 * M_PI).at(2.0));
	EXPECT_TRUE(map.insertObservation(round, CPose3D()));
	EXPECT_EQ(decide(map.getCellMasses(-1.5, 0.0)), Decision::Free);
	EXPECT_TRUE(mapIsValid(map));
}

TEST(BadScan, TinyApertureInformsNoMoreThanItsWedge)
{
	for (const double aperture : {1e-6, 1e-30})
	{
		CEvidentialGridMap2D map = smallMap();
		ASSERT_TRUE(map.insertObservation(
			arcScan(181, 3.0, kBadInputSetup.aperture(aperture)), CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_LT(informedCells(map), 40u) << "aperture " << aperture;
	}
}

TEST(BadScan, SingleRayApertureOutOfRangeIsRejected)
{
	CEvidentialGridMap2D map = smallMap();
	for (const double aperture : {0.0, -1.0, 2 * M_PI + 0.01, 7.0, 1e30, kInf, kNaN})
	{
		EXPECT_THROW(
			map.insertObservation(
				arcScan(1, 3.0, kBadInputSetup.aperture(aperture)), CPose3D()),
			std::invalid_argument)
			<< "aperture " << aperture;
		EXPECT_TRUE(map.isEmpty());
	}
}


TEST(BadScan, RangesBeyondMaxRangeOnlyProveFreeSpace)
{
	for (const double r : {25.0, 1e6, 1e30, double(std::numeric_limits<float>::max())})
	{
		CEvidentialGridMap2D map = smallMap();
		map.insertionOptions.maxRange = 4.0;
		map.insertionOptions.growthMargin = 1.0;
		ASSERT_TRUE(map.insertObservation(wall(r), CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_EQ(map.countDecisions().occupied, 0u) << "range " << r;
		EXPECT_EQ(decide(map.getCellMasses(3.5, 0.0)), Decision::Free);
		EXPECT_EQ(map.getCellMasses(4.5, 0.0), Mass::vacuous());
		EXPECT_EQ(map.getSizeX(), 100) << "grew for a return beyond maxRange";
	}
}

TEST(BadScan, ClockwiseScanEqualsReversedCounterclockwiseOne)
{
	// rightToLeft = false: beam i is at +aperture/2 - i * step.
	const auto range = [](double a) { return 2.0 + std::sin(3 * a) + 0.5 * (a > 0); };
	const auto ccw = scanByAngle(181, kBadInputSetup, range);
	CObservation2DRangeScan cw = ccw;
	cw.rightToLeft = false;
	for (std::size_t i = 0; i < 181; ++i)
		cw.setScanRange(i, ccw.getScanRange(180 - i));
	CEvidentialGridMap2D a = smallMap(), b = smallMap();
	ASSERT_TRUE(a.insertObservation(ccw, CPose3D(0.3, -0.2, 0, 0.4, 0, 0)));
	ASSERT_TRUE(b.insertObservation(cw, CPose3D(0.3, -0.2, 0, 0.4, 0, 0)));
	EXPECT_TRUE(mapIsValid(b));
	EXPECT_TRUE(sameCells(a, b, 2.0 / kMassScale));
}

TEST(BadScan, UpsideDownClockwiseSensorEqualsUprightCounterclockwiseOne)
{
	// Mounted upside down, a sensor that scans clockwise in its own frame
	// scans counterclockwise in the map: same ranges, same map.
	const auto range = [](double a) { return 2.0 + std::sin(3 * a) + 0.5 * (a > 0); };
	const auto upright = scanByAngle(181, kBadInputSetup, range);
	CObservation2DRangeScan flipped = upright;
	flipped.rightToLeft = false;
	flipped.sensorPose = CPose3D(0, 0, 0, 0, 0, M_PI);
	CEvidentialGridMap2D a = smallMap(), b = smallMap();
	ASSERT_TRUE(a.insertObservation(upright, CPose3D(-0.5, 0.5, 0, 1.0, 0, 0)));
	ASSERT_TRUE(b.insertObservation(flipped, CPose3D(-0.5, 0.5, 0, 1.0, 0, 0)));
	EXPECT_TRUE(mapIsValid(b));
	// The mirrored transform rounds differently at cells on a sector edge.
	EXPECT_TRUE(sameCells(a, b, 1e-3));
}

TEST(BadScan, TiltedSensorIsIgnoredWithOneNote)
{
	CEvidentialGridMap2D map = smallMap();
	const std::string err = stderrOf([&] {
		for (const CPose3D& sensorPose :
			 {CPose3D(0, 0, 0, 0, 5 * kDeg, 0), CPose3D(0, 0, 0, 0.3, 0, -10 * kDeg),
			  CPose3D(0, 0, 0, 0, 89 * kDeg, 0)})
		{
			auto scan = wall();
			scan.sensorPose = sensorPose;
			EXPECT_FALSE(map.insertObservation(scan, CPose3D()));
		}
		// A robot pitched on a ramp tilts its sensor just the same.
		EXPECT_FALSE(map.insertObservation(wall(), CPose3D(0, 0, 0, 0, 3 * kDeg, 0)));
	});
	EXPECT_EQ(occurrences(err, "horizontalTolerance"), 1u) << err;
	EXPECT_TRUE(map.isEmpty());
	EXPECT_EQ(informedCells(map), 0u);
}
