/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The motion layer's decisions: which conflicting fusions are something that
 * appeared or left, and which are the map's own noise. doc/dynamics.md gives
 * the reasons. */
#pragma once

#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include <cstddef>
#include <vector>

namespace mrpt_evidential
{
/** What decides an event, from the map's insertion options. */
struct TMotionRules
{
	/** Least conflict of one cause (appeared or left) for a fusion to be an
	 * event. */
	double minConflict = 0.5;
	/** Changes within this many cells of static structure are taken for
	 * pose error. */
	int clearanceCells = 3;
	/** Seconds of data time an event stays. */
	double window = 2.0;
};

/** Collects a scan's candidate events as its cells are fused, then settles
 * them once every cell of the scan is fused (two phases, so that a decision
 * sees the whole scan, and every cell is fused once).
 *
 * - Something appeared: a cell seen free is now occupied (conflict
 *   before(F) observed(O) of at least minConflict), away from static
 *   structure (a cell that leans occupied and is not itself a recent
 *   arrival or leaving).
 * - Something left: a cell that leaned occupied is seen free. Until its
 *   evidence leans free it is only Leaving (a ray that grazes a wall is not
 *   a wall that left); then it is Disappeared, dated from the first free
 *   sight, if it is away from static structure. */
class CMotionDetector
{
   public:
	void begin(const TMotionRules& rules)
	{
		m_rules = rules;
		m_candidates.clear();
	}

	/** After cell idx of `grid` has fused `observed`, with that fusion's
	 * conflict split. */
	void afterFusion(
		EvidentialGridStorage& grid, std::size_t idx, const ConflictSplit& split,
		const Mass& observed)
	{
		if (split.appeared >= m_rules.minConflict)
			m_candidates.push_back({idx, CellEvent::Appeared});
		else if (split.disappeared >= m_rules.minConflict)
			m_candidates.push_back({idx, CellEvent::Disappeared});
		else if (const CellEvent e = grid.event(idx); e != CellEvent::None)
			afterFusionOfEventCell(grid, idx, e, observed);
	}

	/** Settles the candidates of the scan. */
	void settle(EvidentialGridStorage& grid) const;

   private:
	/** A cell with an event that the scan saw without much conflict: an
	 * arrival now seen free, or a leaving cell seen free again, is judged
	 * again; a leaving cell seen occupied stays. */
	void afterFusionOfEventCell(
		EvidentialGridStorage& grid, std::size_t idx, CellEvent e,
		const Mass& observed);
	/** True when a cell within clearanceCells of idx (idx excluded) is static
	 * structure. */
	bool nearStaticStructure(const EvidentialGridStorage& grid, std::size_t idx) const;
	bool isRecent(const EvidentialGridStorage& grid, std::size_t idx) const
	{
		return grid.latestTime() - grid.eventTime(idx) <= m_rules.window;
	}

	struct TCandidate
	{
		std::size_t index;
		CellEvent event;
	};
	TMotionRules m_rules;
	std::vector<TCandidate> m_candidates;
};

}  // namespace mrpt_evidential
