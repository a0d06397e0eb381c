/* mrpt-evidential tests: 3-D clouds into the evidential grid: ground
 * removal, what each kind of point proves, reinforcement across layers, and
 * bad clouds. The worlds of tests/support/clouds.h give the answer per
 * cell. */
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CObservationRotatingScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include "cloud/CloudSectors.h"
#include "cloud/GroundPlane.h"
#include "support/clouds.h"
#include "support/map_bytes.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt::math::TPoint3Df;
using mrpt::poses::CPose3D;

namespace
{
constexpr double kDeg = M_PI / 180;

CEvidentialGridMap2D makeMap(GroundRemoval removal = GroundRemoval::Plane)
{
	CEvidentialGridMap2D map(-10.0, 10.0, -10.0, 10.0, 0.1);
	map.insertionOptions.groundRemoval = removal;
	return map;
}

/** A wall 6 m ahead across the robot's path. */
test::TBox wallAhead() { return {6.0, 6.3, -3.0, 3.0, 0.0, 2.5}; }

Decision at(const CEvidentialGridMap2D& map, double x, double y)
{
	return map.getCellDecision(x, y);
}
}  // namespace

TEST(Clouds, GroundFreeObstacleOccupiedBehindUnknown)
{
	for (const auto removal : {GroundRemoval::Plane, GroundRemoval::Terrain, GroundRemoval::Height})
	{
		SCOPED_TRACE(static_cast<int>(removal));
		CEvidentialGridMap2D map = makeMap(removal);
		ASSERT_TRUE(map.insertObservation(*test::lidarCloud({0.0, {wallAhead()}}), CPose3D()));
		// Ground seen between the robot and the wall, and all around.
		for (const double x : {3.0, 4.5, -4.0}) EXPECT_EQ(at(map, x, 0.05), Decision::Free) << x;
		EXPECT_EQ(at(map, 0.05, 5.0), Decision::Free);
		EXPECT_EQ(at(map, 6.05, 0.05), Decision::Occupied);
		EXPECT_EQ(at(map, 6.05, 2.05), Decision::Occupied);
		// Behind the wall, nothing was seen.
		for (const double x : {7.5, 9.0}) EXPECT_EQ(at(map, x, 0.05), Decision::Unknown) << x;
	}
}

TEST(Clouds, TerrainHoldsWithTheSensorAtTheEdgeOfItsColumns)
{
	// The ground is followed in 1 m columns within 40 m of the robot's
	// origin; a sensor mounted far from that origin stands at their edge or
	// beyond, and most points fall outside them (each takes its nearest
	// column's ground). The same world, seen from the same place, reads the
	// same.
	for (const auto& [x, y] : {std::pair{39.6, -39.6}, std::pair{-39.9, 39.9}, std::pair{45.0, 0.0}})
	{
		SCOPED_TRACE(std::to_string(x) + ", " + std::to_string(y));
		auto cloud = test::lidarCloud({0.0, {wallAhead()}});
		cloud->sensorPose = CPose3D(x, y, cloud->sensorPose.z(), 0, 0, 0);
		CEvidentialGridMap2D map = makeMap(GroundRemoval::Terrain);
		ASSERT_TRUE(map.insertObservation(*cloud, CPose3D(-x, -y, 0, 0, 0, 0)));
		for (const double gx : {3.0, 4.5, -4.0}) EXPECT_EQ(at(map, gx, 0.05), Decision::Free) << gx;
		EXPECT_EQ(at(map, 0.05, 5.0), Decision::Free);
		EXPECT_EQ(at(map, 6.05, 0.05), Decision::Occupied);
		EXPECT_EQ(at(map, 6.05, 2.05), Decision::Occupied);
		EXPECT_EQ(at(map, 9.0, 0.05), Decision::Unknown);
	}
}

TEST(Clouds, OverhangAndLowKerbAreNotObstacles)
{
	const test::TBox overhang{3.0, 3.5, -2.0, 2.0, 2.6, 3.0};
	const test::TBox kerb{2.0, 2.2, -2.0, 2.0, 0.0, 0.1};
	for (const auto removal : {GroundRemoval::Plane, GroundRemoval::Terrain})
	{
		SCOPED_TRACE(static_cast<int>(removal));
		CEvidentialGridMap2D map = makeMap(removal);
		map.insertObservation(*test::lidarCloud({0.0, {overhang, kerb, wallAhead()}}), CPose3D());
		EXPECT_EQ(at(map, 3.25, 0.05), Decision::Free);
		EXPECT_EQ(at(map, 2.15, 0.05), Decision::Free);
		EXPECT_EQ(at(map, 6.05, 0.05), Decision::Occupied);
	}
	// Lowered below maxObstacleHeight, the overhang is an obstacle.
	CEvidentialGridMap2D low = makeMap();
	low.insertionOptions.maxObstacleHeight = 3.5;
	low.insertObservation(*test::lidarCloud({0.0, {overhang, kerb, wallAhead()}}), CPose3D());
	EXPECT_EQ(at(low, 3.05, 0.05), Decision::Occupied);
}

TEST(Clouds, PlaneRemovesTheGroundOfASlope)
{
	const auto cloud = test::lidarCloud({5.0 * kDeg, {}});
	for (const auto removal : {GroundRemoval::Plane, GroundRemoval::Terrain})
	{
		SCOPED_TRACE(static_cast<int>(removal));
		CEvidentialGridMap2D plane = makeMap(removal);
		plane.insertObservation(*cloud, CPose3D());
		EXPECT_EQ(plane.countDecisions().occupied, 0u);
		EXPECT_GT(plane.countDecisions().free, 10000u);
	}
	// A fixed band takes the rising ground ahead for obstacles: the test
	// can tell.
	CEvidentialGridMap2D band = makeMap(GroundRemoval::Height);
	band.insertObservation(*cloud, CPose3D());
	EXPECT_GT(band.countDecisions().occupied, 100u);
}

TEST(Clouds, TerrainFollowsARampThatThePlaneCannot)
{
	// Flat ground out to 15 m ahead, then a 5-degree ramp: the flat ground
	// all around holds most of the low points, so the plane is its own, and
	// the ramp rises 0.9 m above it 10 m farther.
	const test::TBox pole{25.0, 25.3, 0.0, 0.3, 0.0, 10.0};
	const test::TBox lowBox{-8.0, -7.0, -1.0, 1.0, 0.0, 0.1};
	const test::TLidarWorld world{5.0 * kDeg, {pole, lowBox}, 15.0};
	// The ramp's cells from 20 to 29 m, 3 m either side, but the pole's.
	const auto rampCells = [](const CEvidentialGridMap2D& map, Decision d) {
		int n = 0;
		for (double x = 20.05; x < 29.0; x += 0.1)
			for (double y = -2.95; y < 3.0; y += 0.1)
				if (std::abs(x - 25.15) > 0.6 && at(map, x, y) == d) ++n;
		return n;
	};
	const auto make = [&](GroundRemoval removal) {
		CEvidentialGridMap2D map(-30.0, 30.0, -10.0, 10.0, 0.1);
		map.insertionOptions.groundRemoval = removal;
		map.insertionOptions.maxRange = 30.0;
		EXPECT_TRUE(map.insertObservation(*test::lidarCloud(world), CPose3D()));
		return map;
	};
	const CEvidentialGridMap2D plane = make(GroundRemoval::Plane);
	const CEvidentialGridMap2D terrain = make(GroundRemoval::Terrain);
	// The plane takes the ramp for obstacles where it rises 0.2 m above the
	// flat ground, and hides what lies beyond them, the pole too; the
	// followed ground is free up to the pole, which stays an obstacle.
	EXPECT_GT(rampCells(plane, Decision::Occupied), 20);
	EXPECT_GT(rampCells(plane, Decision::Unknown), 1000);
	EXPECT_EQ(rampCells(terrain, Decision::Occupied), 0);
	EXPECT_GT(rampCells(terrain, Decision::Free), 4000);
	EXPECT_EQ(at(plane, 25.05, 0.15), Decision::Unknown);
	EXPECT_EQ(at(terrain, 25.05, 0.15), Decision::Occupied);
	// The flat ground and the low box behind the robot read alike.
	EXPECT_EQ(at(terrain, -7.45, 0.05), Decision::Free);
	EXPECT_EQ(at(terrain, 10.05, 0.05), Decision::Free);
	EXPECT_EQ(at(plane, 10.05, 0.05), Decision::Free);
}

TEST(Clouds, PointsNotFiniteLeaveTheGroundPlaneAlone)
{
	// The slope's cloud in the robot's frame (the sensor 1.8 m up).
	const auto cloud = test::lidarCloud({5.0 * kDeg, {wallAhead()}});
	std::vector<TPoint3Df> points;
	for (std::size_t i = 0; i < cloud->pointcloud->size(); ++i)
	{
		float x, y, z;
		cloud->pointcloud->getPoint(i, x, y, z);
		points.emplace_back(x, y, z + 1.8f);
	}
	TGroundFit fit;
	fit.sensorZ = 1.8;
	std::vector<std::uint8_t> candidate;
	std::vector<int> lowest;
	const auto clean = fitGroundPlane(points, fit, candidate, lowest);
	ASSERT_TRUE(clean);
	EXPECT_NEAR(clean->a, std::tan(5.0 * kDeg), 1e-3);
	// Low enough to pass for ground but for their infinite or NaN
	// coordinates: the plane must not move by a bit.
	const float inf = std::numeric_limits<float>::infinity();
	const float nan = std::numeric_limits<float>::quiet_NaN();
	points.insert(points.begin() + 100, {inf, 0.0f, 0.0f});
	points.emplace_back(1.0f, -inf, 0.0f);
	points.emplace_back(nan, 1.0f, 0.0f);
	// Whatever the plane's signs, one of these is at a NaN height.
	points.emplace_back(inf, inf, 0.0f);
	points.emplace_back(inf, -inf, 0.0f);
	const auto dirty = fitGroundPlane(points, fit, candidate, lowest);
	ASSERT_TRUE(dirty);
	EXPECT_EQ(dirty->a, clean->a);
	EXPECT_EQ(dirty->b, clean->b);
	EXPECT_EQ(dirty->c, clean->c);
}

TEST(Clouds, GroundReturnsProveFreeSpaceOrNothing)
{
	const auto cloud = test::lidarCloud({0.0, {wallAhead()}});
	CEvidentialGridMap2D nothing = makeMap();
	nothing.insertionOptions.groundReturns = GroundReturns::Nothing;
	nothing.insertObservation(*cloud, CPose3D());
	// Behind the robot there is only ground.
	EXPECT_EQ(at(nothing, -4.0, 0.05), Decision::Unknown);
	EXPECT_EQ(at(nothing, 6.05, 0.05), Decision::Occupied);
	EXPECT_EQ(at(nothing, 3.0, 0.05), Decision::Free);  // the wall's beams crossed it
	// Without ground removal every point is an obstacle: the ground too.
	CEvidentialGridMap2D none = makeMap(GroundRemoval::None);
	none.insertObservation(*cloud, CPose3D());
	EXPECT_EQ(at(none, -6.75, 0.05), Decision::Occupied);
}

TEST(Clouds, LayersHittingOneCellReinforce)
{
	// k points of one azimuth and range at k heights: k layers on a pole.
	for (const int k : {1, 3, 5})
	{
		std::vector<TPoint3Df> points;
		for (int i = 0; i < k; ++i) points.emplace_back(3.02f, 0.0f, 0.3f + 0.2f * i);
		TCloudRules rules;
		rules.groundRemoval = GroundRemoval::Height;
		rules.sectorWidth = 1.0 * kDeg;
		TCloudReturns returns;
		const TCloudCounts counts =
			sortCloudIntoSectors(points, {0, 0, 0}, CPose3D(), rules, returns);
		ASSERT_EQ(counts.obstacles, static_cast<std::size_t>(k));
		for (const auto model : {SensorModel::ReinforcedMultiEcho, SensorModel::MultiEcho})
		{
			TSourceGridOptions options;
			options.sensorModel.model = model;
			options.binSize = 0.1;
			CPolarSourceGrid polar;
			polar.build(returns, options);
			const std::size_t s = polar.sectorCount() / 2;  // azimuth 0
			ASSERT_NEAR(polar.sectorAngle(s), 0.0, 1e-12);
			const double expected = model == SensorModel::MultiEcho
				? options.sensorModel.muO
				: 1.0 - std::pow(1.0 - options.sensorModel.muO, k);
			EXPECT_NEAR(polar.at(s, polar.binOfRange(3.02)).occupied, expected, 1e-12)
				<< k;
		}
	}
}

TEST(Clouds, BadPointsAreDroppedAndCounted)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	const std::vector<TPoint3Df> points = {
		{3.0f, 0.0f, 0.0f}, {static_cast<float>(nan), 0.0f, 0.0f},
		{1.0f, static_cast<float>(inf), 0.0f}, {0.0f, 0.0f, 0.0f}, {0.001f, 0.0f, 0.0f}};
	TCloudReturns returns;
	const TCloudCounts counts = sortCloudIntoSectors(
		points, {0, 0, 0}, CPose3D(), TCloudRules{GroundRemoval::None}, returns);
	EXPECT_EQ(counts.used, 1u);
	EXPECT_EQ(counts.dropped, 4u);
	EXPECT_EQ(counts.obstacles, 1u);

	// Through the map: the good point counts, the rest change nothing (one
	// wide sector holds the point and the cell's centre).
	CEvidentialGridMap2D map = makeMap(GroundRemoval::None);
	map.insertionOptions.sectorWidth = 5 * kDeg;
	ASSERT_TRUE(map.insertObservation(*test::cloudOf(points, CPose3D(0, 0, 1, 0, 0, 0)), CPose3D()));
	EXPECT_EQ(at(map, 3.05, 0.05), Decision::Occupied);
}

TEST(Clouds, SectorsTooNarrowAreAClearError)
{
	const auto cloud = test::lidarCloud({0.0, {wallAhead()}});
	CEvidentialGridMap2D map = makeMap();
	map.insertionOptions.sectorWidth = 1e-5 * kDeg;  // 36 million sectors
	EXPECT_THROW(map.insertObservation(*cloud, CPose3D()), std::invalid_argument);
	EXPECT_EQ(map.countDecisions().free, 0u);
	map.insertionOptions.sectorWidth = 0.001 * kDeg;
	EXPECT_TRUE(map.insertObservation(*cloud, CPose3D()));
}

TEST(Clouds, EmptyCloudsInsertNothing)
{
	CEvidentialGridMap2D map = makeMap();
	EXPECT_TRUE(map.insertObservation(*test::cloudOf({}), CPose3D()));
	auto noCloud = test::cloudOf({});
	noCloud->pointcloud.reset();
	EXPECT_TRUE(map.insertObservation(*noCloud, CPose3D()));
	EXPECT_EQ(map.countDecisions().free + map.countDecisions().occupied, 0u);
}

namespace
{
/** The text of the std::invalid_argument that inserting `obs` throws, or ""
 * if it throws none. */
std::string refusal(CEvidentialGridMap2D& map, const mrpt::obs::CObservation& obs)
{
	try
	{
		map.insertObservation(obs, CPose3D());
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}

/** A Velodyne scan of raw packets only, each block's returns at 2 m. The
 * packet's fields are private in MRPT, written as the wire's bytes
 * (little-endian: a block's header, its rotation, then 3 bytes a return). */
mrpt::obs::CObservationVelodyneScan rawVelodyneScan()
{
	using Scan = mrpt::obs::CObservationVelodyneScan;
	Scan scan;
	scan.scan_packets.resize(3);
	for (auto& packet : scan.scan_packets)
		for (auto& block : packet.blocks)
		{
			auto* bytes = reinterpret_cast<std::uint8_t*>(&block);
			const std::uint16_t header = Scan::UPPER_BANK, rotation = 1000, distance = 1000;
			std::memcpy(bytes, &header, 2);
			std::memcpy(bytes + 2, &rotation, 2);
			for (int laser = 0; laser < Scan::SCANS_PER_BLOCK; ++laser)
			{
				std::memcpy(bytes + 4 + 3 * laser, &distance, 2);
				bytes[6 + 3 * laser] = 5;
			}
		}
	return scan;
}
}  // namespace

TEST(Clouds, UndecodableDepthAndVelodyneFramesThrowNamingTheCause)
{
	// MRPT's own assertions (or a silent empty image) become the map's
	// std::invalid_argument, whose text says what is missing.
	CEvidentialGridMap2D map = makeMap();

	// A range image of 64 x 48 pixels with the default camera (640 x 480).
	mrpt::obs::CObservation3DRangeScan frame;
	frame.hasRangeImage = true;
	frame.rangeImage_setSize(48, 64);
	frame.rangeImage.fill(1000);
	frame.rangeUnits = 0.001f;
	EXPECT_NE(refusal(map, frame).find("(64 x 48) does not fit"), std::string::npos);

	// A fitting image kept in a file beside the rawlog: read when MRPT is told
	// where such files are, named when it cannot be read.
	const auto dir = test::scratchDir("clouds", "external_depth");
	mrpt::obs::CObservation3DRangeScan stored;
	stored.hasRangeImage = true;
	stored.rangeImage_setSize(20, 20);
	stored.rangeImage.fill(3000);
	stored.rangeUnits = 0.001f;
	stored.cameraParams.ncols = 20;
	stored.cameraParams.nrows = 20;
	stored.cameraParams.fx(10);
	stored.cameraParams.fy(10);
	stored.cameraParams.cx(10);
	stored.cameraParams.cy(10);
	stored.sensorPose = CPose3D(0, 0, 1.0, 0, 0, 0);
	stored.rangeImage_convertToExternalStorage("range.bin", dir.string() + "/");
	const std::string before = mrpt::img::CImage::getImagesPathBase();
	mrpt::img::CImage::setImagesPathBase((dir / "elsewhere").string());
	const std::string missing = refusal(map, stored);
	EXPECT_NE(missing.find("stored apart in"), std::string::npos) << missing;
	EXPECT_NE(missing.find("range.bin"), std::string::npos) << missing;
	mrpt::img::CImage::setImagesPathBase(dir.string());
	const std::string found = refusal(map, stored);
	mrpt::img::CImage::setImagesPathBase(before);
	EXPECT_EQ(found, "");
	EXPECT_EQ(at(map, 3.05, 0.0), Decision::Occupied);
	EXPECT_EQ(map.insertionCount(), 1u);

	// Raw Velodyne packets with no calibration, and with one that has fewer
	// lasers than the packets fire.
	mrpt::obs::CObservationVelodyneScan velodyne = rawVelodyneScan();
	EXPECT_NE(refusal(map, velodyne).find("without the calibration"), std::string::npos);
	velodyne.calibration.laser_corrections.resize(1);
	EXPECT_NE(refusal(map, velodyne).find("cannot decode"), std::string::npos);
	EXPECT_EQ(map.insertionCount(), 1u);
}

TEST(Clouds, CloudsOfAnySizeInTurnReadAsIntoANewMap)
{
	// The map keeps its storage for points from cloud to cloud: a cloud of
	// fewer points than the one before, then one of none, must read as they
	// do in a copy of the map made from its bytes, which has none of the
	// last cloud's.
	const auto many = test::lidarCloud({0.0, {wallAhead()}});
	const auto left = test::lidarCloud({0.0, {{-3.0, 3.0, 4.0, 4.3, 0.0, 2.5}}});
	std::vector<TPoint3Df> someOfLeft;
	for (std::size_t i = 0; i < left->pointcloud->size(); i += 7)
	{
		float x, y, z;
		left->pointcloud->getPoint(i, x, y, z);
		someOfLeft.emplace_back(x, y, z);
	}
	ASSERT_LT(someOfLeft.size(), many->pointcloud->size());
	const auto fewer = test::cloudOf(someOfLeft, left->sensorPose);
	auto none = test::cloudOf({});
	none->pointcloud.reset();

	CEvidentialGridMap2D reused = makeMap(GroundRemoval::Terrain);
	reused.insertObservation(*many, CPose3D());
	CEvidentialGridMap2D copy = makeMap();
	test::deserialize(test::serialize(reused), copy);
	const std::size_t occupiedBefore = copy.countDecisions().occupied;
	const CPose3D moved(0.3, -0.2, 0.0, 0.1, 0.0, 0.0);
	for (const auto* cloud : {fewer.get(), none.get()})
	{
		reused.insertObservation(*cloud, moved);
		copy.insertObservation(*cloud, moved);
		EXPECT_TRUE(test::serialize(reused) == test::serialize(copy));
	}
	// The fewer points did add their wall.
	EXPECT_GT(copy.countDecisions().occupied, occupiedBefore + 20);
}

TEST(Clouds, SensorUpsideDownSeesTheSameWorld)
{
	const auto upright = test::lidarCloud({0.0, {wallAhead()}});
	// The same points seen by a sensor rolled half a turn: y and z flip in
	// its frame, and its pose on the robot undoes that.
	std::vector<TPoint3Df> flipped;
	const auto& c = *upright->pointcloud;
	for (std::size_t i = 0; i < c.size(); ++i)
	{
		float x, y, z;
		c.getPoint(i, x, y, z);
		flipped.emplace_back(x, -y, -z);
	}
	const auto rolled = test::cloudOf(flipped, CPose3D(0, 0, 1.8, 0, 0, M_PI));
	CEvidentialGridMap2D a = makeMap(), b = makeMap();
	a.insertObservation(*upright, CPose3D());
	b.insertObservation(*rolled, CPose3D());
	const auto da = a.countDecisions(), db = b.countDecisions();
	EXPECT_EQ(da.free, db.free);
	EXPECT_EQ(da.occupied, db.occupied);
	EXPECT_EQ(at(b, 6.05, 0.05), Decision::Occupied);

	// A robot upside down has no ground under it: refused, with its own
	// note once, even after the note on a tilted scan.
	CEvidentialGridMap2D refused = makeMap();
	mrpt::obs::CObservation2DRangeScan tilted;
	tilted.resizeScan(3);
	tilted.sensorPose = CPose3D(0, 0, 0, 0, M_PI / 4, 0);
	const std::string err = test::stderrOf([&] {
		EXPECT_FALSE(refused.insertObservation(tilted, CPose3D()));
		for (int i = 0; i < 2; ++i)
			EXPECT_FALSE(refused.insertObservation(*upright, CPose3D(0, 0, 0, 0, 0, M_PI)));
	});
	EXPECT_EQ(test::occurrences(err, "horizontalTolerance"), 1u) << err;
	EXPECT_EQ(test::occurrences(err, "points down"), 1u) << err;
}

TEST(Clouds, MillionsOfPointsAndUnreadTypes)
{
	// Two million points on one wall: linear work, a correct map.
	std::vector<TPoint3Df> points;
	points.reserve(2'000'000);
	for (int i = 0; i < 2'000'000; ++i)
		points.emplace_back(5.0f, -2.0f + 4.0f * static_cast<float>(i) / 2e6f, 0.5f);
	CEvidentialGridMap2D map = makeMap(GroundRemoval::Height);
	ASSERT_TRUE(map.insertObservation(*test::cloudOf(points, CPose3D(0, 0, 0.5, 0, 0, 0)), CPose3D()));
	EXPECT_EQ(at(map, 5.05, 0.05), Decision::Occupied);
	EXPECT_EQ(at(map, 2.5, 0.05), Decision::Free);
	// A rotating scan has no elevations in MRPT 2.5.8: not for this map.
	EXPECT_FALSE(map.insertObservation(mrpt::obs::CObservationRotatingScan(), CPose3D()));
}
