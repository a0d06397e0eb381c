/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Mass functions on the frame of discernment Omega = {F, O}. Header-only,
 * standard library only: this file must never include MRPT. */
#pragma once

#include <cmath>
#include <initializer_list>

namespace mrpt_evidential
{
/** A basic belief assignment (mass function) on Omega = {F, O}: one mass for
 * each of the four subsets. The masses of a valid mass function are in [0, 1]
 * and sum to 1 (see isValid()).
 *
 * The default-constructed mass is the vacuous one (total ignorance), which is
 * what a cell of a map holds before any sensor has seen it. */
struct Mass
{
	double conflict = 0.0;  //!< m(empty set): sources disagree
	double free = 0.0;  //!< m({F})
	double occupied = 0.0;  //!< m({O})
	double unknown = 1.0;  //!< m(Omega): ignorance

	/** The neutral element of the conjunctive rule: m(Omega) = 1. */
	static constexpr Mass vacuous() noexcept { return {0.0, 0.0, 0.0, 1.0}; }

	/** Total conflict, m(empty) = 1: the neutral element of the disjunctive
	 * rule. */
	static constexpr Mass degenerate() noexcept
	{
		return {1.0, 0.0, 0.0, 0.0};
	}

	/** A simple mass function with `weight` on {F} and the rest on Omega. */
	static constexpr Mass simpleFree(double weight) noexcept
	{
		return {0.0, weight, 0.0, 1.0 - weight};
	}

	/** A simple mass function with `weight` on {O} and the rest on Omega. */
	static constexpr Mass simpleOccupied(double weight) noexcept
	{
		return {0.0, 0.0, weight, 1.0 - weight};
	}

	/** Sum of the four masses (1 for a valid mass function). */
	constexpr double sum() const noexcept
	{
		return conflict + free + occupied + unknown;
	}

	/** True when every mass is a finite number in [-tol, 1 + tol] and the
	 * masses sum to 1 within `tol`. NaN is never valid. */
	bool isValid(double tol = 1e-9) const noexcept
	{
		for (const double v : {conflict, free, occupied, unknown})
			if (!(v >= -tol && v <= 1.0 + tol)) return false;
		return std::abs(sum() - 1.0) <= tol;
	}

	constexpr bool operator==(const Mass& o) const noexcept
	{
		return conflict == o.conflict && free == o.free &&
			occupied == o.occupied && unknown == o.unknown;
	}
	constexpr bool operator!=(const Mass& o) const noexcept
	{
		return !(*this == o);
	}
};

/** Largest absolute difference between the masses of a and b: the distance
 * used by tests and by the quantized storage's precision checks. */
inline double maxAbsDifference(const Mass& a, const Mass& b) noexcept
{
	return std::fmax(
		std::fmax(std::abs(a.conflict - b.conflict), std::abs(a.free - b.free)),
		std::fmax(
			std::abs(a.occupied - b.occupied),
			std::abs(a.unknown - b.unknown)));
}

}  // namespace mrpt_evidential
