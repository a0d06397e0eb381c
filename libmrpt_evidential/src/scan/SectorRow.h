/* mrpt-evidential: internal: a sector's row written sparsely, for
 * CPolarSourceGrid (which checks its options once per scan) and for
 * sectorMasses() (which expands it). */
#pragma once

#include <mrpt_evidential/scan/SensorModel.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace mrpt_evidential::detail
{
/** The bin holding range r, as a whole number in a double (loops over many
 * ranges then vectorize), or nBins when r lies beyond the last bin (+inf
 * included). A range within a billionth of a bin below an edge
 * counts in the upper bin: 4.0 / 0.05 is 79.99999999999999 in binary, yet 4 m
 * lies in the bin that starts at 4 m. Compared as doubles so that huge ranges
 * never overflow the conversion. */
inline double binOfInDouble(double r, double binSize, double nBins)
{
	const double x = r / binSize + 1e-9;
	return x < nBins ? std::trunc(x) : nBins;
}
/** binOfInDouble() as an index. */
inline std::size_t binOf(double r, double binSize, std::size_t nBins)
{
	return static_cast<std::size_t>(binOfInDouble(r, binSize, static_cast<double>(nBins)));
}

/** Writes the row of a sector whose arguments are already checked and whose
 * impact ranges are sorted in increasing order: its leading free bins as a
 * count and one mass, and the bins past them that may hold evidence as runs
 * appended to `runs` (offsets into `masses`, where their masses are
 * appended). Bins outside the runs are vacuous. The free bins hold muF
 * reinforced once per impact (the beams that crossed them), or muF alone
 * with `oneBeamFree` (a cloud: its layers cross the cells before the nearest
 * impact at other heights, most of them above or below the obstacles'). */
TSectorLayout appendSectorRow(
	const SensorModelParams& params, const double* sortedRanges,
	std::size_t nImpacts, double binSize, std::size_t nBins,
	std::vector<TBinRun>& runs, std::vector<Mass>& masses, bool oneBeamFree = false);
}  // namespace mrpt_evidential::detail
