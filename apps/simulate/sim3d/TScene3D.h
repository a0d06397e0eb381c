/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * A 3-D scene: ground, bodies that stay and bodies that move, and the
 * first thing a ray meets in it. */
#pragma once

#include <mrpt/math/TPoint3D.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "Shapes.h"
#include "TBody.h"
#include "TGround.h"

namespace mrpt_evidential::simulate
{
/** A scene in metres, seconds and the world frame of the ground truth. */
struct TScene3D
{
	/** The area the footprint truth covers; bodies stay inside it. */
	TRect extent;
	TGround ground;
	std::vector<TBody> staticBodies;
	std::vector<TMovingBody> moving;

	/** staticBodies, then every moving body where it is at time t. */
	std::vector<TBody> bodiesAt(double t) const;
};

/** What a lidar point hit: the ground, a body that does not move (of the
 * body's kind), or a moving body. */
enum class EPointLabel : uint8_t
{
	Ground,
	Obstacle,
	Low,
	Overhang,
	Moving
};

struct TRayHit
{
	double range;
	EPointLabel label;
};

/** The first thing the ray origin + t dir (dir a unit vector) meets, ground
 * or body, within maxRange; nullopt if none. A ray starting inside a body
 * or under the ground hits it at range 0. */
std::optional<TRayHit> castRay(
	const TGround& ground, const std::vector<TBody>& bodies,
	const mrpt::math::TPoint3D& origin, const mrpt::math::TVector3D& dir,
	double maxRange);

}  // namespace mrpt_evidential::simulate
