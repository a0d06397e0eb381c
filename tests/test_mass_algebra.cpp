/* Laws of the mass algebra on {F, O}. Built without MRPT: it proves the
 * algebra headers stand alone. */
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>
#include <limits>

#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::MassGenerator;

namespace
{
constexpr std::size_t kSamples = 2000;
constexpr double kTol = 1e-12;

/** Hand-picked corners of the simplex, where rules tend to break. */
std::vector<Mass> cornerMasses()
{
	return {
		Mass::vacuous(),
		Mass::degenerate(),
		{0, 1, 0, 0},
		{0, 0, 1, 0},
		{0, 0.5, 0.5, 0},
		{0.5, 0, 0, 0.5},
		Mass::simpleFree(0.3),
		Mass::simpleOccupied(0.999999),
		{0.25, 0.25, 0.25, 0.25}};
}

using Rule = Mass (*)(const Mass&, const Mass&);
const std::vector<std::pair<const char*, Rule>> kRules = {
	{"conjunctive", &conjunctive}, {"disjunctive", &disjunctive},
	{"dempster", &dempster},	   {"yager", &yager},
	{"duboisPrade", &duboisPrade}, {"cautious", &cautious}};
}  // namespace

TEST(Mass, DefaultIsVacuousAndHelpersAreValid)
{
	EXPECT_EQ(Mass{}, Mass::vacuous());
	EXPECT_EQ(Mass::vacuous().unknown, 1.0);
	EXPECT_EQ(Mass::degenerate().conflict, 1.0);
	for (const Mass& m : cornerMasses()) EXPECT_TRUE(m.isValid()) << m;
	EXPECT_EQ(Mass::simpleFree(0.3).free, 0.3);
	EXPECT_EQ(Mass::simpleOccupied(0.4).unknown, 0.6);
}

TEST(Mass, ValidityRejectsBadMasses)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	EXPECT_FALSE((Mass{0, 0.5, 0.4, 0}).isValid());  // sums to 0.9
	EXPECT_FALSE((Mass{0, 1.2, -0.2, 0}).isValid());  // sums to 1, out of range
	EXPECT_FALSE((Mass{0, nan, 0, 1}).isValid());
	EXPECT_FALSE((Mass{0, 0, 0, std::numeric_limits<double>::infinity()}).isValid());
	EXPECT_TRUE((Mass{0, 0.5, 0.5 + 1e-12, 0}).isValid());
	EXPECT_FALSE((Mass{0, 0.5, 0.5 + 1e-6, 0}).isValid());
	EXPECT_TRUE((Mass{0, 0.5, 0.5 + 1e-6, 0}).isValid(1e-5));
}

TEST(Rules, EveryResultIsValid)
{
	MassGenerator gen;
	auto inputs = gen.many(kSamples);
	const auto corners = cornerMasses();
	inputs.insert(inputs.end(), corners.begin(), corners.end());
	for (const auto& [name, rule] : kRules)
		for (std::size_t i = 0; i < inputs.size(); ++i)
			for (const Mass& other : {inputs[(i * 7 + 3) % inputs.size()], corners[i % corners.size()]})
			{
				const Mass r = rule(inputs[i], other);
				ASSERT_TRUE(r.isValid(1e-12))
					<< name << "(" << inputs[i] << ", " << other << ") = " << r;
			}
}

TEST(Rules, MillionChainedFusionsStayValid)
{
	// Each rule fed its own result a sixth of a million times in double
	// precision, discounted in between by rates from none to total, against
	// random masses and the corners (total conflict, dogmatic, vacuous):
	// rounding must never take a result out of the simplex.
	MassGenerator gen(99);
	const auto corners = cornerMasses();
	const double rates[] = {0.0, 1e-300, 1e-9, 0.5, 1.0 - 1e-16, 1.0};
	std::uniform_int_distribution<std::size_t> pick(0, 1 << 20);
	std::size_t fusions = 0;
	for (const auto& [name, rule] : kRules)
	{
		Mass m = Mass::vacuous();
		for (std::size_t k = 0; k < 1'000'000 / kRules.size() + 1; ++k, ++fusions)
		{
			const Mass obs = pick(gen.rng()) % 4 == 0
				? corners[pick(gen.rng()) % corners.size()]
				: gen();
			m = rule(discount(m, rates[pick(gen.rng()) % 6]), obs);
			ASSERT_TRUE(m.isValid(1e-9)) << name << " after " << k << ": " << m;
		}
	}
	EXPECT_GE(fusions, 1'000'000u);
}

TEST(Rules, ConjunctiveAndDisjunctiveAreCommutativeAndAssociative)
{
	MassGenerator gen;
	for (std::size_t i = 0; i < kSamples; ++i)
	{
		const Mass a = gen(), b = gen(), c = gen();
		EXPECT_MASS_NEAR(conjunctive(a, b), conjunctive(b, a), kTol);
		EXPECT_MASS_NEAR(disjunctive(a, b), disjunctive(b, a), kTol);
		EXPECT_MASS_NEAR(
			conjunctive(conjunctive(a, b), c), conjunctive(a, conjunctive(b, c)),
			kTol);
		EXPECT_MASS_NEAR(
			disjunctive(disjunctive(a, b), c), disjunctive(a, disjunctive(b, c)),
			kTol);
	}
}

TEST(Rules, NeutralElements)
{
	MassGenerator gen;
	for (const Mass& m : gen.many(kSamples))
	{
		EXPECT_MASS_NEAR(conjunctive(m, Mass::vacuous()), m, kTol);
		EXPECT_MASS_NEAR(conjunctive(Mass::vacuous(), m), m, kTol);
		EXPECT_MASS_NEAR(disjunctive(m, Mass::degenerate()), m, kTol);
		EXPECT_MASS_NEAR(disjunctive(Mass::degenerate(), m), m, kTol);
	}
}

TEST(Rules, ConjunctiveOfSimpleMassesByHand)
{
	// F^0.6 with O^0.5: conflict 0.3, F 0.3, O 0.2, Omega 0.2.
	const Mass r = conjunctive(Mass::simpleFree(0.6), Mass::simpleOccupied(0.5));
	EXPECT_MASS_NEAR(r, (Mass{0.3, 0.3, 0.2, 0.2}), kTol);
	// Disjunction of F and O certainties is ignorance.
	EXPECT_MASS_NEAR(
		disjunctive(Mass{0, 1, 0, 0}, Mass{0, 0, 1, 0}), Mass::vacuous(), kTol);
}

TEST(Rules, DempsterIsNormalizedConjunctive)
{
	MassGenerator gen;
	for (std::size_t i = 0; i < kSamples; ++i)
	{
		const Mass a = gen(), b = gen();
		const Mass c = conjunctive(a, b);
		const double k = 1.0 - c.conflict;
		if (k < 1e-6) continue;
		const Mass d = dempster(a, b);
		EXPECT_EQ(d.conflict, 0.0);
		EXPECT_MASS_NEAR(
			d, (Mass{0, c.free / k, c.occupied / k, c.unknown / k}), 1e-9);
	}
}

TEST(Rules, DempsterAtTotalConflictIsVacuous)
{
	const Mass r = dempster(Mass{0, 1, 0, 0}, Mass{0, 0, 1, 0});
	EXPECT_EQ(r, Mass::vacuous());
	EXPECT_EQ(dempster(Mass::degenerate(), Mass::vacuous()), Mass::vacuous());
}

TEST(Rules, YagerMovesConflictToOmega)
{
	MassGenerator gen;
	for (std::size_t i = 0; i < kSamples; ++i)
	{
		const Mass a = gen(), b = gen();
		const Mass c = conjunctive(a, b), y = yager(a, b);
		EXPECT_EQ(y.conflict, 0.0);
		EXPECT_DOUBLE_EQ(y.free, c.free);
		EXPECT_DOUBLE_EQ(y.occupied, c.occupied);
		EXPECT_NEAR(y.unknown, c.unknown + c.conflict, kTol);
	}
}

TEST(Rules, DuboisPradeEqualsYagerOnNormalInputs)
{
	MassGenerator gen;
	for (std::size_t i = 0; i < kSamples; ++i)
	{
		const Mass a = gen(false), b = gen(false);
		EXPECT_MASS_NEAR(duboisPrade(a, b), yager(a, b), kTol);
	}
}

TEST(Rules, DuboisPradeGivesInputConflictToTheOtherSet)
{
	// empty u F = F: a source in total conflict leaves the other one as it is.
	EXPECT_MASS_NEAR(
		duboisPrade(Mass::degenerate(), Mass{0, 1, 0, 0}), (Mass{0, 1, 0, 0}),
		kTol);
	// Conflict against conflict has no non-empty union: documented as Omega.
	EXPECT_MASS_NEAR(
		duboisPrade(Mass::degenerate(), Mass::degenerate()), Mass::vacuous(),
		kTol);
	// Yager, by contrast, reads an input's conflict as ignorance.
	EXPECT_MASS_NEAR(
		yager(Mass::degenerate(), Mass{0, 1, 0, 0}), Mass::vacuous(), kTol);
}

TEST(Rules, CautiousIsIdempotentCommutativeAndAssociative)
{
	MassGenerator gen;
	std::size_t associativityChecks = 0;
	for (std::size_t i = 0; i < kSamples; ++i)
	{
		Mass a = gen(), b = gen(), c = gen();
		if (a.unknown < 1e-6) a = discount(a, 1e-3);
		EXPECT_MASS_NEAR(cautious(a, a), a, 1e-9);
		EXPECT_MASS_NEAR(cautious(a, b), cautious(b, a), 1e-12);
		// Associativity holds for non-dogmatic masses; where an intermediate
		// result is dogmatic the rule discounts it by kCautiousMinUnknown,
		// which moves results by about that much.
		const Mass ab = cautious(a, b), bc = cautious(b, c);
		if (ab.unknown < 1e3 * kCautiousMinUnknown ||
			bc.unknown < 1e3 * kCautiousMinUnknown)
			continue;
		EXPECT_MASS_NEAR(cautious(ab, c), cautious(a, bc), 1e-9);
		++associativityChecks;
	}
	EXPECT_GT(associativityChecks, kSamples / 2);
}

TEST(Rules, CautiousKeepsTheStrongerOfSharedEvidence)
{
	// Two sources saying "free" with 0.6 and 0.8 may be the same evidence:
	// the cautious rule keeps 0.8 where the conjunctive rule would give 0.92.
	EXPECT_MASS_NEAR(
		cautious(Mass::simpleFree(0.6), Mass::simpleFree(0.8)),
		Mass::simpleFree(0.8), 1e-12);
	EXPECT_NEAR(
		conjunctive(Mass::simpleFree(0.6), Mass::simpleFree(0.8)).free, 0.92,
		1e-12);
	// Evidence on different sets is not shared: cautious equals conjunctive.
	const Mass f = Mass::simpleFree(0.6), o = Mass::simpleOccupied(0.7);
	EXPECT_MASS_NEAR(cautious(f, o), conjunctive(f, o), 1e-12);
}

TEST(Rules, CautiousWithDogmaticInputsStaysValid)
{
	// m(Omega) = 0 is handled by a discount of kCautiousMinUnknown.
	const Mass f{0, 1, 0, 0}, o{0, 0, 1, 0};
	EXPECT_MASS_NEAR(cautious(f, f), f, 1e-8);
	const Mass r = cautious(f, o);
	EXPECT_TRUE(r.isValid(1e-9)) << r;
	EXPECT_NEAR(r.conflict, 1.0, 1e-8);
	EXPECT_TRUE(cautious(Mass::degenerate(), Mass::vacuous()).isValid(1e-9));
}

TEST(Discount, ZeroIsIdentityAndOneIsVacuous)
{
	MassGenerator gen;
	for (const Mass& m : gen.many(kSamples))
	{
		EXPECT_EQ(discount(m, 0.0), m);
		EXPECT_MASS_NEAR(discount(m, 1.0), Mass::vacuous(), 0.0);
		const Mass half = discount(m, 0.5);
		EXPECT_TRUE(half.isValid());
		EXPECT_DOUBLE_EQ(half.free, 0.5 * m.free);
		EXPECT_DOUBLE_EQ(half.conflict, 0.5 * m.conflict);
	}
}

TEST(Discount, RejectsRatesOutsideTheUnitInterval)
{
	const Mass m = Mass::simpleFree(0.5);
	EXPECT_THROW(discount(m, -0.1), std::invalid_argument);
	EXPECT_THROW(discount(m, 1.1), std::invalid_argument);
	EXPECT_THROW(
		discount(m, std::numeric_limits<double>::quiet_NaN()),
		std::invalid_argument);
	EXPECT_THROW(contextualDiscount(m, 0.2, 2.0), std::invalid_argument);
	EXPECT_THROW(contextualDiscount(m, -1.0, 0.2), std::invalid_argument);
}

TEST(Discount, ContextualDiscountWeakensEachSetByItsOwnRate)
{
	MassGenerator gen;
	for (const Mass& m : gen.many(kSamples, false))
	{
		EXPECT_MASS_NEAR(contextualDiscount(m, 0.3, 0.3), discount(m, 0.3), kTol);
		const Mass r = contextualDiscount(m, 0.25, 0.6);
		EXPECT_TRUE(r.isValid());
		EXPECT_NEAR(r.free, 0.75 * m.free, kTol);
		EXPECT_NEAR(r.occupied, 0.4 * m.occupied, kTol);
		EXPECT_EQ(r.conflict, 0.0);
	}
	MassGenerator withConflict(7);
	for (const Mass& m : withConflict.many(kSamples))
	{
		EXPECT_TRUE(contextualDiscount(m, 0.1, 0.9).isValid());
		EXPECT_MASS_NEAR(contextualDiscount(m, 0.0, 0.0), m, kTol);
		EXPECT_MASS_NEAR(contextualDiscount(m, 1.0, 1.0), Mass::vacuous(), kTol);
	}
}

TEST(Decisions, BetPBeliefAndPlausibility)
{
	EXPECT_EQ(betP(Mass::vacuous()), 0.5);
	EXPECT_EQ(betP(Mass{0, 1, 0, 0}), 0.0);
	EXPECT_EQ(betP(Mass{0, 0, 1, 0}), 1.0);
	EXPECT_EQ(betP(Mass::degenerate()), 0.5);
	// (0.3 + 0.2 / 2) / (1 - 0.2)
	const Mass m{0.2, 0.3, 0.3, 0.2};
	EXPECT_NEAR(betP(m), 0.5, kTol);
	EXPECT_NEAR(betP(Mass{0.2, 0.1, 0.5, 0.2}), 0.75, kTol);
	EXPECT_EQ(belief(m), 0.3);
	EXPECT_EQ(belief(Mass{0, 0.6, 0.1, 0.3}, Hypothesis::Free), 0.6);
	EXPECT_NEAR(plausibility(Mass{0, 0.6, 0.1, 0.3}), 0.4, kTol);
	EXPECT_NEAR(plausibility(Mass{0, 0.6, 0.1, 0.3}, Hypothesis::Free), 0.9, kTol);

	MassGenerator gen;
	for (const Mass& n : gen.many(kSamples, false))
	{
		EXPECT_LE(belief(n), betP(n) + kTol);
		EXPECT_LE(betP(n), plausibility(n) + kTol);
	}
}

TEST(Decisions, MaximumMassWithCautiousTies)
{
	EXPECT_EQ(decide(Mass::vacuous()), Decision::Unknown);
	EXPECT_EQ(decide(Mass{0, 0.6, 0.1, 0.3}), Decision::Free);
	EXPECT_EQ(decide(Mass{0.1, 0.1, 0.7, 0.1}), Decision::Occupied);
	EXPECT_EQ(decide(Mass{0.5, 0.2, 0.2, 0.1}), Decision::Conflict);
	EXPECT_EQ(decide(Mass{0, 0.5, 0, 0.5}), Decision::Unknown);
	EXPECT_EQ(decide(Mass{0, 0.5, 0.5, 0}), Decision::Occupied);
}

TEST(Rules, CombineDispatchesToEachRule)
{
	MassGenerator gen;
	const Mass a = gen(), b = gen();
	EXPECT_EQ(combine(FusionRule::Conjunctive, a, b), conjunctive(a, b));
	EXPECT_EQ(combine(FusionRule::Dempster, a, b), dempster(a, b));
	EXPECT_EQ(combine(FusionRule::Yager, a, b), yager(a, b));
	EXPECT_EQ(combine(FusionRule::DuboisPrade, a, b), duboisPrade(a, b));
	EXPECT_EQ(combine(FusionRule::Cautious, a, b), cautious(a, b));
}
