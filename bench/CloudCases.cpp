/* evgrid-bench: 3-D clouds into our map, and the same cloud flattened into a
 * 2-D scan for COccupancyGridMap2D, as a user without 3-D support would. */

#include "CloudCases.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

#include "../tests/support/clouds.h"
#include "cloud/CloudSectors.h"
#include "RatioReport.h"
#include "TransformLoop.h"

using mrpt::poses::CPose3D;
using namespace mrpt_evidential;

namespace bench
{
namespace
{
constexpr double kMaxRange = 30.0;
constexpr double kHalfSize = 40.0;
/** The flattened scan's beams: one every 0.2 degree, a VLP-16's spacing. */
constexpr std::size_t kFlatBeams = 1800;

/** A street: house fronts 8 m to each side, cars parked along them, poles,
 * the street's far ends; a 16-layer lidar at 0.2 degree sees about 28,000
 * points of it. */
test::TLidarWorld street()
{
	test::TLidarWorld w;
	w.boxes = {{-40, 40, 8, 9, 0, 12},	{-40, 40, -9, -8, 0, 12}, {39, 40, -8, 8, 0, 12},
			   {-40, -39, -8, 8, 0, 12}, {3, 7.5, 5, 6.8, 0, 1.5},	{-9, -4.5, 5, 6.8, 0, 1.5},
			   {10, 14.5, -6.8, -5, 0, 1.5}, {-2, 2.5, -6.8, -5, 0, 1.5}, {6, 6.2, -4.5, -4.3, 0, 4},
			   {-12, -11.8, 4.3, 4.5, 0, 4}};
	return w;
}

/** The real VLP-16 scan of MRPT's datasets, decoded. */
mrpt::obs::CObservationPointCloud::Ptr vlp16()
{
	mrpt::io::CFileGZInputStream file(
		std::string(MRPT_DATASETS_DIR) + "/test_velodyne_VLP16.rawlog");
	auto archive = mrpt::serialization::archiveFrom(file);
	auto scan = archive.ReadObject<mrpt::obs::CObservationVelodyneScan>();
	scan->generatePointCloud();
	std::vector<mrpt::math::TPoint3Df> points;
	const auto& c = scan->point_cloud;
	for (std::size_t i = 0; i < c.size(); ++i) points.emplace_back(c.x[i], c.y[i], c.z[i]);
	return test::cloudOf(points, scan->sensorPose);
}

/** How the clouds of a case are taken. */
enum class Motion
{
	/** The world holds still: the street's clouds simulated along 10 m of the
	 * street at 1 m/s; the real scan at its pose with a SLAM-like error of a
	 * few centimetres and a tenth of a degree. */
	Static,
	/** One cloud at random poses within 1 m, any heading: a world that
	 * changes at every insertion, the motion layer's worst case. */
	Spinning
};
const char* name(Motion m) { return m == Motion::Static ? "static" : "spinning"; }

/** What a case inserts, in turn: clouds and the robot's pose for each. */
struct TCloudInput
{
	std::vector<mrpt::obs::CObservationPointCloud::Ptr> clouds;
	std::vector<mrpt::obs::CObservation2DRangeScan> flattened;
	std::vector<CPose3D> poses;
};

/** A cloud's points in the robot's frame (its sensor pose applied). */
std::vector<mrpt::math::TPoint3Df> worldPoints(const mrpt::obs::CObservationPointCloud& c)
{
	std::vector<mrpt::math::TPoint3Df> points;
	for (std::size_t i = 0; i < c.pointcloud->size(); ++i)
	{
		float px, py, pz;
		c.pointcloud->getPoint(i, px, py, pz);
		double x, y, z;
		c.sensorPose.composePoint(px, py, pz, x, y, z);
		points.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
	}
	return points;
}

/** The cloud as a user would flatten it for a 2-D grid: per 0.2-degree
 * bearing, the nearest obstacle point, its ground removed as our map does. */
mrpt::obs::CObservation2DRangeScan flatten(const mrpt::obs::CObservationPointCloud& c)
{
	const std::vector<mrpt::math::TPoint3Df> points = worldPoints(c);
	TCloudRules rules;
	rules.sectorWidth = 2 * M_PI / kFlatBeams;
	TCloudReturns returns;
	sortCloudIntoSectors(points, c.sensorPose.translation(), CPose3D(), rules, returns);
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(2 * M_PI);
	scan.rightToLeft = true;
	scan.maxRange = static_cast<float>(kMaxRange);
	scan.sensorPose = CPose3D(c.sensorPose.x(), c.sensorPose.y(), 0, 0, 0, 0);
	scan.resizeScan(kFlatBeams + 1);
	// Sector s of the returns is centred at -pi + s spacing, as beam s of a
	// full-turn scan; the last beam repeats the first direction.
	for (std::size_t b = 0; b <= kFlatBeams; ++b)
	{
		const auto& hits = returns.impacts[b % kFlatBeams];
		const double r = hits.empty() ? 0.0 : *std::min_element(hits.begin(), hits.end());
		scan.setScanRange(b, static_cast<float>(r));
		scan.setScanRangeValidity(b, r > 0.0);
	}
	return scan;
}

TCloudInput makeInput(bool real, Motion motion)
{
	TCloudInput in;
	std::mt19937 rng(2026);
	std::uniform_real_distribution<double> xy(-1.0, 1.0), yaw(-M_PI, M_PI);
	std::normal_distribution<double> error(0.0, 1.0);
	test::TLidar lidar;
	lidar.azimuthStep = 0.2;
	lidar.maxRange = 100.0;
	const auto once = real ? vlp16() : test::lidarCloud(street(), lidar);
	for (int i = 0; i < 100; ++i)
	{
		if (motion == Motion::Spinning)
			in.poses.emplace_back(xy(rng), xy(rng), 0.0, yaw(rng), 0.0, 0.0);
		else if (real)
			in.poses.emplace_back(
				0.03 * error(rng), 0.03 * error(rng), 0.0, 0.1 * M_PI / 180 * error(rng), 0.0, 0.0);
		else
			in.poses.emplace_back(-5.0 + 0.1 * i, 0.0, 0.0, 0.0, 0.0, 0.0);
		// The world is fixed: the street is seen from where the robot is.
		test::TLidarWorld world = street();
		for (auto& b : world.boxes) b.xMin -= in.poses.back().x(), b.xMax -= in.poses.back().x();
		const bool simulateHere = !real && motion == Motion::Static;
		in.clouds.push_back(simulateHere ? test::lidarCloud(world, lidar) : once);
		if (in.flattened.empty() || simulateHere) in.flattened.push_back(flatten(*in.clouds.back()));
	}
	return in;
}

const TCloudInput& input(bool real, Motion motion)
{
	static std::map<std::pair<bool, Motion>, TCloudInput> cache;
	auto it = cache.find({real, motion});
	if (it == cache.end()) it = cache.emplace(std::make_pair(real, motion), makeInput(real, motion)).first;
	return it->second;
}

template <typename Map, typename Obs>
void loop(benchmark::State& state, Map& map, const std::vector<Obs>& all, const TCloudInput& in)
{
	std::size_t i = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		Obs obs = all[i % all.size()];
		obs.timestamp = mrpt::Clock::fromDouble(1000.0 + 0.1 * static_cast<double>(i));
		state.ResumeTiming();
		map.insertObservation(obs, in.poses[i % in.poses.size()]);
		++i;
	}
}

void ours(
	benchmark::State& state, bool real, Motion motion, double res,
	std::optional<GroundRemoval> removal = std::nullopt)
{
	CEvidentialGridMap2D map(-kHalfSize, kHalfSize, -kHalfSize, kHalfSize, res);
	map.insertionOptions.maxRange = kMaxRange;
	if (removal) map.insertionOptions.groundRemoval = *removal;
	const TCloudInput& in = input(real, motion);
	std::vector<mrpt::obs::CObservationPointCloud> clouds;
	for (const auto& c : in.clouds) clouds.push_back(*c);
	loop(state, map, clouds, in);
}

/** Our map fed the flattened scan MRPT gets, through the 2-D path: what the
 * cloud's own work (its ground, its layers) adds to our insertion. */
void oursFlattened(benchmark::State& state, bool real, Motion motion, double res)
{
	CEvidentialGridMap2D map(-kHalfSize, kHalfSize, -kHalfSize, kHalfSize, res);
	map.insertionOptions.maxRange = kMaxRange;
	const TCloudInput& in = input(real, motion);
	loop(state, map, in.flattened, in);
}

void theirs(benchmark::State& state, bool real, Motion motion, double res)
{
	mrpt::maps::COccupancyGridMap2D map(-kHalfSize, kHalfSize, -kHalfSize, kHalfSize, res);
	map.insertionOptions.maxDistanceInsertion = static_cast<float>(kMaxRange);
	map.insertionOptions.wideningBeamsWithDistance = true;
	const TCloudInput& in = input(real, motion);
	loop(state, map, in.flattened, in);
}

/** The transform alone of the first cloud of a case, placed at the origin
 * (as the 2-D `ours/polar2cart` cases). */
void oursTransform(benchmark::State& state, bool real, Motion motion, double res)
{
	const auto& cloud = *input(real, motion).clouds.front();
	TCloudRules rules;
	rules.sectorWidth = kDefaultCloudSectorWidth;
	TCloudReturns returns;
	sortCloudIntoSectors(worldPoints(cloud), cloud.sensorPose.translation(), CPose3D(), rules, returns);
	CEvidentialGridMap2D::TInsertionOptions io;
	io.maxRange = kMaxRange;
	CPolarSourceGrid polar;
	polar.build(returns, io.sourceGridOptions(res));
	transformLoop(
		state, polar, {cloud.sensorPose.x(), cloud.sensorPose.y(), 0.0, false}, kHalfSize, res);
}

std::string label(bool real, Motion motion, double res)
{
	char s[64];
	std::snprintf(s, sizeof(s), "%s/%s/%.2fm", real ? "vlp16" : "street16", name(motion), res);
	return s;
}
}  // namespace

void registerCloudCases()
{
	for (const bool real : {false, true})
		for (const Motion motion : {Motion::Static, Motion::Spinning})
			for (const double res : {0.05, 0.10})
			{
				const std::string at = label(real, motion, res);
				addCase("ours/cloud/" + at,
						[=](benchmark::State& s) { ours(s, real, motion, res); }, Timing::Calls);
				addCase("ours/cloud/plane/" + at,
						[=](benchmark::State& s) { ours(s, real, motion, res, GroundRemoval::Plane); },
						Timing::Calls);
				addCase("ours/flattened/" + at,
						[=](benchmark::State& s) { oursFlattened(s, real, motion, res); },
						Timing::Calls);
				addCase("mrpt/flattened/widening/" + at,
						[=](benchmark::State& s) { theirs(s, real, motion, res); }, Timing::Calls);
				if (motion == Motion::Static)
					addCase("ours/cloudpolar2cart/" + at,
							[=](benchmark::State& s) { oursTransform(s, real, motion, res); },
							Timing::Calls);
			}
}

void printCloudRatios(const std::map<std::string, double>& microseconds)
{
	const auto each = [&](const char* what, const std::string& ours) {
		for (const bool real : {false, true})
			for (const Motion motion : {Motion::Static, Motion::Spinning})
				for (const double res : {0.05, 0.10})
				{
					const std::string at = label(real, motion, res);
					printRatio(
						microseconds, what + at, ours + at, "mrpt/flattened/widening/" + at, 1.0,
						Bound::Below);
				}
	};
	each("cloud vs flattened, ", "ours/cloud/");
	std::printf("\nThe ground as one plane (groundRemoval=Plane, the default before Terrain; apart from the targets):\n");
	each("Plane vs flattened, ", "ours/cloud/plane/");
	std::printf("\nOur map fed the same flattened scan (the 2-D path; apart from the targets):\n");
	each("ours flattened vs flattened, ", "ours/flattened/");
}

}  // namespace bench
