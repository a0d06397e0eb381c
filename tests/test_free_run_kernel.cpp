/* The bulk kernels of FreeRunKernel.cpp: a run of cells fused at once gives
 * the cells, bit for bit, that fusing them one by one gives (one mass for the
 * run or one per cell; with and without decay; keeping conflict or not;
 * Dempster's rule, Yager's or the cautious rule, normalized or not), and lists
 * the loud cells it leaves, in order; cell by cell, the single-precision
 * fusion reads as the general rule's. */
#include <gtest/gtest.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>

#include <cstdint>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

using namespace mrpt_evidential;

namespace
{
/** A grid without conflict whose cells hold random masses, stamps of several
 * insertions, impact flags and events of every kind. `mostlyQuiet`: few
 * cells are loud (little occupied mass, events rare), as in the free space
 * of a real scan, where the bulk kernels' whole blocks do the work. */
EvidentialGridStorage gridWithVariedCells(
	double decayRate, std::uint32_t seed, bool mostlyQuiet = false,
	bool firstHalfWrittenLast = false)
{
	EvidentialGridStorage g;
	g.reset(0.0, 4.0, 0.0, 1.0, 0.1, 1000);
	g.setKeepsConflict(false);
	g.setDecayRate(decayRate);
	g.setEventRetention(10.0);
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	for (int scan = 0; scan < 6; ++scan)
	{
		g.beginInsertion(100.0 + 0.7 * scan);
		for (std::size_t idx = 0; idx < g.geometry().cellCount(); ++idx)
		{
			// `firstHalfWrittenLast`: the first half's cells all take the
			// last scan's stamp, whole blocks of one decay factor.
			const bool written = firstHalfWrittenLast && scan == 5 &&
				idx < g.geometry().cellCount() / 2;
			if (!written && unit(rng) < 0.5) continue;
			const double occupiedShare = mostlyQuiet ? 0.02 : (unit(rng) < 0.3 ? 1.0 : 0.1);
			const double f = unit(rng), o = unit(rng) * (1.0 - f) * occupiedShare;
			g.write(idx, Mass{0.0, f, o, 1.0 - f - o});
			// Now and then no ignorance at all, mostly free: quiet for
			// Dempster's rule, loud for the cautious rule's kernels.
			if (!mostlyQuiet && unit(rng) < 0.05)
			{
				const double free = 0.7 + 0.3 * unit(rng);
				g.write(idx, Mass{0.0, free, 1.0 - free, 0.0});
			}
			if (unit(rng) < 0.2) g.markImpact(idx);
			if (unit(rng) < 0.2) g.markFlipped(idx);
			const double e = unit(rng) * (mostlyQuiet ? 10.0 : 1.0);
			if (e < 0.1) g.setEvent(idx, CellEvent::Appeared);
			else if (e < 0.2) g.setEvent(idx, CellEvent::Leaving);
			else if (e < 0.3) g.setEvent(idx, CellEvent::Disappeared);
		}
	}
	g.beginInsertion(106.0);
	return g;
}
/** Fuses w into [first, first + count) of `bulk` as one quiet run and into
 * the same cells of `oneByOne` cell by cell, with `Rule`; fails unless both
 * give the same cells bit for bit (loud cells untouched) and list the same
 * loud cells. Returns how many were loud. */
template <bool Decays, FreeFusion Rule>
std::size_t quietRunAsCellByCell(
	EvidentialGridStorage& bulk, EvidentialGridStorage& oneByOne, std::size_t first,
	std::size_t count, float w, std::uint16_t occupiedBelow)
{
	std::vector<std::size_t> loud, expectedLoud;
	bulk.fuseQuietFreeRun<Decays, Rule>(first, count, w, occupiedBelow, loud);
	for (std::size_t idx = first; idx < first + count; ++idx)
		if (oneByOne.isLoudFor<Rule>(idx, occupiedBelow))
			expectedLoud.push_back(idx);
		else
			oneByOne.fuseSimpleFree<Decays, false, Rule>(idx, w);
	const int rule = static_cast<int>(Rule);
	EXPECT_EQ(loud, expectedLoud) << Decays << rule << " " << first << " " << count;
	EXPECT_TRUE(bulk.cells() == oneByOne.cells())
		<< Decays << rule << " " << first << " " << count;
	return loud.size();
}
template <FreeFusion Rule>
std::size_t expectQuietRunAsCellByCell(
	EvidentialGridStorage& bulk, EvidentialGridStorage& oneByOne, bool decays,
	std::size_t first, std::size_t count, float w, std::uint16_t occupiedBelow)
{
	return decays
		? quietRunAsCellByCell<true, Rule>(bulk, oneByOne, first, count, w, occupiedBelow)
		: quietRunAsCellByCell<false, Rule>(bulk, oneByOne, first, count, w, occupiedBelow);
}
/** expectQuietRunAsCellByCell() with each rule of the kernels. */
template <typename Check>
void forEachFreeFusion(Check&& check)
{
	check(std::integral_constant<FreeFusion, FreeFusion::Dempster>{});
	check(std::integral_constant<FreeFusion, FreeFusion::Yager>{});
	check(std::integral_constant<FreeFusion, FreeFusion::CautiousNormalized>{});
	check(std::integral_constant<FreeFusion, FreeFusion::CautiousToUnknown>{});
}
}  // namespace

TEST(GridStorage, QuietFreeRunsFuseAsCellByCellAndListTheLoudInOrder)
{
	forEachFreeFusion([](auto rule) {
		for (const double rate : {0.0, 0.05})
			for (std::size_t first = 0; first < 5; ++first)
				for (const std::size_t count : {0, 1, 3, 4, 5, 7, 8, 9, 200, 395})
				{
					EvidentialGridStorage bulk = gridWithVariedCells(rate, 7);
					EvidentialGridStorage oneByOne = gridWithVariedCells(rate, 7);
					const std::size_t loud = expectQuietRunAsCellByCell<rule()>(
						bulk, oneByOne, rate > 0.0, first, count, 0.37f, 20000);
					if (count >= 200)
					{
						EXPECT_GT(loud, 10u);
						EXPECT_LT(loud, count / 2);
					}
				}
	});
}

// Blocks of eight cells without a loud one, which processors with AVX2 fuse
// in one step, and the blocks of four around a loud cell.
TEST(GridStorage, LongQuietRunsFuseAsCellByCell)
{
	forEachFreeFusion([](auto rule) {
		for (const double rate : {0.0, 0.05})
			for (std::size_t first = 0; first < 9; ++first)
				for (const std::size_t count : {8, 12, 15, 16, 17, 31, 200, 391})
				{
					EvidentialGridStorage bulk = gridWithVariedCells(rate, 11, true);
					EvidentialGridStorage oneByOne = gridWithVariedCells(rate, 11, true);
					// n(O) of 2000 is above the 0.02 of the scale these cells hold.
					const std::size_t loud = expectQuietRunAsCellByCell<rule()>(
						bulk, oneByOne, rate > 0.0, first, count, 0.61f, 2000);
					if (count >= 200)
					{
						EXPECT_GT(loud, 0u);
						EXPECT_LT(loud, count / 8);
					}
				}
	});
}

// Blocks whose cells the same scan wrote last take one decay factor.
TEST(GridStorage, CellsWrittenTogetherDecayAsCellByCell)
{
	forEachFreeFusion([](auto rule) {
		for (std::size_t first = 0; first < 9; ++first)
			for (const std::size_t count : {8, 16, 17, 200, 391})
			{
				EvidentialGridStorage bulk = gridWithVariedCells(0.05, 13, true, true);
				EvidentialGridStorage oneByOne = gridWithVariedCells(0.05, 13, true, true);
				expectQuietRunAsCellByCell<rule()>(bulk, oneByOne, true, first, count, 0.61f, 2000);
			}
	});
}

TEST(GridStorage, SaturatedFreeCellsWithoutDecayReadAsCellByCell)
{
	// Cells free at the ceiling, in runs long enough for whole groups of
	// four, among varied ones: without decay the bulk (and the cell-by-cell
	// fusion) leaves them as they are (only their stamp stays older), which
	// reads as the full arithmetic does, now and after a change of rate (it
	// rebases every stamp first).
	EvidentialGridStorage bulk = gridWithVariedCells(0.0, 5);
	const std::size_t cells = bulk.geometry().cellCount();
	for (std::size_t idx = 0; idx < cells; ++idx)
		if (idx % 50 < 30)
		{
			bulk.write(idx, Mass{0.0, 1.0, 0.0, 0.0});
			bulk.setEvent(idx, CellEvent::None);  // quiet, so that groups mix both kinds
		}
	bulk.beginInsertion(107.0);
	EvidentialGridStorage oneByOne = bulk;
	const float w = 0.37f;
	const std::uint16_t occupiedBelow = 20000;
	std::vector<std::size_t> loud;
	bulk.fuseQuietFreeRun<false>(0, cells, w, occupiedBelow, loud);
	EvidentialGridStorage alsoSkipping = oneByOne;
	for (std::size_t idx = 0; idx < cells; ++idx)
		if (!alsoSkipping.isLoud(idx, occupiedBelow))
			alsoSkipping.fuseSimpleFree<false, false>(idx, w);
	EXPECT_TRUE(bulk.cells() == alsoSkipping.cells()) << "the bulk as cell by cell";
	// The full arithmetic, cell by cell: the decaying path at rate 0 (a
	// factor of exactly 1) skips no cell.
	for (std::size_t idx = 0; idx < cells; ++idx)
		if (!oneByOne.isLoud(idx, occupiedBelow)) oneByOne.fuseSimpleFree<true, false>(idx, w);
	const auto sameReading = [&](const char* when) {
		for (std::size_t idx = 0; idx < cells; ++idx)
		{
			const Mass a = bulk.read(idx), b = oneByOne.read(idx);
			ASSERT_EQ(a.free, b.free) << when << " cell " << idx;
			ASSERT_EQ(a.occupied, b.occupied) << when << " cell " << idx;
			ASSERT_EQ(a.unknown, b.unknown) << when << " cell " << idx;
			ASSERT_EQ(bulk.event(idx), oneByOne.event(idx));
			ASSERT_EQ(bulk.heldImpact(idx), oneByOne.heldImpact(idx));
			ASSERT_EQ(bulk.flipped(idx), oneByOne.flipped(idx));
		}
	};
	sameReading("now");
	EXPECT_FALSE(bulk.cells() == oneByOne.cells()) << "the saturated cells were skipped";
	bulk.setDecayRate(0.05);
	oneByOne.setDecayRate(0.05);
	bulk.beginInsertion(120.0);
	oneByOne.beginInsertion(120.0);
	sameReading("after a change of rate");
}

TEST(GridStorage, FreeRunsKeepingConflictFuseAsCellByCell)
{
	for (const double rate : {0.0, 0.05})
		for (const std::size_t count : {0, 1, 3, 4, 6, 8, 9, 12, 15, 397})
		{
			const auto grid = [&] {
				EvidentialGridStorage g;
				g.reset(0.0, 4.0, 0.0, 1.0, 0.1, 1000);
				g.setDecayRate(rate);
				std::mt19937 rng(11);
				std::uniform_real_distribution<double> unit(0.0, 1.0);
				for (int scan = 0; scan < 5; ++scan)
				{
					g.beginInsertion(50.0 + 0.9 * scan);
					for (std::size_t idx = 0; idx < g.geometry().cellCount(); ++idx)
					{
						// The last scan writes the first 200 cells: blocks
						// of one decay factor.
						if (!(scan == 4 && idx < 200) && unit(rng) < 0.4) continue;
						// Conflict up to total, so that the cap is met too.
						const double k = unit(rng) < 0.05 ? 1.0 : 0.6 * unit(rng);
						const double f = (1.0 - k) * unit(rng), o = (1.0 - k - f) * unit(rng);
						g.write(idx, Mass{k, f, o, 1.0 - k - f - o});
						if (unit(rng) < 0.2) g.markImpact(idx);
						if (unit(rng) < 0.2) g.markFlipped(idx);
					}
				}
				g.beginInsertion(56.0);
				return g;
			};
			EvidentialGridStorage bulk = grid(), oneByOne = grid();
			const std::size_t first = 3;
			const float w = 0.41f;
			if (rate > 0.0)
				bulk.fuseFreeRunKeepingConflict<true>(first, count, w);
			else
				bulk.fuseFreeRunKeepingConflict<false>(first, count, w);
			for (std::size_t idx = first; idx < first + count; ++idx)
				if (rate > 0.0)
					oneByOne.fuseSimpleFree<true, true>(idx, w);
				else
					oneByOne.fuseSimpleFree<false, true>(idx, w);
			ASSERT_TRUE(bulk.cells() == oneByOne.cells()) << rate << " " << count;
		}
}

// The single-precision fusion of a simple free mass, as the bulk runs it,
// reads as the general rule's fusion to within the stored values' step, for
// each rule and conflict handling the map gives the kernels:
// Dempster's rule, Yager's (which Dubois and Prade's rule and the
// conjunctive rule with its conflict to Omega equal here) and the cautious
// rule, normalized or with its conflict to Omega.
TEST(GridStorage, SimpleFreeFusionReadsAsTheGeneralRule)
{
	struct TCase
	{
		FusionRule rule;
		ConflictHandling handling;
		FreeFusion kernel;
	};
	const ConflictHandling normalize = ConflictHandling::Normalize,
						   toUnknown = ConflictHandling::ToUnknown;
	for (const double rate : {0.0, 0.05})
		for (const TCase& c : std::vector<TCase>{
				 {FusionRule::Dempster, normalize, FreeFusion::Dempster},
				 {FusionRule::Conjunctive, normalize, FreeFusion::Dempster},
				 {FusionRule::Yager, normalize, FreeFusion::Yager},
				 {FusionRule::DuboisPrade, normalize, FreeFusion::Yager},
				 {FusionRule::Conjunctive, toUnknown, FreeFusion::Yager},
				 {FusionRule::Cautious, normalize, FreeFusion::CautiousNormalized},
				 {FusionRule::Cautious, toUnknown, FreeFusion::CautiousToUnknown}})
			for (const float w : {0.05f, 0.37f, 0.7f, 0.99f})
			{
				EvidentialGridStorage simple = gridWithVariedCells(rate, 3);
				EvidentialGridStorage general = gridWithVariedCells(rate, 3);
				const std::size_t cells = simple.geometry().cellCount();
				std::size_t fused = 0;
				for (std::size_t idx = 0; idx < cells; ++idx)
				{
					// The cautious rule's kernels leave cells without
					// ignorance to the general rule.
					if (isCautious(c.kernel) && simple.holdsNoIgnorance(idx)) continue;
					switch (c.kernel)
					{
						case FreeFusion::Dempster:
							simple.fuseSimpleFree<true, false, FreeFusion::Dempster>(idx, w);
							break;
						case FreeFusion::Yager:
							simple.fuseSimpleFree<true, false, FreeFusion::Yager>(idx, w);
							break;
						case FreeFusion::CautiousNormalized:
							simple.fuseSimpleFree<true, false, FreeFusion::CautiousNormalized>(idx, w);
							break;
						case FreeFusion::CautiousToUnknown:
							simple.fuseSimpleFree<true, false, FreeFusion::CautiousToUnknown>(idx, w);
							break;
					}
					general.fuse(idx, Mass::simpleFree(w), c.rule, c.handling);
					++fused;
				}
				EXPECT_GT(fused, cells / 2);
				const std::string what = std::to_string(static_cast<int>(c.rule)) + " " +
					std::to_string(static_cast<int>(c.handling)) + " " + std::to_string(w);
				for (std::size_t idx = 0; idx < cells; ++idx)
				{
					const Mass a = simple.read(idx), b = general.read(idx);
					ASSERT_NEAR(a.free, b.free, 1.5 / kMassScale) << what << " cell " << idx;
					ASSERT_NEAR(a.occupied, b.occupied, 1.5 / kMassScale) << what << " cell " << idx;
					ASSERT_NEAR(a.unknown, b.unknown, 3.0 / kMassScale) << what << " cell " << idx;
					ASSERT_EQ(a.conflict, 0.0);
				}
			}
}
