/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The 8-byte cell of the evidential grid: three masses in 16-bit fixed point
 * and a time stamp. Header-only, standard library only. */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>

#include <algorithm>
#include <cstdint>

namespace mrpt_evidential
{
/** One grid cell. m(empty), m(F) and m(O) are stored as multiples of
 * 1/kMassScale; m(Omega) is what remains, so a stored mass always sums to
 * exactly 1 and is never negative. `stamp` indexes the grid's table of
 * insertion times: the cell was last fused (or decayed) at that time. */
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
/** Largest difference between a mass and its stored value (half a step). */
constexpr double kQuantizationError = 0.5 / kMassScale;

/** Nearest fixed-point value of v, with v clamped to [0, 1] (NaN gives 0). */
inline std::uint16_t quantizeMass(double v) noexcept
{
	if (!(v > 0.0)) return 0;
	if (v >= 1.0) return static_cast<std::uint16_t>(kMassScale);
	return static_cast<std::uint16_t>(v * kMassScale + 0.5);
}

/** Stores m's masses into c (its stamp is left alone). The three stored
 * values are rounded to nearest; if rounding makes them exceed the scale
 * together, the largest gives way so that m(Omega) stays >= 0. */
inline void encodeMass(const Mass& m, QuantizedCell& c) noexcept
{
	std::uint32_t e = quantizeMass(m.conflict), f = quantizeMass(m.free),
				  o = quantizeMass(m.occupied);
	const std::uint32_t limit = static_cast<std::uint32_t>(kMassScale);
	if (e + f + o > limit)
	{
		std::uint32_t& largest = f >= o ? (f >= e ? f : e) : (o >= e ? o : e);
		largest -= std::min(largest, e + f + o - limit);
	}
	c.conflict = static_cast<std::uint16_t>(e);
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** Stores conflict, free and occupied masses given in stored units (times
 * kMassScale), rounded to nearest without branches, so that loops of it
 * vectorize. The values are fused masses: each within [0, kMassScale] and
 * the three summing to at most kMassScale, up to rounding errors far below
 * half a step; the clamps absorb those errors, so the stored values never
 * exceed the scale together. The stamp is left alone. */
template <typename Real>
inline void encodeScaled(QuantizedCell& c, Real conflict, Real free, Real occupied) noexcept
{
	constexpr int kScale = static_cast<int>(kMassScale);
	const int e = static_cast<int>(conflict + Real(0.5));
	const int o = std::min(static_cast<int>(occupied + Real(0.5)), kScale - e);
	const int f = std::min(static_cast<int>(free + Real(0.5)), kScale - e - o);
	c.conflict = static_cast<std::uint16_t>(e);
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** The mass a cell holds (not decayed). Always valid. */
inline Mass decodeMass(const QuantizedCell& c) noexcept
{
	const double scale = 1.0 / kMassScale;
	const int remaining = static_cast<int>(kMassScale) - c.conflict - c.free -
		c.occupied;
	return {
		c.conflict * scale, c.free * scale, c.occupied * scale,
		std::max(remaining, 0) * scale};
}

/** True when the stored masses do not exceed the scale together (a cell read
 * from a file must satisfy this). */
inline bool isConsistent(const QuantizedCell& c) noexcept
{
	return static_cast<std::uint32_t>(c.conflict) + c.free + c.occupied <=
		static_cast<std::uint32_t>(kMassScale);
}

}  // namespace mrpt_evidential
