/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What the simulated robots' odometry reports. */
#include "Odometry.h"

#include <mrpt/obs/CActionRobotMovement2D.h>

namespace mrpt_evidential::simulate
{
mrpt::obs::CActionCollection odometryAction(
	const mrpt::poses::CPose2D& increment, mrpt::Clock::time_point stamp,
	mrpt::random::CRandomGenerator& rng)
{
	// Braces: the three draws are made in this order.
	const mrpt::poses::CPose2D measured{
		increment.x() * (1.0 + kOdoScaleStd * rng.drawGaussian1D_normalized()),
		increment.y() + kOdoLateralStd * rng.drawGaussian1D_normalized(),
		increment.phi() * kOdoRotationBias +
			kOdoRotationStd * rng.drawGaussian1D_normalized()};
	mrpt::obs::CActionRobotMovement2D odometry;
	odometry.timestamp = stamp;
	odometry.computeFromOdometry(
		measured, mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
	mrpt::obs::CActionCollection actions;
	actions.insert(odometry);
	return actions;
}

}  // namespace mrpt_evidential::simulate
