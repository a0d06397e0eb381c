/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Combination rules, discounting and decisions for mass functions on
 * Omega = {F, O}. Header-only, standard library only: never include MRPT. */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mrpt_evidential
{
/** Below this, 1 - m(empty) counts as zero: the sources are in total conflict
 * and normalizing rules take their documented fallback. */
constexpr double kTotalConflictTolerance = 1e-12;

/** The cautious rule needs m(Omega) > 0. A dogmatic input (m(Omega) below this)
 * is first discounted with this rate, which moves its masses by at most this
 * much: the result is the limit of the rule as m(Omega) tends to 0 within
 * that error. */
constexpr double kCautiousMinUnknown = 1e-9;

/** Conjunctive rule (unnormalized, Smets' TBM): the sources are both reliable.
 * Evidence for F from one source and for O from the other becomes conflict,
 * and conflict already present in an input stays conflict. Commutative,
 * associative, with the vacuous mass as neutral element. Never throws. */
inline Mass conjunctive(const Mass& a, const Mass& b) noexcept
{
	Mass r;
	r.free = a.free * b.free + a.free * b.unknown + a.unknown * b.free;
	r.occupied = a.occupied * b.occupied + a.occupied * b.unknown +
		a.unknown * b.occupied;
	r.unknown = a.unknown * b.unknown;
	// Written out (not 1 - the rest) so that inputs a rounding error away
	// from sum 1 do not push the conflict below 0.
	r.conflict = a.conflict * b.sum() +
		b.conflict * (a.free + a.occupied + a.unknown) + a.free * b.occupied +
		a.occupied * b.free;
	return r;
}

/** Disjunctive rule: at least one of the sources is reliable. F with O gives
 * Omega; the degenerate mass (total conflict) is the neutral element.
 * Commutative and associative. Never throws. */
inline Mass disjunctive(const Mass& a, const Mass& b) noexcept
{
	Mass r;
	r.conflict = a.conflict * b.conflict;
	r.free = a.conflict * b.free + a.free * b.conflict + a.free * b.free;
	r.occupied = a.conflict * b.occupied + a.occupied * b.conflict +
		a.occupied * b.occupied;
	r.unknown = a.unknown * b.sum() +
		b.unknown * (a.conflict + a.free + a.occupied) + a.free * b.occupied +
		a.occupied * b.free;
	return r;
}

/** m with its conflict removed by normalization: the other masses divided
 * by 1 - m(empty). At total conflict (nothing left to normalize) it is the
 * vacuous mass; it never divides by zero. Never throws. */
inline Mass normalized(const Mass& m) noexcept
{
	const double k = m.free + m.occupied + m.unknown;
	if (k <= kTotalConflictTolerance) return Mass::vacuous();
	return {0.0, m.free / k, m.occupied / k, m.unknown / k};
}

/** m with its conflict moved to Omega (conflict read as ignorance). Never
 * throws. */
inline Mass conflictToUnknown(Mass m) noexcept
{
	m.unknown += m.conflict;
	m.conflict = 0.0;
	return m;
}

/** Dempster's rule: the conjunctive rule with the conflict removed by
 * normalization. At total conflict the sources together prove nothing and
 * the result is the vacuous mass. Never throws. */
inline Mass dempster(const Mass& a, const Mass& b) noexcept
{
	return normalized(conjunctive(a, b));
}

/** Yager's rule: the conjunctive rule with the conflict moved to Omega.
 * Never throws. */
inline Mass yager(const Mass& a, const Mass& b) noexcept
{
	return conflictToUnknown(conjunctive(a, b));
}

/** Dubois and Prade's rule: each product of masses of disjoint sets goes to
 * their union. On {F, O}, F against O goes to Omega (as in Yager's rule), and
 * conflict already in an input joins the other source's set (empty u A = A).
 * Conflict against conflict has an empty union; it goes to Omega so that the
 * result is always normal (m(empty) = 0). Never throws. */
inline Mass duboisPrade(const Mass& a, const Mass& b) noexcept
{
	Mass r;
	r.conflict = 0.0;
	r.free = a.free * b.free + a.free * b.unknown + a.unknown * b.free +
		a.conflict * b.free + a.free * b.conflict;
	r.occupied = a.occupied * b.occupied + a.occupied * b.unknown +
		a.unknown * b.occupied + a.conflict * b.occupied +
		a.occupied * b.conflict;
	r.unknown = a.unknown * b.unknown + a.free * b.occupied +
		a.occupied * b.free + a.conflict * b.unknown + a.unknown * b.conflict +
		a.conflict * b.conflict;
	return r;
}

/** Classical discounting: every mass times (1 - alpha) and alpha added to
 * m(Omega). alpha = 0 leaves m unchanged, alpha = 1 gives the vacuous mass.
 * \throws std::invalid_argument if alpha is not in [0, 1] (NaN included). */
inline Mass discount(const Mass& m, double alpha)
{
	if (!(alpha >= 0.0 && alpha <= 1.0))
		throw std::invalid_argument(
			"discount: rate must be in [0, 1], got " + std::to_string(alpha));
	const double keep = 1.0 - alpha;
	return {
		m.conflict * keep, m.free * keep, m.occupied * keep,
		m.unknown * keep + alpha};
}

/** Contextual discounting (Mercier, Quost and Denoeux) on the coarsening
 * {F}, {O}: the free mass loses the share `rateFree` to Omega and the occupied
 * mass the share `rateOccupied`. Computed literally as the disjunctive
 * combination of m with the mass that is empty with probability
 * (1 - rateFree)(1 - rateOccupied), {O} with rateFree (1 - rateOccupied),
 * {F} with (1 - rateFree) rateOccupied and Omega with rateFree rateOccupied.
 * With equal rates it equals discount() on normal masses (m(empty) = 0);
 * conflict in m is spread over the four sets by the same disjunction.
 * \throws std::invalid_argument if a rate is not in [0, 1] (NaN included). */
inline Mass contextualDiscount(const Mass& m, double rateFree, double rateOccupied)
{
	if (!(rateFree >= 0.0 && rateFree <= 1.0) ||
		!(rateOccupied >= 0.0 && rateOccupied <= 1.0))
		throw std::invalid_argument(
			"contextualDiscount: rates must be in [0, 1], got " +
			std::to_string(rateFree) + " and " + std::to_string(rateOccupied));
	const Mass context{
		(1.0 - rateFree) * (1.0 - rateOccupied), (1.0 - rateFree) * rateOccupied,
		rateFree * (1.0 - rateOccupied), rateFree * rateOccupied};
	return disjunctive(m, context);
}

/** Denoeux's cautious rule, for sources that may share evidence: idempotent
 * (m with m gives m), commutative and associative. It takes, for each strict
 * subset, the smaller of the two sources' conjunctive weights
 * w(F) = q(Omega)/q(F), w(O) = q(Omega)/q(O), w(empty) = q(F) q(O)/q(Omega)
 * and rebuilds the mass from them. The weights need m(Omega) > 0: a dogmatic
 * input is first discounted with rate kCautiousMinUnknown. Never throws. */
inline Mass cautious(const Mass& a, const Mass& b) noexcept
{
	struct Weights
	{
		double free, occupied, empty;
	};
	const auto weightsOf = [](const Mass& in) {
		const Mass m = in.unknown >= kCautiousMinUnknown
			? in
			: Mass{in.conflict * (1.0 - kCautiousMinUnknown),
				   in.free * (1.0 - kCautiousMinUnknown),
				   in.occupied * (1.0 - kCautiousMinUnknown),
				   in.unknown * (1.0 - kCautiousMinUnknown) +
					   kCautiousMinUnknown};
		const double qF = m.free + m.unknown, qO = m.occupied + m.unknown;
		return Weights{m.unknown / qF, m.unknown / qO, qF * qO / m.unknown};
	};
	const Weights wa = weightsOf(a), wb = weightsOf(b);
	const double wF = std::min(wa.free, wb.free);
	const double wO = std::min(wa.occupied, wb.occupied);
	const double wE = std::min(wa.empty, wb.empty);
	// The conjunction of the simple masses F^wF and O^wO, whose non-empty part
	// the empty-set weight then scales.
	Mass r;
	r.free = (1.0 - wF) * wO * wE;
	r.occupied = (1.0 - wO) * wF * wE;
	r.unknown = wF * wO * wE;
	r.conflict = std::max(0.0, 1.0 - (r.free + r.occupied + r.unknown));
	return r;
}

/** The combination rules a map can fuse with, by name in .ini files. */
enum class FusionRule
{
	Conjunctive,
	Dempster,
	Yager,
	DuboisPrade,
	Cautious
};

/** Combines a and b with the given rule. Never throws. */
inline Mass combine(FusionRule rule, const Mass& a, const Mass& b) noexcept
{
	switch (rule)
	{
		case FusionRule::Dempster: return dempster(a, b);
		case FusionRule::Yager: return yager(a, b);
		case FusionRule::DuboisPrade: return duboisPrade(a, b);
		case FusionRule::Cautious: return cautious(a, b);
		case FusionRule::Conjunctive: break;
	}
	return conjunctive(a, b);
}

/** What becomes of the conflict a fusion creates (the fusion rule decides
 * how much there is; this decides whether the result keeps it). */
enum class ConflictHandling
{
	/** The result keeps it, fusion after fusion: conflict marks change, and
	 * decay fades it like any other evidence. */
	Keep,
	/** It becomes ignorance (conflictToUnknown()). */
	ToUnknown,
	/** It is removed and the rest renormalized (normalized()), as Dempster's
	 * rule does. */
	Normalize
};

/** The conflict of a conjunctive fusion of what a cell held `before` with
 * what a sensor `observed`, split by its cause (Moras, Cherfaoui and
 * Bonnifait): seen free before and occupied now (something appeared), or
 * the other way round (something left). For masses without conflict the two
 * sum to conjunctive(before, observed).conflict. */
struct ConflictSplit
{
	double appeared = 0.0;  //!< before(F) observed(O)
	double disappeared = 0.0;  //!< before(O) observed(F)
};

inline ConflictSplit splitConflict(const Mass& before, const Mass& observed) noexcept
{
	return {before.free * observed.occupied, before.occupied * observed.free};
}

/** A fused mass after the conflict handling. Never throws. */
inline Mass handleConflict(const Mass& m, ConflictHandling handling) noexcept
{
	switch (handling)
	{
		case ConflictHandling::ToUnknown: return conflictToUnknown(m);
		case ConflictHandling::Normalize: return normalized(m);
		case ConflictHandling::Keep: break;
	}
	return m;
}

/** A singleton hypothesis of Omega = {F, O}. */
enum class Hypothesis
{
	Free,
	Occupied
};

/** Belief of a hypothesis: the mass committed to it, m({h}). */
inline double belief(const Mass& m, Hypothesis h = Hypothesis::Occupied) noexcept
{
	return h == Hypothesis::Occupied ? m.occupied : m.free;
}

/** Plausibility of a hypothesis: m({h}) + m(Omega), the mass that does not
 * contradict it. */
inline double plausibility(
	const Mass& m, Hypothesis h = Hypothesis::Occupied) noexcept
{
	return belief(m, h) + m.unknown;
}

/** Pignistic probability of occupancy with the conflict removed:
 * (m(O) + m(Omega)/2) / (1 - m(empty)). At total conflict nothing is left to
 * share and the result is 0.5, as for ignorance. Never throws. */
inline double betP(const Mass& m) noexcept
{
	const double k = m.free + m.occupied + m.unknown;
	if (k <= kTotalConflictTolerance) return 0.5;
	return (m.occupied + 0.5 * m.unknown) / k;
}

/** The four states a cell can be shown in. */
enum class Decision
{
	Unknown,
	Free,
	Occupied,
	Conflict
};

/** Maximum-mass decision: the subset with the largest mass. Ties go to the
 * more cautious reading, in the order Unknown, Conflict, Occupied, Free (a
 * cell never reads free unless free strictly outweighs the rest). */
inline Decision decide(const Mass& m) noexcept
{
	Decision d = Decision::Unknown;
	double best = m.unknown;
	if (m.conflict > best) d = Decision::Conflict, best = m.conflict;
	if (m.occupied > best) d = Decision::Occupied, best = m.occupied;
	if (m.free > best) d = Decision::Free;
	return d;
}

}  // namespace mrpt_evidential
