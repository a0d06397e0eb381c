/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * How a 3-D point cloud's ground is told from its obstacles before the cloud
 * goes into the polar SourceGrid (doc/sensor-models.md, "Point clouds"). */
#pragma once

namespace mrpt_evidential
{
/** Where the ground lies under a cloud. Heights are measured in the robot's
 * frame, from the ground to the point, along the robot's z axis. */
enum class GroundRemoval
{
	/** No ground: every point is an obstacle (the seed's hypothesis, for a
	 * cloud whose ground was removed before). */
	None,
	/** A plane fitted to each cloud, robust to obstacles; the robot's base
	 * plane (z = 0 in its frame) when no plane is found. */
	Plane,
	/** The robot's base plane, always: a fixed band of heights. */
	Height,
	/** The plane of Plane, bent to follow the terrain outwards from the
	 * sensor where the ground rises or falls away from it (a hill ahead, a
	 * crest, a ramp beside flat ground), by at most 10 degrees from one
	 * metre to the next. */
	Terrain
};

/** What a ground return (a point below minObstacleHeight) proves. */
enum class GroundReturns
{
	/** Free space up to it along its azimuth: the beam crossed it. */
	FreeSpace,
	/** Nothing. */
	Nothing
};

}  // namespace mrpt_evidential
