/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The 8-byte cell of the evidential grid: a normal mass in 16-bit fixed
 * point, a time stamp, and a word kept aside (the conflict, or the cell's
 * latest motion event). Header-only, standard library only. */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>

#include <algorithm>
#include <cstdint>

namespace mrpt_evidential
{
/** One grid cell: a normal mass, and a word aside.
 *
 * A mass m is stored as K = m(empty) and the normal mass n = m / (1 - K) on
 * {F}, {O} and Omega, so that m = (1 - K) n + K m_empty. `free` and
 * `occupied` hold n(F) and n(O) in multiples of 1/kMassScale; n(Omega) is
 * what remains. The 14 low bits of `stamp` index the grid's table of
 * insertion times: the cell was last fused (or decayed) at that time; bit 14
 * (kHeldImpact) says that the cell has held a beam's impact, bit 15
 * (kFlipped) that the motion layer saw it flip: a pending arrival beside
 * static structure turned down (CMotionDetector).
 *
 * `aside` depends on what the grid keeps (EvidentialGridStorage::keepsConflict):
 * - K itself, for a grid that keeps conflict (ConflictHandling::Keep). The
 *   conjunctive rule drives K towards 1 at walls that rays also cross; the
 *   ratio of free to occupied evidence that BetP, the occupancy conversion
 *   and the likelihood read is then in n, whole, however close to 1 K gets.
 *   K is stored at most kMaxStoredConflict, so that 1 - K never rounds to 0.
 * - Otherwise the cell's latest motion event (CellEvent, packEvent()): the
 *   conflict of each fusion leaves the cell (K = 0) and only its verdict,
 *   something appeared or left, is kept, with the stamp of its time. */
struct QuantizedCell
{
	std::uint16_t aside = 0;
	std::uint16_t free = 0;
	std::uint16_t occupied = 0;
	std::uint16_t stamp = 0;

	bool operator==(const QuantizedCell& o) const
	{
		return aside == o.aside && free == o.free && occupied == o.occupied &&
			stamp == o.stamp;
	}
};
static_assert(sizeof(QuantizedCell) == 8, "a cell must stay 8 bytes");

/** Fixed-point scale: a stored value q means q / kMassScale. */
constexpr double kMassScale = 65535.0;
/** Largest difference between a value and its stored one (half a step). */
constexpr double kQuantizationError = 0.5 / kMassScale;
/** Largest stored conflict, in steps: one step below total conflict. */
constexpr std::uint16_t kMaxStoredConflict = 65534;

/** What a cell of a grid without conflict remembers of its latest motion
 * event. `Leaving` is a change seen once and not yet confirmed (the motion
 * layer reads it as none), whose stamp is that of the scan that first saw
 * it: a cell seen free while its evidence still says occupied, or, while it
 * leans free, a cell seen occupied beside static structure. */
enum class CellEvent : std::uint8_t
{
	None = 0,
	Appeared = 1,
	Disappeared = 2,
	Leaving = 3
};
/** The stamp's bits (QuantizedCell::stamp). */
constexpr std::uint16_t kStampMask = 0x3FFF;
constexpr std::uint16_t kHeldImpact = 0x4000;
constexpr std::uint16_t kFlipped = 0x8000;
/** The bits of the stamp that stay when a cell is stamped again. */
constexpr std::uint16_t kStampFlags = kHeldImpact | kFlipped;

/** Events keep their stamp in the 14 low bits of `aside`. */
constexpr unsigned kEventStampBits = 14;
constexpr std::uint16_t kEventStampMask = (1u << kEventStampBits) - 1;

/** The bit of `aside` that Appeared and Leaving set (their kinds are odd):
 * the events a free sight of the cell judges again. */
constexpr std::uint16_t kEventJudgedWhenSeenFree = 1u << kEventStampBits;

inline std::uint16_t packEvent(CellEvent e, std::uint16_t stamp) noexcept
{
	return static_cast<std::uint16_t>(
		(static_cast<unsigned>(e) << kEventStampBits) | (stamp & kEventStampMask));
}
inline CellEvent eventOf(const QuantizedCell& c) noexcept
{
	return static_cast<CellEvent>(c.aside >> kEventStampBits);
}
inline std::uint16_t eventStampOf(const QuantizedCell& c) noexcept
{
	return static_cast<std::uint16_t>(c.aside & kEventStampMask);
}

/** Nearest fixed-point value of v, with v clamped to [0, 1] (NaN gives 0). */
inline std::uint16_t quantizeMass(double v) noexcept
{
	if (!(v > 0.0)) return 0;
	if (v >= 1.0) return static_cast<std::uint16_t>(kMassScale);
	return static_cast<std::uint16_t>(v * kMassScale + 0.5);
}

/** Stores the normal part of m into c (its aside word and stamp are left
 * alone): n(F) and n(O) rounded to nearest, the larger giving way if together
 * they pass the scale. A mass of total conflict has no normal part: n is
 * vacuous. */
inline void encodeNormal(const Mass& m, QuantizedCell& c) noexcept
{
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

/** Stores m into a cell that keeps conflict (its stamp is left alone): K
 * rounded to nearest and capped at kMaxStoredConflict, and encodeNormal(). */
inline void encodeMass(const Mass& m, QuantizedCell& c) noexcept
{
	c.aside = std::min(quantizeMass(m.conflict), kMaxStoredConflict);
	encodeNormal(m, c);
}

/** Stores a fused normal part given in stored units (times kMassScale),
 * n(F) and n(O) rounded to nearest without branches, so that loops of it
 * vectorize, each at most `ceiling`. The values are fused ones, each within
 * [0, kMassScale] and n(F) + n(O) at most kMassScale, up to rounding errors
 * far below half a step; the clamps absorb those errors. The aside word and
 * the stamp are left alone. */
template <typename Real>
inline void encodeScaledNormal(
	QuantizedCell& c, Real free, Real occupied,
	int ceiling = static_cast<int>(kMassScale)) noexcept
{
	constexpr int kScale = static_cast<int>(kMassScale);
	const int o = std::min(static_cast<int>(occupied + Real(0.5)), ceiling);
	const int f = std::min(
		std::min(static_cast<int>(free + Real(0.5)), kScale - o), ceiling);
	c.free = static_cast<std::uint16_t>(f);
	c.occupied = static_cast<std::uint16_t>(o);
}

/** encodeScaledNormal() for a cell that keeps conflict, with its conflict K
 * in stored units too. */
template <typename Real>
inline void encodeScaled(QuantizedCell& c, Real conflict, Real free, Real occupied) noexcept
{
	c.aside = static_cast<std::uint16_t>(
		std::min(static_cast<int>(conflict + Real(0.5)), int(kMaxStoredConflict)));
	encodeScaledNormal(c, free, occupied);
}

/** The normal part n of a cell (n(empty) = 0). Always valid. */
inline Mass decodeNormal(const QuantizedCell& c) noexcept
{
	const double scale = 1.0 / kMassScale;
	const int remaining = static_cast<int>(kMassScale) - c.free - c.occupied;
	return {0.0, c.free * scale, c.occupied * scale, std::max(remaining, 0) * scale};
}

/** The mass a cell that keeps conflict holds (not decayed):
 * (1 - K) n + K m_empty. Always valid. */
inline Mass decodeMass(const QuantizedCell& c) noexcept
{
	const double k = c.aside / kMassScale, keep = 1.0 - k;
	const Mass n = decodeNormal(c);
	return {k, keep * n.free, keep * n.occupied, keep * n.unknown};
}

/** True when the stored values are within their ranges (a cell read from a
 * file must satisfy this); `keepsConflict` says what `aside` holds. Event
 * stamps are checked by the grid, which knows its table. */
inline bool isConsistent(const QuantizedCell& c, bool keepsConflict) noexcept
{
	return (!keepsConflict || c.aside <= kMaxStoredConflict) &&
		static_cast<std::uint32_t>(c.free) + c.occupied <=
		static_cast<std::uint32_t>(kMassScale);
}

/** A cell of serialization version 0, which stored m(empty), m(F) and m(O)
 * themselves, in the form of a cell that keeps conflict. The three must sum
 * to at most kMassScale. */
inline QuantizedCell fromVersion0(const QuantizedCell& old) noexcept
{
	const double scale = 1.0 / kMassScale;
	const int remaining = static_cast<int>(kMassScale) - old.aside - old.free -
		old.occupied;
	QuantizedCell c;
	encodeMass(
		{old.aside * scale, old.free * scale, old.occupied * scale,
		 std::max(remaining, 0) * scale},
		c);
	c.stamp = old.stamp;
	return c;
}

}  // namespace mrpt_evidential
