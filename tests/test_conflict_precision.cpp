/* Precision of the stored cell under heavy conflict (issue 14): a wall that
 * rays keep crossing collects conflict until m(empty) is all but 1, and the
 * cell must still tell which way it leans. Checked against the same fusions
 * in double precision, kept in the same split form (conflict apart, normal
 * part normalized), since the masses themselves underflow a double long
 * before 1000 fusions. */
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/grid/QuantizedMass.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <random>
#include <vector>

#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;

namespace
{
/** A mass in split form, in double precision: the conflict and the normal
 * part, as the cell stores them. */
struct SplitMass
{
	double conflict = 0.0;
	Mass normal = Mass::vacuous();
};

SplitMass split(const Mass& m) { return {m.conflict, normalized(m)}; }

/** The conjunctive rule in split form: Dempster's rule on the normal parts,
 * and 1 - conflict multiplied by 1 - the conflict of that fusion. */
SplitMass conjunctiveSplit(const SplitMass& a, const SplitMass& b)
{
	const Mass c = conjunctive(a.normal, b.normal);
	return {1.0 - (1.0 - a.conflict) * (1.0 - b.conflict) * (1.0 - c.conflict),
			normalized(c)};
}

/** 181 valid beams over 180 degrees, every range r, maxRange 80, all at one
 * time. */
CObservation2DRangeScan ring(double r)
{
	return test::arcScan(181, r, test::ScanSetup().maxRange(80.0).at(0.0));
}

/** What one scan alone leaves in the cell at (x, y). */
Mass observedAt(const CObservation2DRangeScan& scan, double x, double y)
{
	CEvidentialGridMap2D fresh(-10, 10, -10, 10, 0.05);
	fresh.insertObservation(scan, CPose3D());
	return fresh.getCellMasses(x, y);
}
}  // namespace

TEST(ConflictPrecision, WallBetweenRepeatedScansKeepsLeaningOccupied)
{
	// The reproduction of issue 14: scans of 5 m and of 6 m in turn, all at
	// one time; the cell (5.025, 0.025) holds the wall of the 5 m scans and is
	// crossed by the rays of the 6 m ones.
	const double x = 5.025, y = 0.025;
	const auto near = ring(5.0), far = ring(6.0);
	const SplitMass seenNear = split(observedAt(near, x, y));
	const SplitMass seenFar = split(observedAt(far, x, y));
	ASSERT_GT(seenNear.normal.occupied, 0.5);
	ASSERT_GT(seenFar.normal.free, 0.5);

	CEvidentialGridMap2D map(-10, 10, -10, 10, 0.05);
	SplitMass exact;
	const std::vector<int> checked{1, 2, 8, 10, 11, 20, 50, 100, 300, 1000};
	for (int n = 1; n <= checked.back(); ++n)
	{
		map.insertObservation(near, CPose3D());
		map.insertObservation(far, CPose3D());
		exact = conjunctiveSplit(conjunctiveSplit(exact, seenNear), seenFar);
		if (std::find(checked.begin(), checked.end(), n) == checked.end()) continue;

		SCOPED_TRACE("after " + std::to_string(n) + " pairs of scans");
		const double exactBetP = betP(exact.normal);
		EXPECT_NEAR(map.getCellBetP(x, y), exactBetP, 2e-3);
		const Mass stored = map.getCellMasses(x, y);
		EXPECT_NEAR(
			stored.occupied / (1.0 - stored.conflict), exact.normal.occupied, 2e-3);
		EXPECT_GT(exactBetP, 0.75);

		// MRPT's grid holds the probability of being free, in 8-bit log-odds.
		mrpt::maps::COccupancyGridMap2D grid;
		map.getAsOccupancyGrid(grid);
		EXPECT_NEAR(1.0 - grid.getPos(x, y), exactBetP, 0.02)
			<< "the wall is gone from the grid";

		const double atTruth = map.computeObservationLikelihood(near, CPose3D());
		const double off = map.computeObservationLikelihood(near, CPose3D(0.2, 0, 0));
		EXPECT_GT(atTruth, off + 1.0) << "the wall no longer places the scan";
	}
	EXPECT_GT(exact.conflict, 1.0 - 1e-12);  // the conflict is all but total
}

TEST(ConflictPrecision, LongConflictingChainsKeepTheNormalPart)
{
	// 10,000 fusions of opposite sensor-like evidence per chain through the
	// 8-byte cell, for every rule and conflict handling, against double
	// precision: the normal part, BetP and the conflict. With a decay, as
	// the storage's precision tests explain for Dempster's rule (whose
	// dynamics the conjunctive rule's normal part follows).
	std::mt19937 rng(14);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	for (const FusionRule rule :
		 {FusionRule::Conjunctive, FusionRule::Dempster, FusionRule::Yager,
		  FusionRule::DuboisPrade, FusionRule::Cautious})
		for (const ConflictHandling handling :
			 {ConflictHandling::Keep, ConflictHandling::ToUnknown,
			  ConflictHandling::Normalize})
			for (int trial = 0; trial < 5; ++trial)
			{
				const double decay = 0.02;
				Mass exact = Mass::vacuous();
				QuantizedCell cell;
				encodeMass(exact, cell);
				for (int k = 0; k < 10'000; ++k)
				{
					// Occupied evidence against weaker free evidence, in turn
					// at random. The decay keeps 1 - m(empty) above 2 %, so the
					// double-precision masses keep their own ratios.
					const Mass obs = u(rng) < 0.5
						? Mass::simpleOccupied(0.6 + 0.35 * u(rng))
						: Mass::simpleFree(0.3 + 0.4 * u(rng));
					const auto fuse = [&](const Mass& m) {
						return handleConflict(combine(rule, discount(m, decay), obs), handling);
					};
					encodeMass(fuse(decodeMass(cell)), cell);
					exact = fuse(exact);
				}
				SCOPED_TRACE(
					"rule " + std::to_string(int(rule)) + " handling " +
					std::to_string(int(handling)) + " trial " + std::to_string(trial));
				EXPECT_MASS_NEAR(decodeNormal(cell), normalized(exact), 2e-3);
				EXPECT_NEAR(betP(decodeMass(cell)), betP(exact), 2e-3);
				EXPECT_NEAR(decodeMass(cell).conflict, exact.conflict, 1e-3);
			}
}
