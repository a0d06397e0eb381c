/* evgrid score-motion: the map's motion layer against the truth, summed over
 * the scans. */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/Motion.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "CMotionTruth.h"
#include "CNearCells.h"

namespace evgrid
{
class CObservedCells;
class CTruthEvents;

/** The counts of one kind of motion (Appeared or Disappeared), summed over
 * the scans scored. */
struct TKindScore
{
	/** Truth cells, and those the map's whole set of the kind holds a cell
	 * near. */
	std::size_t truth = 0, recalled = 0;
	/** Observed cells the map flags with the kind, and those a cell of the
	 * truth's whole set of the kind (observed by the scan or not) lies
	 * near. */
	std::size_t predicted = 0, truePositives = 0;
	/** Cells of the truth's grid the map flags with the kind, observed or
	 * not. */
	std::size_t mapCells = 0;
};

/** The static cells (walls, furniture) the map flags as moving. */
struct TStaticScore
{
	/** Observed static cells and those flagged, summed over the scans. */
	std::size_t observed = 0, flagged = 0;
	/** Scans that observed a static cell, and the sum of their shares. */
	std::size_t scans = 0;
	double shareSum = 0;
	/** The scan of the largest share (the first of equal ones); share -1
	 * when no scan observed a static cell. */
	double worstShare = -1, worstTime = 0;
	std::size_t worstScan = 0;
	/** The centres (x, y in metres) of the static cells that scan flagged: where
	 * to look in the map's motion picture. */
	std::vector<std::pair<double, double>> worstCells;
};

struct TMotionScore
{
	std::size_t scans = 0;
	/** Hit and crossed cells, summed over the scans. */
	std::size_t hitCells = 0, crossedCells = 0;
	TKindScore appeared, disappeared;
	TStaticScore statics;
};

/** Scores the map after each scan: the truth's events among the cells the
 * scan observed against the map's motion read at the truth cells' centres,
 * a truth cell recalled when a cell of the map's whole set lies within
 * `tolerance` cells (Chebyshev), a predicted (observed) cell right when a
 * cell of the truth's whole set does. */
class CMotionScorer
{
   public:
	CMotionScorer(const CMotionTruth& truth, int tolerance);

	/** Scores the map just after it took scan k, at `time` (seconds from
	 * scan 0), whose observed cells are `seen`, the truth being at scan k.
	 * The motion of a truth cell is read in the map at `toMap` composed
	 * with its centre (the identity: at the centre itself); the static
	 * cells' at their centres. */
	void score(
		const mrpt_evidential::CEvidentialGridMap2D& map,
		const CObservedCells& seen, const CTruthEvents& events, std::size_t k,
		double time, const mrpt::poses::CPose2D& toMap = {});

	const TMotionScore& totals() const { return m_totals; }

   private:
	/** Scores one kind: `truth`, its truth cells among the observed ones;
	 * `isTruth`, whether any cell of the grid holds a truth event of it. */
	void scoreKind(
		mrpt_evidential::Motion kind, const std::vector<int>& truth,
		const std::vector<int>& observed, const std::function<bool(int)>& isTruth,
		TKindScore& out);
	/** The static cells the scan observed, the map read at their centres. */
	void scoreStatic(
		const mrpt_evidential::CEvidentialGridMap2D& map, const CObservedCells& seen,
		std::size_t k, double time);

	const TTruthGrid& m_grid;
	int m_tolerance;
	std::vector<bool> m_static;
	/** The map's motion at each truth cell's centre (moved into the scan's
	 * frame when asked), this scan. */
	std::vector<mrpt_evidential::Motion> m_motion;
	CNearCells m_near;
	std::vector<int> m_truth, m_truthWhole, m_predicted, m_whole;
	TMotionScore m_totals;
};

}  // namespace evgrid
