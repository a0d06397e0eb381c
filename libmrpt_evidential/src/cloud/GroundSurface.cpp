/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "cloud/GroundSurface.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mrpt_evidential
{
void CGroundSurface::follow(
	const std::vector<mrpt::math::TPoint3Df>& points, const std::vector<int>& lowest,
	const TGroundPlane& plane, double sensorX, double sensorY)
{
	constexpr int side = kGroundColumns;
	m_ground.assign(side * side, 0.0f);
	m_slack.assign(side * side, 0.0f);
	const int sx = groundColumnOf(sensorX), sy = groundColumnOf(sensorY);
	const auto ringOf = [&](int x, int y) { return std::max(std::abs(x - sx), std::abs(y - sy)); };
	const auto settle = [&](int c, float inner, float slack) {
		const int i = lowest.empty() ? -1 : lowest[static_cast<std::size_t>(c)];
		const float h = i < 0 ? HUGE_VALF
							  : static_cast<float>(plane.heightOf(points[static_cast<std::size_t>(i)]));
		const bool ground = std::abs(h - inner) <= slack + kStep;
		m_ground[c] = ground ? h : inner;
		m_slack[c] = ground ? 0.0f : std::min(slack + kStep, kMaxStray);
	};
	// The inner neighbours of (x, y) on ring r: the next column towards the
	// sensor, in the row or the column that crosses ring r there.
	const auto visit = [&](int x, int y, int r) {
		if (x < 0 || y < 0 || x >= side || y >= side) return;
		const int dx = x - sx, dy = y - sy;
		const int ix = std::abs(dx) == r ? x - (dx > 0 ? 1 : -1) : x;
		const int iy = std::abs(dy) == r ? y - (dy > 0 ? 1 : -1) : y;
		// Along the side's own axis the neighbours either side count too,
		// where they lie within ring r - 1; a corner has the diagonal one.
		const bool alongX = ix == x, alongY = iy == y;
		const int spread = alongX || alongY ? 1 : 0;
		float inner = 0.0f, slack = kMaxStray + 1.0f;
		int count = 0;
		const auto take = [&](int nx, int ny) {
			if (nx < 0 || ny < 0 || nx >= side || ny >= side || ringOf(nx, ny) != r - 1) return;
			const int n = ny * side + nx;
			if (m_slack[n] < slack)
				slack = m_slack[n], inner = m_ground[n], count = 1;
			else if (m_slack[n] == slack)
				inner += m_ground[n], ++count;
		};
		for (int k = -spread; k <= spread; ++k) take(alongX ? ix + k : ix, alongY ? iy + k : iy);
		settle(y * side + x, inner / static_cast<float>(count), slack);
	};
	// The sensor's column: the plane, give or take a step.
	settle(sy * side + sx, 0.0f, 0.0f);
	const int rings = std::max({sx, sy, side - 1 - sx, side - 1 - sy});
	for (int r = 1; r <= rings; ++r)
	{
		for (int x = sx - r; x <= sx + r; ++x) visit(x, sy - r, r), visit(x, sy + r, r);
		for (int y = sy - r + 1; y <= sy + r - 1; ++y) visit(sx - r, y, r), visit(sx + r, y, r);
	}
}

}  // namespace mrpt_evidential
