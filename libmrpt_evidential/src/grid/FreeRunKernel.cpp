/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * EvidentialGridStorage::fuseQuietFreeRun(): the bulk of a scan's cells in a
 * grid without conflict, four cells at a time with SSE2 where the target has
 * it. The compiler vectorizes fuseSimpleFree() itself, but spends most of the
 * time taking the 16-bit fields of the 8-byte cells apart and together
 * again; here each field is moved once. Results are bit for bit those of
 * fuseSimpleFree<Decays, false>() (same float operations in the same order),
 * which stays the code for the tail of a run and for targets without SSE2. */

#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mrpt_evidential
{
template <bool Decays>
void EvidentialGridStorage::fuseQuietFreeRun(
	std::size_t first, std::size_t count, float w, std::uint16_t occupiedBelow,
	std::vector<std::size_t>& loud)
{
	const std::size_t end = first + count;
	std::size_t idx = first;
#if defined(__SSE2__)
	const __m128 scale = _mm_set1_ps(static_cast<float>(kMassScale)), mass = _mm_set1_ps(w),
				 one = _mm_set1_ps(1.0f), tiny = _mm_set1_ps(1e-30f),
				 half = _mm_set1_ps(0.5f), ceiling = _mm_set1_ps(static_cast<float>(m_ceiling));
	const __m128i low16 = _mm_set1_epi32(0xFFFF), heldImpact = _mm_set1_epi32(kHeldImpact),
				  stamp = _mm_set1_epi32(m_currentStamp),
				  judged = _mm_set1_epi32(kEventJudgedWhenSeenFree),
				  occupiedLimit = _mm_set1_epi32(static_cast<int>(occupiedBelow) - 1);
	for (; idx + 4 <= end; idx += 4)
	{
		QuantizedCell* c = &m_cells[idx];
		// Two cells per register; as 32-bit lanes (aside | free << 16,
		// occupied | stamp << 16) for each cell.
		const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c));
		const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + 2));
		const __m128 highA = _mm_castsi128_ps(_mm_srli_epi32(a, 16)),
					 highB = _mm_castsi128_ps(_mm_srli_epi32(b, 16)),
					 lowA = _mm_castsi128_ps(_mm_and_si128(a, low16)),
					 lowB = _mm_castsi128_ps(_mm_and_si128(b, low16));
		// One field of the four cells per register, in cell order.
		const __m128i asideI = _mm_castps_si128(_mm_shuffle_ps(lowA, lowB, _MM_SHUFFLE(2, 0, 2, 0)));
		const __m128i freeI = _mm_castps_si128(_mm_shuffle_ps(highA, highB, _MM_SHUFFLE(2, 0, 2, 0)));
		const __m128i occupiedI = _mm_castps_si128(_mm_shuffle_ps(lowA, lowB, _MM_SHUFFLE(3, 1, 3, 1)));
		const __m128i stampI = _mm_castps_si128(_mm_shuffle_ps(highA, highB, _MM_SHUFFLE(3, 1, 3, 1)));
		// isLoud() on four cells.
		const __m128i loudLanes = _mm_or_si128(
			_mm_cmpgt_epi32(occupiedI, occupiedLimit),
			_mm_cmpeq_epi32(_mm_and_si128(asideI, judged), judged));
		if (_mm_movemask_epi8(loudLanes) != 0)
		{
			for (std::size_t k = idx; k < idx + 4; ++k)
				if (isLoud(k, occupiedBelow))
					loud.push_back(k);
				else
					fuseSimpleFree<Decays, false>(k, w);
			continue;
		}
		__m128 f = _mm_cvtepi32_ps(freeI), o = _mm_cvtepi32_ps(occupiedI);
		if constexpr (Decays)
		{
			const __m128 d = _mm_set_ps(
				static_cast<float>(decayFactor(c[3].stamp)),
				static_cast<float>(decayFactor(c[2].stamp)),
				static_cast<float>(decayFactor(c[1].stamp)),
				static_cast<float>(decayFactor(c[0].stamp)));
			f = _mm_mul_ps(f, d);
			o = _mm_mul_ps(o, d);
		}
		const __m128 u = _mm_sub_ps(_mm_sub_ps(scale, f), o);
		const __m128 newConflict = _mm_div_ps(_mm_mul_ps(o, mass), scale);
		const __m128 normalize =
			_mm_div_ps(one, _mm_max_ps(_mm_sub_ps(one, newConflict), tiny));
		const __m128 fusedFree = _mm_mul_ps(_mm_add_ps(f, _mm_mul_ps(u, mass)), normalize);
		const __m128 fusedOccupied = _mm_mul_ps(_mm_sub_ps(o, _mm_mul_ps(o, mass)), normalize);
		// encodeScaledNormal()'s clamps, taken before the truncation: for
		// whole bounds min(trunc(x), n) is trunc(min(x, n)).
		const __m128i occupiedOut =
			_mm_cvttps_epi32(_mm_min_ps(_mm_add_ps(fusedOccupied, half), ceiling));
		const __m128 room = _mm_sub_ps(scale, _mm_cvtepi32_ps(occupiedOut));
		const __m128i freeOut = _mm_cvttps_epi32(
			_mm_min_ps(_mm_min_ps(_mm_add_ps(fusedFree, half), room), ceiling));
		const __m128i stampOut = _mm_or_si128(_mm_and_si128(stampI, heldImpact), stamp);
		const __m128i lowWords = _mm_or_si128(asideI, _mm_slli_epi32(freeOut, 16));
		const __m128i highWords = _mm_or_si128(occupiedOut, _mm_slli_epi32(stampOut, 16));
		_mm_storeu_si128(reinterpret_cast<__m128i*>(c), _mm_unpacklo_epi32(lowWords, highWords));
		_mm_storeu_si128(reinterpret_cast<__m128i*>(c + 2), _mm_unpackhi_epi32(lowWords, highWords));
	}
#endif
	for (; idx < end; ++idx)
		if (isLoud(idx, occupiedBelow))
			loud.push_back(idx);
		else
			fuseSimpleFree<Decays, false>(idx, w);
}

template void EvidentialGridStorage::fuseQuietFreeRun<true>(
	std::size_t, std::size_t, float, std::uint16_t, std::vector<std::size_t>&);
template void EvidentialGridStorage::fuseQuietFreeRun<false>(
	std::size_t, std::size_t, float, std::uint16_t, std::vector<std::size_t>&);

}  // namespace mrpt_evidential
