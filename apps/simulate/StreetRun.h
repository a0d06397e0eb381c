/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * evgrid-simulate --scene street: a vehicle with a multi-layer lidar
 * driving down the street of CStreetScene. */
#pragma once

#include <cstddef>
#include <string>

#include "CStreetScene.h"

namespace mrpt_evidential::simulate
{
struct TStreetRunOptions
{
	std::string prefix;
	unsigned int seed = 1;
	double duration = CStreetScene::kDefaultDuration;
	/** Spread evenly over -15 to +15 degrees. */
	std::size_t layers = 16;
	double azimuthStepDegrees = 0.2;
};

/** Writes PREFIX.rawlog (gzip: a CActionCollection with the odometry
 * increment and a CSensoryFrame with one CObservationPointCloud labelled
 * VELODYNE, points in the sensor frame, a step), PREFIX.gt.txt,
 * PREFIX.gt3d.txt (the vehicle's true 3-D pose), PREFIX.slam.txt,
 * PREFIX.motion.gz (what moves, as for every scene) and
 * PREFIX.footprint.gz (the static footprint truth). Every noise comes from
 * the seed. Returns what they hold ("scene street, N scans, ...").
 * \throws std::runtime_error if a file cannot be written,
 * std::invalid_argument for bad lidar options. */
std::string simulateStreet(const TStreetRunOptions& options);

}  // namespace mrpt_evidential::simulate
