/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "cloud/CloudSectors.h"

#include <mrpt_evidential/support/CpuClones.h>
#include <mrpt_evidential/support/FastArcTangent.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cloud/GroundPlane.h"
#include "cloud/GroundSurface.h"

namespace mrpt_evidential
{
namespace
{
/** A point's code (classify()): its sector, with kGround for a
 * ground point, or one of the two marks. */
constexpr std::uint32_t kDropped = 0xFFFFFFFFu, kAboveRobot = 0xFFFFFFFEu,
						kGround = 0x80000000u;

/** What classify() needs of the rules, the plane and the poses. */
struct TClassification
{
	float sensorX, sensorY, sensorZ;
	/** The robot's rotation's first two rows: x and y in the world. */
	float r00, r01, r02, r10, r11, r12;
	/** The ground plane, z = a x + b y + c, and with Terrain the ground's
	 * height above it per column (CGroundSurface). */
	float a = 0.0f, b = 0.0f, c = 0.0f;
	const float* surface = nullptr;
	/** Obstacles lie between these heights above the ground (+-inf without
	 * ground removal). */
	float minHeight, maxHeight;
	double sectorsPerRadian;
	std::uint32_t sectors;
};

/** Each point's code and horizontal range, in one loop without branches
 * (it vectorizes; the scattering into sectors cannot). `xyz` holds n
 * points, three floats each. In float, as the points are: eight lanes at a
 * time with AVX2, where double precision took four, for ranges within a
 * part in 1e7 of the double's (the points' own precision). */
template <bool Terrain>
MRPT_EVIDENTIAL_CPU_CLONES void classify(
	const float* xyz, std::size_t n, const TClassification& k, std::uint32_t* codes,
	double* ranges)
{
	constexpr auto reach = static_cast<float>(kGroundReach);
	constexpr auto perColumn = static_cast<float>(1 / kGroundColumn);
	constexpr int side = kGroundColumns;
	constexpr float kNoReturn2 = static_cast<float>(kNoReturnDistance * kNoReturnDistance);
	for (std::size_t i = 0; i < n; ++i)
	{
		const float x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
		const float dx0 = x - k.sensorX, dy0 = y - k.sensorY, dz0 = z - k.sensorZ;
		// Not finite, or at the sensor. A point so far that its square
		// overflows (1e19 m) counts as not finite.
		const float d2 = dx0 * dx0 + dy0 * dy0 + dz0 * dz0;
		const bool dropped = !(d2 >= kNoReturn2 && d2 <= FLT_MAX);
		float base = k.a * x + k.b * y + k.c;
		if constexpr (Terrain)
		{
			// The nearest column's; NaN (a dropped point) takes the first.
			const float ux = (x + reach) * perColumn, uy = (y + reach) * perColumn;
			const float fx = ux >= 0.0f ? std::min(ux, side - 1.0f) : 0.0f;
			const float fy = uy >= 0.0f ? std::min(uy, side - 1.0f) : 0.0f;
			base += k.surface[static_cast<int>(fy) * side + static_cast<int>(fx)];
		}
		const float h = z - base;
		const bool above = h > k.maxHeight, ground = !(h >= k.minHeight);
		const float dx = k.r00 * dx0 + k.r01 * dy0 + k.r02 * dz0;
		const float dy = k.r10 * dx0 + k.r11 * dy0 + k.r12 * dz0;
		// No hypot: its care for overflow costs more than the rest of the loop.
		ranges[i] = static_cast<double>(std::sqrt(dx * dx + dy * dy));
		// Nearest sector centre; the last one wraps to the first. A point
		// within 2e-6 rad of two sectors' border may go to either. The
		// position is >= 0 (to fastAtan2's error): adding a half and
		// truncating rounds it. A dropped point's NaN is never converted.
		const double position =
			(static_cast<double>(detail::fastAtan2(dy, dx)) + M_PI) * k.sectorsPerRadian + 0.5;
		auto s = static_cast<std::uint32_t>(static_cast<std::int32_t>(dropped ? 0.0 : position));
		s = s >= k.sectors ? s - k.sectors : s;
		s = ground ? (s | kGround) : s;
		s = above ? kAboveRobot : s;
		codes[i] = dropped ? kDropped : s;
	}
}
}  // namespace

TCloudCounts sortCloudIntoSectors(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::math::TPoint3D& sensor, const mrpt::poses::CPose3D& robotPose,
	const TCloudRules& rules, TCloudReturns& out, TCloudScratch& scratch)
{
	const double turn = 2 * M_PI / rules.sectorWidth;
	if (!(turn <= static_cast<double>(kMaxCloudSectors)))
		throw std::invalid_argument(
			"sectorWidth " + std::to_string(rules.sectorWidth * 180 / M_PI) +
			" degrees cuts a cloud's turn into more than " + std::to_string(kMaxCloudSectors) +
			" sectors (0.001 degree each)");
	const auto sectors = static_cast<std::size_t>(std::max(1L, std::lround(turn)));
	TCloudCounts counts;
	out.reset(sectors);

	TClassification k;
	const bool terrain = rules.groundRemoval == GroundRemoval::Terrain;
	if (rules.groundRemoval == GroundRemoval::Plane || terrain)
	{
		TGroundFit fit;
		fit.sensorZ = sensor.z;
		// Else the robot's base plane (z = 0).
		TGroundPlane base;
		if (const auto plane = fitGroundPlane(points, fit, scratch.candidate, scratch.lowest))
		{
			k.a = static_cast<float>(plane->a), k.b = static_cast<float>(plane->b);
			k.c = static_cast<float>(plane->c), counts.planeFound = true;
			base = *plane;
		}
		if (terrain)
		{
			scratch.surface.follow(points, scratch.lowest, base, sensor.x, sensor.y);
			k.surface = scratch.surface.heights();
		}
	}
	const bool removal = rules.groundRemoval != GroundRemoval::None;
	k.minHeight = removal ? static_cast<float>(rules.minObstacleHeight) : -HUGE_VALF;
	k.maxHeight = removal ? static_cast<float>(rules.maxObstacleHeight) : HUGE_VALF;
	const auto& R = robotPose.getRotationMatrix();
	const auto single = [](double v) { return static_cast<float>(v); };
	k.r00 = single(R(0, 0)), k.r01 = single(R(0, 1)), k.r02 = single(R(0, 2));
	k.r10 = single(R(1, 0)), k.r11 = single(R(1, 1)), k.r12 = single(R(1, 2));
	k.sensorX = single(sensor.x), k.sensorY = single(sensor.y), k.sensorZ = single(sensor.z);
	k.sectorsPerRadian = 1.0 / (2 * M_PI / static_cast<double>(sectors));
	k.sectors = static_cast<std::uint32_t>(sectors);

	static_assert(sizeof(mrpt::math::TPoint3Df) == 3 * sizeof(float), "packed points");
	const std::size_t n = points.size();
	const bool groundIsFree = rules.groundReturns == GroundReturns::FreeSpace;
	// Block by block: the codes and ranges of a block, worked out in a loop
	// that vectorizes, are scattered into the sectors while they are still
	// in the level-1 cache.
	std::uint32_t codes[kPointBlock];
	double ranges[kPointBlock];
	forEachPointBlock(n, [&](std::size_t first, std::size_t m) {
		if (terrain)
			classify<true>(&points[first].x, m, k, codes, ranges);
		else
			classify<false>(&points[first].x, m, k, codes, ranges);
		for (std::size_t j = 0; j < m; ++j)
		{
			const std::uint32_t code = codes[j];
			const double range = ranges[j];
			if (code == kDropped)
				++counts.dropped;
			else if (code == kAboveRobot)
				++counts.aboveRobot;
			else if (code & kGround)
			{
				++counts.ground;
				double& reach = out.freeReach[code & ~kGround];
				if (groundIsFree) reach = std::max(reach, range);
			}
			else
			{
				++counts.obstacles;
				out.impacts[code].push_back(range);
			}
		}
	});
	counts.used = n - counts.dropped;
	return counts;
}

TCloudCounts sortCloudIntoSectors(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::math::TPoint3D& sensor, const mrpt::poses::CPose3D& robotPose,
	const TCloudRules& rules, TCloudReturns& out)
{
	TCloudScratch scratch;
	return sortCloudIntoSectors(points, sensor, robotPose, rules, out, scratch);
}

}  // namespace mrpt_evidential
