/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scan/SectorRow.h"

namespace mrpt_evidential
{
std::optional<TInvalidOption> TSourceGridOptions::firstInvalid() const
{
	if (auto bad = sensorModel.firstInvalid()) return bad;
	if (!(sectorWidth >= 0.0 && sectorWidth <= 2 * M_PI))
		return TInvalidOption{
			"sectorWidth", "in [0, 2 pi] rad (0 to 360 degrees)", sectorWidth};
	if (!(maxRange > 0.0 && std::isfinite(maxRange)))
		return TInvalidOption{"maxRange", "a finite number > 0 (m)", maxRange};
	if (!(binSize > 0.0 && std::isfinite(binSize)))
		return TInvalidOption{"binSize", "a finite number > 0 (m)", binSize};
	if (!(freeMargin >= 0.0 && std::isfinite(freeMargin)))
		return TInvalidOption{"freeMargin", "a finite number >= 0 (m)", freeMargin};
	if (const double bins = maxRange / binSize; bins > 1e7)
	{
		std::ostringstream rule;
		rule << "at most 1e7 range bins long (" << bins << " bins of " << binSize << " m)";
		return TInvalidOption{"maxRange", rule.str(), maxRange};
	}
	return std::nullopt;
}

void TSourceGridOptions::validate() const
{
	if (const auto bad = firstInvalid()) throw std::invalid_argument(bad->describe());
}

namespace
{
/** The sector of each beam of an evenly spaced scan, by the beam's rank in
 * angle order (0 at the smallest angle): the one whose centre is nearest,
 * and for a beam midway between two centres, the one at the greater angle.
 * Midway beams are common (sectors of an even number of beams); their
 * positions, worked out from the ranks, are off midway by the float
 * aperture's rounding (parts in 1e8 of a position), so a bias far above that
 * and far below the distance of any other beam from midway sends them all
 * the same way. */
class BeamSectors
{
   public:
	BeamSectors(double beamSpacing, double aperture, const CPolarSourceGrid& grid)
		: m_count(grid.sectorCount()), m_fullTurn(grid.fullTurn())
	{
		if (m_count < 2) return;  // one sector (or none) takes every beam
		m_ratio = beamSpacing / grid.sectorSpacing();
		m_start = (-0.5 * aperture - grid.firstSectorAngle()) / grid.sectorSpacing() + 0.5 +
			kMidwayBias;
	}
	std::size_t operator()(std::size_t rank) const
	{
		if (m_count < 2) return 0;
		// Positions are >= 0 up to rounding: truncation rounds them (the
		// half is in m_start), without a call to std::round.
		const auto position = static_cast<std::size_t>(
			std::max(0.0, static_cast<double>(rank) * m_ratio + m_start));
		return m_fullTurn ? position % m_count : std::min(m_count - 1, position);
	}

   private:
	static constexpr double kMidwayBias = 1e-4;
	std::size_t m_count;
	bool m_fullTurn;
	double m_ratio = 0.0, m_start = 0.0;
};
}  // namespace

void CPolarSourceGrid::build(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const TSourceGridOptions& options)
{
	options.validate();
	const std::size_t nBeams = scan.getScanSize();
	const double aperture = scan.aperture;
	// A single beam's sector is as wide as the aperture, so it is checked too.
	if (nBeams > 0 && !(aperture > 0.0 && aperture <= 2 * M_PI + 1e-6))
		throw std::invalid_argument(
			"scan aperture must be in (0, 2 pi] rad, got " +
			std::to_string(aperture));

	const double beamSpacing =
		nBeams > 1 ? aperture / static_cast<double>(nBeams - 1) : aperture;
	m_spacing = std::max(options.sectorWidth, beamSpacing);
	// A scan of a full turn has its first and last beams in the same
	// direction (MRPT spreads N beams over [-pi, pi]): its sectors go round
	// once, evenly, and the last beam joins the first sector.
	m_fullTurn = nBeams > 1 && aperture >= 2 * M_PI - 1e-6;
	if (m_fullTurn)
	{
		m_sectorCount = std::max<std::size_t>(
			1, static_cast<std::size_t>(std::lround(2 * M_PI / m_spacing)));
		m_spacing = 2 * M_PI / static_cast<double>(m_sectorCount);
		m_firstAngle = -M_PI;
	}
	else if (nBeams > 1)
	{
		m_firstAngle = -0.5 * aperture;
		m_sectorCount =
			static_cast<std::size_t>(std::lround(aperture / m_spacing)) + 1;
	}
	else
	{
		m_firstAngle = 0.0;
		m_sectorCount = nBeams;
	}
	startSectors(options);

	constexpr double kNoReturn = std::numeric_limits<double>::infinity();
	const BeamSectors sectorOf(beamSpacing, aperture, *this);
	// Ranges read in place: three library calls per beam cost more than the
	// rest of this loop. Two passes: each beam's sector and the sectors'
	// counts, then the ranges in their sectors' places. A beam that gives no
	// evidence goes to a sector past the last, which no one reads: the
	// second pass then takes every beam alike.
	const float* ranges = nBeams > 0 ? &scan.getScanRange(0) : nullptr;
	const std::size_t none = m_sectorCount;
	m_beams.resize(nBeams);
	for (std::size_t i = 0; i < nBeams; ++i)
	{
		const double r = ranges[i];
		const bool valid = scan.getScanRangeValidity(i) && std::isfinite(r) &&
			r > 0.0;
		// Beam 0 is at the smallest angle when the scan turns
		// counterclockwise, at the largest otherwise.
		const std::size_t sector = valid || options.invalidRangesAsFree
			? sectorOf(scan.rightToLeft ? i : nBeams - 1 - i)
			: none;
		m_beams[i] = {sector, valid ? r : kNoReturn};
		++m_impactStart[sector + 1];
		m_observed[sector] = 1;
	}
	placeSectors();
	// m_impactStart[s] is sector s's next free place until it is set back.
	for (const TBeam& beam : m_beams) m_impactRanges[m_impactStart[beam.sector]++] = beam.range;
	// Each sector's next free place is now where the next sector starts.
	std::copy_backward(
		m_impactStart.begin(), m_impactStart.end() - 1, m_impactStart.end());
	m_impactStart[0] = 0;

	buildRows(options, false);
}

void CPolarSourceGrid::build(const TCloudReturns& returns, const TSourceGridOptions& options)
{
	options.validate();
	const std::size_t n = returns.sectorCount();
	if (n == 0 || returns.freeReach.size() != n)
		throw std::invalid_argument(
			"cloud returns: " + std::to_string(n) + " sectors of impacts and " +
			std::to_string(returns.freeReach.size()) + " free reaches");
	m_sectorCount = n;
	m_spacing = 2 * M_PI / static_cast<double>(n);
	m_firstAngle = -M_PI;
	m_fullTurn = true;
	startSectors(options);
	for (std::size_t s = 0; s < n; ++s)
	{
		const double reach = returns.freeReach[s];
		if (!(reach >= 0.0))
			throw std::invalid_argument(
				"cloud returns: free reach " + std::to_string(reach) + " of sector " +
				std::to_string(s));
		for (const double r : returns.impacts[s])
			if (!(r >= 0.0))
				throw std::invalid_argument(
					"cloud returns: impact range " + std::to_string(r) + " in sector " +
					std::to_string(s));
		m_impactStart[s + 1] = returns.impacts[s].size();
		m_freeReach[s] = reach;
		m_observed[s] = !returns.impacts[s].empty() || reach > 0.0;
	}
	placeSectors();
	for (std::size_t s = 0; s < n; ++s)
		std::copy(
			returns.impacts[s].begin(), returns.impacts[s].end(),
			m_impactRanges.begin() + static_cast<std::ptrdiff_t>(m_impactStart[s]));
	buildRows(options, true);
}

void CPolarSourceGrid::startSectors(const TSourceGridOptions& options)
{
	m_binSize = options.binSize;
	m_freeMargin = options.freeMargin;
	m_binCount =
		static_cast<std::size_t>(std::ceil(options.maxRange / options.binSize));
	// One more sector than the grid's: build()'s beams without evidence.
	m_impactStart.assign(m_sectorCount + 2, 0);
	m_freeReach.assign(m_sectorCount, 0.0);
	m_observed.assign(m_sectorCount + 1, 0);
}

void CPolarSourceGrid::placeSectors()
{
	for (std::size_t s = 1; s < m_impactStart.size(); ++s) m_impactStart[s] += m_impactStart[s - 1];
	m_impactRanges.resize(m_impactStart.back());
}

void CPolarSourceGrid::buildRows(const TSourceGridOptions& options, bool nearestRunOnly)
{
	m_layouts.resize(m_sectorCount);
	m_transformBins.resize(m_sectorCount);
	m_runs.clear();
	m_binMasses.clear();
	m_binsHoldIgnorance = detail::binsHoldIgnorance(options.sensorModel.model);
	m_maxInformedBins = m_maxTransformBins = 0;
	for (std::size_t s = 0; s < m_sectorCount; ++s)
	{
		double* first = m_impactRanges.data() + m_impactStart[s];
		const std::size_t count = m_impactStart[s + 1] - m_impactStart[s];
		std::sort(first, first + count);
		TSectorLayout& layout = m_layouts[s];
		layout = detail::appendSectorRow(
			options.sensorModel, first, count, m_binSize, m_binCount, m_runs, m_binMasses,
			!nearestRunOnly);
		if (count == 0 && m_freeReach[s] > 0.0)
		{
			// Only ground returns: the space they crossed.
			layout.freeBins = binOfRange(m_freeReach[s]);
			layout.informedBins = layout.freeBins;
		}
		// A cloud's layers cross the cells before its nearest impact at
		// other heights, most of them above or below the obstacles': one
		// beam's proof, whatever the model (and one free mass for the
		// whole turn, which the transform fuses as runs).
		if (nearestRunOnly) layout.freeMass = layout.freeBins > 0 ? options.sensorModel.muF : 0.0;
		m_maxInformedBins = std::max(m_maxInformedBins, layout.informedBins);
		m_transformBins[s] = nearestRunOnly && layout.runCount > 0
			? m_runs[layout.firstRun].end
			: layout.informedBins;
		m_maxTransformBins = std::max(m_maxTransformBins, m_transformBins[s]);
	}
}

std::size_t CPolarSourceGrid::binOfRange(double r) const
{
	return detail::binOf(r, m_binSize, m_binCount);
}

Mass CPolarSourceGrid::at(std::size_t sector, std::size_t bin) const
{
	if (sector >= m_sectorCount)
		throw std::out_of_range(
			"sector " + std::to_string(sector) + " of " +
			std::to_string(m_sectorCount));
	if (bin >= m_binCount)
		throw std::out_of_range(
			"bin " + std::to_string(bin) + " of " + std::to_string(m_binCount));
	return massAt(sector, bin);
}

}  // namespace mrpt_evidential
