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
 * `OffCentreLines`: the step between two gaps of different radii is turned
 * off their centre line by kCentreLineSlack as a split is, so that within
 * the slack of the line the region holds only the smaller radius (inside)
 * or the larger one (outside); otherwise the step lies on the line. An
 * outline off the centre lines keeps each gap's radius in `radii` (work
 * memory the caller keeps from scan to scan), where the steps at both of
 * the gap's ends read it. */
template <bool OffCentreLines = false, typename RadiusOf>
void outline(
	std::vector<double>& polygon, Box* box, const CPolarSourceGrid& polar,
	const PlanarSensorPose& sensor, const std::vector<double>& directions,
	bool outside, RadiusOf radiusOf, std::vector<TGapRadius>* radii = nullptr)
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
	const auto addArcIn = [&](const double* dirs, double radius, std::size_t i, std::size_t j,
							  double width) {
		if (radius <= 0.0)
		{
			addPoint(sensor.x, sensor.y);
			return;
		}
		if (width != lastWidth)
		{
			lastWidth = width;
			pieces = std::max(1, static_cast<int>(std::ceil(width / (M_PI / 8))));
			step = width / pieces;
			pushOut = outside ? 1.0 / std::cos(0.5 * step) : 1.0;
		}
		const double cx = dirs[2 * i], cy = dirs[2 * i + 1];
		const double rho = radius * pushOut;
		addPoint(sensor.x + rho * cx, sensor.y + rho * cy);
		for (int k = 1; k < pieces; ++k)
		{
			// Wide arcs only: turn the start direction by k steps.
			const auto [x, y] = turned(cx, cy, k * step);
			addPoint(sensor.x + rho * x, sensor.y + rho * y);
		}
		addPoint(sensor.x + rho * dirs[2 * j], sensor.y + rho * dirs[2 * j + 1]);
	};
	const std::size_t n = polar.sectorCount();
	const bool fullTurn = polar.fullTurn();
	// Off the centre lines: each gap's radii first, then each line's turn
	// (0, or the slack towards the gap after it or before it).
	if constexpr (OffCentreLines)
	{
		radii->assign(n + 1, TGapRadius(0.0));
		forEachGap(polar, [&](std::size_t lo, std::size_t hi, std::size_t i, double) {
			(*radii)[i] = radiusOf(lo, hi, i);
		});
	}
	const auto turnAt = [&](std::size_t line) {
		if constexpr (!OffCentreLines) return 0.0;
		if (fullTurn && line == n + 1) line = 1;  // centre 0 again
		if (!fullTurn && (line == 0 || line == n + 1)) return 0.0;  // the span's ends
		const double before = (*radii)[fullTurn && line == 1 ? n : line - 1].hi,
					 after = (*radii)[line].lo;
		if (before == after) return 0.0;
		return (before < after) != outside ? kCentreLineSlack : -kCentreLineSlack;
	};
	const double slackC = std::cos(kCentreLineSlack), slackS = dir * std::sin(kCentreLineSlack);
	// Direction entry `line` turned by turnAt(line), into out[0], out[1].
	const auto lineDirection = [&](std::size_t line, double turn, double* out) {
		const double x = directions[2 * line], y = directions[2 * line + 1];
		if (turn == 0.0)
			out[0] = x, out[1] = y;
		else
		{
			const double s = turn > 0.0 ? slackS : -slackS;
			out[0] = slackC * x - s * y, out[1] = s * x + slackC * y;
		}
	};
	// Nearly every gap is one sector wide, one chord at one radius: its two
	// corners, as addArcIn() works them out, without its cases (pushed out
	// for the widest such gap, turned by the slack at both ends).
	const double spacing = polar.sectorSpacing();
	const double widest = spacing + (OffCentreLines ? 2 * kCentreLineSlack : 0.0);
	const bool oneChord = std::ceil(widest / (M_PI / 8)) <= 1.0;
	const double chordPushOut = outside ? 1.0 / std::cos(0.5 * widest) : 1.0;
	// A scan that is not a full turn starts and ends at the sensor.
	if (!fullTurn) addPoint(sensor.x, sensor.y);
	forEachGap(polar, [&](std::size_t lo, std::size_t hi, std::size_t i, double width) {
		TGapRadius radius(0.0);
		if constexpr (OffCentreLines)
			radius = (*radii)[i];
		else
			radius = radiusOf(lo, hi, i);
		// The gap's start and end: its lines' own directions, or turned.
		const double startTurn = turnAt(i), endTurn = turnAt(i + 1);
		double turnedEnds[4];
		const double* ends = &directions[2 * i];  // (x, y) of the start, then the end
		if constexpr (OffCentreLines)
		{
			lineDirection(i, startTurn, turnedEnds);
			lineDirection(i + 1, endTurn, turnedEnds + 2);
			ends = turnedEnds;
		}
		if (radius.lo == radius.hi)
		{
			if (oneChord && width == spacing && radius.lo > 0.0)
			{
				const double rho = radius.lo * chordPushOut;
				addPoint(sensor.x + rho * ends[0], sensor.y + rho * ends[1]);
				addPoint(sensor.x + rho * ends[2], sensor.y + rho * ends[3]);
				return;
			}
			addArcIn(ends, radius.lo, 0, 1, width - startTurn + endTurn);
			return;
		}
		// The split between the two halves.
		const bool towardsHi = (radius.lo < radius.hi) != outside;
		const double half = 0.5 * width + (towardsHi ? kCentreLineSlack : -kCentreLineSlack);
		double split[6];
		std::copy_n(ends, 2, split);
		std::tie(split[2], split[3]) = turned(directions[2 * i], directions[2 * i + 1], half);
		std::copy_n(ends + 2, 2, split + 4);
		addArcIn(split, radius.lo, 0, 1, half - startTurn);
		addArcIn(split, radius.hi, 1, 2, width - half + endTurn);
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
