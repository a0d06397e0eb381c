/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Rays against the bodies of a 3-D scene, and moving bodies. */
#include "TBody.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mrpt_evidential::simulate
{
namespace
{
// A direction component under this is taken as parallel to the slab.
constexpr double kParallel = 1e-12;

/** Narrows [tNear, tFar] to where o + t d lies in [lo, hi]; false once the
 * interval is empty. */
bool clipSlab(
	double lo, double hi, double o, double d, double& tNear, double& tFar)
{
	if (std::abs(d) < kParallel) return o >= lo && o <= hi;
	double t1 = (lo - o) / d, t2 = (hi - o) / d;
	if (t1 > t2) std::swap(t1, t2);
	tNear = std::max(tNear, t1);
	tFar = std::min(tFar, t2);
	return tNear <= tFar;
}

/** Narrows [tNear, tFar] to where the ray's x, y lie in the disc. */
bool clipDisc(
	const TDisc& disc, const mrpt::math::TPoint3D& o,
	const mrpt::math::TVector3D& d, double& tNear, double& tFar)
{
	const double ox = o.x - disc.x, oy = o.y - disc.y;
	const double a = d.x * d.x + d.y * d.y;
	const double c = ox * ox + oy * oy - disc.radius * disc.radius;
	// A vertical ray is inside the disc all along, or never.
	if (a < kParallel) return c <= 0;
	const double b = ox * d.x + oy * d.y;  // half the usual b
	const double discriminant = b * b - a * c;
	if (discriminant < 0) return false;
	const double root = std::sqrt(discriminant);
	tNear = std::max(tNear, (-b - root) / a);
	tFar = std::min(tFar, (-b + root) / a);
	return tNear <= tFar;
}

TShape centredAt(const TShape& shape, double x, double y)
{
	if (const TDisc* d = std::get_if<TDisc>(&shape))
		return TDisc{d->x + x, d->y + y, d->radius};
	const TRect& r = std::get<TRect>(shape);
	return TRect{r.xMin + x, r.yMin + y, r.xMax + x, r.yMax + y};
}
}  // namespace

std::optional<double> rayHit(
	const TBody& body, const mrpt::math::TPoint3D& origin,
	const mrpt::math::TVector3D& dir, double tMax)
{
	double tNear = 0, tFar = tMax;
	if (!clipSlab(body.zBottom, body.zTop, origin.z, dir.z, tNear, tFar))
		return std::nullopt;
	bool inside;
	if (const TDisc* disc = std::get_if<TDisc>(&body.shape))
		inside = clipDisc(*disc, origin, dir, tNear, tFar);
	else
	{
		const TRect& r = std::get<TRect>(body.shape);
		inside = clipSlab(r.xMin, r.xMax, origin.x, dir.x, tNear, tFar) &&
			clipSlab(r.yMin, r.yMax, origin.y, dir.y, tNear, tFar);
	}
	if (!inside) return std::nullopt;
	return tNear;
}

TBody TMovingBody::at(double t, const TGround& ground) const
{
	double x, y;
	pointOnPath(path, t, x, y);
	const double z = ground.height(x, y);
	return {centredAt(footprint, x, y), z + bottom, z + top, kind, true};
}

}  // namespace mrpt_evidential::simulate
