/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The room of evgrid-simulate's scenes. */
#include "CRoomScene.h"

#include <cmath>

namespace mrpt_evidential::simulate
{
namespace
{
// The corridor beyond the door is x in [5.15, 7.5].
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
}  // namespace

TRect CRoomScene::extent() const { return {-5.5, -4.5, 8.0, 4.5}; }

std::vector<TShape> CRoomScene::staticShapes() const
{
	std::vector<TShape> shapes(std::begin(kWalls), std::end(kWalls));
	shapes.insert(shapes.end(), std::begin(kFurniture), std::end(kFurniture));
	return shapes;
}

mrpt::poses::CPose2D CRoomScene::robotPoseAt(double t) const
{
	constexpr double cx = -0.2, a = 3.4, b = 2.4;
	const double theta = 2.0 * M_PI * t / kLapPeriod;
	// Heading along the derivative of the ellipse, counter-clockwise.
	return {
		cx + a * std::cos(theta), b * std::sin(theta),
		std::atan2(b * std::cos(theta), -a * std::sin(theta))};
}

std::vector<TShape> CRoomDoorBoxScene::movingAt(double t) const
{
	return {
		t < kDoorOpensAt ? kDoorClosed : kDoorOpen,
		rectOnPath(
			{{kBoxMoveStart, kBoxStartX, kBoxStartY},
			 {kBoxMoveEnd, kBoxEndX, kBoxEndY}},
			t, kBoxSize, kBoxSize)};
}

std::vector<TShape> CChangedRoomScene::staticShapes() const
{
	using S = CRoomDoorBoxScene;
	std::vector<TShape> shapes = CRoomScene::staticShapes();
	shapes.push_back(m_after ? kDoorOpen : kDoorClosed);
	const double x = m_after ? S::kBoxEndX : S::kBoxStartX, y = m_after ? S::kBoxEndY : S::kBoxStartY;
	shapes.push_back(TRect{
		x - 0.5 * S::kBoxSize, y - 0.5 * S::kBoxSize, x + 0.5 * S::kBoxSize, y + 0.5 * S::kBoxSize});
	return shapes;
}

std::vector<TShape> CStaticRoomScene::staticShapes() const
{
	std::vector<TShape> shapes = CRoomScene::staticShapes();
	shapes.push_back(kDoorOpen);
	return shapes;
}

}  // namespace mrpt_evidential::simulate
