/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The simulated world of evgrid-simulate. */
#include "RoomScenario.h"

#include <algorithm>
#include <cmath>

namespace mrpt_evidential::simulate
{
namespace
{
/** An axis-aligned rectangle, metres. */
struct TRect
{
	double xMin, yMin, xMax, yMax;
};

// The room's interior is x in [-5, 5], y in [-4, 4]; the corridor beyond the
// door x in [5.15, 7.5]. Walls are 0.15 m thick.
const TRect kWalls[] = {
	{-5.15, -4.15, 7.65, -4.00},  // south, room and corridor
	{-5.15, 4.00, 7.65, 4.15},	// north, room and corridor
	{-5.15, -4.15, -5.00, 4.15},  // west
	{5.00, -4.15, 5.15, -0.50},	 // east, south of the door
	{5.00, 0.50, 5.15, 4.15},  // east, north of the door
	{7.50, -4.15, 7.65, 4.15},	// corridor's far wall
};
const TRect kFurniture[] = {
	{-5.00, -3.00, -4.60, -1.00},  // shelf against the west wall
	{-3.20, 2.60, -2.80, 3.00},	 // pillar
	{1.50, 3.30, 3.00, 4.00},  // desk against the north wall
	{-1.00, -3.60, -0.70, -3.30},  // bin
	{6.80, -1.50, 7.50, -0.80},	 // cabinet in the corridor
};
// The door panel, hinged at (5.1, 0.5): in the wall gap, or swung 90 degrees
// into the corridor along the wall.
const TRect kDoorClosed = {5.03, -0.50, 5.12, 0.50};
const TRect kDoorOpen = {5.12, 0.50, 6.10, 0.59};

/** Marks the cells of a rectangle as obstacles. */
void drawObstacle(mrpt::maps::COccupancyGridMap2D& grid, const TRect& r)
{
	// Cells whose centres lie inside the rectangle.
	const double res = grid.getResolution();
	const int cx0 = std::max(
		0, static_cast<int>(std::ceil((r.xMin - grid.getXMin()) / res - 0.5)));
	const int cy0 = std::max(
		0, static_cast<int>(std::ceil((r.yMin - grid.getYMin()) / res - 0.5)));
	const int cx1 = std::min(
		static_cast<int>(grid.getSizeX()) - 1,
		static_cast<int>(std::floor((r.xMax - grid.getXMin()) / res - 0.5)));
	const int cy1 = std::min(
		static_cast<int>(grid.getSizeY()) - 1,
		static_cast<int>(std::floor((r.yMax - grid.getYMin()) / res - 0.5)));
	for (int cy = cy0; cy <= cy1; ++cy)
		for (int cx = cx0; cx <= cx1; ++cx)
			grid.setCell(cx, cy, 0.0f);
}
}  // namespace

RoomScenario::RoomScenario()
	: m_static(-5.5, 8.0, -4.5, 4.5, static_cast<float>(kResolution))
{
	// Everything is known: free unless drawn. MRPT's cells hold the
	// probability of being free.
	m_static.fill(1.0f);
	for (const TRect& r : kWalls)
		drawObstacle(m_static, r);
	for (const TRect& r : kFurniture)
		drawObstacle(m_static, r);
}

const mrpt::maps::COccupancyGridMap2D& RoomScenario::worldAt(double t)
{
	m_world = m_static;
	drawObstacle(m_world, t < kDoorOpensAt ? kDoorClosed : kDoorOpen);
	double bx, by;
	boxCentreAt(t, bx, by);
	const double h = 0.5 * kBoxSize;
	drawObstacle(m_world, {bx - h, by - h, bx + h, by + h});
	return m_world;
}

mrpt::poses::CPose2D RoomScenario::robotPoseAt(double t)
{
	constexpr double cx = -0.2, a = 3.4, b = 2.4;
	const double theta = 2.0 * M_PI * t / kLapPeriod;
	// Heading along the derivative of the ellipse, counter-clockwise.
	return {
		cx + a * std::cos(theta), b * std::sin(theta),
		std::atan2(b * std::cos(theta), -a * std::sin(theta))};
}

void RoomScenario::boxCentreAt(double t, double& x, double& y)
{
	const double s = std::clamp(
		(t - kBoxMoveStart) / (kBoxMoveEnd - kBoxMoveStart), 0.0, 1.0);
	x = kBoxStartX + s * (kBoxEndX - kBoxStartX);
	y = kBoxStartY + s * (kBoxEndY - kBoxStartY);
}

}  // namespace mrpt_evidential::simulate
