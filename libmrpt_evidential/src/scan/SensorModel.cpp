/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/scan/SensorModel.h>
#include <mrpt_evidential/algebra/combination.h>

#include "scan/SectorRow.h"

#include <mrpt_evidential/support/CpuClones.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_evidential
{
std::optional<TInvalidOption> SensorModelParams::firstInvalid() const
{
	// Written as !(valid) so that NaN fails every test.
	const auto inUnitInterval = [](double v) { return v >= 0.0 && v <= 1.0; };
	if (!inUnitInterval(muF)) return TInvalidOption{"muF", "in [0, 1]", muF};
	if (!inUnitInterval(muO)) return TInvalidOption{"muO", "in [0, 1]", muO};
	if (!(imprecision >= 0.0 && std::isfinite(imprecision)))
		return TInvalidOption{"imprecision", "a finite number >= 0 (m)", imprecision};
	return std::nullopt;
}

void SensorModelParams::validate() const
{
	if (const auto bad = firstInvalid()) throw std::invalid_argument(bad->describe());
}

namespace
{
void checkArguments(
	const SensorModelParams& params, const double* impactRanges,
	std::size_t nImpacts, double binSize)
{
	params.validate();
	if (!(binSize > 0.0 && std::isfinite(binSize)))
		throw std::invalid_argument(
			"range bin size must be a positive finite number, got " +
			std::to_string(binSize));
	for (std::size_t i = 0; i < nImpacts; ++i)
		if (!(impactRanges[i] >= 0.0))
			throw std::invalid_argument(
				"impact range must be >= 0 (or +inf for no return), got " +
				std::to_string(impactRanges[i]));
}

/** The bins an impact gives occupied evidence to, [first, last] inclusive;
 * first == nBins when they all lie beyond the grid. For the imprecise model
 * these are the bins whose centre lies within d of the impact, plus the bin
 * holding the impact itself, so that d below half a bin gives exactly one bin
 * as in the reinforced model. */
struct Band
{
	std::size_t first, last;
	std::size_t own;  //!< the bin holding the impact (nBins: beyond the grid)
};

/** Whether an impact's occupied evidence spreads beyond its own bin. */
bool spreads(const SensorModelParams& p)
{
	return p.model == SensorModel::ImpreciseMultiEcho && p.imprecision != 0.0;
}

/** A band's bins as whole numbers in doubles: loops over many vectorize. */
struct TBandBins
{
	double first, last, own;
};

/** The band of the impact at range r (>= 0 or +inf), without branches;
 * `Spread`: the imprecise model's bins within d, else the own bin alone. */
template <bool Spread>
inline TBandBins bandBins(double d, double r, double binSize, double maxIndex)
{
	const double own = rangeBin(r, binSize, maxIndex);
	if constexpr (!Spread) return {own, own, own};
	const double lo = std::ceil((r - d) / binSize - 0.5);
	const double hi = std::floor((r + d) / binSize - 0.5);
	// +inf (no return) has no band but its own bin.
	const bool banded = (r <= DBL_MAX) & (hi >= lo);
	const double loIndex = std::min(std::max(lo, 0.0), maxIndex);
	const double hiIndex = std::min(std::max(hi, 0.0), maxIndex);
	return {banded ? std::min(own, loIndex) : own, banded ? std::max(own, hiIndex) : own, own};
}

/** The band of one impact, as above; `spread`: spreads(p). */
inline Band occupiedBand(
	const SensorModelParams& p, bool spread, double r, double binSize, std::size_t nBins)
{
	const auto maxIndex = static_cast<double>(nBins);
	const TBandBins b = spread ? bandBins<true>(p.imprecision, r, binSize, maxIndex)
							   : bandBins<false>(p.imprecision, r, binSize, maxIndex);
	return {static_cast<std::size_t>(b.first), static_cast<std::size_t>(b.last),
			static_cast<std::size_t>(b.own)};
}

/** The imprecise model's bands of up to kBandChunk impacts, for sectors of
 * kChunkFrom impacts or more (fewer are not worth a call to the vector
 * copy). */
constexpr std::size_t kBandChunk = 64, kChunkFrom = 8;
struct TBandChunk
{
	double first[kBandChunk], last[kBandChunk], own[kBandChunk];
	Band operator[](std::size_t i) const
	{
		return {static_cast<std::size_t>(first[i]), static_cast<std::size_t>(last[i]),
				static_cast<std::size_t>(own[i])};
	}
};

/** The imprecise model's bands of n <= kBandChunk impacts in one loop that
 * vectorizes: a cloud's sector holds dozens, each of which waited on its
 * three divisions (a tenth of a cloud's insertion). */
MRPT_EVIDENTIAL_CPU_CLONES void spreadBands(
	double d, const double* ranges, std::size_t n, double binSize, std::size_t nBins,
	TBandChunk& out)
{
	const auto maxIndex = static_cast<double>(nBins);
	for (std::size_t i = 0; i < n; ++i)
	{
		const TBandBins b = bandBins<true>(d, ranges[i], binSize, maxIndex);
		out.first[i] = b.first, out.last[i] = b.last, out.own[i] = b.own;
	}
}

/** Profile weight g of bin b for an impact at range r (g = 1 at the impact's
 * own bin). */
double profileWeight(
	const SensorModelParams& p, double r, std::size_t ownBin, std::size_t b,
	double binSize)
{
	if (p.model != SensorModel::ImpreciseMultiEcho ||
		p.profile == ImprecisionProfile::Box || b == ownBin)
		return 1.0;
	// sigma = d / 2, so x^2 / (2 sigma^2) = 2 x^2 / d^2.
	const double x = (static_cast<double>(b) + 0.5) * binSize - r;
	return std::exp(-2.0 * x * x / (p.imprecision * p.imprecision));
}

/** appendSectorRow() for a sector of one impact (a 2-D scan's beam): the same
 * masses, written once each, without the search for runs to join. */
TSectorLayout oneImpactRow(
	const SensorModelParams& params, bool spread, double r, double binSize,
	std::size_t nBins, std::vector<TBinRun>& runs, std::vector<double>& binMasses,
	bool freeMassToo)
{
	TSectorLayout layout;
	layout.firstRun = runs.size();
	const Band band = occupiedBand(params, spread, r, binSize, nBins);
	layout.freeBins = band.first;
	layout.informedBins = band.first;
	if (band.first > 0 && freeMassToo) layout.freeMass = params.muF;
	if (band.first >= nBins) return layout;

	const std::size_t end = std::min(band.last + 1, nBins);
	TBinRun& run = runs.emplace_back();
	run.begin = band.first, run.end = end, run.offset = binMasses.size();
	layout.runCount = 1;
	layout.informedBins = end;
	if (params.model == SensorModel::MultiEcho)
	{
		binMasses.push_back(params.muO);
		binMasses.resize(binMasses.size() + (end - band.first - 1), 0.0);
		return layout;
	}
	for (std::size_t b = band.first; b < end; ++b)
		binMasses.push_back(1.0 - params.muO * profileWeight(params, r, band.own, b, binSize));
	return layout;
}

}  // namespace

namespace detail
{
TSectorLayout appendSectorRow(
	const SensorModelParams& params, const double* sortedRanges,
	std::size_t nImpacts, double binSize, std::size_t nBins,
	std::vector<TBinRun>& runs, std::vector<double>& binMasses, bool freeMassToo)
{
	TSectorLayout layout;
	layout.firstRun = runs.size();
	if (nImpacts == 0) return layout;
	const bool spread = spreads(params);
	// A 2-D scan's sector holds one beam's impact.
	if (nImpacts == 1)
		return oneImpactRow(
			params, spread, sortedRanges[0], binSize, nBins, runs, binMasses, freeMassToo);

	// Sorted impacts give bands sorted by their first bin. Runs hold the
	// bands; bands a few bins apart share a run (its vacuous bins cost less
	// than one more run to look through). Reinforcement: the occupied mass
	// of a bin is 1 - prod(1 - muO g_i) over the impacts whose band holds
	// it; its m(Omega) is the product (1 for none).
	constexpr std::size_t kJoinGap = 8;
	const bool reinforces = detail::binsHoldIgnorance(params.model);
	const double none = reinforces ? 1.0 : 0.0;
	std::size_t firstOccupied = nBins;
	// A sector of many impacts (a cloud's) has their bands worked out in
	// chunks by the vector code; a few are not worth the call.
	const bool chunked = spread && nImpacts >= kChunkFrom;
	TBandChunk bands;
	for (std::size_t i = 0; i < nImpacts; ++i)
	{
		if (chunked && i % kBandChunk == 0)
			spreadBands(
				params.imprecision, sortedRanges + i, std::min(kBandChunk, nImpacts - i),
				binSize, nBins, bands);
		const Band band = chunked ? bands[i % kBandChunk]
								  : occupiedBand(params, spread, sortedRanges[i], binSize, nBins);
		firstOccupied = std::min(firstOccupied, band.first);
		if (band.first >= nBins) break;
		const std::size_t end = std::min(band.last + 1, nBins);
		if (runs.size() > layout.firstRun &&
			band.first <= runs.back().end + kJoinGap)
		{
			TBinRun& run = runs.back();
			for (; run.end < end; ++run.end) binMasses.push_back(none);
		}
		else
		{
			// Field by field: a run built whole on the stack was read back in
			// one 16-byte load from two 8-byte stores, a stall per sector.
			TBinRun& run = runs.emplace_back();
			run.begin = band.first, run.end = end, run.offset = binMasses.size();
			binMasses.resize(binMasses.size() + (end - band.first), none);
		}
		double* row = binMasses.data() + runs.back().offset - runs.back().begin;
		if (!reinforces)
		{
			row[band.first] = params.muO;
			continue;
		}
		for (std::size_t b = band.first; b < end; ++b)
			row[b] *= 1.0 -
				params.muO * profileWeight(params, sortedRanges[i], band.own, b, binSize);
	}
	layout.runCount = runs.size() - layout.firstRun;

	layout.freeBins = firstOccupied;
	// Every beam crossed the bins before the nearest band.
	if (firstOccupied > 0 && freeMassToo)
		layout.freeMass = params.model == SensorModel::MultiEcho
			? params.muF
			: 1.0 - std::pow(1.0 - params.muF, static_cast<double>(nImpacts));
	layout.informedBins =
		layout.runCount > 0 ? runs.back().end : firstOccupied;
	return layout;
}
}  // namespace detail

std::vector<Mass> sectorMasses(
	const SensorModelParams& params, const std::vector<double>& impactRanges,
	double binSize, std::size_t nBins)
{
	checkArguments(params, impactRanges.data(), impactRanges.size(), binSize);
	std::vector<double> sorted = impactRanges;
	std::sort(sorted.begin(), sorted.end());
	std::vector<TBinRun> runs;
	std::vector<double> binMasses;
	const TSectorLayout layout = detail::appendSectorRow(
		params, sorted.data(), sorted.size(), binSize, nBins, runs, binMasses);
	std::vector<Mass> row(nBins, Mass::vacuous());
	std::fill(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(layout.freeBins),
			  Mass::simpleFree(layout.freeMass));
	const bool ignorance = detail::binsHoldIgnorance(params.model);
	for (const TBinRun& run : runs)
		for (std::size_t b = run.begin; b < run.end; ++b)
			row[b] = detail::binMass(binMasses[run.offset + (b - run.begin)], ignorance);
	return row;
}

std::vector<Mass> sectorMassesByCombination(
	const SensorModelParams& params, const std::vector<double>& impactRanges,
	double binSize, std::size_t nBins)
{
	if (params.model == SensorModel::MultiEcho)
		return sectorMasses(params, impactRanges, binSize, nBins);
	checkArguments(params, impactRanges.data(), impactRanges.size(), binSize);

	std::vector<Mass> cumulative(nBins, Mass::vacuous());
	std::vector<Mass> mask(nBins, Mass::degenerate());
	const Mass maskBehind{0.0, 0.0, 1.0, 0.0};
	for (const double r : impactRanges)
	{
		const Band band = occupiedBand(params, spreads(params), r, binSize, nBins);
		for (std::size_t b = 0; b < nBins; ++b)
		{
			Mass impact = Mass::vacuous();
			if (b < band.first)
				impact = Mass::simpleFree(params.muF);
			else if (b <= band.last)
				impact = Mass::simpleOccupied(
					params.muO * profileWeight(params, r, band.own, b, binSize));
			cumulative[b] = conjunctive(cumulative[b], impact);
			mask[b] = disjunctive(
				mask[b], b < band.first ? Mass::degenerate() : maskBehind);
		}
	}
	std::vector<Mass> row(nBins);
	for (std::size_t b = 0; b < nBins; ++b)
		row[b] = disjunctive(cumulative[b], mask[b]);
	return row;
}

}  // namespace mrpt_evidential
