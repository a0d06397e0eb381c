/* mrpt-evidential: internal: the free runs' kernels eight cells at a time,
 * for processors with AVX2 (EvidentialGridStorage::fuseQuietFreeRun() and
 * fuseFreeRunKeepingConflict() hand them their runs where the processor has
 * it). */
#pragma once

#include <mrpt_evidential/grid/EvidentialGridStorage.h>
#include <mrpt_evidential/grid/QuantizedMass.h>

#include <cstddef>
#include <cstdint>

// Built with GCC's target pragma on x86-64; other compilers (clang builds
// the fuzzers) and architectures keep the SSE2 kernels alone.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
	!defined(MRPT_EVIDENTIAL_NO_CPU_CLONES)
#define MRPT_EVIDENTIAL_HAS_AVX2_KERNELS 1
#endif

#if defined(MRPT_EVIDENTIAL_HAS_AVX2_KERNELS)
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

/** True when the processor (and its operating system) can run the kernels
 * below: found once, when the library is loaded. (Read before that, by
 * another library's static initialization, it is false: the SSE2 kernels,
 * with the same results.) */
extern const bool kAvx2Available;

/** Fuses run.w into cells[idx, end) eight at a time, with the results of
 * fuseSimpleFree<Decays, false, Rule>() bit for bit, and stops at the first
 * block of eight that holds a cell isLoudFor<Rule>() calls loud or when
 * fewer than eight are left: returns the index it stopped at. Call only
 * when kAvx2Available. */
template <bool Decays, FreeFusion Rule>
std::size_t fuseQuietBlocksOfEight(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run);

/** Fuses run.w into cells[idx, end) eight at a time, with the results of
 * fuseSimpleFree<Decays, true>() (a grid that keeps conflict) bit for bit,
 * until fewer than eight are left: returns the index it stopped at. Call
 * only when kAvx2Available. */
template <bool Decays>
std::size_t fuseBlocksOfEightKeepingConflict(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run);

}  // namespace mrpt_evidential::detail
#endif
