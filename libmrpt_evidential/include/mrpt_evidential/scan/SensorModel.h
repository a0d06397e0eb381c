/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The lidar inverse sensor models of one angular sector (standard library
 * only; the MRPT-facing polar grid is in CPolarSourceGrid.h). */
#pragma once

#include <mrpt_evidential/TInvalidOption.h>
#include <mrpt_evidential/algebra/Mass.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace mrpt_evidential
{
/** The three lidar inverse sensor models (see doc/sensor-models.md). */
enum class SensorModel
{
	/** Free before the nearest impact, muO in every bin holding an impact,
	 * whatever the number of impacts there (no reinforcement). */
	MultiEcho,
	/** Impact and mask mass functions per impact, combined conjunctively and
	 * disjunctively: every extra impact in a bin adds occupied evidence, every
	 * impact adds free evidence before the nearest one. */
	ReinforcedMultiEcho,
	/** As ReinforcedMultiEcho, with each impact's occupied evidence spread over
	 * [R - d, R + d] along the beam (d = imprecision) by a profile. */
	ImpreciseMultiEcho
};

/** How the imprecise model spreads an impact's occupied evidence. */
enum class ImprecisionProfile
{
	Box,  //!< muO over the whole interval (the discrete imprecise model)
	Gaussian  //!< muO * exp(-x^2 / (2 sigma^2)) with sigma = d / 2
};

/** Parameters of a sector model. */
struct SensorModelParams
{
	SensorModel model = SensorModel::ReinforcedMultiEcho;
	/** Detection rate: the free mass one beam gives to a bin it crosses,
	 * in [0, 1]. */
	double muF = 0.7;
	/** True-positive rate (1 - false alarm rate): the occupied mass one impact
	 * gives to its bin, in [0, 1]. */
	double muO = 0.9;
	/** Half-width d of an impact's interval, metres, >= 0 (ImpreciseMultiEcho
	 * only). Below half a bin the model equals ReinforcedMultiEcho. */
	double imprecision = 0.0;
	ImprecisionProfile profile = ImprecisionProfile::Box;

	/** The first parameter out of range (muF or muO outside [0, 1],
	 * imprecision negative or not finite), if any. */
	std::optional<TInvalidOption> firstInvalid() const;
	/** \throws std::invalid_argument describing firstInvalid(). */
	void validate() const;
};

namespace detail
{
/** A run's bin holds occupied evidence only: m(O) and the rest on Omega,
 * stored as one number, the one the sensor model works out. The reinforcing
 * models multiply ignorances, so their bins keep m(Omega); MultiEcho's keep
 * m(O). The other is 1 minus it, as the model itself takes it. */
constexpr bool binsHoldIgnorance(SensorModel model)
{
	return model != SensorModel::MultiEcho;
}
/** The mass of a run's bin from its stored number (binsHoldIgnorance()). */
constexpr Mass binMass(double stored, bool ignorance)
{
	// Both parts worked out and then picked, so that the transform's mixed
	// cells select instead of branching.
	const double rest = 1.0 - stored;
	return {0.0, 0.0, ignorance ? rest : stored, ignorance ? stored : rest};
}
}  // namespace detail

/** A run of range bins [begin, end) of a sector row kept sparse, whose
 * masses are stored from `offset` on, one number per bin (detail::binMass()). */
struct TBinRun
{
	std::size_t begin = 0, end = 0, offset = 0;
};

/** Where the evidence of a sector row kept sparse lies: its leading free bins
 * all hold one free mass, then runs of bins (in increasing order, after the
 * free bins) hold occupied evidence; every other bin is vacuous. A row then
 * costs memory for its impacts, not for its length. */
struct TSectorLayout
{
	/** Leading bins that all hold Mass::simpleFree(freeMass): the bins before
	 * the nearest impact. */
	std::size_t freeBins = 0;
	double freeMass = 0.0;
	/** Leading bins that may hold evidence; every bin from it on is vacuous. */
	std::size_t informedBins = 0;
	/** The row's runs, by index into a list of runs. */
	std::size_t firstRun = 0, runCount = 0;
};

/** One sector's row of masses, bin b covering ranges [b binSize,
 * (b + 1) binSize) (a range a billionth of a bin below an edge counts in the
 * upper bin, so that binary rounding of r / binSize does not move ranges that
 * are multiples of the bin size). `impactRanges` holds the ranges of every impact of the
 * sector (echoes, layers or beams), in any order, duplicates allowed; +inf
 * stands for a beam that crossed every bin without a return (free evidence,
 * no impact). An impact beyond the last bin also only gives free evidence.
 * With no impacts every bin is vacuous.
 *
 * Uses the closed forms of the models (doc/sensor-models.md): O(bins +
 * impacts x band width). CPolarSourceGrid builds the same rows sparse.
 * \throws std::invalid_argument if the parameters are invalid, binSize is not
 *  a positive finite number, or an impact range is NaN or negative. */
std::vector<Mass> sectorMasses(
	const SensorModelParams& params, const std::vector<double>& impactRanges,
	double binSize, std::size_t nBins);

/** The seed's literal construction of the same row: for each impact, an impact
 * mass function and a mask mass function over the bins; the impact functions
 * are combined conjunctively from the vacuous mass, the masks disjunctively
 * from the degenerate mass, and the row is the disjunction of the two. It is
 * O(impacts x bins) and serves as the reference the closed form is tested
 * against. MultiEcho is not built by combination in the seed; for it this
 * returns sectorMasses(). Same contract as sectorMasses(). */
std::vector<Mass> sectorMassesByCombination(
	const SensorModelParams& params, const std::vector<double>& impactRanges,
	double binSize, std::size_t nBins);

/** The bin of a row of nBins bins of binSize (sectorMasses()) that holds
 * range r >= 0, as a whole number in a double (loops over many ranges then
 * vectorize): floor(r / binSize), a range within a billionth of a bin below
 * an edge counting in the upper bin (4.0 / 0.05 is 79.99999999999999 in
 * binary, yet 4 m lies in the bin that starts at 4 m); nBins when r lies
 * beyond the last bin, +inf included (compared as doubles, so that huge
 * ranges never overflow a conversion). Never throws. */
inline double rangeBin(double r, double binSize, double nBins)
{
	const double x = r / binSize + 1e-9;
	return x < nBins ? std::trunc(x) : nBins;
}

}  // namespace mrpt_evidential
