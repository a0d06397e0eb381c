/* mrpt-evidential: internal: the quiet free run's kernel eight cells at a
 * time, for processors with AVX2 (EvidentialGridStorage::fuseQuietFreeRun()
 * hands it the run when the processor has them). */
#pragma once

#include <mrpt_evidential/grid/QuantizedMass.h>

#include <cstddef>
#include <cstdint>

namespace mrpt_evidential::detail
{
/** What one quiet run's fusion needs of the storage. */
struct TQuietRun
{
	float w = 0;  //!< the simple free mass fused into each cell
	std::uint16_t ceiling = 0, stamp = 0, occupiedBelow = 0;
	/** decayFactor(s) = presentGain * stampGain[s & kStampMask]. */
	double presentGain = 1.0;
	const double* stampGain = nullptr;
};

/** True when this build has the AVX2 kernel and the processor (and its
 * operating system) can run it. */
bool hasAvx2Kernel();

/** Fuses run.w into cells[idx, end) eight at a time, with the results of
 * fuseSimpleFree<Decays, false>() bit for bit, and stops at the first block
 * of eight that holds a loud cell or when fewer than eight are left: returns
 * the index it stopped at. Call only when hasAvx2Kernel(). */
template <bool Decays>
std::size_t fuseQuietBlocksOfEight(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TQuietRun& run);

}  // namespace mrpt_evidential::detail
