/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The pose error a SLAM front end leaves. */
#include "CSlamError.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>

namespace mrpt_evidential::simulate
{
// Another stream than the global generator's for the same seed.
CSlamError::CSlamError(unsigned int seed) : m_rng(seed ^ 0x51a3u) {}

double CSlamError::step(double error, double stepStd, double bound)
{
	return std::clamp(
		(1.0 - kPull) * error + stepStd * m_rng.drawGaussian1D_normalized(),
		-bound, bound);
}

mrpt::poses::CPose2D CSlamError::estimate(const mrpt::poses::CPose2D& truth)
{
	m_x = step(m_x, kShiftStep, kMaxShift);
	m_y = step(m_y, kShiftStep, kMaxShift);
	m_phi = step(m_phi, kTurnStep, kMaxTurn);
	return {
		truth.x() + m_x, truth.y() + m_y,
		mrpt::math::wrapToPi(truth.phi() + m_phi)};
}

}  // namespace mrpt_evidential::simulate
