/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What the simulated robots' odometry reports. */
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

namespace mrpt_evidential::simulate
{
/** Odometry errors: a random error per increment, and a 2 % over-estimate
 * of rotations (a wheel base slightly off) that makes the path drift. */
constexpr double kOdoScaleStd = 0.02, kOdoLateralStd = 0.002;
constexpr double kOdoRotationBias = 1.02, kOdoRotationStd = 0.2 * M_PI / 180;

/** A step's action: the true increment (in the robot's frame) as the
 * odometry measured it, with three draws from rng, stored with MRPT's
 * Gaussian motion model (CActionRobotMovement2D, default parameters). */
mrpt::obs::CActionCollection odometryAction(
	const mrpt::poses::CPose2D& increment, mrpt::Clock::time_point stamp,
	mrpt::random::CRandomGenerator& rng);

}  // namespace mrpt_evidential::simulate
