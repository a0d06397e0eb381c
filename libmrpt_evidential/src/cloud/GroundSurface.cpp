/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "cloud/GroundSurface.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mrpt_evidential
{
namespace
{
/** The inner neighbours' ground of one column: the lowest slack among them,
 * and the mean ground of those that have it. Folded in without a branch:
 * which neighbour has the least slack follows no pattern. */
struct TInner
{
	float ground = 0.0f, slack = CGroundSurface::kMaxStray + 1.0f;
	int count = 0;
	void take(float g, float s, bool valid)
	{
		const bool less = valid && s < slack, same = valid && s == slack;
		ground = less ? g : same ? ground + g : ground;
		count = less ? 1 : same ? count + 1 : count;
		slack = less ? s : slack;
	}
};
}  // namespace

void CGroundSurface::follow(
	const std::vector<mrpt::math::TPoint3Df>& points, const std::vector<int>& lowest,
	const TGroundPlane& plane, double sensorX, double sensorY)
{
	constexpr int side = kGroundColumns;
	m_ground.assign(side * side, 0.0f);
	m_slack.assign(side * side, 0.0f);
	float* ground = m_ground.data();
	float* slackOf = m_slack.data();
	const int sx = groundColumnOf(sensorX), sy = groundColumnOf(sensorY);
	const auto settle = [&](int c, const TInner& inner) {
		const int i = lowest.empty() ? -1 : lowest[static_cast<std::size_t>(c)];
		const float h = i < 0 ? HUGE_VALF
							  : static_cast<float>(plane.heightOf(points[static_cast<std::size_t>(i)]));
		const float g = inner.ground / static_cast<float>(inner.count);
		const bool isGround = std::abs(h - g) <= inner.slack + kStep;
		ground[c] = isGround ? h : g;
		slackOf[c] = isGround ? 0.0f : std::min(inner.slack + kStep, kMaxStray);
	};
	// One side of ring r: the columns at `fixed` across the side's axis, from
	// `first` to `last` along it (clipped to the grid); `at(along, across)`
	// is a column's index. Their inner neighbours lie one step towards the
	// sensor across the axis (`inward`): the one straight in, and those
	// either side of it that lie within ring r - 1 (nearer than r to the
	// sensor's `centre` along the axis); a corner of the ring has only the
	// diagonal one.
	const auto ringSide = [&](int fixed, int inward, int centre, int r, int first, int last,
							  auto at) {
		if (fixed < 0 || fixed >= side) return;
		for (int a = std::max(first, 0), end = std::min(last, side - 1); a <= end; ++a)
		{
			TInner inner;
			const int d = a - centre;
			if (d == -r || d == r)
			{
				const int n = at(a - (d > 0 ? 1 : -1), fixed + inward);
				inner.take(ground[n], slackOf[n], true);
			}
			else
				for (int k = -1; k <= 1; ++k)
				{
					const int b = a + k;
					const bool valid = b >= 0 && b < side && std::abs(b - centre) < r;
					const int n = at(valid ? b : a, fixed + inward);
					inner.take(ground[n], slackOf[n], valid);
				}
			settle(at(a, fixed), inner);
		}
	};
	const auto alongX = [](int x, int y) { return y * side + x; };
	const auto alongY = [](int y, int x) { return y * side + x; };
	// The sensor's column: the plane, give or take a step.
	TInner onPlane;
	onPlane.take(0.0f, 0.0f, true);
	settle(sy * side + sx, onPlane);
	// Ring by ring outwards: the rows below and above the sensor with the
	// ring's corners, then the columns left and right of it.
	const int rings = std::max({sx, sy, side - 1 - sx, side - 1 - sy});
	for (int r = 1; r <= rings; ++r)
	{
		ringSide(sy - r, 1, sx, r, sx - r, sx + r, alongX);
		ringSide(sy + r, -1, sx, r, sx - r, sx + r, alongX);
		ringSide(sx - r, 1, sy, r, sy - r + 1, sy + r - 1, alongY);
		ringSide(sx + r, -1, sy, r, sy - r + 1, sy + r - 1, alongY);
	}
}

}  // namespace mrpt_evidential
