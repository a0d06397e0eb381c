/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The solid things of a 3-D scene: vertical prisms over a 2-D shape. */
#pragma once

#include <mrpt/math/TPoint3D.h>

#include <cstdint>
#include <optional>

#include "Shapes.h"
#include "TGround.h"

namespace mrpt_evidential::simulate
{
/** What a body is to a vehicle, as the scene's author says: the ground
 * truth of the points it returns. (The footprint grid judges by heights,
 * not by this.) */
enum class EBodyKind : uint8_t
{
	/** In the way: walls, cars, poles, people. */
	Obstacle,
	/** Low enough to drive over or to stop at: a kerb. */
	Low,
	/** Above the vehicle: a barrier's beam, branches. */
	Overhang
};

/** A vertical prism: a 2-D shape of Shapes.h (an axis-aligned rectangle or
 * a disc) between two world heights zBottom < zTop, metres. A body that
 * stands on sloping ground reaches into it (bottom below the ground), so
 * that no gap shows under it. */
struct TBody
{
	TShape shape;
	double zBottom, zTop;
	EBodyKind kind;
	/** Whether it is one of the scene's moving things at some time. */
	bool moving = false;
};

/** The distance t in [0, tMax] along the ray origin + t dir (dir a unit
 * vector) at which it enters the body, 0 if the origin is inside; nullopt
 * if it misses it within tMax. */
std::optional<double> rayHit(
	const TBody& body, const mrpt::math::TPoint3D& origin,
	const mrpt::math::TVector3D& dir, double tMax);

/** A thing that moves along a path: its footprint (centred on (0, 0)),
 * moved to where the path is at each time, standing on the ground under
 * its centre from `bottom` to `top` above it. */
struct TMovingBody
{
	TShape footprint;
	double bottom, top;
	TPath path;
	EBodyKind kind = EBodyKind::Obstacle;

	/** The body at time t. */
	TBody at(double t, const TGround& ground) const;
};

}  // namespace mrpt_evidential::simulate
