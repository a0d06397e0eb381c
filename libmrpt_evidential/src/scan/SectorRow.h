/* mrpt-evidential: internal: a sector's row written sparsely, for
 * CPolarSourceGrid (which checks its options once per scan) and for
 * sectorMasses() (which expands it). */
#pragma once

#include <mrpt_evidential/scan/SensorModel.h>

#include <vector>

namespace mrpt_evidential::detail
{
/** Writes the row of a sector whose arguments are already checked and whose
 * impact ranges are sorted in increasing order: its leading free bins as a
 * count and one mass, and the bins past them that may hold evidence as runs
 * appended to `runs` (offsets into `masses`, where their masses are
 * appended). Bins outside the runs are vacuous. */
TSectorLayout appendSectorRow(
	const SensorModelParams& params, const double* sortedRanges,
	std::size_t nImpacts, double binSize, std::size_t nBins,
	std::vector<TBinRun>& runs, std::vector<Mass>& masses);
}  // namespace mrpt_evidential::detail
