/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The world a scene shows MRPT's laser simulator. */
#include "CScene.h"

namespace mrpt_evidential::simulate
{
namespace
{
void drawObstacles(
	mrpt::maps::COccupancyGridMap2D& grid, const std::vector<TShape>& shapes)
{
	const TGridGeometry geometry = geometryOf(grid);
	for (const TShape& shape : shapes)
		forEachCell(shape, geometry, ECoverage::Centre, [&](int cx, int cy) {
			grid.setCell(cx, cy, 0.0f);
		});
}
}  // namespace

TGridGeometry geometryOf(const mrpt::maps::COccupancyGridMap2D& grid)
{
	return {
		grid.getXMin(), grid.getYMin(), grid.getResolution(),
		static_cast<int>(grid.getSizeX()), static_cast<int>(grid.getSizeY())};
}

const mrpt::maps::COccupancyGridMap2D& CScene::worldAt(double t)
{
	if (!m_staticDrawn)
	{
		const TRect e = extent();
		m_static.setSize(
			static_cast<float>(e.xMin), static_cast<float>(e.xMax),
			static_cast<float>(e.yMin), static_cast<float>(e.yMax),
			static_cast<float>(kWorldResolution),
			1.0f /* MRPT's cells hold the probability of being free */);
		drawObstacles(m_static, staticShapes());
		m_staticDrawn = true;
	}
	m_world = m_static;
	drawObstacles(m_world, movingAt(t));
	return m_world;
}

}  // namespace mrpt_evidential::simulate
