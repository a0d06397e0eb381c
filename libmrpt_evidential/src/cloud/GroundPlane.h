/* mrpt-evidential: internal: the ground under a 3-D cloud, as a plane
 * fitted to the cloud (GroundRemoval::Plane). */
#pragma once

#include <mrpt/math/TPoint3D.h>

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
	/** Under the robot the ground is within this of its base plane, metres:
	 * a car's roof or a table top cannot pass for the ground. */
	double maxOffset = 0.5;
	/** The fewest inliers for a plane, and the least share of the candidate
	 * points (those low enough to be ground) they must be. */
	std::size_t minInliers = 30;
	double minInlierShare = 0.2;
};

/** The plane most of the cloud's low points lie on (RANSAC on a sample of at
 * most a few thousand candidates, then least squares on the inliers), or
 * nothing when no plane meets `fit`'s rules. `points` are in the robot's
 * frame; the search is deterministic (fixed seed). Never throws. */
std::optional<TGroundPlane> fitGroundPlane(
	const std::vector<mrpt::math::TPoint3Df>& points, const TGroundFit& fit);

}  // namespace mrpt_evidential
