/* The seed's three lidar sensor models, one sector at a time. */
#include <mrpt_evidential/scan/SensorModel.h>
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>
#include <limits>

#include "support/test_helpers.h"

using namespace mrpt_evidential;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

SensorModelParams params(SensorModel model, double muF, double muO)
{
	SensorModelParams p;
	p.model = model;
	p.muF = muF;
	p.muO = muO;
	return p;
}

struct RatePair
{
	double muF, muO;
};
const RatePair kRatePairs[] = {{0.7, 0.9}, {0.4, 0.6}, {0.95, 0.55}};
}  // namespace

/** The seed's worked figure: bins 0..4 of 1 m, impacts at 3, then 1, then 1
 * again. Every mass of every bin after each impact, by the closed form and by
 * the literal impact/mask combination. */
TEST(ReinforcedMultiEcho, SeedWorkedExample)
{
	for (const RatePair& rates : kRatePairs)
	{
		SCOPED_TRACE(testing::Message() << "muF " << rates.muF << " muO " << rates.muO);
		const SensorModelParams p =
			params(SensorModel::ReinforcedMultiEcho, rates.muF, rates.muO);
		const double f = rates.muF, o = rates.muO;
		const Mass V = Mass::vacuous();
		const std::vector<std::pair<std::vector<double>, std::vector<Mass>>> steps = {
			{{3},
			 {Mass::simpleFree(f), Mass::simpleFree(f), Mass::simpleFree(f),
			  Mass::simpleOccupied(o), V}},
			{{3, 1},
			 {Mass::simpleFree(1 - (1 - f) * (1 - f)), Mass::simpleOccupied(o), V,
			  Mass::simpleOccupied(o), V}},
			{{3, 1, 1},
			 {Mass::simpleFree(1 - (1 - f) * (1 - f) * (1 - f)),
			  Mass::simpleOccupied(1 - (1 - o) * (1 - o)), V,
			  Mass::simpleOccupied(o), V}}};
		for (const auto& [impacts, expected] : steps)
		{
			SCOPED_TRACE(testing::Message() << impacts.size() << " impacts");
			const auto closed = sectorMasses(p, impacts, 1.0, 5);
			const auto literal = sectorMassesByCombination(p, impacts, 1.0, 5);
			ASSERT_EQ(closed.size(), 5u);
			ASSERT_EQ(literal.size(), 5u);
			for (std::size_t b = 0; b < 5; ++b)
			{
				SCOPED_TRACE(testing::Message() << "bin " << b);
				EXPECT_MASS_NEAR(closed[b], expected[b], 1e-12);
				EXPECT_MASS_NEAR(literal[b], expected[b], 1e-12);
			}
		}
	}
}

TEST(MultiEcho, DoesNotReinforce)
{
	const SensorModelParams p = params(SensorModel::MultiEcho, 0.7, 0.9);
	const auto row = sectorMasses(p, {3, 1, 1}, 1.0, 5);
	const Mass V = Mass::vacuous();
	const std::vector<Mass> expected = {
		Mass::simpleFree(0.7), Mass::simpleOccupied(0.9), V,
		Mass::simpleOccupied(0.9), V};
	for (std::size_t b = 0; b < 5; ++b) EXPECT_MASS_NEAR(row[b], expected[b], 0.0);
	// The literal reference of this model is the model itself.
	const auto literal = sectorMassesByCombination(p, {3, 1, 1}, 1.0, 5);
	for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(literal[b], row[b]);
}

TEST(SectorModels, ClosedFormEqualsLiteralCombination)
{
	test::MassGenerator gen(99);
	auto& rng = gen.rng();
	std::uniform_real_distribution<double> u(0.0, 1.0);
	const SensorModel models[] = {
		SensorModel::ReinforcedMultiEcho, SensorModel::ImpreciseMultiEcho};
	for (int trial = 0; trial < 3000; ++trial)
	{
		SensorModelParams p = params(models[trial % 2], u(rng), u(rng));
		p.imprecision = u(rng) < 0.2 ? 0.0 : 0.6 * u(rng);
		p.profile = u(rng) < 0.5 ? ImprecisionProfile::Box : ImprecisionProfile::Gaussian;
		const double binSize = 0.02 + 0.2 * u(rng);
		const std::size_t nBins = 1 + static_cast<std::size_t>(60 * u(rng));
		std::vector<double> impacts(static_cast<std::size_t>(7 * u(rng)));
		for (double& r : impacts)
			r = u(rng) < 0.1 ? kInf : 1.2 * binSize * static_cast<double>(nBins) * u(rng);
		const auto closed = sectorMasses(p, impacts, binSize, nBins);
		const auto literal = sectorMassesByCombination(p, impacts, binSize, nBins);
		for (std::size_t b = 0; b < nBins; ++b)
		{
			ASSERT_TRUE(test::massNear(closed[b], literal[b], 1e-12))
				<< "trial " << trial << " bin " << b;
			ASSERT_TRUE(closed[b].isValid(1e-12));
			// Conflict only arises between scans, never inside one sector.
			ASSERT_NEAR(literal[b].conflict, 0.0, 1e-12);
		}
	}
}

TEST(ImpreciseMultiEcho, ReducesToReinforcedBelowHalfABin)
{
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	for (int trial = 0; trial < 500; ++trial)
	{
		const double binSize = 0.05 + 0.1 * u(rng);
		std::vector<double> impacts(1 + trial % 5);
		for (double& r : impacts) r = 40 * binSize * u(rng);
		SensorModelParams reinforced = params(SensorModel::ReinforcedMultiEcho, 0.6, 0.8);
		SensorModelParams imprecise = reinforced;
		imprecise.model = SensorModel::ImpreciseMultiEcho;
		imprecise.imprecision = 0.499 * binSize * u(rng);
		imprecise.profile = trial % 2 ? ImprecisionProfile::Box : ImprecisionProfile::Gaussian;
		const auto a = sectorMasses(reinforced, impacts, binSize, 50);
		const auto b = sectorMasses(imprecise, impacts, binSize, 50);
		for (std::size_t i = 0; i < 50; ++i) ASSERT_EQ(a[i], b[i]) << "bin " << i;
	}
}

TEST(ImpreciseMultiEcho, OccupiedBandWidensWithImprecision)
{
	const double binSize = 0.1, r = 5.05;  // the centre of bin 50
	for (const ImprecisionProfile profile :
		 {ImprecisionProfile::Box, ImprecisionProfile::Gaussian})
	{
		SensorModelParams p = params(SensorModel::ImpreciseMultiEcho, 0.7, 0.9);
		p.profile = profile;
		std::size_t previousBand = 1, previousFree = 50;
		// d away from multiples of the bin size, so that no centre lies on the
		// band's edge: k bins on each side of the peak.
		for (const auto& [d, k] : std::vector<std::pair<double, std::size_t>>{
				 {0.15, 1}, {0.25, 2}, {0.45, 4}, {0.85, 8}})
		{
			p.imprecision = d;
			const auto row = sectorMasses(p, {r}, binSize, 100);
			std::size_t band = 0, freeBins = 0;
			for (std::size_t b = 0; b < row.size(); ++b)
			{
				if (row[b].occupied > 0) ++band;
				if (row[b].free > 0) ++freeBins;
			}
			// Free space stops where the band starts.
			EXPECT_EQ(band, 2 * k + 1) << "d " << d;
			EXPECT_EQ(freeBins, 50 - k) << "d " << d;
			EXPECT_GT(band, previousBand);
			EXPECT_LT(freeBins, previousFree);
			previousBand = band;
			previousFree = freeBins;
			EXPECT_NEAR(row[50].occupied, 0.9, 1e-12);  // the peak keeps muO
			const double x = static_cast<double>(k) * binSize;
			const double edgeWeight =
				profile == ImprecisionProfile::Box ? 1.0 : std::exp(-2.0 * x * x / (d * d));
			EXPECT_NEAR(row[50 + k].occupied, 0.9 * edgeWeight, 1e-9);
			EXPECT_NEAR(row[50 - k].occupied, 0.9 * edgeWeight, 1e-9);
			EXPECT_EQ(row[50 + k + 1], Mass::vacuous());
			if (profile == ImprecisionProfile::Gaussian)
			{
				EXPECT_LT(row[50 + k].occupied, row[50].occupied);
			}
		}
	}
}

TEST(SectorModels, EdgeCasesOfImpacts)
{
	for (const SensorModel model :
		 {SensorModel::MultiEcho, SensorModel::ReinforcedMultiEcho,
		  SensorModel::ImpreciseMultiEcho})
	{
		const SensorModelParams p = params(model, 0.7, 0.9);
		for (const Mass& m : sectorMasses(p, {}, 0.1, 20))
			EXPECT_EQ(m, Mass::vacuous());
		// No return, or a return beyond the row: every bin was crossed.
		for (const double r : {kInf, 2.0, 1e300})
			for (const Mass& m : sectorMasses(p, {r}, 0.1, 20))
				EXPECT_MASS_NEAR(m, Mass::simpleFree(0.7), 1e-15);
		// A return at 0 leaves no free space.
		const auto atZero = sectorMasses(p, {0.0}, 0.1, 20);
		EXPECT_MASS_NEAR(atZero[0], Mass::simpleOccupied(0.9), 1e-15);
		EXPECT_EQ(atZero[1], Mass::vacuous());
		EXPECT_TRUE(sectorMasses(p, {1.0}, 0.1, 0).empty());
	}
}

TEST(SectorModels, RangeBinCountsEdgesInTheUpperBin)
{
	// 4.0 / 0.05 is 79.99999999999999 in binary: 4 m starts bin 80.
	EXPECT_EQ(rangeBin(4.0, 0.05, 1000.0), 80.0);
	EXPECT_EQ(rangeBin(0.0, 0.05, 1000.0), 0.0);
	EXPECT_EQ(rangeBin(0.0749, 0.05, 1000.0), 1.0);
	// Beyond the last bin, +inf and huge ranges included: nBins.
	for (const double r : {50.0, 1e300, kInf}) EXPECT_EQ(rangeBin(r, 0.05, 1000.0), 1000.0);
}

TEST(SectorModels, RejectsInvalidArguments)
{
	const SensorModelParams p = params(SensorModel::ReinforcedMultiEcho, 0.7, 0.9);
	const double nan = std::numeric_limits<double>::quiet_NaN();
	EXPECT_THROW(sectorMasses(p, {nan}, 0.1, 10), std::invalid_argument);
	EXPECT_THROW(sectorMasses(p, {-0.5}, 0.1, 10), std::invalid_argument);
	EXPECT_THROW(sectorMasses(p, {1.0}, 0.0, 10), std::invalid_argument);
	EXPECT_THROW(sectorMasses(p, {1.0}, nan, 10), std::invalid_argument);
	EXPECT_THROW(sectorMassesByCombination(p, {-1.0}, 0.1, 10), std::invalid_argument);
	for (const auto& bad :
		 {params(SensorModel::MultiEcho, 1.5, 0.9),
		  params(SensorModel::MultiEcho, 0.5, -0.1),
		  params(SensorModel::MultiEcho, nan, 0.5)})
		EXPECT_THROW(bad.validate(), std::invalid_argument);
	SensorModelParams negativeImprecision = p;
	negativeImprecision.imprecision = -0.1;
	EXPECT_THROW(sectorMasses(negativeImprecision, {1.0}, 0.1, 10), std::invalid_argument);
	try
	{
		params(SensorModel::MultiEcho, 0.5, 2.0).validate();
		FAIL() << "no exception";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("muO"), std::string::npos) << e.what();
	}
}
