/* mrpt-evidential: internal: the visit of CPolarToCartesian's cells, inline
 * so that the insertion compiles it with its own visitors: each mixed cell's
 * polar coordinates and mix, and the rows' spans walked in order. Included by
 * PolarToCartesian.h. */
#pragma once

#include "insert/PolarToCartesian.h"

#include <algorithm>
#include <cstddef>

namespace mrpt_evidential
{
inline void CPolarToCartesian::polarOfCells(
	const GridGeometry& grid, int firstColumn, double dy, int count, double* angle,
	double* range2) const
{
	for (int k = 0; k < count; ++k)
	{
		const double dx = grid.cellCenterX(firstColumn + k) - m_sensor.x;
		angle[k] = angleFrom(dx, dy);
		range2[k] = dx * dx + dy * dy;
	}
}

inline bool CPolarToCartesian::mixAt(
	double angle, double range2, Mass& observed) const
{
	const CPolarSourceGrid& polar = *m_polar;
	if (angle >= m_span) return false;  // outside the field of view
	const double position = angle * m_invSpacing - 0.5;
	// The weight as detail::neighbours() works it out, bit for bit.
	const double shifted = position + 1.0;
	const auto whole = static_cast<std::size_t>(shifted);
	const GapMix& gap = m_gapMixes[whole];
	if (range2 < gap.simpleEnd2)
	{
		const double w = simpleWeight(gap, shifted - static_cast<double>(whole), range2);
		const double free = (1 - w) * gap.loFree + w * gap.hiFree;
		observed = Mass::simpleFree(free);
		return free > 1e-12;
	}
	if (range2 >= gap.vacuous.from2 && range2 < gap.vacuous.to2) return false;
	auto ns = detail::neighbours(position, polar.sectorCount(), polar.fullTurn());
	ns.wHi = nearestWeight(gap, ns.wHi);
	const SectorSpan &lo = m_sectorSpans[ns.lo], &hi = m_sectorSpans[ns.hi];
	if (range2 >= std::max(lo.reach2, hi.reach2)) return false;
	// Where each sector's two bins hold one constant mass (free run or
	// vacuous tail: most cells between sectors of different lengths), the mix
	// is along the angle only, with no range bins to look up.
	// Between two sectors free evidence stops at the nearer one's limit
	// (even on a centre line, so that the cells prepareRows() leaves out as
	// vacuous are exactly those found vacuous here).
	const double limit = std::min(lo.freeLimit, hi.freeLimit);
	const bool pastImpacts = range2 >= limit * limit;  // false for +inf
	const bool loFree = range2 < lo.freeEnd2, hiFree = range2 < hi.freeEnd2;
	if ((loFree || range2 >= lo.reach2) && (hiFree || range2 >= hi.reach2))
	{
		const double free = pastImpacts
			? 0.0
			: (1 - ns.wHi) * (loFree ? lo.freeMass : 0.0) +
				ns.wHi * (hiFree ? hi.freeMass : 0.0);
		observed = Mass::simpleFree(free);
		return free > 1e-12;
	}
	const auto nb = detail::neighbours(
		std::sqrt(range2) * m_invBin - 0.5, polar.binCount(), false);
	const Mass a = polar.massAt(ns.lo, nb.lo), b = polar.massAt(ns.lo, nb.hi);
	const Mass c = polar.massAt(ns.hi, nb.lo), d = polar.massAt(ns.hi, nb.hi);
	const double wa = (1 - ns.wHi) * (1 - nb.wHi), wb = (1 - ns.wHi) * nb.wHi,
				 wc = ns.wHi * (1 - nb.wHi), wd = ns.wHi * nb.wHi;
	observed = {
		wa * a.conflict + wb * b.conflict + wc * c.conflict + wd * d.conflict,
		wa * a.free + wb * b.free + wc * c.free + wd * d.free,
		wa * a.occupied + wb * b.occupied + wc * c.occupied + wd * d.occupied,
		wa * a.unknown + wb * b.unknown + wc * c.unknown + wd * d.unknown};
	if (observed.unknown >= 1.0 - 1e-12) return false;
	const bool touchedByImpact = pastImpacts ||
		a.occupied + b.occupied + c.occupied + d.occupied > 0.0;
	const double freeToUnknown = touchedByImpact ? observed.free : 0.0;
	observed.unknown += freeToUnknown;
	observed.free -= freeToUnknown;
	return true;
}

template <typename VisitMixed, typename VisitUniform, typename Ahead>
void CPolarToCartesian::visitRows(
	const GridGeometry& grid, int first, int last, VisitMixed&& visitMixed,
	VisitUniform&& visitUniform, Ahead&& ahead) const
{
	if (!m_polar || m_box.empty()) return;
	Mass observed;
	for (int cy = first; cy <= last; ++cy)
	{
		const auto k = static_cast<std::size_t>(cy - m_rows.first);
		const double dy = grid.cellCenterY(cy) - m_sensor.y;
		const std::size_t rowIndex = grid.index(0, cy);
		if (cy + kRowsAhead <= last)
		{
			const std::size_t a = k + kRowsAhead, aheadIndex = grid.index(0, cy + kRowsAhead);
			for (std::size_t o = m_spans.start[a]; o < m_spans.start[a + 1]; o += 2)
				ahead(
					aheadIndex + static_cast<std::size_t>(m_spans.columns[o]),
					static_cast<std::size_t>(m_spans.columns[o + 1] - m_spans.columns[o] + 1));
		}
		std::size_t u = m_uniformSpans.start[k];
		const std::size_t uEnd = m_uniformSpans.start[k + 1];
		std::size_t v = m_skipsVacuous ? m_vacuousSpans.start[k] : 0;
		const std::size_t vEnd = m_skipsVacuous ? m_vacuousSpans.start[k + 1] : 0;
		const auto mixed = [&](int from, int to) {
			if (to - from >= 4 && withinOneBand(grid, from, to, dy)) return;
			double angle[kBatch], range2[kBatch];
			for (int cx = from; cx <= to; cx += kBatch)
			{
				const int count = std::min(kBatch, to - cx + 1);
				polarOfCells(grid, cx, dy, count, angle, range2);
				for (int k = 0; k < count; ++k)
					if (mixAt(angle[k], range2[k], observed))
						visitMixed(rowIndex + static_cast<std::size_t>(cx + k), observed);
			}
		};
		// The mixed cells outside the vacuous bands.
		const auto mixedOutsideBands = [&](int from, int to) {
			detail::forEachPieceOutside(m_vacuousSpans.columns, v, vEnd, from, to, mixed);
		};
		for (std::size_t o = m_spans.start[k]; o < m_spans.start[k + 1]; o += 2)
		{
			// The informed span, cut by the uniform spans it holds.
			int cx = m_spans.columns[o];
			const int end = m_spans.columns[o + 1];
			while (cx <= end)
			{
				while (u < uEnd && m_uniformSpans.columns[u + 1] < cx) u += 2;
				if (u < uEnd && m_uniformSpans.columns[u] <= cx)
				{
					const int stop = std::min(end, m_uniformSpans.columns[u + 1]);
					visitUniform(
						rowIndex + static_cast<std::size_t>(cx),
						static_cast<std::size_t>(stop - cx + 1));
					cx = stop + 1;
				}
				else
				{
					const int stop = u < uEnd
						? std::min(end, m_uniformSpans.columns[u] - 1)
						: end;
					mixedOutsideBands(cx, stop);
					cx = stop + 1;
				}
			}
		}
	}
}

namespace
{
/** transform.visitRows() built for AVX2 as well (CpuClones.h): what the
 * insertion's fusion calls. A function of each file that includes this
 * header (unnamed namespace): on a clone of a template whose instances files
 * share (COMDAT), GCC 14 stops with an internal compiler error. */
template <typename VisitMixed, typename VisitUniform, typename Ahead>
MRPT_EVIDENTIAL_CPU_CLONES void visitRowsCloned(
	const CPolarToCartesian& transform, const GridGeometry& grid, int first, int last,
	VisitMixed&& visitMixed, VisitUniform&& visitUniform, Ahead&& ahead)
{
	transform.visitRows(grid, first, last, visitMixed, visitUniform, ahead);
}
}  // namespace

}  // namespace mrpt_evidential
