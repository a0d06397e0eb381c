/* mrpt-evidential: internal: a sector's row written sparsely, for
 * CPolarSourceGrid (which checks its options once per scan) and for
 * sectorMasses() (which expands it). */
#pragma once

#include <mrpt_evidential/scan/SensorModel.h>

#include <cstddef>
#include <vector>

namespace mrpt_evidential::detail
{
/** rangeBin() as an index. */
inline std::size_t binOf(double r, double binSize, std::size_t nBins)
{
	return static_cast<std::size_t>(rangeBin(r, binSize, static_cast<double>(nBins)));
}

/** Writes the row of a sector whose arguments are already checked and whose
 * impact ranges are sorted in increasing order: its leading free bins as a
 * count and one mass, and the bins past them that may hold evidence as runs
 * appended to `runs` (offsets into `binMasses`, where one number per bin is
 * appended: binMass() turns it into the bin's mass). Bins outside the runs
 * are vacuous. The free bins hold muF reinforced once per impact (the beams
 * that crossed them); without
 * `freeMassToo` the layout's free mass is left at 0 for the caller to set
 * (CPolarSourceGrid gives a cloud's turn one free mass). */
TSectorLayout appendSectorRow(
	const SensorModelParams& params, const double* sortedRanges,
	std::size_t nImpacts, double binSize, std::size_t nBins,
	std::vector<TBinRun>& runs, std::vector<double>& binMasses, bool freeMassToo = true);
}  // namespace mrpt_evidential::detail
