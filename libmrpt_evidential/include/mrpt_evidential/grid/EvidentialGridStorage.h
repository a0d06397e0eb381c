/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Storage of an evidential grid: 8-byte cells, their lazy decay and the
 * fusions that update them. Standard library only; the MRPT map class is
 * built on it. */
#pragma once

#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/grid/CellBlock.h>
#include <mrpt_evidential/grid/GridGeometry.h>
#include <mrpt_evidential/grid/QuantizedMass.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt_evidential
{
/** The rule by which the bulk kernels fuse a simple free mass into a cell of
 * a grid without conflict. */
enum class FreeFusion
{
	/** Dempster's rule: the conflict normalized away. */
	Dempster,
	/** Yager's rule: the conflict to Omega (for masses without conflict, on
	 * {F, O}, also Dubois and Prade's rule). */
	Yager,
	/** Denoeux's cautious rule, its conflict normalized away. */
	CautiousNormalized,
	/** Denoeux's cautious rule, its conflict to Omega. */
	CautiousToUnknown
};
/** True for the cautious rule, however its conflict is handled. */
constexpr bool isCautious(FreeFusion rule)
{
	return rule == FreeFusion::CautiousNormalized || rule == FreeFusion::CautiousToUnknown;
}

namespace detail
{
/** The data of an EvidentialGridStorage, apart so that a move can leave the
 * grid it moves from as the default constructor makes it (an empty grid
 * whose invariants hold) instead of a geometry without its cells. */
struct TGridStorageState
{
	GridGeometry m_geometry;
	CellBlock m_cells;
	/** See layout(); 0 for the empty grid of the default constructor. */
	std::size_t m_layout = 0;
	/** The latest growth into a new block: the layout and geometry before
	 * it, and the columns and rows it added before the old cells. */
	struct TGrowth
	{
		std::size_t layout = 0;
		GridGeometry geometry;
		int dx = 0, dy = 0;
	} m_grownFrom;
	double m_decayRate = 0.0;
	bool m_keepsConflict = true;
	/** Every cell vacuous since reset(), no insertion begun and nothing
	 * assigned: setKeepsConflict() has no cell to convert. (Cells change only
	 * within an insertion, after beginInsertion().) */
	bool m_pristine = true;
	double m_eventRetention = 0.0;
	/** kMaxCertainty in stored units, or the scale itself when the grid
	 * keeps conflict. */
	std::uint16_t m_ceiling = static_cast<std::uint16_t>(kMassScale);
	/** Time of each stamp; stamp 0 is the oldest. Never empty. */
	std::vector<double> m_stampTimes{0.0};
	/** exp(decayRate (time of stamp - oldest)) and exp(-decayRate (latest -
	 * oldest)): their product is a stamp's decay factor, one multiplication
	 * per cell read instead of an exp. */
	std::vector<double> m_stampGain{1.0};
	double m_presentGain = 1.0;
	std::uint16_t m_currentStamp = 0;
	std::size_t m_insertions = 0;
};
}  // namespace detail

/** The cells of an evidential grid with their decay and motion events.
 *
 * Decay is classical discounting with rate 1 - exp(-decayRate dt) after dt
 * seconds of data time. It is applied lazily: every cell carries the stamp of
 * the insertion that last wrote it, and reading a cell discounts it from that
 * stamp's time to the latest insertion's time. The cost of an insertion
 * therefore depends on the cells it writes, not on the size of the grid.
 * Once in a long while (kMaxStamps distinct insertion times, or
 * exp(decayRate dt) about to lose precision) every cell is decayed to the
 * present and the stamps start again: O(cells), amortized over thousands of
 * insertions.
 *
 * A grid either keeps conflict (keepsConflict(): each cell's m(empty) grows
 * with every conflicting fusion) or keeps none: then every fusion's conflict
 * leaves the cell, no cell is ever surer than kMaxCertainty of one
 * hypothesis (so that evidence against it can always win), and each cell
 * remembers its latest motion event instead (CellEvent), with its time. */
class EvidentialGridStorage : private detail::TGridStorageState
{
   public:
	/** Largest number of insertion times before the stamps are rebased (an
	 * event keeps its stamp in 14 bits). */
	static constexpr std::size_t kMaxStamps = 16383;
	/** Largest m(F) or m(O) of a cell of a grid without conflict: a parked
	 * car seen for an hour is forgotten after some eight free scans, as after
	 * a minute (and a cell seen at the ceiling reads within 1e-4 of the
	 * exact Dempster fusion). */
	static constexpr double kMaxCertainty = 0.9999;

	/** An empty (0 x 0) grid of resolution 0.1 m with no decay, keeping
	 * conflict. */
	EvidentialGridStorage() = default;
	EvidentialGridStorage(const EvidentialGridStorage&) = default;
	EvidentialGridStorage& operator=(const EvidentialGridStorage&) = default;
	/** Takes `other`'s cells and settings; `other` is left an empty grid, as
	 * the default constructor makes it. \throws std::bad_alloc */
	EvidentialGridStorage(EvidentialGridStorage&& other);
	/** As the move constructor; moving a grid into itself changes nothing.
	 * \throws std::bad_alloc */
	EvidentialGridStorage& operator=(EvidentialGridStorage&& other);

	/** Discards every cell and sets the geometry to cover [xMin, xMax] x
	 * [yMin, yMax] with square cells of `resolution` metres, all vacuous.
	 * Insertion times start again.
	 * \throws std::invalid_argument if the resolution or a bound is beyond
	 *  GridGeometry's limits (NaN included), min >= max, or the grid would
	 *  exceed `maxCells` cells. */
	void reset(
		double xMin, double xMax, double yMin, double yMax, double resolution,
		std::size_t maxCells);

	const GridGeometry& geometry() const { return m_geometry; }

	/** Grows the grid so that it covers [xMin, xMax] x [yMin, yMax], adding
	 * `margin` metres beyond each side that has to grow, keeping every cell
	 * where it is. Does nothing when the box is already covered. A grid that
	 * outgrows its memory moves to a block with room beyond the sides that
	 * grew (up to four times the grid's extent, within `maxCells`; memory
	 * never written costs nothing), and grows into that
	 * room later without moving: geometry()'s firstIndex and rowStride then
	 * change, and the indices of the cells with them.
	 * Where the margin would take the grid past `maxCells` cells or
	 * GridGeometry's limits, it is halved until the grid fits, down to none.
	 * \return false (and leaves the grid as it is) if even without a margin
	 *  the grown grid would exceed `maxCells` cells or GridGeometry's
	 *  limits, or a bound is not finite. */
	bool growToInclude(
		double xMin, double xMax, double yMin, double yMax, double margin,
		std::size_t maxCells);

	/** A number that changes whenever the cells move to other indices
	 * (reset(), assign(), a growth into a new block) and no other grid had
	 * before (a copy has the same cells at the same indices, and the same
	 * number): while it stays, an index kept from an earlier insertion names
	 * the same cell, growth into the kept room included. */
	std::size_t layout() const { return m_layout; }
	/** The layout the grid had just before its latest growth into a new
	 * block; 0 when its layout last changed otherwise (reset(), assign()). */
	std::size_t grownFromLayout() const { return m_grownFrom.layout; }
	/** The index now of the cell whose index was `before` in layout
	 * grownFromLayout(): growth keeps every cell where it is. `before` must
	 * name a cell of that layout's grid. */
	std::size_t indexAfterGrowth(std::size_t before) const
	{
		const GridGeometry& was = m_grownFrom.geometry;
		return m_geometry.index(
			was.columnOf(before) + m_grownFrom.dx, was.rowOf(before) + m_grownFrom.dy);
	}

	/** Decay rate, per second of data time, >= 0 (0: no decay).
	 * \throws std::invalid_argument if negative or not finite. */
	void setDecayRate(double perSecond);
	double decayRate() const { return m_decayRate; }

	/** Whether cells keep conflict. Changing it clears every cell's aside
	 * word: the conflict of a grid that kept it (the normal parts stay: they
	 * are the masses with the conflict normalized away), or the events. */
	void setKeepsConflict(bool keeps);
	bool keepsConflict() const { return m_keepsConflict; }
	/** A cell of a grid that keeps conflict as a grid without conflict
	 * holds it: no event, and the normal part capped at kMaxCertainty. */
	static QuantizedCell withoutConflict(QuantizedCell c);
	/** Events are remembered at least this long, seconds, >= 0 (the stamps
	 * of older ones may be dropped when the stamps are rebased). Events
	 * older than 100 / decayRate seconds or 8191 insertion times may be
	 * dropped too. \throws std::invalid_argument if negative or NaN. */
	void setEventRetention(double seconds);

	/** Starts an insertion at data time t (seconds, any origin). A time
	 * before the latest one is taken as the latest: data that go back in time
	 * never undo decay. The first insertion after reset() sets the origin.
	 * \throws std::invalid_argument if t is not finite. */
	void beginInsertion(double t);
	/** Time of the latest insertion (0 before the first). */
	double latestTime() const { return m_stampTimes.back(); }
	/** Number of insertions since reset(). */
	std::size_t insertionCount() const { return m_insertions; }

	/** The mass of a cell as decayed to latestTime() (m(empty) = 0 in a grid
	 * without conflict). idx is geometry().index() of a cell. */
	Mass read(std::size_t idx) const
	{
		const QuantizedCell& c = m_cells[idx];
		return decayed(m_keepsConflict ? decodeMass(c) : decodeNormal(c), decayFactor(c.stamp));
	}
	/** Stores m in a cell, stamped with the current insertion; in a grid
	 * without conflict, m normalized and capped at kMaxCertainty (the event
	 * stays). */
	void write(std::size_t idx, const Mass& m)
	{
		// Read first: threads that write cells of one insertion at once
		// (beginInsertion() cleared the flag) then share no store.
		if (m_pristine) m_pristine = false;
		QuantizedCell& c = m_cells[idx];
		if (m_keepsConflict)
			encodeMass(m, c);
		else
		{
			encodeNormal(m, c);
			c.free = std::min<std::uint16_t>(c.free, m_ceiling);
			c.occupied = std::min<std::uint16_t>(c.occupied, m_ceiling);
		}
		restamp(c);
	}

	/** @name Fusing evidence into cells
	 * Each decays cell idx (an index() of the geometry) from its stamp to the current
	 * insertion, fuses `observed` into it and stamps it with the current
	 * insertion, so that a cell is always decayed exactly once for the time
	 * it spent unchanged. Fuse a cell at most once per insertion.
	 * @{ */
	/** With any rule and conflict handling: read, combine, write. Returns
	 * the fusion's conflict split. */
	ConflictSplit fuse(
		std::size_t idx, const Mass& observed, FusionRule rule,
		ConflictHandling handling)
	{
		const Mass before = read(idx);
		write(idx, handleConflict(combine(rule, before, observed), handling));
		return splitConflict(before, observed);
	}
	/** The conjunctive rule keeping the conflict (a grid that keeps
	 * conflict), computed on the stored values: fuse() without its
	 * generality. In the stored form the conjunctive rule is Dempster's rule
	 * on the normal parts, and 1 - K multiplies by 1 - (the conflict of that
	 * fusion). */
	void fuseConjunctive(std::size_t idx, const Mass& observed)
	{
		QuantizedCell& c = m_cells[idx];
		double f, o, keep;
		decayedNormal(c, f, o, keep);
		double of, oo, ou;
		normalPart(observed, of, oo, ou);
		const double observedKeep = 1.0 - observed.conflict;
		const double newConflict = (f * oo + o * of) / kMassScale;
		// At total conflict both products are 0 and n becomes vacuous.
		const double normalize = 1.0 / std::max(1.0 - newConflict, 1e-300);
		encodeScaled(
			c, kMassScale * (1.0 - keep * observedKeep * (1.0 - newConflict)),
			(f * (of + ou) + (kMassScale - f - o) * of) * normalize,
			(o * (oo + ou) + (kMassScale - f - o) * oo) * normalize);
		restamp(c);
	}
	/** Dempster's rule on the stored values of a grid without conflict (the
	 * conjunctive rule with the conflict normalized away, which is
	 * ConflictHandling::Normalize): fuse() without its generality. Returns
	 * the fusion's conflict split. */
	ConflictSplit fuseNormalized(std::size_t idx, const Mass& observed)
	{
		QuantizedCell& c = m_cells[idx];
		double f, o, keep;
		decayedNormal(c, f, o, keep);
		double of, oo, ou;
		normalPart(observed, of, oo, ou);
		const double u = kMassScale - f - o;
		const ConflictSplit split{f * oo / kMassScale, o * of / kMassScale};
		const double normalize =
			1.0 / std::max(1.0 - split.appeared - split.disappeared, 1e-300);
		encodeScaledNormal(
			c, (f * (of + ou) + u * of) * normalize,
			(o * (oo + ou) + u * oo) * normalize, m_ceiling);
		restamp(c);
		return split;
	}
	/** The simple free mass m(F) = w, the mass of the bulk of a scan's
	 * cells, in single precision (the compiler runs it on four cells at
	 * once): a float holds a stored value to 1/256 of a step. fuseConjunctive()
	 * in a grid that keeps conflict, fuseNormalized() in one that does not:
	 * `KeepsConflict` must be keepsConflict(). `Decays` false skips the
	 * decay, for grids whose decay rate is 0. `Rule`: Dempster's rule, or in
	 * a grid without conflict Yager's, or the cautious rule (only on a cell
	 * that isLoudFor() the cautious rule does not call loud). */
	template <bool Decays, bool KeepsConflict, FreeFusion Rule = FreeFusion::Dempster>
	void fuseSimpleFree(std::size_t idx, float w)
	{
		static_assert(
			Rule == FreeFusion::Dempster || !KeepsConflict,
			"a grid that keeps conflict fuses with the conjunctive rule (Dempster's on the normal part)");
		QuantizedCell& c = m_cells[idx];
		// Free at the ceiling, nothing occupied, no decay: the fusion gives
		// the cell back as it was, and its stamp means nothing.
		if constexpr (!Decays && !KeepsConflict)
			if (c.free == m_ceiling && c.occupied == 0) return;
		const float scale = static_cast<float>(kMassScale);
		float f = c.free, o = c.occupied;
		float keep = KeepsConflict ? 1.0f - c.aside / scale : 1.0f;
		if constexpr (Decays)
		{
			// Decay moves the share 1 - d of each mass to Omega: the conflict
			// becomes d K and the normal part keeps s = d (1 - K) / (1 - d K).
			const auto d = static_cast<float>(decayFactor(c.stamp));
			if constexpr (KeepsConflict)
			{
				const float decayedKeep = 1.0f - d * (1.0f - keep);
				const float s = d * keep / decayedKeep;
				f *= s;
				o *= s;
				keep = decayedKeep;
			}
			else
			{
				// Without conflict the normal part is the mass: s = d, and no
				// division (the compiler may not fold d * 0 itself).
				f *= d;
				o *= d;
			}
		}
		const float u = scale - f - o;
		if constexpr (isCautious(Rule))
		{
			float nf, no;
			cautiousFree<Rule == FreeFusion::CautiousNormalized>(f, o, u, w, nf, no);
			encodeScaledNormal(c, nf, no, m_ceiling);
			restamp(c);
			return;
		}
		// The occupied mass the free sight conflicts with; Dempster's
		// 1 / (1 - lost / scale) in one division, not two in a row. At total
		// conflict both products are 0 and n becomes vacuous.
		const float lost = o * w;
		const float normalize =
			Rule == FreeFusion::Dempster ? scale / std::max(scale - lost, 1e-30f) : 1.0f;
		if constexpr (KeepsConflict)
			encodeScaled(
				c, scale * (1.0f - keep * (1.0f - lost / scale)), (f + u * w) * normalize,
				(o - lost) * normalize);
		else
			encodeScaledNormal(c, (f + u * w) * normalize, (o - lost) * normalize, m_ceiling);
		restamp(c);
	}
	/** True when a free sight of cell idx may find something for the motion
	 * layer: the cell has an event that a free sight judges again (Appeared,
	 * Leaving) or a stored n(O) of `occupiedBelow` or more (decay only lowers
	 * n(O)). A cell that is not loud is quiet. */
	bool isLoud(std::size_t idx, std::uint16_t occupiedBelow) const
	{
		const QuantizedCell& c = m_cells[idx];
		return c.occupied >= occupiedBelow || (c.aside & kEventJudgedWhenSeenFree) != 0;
	}
	/** True when cell idx stores no ignorance: n(F) + n(O) at the scale. */
	bool holdsNoIgnorance(std::size_t idx) const
	{
		const QuantizedCell& c = m_cells[idx];
		return c.free + c.occupied >= static_cast<int>(kMassScale);
	}
	/** isLoud(), and for the cautious rule also a cell that holdsNoIgnorance():
	 * the rule's weights need some, and the general rule, in double
	 * precision, discounts such a cell first. */
	template <FreeFusion Rule>
	bool isLoudFor(std::size_t idx, std::uint16_t occupiedBelow) const
	{
		return isLoud(idx, occupiedBelow) || (isCautious(Rule) && holdsNoIgnorance(idx));
	}
	/** The cautious rule of the simple free mass w on the normal parts
	 * (f, o), u = scale - f - o, in stored units: n(F) and n(O) in stored
	 * units, the conflict normalized away or (not `Normalizes`) given to
	 * Omega. With w's weight 1 - w on F and 1 on O and the cell's
	 * u / (f + u) on F, u / (o + u) on O (and at least 1 on the empty set,
	 * as for every mass without conflict), the rule keeps the smaller weight
	 * of each. The products of the weights fold into one division: where
	 * the cell's weight on F is the smaller (u <= (1 - w)(f + u)),
	 * n(F) = f s and n(O) = o s, s = scale u / ((f + u)(o + u)), and with
	 * the normalization s = 1 (the cell is given back as it was); otherwise
	 * n(F) = w u s and n(O) = (1 - w) o s, s = scale / (o + u), normalized
	 * scale / (u + (1 - w) o). For u > 0, which isLoudFor() leaves to the
	 * bulk. The kernels do the same operations in the same order. */
	template <bool Normalizes>
	static void cautiousFree(float f, float o, float u, float w, float& nf, float& no)
	{
		const float scale = static_cast<float>(kMassScale), tiny = 1e-30f;
		const float notW = 1.0f - w;
		const bool cellsWeight = u <= notW * (f + u);
		if (Normalizes && cellsWeight)
		{
			nf = f, no = o;
			return;
		}
		const float s = cellsWeight ? scale * u / std::max((f + u) * (o + u), tiny)
			: Normalizes            ? scale / std::max(u + notW * o, tiny)
									: scale / std::max(o + u, tiny);
		nf = cellsWeight ? f * s : w * u * s;
		no = cellsWeight ? o * s : notW * o * s;
	}
	/** fuseSimpleFree<Decays, true>() (a grid that keeps conflict) into
	 * every cell of [first, first + count), four at a time where the target
	 * has SSE2, eight where the processor has AVX2, with the same results. */
	template <bool Decays>
	void fuseFreeRunKeepingConflict(std::size_t first, std::size_t count, float w);
	/** fuseSimpleFree<Decays, false, Rule>() (a grid without conflict) into
	 * every quiet cell of [first, first + count) (see isLoudFor()); loud
	 * cells are left unfused, their indices appended to `loud` in order.
	 * Four cells at a time where the target has SSE2, eight where the
	 * processor has AVX2, with the same results. */
	template <bool Decays, FreeFusion Rule = FreeFusion::Dempster>
	void fuseQuietFreeRun(
		std::size_t first, std::size_t count, float w, std::uint16_t occupiedBelow,
		std::vector<std::size_t>& loud);
	/** @} */

	/** Asks the processor to bring cells [first, first + count) into its
	 * cache, to be written soon; changes nothing. The insertion announces the
	 * spans of a row a few rows before it fuses them: a row's spans are
	 * short, and the processor's own prefetcher, which follows a stream only
	 * after a few misses, leaves each one waiting on memory
	 * (doc/performance-history.md). At most kMaxPrefetchLines cache lines of
	 * kCacheLine bytes a call: past them the processor's prefetcher has the
	 * stream. [first, first + count) must lie within the grid; never
	 * throws. */
	void prefetchForWrite(std::size_t first, std::size_t count) const
	{
#if defined(__GNUC__)
		if (count == 0) return;
		const char* from = reinterpret_cast<const char*>(&m_cells[first]);
		const char* last = reinterpret_cast<const char*>(&m_cells[first + count - 1]);
		for (int line = 0; line < kMaxPrefetchLines && from <= last; ++line, from += kCacheLine)
			__builtin_prefetch(from, 1);
		// An empty statement the compiler must keep: without it GCC finds the
		// function free of effects (a prefetch is only a hint) and drops its
		// calls before it inlines them.
		asm volatile("");
#else
		(void)first, (void)count;
#endif
	}
	static constexpr int kMaxPrefetchLines = 16, kCacheLine = 64;

	/** Records that cell idx holds an impact of the current scan. The
	 * likelihood field takes its obstacles among such cells: the sensor
	 * models spread an impact's occupied evidence over the cells around it,
	 * but the scans being scored end where beams ended. */
	void markImpact(std::size_t idx) { m_cells[idx].stamp |= kHeldImpact; }
	bool heldImpact(std::size_t idx) const { return (m_cells[idx].stamp & kHeldImpact) != 0; }
	/** No free mass stored (n(F) = 0, decayed or not): the cell was never
	 * seen free, or hits left it none. */
	bool neverSeenFree(std::size_t idx) const { return neverSeenFree(m_cells[idx]); }
	/** Records that the motion layer saw cell idx flip (a pending arrival
	 * beside static structure turned down): pose error, not the world,
	 * changes such a cell, and it is never again confirmed an arrival
	 * beside structure. Kept in map files (version 5). */
	void markFlipped(std::size_t idx) { m_cells[idx].stamp |= kFlipped; }
	bool flipped(std::size_t idx) const { return (m_cells[idx].stamp & kFlipped) != 0; }
	/** Width of the masks mayBeStructure() returns. */
	static constexpr int kMaskWidth = 32;
	/** Bit k set when cell first + k (k < count <= kMaskWidth, all in one
	 * row) held an impact or was never seen free (the inside of a wall,
	 * which beams end before), and may have m(O) > m(F) and m(O) >= 0.5,
	 * decayed or not (decay only scales both down): a test on the stored
	 * values, without branches or decoding, that rules most cells out. */
	std::uint32_t mayBeStructure(std::size_t first, int count) const
	{
		std::uint32_t mask = 0;
		for (int k = 0; k < count; ++k)
		{
			const QuantizedCell& c = m_cells[first + static_cast<std::size_t>(k)];
			const bool heldOrInside = (c.stamp & kHeldImpact) != 0 || neverSeenFree(c);
			const bool leans = c.occupied > c.free && c.occupied >= kMassScale / 2;
			mask |= static_cast<std::uint32_t>(heldOrInside && leans) << k;
		}
		return mask;
	}

	/** @name Motion events (grids without conflict; CellEvent::None
	 * otherwise)
	 * @{ */
	CellEvent event(std::size_t idx) const
	{
		return m_keepsConflict ? CellEvent::None : eventOf(m_cells[idx]);
	}
	/** Data time of the cell's event (meaningless for CellEvent::None). */
	double eventTime(std::size_t idx) const
	{
		return m_stampTimes[eventStampOf(m_cells[idx])];
	}
	/** Sets the cell's event, at the current insertion's time. */
	void setEvent(std::size_t idx, CellEvent e)
	{
		if (!m_keepsConflict) m_cells[idx].aside = packEvent(e, m_currentStamp);
	}
	/** Sets the cell's event, keeping the time of the one it had (a leaving
	 * cell's disappearance dates from when it was first seen free). */
	void setEventKeepingTime(std::size_t idx, CellEvent e)
	{
		QuantizedCell& c = m_cells[idx];
		if (!m_keepsConflict) c.aside = packEvent(e, eventStampOf(c));
	}
	/** @} */

	/** The stored cells, read-only, at the indices geometry().index() gives
	 * (with the room kept for growth: vacuous cells outside the grid). */
	const CellBlock& cells() const { return m_cells; }
	/** The grid's cells row by row, cx + sizeX cy (what files hold). */
	std::vector<QuantizedCell> packedCells() const;
	/** The insertion times of the stamps, oldest first. */
	const std::vector<double>& stampTimes() const { return m_stampTimes; }

	/** Replaces the whole state with one read from a file. `plainStamps`:
	 * the cells' stamps are whole indices without flags (files of version 1,
	 * which allowed 65535 times): a longer table than kMaxStamps is then
	 * rebased, and the cells that lean occupied are taken to have held
	 * impacts.
	 * \throws std::invalid_argument if the pieces do not fit together (a
	 *  geometry beyond the limits, cell count against geometry, a stamp
	 *  without a time, masses above 1, times that go backwards, several
	 *  times but no insertion). */
	void assign(
		const GridGeometry& geometry, std::vector<QuantizedCell> cells,
		std::vector<double> stampTimes, std::size_t insertions,
		double decayRate, bool keepsConflict, bool plainStamps = false);

   private:
	/** A mass discounted by a decay factor. */
	static Mass decayed(const Mass& m, double factor)
	{
		if (factor >= 1.0) return m;
		return {
			m.conflict * factor, m.free * factor, m.occupied * factor,
			m.unknown * factor + (1.0 - factor)};
	}
	/** The normal part of an observed mass (vacuous at total conflict). */
	static void normalPart(const Mass& m, double& f, double& o, double& u)
	{
		// A mass without conflict (every sensor model's) is its own normal
		// part: 1 / 1 is not worked out.
		const double keep = 1.0 - m.conflict;
		const double toNormal = m.conflict == 0.0 ? 1.0 : keep > 0.0 ? 1.0 / keep : 0.0;
		f = m.free * toNormal;
		o = m.occupied * toNormal;
		u = 1.0 - f - o;
	}

	/** The normal part of a cell decayed to latestTime(), in stored units
	 * (n(F), n(O)), and its 1 - K. Decay discounts the whole mass, so the
	 * conflict shrinks to d K and the normal part keeps the share
	 * s = d (1 - K) / (1 - d K) of its evidence. */
	void decayedNormal(const QuantizedCell& c, double& f, double& o, double& keep) const
	{
		const double d = decayFactor(c.stamp);
		if (!m_keepsConflict)
		{
			// K = 0: s = d, the same number without a division (a mixed
			// cell's fusion waited on it).
			keep = 1.0;
			f = c.free * d;
			o = c.occupied * d;
			return;
		}
		const double k = c.aside / kMassScale;
		keep = 1.0 - d * k;
		const double s = d * (1.0 - k) / keep;
		f = c.free * s;
		o = c.occupied * s;
	}
	static bool neverSeenFree(const QuantizedCell& c) { return c.free == 0; }
	/** exp(-decayRate (latestTime - time of stamp)); exactly 1 without
	 * decay (every gain is then exp(0)). No branch, so that the insertion
	 * kernels vectorize. */
	double decayFactor(std::uint16_t stamp) const
	{
		return m_presentGain * m_stampGain[stamp & kStampMask];
	}
	/** Stamps a cell with the current insertion, keeping its flags. */
	void restamp(QuantizedCell& c) const
	{
		c.stamp = static_cast<std::uint16_t>((c.stamp & kStampFlags) | m_currentStamp);
	}
	/** Decays every cell to time `to` (>= every stamp's time) and makes it
	 * the stamp of every cell; the times of recent events stay. */
	void rebaseStamps(double to);
	void updateGains();
	/** Tells the cells' block that only the grid's cells are written (the
	 * room around them never is), after the geometry changed in it. */
	void writeOnlyTheGrid();
};

}  // namespace mrpt_evidential
