/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "cloud/CloudSectors.h"

#include <mrpt_evidential/support/FastArcTangent.h>

#include <cmath>

#include "cloud/GroundPlane.h"

namespace mrpt_evidential
{
TCloudCounts sortCloudIntoSectors(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::math::TPoint3D& sensor, const mrpt::poses::CPose3D& robotPose,
	const TCloudRules& rules, TCloudReturns& out)
{
	TCloudCounts counts;
	const auto sectors = static_cast<std::size_t>(
		std::max(1L, std::lround(2 * M_PI / rules.sectorWidth)));
	out.reset(sectors);
	const double spacing = 2 * M_PI / static_cast<double>(sectors);
	const double perRadian = 1.0 / spacing;

	TGroundPlane ground;  // the robot's base plane
	if (rules.groundRemoval == GroundRemoval::Plane)
	{
		TGroundFit fit;
		fit.sensorZ = sensor.z;
		if (const auto plane = fitGroundPlane(points, fit))
			ground = *plane, counts.planeFound = true;
	}

	const auto& R = robotPose.getRotationMatrix();
	const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1),
				 r12 = R(1, 2);
	for (const auto& p : points)
	{
		const double dx0 = p.x - sensor.x, dy0 = p.y - sensor.y, dz0 = p.z - sensor.z;
		if (!(std::isfinite(dx0) && std::isfinite(dy0) && std::isfinite(dz0)) ||
			dx0 * dx0 + dy0 * dy0 + dz0 * dz0 < kNoReturnDistance * kNoReturnDistance)
		{
			++counts.dropped;
			continue;
		}
		++counts.used;
		bool obstacle = true;
		if (rules.groundRemoval != GroundRemoval::None)
		{
			const double h = ground.heightOf(p);
			if (h > rules.maxObstacleHeight)
			{
				++counts.aboveRobot;
				continue;
			}
			obstacle = h >= rules.minObstacleHeight;
		}
		// Only x and y of the point in the world, from the sensor's place.
		const double dx = r00 * (p.x - sensor.x) + r01 * (p.y - sensor.y) + r02 * (p.z - sensor.z);
		const double dy = r10 * (p.x - sensor.x) + r11 * (p.y - sensor.y) + r12 * (p.z - sensor.z);
		// No hypot: its care for overflow costs more than the rest of the loop.
		const double range = std::sqrt(dx * dx + dy * dy);
		// Nearest sector centre; the last one wraps to the first. A point
		// within 2e-6 rad of two sectors' border may go to either. The
		// position is >= 0 (to fastAtan2's error): adding a half and
		// truncating rounds it, without a call to lround for each point.
		const auto s =
			static_cast<std::size_t>((detail::fastAtan2(dy, dx) + M_PI) * perRadian + 0.5) %
			sectors;
		if (obstacle)
		{
			++counts.obstacles;
			out.impacts[s].push_back(range);
			continue;
		}
		++counts.ground;
		if (rules.groundReturns == GroundReturns::FreeSpace)
			out.freeReach[s] = std::max(out.freeReach[s], range);
	}
	return counts;
}

}  // namespace mrpt_evidential
