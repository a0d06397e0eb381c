/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The room of evgrid-simulate's scenes, and the scenes that only change its
 * door and a box. */
#pragma once

#include "CScene.h"

namespace mrpt_evidential::simulate
{
/** A 10 x 8 m room, x in [-5, 5], y in [-4, 4], walls 0.15 m thick, with a
 * shelf, a pillar, a desk and a bin; a 1 m door in its east wall (x = 5,
 * y in [-0.5, 0.5]) that swings into a 2.35 m wide corridor with a cabinet.
 * The robot drives counter-clockwise around an ellipse centred on (-0.2, 0)
 * with semi-axes 3.4 m and 2.4 m, one lap per kLapPeriod, heading along the
 * ellipse's tangent. What moves is the subclasses'. */
class CRoomScene : public CScene
{
   public:
	static constexpr double kLapPeriod = 40.0;
	/** The door's panel, hinged at (5.1, 0.5): in the wall gap, or swung 90
	 * degrees into the corridor along its wall. */
	static constexpr TRect kDoorClosed = {5.03, -0.50, 5.12, 0.50};
	static constexpr TRect kDoorOpen = {5.12, 0.50, 6.10, 0.59};

	TRect extent() const override;
	std::vector<TShape> staticShapes() const override;
	mrpt::poses::CPose2D robotPoseAt(double t) const override;
	double lapPeriod() const override { return kLapPeriod; }
};

/** The scene "room_door_box": the door opens at kDoorOpensAt, and a
 * kBoxSize box is pushed from (kBoxStartX, kBoxStartY) to (kBoxEndX,
 * kBoxEndY) between kBoxMoveStart and kBoxMoveEnd. */
class CRoomDoorBoxScene : public CRoomScene
{
   public:
	static constexpr double kDoorOpensAt = 20.0;
	static constexpr double kBoxMoveStart = 25.0, kBoxMoveEnd = 30.0;
	static constexpr double kBoxSize = 0.5;
	static constexpr double kBoxStartX = -0.8, kBoxStartY = -0.6;
	static constexpr double kBoxEndX = 0.9, kBoxEndY = 0.7;

	std::vector<TShape> movingAt(double t) const override;
};

/** The scene "static": the room with its door open and nothing moving, for
 * counting the changes a map reports where there are none. */
class CStaticRoomScene : public CRoomScene
{
   public:
	std::vector<TShape> staticShapes() const override;
	std::vector<TShape> movingAt(double) const override { return {}; }
};

/** The scenes "room_before" and "room_after": the room as it stands before
 * and after room_door_box's changes, nothing moving in either: the door shut
 * and the box at its start, or the door open and the box at its end. Two
 * runs of a place that changed in between, for evgrid diff and merge. */
class CChangedRoomScene : public CRoomScene
{
   public:
	explicit CChangedRoomScene(bool after) : m_after(after) {}
	std::vector<TShape> staticShapes() const override;
	std::vector<TShape> movingAt(double) const override { return {}; }

   private:
	bool m_after;
};

}  // namespace mrpt_evidential::simulate
