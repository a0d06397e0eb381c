/* mrpt-evidential tests: one factory of 3-D lidar clouds for all tests: a
 * multi-layer lidar ray-cast in a small world of known geometry. */
#pragma once

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mrpt_evidential::test
{
/** A box, metres in the robot's frame; z from the flat ground. */
struct TBox
{
	double xMin, xMax, yMin, yMax, zMin, zMax;
};

/** The world: a ground plane rising `slope` radians towards +x
 * (z = tan(slope) x), or, with a finite `rampFrom`, flat ground (z = 0) that
 * rises so from x = rampFrom on; and boxes. */
struct TLidarWorld
{
	double slope = 0.0;
	std::vector<TBox> boxes;
	double rampFrom = -std::numeric_limits<double>::infinity();
};

/** Distance along unit ray (o, d) to the ground of `world`, or +inf. */
inline double rayToGround(const double o[3], const double d[3], const TLidarWorld& world)
{
	const double inf = std::numeric_limits<double>::infinity();
	const double k = std::tan(world.slope);
	// The plane z = k (x - x0) the ray meets going down it, if it does.
	const auto toPlane = [&](double x0) {
		const double towards = d[2] - k * d[0];
		return towards < -1e-12 ? (k * (o[0] - x0) - o[2]) / towards : inf;
	};
	if (!std::isfinite(world.rampFrom)) return toPlane(0.0);
	const double flat = d[2] < -1e-12 ? -o[2] / d[2] : inf;
	const double ramp = toPlane(world.rampFrom);
	const bool flatHit = flat < inf && o[0] + flat * d[0] < world.rampFrom;
	const bool rampHit = ramp < inf && ramp >= 0.0 && o[0] + ramp * d[0] >= world.rampFrom;
	return std::min(flatHit ? flat : inf, rampHit ? ramp : inf);
}

/** The lidar: `layers` elevations evenly from -15 to +15 degrees, one ray
 * every `azimuthStep` degrees, mounted `height` m above the robot's origin. */
struct TLidar
{
	int layers = 16;
	double azimuthStep = 0.4;
	double height = 1.8;
	double maxRange = 60.0;
};

/** Distance along unit ray (o, d) to box b, or +inf. */
inline double rayToBox(const double o[3], const double d[3], const TBox& b)
{
	const double lo[3] = {b.xMin, b.yMin, b.zMin}, hi[3] = {b.xMax, b.yMax, b.zMax};
	double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
	for (int i = 0; i < 3; ++i)
	{
		if (std::abs(d[i]) < 1e-12)
		{
			if (o[i] < lo[i] || o[i] > hi[i]) return std::numeric_limits<double>::infinity();
			continue;
		}
		double a = (lo[i] - o[i]) / d[i], c = (hi[i] - o[i]) / d[i];
		if (a > c) std::swap(a, c);
		t0 = std::max(t0, a), t1 = std::min(t1, c);
	}
	return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
}

/** The cloud the lidar sees in the world, as a CObservationPointCloud
 * (points in the sensor's frame, sensorPose the mount). */
inline mrpt::obs::CObservationPointCloud::Ptr lidarCloud(
	const TLidarWorld& world, const TLidar& lidar = TLidar(), double time = 1.0)
{
	auto cloud = mrpt::maps::CSimplePointsMap::Create();
	const double o[3] = {0.0, 0.0, lidar.height};
	const int columns = static_cast<int>(std::lround(360.0 / lidar.azimuthStep));
	for (int layer = 0; layer < lidar.layers; ++layer)
	{
		const double e = (-15.0 + 30.0 * layer / std::max(1, lidar.layers - 1)) * M_PI / 180;
		for (int c = 0; c < columns; ++c)
		{
			const double a = c * lidar.azimuthStep * M_PI / 180;
			const double d[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
			double t = rayToGround(o, d, world);
			for (const TBox& b : world.boxes) t = std::min(t, rayToBox(o, d, b));
			if (!(t <= lidar.maxRange)) continue;
			cloud->insertPoint(
				static_cast<float>(t * d[0]), static_cast<float>(t * d[1]),
				static_cast<float>(o[2] + t * d[2] - lidar.height));
		}
	}
	auto obs = mrpt::obs::CObservationPointCloud::Create();
	obs->sensorLabel = "LIDAR";
	obs->timestamp = mrpt::Clock::fromDouble(time);
	obs->sensorPose = mrpt::poses::CPose3D(0, 0, lidar.height, 0, 0, 0);
	obs->pointcloud = cloud;
	return obs;
}

/** A cloud of the given points in the sensor's frame, at `sensorPose`. */
inline mrpt::obs::CObservationPointCloud::Ptr cloudOf(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::poses::CPose3D& sensorPose = mrpt::poses::CPose3D(), double time = 1.0)
{
	auto cloud = mrpt::maps::CSimplePointsMap::Create();
	for (const auto& p : points) cloud->insertPoint(p.x, p.y, p.z);
	auto obs = mrpt::obs::CObservationPointCloud::Create();
	obs->timestamp = mrpt::Clock::fromDouble(time);
	obs->sensorPose = sensorPose;
	obs->pointcloud = cloud;
	return obs;
}

}  // namespace mrpt_evidential::test
