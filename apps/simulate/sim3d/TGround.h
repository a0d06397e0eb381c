/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The ground of a 3-D scene: a height field, and where a ray meets it. */
#pragma once

#include <mrpt/math/TPoint3D.h>

#include <optional>
#include <vector>

namespace mrpt_evidential::simulate
{
/** A gentle bump (or dip, for a negative height): a raised cosine of the
 * given height at (x, y), falling to zero at `radius` from it. */
struct TBump
{
	double x, y, height, radius;
};

/** The ground, z = height(x, y), metres: flat at z = 0 for x <= rampStartX,
 * a ramp rising rampSlope metres a metre (tan of its angle; negative falls)
 * along x up to rampEndX, flat beyond at the ramp's top; plus the bumps,
 * summed. The ramp runs along x only, across the whole scene. */
struct TGround
{
	double rampStartX = 0, rampEndX = 0, rampSlope = 0;
	std::vector<TBump> bumps;

	double height(double x, double y) const;
	/** A bound on the steepness of the ground, |grad height|, anywhere:
	 * the ray marcher's steps rely on it. */
	double maxSlope() const;
	/** Bounds on height() over the whole plane. */
	double lowest() const;
	double highest() const;

	/** The distance t in [0, tMax] along the ray origin + t dir (dir a unit
	 * vector) at which it first meets the ground, 0 if the origin is under
	 * it; nullopt if it stays above up to tMax. Accurate to 1e-6 m; a bump
	 * the ray crosses in and out within kMinStep may be missed. */
	std::optional<double> rayHit(
		const mrpt::math::TPoint3D& origin, const mrpt::math::TVector3D& dir,
		double tMax) const;

	/** The shortest step of the ray marcher, metres. */
	static constexpr double kMinStep = 0.01;
};

}  // namespace mrpt_evidential::simulate
