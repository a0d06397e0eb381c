/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: maps from many runs (fusing maps, what changed
 * between two). */

#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "insert/MotionDetector.h"
#include "map/ConfigReading.h"
#include "map/MapWorkspace.h"
#include <mrpt_evidential/support/NumberText.h>

using namespace mrpt_evidential;

namespace
{
/** Other's origin in cells of `mine`, both on one lattice.
 * \throws std::invalid_argument naming both geometries otherwise. */
std::pair<int, int> latticeOffset(const GridGeometry& mine, const GridGeometry& other)
{
	const double r = mine.resolution;
	const double fx = (other.xMin - mine.xMin) / r, fy = (other.yMin - mine.yMin) / r;
	const bool sameResolution = std::abs(other.resolution - r) <= 1e-9 * r;
	const bool aligned = std::abs(fx - std::round(fx)) <= 1e-6 && std::abs(fy - std::round(fy)) <= 1e-6;
	if (!sameResolution || !aligned)
		throw std::invalid_argument(
			"the maps do not share a lattice: cells of " + detail::shortestText(r) +
			" m from (" + detail::shortestText(mine.xMin) + ", " +
			detail::shortestText(mine.yMin) + ") and of " +
			detail::shortestText(other.resolution) + " m from (" +
			detail::shortestText(other.xMin) + ", " + detail::shortestText(other.yMin) +
			")" +
			(sameResolution
				 ? ": their origins are not a whole number of cells apart (build the runs "
				   "with the same creationOpts min_x and min_y)"
				 : ": other resolutions (build the runs with the same creationOpts "
				   "resolution)"));
	return {static_cast<int>(std::lround(fx)), static_cast<int>(std::lround(fy))};
}

bool seen(const Mass& m) { return m.unknown < 1.0 - 1e-4; }
}  // namespace

std::optional<std::size_t> CEvidentialGridMap2D::cellOfOther(
	const GridGeometry& other, std::size_t idx, int offsetX, int offsetY) const
{
	const int cx = other.columnOf(idx) + offsetX, cy = other.rowOf(idx) + offsetY;
	if (!geometry().inside(cx, cy)) return std::nullopt;
	return geometry().index(cx, cy);
}

void CEvidentialGridMap2D::fuseMap(
	const CEvidentialGridMap2D& other, FusionRule rule, ConflictHandling handling)
{
	// Before anything changes.
	if (!detail::isMember(rule))
		throw std::invalid_argument("fuseMap: unknown rule " + std::to_string(int(rule)));
	if (!detail::isMember(handling))
		throw std::invalid_argument(
			"fuseMap: unknown conflict handling " + std::to_string(int(handling)));
	latticeOffset(geometry(), other.geometry());
	const GridGeometry& g = other.geometry();
	if (!other.isEmpty() &&
		!m_grid.growToInclude(g.xMin, g.xMax(), g.yMin, g.yMax(), 0.0, m_maxCells))
		throw std::invalid_argument(
			"the map cannot grow to hold the other's extent within its budget of " +
			std::to_string(m_maxCells) + " cells (maxCells)");
	// Plain ints: lambdas may not capture structured bindings in C++17.
	const std::pair<int, int> offset = latticeOffset(geometry(), g);
	const int ox = offset.first, oy = offset.second;
	insertionOptions.conflictHandling = handling;
	m_grid.setKeepsConflict(handling == ConflictHandling::Keep);
	if (!m_grid.keepsConflict())
		geometry().forEachIndex([&](std::size_t i) {
			if (m_grid.event(i) != CellEvent::None) m_grid.setEvent(i, CellEvent::None);
		});
	if (other.isEmpty()) return;
	m_grid.beginInsertion(std::max(latestTime(), other.latestTime()));
	invalidateLikelihoodCache();
	const EvidentialGridStorage& theirs = other.storage();
	g.forEachIndex([&](std::size_t j) {
		const Mass m = theirs.read(j);
		if (!seen(m)) return;
		const auto idx = cellOfOther(g, j, ox, oy);
		if (!idx) return;  // cannot happen: the grid holds other's extent
		m_grid.fuse(*idx, m, rule, handling);
		if (theirs.heldImpact(j)) m_grid.markImpact(*idx);
	});
}

CEvidentialGridMap2D::TMapChanges CEvidentialGridMap2D::changesSince(
	const CEvidentialGridMap2D& earlier, double minConflict, double clearance) const
{
	if (!(minConflict > 0.0 && minConflict <= 1.0))
		throw std::invalid_argument(
			"minConflict must be in (0, 1], got " + detail::shortestText(minConflict));
	if (!(clearance >= 0.0 && clearance <= 10.0))
		throw std::invalid_argument(
			"clearance must be in [0, 10] m, got " + detail::shortestText(clearance));
	const GridGeometry& g = geometry();
	// Plain ints: lambdas may not capture structured bindings in C++17.
	const std::pair<int, int> offset = latticeOffset(earlier.geometry(), g);
	const int ox = offset.first, oy = offset.second;
	const GridGeometry& e = earlier.geometry();
	// Per cell of this map: the earlier masses, or nothing unseen there.
	const auto before = [&](int cx, int cy) -> std::optional<Mass> {
		const int ex = cx + ox, ey = cy + oy;
		if (!e.inside(ex, ey)) return std::nullopt;
		const Mass m = earlier.storage().read(e.index(ex, ey));
		return seen(m) ? std::optional<Mass>(m) : std::nullopt;
	};
	const int r = static_cast<int>(std::floor(clearance / g.resolution + 0.5));
	const auto nearStructure = [&](int cx, int cy) {
		for (int y = std::max(0, cy - r); y <= std::min(g.sizeY - 1, cy + r); ++y)
			for (int x = std::max(0, cx - r); x <= std::min(g.sizeX - 1, cx + r); ++x)
			{
				const auto was = before(x, y);
				if (was && leansOccupied(*was) && leansOccupied(m_grid.read(g.index(x, y))))
					return true;
			}
		return false;
	};
	TMapChanges out;
	const GridGeometry packed = g.packed();  // what TMapChanges holds
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
		{
			const std::size_t idx = g.index(cx, cy);
			const Mass now = m_grid.read(idx);
			const auto was = before(cx, cy);
			if (!was || !seen(now)) continue;
			++out.compared;
			const ConflictSplit split = splitConflict(*was, now);
			const bool appeared = split.appeared >= minConflict;
			const bool left = split.disappeared >= minConflict;
			if ((!appeared && !left) || nearStructure(cx, cy)) continue;
			(appeared ? out.appeared : out.disappeared).push_back(packed.index(cx, cy));
		}
	return out;
}

