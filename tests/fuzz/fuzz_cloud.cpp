/* Fuzz target: 3-D clouds of arbitrary points (NaN, infinite, huge, at the
 * sensor) in each observation type the map reads, at arbitrary sensor and
 * robot poses (upside down included), under every ground removal, ground
 * meaning, sensor model and conflict handling. Non-finite poses may throw
 * std::invalid_argument; anything else that escapes or an invalid cell is a
 * finding. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/poses/CPose3D.h>

#include <stdexcept>

#include "../support/clouds.h"
#include "FuzzSupport.h"

using namespace mrpt_evidential;

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
	fuzz::silenceMapWarnings();
	return 0;
}

namespace
{
/** The cloud as an observation of its type. */
mrpt::obs::CObservation::Ptr observation(const fuzz::CloudCase::Cloud& c)
{
	const mrpt::poses::CPose3D sensor(
		c.sensorPose[0], c.sensorPose[1], c.sensorPose[2], c.sensorPose[3], c.sensorPose[4],
		c.sensorPose[5]);
	const std::size_t n = c.xyz.size() / 3;
	mrpt::obs::CObservation::Ptr obs;
	if (c.type % 3 == 0)
	{
		std::vector<mrpt::math::TPoint3Df> points;
		for (std::size_t i = 0; i < n; ++i)
			points.emplace_back(c.xyz[3 * i], c.xyz[3 * i + 1], c.xyz[3 * i + 2]);
		obs = test::cloudOf(points, sensor);
	}
	else if (c.type % 3 == 1)
	{
		auto v = mrpt::obs::CObservationVelodyneScan::Create();
		v->sensorPose = sensor;
		for (std::size_t i = 0; i < n; ++i)
		{
			v->point_cloud.x.push_back(c.xyz[3 * i]);
			v->point_cloud.y.push_back(c.xyz[3 * i + 1]);
			v->point_cloud.z.push_back(c.xyz[3 * i + 2]);
		}
		obs = v;
	}
	else
	{
		auto d = mrpt::obs::CObservation3DRangeScan::Create();
		d->sensorPose = sensor;
		d->hasPoints3D = true;
		for (std::size_t i = 0; i < n; ++i)
		{
			d->points3D_x.push_back(c.xyz[3 * i]);
			d->points3D_y.push_back(c.xyz[3 * i + 1]);
			d->points3D_z.push_back(c.xyz[3 * i + 2]);
		}
		obs = d;
	}
	obs->timestamp = mrpt::Clock::time_point(mrpt::Clock::duration(c.ticks));
	return obs;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	fuzz::CloudCase c;
	fuzz::Reader in(data, size);
	fuzz::visit(in, c);

	static const double kResolutions[] = {0.05, 0.1, 0.25};
	static const double kMaxRanges[] = {0.5, 20.0, 100.0, 1000.0};
	CEvidentialGridMap2D map(-2, 2, -2, 2, kResolutions[c.resolution % 3]);
	map.setMaxCells(1 << 20);
	auto& o = map.insertionOptions;
	o.sensorModel = static_cast<SensorModel>(c.model % 3);
	o.conflictHandling = static_cast<ConflictHandling>(c.handling % 3);
	o.groundRemoval = static_cast<GroundRemoval>(c.removal % 4);
	o.groundReturns = static_cast<GroundReturns>(c.returns % 2);
	o.minObstacleHeight = c.minHeight * 0.02;
	o.maxObstacleHeight = o.minObstacleHeight + (1 + c.heightSpan) * 0.05;
	o.sectorWidth = c.sectorWidth * (2 * M_PI / 255);
	o.maxRange = kMaxRanges[c.maxRange % 4];

	for (const fuzz::CloudCase::Cloud& cloud : c.clouds)
	{
		const mrpt::poses::CPose3D robot(
			cloud.robotPose[0], cloud.robotPose[1], cloud.robotPose[2], cloud.robotPose[3],
			cloud.robotPose[4], cloud.robotPose[5]);
		try
		{
			map.insertObservation(*observation(cloud), robot);
		}
		catch (const std::invalid_argument&)
		{
			// A non-finite pose: documented.
		}
		fuzz::checkMap(map);
	}
	return 0;
}
