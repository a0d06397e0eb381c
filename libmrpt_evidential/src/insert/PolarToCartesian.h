/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The bilinear transform of a polar SourceGrid onto the cells of a grid. */
#pragma once

#include <mrpt_evidential/scan/CPolarSourceGrid.h>
#include <mrpt_evidential/support/FastArcTangent.h>
#include <mrpt_evidential/support/CpuClones.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace mrpt::poses
{
class CPose3D;
}

namespace mrpt_evidential
{
/** Where a sensor lies in the map's plane. */
struct PlanarSensorPose
{
	double x = 0.0, y = 0.0, yaw = 0.0;
	/** True for a sensor mounted upside down: its angles turn clockwise in
	 * the map. */
	bool mirrored = false;
};

/** The sensor pose in the plane, or nothing when the sensor's x and y axes
 * tilt more than `tolerance` radians out of the horizontal plane. */
std::optional<PlanarSensorPose> planarSensorPose(
	const mrpt::poses::CPose3D& sensor, double tolerance);

/** Axis-aligned box. */
struct Box
{
	double xMin = HUGE_VAL, xMax = -HUGE_VAL, yMin = HUGE_VAL, yMax = -HUGE_VAL;
	void add(double x, double y)
	{
		xMin = std::min(xMin, x), xMax = std::max(xMax, x);
		yMin = std::min(yMin, y), yMax = std::max(yMax, y);
	}
	bool empty() const { return !(xMin <= xMax && yMin <= yMax); }
};

namespace detail
{
/** The radius of an outline over a gap's two halves, up to and from its
 * middle (detail::outline()): the same for most gaps, not beside a sector
 * without evidence. */
struct TGapRadius
{
	double lo, hi;
	TGapRadius(double both) : lo(both), hi(both) {}
	TGapRadius(double first, double second) : lo(first), hi(second) {}
};

/** v clamped to [lo, hi], then converted: a point a billion cells away must
 * not overflow an int. NaN gives lo. */
inline int clampToInt(double v, int lo, int hi)
{
	if (!(v > lo)) return lo;
	return v < hi ? static_cast<int>(v) : hi;
}

/** The two neighbours along one axis of the polar grid and the weight of the
 * second; outside the first and last centres the nearest is used alone. */
struct Neighbours
{
	std::size_t lo, hi;
	double wHi;
};

inline Neighbours neighbours(double position, std::size_t count, bool wraps)
{
	// position >= -1 here: truncation of position + 1 is the floor, without
	// std::floor's slow path on processors before SSE4.1. Selects, not
	// branches: a cell's neighbours are hard to predict.
	const double shifted = position + 1.0;
	const auto whole = static_cast<std::ptrdiff_t>(shifted);
	const double w = shifted - static_cast<double>(whole);
	const std::ptrdiff_t f = whole - 1, last = static_cast<std::ptrdiff_t>(count) - 1;
	if (wraps)  // position < count: only the ends wrap
		return {
			static_cast<std::size_t>(f < 0 ? last : f),
			static_cast<std::size_t>(f >= last ? 0 : f + 1), w};
	const std::ptrdiff_t lo = std::clamp<std::ptrdiff_t>(f, 0, last),
						 hi = std::clamp<std::ptrdiff_t>(f + 1, 0, last);
	return {
		static_cast<std::size_t>(lo), static_cast<std::size_t>(hi),
		lo == hi ? 0.0 : w};
}
/** piece(from, to) for each run of columns [from, to] outside the spans
 * spans[i], spans[i + 1], ... before `end` (sorted, disjoint pairs of first
 * and last column), in order; i moves on past the spans left behind, so that
 * the runs of one row can be taken in turn. */
template <typename Piece>
void forEachPieceOutside(
	const std::vector<int>& spans, std::size_t& i, std::size_t end, int from, int to,
	Piece&& piece)
{
	while (from <= to)
	{
		while (i < end && spans[i + 1] < from) i += 2;
		if (i < end && spans[i] <= from)
		{
			from = spans[i + 1] + 1;
			continue;
		}
		const int stop = i < end ? std::min(to, spans[i] - 1) : to;
		piece(from, stop);
		from = stop + 1;
	}
}
}  // namespace detail

/** Places a polar SourceGrid at a sensor pose and visits the grid cells it
 * informs, each once, with the bilinear mix of the four polar cells around
 * the cell's centre (two sectors, two bins). A sector without evidence (a
 * beam without a return) is mixed with nothing: each sector holds its own
 * span, out to the middle of the gap, whole (doc/map.md).
 *
 * Only the cells that can receive evidence are looked at: the region a scan
 * informs (between two sector centres, up to the longer of the two sectors'
 * reach; beside a sector without evidence, the other's half alone) is a
 * polygon around the sensor, filled row by row. Inside it, a
 * second polygon holds the cells whose four polar neighbours are all the same
 * free mass, the bulk of a scan: those cells need no polar coordinates and no
 * mix, and are visited apart. Keep one object and reuse it: its buffers then
 * stop allocating. */
class CPolarToCartesian
{
   public:
	/** Prepares the transform of `polar` (which must outlive the calls to
	 * forEachInformedCell) placed at `sensor`. */
	void setup(const CPolarSourceGrid& polar, const PlanarSensorPose& sensor);

	/** Box holding every point the polar grid can inform (empty when it
	 * informs nothing). */
	const Box& box() const { return m_box; }

	/** World unit vector (x, y) of sector s's centre line, s < the polar
	 * grid's sectorCount(); valid after setup() of a grid that informs
	 * something. */
	std::pair<double, double> sectorDirection(std::size_t s) const
	{
		return {m_directions[2 * s + 2], m_directions[2 * s + 3]};
	}
	/** Every sector's sectorDirection() in turn, as (x, y) pairs. */
	const double* sectorDirections() const { return m_directions.data() + 2; }
	/** Every sector's nearest impact in turn, +inf for a sector without one
	 * (valid as sectorDirection()). */
	const double* nearestImpacts() const { return m_nearest.data(); }

	/** True when a beam crossed world point (x, y) but gave its cell no
	 * free evidence: each of the two sectors around the point either
	 * crossed it (it lies a bin short of the sector's nearest impact) or
	 * stopped at something at least kOccluderGap in front of it, one of
	 * them crossed it, and it lies past the free limit of one of them (in
	 * the free margin before an impact, or where free evidence stops at the
	 * nearer sector's limit, beside what the other beam hit). */
	bool crossedWithoutFreeEvidence(double x, double y) const;
	/** The sensor of the latest setup(). */
	const PlanarSensorPose& sensor() const { return m_sensor; }
	/** Metres: a beam whose nearest impact lies this much in front of a
	 * point stopped at something else than what may stand at the point (a
	 * thing that walked on, now between the point and the sensor), not at
	 * a part of the point's own thing seen at a slant. Measured on the
	 * simulated scenes, doc/dynamics.md. */
	static constexpr double kOccluderGap = 0.2;

	/** True when the last prepareRows() outlined the vacuous bands between
	 * near and far sectors, so that the visit leaves their cells out (a
	 * scan whose bands hold enough cells to be worth it). */
	bool leavesOutVacuousBands() const { return m_skipsVacuous; }

	/** The free mass every cell of the uniform region receives. */
	const Mass& uniformMass() const { return m_uniformMass; }

	/** Visits every cell of `grid` that the polar grid informs, once:
	 * visitUniform(firstIndex, count) for runs of cells along a row whose mix
	 * is uniformMass(), visitMixed(cellIndex, observed) for the others, in
	 * increasing order of cell index. Cells whose mix is
	 * vacuous are not visited. A cell touched by a bin with occupied evidence
	 * gets no free evidence: it holds part of what a beam hit, so that beam
	 * does not prove it free (without this, walls gather free and occupied
	 * evidence from scan to scan and turn into conflict). Nor does a cell
	 * between two sectors past the nearer one's free limit (its nearest
	 * impact less the free margin): where a wall is oblique, the longer
	 * sector's free run would otherwise reach into the wall behind the
	 * shorter one's impact. */
	template <typename VisitMixed, typename VisitUniform>
	void forEachInformedCell(
		const GridGeometry& grid, VisitMixed&& visitMixed,
		VisitUniform&& visitUniform)
	{
		const TRows rows = prepareRows(grid);
		visitRows(
			grid, rows.first, rows.last, visitMixed, visitUniform,
			[](std::size_t, std::size_t) {});
	}

	/** The rows of `grid` that the scan informs, first to last (none when
	 * first > last). */
	struct TRows
	{
		int first = 0, last = -1;
	};
	/** forEachInformedCell() in two steps, so that bands of rows can be
	 * visited on several threads: prepareRows() works out the rows' spans,
	 * then visitRows() visits rows [first, last] within them, changing
	 * nothing of the transform. Before it visits a row, it calls
	 * ahead(firstIndex, count) for each informed span of the row
	 * kRowsAhead rows on (within [first, last]), so that the visitor can ask
	 * for those cells' memory in time. */
	TRows prepareRows(const GridGeometry& grid);
	template <typename VisitMixed, typename VisitUniform, typename Ahead>
	void visitRows(
		const GridGeometry& grid, int first, int last, VisitMixed&& visitMixed,
		VisitUniform&& visitUniform, Ahead&& ahead) const;
	/** How many rows ahead visitRows() announces a row's spans (2 to 4
	 * measured alike, 1 a little slower: doc/performance-history.md). */
	static constexpr int kRowsAhead = 3;

   private:
	/** For each grid row from `first`, the sorted x where its centre line
	 * crosses a polygon, as inclusive ranges of cell columns. */
	struct RowSpans
	{
		std::vector<std::size_t> start, cursor;
		/** Pairs of first and last column, row k's in [start[k],
		 * start[k + 1]); fill() leaves the vector as long as it was when
		 * a scan needed more, so read no further than start.back(). */
		std::vector<int> columns;
		std::vector<double> crossingX;  //!< fill()'s work array
		/** Polygon edges that cross a row: rows [row0, row1) from `first`,
		 * x at row0 and its change per row, in columns (0 at the first
		 * column's centre). */
		struct Edge
		{
			int row0, row1;
			double x, dxPerRow;
		};
		std::vector<Edge> edges;
		std::vector<int> vertexRow;
		void fill(
			const std::vector<double>& polygon, const GridGeometry& grid,
			int first, int last);
		/** The spans, row by row, of the cells `outer`'s spans hold and
		 * `inner`'s do not (both filled for the same rows). */
		void assignDifference(const RowSpans& outer, const RowSpans& inner);
	};

	/** Cells handled per batch of the mixed path. */
	static constexpr int kBatch = 64;
	/** The angle of a point `dx` east and `dy` north of the sensor, from
	 * the start of sector 0's span, in [0, 2 pi). No branches or library
	 * calls: a loop of it vectorizes. */
	double angleFrom(double dx, double dy) const
	{
		const double twoPi = 2 * M_PI;
		// m_yawOffset is in [0, 2 pi) and atan2 in [-pi, pi].
		const double a = m_dir * (detail::fastAtan2(dy, dx) - m_yawOffset);
		const double up = a + twoPi, upTwice = up + twoPi, down = a - twoPi;
		return a < 0.0 ? (up < 0.0 ? upTwice : up) : (a >= twoPi ? down : a);
	}
	/** For `count` <= kBatch cells of a row from column `firstColumn`, `dy`
	 * north of the sensor: angleFrom() and the squared range. Each cell's
	 * offset is taken from its own column, so that a cell's mix does not
	 * depend on where its batch starts. */
	void polarOfCells(
		const GridGeometry& grid, int firstColumn, double dy, int count, double* angle,
		double* range2) const;
	/** True when cells [from, to] of a row `dy` north of the sensor all lie
	 * in one gap's vacuous band, found from the two end cells alone: along a
	 * row the angle only grows or only falls (a wrap past 2 pi changes the
	 * gap), and the range is largest at an end and smallest at an end or
	 * abreast of the sensor. The ends must lie a hair inside the gap, so that
	 * no cell between is one the arctangent could put in the next gap. Runs
	 * of five cells or more only: for fewer, the two ends' angles cost what
	 * the cells do (doc/performance-history.md). */
	bool withinOneBand(const GridGeometry& grid, int from, int to, double dy) const
	{
		if (dy == 0.0) return false;
		const double x0 = grid.cellCenterX(from) - m_sensor.x,
					 x1 = grid.cellCenterX(to) - m_sensor.x;
		const double p0 = angleFrom(x0, dy) * m_invSpacing + 0.5,
					 p1 = angleFrom(x1, dy) * m_invSpacing + 0.5;
		const double whole = std::floor(p0);
		const double lo = std::min(p0, p1) - whole, hi = std::max(p0, p1) - whole;
		if (std::floor(p1) != whole || hi + whole >= m_span * m_invSpacing + 0.5)
			return false;  // two gaps, or out of the field of view
		if (lo < m_bandSlack || hi > 1.0 - m_bandSlack) return false;
		const VacuousBand& band = m_gapMixes[static_cast<std::size_t>(whole)].vacuous;
		const double dy2 = dy * dy;
		const double near2 = x0 * x1 <= 0.0 ? dy2 : std::min(x0 * x0, x1 * x1) + dy2;
		const double far2 = std::max(x0 * x0, x1 * x1) + dy2;
		return near2 >= band.from2 && far2 < band.to2;
	}
	/** The mix at a cell's polar coordinates (angle as polarOfCells() gives
	 * it, squared range), or false when it is vacuous. */
	bool mixAt(double angle, double range2, Mass& observed) const;

	const CPolarSourceGrid* m_polar = nullptr;
	PlanarSensorPose m_sensor;
	Box m_box;
	/** The rows prepareRows() worked out the spans of. */
	TRows m_rows;
	/** What the mix needs of a sector, side by side. */
	struct SectorSpan
	{
		/** Squared reach: half a bin past the last informed bin (from it on
		 * the two bins around a range are vacuous). */
		double reach2;
		/** Squared end of the free run (before it the two bins around a
		 * range both hold freeMass); negative without a free run. */
		double freeEnd2;
		double freeMass;
		/** Range of the sector's nearest impact less half a bin (or the free
		 * margin, if longer), +inf without one: between two sectors, free
		 * evidence stops at the nearer one's limit (past it, where a wall is
		 * oblique, lies the wall the nearer beam hit). */
		double freeLimit;
	};
	std::vector<SectorSpan> m_sectorSpans;
	/** The squared ranges [from, to) between two sectors within which every
	 * cell is vacuous (free evidence stopped, neither sector's bins hold
	 * anything but their free run or their vacuous tail there); from == to
	 * when there are none. */
	struct VacuousBand
	{
		double from2 = 0.0, to2 = 0.0;
	};
	VacuousBand vacuousBand(std::size_t lo, std::size_t hi) const;
	/** The mix of a gap between two sector centres where both sectors hold
	 * one constant mass (within their free runs, or a sector without
	 * evidence), short of the nearer free limit: most mixed cells (the
	 * gaps beside beams without a return, between sectors of different
	 * free masses), whose mix needs no sector spans and no range bins. */
	struct GapMix
	{
		/** Squared range below which the mix is (1 - w) loFree + w hiFree,
		 * w the cell's angular weight; 0 for none (and for the half gaps at
		 * the ends of a scan that is not a full turn). */
		double simpleEnd2;
		double loFree, hiFree;
		/** The gap's vacuous band (vacuousBand()). */
		VacuousBand vacuous;
		/** True beside a sector without evidence (a beam without a return):
		 * each half of the gap then holds its own sector alone, unmixed,
		 * but within bridge2. */
		bool nearestOnly;
		/** Beside a sector without evidence, the squared range below which
		 * the other sector holds the whole gap (bridgeRadius(); 0 for any
		 * other gap), and that sector's weight (0 the first, 1 the second). */
		double bridge2;
		double bridgeWeight;
	};
	/** Indexed by the whole part of a cell's sector position + 1, as
	 * detail::neighbours() takes it: n + 1 entries. */
	std::vector<GapMix> m_gapMixes;
	/** The weight of a gap's second sector: `w` itself, or in a gap
	 * beside a sector without evidence that of the nearer sector alone (the
	 * second from the gap's middle on). */
	static double nearestWeight(const GapMix& gap, double w)
	{
		return gap.nearestOnly ? (w < 0.5 ? 0.0 : 1.0) : w;
	}
	/** The weight of a gap's second sector at squared range `range2` on
	 * the simple path: nearestWeight(), or inside the bridge of a gap beside
	 * a sector without evidence the other sector's alone. */
	static double simpleWeight(const GapMix& gap, double w, double range2)
	{
		return range2 < gap.bridge2 ? gap.bridgeWeight : nearestWeight(gap, w);
	}
	/** For a gap beside a sector without evidence (nearestOnly()): the
	 * range within which the other sector holds the silent one's half too.
	 * Nearer than a bin (the grid's cell) over the sector spacing, the silent
	 * span is narrower than a cell, which then lies mostly in its
	 * neighbours' halves; and only as far as the other sector's free run
	 * holds its free mass, short of its free limit, so that the bridge is a
	 * simple mix. 0 for any other gap. */
	double bridgeRadius(std::size_t lo, std::size_t hi) const;
	/** True for a gap between two sectors (not a half gap at an end) of
	 * which one has no evidence: GapMix::nearestOnly, from the spans. */
	bool nearestOnly(std::size_t lo, std::size_t hi) const
	{
		return lo != hi &&
			(m_sectorSpans[lo].reach2 <= 0.0) != (m_sectorSpans[hi].reach2 <= 0.0);
	}
	/** The area of all the gaps' vacuous bands (m^2, set by setup()): when
	 * it holds enough cells, prepareRows() outlines them and the visit
	 * leaves them out. */
	double m_vacuousArea = 0.0;
	/** Each sector's nearest impact, +inf without one (nearestImpacts()), the
	 * range within which it bounds the uniform region, and its reach and free
	 * run's end (0 without one) unsquared, for the outlines. */
	std::vector<double> m_nearest, m_uniformReach, m_reach, m_freeEnd;
	/** The informed and the uniform outlines' radii over each gap, by its
	 * entry among the directions (setup()'s scratch). */
	std::vector<detail::TGapRadius> m_informedRadii, m_uniformRadii;
	/** The vacuous bands' outlines' radii over each gap (prepareRows()'s
	 * scratch). */
	std::vector<detail::TGapRadius> m_bandRadii;
	/** Outlines of the informed and of the uniform regions (x, y pairs), and
	 * the world directions of their corners. */
	std::vector<double> m_polygon, m_uniformPolygon, m_directions;
	/** Outlines inside the vacuous bands' far ends and outside their near
	 * ends (prepareRows()'s scratch). */
	std::vector<double> m_vacuousOuter, m_vacuousInner;
	Mass m_uniformMass;
	/** Free masses of the sectors and how many sectors hold each (setup()'s
	 * scratch, kept to reuse its storage). */
	std::vector<std::pair<double, std::size_t>> m_freeMassVotes;
	RowSpans m_spans, m_uniformSpans;
	/** The vacuous bands' spans (outer less inner), when m_skipsVacuous. */
	RowSpans m_vacuousOuterSpans, m_vacuousInnerSpans, m_vacuousSpans;
	bool m_skipsVacuous = false;
	/** Constants of mixAt(), set by setup(). */
	double m_invSpacing = 0, m_span = 0, m_invBin = 0, m_dir = 1,
		   m_yawOffset = 0;
	/** The centre lines' slack in units of the sector spacing. */
	double m_bandSlack = 0;
};

}  // namespace mrpt_evidential

// The visit's hot loop: inline, for the insertion to compile it with its own
// visitors.
#include "insert/PolarToCartesianVisit.h"
