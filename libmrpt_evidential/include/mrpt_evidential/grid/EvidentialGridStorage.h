/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Storage of an evidential grid: 8-byte cells, their lazy decay and the
 * fusions that update them. Standard library only; the MRPT map class is
 * built on it. */
#pragma once

#include <mrpt_evidential/algebra/combination.h>
#include <mrpt_evidential/grid/GridGeometry.h>
#include <mrpt_evidential/grid/QuantizedMass.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt_evidential
{
/** The cells of an evidential grid with their decay.
 *
 * Decay is classical discounting with rate 1 - exp(-decayRate dt) after dt
 * seconds of data time. It is applied lazily: every cell carries the stamp of
 * the insertion that last wrote it, and reading a cell discounts it from that
 * stamp's time to the latest insertion's time. The cost of an insertion
 * therefore depends on the cells it writes, not on the size of the grid.
 * Once in a long while (65535 distinct insertion times, or exp(decayRate dt)
 * about to lose precision) every cell is decayed to the present and the
 * stamps start again: O(cells), amortized over thousands of insertions. */
class EvidentialGridStorage
{
   public:
	/** Largest number of insertion times before the stamps are rebased. */
	static constexpr std::size_t kMaxStamps = 65535;

	/** An empty (0 x 0) grid of resolution 0.1 m with no decay. */
	EvidentialGridStorage() = default;

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
	 * where it is. Does nothing when the box is already covered.
	 * \return false (and leaves the grid as it is) if the grown grid would
	 *  exceed `maxCells` cells or GridGeometry's limits, or a bound is not
	 *  finite. */
	bool growToInclude(
		double xMin, double xMax, double yMin, double yMax, double margin,
		std::size_t maxCells);

	/** Decay rate, per second of data time, >= 0 (0: no decay).
	 * \throws std::invalid_argument if negative or not finite. */
	void setDecayRate(double perSecond);
	double decayRate() const { return m_decayRate; }

	/** Starts an insertion at data time t (seconds, any origin). A time
	 * before the latest one is taken as the latest: data that go back in time
	 * never undo decay. The first insertion after reset() sets the origin.
	 * \throws std::invalid_argument if t is not finite. */
	void beginInsertion(double t);
	/** Time of the latest insertion (0 before the first). */
	double latestTime() const { return m_stampTimes.back(); }
	/** Number of insertions since reset(). */
	std::size_t insertionCount() const { return m_insertions; }

	/** The mass of a cell as decayed to latestTime(). idx < cellCount(). */
	Mass read(std::size_t idx) const
	{
		return decayed(m_cells[idx], decayFactor(m_cells[idx].stamp));
	}
	/** Stores m in a cell, stamped with the current insertion. */
	void write(std::size_t idx, const Mass& m)
	{
		QuantizedCell& c = m_cells[idx];
		encodeMass(m, c);
		c.stamp = m_currentStamp;
	}

	/** @name Fusing evidence into cells
	 * Each decays cell idx (< cellCount()) from its stamp to the current
	 * insertion, fuses `observed` into it and stamps it with the current
	 * insertion, so that a cell is always decayed exactly once for the time
	 * it spent unchanged. Fuse a cell at most once per insertion.
	 * @{ */
	/** With any rule and conflict handling: read, combine, write. */
	void fuse(
		std::size_t idx, const Mass& observed, FusionRule rule,
		ConflictHandling handling)
	{
		write(idx, handleConflict(combine(rule, read(idx), observed), handling));
	}
	/** The conjunctive rule keeping the conflict (the default), computed on
	 * the stored values: fuse() without its generality. In the stored form
	 * the conjunctive rule is Dempster's rule on the normal parts, and
	 * 1 - K multiplies by 1 - (the conflict of that fusion). */
	void fuseConjunctive(std::size_t idx, const Mass& observed)
	{
		QuantizedCell& c = m_cells[idx];
		double f, o, keep;
		decayedNormal(c, f, o, keep);
		const double u = kMassScale - f - o;
		// The observation's normal part and conflict.
		const double observedKeep = 1.0 - observed.conflict;
		const double toNormal = observedKeep > 0.0 ? 1.0 / observedKeep : 0.0;
		const double of = observed.free * toNormal,
					 oo = observed.occupied * toNormal, ou = 1.0 - of - oo;
		const double newConflict = (f * oo + o * of) / kMassScale;
		// At total conflict both products are 0 and n becomes vacuous.
		const double normalize = 1.0 / std::max(1.0 - newConflict, 1e-300);
		encodeScaled(
			c, kMassScale * (1.0 - keep * observedKeep * (1.0 - newConflict)),
			(f * (of + ou) + u * of) * normalize, (o * (oo + ou) + u * oo) * normalize);
		c.stamp = m_currentStamp;
	}
	/** fuseConjunctive() with the simple free mass m(F) = w, the mass of the
	 * bulk of a scan's cells, in single precision (the compiler runs it on
	 * four cells at once): a float holds a stored value to 1/256 of a step.
	 * `Decays` false skips the decay, for grids whose decay rate is 0. */
	template <bool Decays>
	void fuseSimpleFree(std::size_t idx, float w)
	{
		QuantizedCell& c = m_cells[idx];
		const float scale = static_cast<float>(kMassScale);
		float f = c.free, o = c.occupied, keep = 1.0f - c.conflict / scale;
		if constexpr (Decays)
		{
			// Decay moves the share 1 - d of each mass to Omega: the conflict
			// becomes d K and the normal part keeps s = d (1 - K) / (1 - d K).
			const auto d = static_cast<float>(decayFactor(c.stamp));
			const float decayedKeep = 1.0f - d * (1.0f - keep);
			const float s = d * keep / decayedKeep;
			f *= s;
			o *= s;
			keep = decayedKeep;
		}
		const float u = scale - f - o;
		const float newConflict = o * w / scale;
		// At total conflict both products are 0 and n becomes vacuous.
		const float normalize = 1.0f / std::max(1.0f - newConflict, 1e-30f);
		encodeScaled(
			c, scale * (1.0f - keep * (1.0f - newConflict)), (f + u * w) * normalize,
			(o - o * w) * normalize);
		c.stamp = m_currentStamp;
	}
	/** @} */

	/** The stored cells and stamp times, read-only (serialization, tests). */
	const std::vector<QuantizedCell>& cells() const { return m_cells; }
	const std::vector<double>& stampTimes() const { return m_stampTimes; }

	/** Replaces the whole state with one read from a file.
	 * \throws std::invalid_argument if the pieces do not fit together (a
	 *  geometry beyond the limits, cell count against geometry, a stamp
	 *  without a time, masses above 1, times that go backwards, several
	 *  times but no insertion). */
	void assign(
		const GridGeometry& geometry, std::vector<QuantizedCell> cells,
		std::vector<double> stampTimes, std::size_t insertions,
		double decayRate);

   private:
	/** A stored mass discounted by a decay factor. */
	static Mass decayed(const QuantizedCell& c, double factor)
	{
		Mass m = decodeMass(c);
		if (factor >= 1.0) return m;
		return {
			m.conflict * factor, m.free * factor, m.occupied * factor,
			m.unknown * factor + (1.0 - factor)};
	}

	/** The normal part of a cell decayed to latestTime(), in stored units
	 * (n(F), n(O)), and its 1 - K. Decay discounts the whole mass, so the
	 * conflict shrinks to d K and the normal part keeps the share
	 * s = d (1 - K) / (1 - d K) of its evidence. */
	void decayedNormal(const QuantizedCell& c, double& f, double& o, double& keep) const
	{
		const double d = decayFactor(c.stamp), k = c.conflict / kMassScale;
		keep = 1.0 - d * k;
		const double s = d * (1.0 - k) / keep;
		f = c.free * s;
		o = c.occupied * s;
	}
	/** exp(-decayRate (latestTime - time of stamp)); exactly 1 without
	 * decay (every gain is then exp(0)). No branch, so that the insertion
	 * kernels vectorize. */
	double decayFactor(std::uint16_t stamp) const
	{
		return m_presentGain * m_stampGain[stamp];
	}
	/** Decays every cell to time `to` (>= every stamp's time) and makes it
	 * the only stamp. */
	void rebaseStamps(double to);
	void updateGains();

	GridGeometry m_geometry;
	std::vector<QuantizedCell> m_cells;
	double m_decayRate = 0.0;
	/** Time of each stamp; stamp 0 is the time origin. Never empty. */
	std::vector<double> m_stampTimes{0.0};
	/** exp(decayRate (time of stamp - origin)) and exp(-decayRate (latest -
	 * origin)): their product is a stamp's decay factor, one multiplication
	 * per cell read instead of an exp. */
	std::vector<double> m_stampGain{1.0};
	double m_presentGain = 1.0;
	std::uint16_t m_currentStamp = 0;
	std::size_t m_insertions = 0;
};

}  // namespace mrpt_evidential
