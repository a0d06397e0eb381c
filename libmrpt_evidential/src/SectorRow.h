/* mrpt-evidential: internal: a sector's row written without the argument
 * checks and the clearing of sectorMassesInto(), for CPolarSourceGrid, which
 * checks its options once per scan and clears only what it wrote before. */
#pragma once

#include <mrpt_evidential/SensorModel.h>

namespace mrpt_evidential::detail
{
/** How far a written row reaches. */
struct SectorExtent
{
	/** Leading bins that all hold the row's free mass, out[0]. */
	std::size_t freeBins = 0;
	/** Leading bins that may hold evidence; the rest stay vacuous. */
	std::size_t informedBins = 0;
};

/** sectorMassesInto() on a row that already holds vacuous masses, with
 * arguments already checked; writes only the leading informed bins. */
SectorExtent writeSectorRow(
	const SensorModelParams& params, const double* impactRanges,
	std::size_t nImpacts, double binSize, std::size_t nBins, Mass* out);
}  // namespace mrpt_evidential::detail
