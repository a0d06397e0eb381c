/* evgrid score-motion: the map's motion layer against the truth, summed over
 * the scans. */

#include "CMotionScorer.h"

#include "CObservedCells.h"
#include "CTruthEvents.h"

using mrpt_evidential::Motion;

namespace evgrid
{
CMotionScorer::CMotionScorer(const CMotionTruth& truth, int tolerance)
	: m_grid(truth.grid()),
	  m_tolerance(tolerance),
	  m_static(m_grid.cellCount(), false),
	  m_motion(m_grid.cellCount(), Motion::None),
	  m_near(m_grid)
{
	for (const int cell : truth.staticCells())
		m_static[cell] = true;
}

void CMotionScorer::score(
	const mrpt_evidential::CEvidentialGridMap2D& map,
	const CObservedCells& seen, const CTruthEvents& events, std::size_t k,
	double time, const mrpt::poses::CPose2D& toMap)
{
	const int cells = static_cast<int>(m_grid.cellCount());
	const bool moved = toMap.x() != 0.0 || toMap.y() != 0.0 || toMap.phi() != 0.0;
	for (int cell = 0; cell < cells; ++cell)
	{
		double x = m_grid.centreX(cell), y = m_grid.centreY(cell);
		if (moved) toMap.composePoint(x, y, x, y);
		m_motion[cell] = map.getCellMotion(x, y);
	}
	++m_totals.scans;
	m_totals.hitCells += seen.hit().size();
	m_totals.crossedCells += seen.crossed().size();

	// Appeared things are where beams end, left cells where beams pass.
	m_truth.clear();
	for (const int cell : seen.hit())
		if (events.appeared(cell)) m_truth.push_back(cell);
	scoreKind(
		Motion::Appeared, m_truth, seen.observed(),
		[&](int cell) { return events.appeared(cell); }, m_totals.appeared);
	m_truth.clear();
	for (const int cell : seen.crossed())
		if (events.disappeared(cell)) m_truth.push_back(cell);
	scoreKind(
		Motion::Disappeared, m_truth, seen.observed(),
		[&](int cell) { return events.disappeared(cell); }, m_totals.disappeared);
	scoreStatic(map, seen, k, time);
}

void CMotionScorer::scoreKind(
	Motion kind, const std::vector<int>& truth, const std::vector<int>& observed,
	const std::function<bool(int)>& isTruth, TKindScore& out)
{
	m_predicted.clear();
	for (const int cell : observed)
		if (m_motion[cell] == kind) m_predicted.push_back(cell);
	m_whole.clear();
	for (int cell = 0, n = static_cast<int>(m_motion.size()); cell < n; ++cell)
		if (m_motion[cell] == kind) m_whole.push_back(cell);
	out.truth += truth.size();
	out.predicted += m_predicted.size();
	out.mapCells += m_whole.size();

	// Each table costs a pass over the grid: built only when asked. Both
	// sides are matched against the other's whole set: the map may flag a
	// thing from where this scan did not look, and a flag may stand beside
	// a cell of the thing this scan did not reach.
	if (!m_predicted.empty())
	{
		m_truthWhole.clear();
		for (int cell = 0, n = static_cast<int>(m_motion.size()); cell < n; ++cell)
			if (isTruth(cell)) m_truthWhole.push_back(cell);
		m_near.assign(m_truthWhole);
		for (const int cell : m_predicted)
			out.truePositives += m_near.anyWithin(cell, m_tolerance);
	}
	if (!truth.empty())
	{
		m_near.assign(m_whole);
		for (const int cell : truth)
			out.recalled += m_near.anyWithin(cell, m_tolerance);
	}
}

void CMotionScorer::scoreStatic(
	const mrpt_evidential::CEvidentialGridMap2D& map, const CObservedCells& seen,
	std::size_t k, double time)
{
	const auto flags = [&](int cell) {
		return map.getCellMotion(m_grid.centreX(cell), m_grid.centreY(cell)) != Motion::None;
	};
	std::size_t observed = 0, flagged = 0;
	for (const int cell : seen.observed())
	{
		if (!m_static[cell]) continue;
		++observed;
		flagged += flags(cell);
	}
	TStaticScore& s = m_totals.statics;
	s.observed += observed;
	s.flagged += flagged;
	if (observed == 0) return;
	++s.scans;
	const double share =
		static_cast<double>(flagged) / static_cast<double>(observed);
	s.shareSum += share;
	if (share > s.worstShare)
	{
		s.worstShare = share;
		s.worstScan = k;
		s.worstTime = time;
		s.worstCells.clear();
		for (const int cell : seen.observed())
			if (m_static[cell] && flags(cell))
				s.worstCells.emplace_back(m_grid.centreX(cell), m_grid.centreY(cell));
	}
}

}  // namespace evgrid
