/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * A multi-layer spinning lidar (a Velodyne VLP-16 by default) cast into a
 * 3-D scene. */
#pragma once

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>

#include <cstddef>
#include <vector>

#include "TScene3D.h"

namespace mrpt_evidential::simulate
{
/** The lidar's geometry and noise; angles in radians, ranges in metres. */
struct TLidarOptions
{
	/** One elevation a layer, from the sensor's x-y plane (up positive). */
	std::vector<double> elevations = evenLayers(16, -15.0, 15.0);
	/** Between two firings of a turn; rounded to a whole number of firings
	 * a turn by raysPerTurn(). */
	double azimuthStep = 0.2 * M_PI / 180;
	/** Returns nearer than minRange or farther than maxRange are dropped
	 * (after the noise): a ray that hits nothing within range, or something
	 * too near, gives no point. */
	double minRange = 0.5, maxRange = 100.0;
	/** Standard deviation of the Gaussian error of each range. */
	double rangeNoise = 0.02;

	/** n layers evenly spread from `lowest` to `highest` degrees (one
	 * layer: half-way); radians. \throws std::invalid_argument if n is 0. */
	static std::vector<double> evenLayers(
		std::size_t n, double lowestDegrees, double highestDegrees);
	/** Firings a turn: 360 degrees / azimuthStep, rounded. */
	std::size_t raysPerTurn() const;
	/** \throws std::invalid_argument naming the first bad field: no layer,
	 * an elevation outside [-90, 90] degrees, azimuthStep outside
	 * (0, 90] degrees, minRange < 0, maxRange <= minRange, rangeNoise < 0. */
	void validate() const;
};

/** A turn's returns: points in the sensor frame (x forward, y left, z up),
 * and what each hit, in the same order: azimuth by azimuth from 0 (ahead)
 * counter-clockwise, each azimuth's layers in the order of `elevations`.
 * Rays that gave no point leave no gap. */
struct TLidarScan
{
	mrpt::maps::CSimplePointsMap::Ptr points;
	std::vector<EPointLabel> labels;
};

/** Casts every ray of a turn into a scene frozen at the scan's time (the
 * turn takes no time: no distortion by the sensor's or the bodies'
 * motion). The range noise comes from the lidar's own generator: the same
 * seed and the same calls give the same scans. */
class CMultiLayerLidar
{
   public:
	/** \throws std::invalid_argument if the options are bad (validate()). */
	CMultiLayerLidar(const TLidarOptions& options, unsigned int seed);

	const TLidarOptions& options() const { return m_options; }

	/** The turn seen from sensorPose (in the world frame) at time t. */
	TLidarScan scan(
		const TScene3D& scene, const mrpt::poses::CPose3D& sensorPose,
		double t);

   private:
	TLidarOptions m_options;
	/** The rays' unit directions in the sensor frame, in output order. */
	std::vector<mrpt::math::TVector3D> m_directions;
	mrpt::random::CRandomGenerator m_rng;
};

}  // namespace mrpt_evidential::simulate
