/* evgrid compare: can a map tell a held-out scan's pose from the poses
 * around it? */

#include "LocalizationTest.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/maps/CMetricMap.h>

#include <cmath>
#include <limits>

using mrpt::poses::CPose3D;
using P = evgrid::TPerturbations;

namespace evgrid
{
bool TBestPerturbation::isHit() const
{
	return distance() <= P::kHitDistance + P::kEpsilon &&
		std::abs(dphiDeg) <= P::kHitAngleDeg + P::kEpsilon;
}

double TBestPerturbation::distance() const { return std::hypot(dx, dy); }

TBestPerturbation bestPerturbation(
	const mrpt::maps::CMetricMap& map, const THeldOutScan& held)
{
	const CPose3D& p = held.pose;
	TBestPerturbation best;
	best.logLikelihood = -std::numeric_limits<double>::infinity();
	bool first = true;
	// Steps are counted in integers and scaled, so that every run tries the
	// very same poses.
	for (int i = -P::kStepsXY; i <= P::kStepsXY; ++i)
		for (int j = -P::kStepsXY; j <= P::kStepsXY; ++j)
			for (int k = -P::kStepsPhi; k <= P::kStepsPhi; ++k)
			{
				const double dx = i * P::kStepXY, dy = j * P::kStepXY;
				const double dphiDeg = k * P::kStepPhiDeg;
				const CPose3D pose(
					p.x() + dx, p.y() + dy, p.z(),
					p.yaw() + mrpt::DEG2RAD(dphiDeg), p.pitch(), p.roll());
				double score = map.computeObservationLikelihood(held.scan, pose);
				if (std::isnan(score))
					score = -std::numeric_limits<double>::infinity();
				if (first || score > best.logLikelihood)
					best = {dx, dy, dphiDeg, score};
				first = false;
			}
	return best;
}

TLocalizationScore scoreLocalization(
	const mrpt::maps::CMetricMap& map, const std::vector<THeldOutScan>& scans,
	const std::function<void()>& afterScan)
{
	TLocalizationScore score;
	for (const THeldOutScan& held : scans)
	{
		const TBestPerturbation b = bestPerturbation(map, held);
		++score.scans;
		if (b.isHit()) ++score.hits;
		score.distanceSum += b.distance();
		score.angleSumDeg += std::abs(b.dphiDeg);
		afterScan();
	}
	return score;
}

}  // namespace evgrid
