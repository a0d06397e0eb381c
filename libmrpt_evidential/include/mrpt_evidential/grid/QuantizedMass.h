/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The 8-byte cell of the evidential grid: the conflict and a normal mass in
 * 16-bit fixed point, and a time stamp. Header-only, standard library only. */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>

#include <algorithm>
#include <cstdint>

namespace mrpt_evidential
{
/** One grid cell: the conflict apart, and the rest as a normal mass.
 *
 * A mass m is stored as K = m(empty) and the normal mass n = m / (1 - K) on
 * {F}, {O} and Omega, so that m = (1 - K) n + K m_empty. The conjunctive rule
 * keeps conflict and drives K towards 1 at walls that rays also cross; the
 * ratio of free to occupied evidence that BetP, the occupancy conversion and
 * the likelihood read is then in n, whole, however close to 1 K gets.
 * `conflict` holds K, `free` and `occupied` n(F) and n(O), in multiples of
 * 1/kMassScale; n(Omega) is what remains. K is stored at most
 * kMaxStoredConflict, so that 1 - K never rounds to 0 and the masses a cell
 * decodes to keep n's ratios. `stamp` indexes the grid's table of insertion
 * times: the cell was last fused (or decayed) at that time. */
struct QuantizedCell
{
	std::uint16_t conflict = 0;
	std::uint16_t free = 0;
	std::uint16_t occupied = 0;
	std::uint16_t stamp = 0;

	bool operator==(const QuantizedCell& o) const
	{
		return conflict == o.conflict && free == o.free &&
			occupied == o.occupied && stamp == o.stamp;
	}
};
static_assert(sizeof(QuantizedCell) == 8, "a cell must stay 8 bytes");

/** Fixed-point scale: a stored value q means q / kMassScale. */
constexpr double kMassScale = 65535.0;
/** Largest difference between a value and its stored one (half a step). */
constexpr double kQuantizationError = 0.5 / kMassScale;
/** Largest stored conflict, in steps: one step below total conflict. */
constexpr std::uint16_t kMaxStoredConflict = 65534;

/** Nearest fixed-point value of v, with v clamped to [0, 1] (NaN gives 0). */
inline std::uint16_t quantizeMass(double v) noexcept
{
	if (!(v > 0.0)) return 0;
	if (v >= 1.0) return static_cast<std::uint16_t>(kMassScale);
	return static_cast<std::uint16_t>(v * kMassScale + 0.5);
}

/** Stores m into c (its stamp is left alone): K rounded to nearest and
 * capped at kMaxStoredConflict, n(F) and n(O) rounded to nearest, the larger
 * giving way if together they pass the scale. A mass of total conflict
 * keeps no normal part: n is vacuous. */
inline void encodeMass(const Mass& m, QuantizedCell& c) noexcept
{
	c.conflict = std::min(quantizeMass(m.conflict), kMaxStoredConflict);
	const double rest = m.free + m.occupied + m.unknown;
	std::uint32_t f = 0, o = 0;
	if (rest > 0.0)
	{
		const double toNormal = 1.0 / rest;
		f = quantizeMass(m.free * toNormal);
		o = quantizeMass(m.occupied * toNormal);
		const std::uint32_t limit = static_cast<std::uint32_t>(kMassScale);
		if (f + o > limit) (f >= o ? f : o) -= f + o - limit;
	}
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** Stores a fused cell given in stored units (times kMassScale): the
 * conflict K and the normal part's n(F) and n(O), rounded to nearest without
 * branches, so that loops of it vectorize. The values are fused ones, each
 * within [0, kMassScale] and n(F) + n(O) at most kMassScale, up to rounding
 * errors far below half a step; the clamps absorb those errors. The stamp is
 * left alone. */
template <typename Real>
inline void encodeScaled(QuantizedCell& c, Real conflict, Real free, Real occupied) noexcept
{
	constexpr int kScale = static_cast<int>(kMassScale);
	const int e = std::min(static_cast<int>(conflict + Real(0.5)), int(kMaxStoredConflict));
	const int o = std::min(static_cast<int>(occupied + Real(0.5)), kScale);
	const int f = std::min(static_cast<int>(free + Real(0.5)), kScale - o);
	c.conflict = static_cast<std::uint16_t>(e);
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** The normal part n of a cell (n(empty) = 0). Always valid. */
inline Mass decodeNormal(const QuantizedCell& c) noexcept
{
	const double scale = 1.0 / kMassScale;
	const int remaining = static_cast<int>(kMassScale) - c.free - c.occupied;
	return {0.0, c.free * scale, c.occupied * scale, std::max(remaining, 0) * scale};
}

/** The mass a cell holds (not decayed): (1 - K) n + K m_empty. Always
 * valid. */
inline Mass decodeMass(const QuantizedCell& c) noexcept
{
	const double k = c.conflict / kMassScale, keep = 1.0 - k;
	const Mass n = decodeNormal(c);
	return {k, keep * n.free, keep * n.occupied, keep * n.unknown};
}

/** True when the stored values are within their ranges (a cell read from a
 * file must satisfy this). */
inline bool isConsistent(const QuantizedCell& c) noexcept
{
	return c.conflict <= kMaxStoredConflict &&
		static_cast<std::uint32_t>(c.free) + c.occupied <=
		static_cast<std::uint32_t>(kMassScale);
}

/** A cell of serialization version 0, which stored m(empty), m(F) and m(O)
 * themselves, in today's form. The three must sum to at most kMassScale. */
inline QuantizedCell fromVersion0(const QuantizedCell& old) noexcept
{
	const double scale = 1.0 / kMassScale;
	const int remaining = static_cast<int>(kMassScale) - old.conflict - old.free -
		old.occupied;
	QuantizedCell c;
	encodeMass(
		{old.conflict * scale, old.free * scale, old.occupied * scale,
		 std::max(remaining, 0) * scale},
		c);
	c.stamp = old.stamp;
	return c;
}

}  // namespace mrpt_evidential
