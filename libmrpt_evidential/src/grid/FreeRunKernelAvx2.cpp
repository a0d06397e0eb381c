/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The free runs' kernels with AVX2: FreeRunKernel.cpp's SSE2 kernels on
 * eight cells at a time, the same float operations in the same order, so
 * that a map is the same bit for bit whichever kernel the processor runs.
 * Only this file's kernels are compiled for AVX2 (GCC's target pragma), so the
 * rest of the library stays on the baseline x86-64 of Debian's packages. */

#include "grid/FreeRunKernelAvx2.h"

#if defined(MRPT_EVIDENTIAL_HAS_AVX2_KERNELS)
#include <immintrin.h>

namespace mrpt_evidential::detail
{
const bool kAvx2Available = [] {
	__builtin_cpu_init();
	return __builtin_cpu_supports("avx2") != 0;
}();

// Everything from here to the instantiations is compiled for AVX2.
#pragma GCC push_options
#pragma GCC target("avx2")
namespace
{

/** The fields of eight cells, one 32-bit lane per cell, in cell order. */
struct TLanes8
{
	__m256i aside, free, occupied, stamp;
};

TLanes8 loadEight(const QuantizedCell* c)
{
	// Cells 0-1 | 4-5 in one register and 2-3 | 6-7 in the other: the
	// in-lane shuffles below then leave cells 0-3 in the low half and 4-7
	// in the high one.
	const __m256i p = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c));
	const __m256i q = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + 4));
	const __m256i a = _mm256_permute2x128_si256(p, q, 0x20);
	const __m256i b = _mm256_permute2x128_si256(p, q, 0x31);
	// Each 32-bit word is aside | free << 16 or occupied | stamp << 16.
	const __m256i low16 = _mm256_set1_epi32(0xFFFF);
	const __m256 highA = _mm256_castsi256_ps(_mm256_srli_epi32(a, 16)),
				 highB = _mm256_castsi256_ps(_mm256_srli_epi32(b, 16)),
				 lowA = _mm256_castsi256_ps(_mm256_and_si256(a, low16)),
				 lowB = _mm256_castsi256_ps(_mm256_and_si256(b, low16));
	return {
		_mm256_castps_si256(_mm256_shuffle_ps(lowA, lowB, _MM_SHUFFLE(2, 0, 2, 0))),
		_mm256_castps_si256(_mm256_shuffle_ps(highA, highB, _MM_SHUFFLE(2, 0, 2, 0))),
		_mm256_castps_si256(_mm256_shuffle_ps(lowA, lowB, _MM_SHUFFLE(3, 1, 3, 1))),
		_mm256_castps_si256(_mm256_shuffle_ps(highA, highB, _MM_SHUFFLE(3, 1, 3, 1)))};
}

void storeEight(QuantizedCell* c, const TLanes8& v)
{
	const __m256i lowWords = _mm256_or_si256(v.aside, _mm256_slli_epi32(v.free, 16));
	const __m256i highWords = _mm256_or_si256(v.occupied, _mm256_slli_epi32(v.stamp, 16));
	// Cells 0-1 | 4-5 and 2-3 | 6-7, put back in order.
	const __m256i a = _mm256_unpacklo_epi32(lowWords, highWords);
	const __m256i b = _mm256_unpackhi_epi32(lowWords, highWords);
	_mm256_storeu_si256(reinterpret_cast<__m256i*>(c), _mm256_permute2x128_si256(a, b, 0x20));
	_mm256_storeu_si256(reinterpret_cast<__m256i*>(c + 4), _mm256_permute2x128_si256(a, b, 0x31));
}

/** The decay factors of eight cells' stamps, each taken in double precision
 * and then rounded to single, as the other kernels take them. Loaded one by
 * one: AVX2's gather was slower than that on the AMD EPYC measured. */
__m256 eightFactors(const QuantizedCell* c, const TFreeRun& run, __m256i stamps)
{
	// Cells last written by the same scan share one factor: most blocks of
	// a free run, whose cells the scan before also crossed.
	const __m256i times = _mm256_and_si256(stamps, _mm256_set1_epi32(kStampMask));
	const __m256i firstTime = _mm256_permutevar8x32_epi32(times, _mm256_setzero_si256());
	if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(times, firstTime)) == -1)
		return _mm256_set1_ps(
			static_cast<float>(run.presentGain * run.stampGain[c[0].stamp & kStampMask]));
	float d[8];
	for (int k = 0; k < 8; ++k)
		d[k] = static_cast<float>(run.presentGain * run.stampGain[c[k].stamp & kStampMask]);
	return _mm256_loadu_ps(d);
}

/** The simple free mass w fused into normal parts (f, o) in stored units
 * with `Rule`, and the conflict of that fusion (Dempster's rule)
 * (fuseSimpleFree()). */
struct TFused8
{
	__m256 free, occupied, newConflict;
};
template <FreeFusion Rule = FreeFusion::Dempster>
TFused8 fuseFree(__m256 f, __m256 o, __m256 w)
{
	const __m256 scale = _mm256_set1_ps(static_cast<float>(kMassScale)),
				 one = _mm256_set1_ps(1.0f);
	const __m256 u = _mm256_sub_ps(_mm256_sub_ps(scale, f), o);
	if constexpr (isCautious(Rule))
	{
		// EvidentialGridStorage::cautiousFree(): both of its cases, selected.
		const __m256 tiny = _mm256_set1_ps(1e-30f), notW = _mm256_sub_ps(one, w);
		const __m256 cellsWeight =
			_mm256_cmp_ps(u, _mm256_mul_ps(notW, _mm256_add_ps(f, u)), _CMP_LE_OQ);
		const auto select = [&cellsWeight](__m256 ifCells, __m256 otherwise) {
			return _mm256_blendv_ps(otherwise, ifCells, cellsWeight);
		};
		const __m256 wu = _mm256_mul_ps(w, u), notWo = _mm256_mul_ps(notW, o);
		if constexpr (Rule == FreeFusion::CautiousNormalized)
		{
			const __m256 s =
				_mm256_div_ps(scale, _mm256_max_ps(_mm256_add_ps(u, notWo), tiny));
			return {select(f, _mm256_mul_ps(wu, s)), select(o, _mm256_mul_ps(notWo, s)),
					_mm256_setzero_ps()};
		}
		const __m256 s = _mm256_div_ps(
			select(_mm256_mul_ps(scale, u), scale),
			select(
				_mm256_max_ps(_mm256_mul_ps(_mm256_add_ps(f, u), _mm256_add_ps(o, u)), tiny),
				_mm256_max_ps(_mm256_add_ps(o, u), tiny)));
		return {select(_mm256_mul_ps(f, s), _mm256_mul_ps(wu, s)),
				select(_mm256_mul_ps(o, s), _mm256_mul_ps(notWo, s)), _mm256_setzero_ps()};
	}
	const __m256 lost = _mm256_mul_ps(o, w), newConflict = _mm256_div_ps(lost, scale);
	const __m256 normalize = Rule == FreeFusion::Dempster
		? _mm256_div_ps(scale, _mm256_max_ps(_mm256_sub_ps(scale, lost), _mm256_set1_ps(1e-30f)))
		: one;
	return {
		_mm256_mul_ps(_mm256_add_ps(f, _mm256_mul_ps(u, w)), normalize),
		_mm256_mul_ps(_mm256_sub_ps(o, lost), normalize), newConflict};
}

/** encodeScaledNormal(): n(F) and n(O) rounded, each at most `ceiling`,
 * together at most the scale. */
void encode(const TFused8& fused, __m256 ceiling, __m256i& free, __m256i& occupied)
{
	const __m256 half = _mm256_set1_ps(0.5f),
				 scale = _mm256_set1_ps(static_cast<float>(kMassScale));
	occupied = _mm256_cvttps_epi32(_mm256_min_ps(_mm256_add_ps(fused.occupied, half), ceiling));
	const __m256 room = _mm256_sub_ps(scale, _mm256_cvtepi32_ps(occupied));
	free = _mm256_cvttps_epi32(
		_mm256_min_ps(_mm256_min_ps(_mm256_add_ps(fused.free, half), room), ceiling));
}

/** The stamps of fused cells: the current one, with each cell's flags. */
__m256i restamped(__m256i stamps, const TFreeRun& run)
{
	return _mm256_or_si256(
		_mm256_and_si256(stamps, _mm256_set1_epi32(kStampFlags)), _mm256_set1_epi32(run.stamp));
}
}  // namespace

template <bool Decays, FreeFusion Rule>
std::size_t fuseQuietBlocksOfEight(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run)
{
	const __m256 mass = _mm256_set1_ps(run.w), ceiling = _mm256_set1_ps(run.ceiling);
	const __m256i judged = _mm256_set1_epi32(kEventJudgedWhenSeenFree),
				  occupiedLimit = _mm256_set1_epi32(static_cast<int>(run.occupiedBelow) - 1),
				  ceilingWord = _mm256_set1_epi32(run.ceiling), zero = _mm256_setzero_si256();
	for (; idx + 8 <= end; idx += 8)
	{
		QuantizedCell* c = cells + idx;
		const TLanes8 in = loadEight(c);
		// isLoudFor() on eight cells: such a block is the caller's.
		__m256i loudLanes = _mm256_or_si256(
			_mm256_cmpgt_epi32(in.occupied, occupiedLimit),
			_mm256_cmpeq_epi32(_mm256_and_si256(in.aside, judged), judged));
		if constexpr (isCautious(Rule))
			loudLanes = _mm256_or_si256(
				loudLanes,
				_mm256_cmpgt_epi32(
					_mm256_add_epi32(in.free, in.occupied),
					_mm256_set1_epi32(static_cast<int>(kMassScale) - 1)));
		if (_mm256_movemask_epi8(loudLanes) != 0) break;
		// Free at the ceiling, nothing occupied, no decay: left as they are,
		// stamp included (see the SSE2 kernel).
		__m256i saturated = zero;
		if constexpr (!Decays)
		{
			saturated = _mm256_and_si256(
				_mm256_cmpeq_epi32(in.free, ceilingWord), _mm256_cmpeq_epi32(in.occupied, zero));
			if (_mm256_movemask_epi8(saturated) == -1) continue;
		}
		__m256 f = _mm256_cvtepi32_ps(in.free), o = _mm256_cvtepi32_ps(in.occupied);
		if constexpr (Decays)
		{
			const __m256 d = eightFactors(c, run, in.stamp);
			f = _mm256_mul_ps(f, d);
			o = _mm256_mul_ps(o, d);
		}
		__m256i freeOut, occupiedOut;
		encode(fuseFree<Rule>(f, o, mass), ceiling, freeOut, occupiedOut);
		storeEight(c, {in.aside, freeOut, occupiedOut,
					   _mm256_or_si256(_mm256_and_si256(saturated, in.stamp),
									   _mm256_andnot_si256(saturated, restamped(in.stamp, run)))});
	}
	return idx;
}

template <bool Decays>
std::size_t fuseBlocksOfEightKeepingConflict(
	QuantizedCell* cells, std::size_t idx, std::size_t end, const TFreeRun& run)
{
	const __m256 scale = _mm256_set1_ps(static_cast<float>(kMassScale)),
				 mass = _mm256_set1_ps(run.w), one = _mm256_set1_ps(1.0f),
				 half = _mm256_set1_ps(0.5f),
				 maxConflict = _mm256_set1_ps(static_cast<float>(kMaxStoredConflict));
	for (; idx + 8 <= end; idx += 8)
	{
		QuantizedCell* c = cells + idx;
		const TLanes8 in = loadEight(c);
		__m256 f = _mm256_cvtepi32_ps(in.free), o = _mm256_cvtepi32_ps(in.occupied);
		// 1 - K, K the conflict the cell keeps.
		__m256 keep = _mm256_sub_ps(one, _mm256_div_ps(_mm256_cvtepi32_ps(in.aside), scale));
		if constexpr (Decays)
		{
			const __m256 d = eightFactors(c, run, in.stamp);
			const __m256 decayedKeep = _mm256_sub_ps(one, _mm256_mul_ps(d, _mm256_sub_ps(one, keep)));
			const __m256 s = _mm256_div_ps(_mm256_mul_ps(d, keep), decayedKeep);
			f = _mm256_mul_ps(f, s);
			o = _mm256_mul_ps(o, s);
			keep = decayedKeep;
		}
		const TFused8 fused = fuseFree(f, o, mass);
		// encodeScaled(): K rounded and capped, then the normal part.
		const __m256 conflict = _mm256_mul_ps(
			scale, _mm256_sub_ps(one, _mm256_mul_ps(keep, _mm256_sub_ps(one, fused.newConflict))));
		const __m256i conflictOut =
			_mm256_cvttps_epi32(_mm256_min_ps(_mm256_add_ps(conflict, half), maxConflict));
		__m256i freeOut, occupiedOut;
		encode(fused, scale, freeOut, occupiedOut);
		storeEight(c, {conflictOut, freeOut, occupiedOut, restamped(in.stamp, run)});
	}
	return idx;
}

// Instantiated where the pragma still holds: a template takes the target
// options of the place it is instantiated.
#define MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(Decays, Rule)                  \
	template std::size_t fuseQuietBlocksOfEight<Decays, FreeFusion::Rule>( \
		QuantizedCell*, std::size_t, std::size_t, const TFreeRun&);
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(true, Dempster)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(false, Dempster)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(true, Yager)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(false, Yager)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(true, CautiousNormalized)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(false, CautiousNormalized)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(true, CautiousToUnknown)
MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT(false, CautiousToUnknown)
#undef MRPT_EVIDENTIAL_BLOCKS_OF_EIGHT
template std::size_t fuseBlocksOfEightKeepingConflict<true>(
	QuantizedCell*, std::size_t, std::size_t, const TFreeRun&);
template std::size_t fuseBlocksOfEightKeepingConflict<false>(
	QuantizedCell*, std::size_t, std::size_t, const TFreeRun&);
#pragma GCC pop_options

}  // namespace mrpt_evidential::detail
#endif
