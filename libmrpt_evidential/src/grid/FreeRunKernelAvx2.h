/* mrpt-evidential: internal: the free runs' kernels eight cells at a time,
 * for processors with AVX2 (EvidentialGridStorage::fuseQuietFreeRun() and
 * fuseFreeRunKeepingConflict() hand them their runs where the processor has
 * it). */
#pragma once

#include <mrpt_evidential/grid/QuantizedMass.h>

#include <cstddef>
#include <cstdint>

namespace mrpt_evidential::detail
{
/** What a free run's fusion needs of the storage. */
struct TFreeRun
{
	float w = 0;  //!< the simple free mass fused into each cell
	std::uint16_t ceiling = 0, stamp = 0;
	std::uint16_t occupiedBelow = 0;  //!< see isLoud(); quiet runs only
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
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run);

/** Fuses run.w into cells[idx, end) eight at a time, with the results of
 * fuseSimpleFree<Decays, true>() (a grid that keeps conflict) bit for bit,
 * until fewer than eight are left: returns the index it stopped at. Call
 * only when hasAvx2Kernel(). */
template <bool Decays>
std::size_t fuseBlocksOfEightKeepingConflict(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run);

}  // namespace mrpt_evidential::detail
