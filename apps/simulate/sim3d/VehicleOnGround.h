/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * How a vehicle stands on uneven ground: its 3-D pose from its 2-D one. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include "TGround.h"

namespace mrpt_evidential::simulate
{
/** Where the wheels touch the ground, metres: at +-wheelBase / 2 along the
 * heading and +-track / 2 across it, about the vehicle's origin. */
struct TWheelBase
{
	double wheelBase = 2.7, track = 1.6;
};

/** The vehicle's pose in 3-D at the 2-D pose `pose` (x, y, heading): its
 * origin on the plane of its four wheels' contact points, at their mean
 * height; x along the heading tilted by the mean front-to-rear height
 * difference (pitch), y tilted by the left-to-right one (roll), z up from
 * that plane. On a plane of slope s along the heading it pitches nose up
 * by atan(s) exactly; over a kink or a bump it tilts by the mean of what
 * its wheels stand on, not by the ground under its centre. */
mrpt::poses::CPose3D vehicleOnGround(
	const TGround& ground, const mrpt::poses::CPose2D& pose,
	const TWheelBase& wheels = {});

}  // namespace mrpt_evidential::simulate
