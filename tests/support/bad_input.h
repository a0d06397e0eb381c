/* What the bad-input tests (doc/reliability.md) share across the suites of
 * the layers they test: the map they start from, the way they take scans,
 * their usual scan and the extreme values they feed in. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <limits>

#include "scans.h"

namespace mrpt_evidential::test
{
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kDeg = M_PI / 180.0;

/** 10 m by 10 m around the origin at 0.1 m: 100 x 100 cells, default
 * options. */
inline CEvidentialGridMap2D smallMap() { return CEvidentialGridMap2D(-5, 5, -5, 5, 0.1); }

/** How these tests take scans: aperture pi, maxRange 30 m, time stamp 0 s
 * unless a test sets another. */
inline const ScanSetup kBadInputSetup = ScanSetup().maxRange(30.0).at(0.0);

/** Their usual scan: 181 beams over 180 degrees, all returning at `range`,
 * taken at `time`. */
inline mrpt::obs::CObservation2DRangeScan wall(double range = 3.0, double time = 0.0)
{
	return arcScan(181, range, kBadInputSetup.at(time));
}
}  // namespace mrpt_evidential::test
