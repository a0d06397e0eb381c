/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * EvidentialGridStorage::fuseQuietFreeRun() and fuseFreeRunKeepingConflict():
 * the bulk of a scan's cells, four cells at a time with SSE2 where the
 * target has it (eight with AVX2, FreeRunKernelAvx2.cpp, where the processor
 * has it). The compiler vectorizes fuseSimpleFree() itself, but spends most
 * of the time taking the 16-bit fields of the 8-byte cells apart and together
 * again; here each field is moved once. Results are bit for bit
 * those of fuseSimpleFree() (same float operations in the same order), which
 * stays the code for the tail of a run and for targets without SSE2. */

#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include "grid/FreeRunKernelAvx2.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mrpt_evidential
{
#if defined(__SSE2__)
namespace
{
/** The fields of four cells, one 32-bit lane per cell, in cell order. */
struct TLanes
{
	__m128i aside, free, occupied, stamp;
};

TLanes loadFour(const QuantizedCell* c)
{
	// Two cells per register; as 32-bit lanes (aside | free << 16,
	// occupied | stamp << 16) for each cell.
	const __m128i low16 = _mm_set1_epi32(0xFFFF);
	const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c));
	const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + 2));
	const __m128 highA = _mm_castsi128_ps(_mm_srli_epi32(a, 16)),
				 highB = _mm_castsi128_ps(_mm_srli_epi32(b, 16)),
				 lowA = _mm_castsi128_ps(_mm_and_si128(a, low16)),
				 lowB = _mm_castsi128_ps(_mm_and_si128(b, low16));
	return {
		_mm_castps_si128(_mm_shuffle_ps(lowA, lowB, _MM_SHUFFLE(2, 0, 2, 0))),
		_mm_castps_si128(_mm_shuffle_ps(highA, highB, _MM_SHUFFLE(2, 0, 2, 0))),
		_mm_castps_si128(_mm_shuffle_ps(lowA, lowB, _MM_SHUFFLE(3, 1, 3, 1))),
		_mm_castps_si128(_mm_shuffle_ps(highA, highB, _MM_SHUFFLE(3, 1, 3, 1)))};
}

void storeFour(QuantizedCell* c, const TLanes& v)
{
	const __m128i lowWords = _mm_or_si128(v.aside, _mm_slli_epi32(v.free, 16));
	const __m128i highWords = _mm_or_si128(v.occupied, _mm_slli_epi32(v.stamp, 16));
	_mm_storeu_si128(reinterpret_cast<__m128i*>(c), _mm_unpacklo_epi32(lowWords, highWords));
	_mm_storeu_si128(reinterpret_cast<__m128i*>(c + 2), _mm_unpackhi_epi32(lowWords, highWords));
}
/** The simple free mass w fused into normal parts (f, o) in stored units
 * with `Rule`, and the conflict of that fusion (Dempster's rule), as
 * fuseSimpleFree() does. */
struct TFused
{
	__m128 free, occupied, newConflict;
};
template <FreeFusion Rule = FreeFusion::Dempster>
TFused fuseFree(__m128 f, __m128 o, __m128 w)
{
	const __m128 scale = _mm_set1_ps(static_cast<float>(kMassScale)), one = _mm_set1_ps(1.0f);
	const __m128 u = _mm_sub_ps(_mm_sub_ps(scale, f), o);
	if constexpr (isCautious(Rule))
	{
		// EvidentialGridStorage::cautiousFree(): both of its cases, selected.
		const __m128 tiny = _mm_set1_ps(1e-30f), notW = _mm_sub_ps(one, w);
		const __m128 cellsWeight = _mm_cmple_ps(u, _mm_mul_ps(notW, _mm_add_ps(f, u)));
		const auto select = [&cellsWeight](__m128 ifCells, __m128 otherwise) {
			return _mm_or_ps(
				_mm_and_ps(cellsWeight, ifCells), _mm_andnot_ps(cellsWeight, otherwise));
		};
		const __m128 wu = _mm_mul_ps(w, u), notWo = _mm_mul_ps(notW, o);
		if constexpr (Rule == FreeFusion::CautiousNormalized)
		{
			const __m128 s = _mm_div_ps(scale, _mm_max_ps(_mm_add_ps(u, notWo), tiny));
			return {select(f, _mm_mul_ps(wu, s)), select(o, _mm_mul_ps(notWo, s)),
					_mm_setzero_ps()};
		}
		const __m128 s = _mm_div_ps(
			select(_mm_mul_ps(scale, u), scale),
			select(
				_mm_max_ps(_mm_mul_ps(_mm_add_ps(f, u), _mm_add_ps(o, u)), tiny),
				_mm_max_ps(_mm_add_ps(o, u), tiny)));
		return {select(_mm_mul_ps(f, s), _mm_mul_ps(wu, s)),
				select(_mm_mul_ps(o, s), _mm_mul_ps(notWo, s)), _mm_setzero_ps()};
	}
	const __m128 lost = _mm_mul_ps(o, w), newConflict = _mm_div_ps(lost, scale);
	// At total conflict both products are 0 and n becomes vacuous.
	const __m128 normalize = Rule == FreeFusion::Dempster
		? _mm_div_ps(scale, _mm_max_ps(_mm_sub_ps(scale, lost), _mm_set1_ps(1e-30f)))
		: one;
	return {
		_mm_mul_ps(_mm_add_ps(f, _mm_mul_ps(u, w)), normalize),
		_mm_mul_ps(_mm_sub_ps(o, lost), normalize), newConflict};
}

/** encodeScaledNormal() on four cells: n(F) and n(O) rounded, each at most
 * `ceiling`, together at most the scale. The clamps are taken before the
 * truncation: for whole bounds min(trunc(x), n) is trunc(min(x, n)). */
void encodeFour(const TFused& fused, __m128 ceiling, __m128i& free, __m128i& occupied)
{
	const __m128 half = _mm_set1_ps(0.5f), scale = _mm_set1_ps(static_cast<float>(kMassScale));
	occupied = _mm_cvttps_epi32(_mm_min_ps(_mm_add_ps(fused.occupied, half), ceiling));
	const __m128 room = _mm_sub_ps(scale, _mm_cvtepi32_ps(occupied));
	free = _mm_cvttps_epi32(_mm_min_ps(_mm_min_ps(_mm_add_ps(fused.free, half), room), ceiling));
}
/** The decay factors of four cells' stamps (`stamps`, one lane each), in
 * single precision: one factor when the four were last written by the same
 * scan, as most blocks of a free run were. */
template <typename Factor>
__m128 fourFactors(const QuantizedCell* c, __m128i stamps, Factor&& factor)
{
	const __m128i times = _mm_and_si128(stamps, _mm_set1_epi32(kStampMask));
	if (_mm_movemask_epi8(_mm_cmpeq_epi32(times, _mm_shuffle_epi32(times, 0))) == 0xFFFF)
		return _mm_set1_ps(static_cast<float>(factor(c[0].stamp)));
	return _mm_set_ps(
		static_cast<float>(factor(c[3].stamp)), static_cast<float>(factor(c[2].stamp)),
		static_cast<float>(factor(c[1].stamp)), static_cast<float>(factor(c[0].stamp)));
}
}  // namespace
#endif

template <bool Decays, FreeFusion Rule>
void EvidentialGridStorage::fuseQuietFreeRun(
	std::size_t first, std::size_t count, float w, std::uint16_t occupiedBelow,
	std::vector<std::size_t>& loud)
{
	const std::size_t end = first + count;
	std::size_t idx = first;
#if defined(__SSE2__)
	const __m128 mass = _mm_set1_ps(w), ceiling = _mm_set1_ps(static_cast<float>(m_ceiling));
	const __m128i flags = _mm_set1_epi32(kStampFlags),
				  stamp = _mm_set1_epi32(m_currentStamp),
				  judged = _mm_set1_epi32(kEventJudgedWhenSeenFree),
				  occupiedLimit = _mm_set1_epi32(static_cast<int>(occupiedBelow) - 1),
				  ceilingWord = _mm_set1_epi32(m_ceiling), zero = _mm_setzero_si128(),
				  noIgnorance = _mm_set1_epi32(static_cast<int>(kMassScale) - 1);
#if defined(MRPT_EVIDENTIAL_HAS_AVX2_KERNELS)
	// Eight cells at a time where the processor has AVX2; this loop takes
	// the blocks of four that hold a loud cell, and the rest.
	const detail::TFreeRun run{
		w, m_ceiling, m_currentStamp, occupiedBelow, m_presentGain, m_stampGain.data()};
#endif
	for (; idx + 4 <= end; idx += 4)
	{
#if defined(MRPT_EVIDENTIAL_HAS_AVX2_KERNELS)
		// Only while a block of eight is left: a call that had none to
		// fuse cost most runs' tails some forty instructions for nothing.
		if (detail::kAvx2Available && idx + 8 <= end)
		{
			idx = detail::fuseQuietBlocksOfEight<Decays, Rule>(
				m_cells.data(), idx, end, run);
			if (idx + 4 > end) break;
		}
#endif
		QuantizedCell* c = &m_cells[idx];
		const TLanes in = loadFour(c);
		// isLoudFor() on four cells.
		__m128i loudLanes = _mm_or_si128(
			_mm_cmpgt_epi32(in.occupied, occupiedLimit),
			_mm_cmpeq_epi32(_mm_and_si128(in.aside, judged), judged));
		if constexpr (isCautious(Rule))
			loudLanes = _mm_or_si128(
				loudLanes, _mm_cmpgt_epi32(_mm_add_epi32(in.free, in.occupied), noIgnorance));
		if (_mm_movemask_epi8(loudLanes) != 0)
		{
			for (std::size_t k = idx; k < idx + 4; ++k)
				if (isLoudFor<Rule>(k, occupiedBelow))
					loud.push_back(k);
				else
					fuseSimpleFree<Decays, false, Rule>(k, w);
			continue;
		}
		// Free at the ceiling, nothing occupied: the fusion gives the cell
		// back as it was, and without decay its stamp means nothing (a
		// change of rate first rebases every stamp). Such cells are left as
		// they are, stamp included, as fuseSimpleFree() leaves them.
		__m128i saturated = zero;
		if constexpr (!Decays)
		{
			saturated = _mm_and_si128(
				_mm_cmpeq_epi32(in.free, ceilingWord), _mm_cmpeq_epi32(in.occupied, zero));
			if (_mm_movemask_epi8(saturated) == 0xFFFF) continue;
		}
		__m128 f = _mm_cvtepi32_ps(in.free), o = _mm_cvtepi32_ps(in.occupied);
		if constexpr (Decays)
		{
			const __m128 d = fourFactors(c, in.stamp, [this](std::uint16_t t) { return decayFactor(t); });
			f = _mm_mul_ps(f, d);
			o = _mm_mul_ps(o, d);
		}
		__m128i freeOut, occupiedOut;
		encodeFour(fuseFree<Rule>(f, o, mass), ceiling, freeOut, occupiedOut);
		const __m128i restamped = _mm_or_si128(_mm_and_si128(in.stamp, flags), stamp);
		storeFour(c, {in.aside, freeOut, occupiedOut,
					  _mm_or_si128(_mm_and_si128(saturated, in.stamp),
								   _mm_andnot_si128(saturated, restamped))});
	}
#endif
	for (; idx < end; ++idx)
		if (isLoudFor<Rule>(idx, occupiedBelow))
			loud.push_back(idx);
		else
			fuseSimpleFree<Decays, false, Rule>(idx, w);
}

template <bool Decays>
void EvidentialGridStorage::fuseFreeRunKeepingConflict(
	std::size_t first, std::size_t count, float w)
{
	const std::size_t end = first + count;
	std::size_t idx = first;
#if defined(__SSE2__)
	const __m128 scale = _mm_set1_ps(static_cast<float>(kMassScale)), mass = _mm_set1_ps(w),
				 one = _mm_set1_ps(1.0f), half = _mm_set1_ps(0.5f),
				 maxConflict = _mm_set1_ps(static_cast<float>(kMaxStoredConflict));
	const __m128i flags = _mm_set1_epi32(kStampFlags), stamp = _mm_set1_epi32(m_currentStamp);
#if defined(MRPT_EVIDENTIAL_HAS_AVX2_KERNELS)
	// Eight cells at a time where the processor has AVX2, the rest here.
	if (detail::kAvx2Available)
		idx = detail::fuseBlocksOfEightKeepingConflict<Decays>(
			m_cells.data(), idx, end,
			{w, m_ceiling, m_currentStamp, 0, m_presentGain, m_stampGain.data()});
#endif
	for (; idx + 4 <= end; idx += 4)
	{
		QuantizedCell* c = &m_cells[idx];
		const TLanes in = loadFour(c);
		__m128 f = _mm_cvtepi32_ps(in.free), o = _mm_cvtepi32_ps(in.occupied);
		// 1 - K, K the conflict the cell keeps.
		__m128 keep = _mm_sub_ps(one, _mm_div_ps(_mm_cvtepi32_ps(in.aside), scale));
		if constexpr (Decays)
		{
			const __m128 d = fourFactors(c, in.stamp, [this](std::uint16_t t) { return decayFactor(t); });
			const __m128 decayedKeep = _mm_sub_ps(one, _mm_mul_ps(d, _mm_sub_ps(one, keep)));
			const __m128 s = _mm_div_ps(_mm_mul_ps(d, keep), decayedKeep);
			f = _mm_mul_ps(f, s);
			o = _mm_mul_ps(o, s);
			keep = decayedKeep;
		}
		const TFused fused = fuseFree(f, o, mass);
		// encodeScaled(): K rounded and capped, then the normal part.
		const __m128 conflict = _mm_mul_ps(
			scale, _mm_sub_ps(one, _mm_mul_ps(keep, _mm_sub_ps(one, fused.newConflict))));
		const __m128i conflictOut =
			_mm_cvttps_epi32(_mm_min_ps(_mm_add_ps(conflict, half), maxConflict));
		__m128i freeOut, occupiedOut;
		encodeFour(fused, scale, freeOut, occupiedOut);
		storeFour(c, {conflictOut, freeOut, occupiedOut,
					  _mm_or_si128(_mm_and_si128(in.stamp, flags), stamp)});
	}
#endif
	for (; idx < end; ++idx) fuseSimpleFree<Decays, true>(idx, w);
}

template void EvidentialGridStorage::fuseFreeRunKeepingConflict<true>(
	std::size_t, std::size_t, float);
template void EvidentialGridStorage::fuseFreeRunKeepingConflict<false>(
	std::size_t, std::size_t, float);
#define MRPT_EVIDENTIAL_QUIET_RUN(Decays, Rule)                                  \
	template void EvidentialGridStorage::fuseQuietFreeRun<Decays, FreeFusion::Rule>( \
		std::size_t, std::size_t, float, std::uint16_t, std::vector<std::size_t>&);
MRPT_EVIDENTIAL_QUIET_RUN(true, Dempster)
MRPT_EVIDENTIAL_QUIET_RUN(false, Dempster)
MRPT_EVIDENTIAL_QUIET_RUN(true, Yager)
MRPT_EVIDENTIAL_QUIET_RUN(false, Yager)
MRPT_EVIDENTIAL_QUIET_RUN(true, CautiousNormalized)
MRPT_EVIDENTIAL_QUIET_RUN(false, CautiousNormalized)
MRPT_EVIDENTIAL_QUIET_RUN(true, CautiousToUnknown)
MRPT_EVIDENTIAL_QUIET_RUN(false, CautiousToUnknown)
#undef MRPT_EVIDENTIAL_QUIET_RUN

}  // namespace mrpt_evidential
