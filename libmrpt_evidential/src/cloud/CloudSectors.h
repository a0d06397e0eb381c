/* mrpt-evidential: internal: a 3-D cloud's points told apart (ground,
 * obstacle, above the robot) and grouped by azimuth into the sectors of the
 * polar SourceGrid. */
#pragma once

#include <mrpt/math/TPoint3D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/cloud/GroundRemoval.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cloud/GroundSurface.h"

namespace mrpt_evidential
{
/** How a cloud is read, from the map's insertion options. */
struct TCloudRules
{
	GroundRemoval groundRemoval = GroundRemoval::Terrain;
	/** Heights above the ground, metres: points from min up to max are
	 * obstacles, lower ones ground, higher ones nothing. */
	double minObstacleHeight = 0.2, maxObstacleHeight = 2.0;
	GroundReturns groundReturns = GroundReturns::FreeSpace;
	/** Width of a sector, radians, > 0. */
	double sectorWidth = 0.5 * 3.14159265358979323846 / 180.0;
};

/** What became of a cloud's points. */
struct TCloudCounts
{
	/** Points that were finite and away from the sensor. */
	std::size_t used = 0;
	/** NaN or infinite coordinates, so far (1e19 m) that the squared
	 * distance overflows a float, or within 1 cm of the sensor (where
	 * drivers put returns they did not get). */
	std::size_t dropped = 0;
	std::size_t ground = 0, obstacles = 0, aboveRobot = 0;
	/** GroundRemoval::Plane or Terrain found a plane (else the base plane
	 * was used). */
	bool planeFound = false;
};

/** A cloud's sector width when the options say 0 (one sector per beam,
 * which a cloud does not have), radians: 0.5 degree, as a SICK's beams. */
constexpr double kDefaultCloudSectorWidth = 0.5 * 3.14159265358979323846 / 180.0;

/** Points closer than this to the sensor are no returns, metres. */
constexpr double kNoReturnDistance = 0.01;

/** The most sectors a cloud's turn is cut into: 0.001 degree each, finer
 * than any lidar's azimuths (a width that asks for more is an error, not
 * gigabytes of empty sectors). */
constexpr std::size_t kMaxCloudSectors = 360'000;

/** Storage of sortCloudIntoSectors(), kept between clouds so that it is not
 * allocated for each. */
struct TCloudScratch
{
	/** The ground plane's fit's (fitGroundPlane()): which points may be
	 * ground, each column's lowest of them. */
	std::vector<std::uint8_t> candidate;
	std::vector<int> lowest;
	/** The ground followed over the terrain (GroundRemoval::Terrain). */
	CGroundSurface surface;
};

/** Fills `out` with the cloud's returns: each obstacle point an impact of
 * the sector of its azimuth around the sensor, at its horizontal range; each
 * ground point (with GroundReturns::FreeSpace) a free reach of its sector.
 * `points` and `sensor` are in the robot's frame; heights are measured
 * there (rules.groundRemoval), azimuths and ranges in the world, after
 * `robotPose`.
 * \throws std::invalid_argument if rules.sectorWidth cuts the turn into more
 * than kMaxCloudSectors sectors; std::bad_alloc. */
TCloudCounts sortCloudIntoSectors(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::math::TPoint3D& sensor, const mrpt::poses::CPose3D& robotPose,
	const TCloudRules& rules, TCloudReturns& out, TCloudScratch& scratch);
/** The same with storage of its own. */
TCloudCounts sortCloudIntoSectors(
	const std::vector<mrpt::math::TPoint3Df>& points,
	const mrpt::math::TPoint3D& sensor, const mrpt::poses::CPose3D& robotPose,
	const TCloudRules& rules, TCloudReturns& out);

}  // namespace mrpt_evidential
