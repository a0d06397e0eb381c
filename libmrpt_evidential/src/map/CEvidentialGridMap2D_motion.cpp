/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CEvidentialGridMap2D: the motion layer (fusion without conflict, and what
 * the layer reads). */

#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "insert/MotionDetector.h"
#include "insert/PolarToCartesian.h"
#include "insert/ScanImpacts.h"
#include "map/MapWorkspace.h"

using namespace mrpt_evidential;

void CEvidentialGridMap2D::fuseWithMotion(CScanImpacts& impacts)
{
	const TInsertionOptions& io = insertionOptions;
	CPolarToCartesian& transform = m_workspace->transform;
	CMotionDetector& motion = m_workspace->motion;
	const auto cells = [this](double metres) {
		return static_cast<int>(std::floor(metres / getResolution() + 0.5));
	};
	const int clearance = cells(io.motionClearance);
	// The imprecise model's spread leans occupied in front of a face as far
	// as no free evidence reaches it: the lesser of imprecision and margin.
	const int spread = io.sensorModel == SensorModel::ImpreciseMultiEcho
		? cells(std::min(io.imprecision, io.freeMargin))
		: 0;
	const TMotionRules rules{
		TMotionRules::reachableConflict(io.motionMinConflict, io.muO),
		TMotionRules::reachableConflict(io.motionMinConflict, io.muF), clearance,
		cells(TMotionRules::kThingSize), io.motionWindow,
		clearance == 0 ? 0 : std::max(1, clearance - spread),
		std::max(1, cells(TMotionRules::kFaceGap))};
	motion.begin(rules);
	const FusionRule rule = io.fusionRule;
	const ConflictHandling handling = io.conflictHandling;
	// The rule of the bulk kernels that fuse the simple free masses of most
	// of a scan's cells: every rule has one. Dubois and Prade's rule, on
	// {F, O} and for cells without conflict, and the conjunctive rule with
	// its conflict to Omega are Yager's.
	const FreeFusion bulkRule = [&] {
		const bool normalizes = handling == ConflictHandling::Normalize;
		switch (rule)
		{
			case FusionRule::Dempster: return FreeFusion::Dempster;
			case FusionRule::Yager:
			case FusionRule::DuboisPrade: return FreeFusion::Yager;
			case FusionRule::Cautious:
				return normalizes ? FreeFusion::CautiousNormalized : FreeFusion::CautiousToUnknown;
			case FusionRule::Conjunctive: break;
		}
		return normalizes ? FreeFusion::Dempster : FreeFusion::Yager;
	}();
	// Calls fuse() with the bulk rule as a compile-time constant.
	const auto withBulkRule = [bulkRule](auto&& fuse) {
		switch (bulkRule)
		{
			case FreeFusion::Yager:
				return fuse(std::integral_constant<FreeFusion, FreeFusion::Yager>{});
			case FreeFusion::CautiousNormalized:
				return fuse(std::integral_constant<FreeFusion, FreeFusion::CautiousNormalized>{});
			case FreeFusion::CautiousToUnknown:
				return fuse(std::integral_constant<FreeFusion, FreeFusion::CautiousToUnknown>{});
			case FreeFusion::Dempster: break;
		}
		return fuse(std::integral_constant<FreeFusion, FreeFusion::Dempster>{});
	};
	// Dempster's rule, however it is asked for, has a cell-by-cell fusion of
	// its own too.
	const bool dempster = bulkRule == FreeFusion::Dempster;
	const Mass& uniform = transform.uniformMass();

	const auto single = [&](CMotionDetector& detector, std::size_t idx, const Mass& observed,
							bool impact) {
		const ConflictSplit split = dempster
			? m_grid.fuseNormalized(idx, observed)
			: m_grid.fuse(idx, observed, rule, handling);
		detector.afterFusion(m_grid, idx, split, observed, impact);
	};
	// A free mass w finds an event only in a cell that already has one, or
	// whose n(O) w reaches the least conflict of a departure.
	const auto occupiedBelowFor = [&](double w) {
		return static_cast<std::uint16_t>(std::min(
			std::ceil(rules.minLeft / std::max(w, 1e-9) * kMassScale), kMassScale));
	};
	const double w = uniform.free;
	const std::uint16_t occupiedBelow = occupiedBelowFor(w);
	// Runs shorter than this are fused cell by cell (fewer instructions on
	// SENA and the stock scan, counted; from four cells the bulk's block of
	// four pays).
	constexpr std::size_t kFewCells = 4;
	const GridGeometry& g = geometry();
	motion.judgeCrossedArrivals(m_grid, [&](std::size_t idx) {
		return transform.crossedWithoutFreeEvidence(
			g.cellCenterX(g.columnOf(idx)), g.cellCenterY(g.rowOf(idx)));
	});

	// Each band of rows on its own thread: its cells, its impact cursor, its
	// candidates (every cell is fused by one band, and changes only itself).
	impacts.clearVisits();
	const auto fuseBand = [&](auto decays, TWorkspace::TFusionBand& band) {
		band.motion.begin(rules);
		auto hits = impacts.cursorFrom(g.index(0, band.firstRow));
		constexpr bool kDecays = decltype(decays)::value;
		const auto fuseRun = [&](std::size_t first, std::size_t count) {
			withBulkRule([&](auto bulk) {
				constexpr FreeFusion kRule = decltype(bulk)::value;
				// A run of a few cells (a quarter of SENA's), cell by cell as
				// the bulk's tail fuses them: the bulk's call and set-up cost
				// more than such a run's cells.
				if (count < kFewCells)
				{
					for (std::size_t idx = first; idx < first + count; ++idx)
						if (m_grid.isLoudFor<kRule>(idx, occupiedBelow))
							single(band.motion, idx, uniform, false);
						else
							m_grid.fuseSimpleFree<kDecays, false, kRule>(idx, static_cast<float>(w));
					return;
				}
				// The quiet cells in bulk, then the loud ones one by one, in
				// order (a cell's fusion reads only the cell).
				band.loud.clear();
				m_grid.fuseQuietFreeRun<kDecays, kRule>(
					first, count, static_cast<float>(w), occupiedBelow, band.loud);
				for (const std::size_t idx : band.loud) single(band.motion, idx, uniform, false);
			});
		};
		visitRowsCloned(
			transform, g, band.firstRow, band.lastRow,
			[&](std::size_t idx, const Mass& observed) {
				if (const double hit = hits.occupiedAt(idx); hit > 0.0)
				{
					m_grid.markImpact(idx);
					single(band.motion, idx, withImpact(observed, hit), true);
				}
				// Most mixes are along the angle only, a simple free mass: a
				// quiet cell takes it as the bulk does.
				// A cell quiet at the lowest threshold (1) is quiet at every w:
				// its own threshold, a division, is then not worked out.
				else if (
					observed.occupied == 0.0 && observed.conflict == 0.0 &&
					!(m_grid.isLoud(idx, 1) && m_grid.isLoud(idx, occupiedBelowFor(observed.free))) &&
					!(isCautious(bulkRule) && m_grid.holdsNoIgnorance(idx)))
					withBulkRule([&](auto bulk) {
						m_grid.fuseSimpleFree<kDecays, false, decltype(bulk)::value>(
							idx, static_cast<float>(observed.free));
					});
				else
					single(band.motion, idx, observed, false);
			},
			[&](std::size_t first, std::size_t count) {
				hits.splitRun(first, count, fuseRun, [&](std::size_t idx, double occupied) {
					m_grid.markImpact(idx);
					single(band.motion, idx, withImpact(uniform, occupied), true);
				});
			},
			[&](std::size_t first, std::size_t count) { m_grid.prefetchForWrite(first, count); });
	};
	const std::size_t used =
		m_workspace->fuseInBands(g, io.insertionThreads, m_grid.decayRate() > 0.0, fuseBand);
	for (std::size_t b = 0; b < used; ++b) motion.adoptCandidates(m_workspace->bands[b].motion);

	impacts.forEachUnvisited([&](std::size_t idx, double occupied) {
		m_grid.markImpact(idx);
		single(motion, idx, withImpact(Mass::vacuous(), occupied), true);
	});
	motion.settle(m_grid, impacts.cells().size(), transform.sensor().x, transform.sensor().y);
}

Motion CEvidentialGridMap2D::motionOf(std::size_t idx) const
{
	const CellEvent e = m_grid.event(idx);
	if (e != CellEvent::Appeared && e != CellEvent::Disappeared) return Motion::None;
	if (latestTime() - m_grid.eventTime(idx) > insertionOptions.motionWindow)
		return Motion::None;
	return e == CellEvent::Appeared ? Motion::Appeared : Motion::Disappeared;
}

Motion CEvidentialGridMap2D::getCellMotionByIndex(int cx, int cy) const
{
	if (!geometry().inside(cx, cy)) return Motion::None;
	return motionOf(geometry().index(cx, cy));
}

namespace
{
/** The cell holding (x, y), or nothing outside the grid (NaN included). */
std::optional<std::size_t> cellHolding(const GridGeometry& g, double x, double y)
{
	if (!(x >= g.xMin && x < g.xMax() && y >= g.yMin && y < g.yMax()))
		return std::nullopt;
	const int cx = g.cellX(x), cy = g.cellY(y);
	if (!g.inside(cx, cy)) return std::nullopt;
	return g.index(cx, cy);
}
}  // namespace

Motion CEvidentialGridMap2D::getCellMotion(double x, double y) const
{
	const auto idx = cellHolding(geometry(), x, y);
	return idx ? motionOf(*idx) : Motion::None;
}

double CEvidentialGridMap2D::getCellMotionTime(double x, double y) const
{
	const auto idx = cellHolding(geometry(), x, y);
	if (!idx || motionOf(*idx) == Motion::None)
		return std::numeric_limits<double>::quiet_NaN();
	return m_grid.eventTime(*idx);
}

CEvidentialGridMap2D::TMotionCounts CEvidentialGridMap2D::countMotion() const
{
	TMotionCounts counts;
	geometry().forEachIndex([&](std::size_t idx) {
		const Motion m = motionOf(idx);
		counts.appeared += m == Motion::Appeared;
		counts.disappeared += m == Motion::Disappeared;
	});
	return counts;
}

namespace
{
std::vector<std::pair<double, double>> centresOf(
	const CEvidentialGridMap2D& map, Motion wanted)
{
	std::vector<std::pair<double, double>> centres;
	const GridGeometry& g = map.geometry();
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
			if (map.getCellMotionByIndex(cx, cy) == wanted)
				centres.emplace_back(g.cellCenterX(cx), g.cellCenterY(cy));
	return centres;
}
}  // namespace

std::vector<std::pair<double, double>> CEvidentialGridMap2D::getAppearedCellCenters() const
{
	return centresOf(*this, Motion::Appeared);
}

std::vector<std::pair<double, double>>
	CEvidentialGridMap2D::getDisappearedCellCenters() const
{
	return centresOf(*this, Motion::Disappeared);
}
