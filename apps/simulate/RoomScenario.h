/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The simulated world of evgrid-simulate: a room whose door opens and whose
 * box is pushed across the floor while a robot drives loops in it. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

namespace mrpt_evidential::simulate
{
/** The scenario "room_door_box", all in metres, seconds and radians:
 *
 * - a 10 x 8 m room, x in [-5, 5], y in [-4, 4], walls 0.15 m thick, with a
 *   shelf, a pillar, a desk and a bin that never move;
 * - a 1 m door in its east wall (x = 5, y in [-0.5, 0.5]) that swings open
 *   into a 2.35 m wide corridor at kDoorOpensAt;
 * - a kBoxSize box pushed from (kBoxStartX, kBoxStartY) to (kBoxEndX,
 *   kBoxEndY) between kBoxMoveStart and kBoxMoveEnd;
 * - a robot driving counter-clockwise around an ellipse centred on
 *   (-0.2, 0) with semi-axes 3.4 m and 2.4 m, one lap per kLapPeriod,
 *   heading along the ellipse's tangent.
 *
 * Times are counted from the start of the run; the world is drawn in cells
 * of kResolution. */
class RoomScenario
{
   public:
	static constexpr double kResolution = 0.02;
	static constexpr double kLapPeriod = 40.0;
	static constexpr double kDoorOpensAt = 20.0;
	static constexpr double kBoxMoveStart = 25.0, kBoxMoveEnd = 30.0;
	static constexpr double kBoxSize = 0.5;
	static constexpr double kBoxStartX = -0.8, kBoxStartY = -0.6;
	static constexpr double kBoxEndX = 0.9, kBoxEndY = 0.7;

	RoomScenario();

	/** The world at time t: obstacles are occupied cells, everything else
	 * is free (no cell is unknown: the laser simulator reports a ray that
	 * reaches an unknown cell as invalid). */
	const mrpt::maps::COccupancyGridMap2D& worldAt(double t);

	/** The robot's true pose at time t. */
	static mrpt::poses::CPose2D robotPoseAt(double t);

	/** Centre of the box at time t. */
	static void boxCentreAt(double t, double& x, double& y);

   private:
	/** Walls and furniture: what never changes. */
	mrpt::maps::COccupancyGridMap2D m_static;
	/** m_static plus the door and the box at the time asked last. */
	mrpt::maps::COccupancyGridMap2D m_world;
};

}  // namespace mrpt_evidential::simulate
