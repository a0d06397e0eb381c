/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The grid cells a shape covers. */
#include "Shapes.h"

#include <algorithm>
#include <cmath>

namespace mrpt_evidential::simulate
{
namespace
{
// Shapes placed on cell borders (0.05 m multiples) must not pick up the
// neighbouring cell through a rounding error.
constexpr double kBorderSlack = 1e-9;

/** The cells [first, last] along one axis that a span [lo, hi] covers. */
void cellSpan(
	double lo, double hi, double origin, double res, int size,
	ECoverage coverage, int& first, int& last)
{
	if (coverage == ECoverage::Centre)
	{
		first = static_cast<int>(std::ceil((lo - origin) / res - 0.5));
		last = static_cast<int>(std::floor((hi - origin) / res - 0.5));
	}
	else
	{
		first = static_cast<int>(
			std::floor((lo - origin) / res + kBorderSlack));
		last = static_cast<int>(
				   std::ceil((hi - origin) / res - kBorderSlack)) -
			1;
	}
	first = std::max(0, first);
	last = std::min(size - 1, last);
}

/** Whether a disc covers cell (cx, cy). */
bool discCovers(
	const TDisc& d, const TGridGeometry& g, ECoverage coverage, int cx, int cy)
{
	const double x0 = g.xMin + cx * g.resolution,
				 y0 = g.yMin + cy * g.resolution;
	double dx, dy;
	if (coverage == ECoverage::Centre)
	{
		dx = x0 + 0.5 * g.resolution - d.x;
		dy = y0 + 0.5 * g.resolution - d.y;
		return dx * dx + dy * dy <= d.radius * d.radius;
	}
	// The distance from the centre to the nearest point of the cell.
	dx = std::clamp(d.x, x0, x0 + g.resolution) - d.x;
	dy = std::clamp(d.y, y0, y0 + g.resolution) - d.y;
	return dx * dx + dy * dy < d.radius * d.radius;
}
}  // namespace

void pointOnPath(const TPath& path, double t, double& x, double& y)
{
	// The segment t falls in, the first before the path, the last after it.
	std::size_t i = 0;
	while (i + 2 < path.size() && t >= path[i + 1].t)
		++i;
	const TWaypoint& a = path[i];
	const TWaypoint& b = path[std::min(i + 1, path.size() - 1)];
	const double s =
		b.t > a.t ? std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
	x = a.x + s * (b.x - a.x);
	y = a.y + s * (b.y - a.y);
}

TRect rectOnPath(const TPath& path, double t, double sizeX, double sizeY)
{
	double x, y;
	pointOnPath(path, t, x, y);
	return {x - 0.5 * sizeX, y - 0.5 * sizeY, x + 0.5 * sizeX, y + 0.5 * sizeY};
}

TGridGeometry gridOver(const TRect& area, double resolution)
{
	return {
		area.xMin, area.yMin, resolution,
		static_cast<int>(std::lround((area.xMax - area.xMin) / resolution)),
		static_cast<int>(std::lround((area.yMax - area.yMin) / resolution))};
}

void forEachCell(
	const TShape& shape, const TGridGeometry& grid, ECoverage coverage,
	const std::function<void(int, int)>& visit)
{
	const TRect box = std::holds_alternative<TRect>(shape)
		? std::get<TRect>(shape)
		: [&] {
			  const TDisc& d = std::get<TDisc>(shape);
			  return TRect{
				  d.x - d.radius, d.y - d.radius, d.x + d.radius,
				  d.y + d.radius};
		  }();
	int cx0, cx1, cy0, cy1;
	cellSpan(
		box.xMin, box.xMax, grid.xMin, grid.resolution, grid.sizeX, coverage,
		cx0, cx1);
	cellSpan(
		box.yMin, box.yMax, grid.yMin, grid.resolution, grid.sizeY, coverage,
		cy0, cy1);
	const TDisc* disc = std::get_if<TDisc>(&shape);
	for (int cy = cy0; cy <= cy1; ++cy)
		for (int cx = cx0; cx <= cx1; ++cx)
			if (!disc || discCovers(*disc, grid, coverage, cx, cy))
				visit(cx, cy);
}

}  // namespace mrpt_evidential::simulate
