/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * A 3-D scene and the first thing a ray meets in it. */
#include "TScene3D.h"

namespace mrpt_evidential::simulate
{
namespace
{
EPointLabel labelOf(const TBody& body)
{
	if (body.moving) return EPointLabel::Moving;
	switch (body.kind)
	{
		case EBodyKind::Low:
			return EPointLabel::Low;
		case EBodyKind::Overhang:
			return EPointLabel::Overhang;
		case EBodyKind::Obstacle:
			break;
	}
	return EPointLabel::Obstacle;
}
}  // namespace

std::vector<TBody> TScene3D::bodiesAt(double t) const
{
	std::vector<TBody> bodies = staticBodies;
	for (const TMovingBody& m : moving)
		bodies.push_back(m.at(t, ground));
	return bodies;
}

std::optional<TRayHit> castRay(
	const TGround& ground, const std::vector<TBody>& bodies,
	const mrpt::math::TPoint3D& origin, const mrpt::math::TVector3D& dir,
	double maxRange)
{
	std::optional<TRayHit> nearest;
	double limit = maxRange;
	for (const TBody& body : bodies)
		if (const auto t = rayHit(body, origin, dir, limit))
		{
			nearest = TRayHit{*t, labelOf(body)};
			limit = *t;
		}
	// The ground is marched only up to the nearest body: the costly part
	// of a ray stays short where bodies are close.
	if (const auto t = ground.rayHit(origin, dir, limit);
		t && (!nearest || *t < nearest->range))
		nearest = TRayHit{*t, EPointLabel::Ground};
	return nearest;
}

}  // namespace mrpt_evidential::simulate
