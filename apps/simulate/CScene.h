/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What every simulated scene of evgrid-simulate tells: what never moves,
 * what moves and where it is at each time, and where the robot drives. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

#include "Shapes.h"

namespace mrpt_evidential::simulate
{
/** A scene, in metres, seconds counted from the first scan, and radians, in
 * the world frame of the rawlog's ground truth. */
class CScene
{
   public:
	/** The simulated world's cell size: finer than any map built from it,
	 * so that the map's cells are not the world's, and a divisor of 0.05 m,
	 * so that a shape's sides, placed on multiples of 0.05 m, fall on the
	 * world's cell borders and the world drawn is the shape itself. (With
	 * 0.02 m cells, every other side fell on cell centres and was drawn a
	 * centimetre out: beams ended in the cell beyond a face that the motion
	 * truth, made from the shapes, says the thing does not cover.) */
	static constexpr double kWorldResolution = 0.01;

	virtual ~CScene() = default;

	/** The area drawn, walls included. */
	virtual TRect extent() const = 0;
	/** Walls and furniture: what never moves. */
	virtual std::vector<TShape> staticShapes() const = 0;
	/** Where every moving thing is at time t (nothing may overlap another
	 * thing or the robot). */
	virtual std::vector<TShape> movingAt(double t) const = 0;
	/** The robot's true pose at time t. */
	virtual mrpt::poses::CPose2D robotPoseAt(double t) const = 0;
	/** How long one of the --laps takes. */
	virtual double lapPeriod() const = 0;

	/** The world at time t for MRPT's laser simulator: obstacles are
	 * occupied cells, everything else free (no cell is unknown: the
	 * simulator reports a ray reaching an unknown cell as invalid). */
	const mrpt::maps::COccupancyGridMap2D& worldAt(double t);

   private:
	/** staticShapes(), drawn on the first call to worldAt. */
	mrpt::maps::COccupancyGridMap2D m_static;
	bool m_staticDrawn = false;
	/** m_static plus the moving things at the time asked last. */
	mrpt::maps::COccupancyGridMap2D m_world;
};

/** The cells of an MRPT grid, as a geometry shapes can be drawn in. */
TGridGeometry geometryOf(const mrpt::maps::COccupancyGridMap2D& grid);

}  // namespace mrpt_evidential::simulate
