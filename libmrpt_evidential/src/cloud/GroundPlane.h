/* mrpt-evidential: internal: the ground under a 3-D cloud, as a plane
 * fitted to the cloud (GroundRemoval::Plane). */
#pragma once

#include <mrpt/math/TPoint3D.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace mrpt_evidential
{
/** The plane z = a x + b y + c, in the robot's frame. */
struct TGroundPlane
{
	double a = 0.0, b = 0.0, c = 0.0;
	/** Height of p above the plane, along z. */
	double heightOf(const mrpt::math::TPoint3Df& p) const
	{
		return static_cast<double>(p.z) -
			(a * static_cast<double>(p.x) + b * static_cast<double>(p.y) + c);
	}
};

/** What fitGroundPlane() accepts as ground. */
struct TGroundFit
{
	/** Points within this height of the plane are its inliers, metres. */
	double inlierDistance = 0.1;
	/** The ground is taken to slope less than this, radians. */
	double maxSlope = 20.0 * 3.14159265358979323846 / 180.0;
	/** Height of the sensor in the robot's frame, metres. */
	double sensorZ = 0.0;
	/** The ground under the sensor lies between these distances below it,
	 * metres: a lidar is mounted above the ground, and not higher than a
	 * truck's roof. The robot's frame need not be on the ground (MRPT's
	 * VLP-16 dataset has it at the sensor). */
	double minSensorHeight = 0.3, maxSensorHeight = 5.0;
	/** The fewest inliers for a plane, and the least share of the candidate
	 * points (those low enough to be ground) they must be: in a street the
	 * candidates hold the lower parts of walls, cars and trees too, and the
	 * ground holds 15 % of MRPT's VLP-16 scan. */
	std::size_t minInliers = 30;
	double minInlierShare = 0.1;
};

/** The plane most of the cloud's low points lie on (RANSAC on the lowest
 * candidate of each square metre around the robot, up to 200 tries and
 * fewer once the best plane holds most of them, then least squares on the
 * inliers among all candidates), or
 * nothing when no plane meets `fit`'s rules. Of two planes with as many
 * inliers the first found wins; the ground of a lidar scan holds most of
 * its points below the sensor, so a car's roof rarely competes. `points` are
 * in the robot's frame; the search is deterministic (fixed seed). Points
 * that are not finite are never ground. `candidate` and `lowest` are kept by
 * the caller, so that they are not allocated for each cloud: `candidate`
 * gets one byte a point, 1 if it may be ground (low enough for its
 * distance); `lowest` the index of each column's lowest candidate
 * (kGroundColumns^2 of them, row by row from (-kGroundReach, -kGroundReach),
 * -1 for none; empty when there are too few candidates for a plane). Never
 * throws but std::bad_alloc. */
std::optional<TGroundPlane> fitGroundPlane(
	const std::vector<mrpt::math::TPoint3Df>& points, const TGroundFit& fit,
	std::vector<std::uint8_t>& candidate, std::vector<int>& lowest);

/** The points a loop over a cloud takes at a time, when a second loop reads
 * what the first wrote per point: a block's values (a few kilobytes) are
 * then still in the level-1 cache, where a whole cloud's (hundreds of
 * kilobytes) would go through memory twice. */
constexpr std::size_t kPointBlock = 512;

/** Calls f(first, count) for a cloud of n points block by block: points
 * [first, first + count), count at most kPointBlock. */
template <typename F>
void forEachPointBlock(std::size_t n, F&& f)
{
	for (std::size_t first = 0; first < n; first += kPointBlock)
		f(first, std::min(kPointBlock, n - first));
}

/** The columns of fitGroundPlane() and CGroundSurface: 1 m square, within
 * kGroundReach metres of the robot's origin along x and y. */
constexpr double kGroundColumn = 1.0, kGroundReach = 40.0;
constexpr int kGroundColumns = static_cast<int>(2 * kGroundReach / kGroundColumn);

/** The column along one axis of a coordinate of the robot's frame, clamped
 * to the columns (the loops over every point work it out without a branch,
 * in their own precision). */
inline int groundColumnOf(double v)
{
	const double f = std::floor((v + kGroundReach) / kGroundColumn);
	return f < 0.0 ? 0 : f >= kGroundColumns ? kGroundColumns - 1 : static_cast<int>(f);
}

}  // namespace mrpt_evidential
