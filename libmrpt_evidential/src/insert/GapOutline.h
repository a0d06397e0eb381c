/* mrpt-evidential: internal: the outlines of the regions a polar grid
 * informs, one radius per gap between sector centres, for
 * CPolarToCartesian (PolarToCartesian.cpp), which fills them row by row. */
#pragma once

#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include "insert/PolarToCartesian.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace mrpt_evidential::detail
{
/** Radians: the transform's angles (fastAtan2) are within 2e-6 rad, so a
 * cell this close to a centre line may be mixed as the next gap's, where the
 * free limit can differ; a band leaves such cells to the visit. */
inline constexpr double kCentreLineSlack = 1e-5;

/** No flanks: see outline(). */
struct TNoFlanks
{
	double operator()(std::size_t, std::size_t) const { return 0.0; }
};

/** fn(lo, hi, i, width) for each gap between sector centres, in order: gap g
 * between sectors g and g + 1 (g + 1 wraps to 0 for the last gap of a full
 * turn), and at the ends of a scan that is not a full turn the half sectors
 * before the first centre and after the last (lo == hi). i is the entry of
 * the gap's start among the outline's directions (the start of sector 0's
 * span, each centre, the end of the last span), width its angle. */
template <typename Fn>
void forEachGap(const CPolarSourceGrid& polar, Fn&& fn)
{
	const std::size_t n = polar.sectorCount();
	if (n == 0) return;
	const double spacing = polar.sectorSpacing();
	const bool fullTurn = polar.fullTurn();
	// By the gap's start among the directions, i = 0 (a half gap) or 1 to n;
	// fn called from one place, so that the compiler puts it in the loop.
	for (std::size_t i = fullTurn ? 1 : 0; i <= n; ++i)
	{
		const bool half = !fullTurn && (i == 0 || i == n);
		const std::size_t lo = i == 0 ? 0 : i - 1;
		const std::size_t hi = i < n ? i : (fullTurn ? 0 : n - 1);
		fn(lo, hi, i, half ? 0.5 * spacing : spacing);
	}
}

/** Builds the outline of a region made of one radius per gap between sector
 * centres (and per half sector at the ends of a scan that is not a full
 * turn): radiusOf(lo, hi, i) for the gap between sectors lo and hi, i its
 * entry among the directions (as forEachGap() gives them), a
 * TGapRadius (a gap whose halves differ splits at its middle, turned by
 * kCentreLineSlack into the longer half for an outline inside the region,
 * into the shorter one for an outline that holds it). Arcs become
 * chords of at most 22.5 degrees, pushed out far enough to hold the arc when
 * `outside` (an outline that must hold the region; otherwise it must stay
 * inside it); a radius of 0 puts the sensor itself in the outline.
 * `directions` holds the world unit vectors of the gaps' ends (x, y pairs):
 * the start of sector 0's span, every centre, the end of the last span.
 * flankOf(lo, hi) > 0 also puts in the region, out to that radius, the
 * strips of kCentreLineSlack along the gap's two ends. */
template <typename RadiusOf, typename FlankOf = TNoFlanks>
void outline(
	std::vector<double>& polygon, Box* box, const CPolarSourceGrid& polar,
	const PlanarSensorPose& sensor, const std::vector<double>& directions,
	bool outside, RadiusOf radiusOf, FlankOf flankOf = {})
{
	polygon.clear();
	const auto addPoint = [&](double x, double y) {
		// Neighbouring arcs of one radius meet at the same corner.
		const std::size_t size = polygon.size();
		if (size >= 2 && polygon[size - 2] == x && polygon[size - 1] == y) return;
		polygon.push_back(x);
		polygon.push_back(y);
	};
	const double dir = sensor.mirrored ? -1.0 : 1.0;
	// The arc from direction entry i to entry j, `width` radians wide. Nearly
	// every arc is one sector wide: its chords are worked out once.
	double lastWidth = -1.0, step = 0.0, pushOut = 1.0;
	int pieces = 1;
	const auto turned = [&](double cx, double cy, double angle) {
		const double c = std::cos(dir * angle), s = std::sin(dir * angle);
		return std::pair<double, double>{c * cx - s * cy, s * cx + c * cy};
	};
	// The arc from entry i to entry j of `dirs` (x, y pairs).
	const auto addArcIn = [&](const double* dirs, double radius, double flank,
							  std::size_t i, std::size_t j, double width) {
		double cx = dirs[2 * i], cy = dirs[2 * i + 1];
		double ex = dirs[2 * j], ey = dirs[2 * j + 1];
		if (flank > 0.0)
		{
			// Out to the flank along the start, across the strip, and the
			// arc between the strips; the same back at the end.
			addPoint(sensor.x + flank * cx, sensor.y + flank * cy);
			std::tie(cx, cy) = turned(cx, cy, kCentreLineSlack);
			std::tie(ex, ey) = turned(ex, ey, -kCentreLineSlack);
			addPoint(sensor.x + flank * cx, sensor.y + flank * cy);
			width -= 2 * kCentreLineSlack;
		}
		if (radius <= 0.0)
			addPoint(sensor.x, sensor.y);
		else
		{
			if (width != lastWidth)
			{
				lastWidth = width;
				pieces = std::max(1, static_cast<int>(std::ceil(width / (M_PI / 8))));
				step = width / pieces;
				pushOut = outside ? 1.0 / std::cos(0.5 * step) : 1.0;
			}
			const double rho = radius * pushOut;
			addPoint(sensor.x + rho * cx, sensor.y + rho * cy);
			for (int k = 1; k < pieces; ++k)
			{
				// Wide arcs only: turn the start direction by k steps.
				const auto [x, y] = turned(cx, cy, k * step);
				addPoint(sensor.x + rho * x, sensor.y + rho * y);
			}
			addPoint(sensor.x + rho * ex, sensor.y + rho * ey);
		}
		if (flank > 0.0)
		{
			addPoint(sensor.x + flank * ex, sensor.y + flank * ey);
			addPoint(sensor.x + flank * dirs[2 * j], sensor.y + flank * dirs[2 * j + 1]);
		}
	};
	const auto addArc = [&](double radius, double flank, std::size_t i, std::size_t j,
							double width) {
		addArcIn(directions.data(), radius, flank, i, j, width);
	};
	// Nearly every gap is one sector wide, one chord at one radius: its two
	// corners, as addArcIn() works them out, without its cases.
	const double spacing = polar.sectorSpacing();
	const bool oneChord = std::ceil(spacing / (M_PI / 8)) <= 1.0;
	const double chordPushOut = outside ? 1.0 / std::cos(0.5 * spacing) : 1.0;
	// A scan that is not a full turn starts and ends at the sensor.
	if (!polar.fullTurn()) addPoint(sensor.x, sensor.y);
	forEachGap(polar, [&](std::size_t lo, std::size_t hi, std::size_t i, double width) {
		const TGapRadius radius = radiusOf(lo, hi, i);
		if (radius.lo == radius.hi)
		{
			const double flank = flankOf(lo, hi);
			if (oneChord && width == spacing && radius.lo > 0.0 && !(flank > 0.0))
			{
				const double rho = radius.lo * chordPushOut;
				const double* d = &directions[2 * i];
				addPoint(sensor.x + rho * d[0], sensor.y + rho * d[1]);
				addPoint(sensor.x + rho * d[2], sensor.y + rho * d[3]);
				return;
			}
			addArc(radius.lo, flank, i, i + 1, width);
			return;
		}
		// The gap's start, its split and its end.
		double splitDirections[6];
		const bool towardsHi = (radius.lo < radius.hi) != outside;
		const double half = 0.5 * width + (towardsHi ? kCentreLineSlack : -kCentreLineSlack);
		std::copy_n(&directions[2 * i], 2, splitDirections);
		std::tie(splitDirections[2], splitDirections[3]) =
			turned(directions[2 * i], directions[2 * i + 1], half);
		std::copy_n(&directions[2 * i + 2], 2, splitDirections + 4);
		addArcIn(splitDirections, radius.lo, 0.0, 0, 1, half);
		addArcIn(splitDirections, radius.hi, 0.0, 1, 2, width - half);
	});
	// The box once the corners are known (min and max in any order).
	if (box)
	{
		Box corners = *box;
		for (std::size_t k = 0; k + 1 < polygon.size(); k += 2)
			corners.add(polygon[k], polygon[k + 1]);
		*box = corners;
	}
}
}  // namespace mrpt_evidential::detail
