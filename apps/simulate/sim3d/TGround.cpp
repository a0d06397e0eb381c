/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The ground of a 3-D scene. */
#include "TGround.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrpt_evidential::simulate
{
namespace
{
// The bisection stops once the ground lies within this distance.
constexpr double kTolerance = 1e-6;

double rampTop(const TGround& g)
{
	return g.rampSlope * std::max(0.0, g.rampEndX - g.rampStartX);
}
}  // namespace

double TGround::height(double x, double y) const
{
	double z = rampSlope *
		std::clamp(x - rampStartX, 0.0, std::max(0.0, rampEndX - rampStartX));
	for (const TBump& b : bumps)
	{
		const double dx = x - b.x, dy = y - b.y;
		const double r2 = dx * dx + dy * dy;
		if (r2 >= b.radius * b.radius) continue;
		z += 0.5 * b.height * (1.0 + std::cos(M_PI * std::sqrt(r2) / b.radius));
	}
	return z;
}

double TGround::maxSlope() const
{
	// The steepest point of a raised cosine is half-way out: h pi / (2 R).
	// Bumps may overlap each other and the ramp, so their slopes add up.
	double slope = std::abs(rampSlope);
	for (const TBump& b : bumps)
		slope += std::abs(b.height) * M_PI / (2.0 * b.radius);
	return slope;
}

double TGround::lowest() const
{
	double z = std::min(0.0, rampTop(*this));
	for (const TBump& b : bumps)
		z += std::min(0.0, b.height);
	return z;
}

double TGround::highest() const
{
	double z = std::max(0.0, rampTop(*this));
	for (const TBump& b : bumps)
		z += std::max(0.0, b.height);
	return z;
}

std::optional<double> TGround::rayHit(
	const mrpt::math::TPoint3D& origin, const mrpt::math::TVector3D& dir,
	double tMax) const
{
	const auto above = [&](double t) {
		return origin.z + t * dir.z -
			height(origin.x + t * dir.x, origin.y + t * dir.y);
	};
	// Above the highest ground nothing is hit: start where the ray comes
	// down to it, end a step after it goes under the lowest (surely a hit,
	// whatever the rounding).
	const double top = highest(), bottom = lowest();
	double t = 0, tEnd = tMax;
	if (origin.z > top)
	{
		if (dir.z >= 0) return std::nullopt;
		t = (origin.z - top) / -dir.z;
	}
	if (dir.z < 0)
		tEnd = std::min(tEnd, (origin.z - bottom) / -dir.z + kMinStep);
	if (t > tEnd) return std::nullopt;

	// The ray's height above the ground changes by at most `rate` a metre
	// along it, so it cannot reach the ground within h / rate of a point h
	// above it.
	const double rate = maxSlope() * std::hypot(dir.x, dir.y) + std::abs(dir.z);
	double h = above(t);
	if (h <= 0) return t;
	for (;;)
	{
		const double step = rate > 0 ? std::max(h / rate, kMinStep)
									 : std::numeric_limits<double>::infinity();
		const double next = std::min(t + step, tEnd);
		const double hNext = above(next);
		if (hNext <= 0)
		{
			// Above at t, on or under at `next`: bisect.
			double lo = t, hi = next;
			while (hi - lo > kTolerance)
			{
				const double mid = 0.5 * (lo + hi);
				(above(mid) > 0 ? lo : hi) = mid;
			}
			return hi;
		}
		if (next >= tEnd) return std::nullopt;
		t = next;
		h = hNext;
	}
}

}  // namespace mrpt_evidential::simulate
