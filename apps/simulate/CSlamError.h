/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The pose error a SLAM front end leaves, for PREFIX.slam.txt. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

namespace mrpt_evidential::simulate
{
/** A small error that varies slowly from scan to scan, as a SLAM front end's
 * does: x, y (world frame) and phi each follow a random walk pulled back
 * towards zero (by kPull a scan: a time constant of 100 scans) and clipped to
 * kMaxShift and kMaxTurn. It draws from its own generator, so that adding it
 * changes no other noise of the run. */
class CSlamError
{
   public:
	static constexpr double kPull = 0.01;
	static constexpr double kShiftStep = 0.003, kMaxShift = 0.05;
	static constexpr double kTurnStep = 0.06 * M_PI / 180,
							kMaxTurn = 1.0 * M_PI / 180;

	explicit CSlamError(unsigned int seed);

	/** The estimate of the next scan's pose. */
	mrpt::poses::CPose2D estimate(const mrpt::poses::CPose2D& truth);

   private:
	double step(double error, double stepStd, double bound);

	mrpt::random::CRandomGenerator m_rng;
	double m_x = 0, m_y = 0, m_phi = 0;
};

}  // namespace mrpt_evidential::simulate
