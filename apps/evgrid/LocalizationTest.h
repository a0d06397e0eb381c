/* evgrid compare: can a map tell a held-out scan's pose from the poses
 * around it? */
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "CSideBySideMaps.h"

namespace mrpt::maps
{
class CMetricMap;
}

namespace evgrid
{
/** The perturbations tried around each reference pose p = (x, y, phi):
 * robot poses (x + dx, y + dy, phi + dphi), composed in the world frame;
 * dx, dy = i kStepXY for i in [-kStepsXY, kStepsXY], dphi = k kStepPhiDeg
 * degrees for k in [-kStepsPhi, kStepsPhi]. A scan's z, pitch and roll stay
 * as they are. */
struct TPerturbations
{
	static constexpr double kStepXY = 0.05;
	static constexpr int kStepsXY = 6;
	static constexpr double kStepPhiDeg = 1.0;
	static constexpr int kStepsPhi = 5;
	/** A hit: the best perturbation within these of p (plus kEpsilon). */
	static constexpr double kHitDistance = 0.05, kHitAngleDeg = 1.0;
	static constexpr double kEpsilon = 1e-9;
};

/** The best-scoring perturbation of one scan. */
struct TBestPerturbation
{
	double dx = 0, dy = 0, dphiDeg = 0;
	double logLikelihood = 0;
	bool isHit() const;
	double distance() const;
};

/** A map's score over the held-out scans. */
struct TLocalizationScore
{
	std::size_t scans = 0, hits = 0;
	/** Sums over the scans of the best perturbation's distance to p (m) and
	 * |dphi| (degrees). */
	double distanceSum = 0, angleSumDeg = 0;
};

/** The perturbation at which `map` gives the held-out scan the largest
 * log-likelihood (computeObservationLikelihood()). They are tried in a fixed
 * order, dx ascending, then dy, then dphi (the innermost), and the first
 * maximum wins ties; a NaN counts as -infinity. */
TBestPerturbation bestPerturbation(
	const mrpt::maps::CMetricMap& map, const THeldOutScan& scan);

/** bestPerturbation() of each scan, tallied; `afterScan` is called after
 * each one. */
TLocalizationScore scoreLocalization(
	const mrpt::maps::CMetricMap& map, const std::vector<THeldOutScan>& scans,
	const std::function<void()>& afterScan);

}  // namespace evgrid
