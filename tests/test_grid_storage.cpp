/* The grid's storage: geometry, growth and lazy decay; state a forged file
 * could hand it; a million fusions at the corners of the algebra and of the
 * decay; the events it keeps. (The cell's fixed point: test_quantized_mass;
 * the bulk kernels: test_free_run_kernel.) */
#include <mrpt_evidential/grid/EvidentialGridStorage.h>
#include <mrpt_evidential/grid/QuantizedMass.h>
#include <mrpt_evidential/algebra/combination.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/test_helpers.h"

using namespace mrpt_evidential;

TEST(GridStorage, GeometryAndBadArguments)
{
	EvidentialGridStorage s;
	s.reset(-1.0, 1.0, 0.0, 0.55, 0.1, 1000);
	EXPECT_EQ(s.geometry().sizeX, 20);
	EXPECT_EQ(s.geometry().sizeY, 6);  // 0.55 m needs 6 cells
	EXPECT_EQ(s.cells().size(), 120u);
	EXPECT_EQ(s.geometry().cellX(-1.0), 0);
	EXPECT_EQ(s.geometry().cellX(0.95), 19);
	EXPECT_NEAR(s.geometry().cellCenterX(0), -0.95, 1e-12);
	for (std::size_t i = 0; i < s.cells().size(); ++i)
		EXPECT_EQ(s.read(i), Mass::vacuous());
	EXPECT_THROW(s.reset(0, 1, 0, 1, 0.0, 1000), std::invalid_argument);
	EXPECT_THROW(s.reset(0, 1, 0, 1, -0.1, 1000), std::invalid_argument);
	EXPECT_THROW(s.reset(1, 1, 0, 1, 0.1, 1000), std::invalid_argument);
	EXPECT_THROW(s.reset(0, 1, 2, 1, 0.1, 1000), std::invalid_argument);
	EXPECT_THROW(
		s.reset(0, std::numeric_limits<double>::quiet_NaN(), 0, 1, 0.1, 1000),
		std::invalid_argument);
	EXPECT_THROW(s.reset(0, 100, 0, 100, 0.1, 1000), std::invalid_argument);
	EXPECT_THROW(s.setDecayRate(-1.0), std::invalid_argument);
	EXPECT_THROW(
		s.beginInsertion(std::numeric_limits<double>::infinity()),
		std::invalid_argument);
}

TEST(GridStorage, GrowthKeepsCellsInPlace)
{
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10'000);
	s.beginInsertion(0.0);
	const Mass m = Mass::simpleOccupied(0.8);
	s.write(s.geometry().index(3, 7), m);  // the cell around (0.35, 0.75)

	EXPECT_TRUE(s.growToInclude(0.2, 0.8, 0.2, 0.8, 1.0, 10'000));  // inside
	EXPECT_EQ(s.geometry().sizeX, 10);

	ASSERT_TRUE(s.growToInclude(-2.05, 0.5, 0.5, 3.0, 1.0, 10'000));
	const GridGeometry& g = s.geometry();
	EXPECT_LE(g.xMin, -3.05);
	EXPECT_GE(g.yMax(), 4.0);
	EXPECT_EQ(g.yMin, 0.0);  // sides that did not need to grow stay
	EXPECT_NEAR(g.xMax(), 1.0, 1e-9);
	const int cx = g.cellX(0.35), cy = g.cellY(0.75);
	EXPECT_MASS_NEAR(s.read(g.index(cx, cy)), m, 2.0 / kMassScale);
	std::size_t nonVacuous = 0;
	for (std::size_t i = 0; i < s.cells().size(); ++i)
		if (s.read(i) != Mass::vacuous()) ++nonVacuous;
	EXPECT_EQ(nonVacuous, 1u);

	// Beyond the budget: refused, nothing changes.
	const GridGeometry before = s.geometry();
	EXPECT_FALSE(s.growToInclude(0, 1000, 0, 1, 1.0, 10'000));
	EXPECT_FALSE(s.growToInclude(
		0, std::numeric_limits<double>::quiet_NaN(), 0, 1, 1.0, 10'000));
	EXPECT_EQ(s.geometry().sizeX, before.sizeX);
	EXPECT_EQ(s.geometry().xMin, before.xMin);
}

TEST(GridStorage, GrowthNearTheBudgetGivesUpTheMarginFirst)
{
	// 10 x 10 cells of 0.1 m in a budget of 200: the box to x = 1.5 m with
	// 1 m of margin would make 25 x 10 cells, with half of it 20 x 10.
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 200);
	s.beginInsertion(0.0);
	ASSERT_TRUE(s.growToInclude(0.0, 1.5, 0.2, 0.8, 1.0, 200));
	const GridGeometry& g = s.geometry();
	EXPECT_GE(g.xMax(), 1.5 - 1e-9);  // the box is held
	EXPECT_LE(g.cellCount(), 200u);
	EXPECT_NEAR(g.xMax(), 2.0, 1e-9);  // with the margin that fits
	EXPECT_EQ(g.sizeY, 10);  // the sides that did not need to grow stay

	// A margin that fits is kept whole.
	EvidentialGridStorage roomy;
	roomy.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10'000);
	ASSERT_TRUE(roomy.growToInclude(0.0, 1.5, 0.2, 0.8, 1.0, 10'000));
	EXPECT_NEAR(roomy.geometry().xMax(), 2.5, 1e-9);

	// Without any margin still too large: refused, nothing changes.
	EXPECT_FALSE(s.growToInclude(0.0, 2.5, 0.2, 0.8, 1.0, 200));
	EXPECT_EQ(s.geometry().sizeX, 20);
	EXPECT_NEAR(s.geometry().xMax(), 2.0, 1e-9);
}

TEST(GridStorage, GrowthAlongAPathMovesTheCellsAFewTimesOnly)
{
	// A grid that grows 0.5 m at a time, 400 times to the east and now and
	// then south, as a robot's path makes it grow: each cell keeps its
	// coordinates and mass, new cells are vacuous, and the cells move to a
	// new block a few times, not at each growth.
	EvidentialGridStorage s;
	constexpr std::size_t kBudget = 2'000'000;
	s.reset(0.0, 2.0, 0.0, 2.0, 0.05, kBudget);
	s.beginInsertion(0.0);
	std::vector<std::pair<double, double>> written;
	int moves = 0;
	for (int step = 0; step < 400; ++step)
	{
		const double x = 0.5 * step + 0.01, y = -0.02 * step;
		const QuantizedCell* before = s.cells().data();
		ASSERT_TRUE(s.growToInclude(x, x + 2.0, y, y + 2.0, 0.0, kBudget)) << step;
		moves += s.cells().data() != before;
		const GridGeometry& g = s.geometry();
		ASSERT_LE(g.cellCount(), kBudget);
		ASSERT_LE(s.cells().size(), kBudget);
		if (step % 7 == 0)
		{
			// Off the cells' edges, where rounding may pick either cell.
			s.write(g.index(g.cellX(x + 1.0), g.cellY(y + 1.013)), Mass::simpleOccupied(0.6));
			written.emplace_back(x + 1.0, y + 1.013);
		}
	}
	EXPECT_LE(moves, 20);
	const GridGeometry& g = s.geometry();
	EXPECT_TRUE(g.firstIndex > 0 || g.stride() > static_cast<std::size_t>(g.sizeX));  // room kept
	std::size_t informed = 0;
	g.forEachIndex([&](std::size_t i) { informed += s.read(i) != Mass::vacuous(); });
	EXPECT_EQ(informed, written.size());
	for (const auto& [x, y] : written)
		EXPECT_MASS_NEAR(
			s.read(g.index(g.cellX(x), g.cellY(y))), Mass::simpleOccupied(0.6), 2.0 / kMassScale)
			<< x << " " << y;
	// Packed, the cells are those of a grid that holds them row by row.
	const std::vector<QuantizedCell> packed = s.packedCells();
	ASSERT_EQ(packed.size(), g.cellCount());
	for (int cy = 0; cy < g.sizeY; cy += 13)
		for (int cx = 0; cx < g.sizeX; cx += 11)
			ASSERT_EQ(packed[g.packed().index(cx, cy)], s.cells()[g.index(cx, cy)]);
}

TEST(GridStorage, GrowthRoomStaysWithinTheBudget)
{
	// Near the budget the block gets less room, as much as fits: every cell
	// still fits, and the next growth into the room moves nothing.
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 150);
	ASSERT_TRUE(s.growToInclude(0.0, 1.4, 0.0, 1.0, 0.0, 150));
	EXPECT_EQ(s.geometry().cellCount(), 140u);
	EXPECT_EQ(s.cells().size(), 150u);
	const std::size_t layout = s.layout();
	ASSERT_TRUE(s.growToInclude(0.0, 1.5, 0.0, 1.0, 0.0, 150));
	EXPECT_EQ(s.layout(), layout) << "grown into the room";
	EXPECT_FALSE(s.growToInclude(0.0, 1.6, 0.0, 1.0, 0.0, 150));
	// A budget that leaves no room at all: a block of the grid's size.
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 140);
	ASSERT_TRUE(s.growToInclude(0.0, 1.4, 0.0, 1.0, 0.0, 140));
	EXPECT_EQ(s.cells().size(), 140u);
}

TEST(GridStorage, APathThatTurnsBackFindsRoom)
{
	// Outgrown eastwards, the block keeps room beyond the other sides too: a
	// run that turns back west (or north, or south) grows into it without
	// a copy of its cells, each of which writes fresh memory.
	EvidentialGridStorage s;
	s.reset(0.0, 10.0, 0.0, 10.0, 0.1, 100'000'000);
	ASSERT_TRUE(s.growToInclude(0.0, 20.0, 0.0, 10.0, 0.0, 100'000'000));
	const std::size_t layout = s.layout();
	ASSERT_TRUE(s.growToInclude(-15.0, 20.0, 0.0, 10.0, 0.0, 100'000'000));
	ASSERT_TRUE(s.growToInclude(-15.0, 20.0, -4.0, 14.0, 0.0, 100'000'000));
	EXPECT_EQ(s.layout(), layout) << "grown into the room kept beyond the other sides";
	// Near the budget the other sides' room goes first: the growing side
	// keeps as much as before.
	EvidentialGridStorage tight;
	tight.reset(0.0, 10.0, 0.0, 10.0, 0.1, 100'000);
	ASSERT_TRUE(tight.growToInclude(0.0, 20.0, 0.0, 10.0, 0.0, 100'000));
	EXPECT_EQ(tight.geometry().firstIndex, 0u) << "no room west";
	EXPECT_EQ(tight.cells().size(), 100'000u) << "room east up to the budget";
}

TEST(GridStorage, PackedNumbersNameTheCellsOfAGrownGrid)
{
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10000);
	ASSERT_TRUE(s.growToInclude(-0.3, 1.4, -0.2, 1.0, 0.0, 10000));
	s.beginInsertion(1.0);
	const GridGeometry& g = s.geometry();
	for (int cy = 0; cy < g.sizeY; ++cy)
		for (int cx = 0; cx < g.sizeX; ++cx)
			s.write(g.index(cx, cy), Mass::simpleFree(0.001 * (cx + 20 * cy)));
	ASSERT_NE(g.stride(), static_cast<std::size_t>(g.sizeX)) << "room between rows";
	const std::vector<QuantizedCell> packed = s.packedCells();
	for (std::size_t i = 0; i < packed.size(); ++i)
		ASSERT_TRUE(s.cells()[g.indexOfPacked(i)] == packed[i]) << i;
}

TEST(GridStorage, LayoutChangesWhenTheCellsMove)
{
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10000);
	const std::size_t first = s.layout();
	ASSERT_TRUE(s.growToInclude(0.0, 1.4, 0.0, 1.0, 0.0, 10000));
	const std::size_t grown = s.layout();
	EXPECT_NE(grown, first) << "outgrown: a new block";
	ASSERT_TRUE(s.growToInclude(0.0, 1.6, 0.0, 1.0, 0.0, 10000));
	EXPECT_EQ(s.layout(), grown) << "into the room kept";
	const EvidentialGridStorage copy = s;
	EXPECT_EQ(copy.layout(), grown) << "the same cells at the same indices";
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10000);
	EXPECT_NE(s.layout(), grown);
	EXPECT_NE(s.layout(), first) << "no grid had it before";
	const std::size_t afterReset = s.layout();
	s.assign(copy.geometry(), copy.packedCells(), copy.stampTimes(), 0, 0.0, true);
	EXPECT_NE(s.layout(), afterReset);
	EXPECT_NE(s.layout(), grown);
}

TEST(GridStorage, GrowthIntoANewBlockSaysWhereEachCellWent)
{
	EvidentialGridStorage s;
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10000);
	EXPECT_EQ(s.grownFromLayout(), 0u) << "no growth yet";
	const std::size_t first = s.layout();
	const GridGeometry before = s.geometry();
	ASSERT_TRUE(s.growToInclude(-0.35, 1.0, -0.2, 1.25, 0.0, 10000));
	ASSERT_NE(s.layout(), first) << "a new block";
	EXPECT_EQ(s.grownFromLayout(), first);
	const GridGeometry& now = s.geometry();
	for (const auto& [cx, cy] : {std::pair{0, 0}, std::pair{9, 0}, std::pair{4, 7}, std::pair{9, 9}})
	{
		const std::size_t moved = s.indexAfterGrowth(before.index(cx, cy));
		EXPECT_DOUBLE_EQ(now.cellCenterX(now.columnOf(moved)), before.cellCenterX(cx));
		EXPECT_DOUBLE_EQ(now.cellCenterY(now.rowOf(moved)), before.cellCenterY(cy));
	}
	const std::size_t grown = s.layout();
	ASSERT_TRUE(s.growToInclude(-0.35, 1.1, -0.2, 1.25, 0.0, 10000));
	EXPECT_EQ(s.layout(), grown) << "into the room kept";
	EXPECT_EQ(s.grownFromLayout(), first) << "still the latest growth into a block";
	s.reset(0.0, 1.0, 0.0, 1.0, 0.1, 10000);
	EXPECT_EQ(s.grownFromLayout(), 0u) << "a reset is no growth";
}

TEST(GridStorage, DecayFollowsTheExponentialLaw)
{
	EvidentialGridStorage s;
	s.reset(0, 1, 0, 1, 0.5, 100);
	const double rate = 0.2;
	s.setDecayRate(rate);
	const Mass m{0.1, 0.5, 0.3, 0.1};
	s.beginInsertion(100.0);
	s.write(0, m);
	EXPECT_MASS_NEAR(s.read(0), m, 2.0 / kMassScale);
	for (const double t : {100.5, 101.0, 103.0, 110.0, 150.0})
	{
		s.beginInsertion(t);
		const Mass expected = discount(m, 1.0 - std::exp(-rate * (t - 100.0)));
		EXPECT_MASS_NEAR(s.read(0), expected, 2.0 / kMassScale) << "t " << t;
		EXPECT_EQ(s.read(1), Mass::vacuous());
	}
	// Back in time: nothing un-decays.
	const Mass at150 = s.read(0);
	s.beginInsertion(120.0);
	EXPECT_EQ(s.read(0), at150);
	EXPECT_EQ(s.latestTime(), 150.0);
}

TEST(GridStorage, ChangingTheRateKeepsPastDecay)
{
	EvidentialGridStorage s;
	s.reset(0, 1, 0, 1, 0.5, 100);
	s.setDecayRate(0.1);
	s.beginInsertion(0.0);
	const Mass m = Mass::simpleFree(0.9);
	s.write(0, m);
	s.beginInsertion(5.0);
	s.setDecayRate(0.5);
	s.beginInsertion(7.0);
	const double keep = std::exp(-0.1 * 5.0) * std::exp(-0.5 * 2.0);
	EXPECT_MASS_NEAR(s.read(0), discount(m, 1.0 - keep), 3.0 / kMassScale);
}

TEST(GridStorage, StampsRebaseWithoutChangingMasses)
{
	// More insertion times than stamps, and a decay exponent past the rebase
	// threshold: reads must follow the law throughout.
	EvidentialGridStorage s;
	s.reset(0, 2, 0, 1, 1.0, 100);
	const double rate = 0.002;
	s.setDecayRate(rate);
	s.beginInsertion(0.0);
	const Mass m = Mass::simpleOccupied(1.0);
	s.write(0, m);
	s.markImpact(0);
	s.markFlipped(0);
	const std::size_t n = EvidentialGridStorage::kMaxStamps + 5000;
	for (std::size_t i = 1; i <= n; ++i)
	{
		s.beginInsertion(static_cast<double>(i));
		s.write(1, Mass::simpleFree(0.5));  // a cell written every time
	}
	const double keep = std::exp(-rate * static_cast<double>(n));
	// Each rebase re-stores the cell: a few quantization steps at most.
	EXPECT_NEAR(s.read(0).occupied, keep, 4.0 / kMassScale);
	EXPECT_MASS_NEAR(s.read(1), Mass::simpleFree(0.5), 2.0 / kMassScale);
	EXPECT_EQ(s.insertionCount(), n + 1);
	EXPECT_LT(s.stampTimes().size(), EvidentialGridStorage::kMaxStamps);
	// The cell's flags outlive the rebases.
	EXPECT_TRUE(s.heldImpact(0));
	EXPECT_TRUE(s.flipped(0));
	EXPECT_FALSE(s.heldImpact(1) || s.flipped(1));
}

TEST(GridStorage, AssignRejectsInconsistentState)
{
	EvidentialGridStorage s;
	GridGeometry g{0.0, 0.0, 0.1, 2, 2};
	std::vector<QuantizedCell> cells(4);
	EXPECT_NO_THROW(s.assign(g, cells, {0.0, 1.0}, 2, 0.1, true));
	EXPECT_EQ(s.geometry().sizeX, 2);
	EXPECT_THROW(s.assign(g, std::vector<QuantizedCell>(3), {0.0}, 1, 0.0, true), std::invalid_argument);
	EXPECT_THROW(s.assign(g, cells, {}, 1, 0.0, true), std::invalid_argument);
	EXPECT_THROW(s.assign(g, cells, {1.0, 0.0}, 1, 0.0, true), std::invalid_argument);
	EXPECT_THROW(s.assign(g, cells, {0.0}, 1, -1.0, true), std::invalid_argument);
	cells[1].free = 40000;
	cells[1].occupied = 40000;
	EXPECT_THROW(s.assign(g, cells, {0.0}, 1, 0.0, true), std::invalid_argument);
	cells[1] = QuantizedCell{};
	cells[2].stamp = 5;
	EXPECT_THROW(s.assign(g, cells, {0.0}, 1, 0.0, true), std::invalid_argument);
}

TEST(BadFile, InconsistentStorageIsRejected)
{
	EvidentialGridStorage s;
	// Geometries beyond the limits (found by fuzz_deserialize: 4 cells of
	// 5.6e243 m made the insertion's squared reach infinite).
	for (const GridGeometry& g :
		 {GridGeometry{1e308, 0.0, 1e308, 2, 2}, GridGeometry{-2.2e43, -1.0, 5.6e243, 2, 2},
		  GridGeometry{0.0, 0.0, 1e-9, 2, 2}, GridGeometry{9.9e8, 0.0, 1e7, 2, 2}})
		EXPECT_THROW(
			s.assign(g, std::vector<QuantizedCell>(4), {0.0}, 0, 0.0, true),
			std::invalid_argument)
			<< g.xMin << " " << g.resolution;
	// A file may hold several insertion times only once something was
	// inserted: the first insertion would start the times again and leave
	// the cells stamped beyond them.
	std::vector<QuantizedCell> cells(4);
	cells[3].stamp = 2;
	cells[3].free = 30000;
	EXPECT_THROW(
		s.assign({0.0, 0.0, 1.0, 2, 2}, cells, {1.0, 2.0, 3.0}, 0, 0.5, true),
		std::invalid_argument);
	EXPECT_NO_THROW(s.assign({0.0, 0.0, 1.0, 2, 2}, cells, {1.0, 2.0, 3.0}, 3, 0.5, true));
	s.beginInsertion(10.0);
	EXPECT_TRUE(s.read(3).isValid(1e-9));
}

// ---------------------------------------------------------------------------
// Numbers: a million fusions through the cells, every rule, every conflict
// handling, total conflict, and decay from none to absurd rates and steps.
// ---------------------------------------------------------------------------

TEST(Numbers, MillionFusionsThroughTheCellsStayValid)
{
	const std::vector<double> rates = {0.0, 1e-300, 1e-9, 0.7, 1e3, 1e9, 1e300};
	// Time steps: none, tiny, usual, huge, backwards, and 400 years.
	const std::vector<double> steps = {0.0, 1e-9, 0.05, 1.0, 1e4, -3.0, 1.3e10};
	const std::vector<Mass> corners = {
		Mass::vacuous(), Mass::degenerate(), {0, 1, 0, 0}, {0, 0, 1, 0},
		{0, 0.5, 0.5, 0}, Mass::simpleFree(1e-300), {1e-300, 0, 0, 1 - 1e-300}};
	const FusionRule rules[] = {
		FusionRule::Conjunctive, FusionRule::Dempster, FusionRule::Yager,
		FusionRule::DuboisPrade, FusionRule::Cautious};
	const ConflictHandling handlings[] = {
		ConflictHandling::Keep, ConflictHandling::ToUnknown,
		ConflictHandling::Normalize};
	const auto handle = [](Mass m, ConflictHandling h) {
		if (h == ConflictHandling::ToUnknown)
			m = {0.0, m.free, m.occupied, m.unknown + m.conflict};
		else if (h == ConflictHandling::Normalize)
		{
			const double k = m.free + m.occupied + m.unknown;
			m = k > kTotalConflictTolerance
				? Mass{0.0, m.free / k, m.occupied / k, m.unknown / k}
				: Mass::vacuous();
		}
		return m;
	};

	test::MassGenerator gen(1234);
	std::uniform_int_distribution<std::size_t> pick(0, 1 << 20);
	constexpr std::size_t kCells = 64, kPerInsertion = 32;
	const std::size_t configs = rates.size() * 5 * 3;
	const std::size_t insertions = 1'000'000 / (configs * kPerInsertion) + 1;
	std::size_t fusions = 0;
	for (const double rate : rates)
		for (const FusionRule rule : rules)
			for (const ConflictHandling handling : handlings)
			{
				EvidentialGridStorage s;
				s.reset(0, 8, 0, 8, 1.0, kCells);
				s.setDecayRate(rate);
				double t = 0.0;
				for (std::size_t k = 0; k < insertions; ++k)
				{
					t += steps[pick(gen.rng()) % steps.size()];
					s.beginInsertion(t);
					for (std::size_t j = 0; j < kPerInsertion; ++j, ++fusions)
					{
						const std::size_t idx = pick(gen.rng()) % kCells;
						const Mass obs = pick(gen.rng()) % 3 == 0
							? corners[pick(gen.rng()) % corners.size()]
							: gen();
						const Mass old = s.read(idx);
						ASSERT_TRUE(old.isValid(1e-9))
							<< "rate " << rate << " t " << t << ": " << old;
						const Mass fused = handle(combine(rule, old, obs), handling);
						ASSERT_TRUE(fused.isValid(1e-9)) << fused;
						s.write(idx, fused);
					}
				}
				for (std::size_t i = 0; i < kCells; ++i)
					ASSERT_TRUE(s.read(i).isValid(1e-9))
						<< "rate " << rate << ": " << s.read(i);
			}
	EXPECT_GE(fusions, 1'000'000u);
}

TEST(GridStorageEvents, RebaseKeepsRecentEventsAndDropsOldOnes)
{
	EvidentialGridStorage s;
	s.reset(0, 2, 0, 1, 1.0, 2);
	s.setKeepsConflict(false);
	s.setEventRetention(5.0);
	s.beginInsertion(0.0);
	s.setEvent(0, CellEvent::Disappeared);  // at 0 s
	s.beginInsertion(1.0);
	double t = 1.0;
	// Fill the table of times until it is rebased; cell 1's event is kept
	// fresh, 2 s before each insertion.
	std::size_t rebases = 0, previous = s.stampTimes().size();
	while (rebases < 2)
	{
		t += 1.0;
		s.beginInsertion(t);
		if (s.stampTimes().size() < previous) ++rebases;
		previous = s.stampTimes().size();
		if (s.eventTime(1) < t - 2.0 || s.event(1) == CellEvent::None) s.setEvent(1, CellEvent::Appeared);
	}
	EXPECT_LT(s.stampTimes().size(), EvidentialGridStorage::kMaxStamps);
	EXPECT_EQ(s.event(0), CellEvent::None) << "older than the retention";
	EXPECT_EQ(s.event(1), CellEvent::Appeared);
	EXPECT_GE(s.eventTime(1), t - 2.0);
	EXPECT_LE(s.eventTime(1), t);
}

TEST(GridStorageEvents, ChangingWhatCellsKeepClearsTheWordAside)
{
	EvidentialGridStorage s;
	s.reset(0, 1, 0, 1, 1.0, 1);
	s.beginInsertion(1.0);
	s.write(0, {0.5, 0.2, 0.3, 0.0});  // keeps conflict: the default
	EXPECT_NEAR(s.read(0).conflict, 0.5, 1e-4);
	s.setKeepsConflict(false);
	EXPECT_EQ(s.read(0).conflict, 0.0);
	EXPECT_NEAR(s.read(0).occupied, 0.6, 1e-4) << "the normal part stays";
	EXPECT_EQ(s.event(0), CellEvent::None);
	s.setEvent(0, CellEvent::Appeared);
	s.setKeepsConflict(true);
	EXPECT_EQ(s.read(0).conflict, 0.0);
	EXPECT_EQ(s.event(0), CellEvent::None) << "a grid with conflict has no events";
}

TEST(GridStorageEvents, AssignChecksEventsAndStampBits)
{
	EvidentialGridStorage s;
	const GridGeometry g{0.0, 0.0, 1.0, 1, 1};
	QuantizedCell c;
	c.aside = packEvent(CellEvent::Appeared, 1);
	EXPECT_NO_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false));
	EXPECT_EQ(s.event(0), CellEvent::Appeared);
	EXPECT_EQ(s.eventTime(0), 1.0);
	c.aside = packEvent(CellEvent::Appeared, 2);  // no such time
	EXPECT_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false), std::invalid_argument);
	c.aside = 0;
	c.stamp = kHeldImpact | 1;
	EXPECT_NO_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false));
	EXPECT_TRUE(s.heldImpact(0));
	EXPECT_FALSE(s.flipped(0));
	c.stamp = kFlipped | 1;
	EXPECT_NO_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false));
	EXPECT_TRUE(s.flipped(0));
	EXPECT_FALSE(s.heldImpact(0));
	c.stamp = kStampFlags | 2;  // no such time, whatever the flags
	EXPECT_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false), std::invalid_argument);
	// A cell of a grid without conflict above the ceiling is refused.
	c.stamp = 0;
	c.occupied = static_cast<std::uint16_t>(kMassScale);
	EXPECT_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, false), std::invalid_argument);
	EXPECT_NO_THROW(s.assign(g, {c}, {0.0, 1.0}, 2, 0.0, true));
}
