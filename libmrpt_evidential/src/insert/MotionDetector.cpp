/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "insert/MotionDetector.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mrpt_evidential
{
namespace
{
/** Time of the insertion `k` insertions before the latest (the oldest one
 * kept, if there are not that many). */
double insertionTimeBefore(const EvidentialGridStorage& grid, std::size_t k)
{
	const std::vector<double>& times = grid.stampTimes();
	return times.size() > k ? times[times.size() - 1 - k] : times.front();
}

/** The cell leans occupied and has no event of a thing that moved. */
bool leansOccupiedWithoutEvent(const EvidentialGridStorage& grid, std::size_t cell)
{
	if (!leansOccupied(grid.read(cell))) return false;
	const CellEvent e = grid.event(cell);
	return e != CellEvent::Leaving && e != CellEvent::Appeared;
}

/** The cells within `r` cells of idx (a square, cut at the grid's edges). */
struct TWindow
{
	int x0, x1, y0, y1;
};
TWindow windowAround(const GridGeometry& g, std::size_t idx, int r)
{
	const int cx = g.columnOf(idx), cy = g.rowOf(idx);
	return {std::max(0, cx - r), std::min(g.sizeX - 1, cx + r), std::max(0, cy - r),
			std::min(g.sizeY - 1, cy + r)};
}

/** True when `pred` holds for a cell within `r` cells of idx, idx excluded. */
template <typename Pred>
bool anyAround(const GridGeometry& g, std::size_t idx, int r, Pred&& pred)
{
	const TWindow w = windowAround(g, idx, r);
	for (int y = w.y0; y <= w.y1; ++y)
		for (int x = w.x0; x <= w.x1; ++x)
			if (const std::size_t cell = g.index(x, y); cell != idx && pred(cell)) return true;
	return false;
}
}  // namespace

bool CMotionDetector::standsStill(const EvidentialGridStorage& grid, std::size_t cell) const
{
	return leansOccupiedWithoutEvent(grid, cell) && !isScanArrival(cell);
}

void CMotionDetector::afterFusionOfEventCell(
	EvidentialGridStorage& grid, std::size_t idx, CellEvent e, const Mass& observed,
	bool impact)
{
	const bool seenFree = observed.free > observed.occupied;
	// Seen occupied: a beam ends in the cell, not the imprecision's spread
	// of one that ends beside it.
	const bool seenOccupied = impact && observed.occupied > observed.free;
	if ((e == CellEvent::Appeared || e == CellEvent::Leaving) && seenFree)
		m_candidates.push_back({idx, CellEvent::Disappeared});
	else if (e == CellEvent::Disappeared && seenOccupied)
		m_candidates.push_back({idx, CellEvent::Appeared});
	else if (e == CellEvent::Disappeared && !isRecent(grid, idx))
		// Seen free again after its window: the event is over. Clearing it
		// keeps the cell out of the slow path of later scans. An arrival
		// stays while the thing does: it is no structure (see
		// nearStaticStructure), and its leaving is a departure.
		grid.setEvent(idx, CellEvent::None);
	else if (e == CellEvent::Leaving && seenOccupied)
		grid.setEvent(idx, CellEvent::None);
}

bool CMotionDetector::nearStaticStructure(
	const EvidentialGridStorage& grid, std::size_t idx, int clearance) const
{
	const GridGeometry& g = grid.geometry();
	const TWindow w = windowAround(g, idx, clearance);
	for (int y = w.y0; y <= w.y1; ++y)
		for (int x = w.x0; x <= w.x1;)
		{
			// Most cells are not structure; the exact test is for the few
			// whose stored values may be.
			const int n = std::min(w.x1 - x + 1, EvidentialGridStorage::kMaskWidth);
			std::uint32_t maybe = grid.mayBeStructure(g.index(x, y), n);
			for (; maybe != 0; maybe &= maybe - 1)
			{
				const std::size_t cell = g.index(x + __builtin_ctz(maybe), y);
				if (cell != idx && standsStill(grid, cell)) return true;
			}
			x += n;
		}
	return false;
}

bool CMotionDetector::besideUnseen(
	const EvidentialGridStorage& grid, std::size_t idx, int reach)
{
	const GridGeometry& g = grid.geometry();
	const TWindow w = windowAround(g, idx, reach);
	for (int y = w.y0; y <= w.y1; ++y)
		for (int x = w.x0; x <= w.x1; ++x)
		{
			// An arrival was seen free before its thing came, however
			// little free mass its hits left it.
			const std::size_t cell = g.index(x, y);
			if (grid.neverSeenFree(cell) && grid.event(cell) != CellEvent::Appeared)
				return true;
		}
	return false;
}

bool CMotionDetector::besideOccupied(
	const EvidentialGridStorage& grid, std::size_t idx, int near) const
{
	const GridGeometry& g = grid.geometry();
	const int cx = g.columnOf(idx), cy = g.rowOf(idx);
	return anyAround(g, idx, std::max(near, m_rules.clearanceCells), [&](std::size_t cell) {
		// Farther than the next cells, only what no beam ever crossed: a
		// face seen at a grazing angle, whose spread lies along it.
		const bool nearby =
			std::max(std::abs(g.columnOf(cell) - cx), std::abs(g.rowOf(cell) - cy)) <= near;
		return (nearby || grid.neverSeenFree(cell)) && standsStill(grid, cell);
	});
}

bool CMotionDetector::besideOpenArrival(
	const EvidentialGridStorage& grid, std::size_t idx) const
{
	return anyAround(grid.geometry(), idx, m_rules.thingCells, [&](std::size_t cell) {
		return isRecentArrival(grid, cell) && !nearStaticStructure(grid, cell, m_rules.clearanceCells) &&
			!besideUnseen(grid, cell, 1);
	});
}

bool CMotionDetector::touchesArrival(
	const EvidentialGridStorage& grid, std::size_t idx) const
{
	return anyAround(grid.geometry(), idx, m_rules.faceGapCells, [&](std::size_t cell) {
		// A pending arrival leans free; a leaving cell leans occupied or,
		// waiting beside structure, is listed.
		const CellEvent e = grid.event(cell);
		return e == CellEvent::Appeared ||
			(e == CellEvent::Leaving && !leansOccupied(grid.read(cell)) && !isLeaving(cell)) ||
			isScanArrival(cell);
	});
}

bool CMotionDetector::touchesEarlierArrival(
	const EvidentialGridStorage& grid, std::size_t idx) const
{
	return anyAround(grid.geometry(), idx, m_rules.faceGapCells, [&](std::size_t cell) {
		return isRecentArrival(grid, cell) && grid.eventTime(cell) < grid.latestTime();
	});
}

void CMotionDetector::settleArrival(
	EvidentialGridStorage& grid, std::size_t idx, CellEvent before, int near)
{
	// A leaving cell waiting beside structure hit again: what left it is
	// back, or the pose's error that turned it has turned back.
	if (before == CellEvent::Leaving && isLeaving(idx))
	{
		grid.setEvent(idx, CellEvent::None);
		return;
	}
	// What stood hidden and is seen for the first time lies next to cells
	// never seen free; far from the sensor, within what the heading's error
	// moves them by (an unseen room's edge, seen at a grazing angle).
	const bool unseen = besideUnseen(grid, idx, std::max(1, near));
	if (!unseen && !besideOccupied(grid, idx, near))
	{
		grid.setEvent(idx, CellEvent::Appeared), m_arrivals.push_back(idx);
		return;
	}
	const double since = grid.eventTime(idx);
	if (before == CellEvent::Leaving)
	{
		// Pending: confirmed by a hit at one of the next insertions, unless
		// the cell has flipped before, and only as part of a thing seen
		// arriving in the open.
		const bool confirmed = !leansOccupied(grid.read(idx)) && !grid.flipped(idx) &&
			since < grid.latestTime() &&
			since >= insertionTimeBefore(grid, kConfirmationInsertions) &&
			touchesArrival(grid, idx) && besideOpenArrival(grid, idx);
		if (confirmed) grid.setEventKeepingTime(idx, CellEvent::Appeared), m_arrivals.push_back(idx);
		return;
	}
	// The first hit beside structure: at once when it extends the face of
	// a thing seen arriving at an earlier insertion, in the open (not the
	// first sight of what stood hidden, nor a cell that flips).
	if (before == CellEvent::None && !unseen && !grid.flipped(idx) &&
		touchesEarlierArrival(grid, idx) && besideOpenArrival(grid, idx))
	{
		grid.setEvent(idx, CellEvent::Appeared), m_arrivals.push_back(idx);
		return;
	}
	// A cell with no event whose time is later than the oldest one was set
	// back to none by a recent judgement (most often a pending arrival seen
	// free): a flip, whose new pending arrival keeps that older time.
	const bool flips = before == CellEvent::None && since > grid.stampTimes().front() &&
		since >= insertionTimeBefore(grid, kFlipMemory);
	if (flips)
		grid.setEventKeepingTime(idx, CellEvent::Leaving);
	else
		grid.setEvent(idx, CellEvent::Leaving);
	// A pending arrival is no departure under way, whatever the cell was
	// listed as before.
	const auto listed = std::lower_bound(m_leaving.begin(), m_leaving.end(), idx);
	if (listed != m_leaving.end() && *listed == idx) m_leaving.erase(listed);
}

void CMotionDetector::settleDeparture(
	EvidentialGridStorage& grid, std::size_t idx, CellEvent before, int clearance)
{
	if (leansOccupied(grid.read(idx)))
	{
		// Still leaning occupied: a ray may have grazed it (a wall's face,
		// with the pose's error), and the static map does not say free yet.
		// Remember when this began.
		if (before != CellEvent::Leaving)
		{
			grid.setEvent(idx, CellEvent::Leaving);
			if (!isLeaving(idx)) m_scanLeaving.push_back(idx);
		}
		return;
	}
	if (before == CellEvent::Leaving && !isLeaving(idx))
	{
		// A pending arrival turned down: it was never reported, so neither
		// is its leaving, wherever it lies (in the open too: it was pending
		// for what stood near it when it was hit, from a range the clearances
		// are judged at no longer). The cell flips.
		grid.markFlipped(idx);
		grid.setEvent(idx, CellEvent::None);
		return;
	}
	if (!nearStaticStructure(grid, idx, clearance) && !besideUnseen(grid, idx, clearance))
	{
		// Free now, and nothing stands beside it that could explain a ray
		// through it: no structure, and no unseen inside of a wall whose
		// face a ray grazed (the face's cells then all turn free together,
		// and none of them counts as structure). That inside may lie a row
		// or two behind the face: a thin thing (a door's leaf) is a face, a
		// row of cells rays crossed at times, and what no ray reached,
		// within the clearance.
		if (before == CellEvent::Leaving)
			grid.setEventKeepingTime(idx, CellEvent::Disappeared);
		else
			grid.setEvent(idx, CellEvent::Disappeared);
		return;
	}
	// Beside structure: a leaving cell (a departure under way: the pending
	// arrivals were settled above) waits for the thing to move on.
	const bool waits = before == CellEvent::Leaving &&
		grid.eventTime(idx) > insertionTimeBefore(grid, kDepartureWait);
	if (waits) return;
	// Free again beside structure after the wait (a grazed cell that turned
	// free): the cell flips.
	if (before == CellEvent::Leaving) grid.markFlipped(idx);
	grid.setEvent(idx, CellEvent::None);
}

CMotionDetector::TMemory CMotionDetector::memory(const EvidentialGridStorage& grid) const
{
	TMemory kept;
	if (m_listedLayout == 0) return kept;
	const bool grown = grid.layout() != m_listedLayout;
	if (grown && grid.grownFromLayout() != m_listedLayout) return kept;
	kept.arrivals = m_arrivals;
	kept.leaving = m_leaving;
	kept.leavingKept = m_leavingKept;
	if (grown)
	{
		// Growth keeps the cells' order: the leaving list stays sorted.
		for (std::size_t& idx : kept.arrivals) idx = grid.indexAfterGrowth(idx);
		for (std::size_t& idx : kept.leaving) idx = grid.indexAfterGrowth(idx);
	}
	return kept;
}

void CMotionDetector::restore(const EvidentialGridStorage& grid, TMemory memory)
{
	m_arrivals = std::move(memory.arrivals);
	m_leaving = std::move(memory.leaving);
	m_leavingKept = memory.leavingKept;
	m_listedLayout = grid.layout();
}

void CMotionDetector::listScanLeaving()
{
	if (m_scanLeaving.empty()) return;
	std::sort(m_scanLeaving.begin(), m_scanLeaving.end());
	const auto middle = static_cast<std::ptrdiff_t>(m_leaving.size());
	m_leaving.insert(m_leaving.end(), m_scanLeaving.begin(), m_scanLeaving.end());
	std::inplace_merge(m_leaving.begin(), m_leaving.begin() + middle, m_leaving.end());
	m_scanLeaving.clear();
}

void CMotionDetector::settle(
	EvidentialGridStorage& grid, std::size_t impactCells, double sensorX, double sensorY)
{
	// A listed cell is a departure under way only while its event is
	// Leaving (every use of the list asks both), so the cells judged since
	// (reported, set back) can stay listed for a while: they leave the list
	// once it has doubled, not at every scan (it holds thousands of cells on
	// a long run, grazed faces that never turned free).
	if (m_leaving.size() > 2 * m_leavingKept + kLeavingSlack)
	{
		m_leaving.erase(
			std::remove_if(m_leaving.begin(), m_leaving.end(),
						   [&](std::size_t idx) { return grid.event(idx) != CellEvent::Leaving; }),
			m_leaving.end());
		m_leavingKept = m_leaving.size();
	}
	const auto arrivals = static_cast<std::size_t>(std::count_if(
		m_candidates.begin(), m_candidates.end(),
		[](const TCandidate& c) { return c.event == CellEvent::Appeared; }));
	if (arrivals >= kMisplacedArrivals &&
		static_cast<double>(arrivals) >= kMisplacedShare * static_cast<double>(impactCells))
	{
		m_candidates.clear();
		return;
	}
	// The scan's candidate arrivals, whatever the order they are settled
	// in: no structure for each other (standsStill), and the face a pending
	// arrival may be part of (touchesArrival).
	m_scanArrivals.clear();
	for (const TCandidate& c : m_candidates)
		if (c.event == CellEvent::Appeared) m_scanArrivals.push_back(c.index);
	std::sort(m_scanArrivals.begin(), m_scanArrivals.end());
	const GridGeometry& g = grid.geometry();
	const double cellsPerMetre = std::tan(TMotionRules::kHeadingError) / g.resolution;
	for (const TCandidate& c : m_candidates)
	{
		// The arrival's reach to a face grows with range, or the
		// departure's clearance (an arrival's test of the recent arrivals
		// around it keeps the rules' own).
		const int atRange = m_rules.clearanceCells == 0 ? 0 : static_cast<int>(std::lround(
			std::hypot(g.cellCenterX(g.columnOf(c.index)) - sensorX,
					   g.cellCenterY(g.rowOf(c.index)) - sensorY) *
			cellsPerMetre));
		const CellEvent before = grid.event(c.index);
		if (c.event == CellEvent::Appeared)
			settleArrival(grid, c.index, before, std::max(m_rules.arrivalClearanceCells, atRange));
		else
			settleDeparture(grid, c.index, before, std::max(m_rules.clearanceCells, atRange));
	}
	listScanLeaving();
}

}  // namespace mrpt_evidential
