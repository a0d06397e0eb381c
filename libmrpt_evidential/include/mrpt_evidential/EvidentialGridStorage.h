/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Storage of an evidential grid: geometry, 8-byte cells and lazy decay.
 * Standard library only; the MRPT map class is built on it. */
#pragma once

#include <mrpt_evidential/Mass.h>
#include <mrpt_evidential/QuantizedMass.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace mrpt_evidential
{
/** Where the cells of a grid lie. Cell (cx, cy) covers
 * [xMin + cx res, xMin + (cx + 1) res) x [yMin + cy res, yMin + (cy + 1) res). */
struct GridGeometry
{
	double xMin = 0.0, yMin = 0.0, resolution = 0.1;
	int sizeX = 0, sizeY = 0;

	/** Limits of every grid: bounds within kMaxCoordinate metres of the
	 * origin, cells of kMinResolution to kMaxResolution metres. Beyond them
	 * cell centres lose their precision, and squared distances overflow. */
	static constexpr double kMaxCoordinate = 1e9;
	static constexpr double kMinResolution = 1e-6, kMaxResolution = 1e6;
	/** True when the bounds and resolution are within the limits (NaN is
	 * not). */
	static bool withinLimits(
		double xMin, double xMax, double yMin, double yMax, double resolution)
	{
		const auto near = [](double v) {
			return v >= -kMaxCoordinate && v <= kMaxCoordinate;
		};
		return resolution >= kMinResolution && resolution <= kMaxResolution &&
			near(xMin) && near(xMax) && near(yMin) && near(yMax);
	}

	/** Number of cells needed to cover `length` metres, at least 1 (a
	 * length within a billionth of a cell above a whole number of cells
	 * needs that number). */
	static double cellsToCover(double length, double resolution)
	{
		return std::max(1.0, std::ceil(length / resolution - 1e-9));
	}

	double xMax() const { return xMin + sizeX * resolution; }
	double yMax() const { return yMin + sizeY * resolution; }
	std::size_t cellCount() const
	{
		return static_cast<std::size_t>(sizeX) * static_cast<std::size_t>(sizeY);
	}
	/** Column of x; may be outside [0, sizeX) (far away or NaN: an int's
	 * smallest or largest value). */
	int cellX(double x) const { return floorToInt((x - xMin) / resolution); }
	int cellY(double y) const { return floorToInt((y - yMin) / resolution); }
	/** floor(v), saturated to an int: a plain cast of a larger value is
	 * undefined behaviour. NaN gives the smallest int. */
	static int floorToInt(double v)
	{
		constexpr double lo = std::numeric_limits<int>::min();
		constexpr double hi = std::numeric_limits<int>::max();
		const double f = std::floor(v);
		if (f >= hi) return std::numeric_limits<int>::max();
		return f >= lo ? static_cast<int>(f) : std::numeric_limits<int>::min();
	}
	double cellCenterX(int cx) const { return xMin + (cx + 0.5) * resolution; }
	double cellCenterY(int cy) const { return yMin + (cy + 0.5) * resolution; }
	bool inside(int cx, int cy) const
	{
		return cx >= 0 && cy >= 0 && cx < sizeX && cy < sizeY;
	}
	std::size_t index(int cx, int cy) const
	{
		return static_cast<std::size_t>(cy) * static_cast<std::size_t>(sizeX) +
			static_cast<std::size_t>(cx);
	}
};

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

	/** Raw access for insertion kernels that fuse in place: they must leave
	 * a consistent cell stamped with currentStamp(), its masses decayed with
	 * decayFactor() of its old stamp before fusion. */
	QuantizedCell& rawCell(std::size_t idx) { return m_cells[idx]; }

	/** exp(-decayRate (latestTime - time of stamp)). */
	double decayFactor(std::uint16_t stamp) const
	{
		return m_decayRate == 0.0 ? 1.0 : m_presentGain * m_stampGain[stamp];
	}
	/** A stored mass discounted by a decay factor. */
	static Mass decayed(const QuantizedCell& c, double factor)
	{
		Mass m = decodeMass(c);
		if (factor >= 1.0) return m;
		return {
			m.conflict * factor, m.free * factor, m.occupied * factor,
			m.unknown * factor + (1.0 - factor)};
	}

	/** Raw access, for serialization and fast loops. */
	const std::vector<QuantizedCell>& cells() const { return m_cells; }
	const std::vector<double>& stampTimes() const { return m_stampTimes; }
	std::uint16_t currentStamp() const { return m_currentStamp; }

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
