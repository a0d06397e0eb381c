/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The 2-D footprint truth of a 3-D scene. */
#include "TFootprintGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_evidential::simulate
{
namespace
{
/** The class of the part of [bottom, top] above the ground at z = ground. */
EFootprint classOf(double bottom, double top, double ground)
{
	bottom -= ground;
	top -= ground;
	if (top <= 0) return EFootprint::Ground;
	if (bottom < TFootprintGrid::kHigh && top > TFootprintGrid::kLow)
		return EFootprint::Obstacle;
	return top <= TFootprintGrid::kLow ? EFootprint::Low
									   : EFootprint::Overhang;
}
}  // namespace

EFootprint TFootprintGrid::at(double x, double y) const
{
	const auto cx = static_cast<int>(
		std::floor((x - geometry.xMin) / geometry.resolution));
	const auto cy = static_cast<int>(
		std::floor((y - geometry.yMin) / geometry.resolution));
	if (cx < 0 || cy < 0 || cx >= geometry.sizeX || cy >= geometry.sizeY)
		throw std::out_of_range("footprint: point outside the grid");
	return cells[static_cast<std::size_t>(cx + geometry.sizeX * cy)];
}

TFootprintGrid footprintOf(
	const TGround& ground, const std::vector<TBody>& bodies,
	const TGridGeometry& geometry)
{
	if (geometry.sizeX <= 0 || geometry.sizeY <= 0 ||
		!(geometry.resolution > 0))
		throw std::invalid_argument("footprint: empty grid");
	TFootprintGrid grid{
		geometry,
		std::vector<EFootprint>(
			static_cast<std::size_t>(geometry.sizeX) *
				static_cast<std::size_t>(geometry.sizeY),
			EFootprint::Ground)};
	const double res = geometry.resolution;
	for (const TBody& body : bodies)
		forEachCell(
			body.shape, geometry, ECoverage::Overlap, [&](int cx, int cy) {
				const double g = ground.height(
					geometry.xMin + (cx + 0.5) * res,
					geometry.yMin + (cy + 0.5) * res);
				EFootprint& cell = grid.cells[static_cast<std::size_t>(
					cx + geometry.sizeX * cy)];
				cell = std::max(cell, classOf(body.zBottom, body.zTop, g));
			});
	return grid;
}

}  // namespace mrpt_evidential::simulate
