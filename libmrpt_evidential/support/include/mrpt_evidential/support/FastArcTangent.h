/* mrpt-evidential: internal: an atan2 for the loops over cells and points. */
#pragma once

#include <algorithm>
#include <cmath>

namespace mrpt_evidential::detail
{
/** atan2 to within 2e-6 rad, several times faster than std::atan2: on a
 * 20 m ray the error is 0.04 mm. Written without branches so that loops over
 * many points vectorize. In float (a cloud's points) the error is the same:
 * the polynomial's, not the type's. */
template <typename Real>
inline Real fastAtan2(Real y, Real x)
{
	const Real ax = std::abs(x), ay = std::abs(y);
	const Real hi = std::max(ax, ay), lo = std::min(ax, ay);
	const Real a = lo / (hi > Real(0) ? hi : Real(1)), s = a * a;
	// Odd minimax polynomial for atan on [0, 1].
	Real r = (((Real(-0.0117212) * s + Real(0.05265332)) * s - Real(0.11643287)) * s +
			  Real(0.19354346)) * s;
	r = ((r - Real(0.33262347)) * s + Real(0.99997726)) * a;
	// Both sides of each choice are computed first: the compiler then turns
	// the choices into selects (it does not add arithmetic to a branch).
	const Real steep = Real(M_PI_2) - r;
	r = ay > ax ? steep : r;
	const Real behind = Real(M_PI) - r;
	r = x < Real(0) ? behind : r;
	const Real negated = -r;
	return y < Real(0) ? negated : r;
}

}  // namespace mrpt_evidential::detail
