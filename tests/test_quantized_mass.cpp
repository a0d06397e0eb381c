/* The 16-bit fixed-point cell: every stored value round trips, out-of-range
 * values clamp, and a thousand fusions through it stay close to double
 * precision, for every rule and with decay. */
#include <mrpt_evidential/grid/QuantizedMass.h>
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/test_helpers.h"

using namespace mrpt_evidential;

TEST(QuantizedMass, EveryStoredValueRoundTrips)
{
	for (std::uint32_t q = 0; q <= 65535; ++q)
		ASSERT_EQ(quantizeMass(q / kMassScale), q) << q;
}

TEST(QuantizedMass, ClampsOutOfRangeValues)
{
	EXPECT_EQ(quantizeMass(-0.5), 0);
	EXPECT_EQ(quantizeMass(std::numeric_limits<double>::quiet_NaN()), 0);
	EXPECT_EQ(quantizeMass(1.5), 65535);
	EXPECT_EQ(quantizeMass(std::numeric_limits<double>::infinity()), 65535);
}

TEST(QuantizedMass, EncodedMassesStayValidAndClose)
{
	test::MassGenerator gen(3);
	for (int i = 0; i < 1'000'000; ++i)
	{
		const Mass m = gen();
		QuantizedCell c;
		encodeMass(m, c);
		ASSERT_TRUE(isConsistent(c, true));
		const Mass back = decodeMass(c);
		ASSERT_TRUE(back.isValid(1e-12)) << back;
		// Three roundings to nearest, and at most one step given back by the
		// largest: every mass within 2 steps.
		ASSERT_LE(maxAbsDifference(back, m), 2.0 / kMassScale) << m;
	}
	QuantizedCell c;
	encodeMass(Mass::vacuous(), c);
	EXPECT_EQ(decodeMass(c), Mass::vacuous());
	// Total conflict is stored one step below 1, so that 1 - m(empty) never
	// rounds to 0 and the normal part keeps its ratios (issue 14).
	encodeMass(Mass::degenerate(), c);
	EXPECT_EQ(c.aside, kMaxStoredConflict);
	EXPECT_MASS_NEAR(decodeMass(c), Mass::degenerate(), 1.0 / kMassScale);
	EXPECT_EQ(decide(decodeMass(c)), Decision::Conflict);
	// Three masses of 1/3 round up together: the sum must not pass the scale.
	encodeMass(Mass{1.0 / 3, 1.0 / 3, 1.0 / 3, 0.0}, c);
	EXPECT_TRUE(isConsistent(c, true));
	EXPECT_GE(decodeMass(c).unknown, 0.0);
}

TEST(QuantizedMass, ManyFusionsStayCloseToDoublePrecision)
{
	// Long chains (5000 fusions) of opposite sensor-like evidence through the
	// 8-byte cell against the same fusions in double precision, for every
	// rule, with and without a decay between fusions. Dempster's rule without
	// decay is left out: once a cell is all but dogmatic its result hinges on
	// masses far below any fixed-point step (or on rounding in double
	// precision itself), so no finite precision follows it; with decay the
	// cell never gets there. The conjunctive rule's normal part follows
	// Dempster's rule, so it is compared without decay only as masses, which
	// the conflict then dominates.
	struct Case
	{
		FusionRule rule;
		double decayPerFusion;
	};
	std::vector<Case> cases;
	for (const FusionRule rule :
		 {FusionRule::Conjunctive, FusionRule::Dempster, FusionRule::Yager,
		  FusionRule::DuboisPrade, FusionRule::Cautious})
		for (const double decay : {0.0, 0.02})
			if (!(rule == FusionRule::Dempster && decay == 0.0))
				cases.push_back({rule, decay});
	for (const Case& c : cases)
	{
		test::MassGenerator gen(11);
		std::uniform_real_distribution<double> u(0.0, 1.0);
		const bool normalPartConditioned =
			!(c.rule == FusionRule::Conjunctive && c.decayPerFusion == 0.0);
		for (int trial = 0; trial < 20; ++trial)
		{
			Mass exact = Mass::vacuous();
			QuantizedCell cell;
			encodeMass(exact, cell);
			for (int k = 0; k < 5000; ++k)
			{
				const double w = 0.9 * u(gen.rng());
				const Mass obs = u(gen.rng()) < 0.5 ? Mass::simpleFree(w)
													 : Mass::simpleOccupied(w);
				exact = combine(c.rule, discount(exact, c.decayPerFusion), obs);
				encodeMass(
					combine(c.rule, discount(decodeMass(cell), c.decayPerFusion), obs),
					cell);
			}
			SCOPED_TRACE(
				"rule " + std::to_string(static_cast<int>(c.rule)) + " decay " +
				std::to_string(c.decayPerFusion) + " trial " + std::to_string(trial));
			EXPECT_LE(maxAbsDifference(decodeMass(cell), exact), 1e-3);
			if (normalPartConditioned)
			{
				EXPECT_MASS_NEAR(decodeNormal(cell), normalized(exact), 1e-3);
				EXPECT_NEAR(betP(decodeMass(cell)), betP(exact), 1e-3);
			}
		}
	}
}
