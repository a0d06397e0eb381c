/* A 2-D world of axis-aligned boxes, scanned exactly: the ground truth of the
 * motion tests (what stands where at each scan is known cell by cell). */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "scans.h"

namespace mrpt_evidential::test
{
struct TBox
{
	double xMin, yMin, xMax, yMax;
	bool contains(double x, double y) const
	{
		return x >= xMin && x <= xMax && y >= yMin && y <= yMax;
	}
};

/** A room of 8 x 6 m centred on the origin, walls 0.2 m thick. */
inline std::vector<TBox> roomWalls()
{
	return {
		{-4.2, -3.2, 4.2, -3.0}, {-4.2, 3.0, 4.2, 3.2},
		{-4.2, -3.0, -4.0, 3.0}, {4.0, -3.0, 4.2, 3.0}};
}

/** Distance from (x, y) along direction a to the nearest box, +inf if none
 * (slab test). */
inline double rayToBoxes(const std::vector<TBox>& boxes, double x, double y, double a)
{
	const double dx = std::cos(a), dy = std::sin(a);
	double best = std::numeric_limits<double>::infinity();
	for (const TBox& b : boxes)
	{
		double t0 = 0.0, t1 = best;
		const auto slab = [&](double o, double d, double lo, double hi) {
			if (std::abs(d) < 1e-12) return o >= lo && o <= hi;
			double ta = (lo - o) / d, tb = (hi - o) / d;
			if (ta > tb) std::swap(ta, tb);
			t0 = std::max(t0, ta);
			t1 = std::min(t1, tb);
			return t0 <= t1;
		};
		if (slab(x, dx, b.xMin, b.xMax) && slab(y, dy, b.yMin, b.yMax)) best = t0;
	}
	return best;
}

/** A scan of `boxes` by a sensor at the robot's origin (setup's sensor pose
 * must be the identity), robot at `robot`: 361 beams over pi unless given;
 * beams that reach nothing within the scan's maxRange are invalid. */
inline mrpt::obs::CObservation2DRangeScan scanOfBoxes(
	const std::vector<TBox>& boxes, const mrpt::poses::CPose3D& robot,
	const ScanSetup& setup, std::size_t beams = 361)
{
	const double maxRange = setup.make(1).maxRange;
	return scanByAngle(beams, setup, [&](double a) {
		const double r = rayToBoxes(boxes, robot.x(), robot.y(), robot.yaw() + a);
		return Beam{std::min(r, maxRange), r < maxRange};
	});
}
}  // namespace mrpt_evidential::test
