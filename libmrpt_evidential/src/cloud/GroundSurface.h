/* mrpt-evidential: internal: the ground under a 3-D cloud followed outwards
 * from the sensor where it bends away from the fitted plane
 * (GroundRemoval::Terrain). */
#pragma once

#include <mrpt/math/TPoint3D.h>

#include <vector>

#include "cloud/GroundPlane.h"

namespace mrpt_evidential
{
/** The ground's height above a cloud's plane in each of the columns of
 * fitGroundPlane() (a point beyond them takes its nearest column's). */
class CGroundSurface
{
   public:
	/** The most the ground may rise or fall from one column to the next
	 * (10 degrees over a diagonal step), and the slack it gains across
	 * columns that show nothing (the blind ring around a lidar, where the
	 * plane may be a little off), metres. A larger slack takes the low
	 * obstacles around the vehicle for ground (MRPT's VLP-16 scan: its
	 * hedge, with 1 m). */
	static constexpr float kStep = 0.25f, kMaxStray = 0.25f;

	/** Follows the ground from the sensor's column (at `sensorX`, `sensorY`
	 * in the robot's frame) outwards, ring by ring. A column's lowest
	 * candidate (`lowest`, from fitGroundPlane(); empty: none), as high
	 * above `plane` as its inner neighbours' ground give or take kStep and
	 * the slack of the rings they crossed without one, is its ground; else
	 * (an obstacle whose foot is hidden, a drop, no candidate) the inner
	 * neighbours' ground carries on. Never throws but std::bad_alloc. */
	void follow(
		const std::vector<mrpt::math::TPoint3Df>& points, const std::vector<int>& lowest,
		const TGroundPlane& plane, double sensorX, double sensorY);
	/** kGroundColumns^2 heights above the plane, row by row from the column
	 * at (-kGroundReach, -kGroundReach). */
	const float* heights() const { return m_ground.data(); }

   private:
	std::vector<float> m_ground, m_slack;
};

}  // namespace mrpt_evidential
