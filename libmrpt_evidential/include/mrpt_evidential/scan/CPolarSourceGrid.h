/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The polar SourceGrid: one row of range bins per angular sector of a scan,
 * each row built by a sector model (SensorModel.h). */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>
#include <mrpt_evidential/scan/SensorModel.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

namespace mrpt::obs
{
class CObservation2DRangeScan;
}

namespace mrpt_evidential
{
/** How a scan is cut into a polar SourceGrid. */
struct TSourceGridOptions
{
	SensorModelParams sensorModel;
	/** Angular width of a sector, radians, >= 0. 0 gives one sector per beam;
	 * a width below the beam spacing is raised to it (a sector never holds
	 * less than one beam). */
	double sectorWidth = 0.0;
	/** Length of every sector's row, metres, > 0. A return beyond it proves the
	 * row free and nothing occupied. */
	double maxRange = 20.0;
	/** Length of a range bin, metres, > 0 (the map uses its cell size). */
	double binSize = 0.05;
	/** What a beam without a return means. false (default): nothing, the beam
	 * may have hit glass, black or a sensor fault. true: free space up to
	 * maxRange, like COccupancyGridMap2D's considerInvalidRangesAsFreeSpace. */
	bool invalidRangesAsFree = false;
	/** Metres before a sector's nearest impact where the grid cells get no
	 * free evidence from it, >= 0, default 0 (the seed's models). The rows
	 * keep the model's masses; the transform onto the cells applies the
	 * margin. Where the impact lies is uncertain by the error of the robot's
	 * pose, and walls seen from elsewhere, with that error, lie there:
	 * without a margin, rays that end just behind a wall cell erase it.
	 * The margin is that depth across the surface the sector's nearest
	 * impact lies on: along a beam that meets it at incidence a, up to
	 * three times longer (1 / cos a), so that grazed walls keep it too. */
	double freeMargin = 0.0;

	/** The first option out of range, the sensor model's first. */
	std::optional<TInvalidOption> firstInvalid() const;
	/** \throws std::invalid_argument describing firstInvalid(). */
	void validate() const;
};

/** The returns of a 3-D cloud, already sorted out (ground, obstacles) and
 * grouped by azimuth: a full turn of sectors, sector s centred at
 * -pi + s 2 pi / sectorCount() radians. Ranges are horizontal, metres, from
 * the sensor's vertical axis. */
struct TCloudReturns
{
	/** Per sector, the ranges of its obstacle points: its impacts. */
	std::vector<std::vector<double>> impacts;
	/** Per sector, the farthest range that a return proved free without
	 * being an impact (a ground point); 0 for none. */
	std::vector<double> freeReach;

	std::size_t sectorCount() const { return impacts.size(); }
	/** Empties every sector, keeping `sectors` of them and their storage. */
	void reset(std::size_t sectors)
	{
		impacts.resize(sectors);
		for (auto& ranges : impacts) ranges.clear();
		freeReach.assign(sectors, 0.0);
	}
};

/** The impact ranges of one sector of a CPolarSourceGrid, sorted: a view
 * into the grid's storage, valid until the grid is built again. */
class TImpactRanges
{
   public:
	TImpactRanges(const double* first, const double* last) : m_first(first), m_last(last) {}
	const double* begin() const { return m_first; }
	const double* end() const { return m_last; }
	const double* data() const { return m_first; }
	std::size_t size() const { return static_cast<std::size_t>(m_last - m_first); }
	bool empty() const { return m_first == m_last; }
	/** The nearest impact; the view must not be empty. */
	double front() const { return *m_first; }
	double operator[](std::size_t i) const { return m_first[i]; }

   private:
	const double* m_first;
	const double* m_last;
};

/** The polar SourceGrid of one 2-D scan or 3-D cloud, in the sensor's
 * frame.
 *
 * Sector s is centred at angle firstSectorAngle() + s * sectorSpacing()
 * (radians, counterclockwise, 0 = the sensor's forward axis), so angles grow
 * with s whatever the scan's direction (rightToLeft). A scan whose aperture
 * is a full turn gets sectors that go round once (fullTurn()). Bin b covers ranges
 * [b binSize, (b + 1) binSize). Each beam goes to the sector nearest to its
 * angle (midway between two, to the one at the greater angle); its range is
 * an impact of that sector when it is valid: flagged valid, finite and > 0.
 * Other ranges are no return (see TSourceGridOptions::invalidRangesAsFree).
 *
 * Rows are kept sparse (TSectorLayout): a row's leading free bins are a count
 * and one mass, and only the bins around its impacts are stored, so memory
 * and time follow the returns, not maxRange / binSize. */
class CPolarSourceGrid
{
   public:
	/** Rebuilds the grid from a scan, reusing the storage.
	 * \throws std::invalid_argument if the options are invalid, or the scan
	 *  has beams and its aperture is not in (0, 2 pi]. */
	void build(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const TSourceGridOptions& options);
	/** Rebuilds the grid from a cloud's returns: a full turn, sector s of
	 * `returns` is sector s here (options.sectorWidth is not used: the
	 * returns were grouped with it). A sector with impacts gets the sensor
	 * model's row of them, as a scan's sector; one with only a free reach r,
	 * m(F) = muF up to r (one beam's proof, whatever the model) and nothing
	 * beyond. A free reach beyond a sector's nearest impact proves nothing
	 * behind the impact.
	 * \throws std::invalid_argument if the options are invalid, the returns
	 *  have no sector, their two vectors differ in size, or an impact or
	 *  free reach is negative or NaN. */
	void build(const TCloudReturns& returns, const TSourceGridOptions& options);

	std::size_t sectorCount() const { return m_sectorCount; }
	std::size_t binCount() const { return m_binCount; }
	double binSize() const { return m_binSize; }
	/** Angle of sector 0's centre, radians. */
	double firstSectorAngle() const { return m_firstAngle; }
	/** Angle between neighbouring sector centres, radians (the scan's aperture
	 * for a single-beam scan). */
	double sectorSpacing() const { return m_spacing; }
	double sectorAngle(std::size_t s) const
	{
		return m_firstAngle + static_cast<double>(s) * m_spacing;
	}
	/** True for a scan of a full turn: the sectors go round once, and the
	 * last one neighbours the first. */
	bool fullTurn() const { return m_fullTurn; }
	// The per-sector accessors below throw std::out_of_range if s >=
	// sectorCount().

	/** True when at least one beam of the sector gave evidence (a valid return,
	 * or an invalid one read as free). A sector that is not observed is
	 * vacuous. */
	bool sectorObserved(std::size_t s) const
	{
		if (s >= m_sectorCount) throw std::out_of_range("no such sector");
		return m_observed[s] != 0;
	}

	/** Number of leading bins of sector s that may hold evidence; every bin
	 * from it on is vacuous. */
	std::size_t informedBins(std::size_t s) const { return m_layouts.at(s).informedBins; }
	/** Number of leading bins of sector s that all hold its free mass: the
	 * bins before its nearest impact. */
	std::size_t freeBins(std::size_t s) const { return m_layouts.at(s).freeBins; }
	/** m(F) of the leading free bins of sector s (0 when it has none). */
	double freeMass(std::size_t s) const { return m_layouts.at(s).freeMass; }
	/** The ranges of sector s's impacts, sorted (+inf for a beam without
	 * return read as free). */
	TImpactRanges impacts(std::size_t s) const
	{
		if (s >= m_sectorCount) throw std::out_of_range("no such sector");
		return {m_impactRanges.data() + m_impactStart[s],
				m_impactRanges.data() + m_impactStart[s + 1]};
	}
	/** Index of the bin holding range r (binCount() beyond the last). */
	std::size_t binOfRange(double r) const;
	/** TSourceGridOptions::freeMargin of the latest build. */
	double freeMargin() const { return m_freeMargin; }
	/** The largest informedBins() of all sectors. */
	std::size_t maxInformedBins() const { return m_maxInformedBins; }
	/** Number of leading bins of sector s that the transform spreads over
	 * the cells: informedBins() for a scan. For a cloud, only up to the end
	 * of the run of bins around its nearest impacts: its farther impacts (a
	 * tree seen over a car, by many layers) reach the cells as the cells
	 * their points end in (CScanImpacts), not spread over the whole width of
	 * the sector, whose bins between them are vacuous. */
	std::size_t transformBins(std::size_t s) const { return m_transformBins.at(s); }
	/** The largest transformBins() of all sectors. */
	std::size_t maxTransformBins() const { return m_maxTransformBins; }

	/** The mass of one bin.
	 * \throws std::out_of_range if a coordinate is out of range. */
	Mass at(std::size_t sector, std::size_t bin) const;
	/** at() without the checks, for the transform's inner loop: sector <
	 * sectorCount(), bin < binCount(). */
	Mass massAt(std::size_t sector, std::size_t bin) const
	{
		const TSectorLayout& row = m_layouts[sector];
		if (bin < row.freeBins) return Mass::simpleFree(row.freeMass);
		const TBinRun* run = m_runs.data() + row.firstRun;
		for (const TBinRun* end = run + row.runCount; run != end; ++run)
		{
			if (bin < run->begin) break;
			if (bin < run->end)
				return detail::binMass(
					m_binMasses[run->offset + (bin - run->begin)], m_binsHoldIgnorance);
		}
		return Mass::vacuous();
	}

   private:
	/** Sets the bins, margin and per-sector storage for m_sectorCount
	 * sectors. */
	void startSectors(const TSourceGridOptions& options);
	/** Turns m_impactStart from the count of each sector's impacts (entry
	 * s + 1 for sector s) into where they start in m_impactRanges, which it
	 * sizes to hold them all. */
	void placeSectors();
	/** Writes every sector's row from its impacts and m_freeReach;
	 * `nearestRunOnly`: the transform covers each row up to the end of its
	 * first run (clouds). */
	void buildRows(const TSourceGridOptions& options, bool nearestRunOnly);

	std::size_t m_sectorCount = 0, m_binCount = 0;
	double m_binSize = 0.0, m_firstAngle = 0.0, m_spacing = 0.0, m_freeMargin = 0.0;
	bool m_fullTurn = false;
	std::vector<TSectorLayout> m_layouts;  //!< one per sector
	std::vector<TBinRun> m_runs;
	/** The runs' bins, one number each (detail::binMass()): a quarter of the
	 * memory of whole masses, which the transform's mixed cells read. */
	std::vector<double> m_binMasses;
	bool m_binsHoldIgnorance = true;
	std::vector<char> m_observed;  //!< per sector, and build()'s one more
	std::size_t m_maxInformedBins = 0, m_maxTransformBins = 0;
	std::vector<std::size_t> m_transformBins;  //!< per sector
	/** Every sector's impact ranges, sector after sector: sector s's are
	 * [m_impactStart[s], m_impactStart[s + 1]). One array, so that the
	 * transform's walks over the sectors read them in order. */
	std::vector<double> m_impactRanges;
	/** sectorCount() + 2 entries: after the last sector's end, that of the
	 * beams without evidence (build()'s). */
	std::vector<std::size_t> m_impactStart;
	/** A beam's sector (sectorCount() for a beam without evidence) and
	 * impact range, +inf for no return read as free (build()'s scratch). */
	struct TBeam
	{
		std::size_t sector;
		double range;
	};
	std::vector<TBeam> m_beams;
	std::vector<double> m_freeReach;  //!< per sector, 0 for scans
};

}  // namespace mrpt_evidential
