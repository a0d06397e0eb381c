/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The scene "street" of evgrid-simulate: a vehicle with a multi-layer lidar
 * drives down a street with a hill, parked cars, poles, a gantry over the
 * road, a tree, kerbs, two people and an oncoming car. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include "TScene3D.h"

namespace mrpt_evidential::simulate
{
/** The street runs along x, metres, in the world frame of the ground truth
 * (its layout is in rawlogs/README.md): house fronts at y = +-kHouseY,
 * kerbs at y = +-kKerbY (the road between them), flat ground up to
 * kRampStartX, a ramp of kRampDegrees up to kRampEndX, flat beyond. The
 * vehicle drives east along y = kLaneY at kSpeed, weaving gently, from
 * x = 0 at t = 0. Times are seconds from the first scan. */
class CStreetScene
{
   public:
	static constexpr double kRampStartX = 20, kRampEndX = 40;
	static constexpr double kRampDegrees = 5;
	static constexpr double kHouseY = 8.0, kKerbY = 4.0;
	static constexpr double kKerbHeight = 0.10;
	static constexpr double kLaneY = -2.0, kSpeed = 2.5;
	static constexpr double kWeave = 0.2, kWeavePeriod = 10;
	/** The gantry over the road: its beam's extent and heights. */
	static constexpr TRect kGantryBeam = {13.5, -4.6, 14.5, 4.6};
	static constexpr double kGantryBottom = 2.6, kGantryTop = 3.2;
	/** The lidar's mount on the vehicle: kSensorHeight above its origin
	 * (which is on the ground), level, looking ahead. */
	static constexpr double kSensorHeight = 1.8;
	/** The longest drive that stays clear of the street's east end. */
	static constexpr double kMaxDuration = 24, kDefaultDuration = 20;

	CStreetScene();

	const TScene3D& scene() const { return m_scene; }
	/** The vehicle's true 2-D pose at time t (x, y, heading). */
	static mrpt::poses::CPose2D vehiclePoseAt(double t);
	/** The lidar relative to the vehicle. */
	static mrpt::poses::CPose3D sensorMount();

   private:
	TScene3D m_scene;
};

}  // namespace mrpt_evidential::simulate
