/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scene "people": the room with people walking, a door, a box and a
 * cart, each moving at known times. */
#pragma once

#include "CRoomScene.h"

namespace mrpt_evidential::simulate
{
/** The room of CRoomScene with four people (discs walking piecewise
 * straight paths: two cross, one stops and walks on, one goes out through
 * the door), the door opening at kDoorOpensAt, a box pushed once and a
 * parked cart rolled out through the door. Paths and times are in
 * CPeopleScene.cpp and rawlogs/README.md. Nothing comes within 0.45 m of
 * the robot's centre. */
class CPeopleScene : public CRoomScene
{
   public:
	static constexpr double kDoorOpensAt = 15.0;
	static constexpr double kBoxSize = 0.5;
	static constexpr double kCartSizeX = 1.5, kCartSizeY = 0.8;

	std::vector<TShape> movingAt(double t) const override;
};

}  // namespace mrpt_evidential::simulate
