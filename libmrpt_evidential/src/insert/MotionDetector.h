/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The motion layer's decisions: which conflicting fusions are something that
 * appeared or left, and which are the map's own noise. doc/dynamics.md gives
 * the reasons. */
#pragma once

#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mrpt_evidential
{
/** The motion layer's test of a mass for static structure: it leans
 * occupied (m(O) > m(F) and m(O) >= 0.5). */
inline bool leansOccupied(const Mass& m) { return m.occupied > m.free && m.occupied >= 0.5; }

/** What decides an event, from the map's insertion options (the defaults
 * are the map's). */
struct TMotionRules
{
	/** Least conflict of each cause for a fusion to be an event: seen free
	 * before and hit now (appeared), hit before and seen free now (left). */
	double minAppeared = 0.65, minLeft = 0.65;
	/** Changes within this many cells of static structure are taken for
	 * pose error. */
	int clearanceCells = 3;
	/** The reach, in cells, of a thing that moves (kThingSize): a pending
	 * arrival beside structure is confirmed only this close to an arrival in
	 * the open. */
	int thingCells = 10;
	/** Metres: the size of the things that move (people, boxes, carts, a
	 * door's leaf), whose faces reach out of the clearance of the structure
	 * they pass. */
	static constexpr double kThingSize = 0.5;
	/** Seconds of data time an event stays. */
	double window = 2.0;
	/** Arrivals within this many cells of a cell that leans occupied and
	 * is no thing that moved are taken for pose error. The sensor model's
	 * spread makes the cells in front of a face lean occupied, so this is
	 * the clearance less that spread (measured from the spread, not the
	 * face), at least the next cell; 0 with no clearance. */
	int arrivalClearanceCells = 1;
	/** The reach, in cells, between the hits of one thing's face
	 * (kFaceGap): a pending arrival is confirmed only this close to
	 * another arrival. */
	int faceGapCells = 2;
	/** Metres: beams half a degree apart end 9 cm apart on a face 10 m
	 * away. */
	static constexpr double kFaceGap = 0.1;
	/** Radians: the error of the robot's heading the layer is sized for (a
	 * SLAM front end's degree). It moves a face r metres from the sensor by
	 * up to r tan(kHeadingError), so a candidate's clearance
	 * (arrivalClearanceCells for an arrival, clearanceCells for a
	 * departure) grows to that many cells at its range: at 0.05 m cells two
	 * from 4.3 m, three from 7.2 m. No clearance (0) stays none. */
	static constexpr double kHeadingError = 0.017453292519943295;
	/** `threshold`, or less where a sight of mass `strongest` (muO for a
	 * hit, muF for a free sight) could not reach it from a cell kSureBefore
	 * sure of the other class: with the default masses motionMinConflict
	 * 0.65 asks that much (0.65 / 0.7) of a cell before a free sight
	 * counts, and weaker masses ask the same instead of nothing ever
	 * counting (a departure needs 0.65 of m(O) muF, out of reach with
	 * muF 0.6). A sight without mass (muF or muO 0) keeps `threshold`: a
	 * conflict of 0 is no event. */
	static double reachableConflict(double threshold, double strongest)
	{
		return strongest > 0.0 ? std::min(threshold, kSureBefore * strongest) : threshold;
	}
	static constexpr double kSureBefore = 0.93;
};

/** Collects a scan's candidate events as its cells are fused, then settles
 * them once every cell of the scan is fused (two phases, so that a decision
 * sees the whole scan, and every cell is fused once).
 *
 * - Something appeared: a cell seen free now holds a beam's end (conflict
 *   before(F) observed(O) of at least minAppeared). Beside what leans
 *   occupied and is not itself an arrival, of any age, leaving or another
 *   candidate arrival of the scan (within
 *   arrivalClearanceCells: a face, or the imprecision's spread in front of
 *   it; within the clearance: a face no beam ever crossed), or beside a
 *   cell never seen free (what stood hidden is seen for the first time),
 *   that is likely the pose's error: the cell
 *   is only pending (CellEvent::Leaving while it leans free) until one of
 *   the next kConfirmationInsertions insertions hits it again, beside a
 *   thing seen arriving in the open (besideOpenArrival) and within
 *   faceGapCells of another arrival (touchesArrival: a wall's end beside
 *   the door a person walks through is no part of the person). A first hit
 *   within faceGapCells of a recent arrival of an earlier insertion, beside
 *   a thing seen arriving in the open and next to no cell never seen free,
 *   is an arrival at once: the thing's face grows along what it covered
 *   (touchesEarlierArrival). A thing that
 *   arrived is hit again at once; a cell that pose error flips beside a wall
 *   or a thing's face comes and goes, so a pending arrival turned down (seen
 *   free) marks the cell flipped for good (never confirmed again), and a
 *   cell set back to no event within the last kFlipMemory insertions starts
 *   its next pending arrival dated from then, too old to be confirmed. An
 *   arrival hit again while it is recent is no candidate: it stays, with its
 *   time.
 * - Something left: a cell that leaned occupied and held beams' ends is
 *   seen free. While its evidence still leans occupied (a ray may have
 *   grazed a wall or a pillar, and the static map does not say free yet)
 *   the cell is only Leaving (not reported); once it no longer leans
 *   occupied, away from static structure and from cells never seen free
 *   (within the clearance: a wall's inside, or what lies behind a thin
 *   thing, behind a face that rays grazed), its departure is reported,
 *   dated from the first free sight. Beside structure it waits, still
 *   Leaving, until kDepartureWait insertions after that sight before it
 *   is taken for the pose's error: a thing's cells that turn free while
 *   its body still stands within the clearance (masses stronger than the
 *   defaults turn a cell in fewer sights) are reported once it has moved
 *   on. Only a leaving cell waits, not a pending arrival seen free (both
 *   are Leaving and lean free: the detector lists the leaving ones). A
 *   pending arrival seen free is no departure, wherever it lies: it was
 *   never reported, and the cell flips. An arrival stays while its thing
 *   does; a departure seen free again after its window is over.
 * - Far from the sensor the clearances grow: an error of the heading moves
 *   a face by more there (TMotionRules::kHeadingError), and the edge of
 *   what was never seen free (an arrival's reach to it grows the same way).
 * - A misplaced scan: when a large share of the cells a scan's beams ended
 *   in were seen free before (kMisplacedShare of them, and at least
 *   kMisplacedArrivals), the scan disagrees with the map as a whole. That
 *   is its pose's error, larger than motionClearance (odometry that
 *   drifted, a SLAM front end's jump), not the world: the scan's evidence
 *   is fused, but it settles no event. A thing that moves fills a small
 *   share of a scan's impact cells. */
class CMotionDetector
{
   public:
	void begin(const TMotionRules& rules)
	{
		m_rules = rules;
		m_candidates.clear();
		m_scanArrivals.clear();
	}

	/** After cell idx of `grid` has fused `observed`, with that fusion's
	 * conflict split; `impact`: a beam of the scan ended in the cell. */
	void afterFusion(
		EvidentialGridStorage& grid, std::size_t idx, const ConflictSplit& split,
		const Mass& observed, bool impact)
	{
		// Something appears where a beam ends, not in the cells around it
		// that the sensor model's imprecision reaches; something leaves a
		// cell that beams ended in.
		if (impact && split.appeared >= m_rules.minAppeared)
		{
			// A recent arrival hit again: the thing is still there, nothing
			// new (and no sign of a misplaced scan).
			if (!isRecentArrival(grid, idx)) m_candidates.push_back({idx, CellEvent::Appeared});
		}
		else if (split.disappeared >= m_rules.minLeft && grid.heldImpact(idx))
			m_candidates.push_back({idx, CellEvent::Disappeared});
		else if (const CellEvent e = grid.event(idx); e != CellEvent::None)
			afterFusionOfEventCell(grid, idx, e, observed, impact);
	}

	/** Before the scan's cells are fused: the recent arrivals that its beams
	 * crossed without giving them free evidence (within the free margin, or
	 * past the nearer sector's free limit beside what the other beam hit)
	 * are candidate departures all the same: an arrival is no wall to
	 * protect. */
	template <typename Crossed>
	void judgeCrossedArrivals(const EvidentialGridStorage& grid, Crossed&& crossed)
	{
		// A grid grown into a new block keeps its cells where they were, at
		// other indices: the lists follow them. A grid reset holds other
		// cells: the lists start again (its arrivals then last their window
		// at most). Growth into the room the grid kept moves no cell; a map
		// read from its file restores the lists (restore()).
		if (grid.layout() != m_listedLayout) restore(grid, memory(grid));
		std::size_t kept = 0;
		for (const std::size_t idx : m_arrivals)
		{
			if (grid.event(idx) != CellEvent::Appeared || !isRecent(grid, idx)) continue;
			m_arrivals[kept++] = idx;
			if (crossed(idx)) m_candidates.push_back({idx, CellEvent::Disappeared});
		}
		m_arrivals.resize(kept);
	}
	/** What the detector remembers from one scan to the next, part of the
	 * map's value (a copy, or a map read back from its file, must decide
	 * later scans as the original does): the recent arrivals, in the order
	 * they were set, and the departures under way, sorted, as indices of the
	 * grid's cells. */
	struct TMemory
	{
		std::vector<std::size_t> arrivals, leaving;
		/** The leaving list's length after its latest pruning (settle()). */
		std::size_t leavingKept = 0;
	};
	/** The memory in the indices of `grid` as it is now: followed through
	 * a growth into a new block since the latest scan, empty when the lists
	 * belong to another grid (one reset or read since). */
	TMemory memory(const EvidentialGridStorage& grid) const;
	/** Takes `memory` for the cells of `grid` as it is now. Its indices must
	 * be cells of `grid` and `leaving` sorted, without repeats (a file's
	 * reader checks both). */
	void restore(const EvidentialGridStorage& grid, TMemory memory);

	/** Appends the candidates `band` collected (a detector that only ran
	 * afterFusion() over a band of the scan's rows) to this scan's, and
	 * clears them there. */
	void adoptCandidates(CMotionDetector& band)
	{
		m_candidates.insert(m_candidates.end(), band.m_candidates.begin(), band.m_candidates.end());
		band.m_candidates.clear();
	}
	/** Settles the candidates of the scan, whose beams ended in
	 * `impactCells` cells, taken from (sensorX, sensorY) (metres, the
	 * grid's frame): none when the scan is a misplaced one (see the class).
	 * After judgeCrossedArrivals() of the same scan. */
	void settle(
		EvidentialGridStorage& grid, std::size_t impactCells, double sensorX, double sensorY);
	/** The rule of a misplaced scan (see the class). */
	static constexpr double kMisplacedShare = 0.2;
	static constexpr std::size_t kMisplacedArrivals = 8;
	/** Insertions a departure beside structure waits from its first free
	 * sight (see the class): the default masses need some eight free
	 * sights to turn a cell that stood long. */
	static constexpr std::size_t kDepartureWait = 8;

   private:
	/** A cell with an event that the scan saw without much conflict: an
	 * arrival now seen free, or a leaving cell seen free again, is judged
	 * again; a leaving cell seen occupied stays. */
	void afterFusionOfEventCell(
		EvidentialGridStorage& grid, std::size_t idx, CellEvent e,
		const Mass& observed, bool impact);
	/** True when a cell within `clearance` cells of idx (idx excluded) is static
	 * structure: it leans occupied, held beams' ends or was never seen free
	 * (a wall's inside), and stands still (standsStill: no thing that
	 * moved). */
	bool nearStaticStructure(
		const EvidentialGridStorage& grid, std::size_t idx, int clearance) const;
	/** True when a cell within `reach` cells of idx was never seen free
	 * (n(F) = 0; an arrival's cell counts as seen): a hit next to one is the
	 * first sight of what stood hidden behind it (a block's corner, a wall's
	 * end), and a cell turned free within the clearance of one is a face
	 * that rays grazed, not a change of what the map had seen. */
	static bool besideUnseen(const EvidentialGridStorage& grid, std::size_t idx, int reach);
	/** True when a cell near idx (idx excluded) leans occupied and is not
	 * an arrival or leaving, within `near` cells (a face the
	 * pose's error moves, or the imprecision's spread in front of it, which
	 * was seen free before it leaned occupied), or within clearanceCells
	 * and never seen free (a face seen at a grazing angle, whose spread
	 * lies along it, not in front). A thing that walks on leaves no spread
	 * behind that leans occupied: one scan's spread does not turn a free
	 * cell. */
	bool besideOccupied(const EvidentialGridStorage& grid, std::size_t idx, int near) const;
	/** True when a recent arrival within thingCells of idx (idx excluded)
	 * lies in the open: away from static structure and from cells never seen
	 * free. A thing that moves shows faces out of the clearance of what it
	 * passes; hits that stay within it, along a face, are the pose's error. */
	bool besideOpenArrival(const EvidentialGridStorage& grid, std::size_t idx) const;
	/** True when an arrival, a pending arrival or a candidate arrival of
	 * the scan lies within faceGapCells of idx (idx excluded): idx is part
	 * of a thing's face, not a wall's end that a thing passes. */
	bool touchesArrival(const EvidentialGridStorage& grid, std::size_t idx) const;
	/** True when a recent arrival of an earlier insertion lies within
	 * faceGapCells of idx (idx excluded): a thing seen arriving whose face
	 * idx extends. */
	bool touchesEarlierArrival(const EvidentialGridStorage& grid, std::size_t idx) const;
	/** The cell leans occupied and is no thing that moved: a thing that
	 * arrived, however long ago, is no structure (its sides, first seen
	 * later, are arrivals too), nor is a cell leaving, nor a candidate
	 * arrival of the scan (a thing's new face, each cell of which may lean
	 * occupied after its first hit). */
	bool standsStill(const EvidentialGridStorage& grid, std::size_t cell) const;
	bool isScanArrival(std::size_t idx) const
	{
		return std::binary_search(m_scanArrivals.begin(), m_scanArrivals.end(), idx);
	}
	bool isRecent(const EvidentialGridStorage& grid, std::size_t idx) const
	{
		return grid.latestTime() - grid.eventTime(idx) <= m_rules.window;
	}
	bool isRecentArrival(const EvidentialGridStorage& grid, std::size_t idx) const
	{
		return grid.event(idx) == CellEvent::Appeared && isRecent(grid, idx);
	}
	/** The cell is listed as a departure under way: while its event is
	 * Leaving, it is not a pending arrival. */
	bool isLeaving(std::size_t idx) const
	{
		return std::binary_search(m_leaving.begin(), m_leaving.end(), idx);
	}
	/** The rules of a pending arrival, in insertions (see the class). */
	static constexpr std::size_t kConfirmationInsertions = 2, kFlipMemory = 40;
	/** Settles the candidate arrival at cell idx, whose event was `before`;
	 * `near`: its reach to a face (arrivalClearanceCells, grown with its
	 * range). */
	void settleArrival(
		EvidentialGridStorage& grid, std::size_t idx, CellEvent before, int near);
	/** Settles the candidate departure at cell idx, whose event was
	 * `before`; `clearance`: clearanceCells, grown with its range. */
	void settleDeparture(
		EvidentialGridStorage& grid, std::size_t idx, CellEvent before, int clearance);
	/** Adds the scan's leaving cells to m_leaving. */
	void listScanLeaving();

	struct TCandidate
	{
		std::size_t index;
		CellEvent event;
	};
	TMotionRules m_rules;
	std::vector<TCandidate> m_candidates;
	/** The scan's candidate arrivals, sorted, while they are settled. */
	std::vector<std::size_t> m_scanArrivals;
	/** Cells set Appeared, to find those that later scans cross,
	 * at their indices in the grid of layout `m_listedLayout`. */
	std::vector<std::size_t> m_arrivals;
	/** Cells set Leaving as departures under way, sorted, at their indices
	 * in the grid of layout `m_listedLayout` (followed when the grid grows
	 * into a new block; a grid reset starts the list again, and its leaving
	 * cells are then judged as pending arrivals are);
	 * those set by the scan being settled, merged once it is. A cell
	 * judged since may stay listed until the list is pruned (settle()). */
	std::vector<std::size_t> m_leaving, m_scanLeaving;
	/** The list's length after its latest pruning, and the growth beyond
	 * twice that which prunes it again. */
	std::size_t m_leavingKept = 0;
	static constexpr std::size_t kLeavingSlack = 256;
	std::size_t m_listedLayout = 0;
};

}  // namespace mrpt_evidential
