/* The motion layer's decisions on hand-made fusions (src/insert/): arrivals
 * beside static structure wait for a hit at the next insertions, and a cell
 * that flips between hit and free does not become an arrival, a scan whose
 * impacts mostly land on free cells (a misplaced one) settles nothing, and
 * the list of recent arrivals outlives growth that moves no cell. */
#include <gtest/gtest.h>
#include "insert/MotionDetector.h"

#include <algorithm>
#include <functional>
#include <vector>

using namespace mrpt_evidential;

namespace
{
/** A 1 x 1 m grid without conflict, 5 cm cells, with a wall cell that beams
 * ended in for a while and a floor cell two cells from it, seen free. */
class DetectorOnAGrid : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
		wall = grid.geometry().index(10, 12);
		floor = grid.geometry().index(10, 10);
		grid.setKeepsConflict(false);
		grid.setEventRetention(10.0);
		for (int k = 0; k < 5; ++k)
			insertion(0.1 * k, [&] {
				fuse(wall, Mass::simpleOccupied(0.9), true);
				fuse(floor, Mass::simpleFree(0.7), false);
			});
	}
	/** One insertion at data time t, whose fusions `fusions` makes, as the
	 * map makes it: the recent arrivals that its beams cross in their free
	 * margins (crossedInMargin) judged first. */
	void insertion(double t, const std::function<void()>& fusions)
	{
		grid.beginInsertion(t);
		detector.begin(rules);
		detector.judgeArrivalsInMargins(grid, crossedInMargin);
		fusions();
		detector.settle(grid, impactCells);
	}
	void fuse(std::size_t idx, const Mass& observed, bool impact)
	{
		const ConflictSplit split = grid.fuseNormalized(idx, observed);
		if (impact) grid.markImpact(idx);
		detector.afterFusion(grid, idx, split, observed, impact);
	}
	/** A beam's end in the floor cell: little occupied mass, so that the
	 * cell still leans free after a few of them (as in cells a thing or a
	 * wall covers in part), but conflict enough for an event. */
	void weakHit() { fuse(floor, Mass::simpleOccupied(0.55), true); }
	void freeSight() { fuse(floor, Mass::simpleFree(0.7), false); }

	EvidentialGridStorage grid;
	CMotionDetector detector;
	const TMotionRules rules{0.5, 2, 2.0};
	std::size_t wall = 0, floor = 0;
	/** Cells the beams of each insertion ended in, for settle(). */
	std::size_t impactCells = 100;
	std::function<bool(std::size_t)> crossedInMargin = [](std::size_t) { return false; };
};
}  // namespace

TEST_F(DetectorOnAGrid, ArrivalBesideStructureIsConfirmedByTheNextHit)
{
	insertion(1.0, [&] { weakHit(); });
	EXPECT_EQ(grid.event(floor), CellEvent::Leaving) << "pending beside the wall";
	insertion(1.1, [&] { weakHit(); });
	EXPECT_EQ(grid.event(floor), CellEvent::Appeared);
	EXPECT_DOUBLE_EQ(grid.eventTime(floor), 1.0) << "dated from the first hit";
}

TEST_F(DetectorOnAGrid, PendingArrivalHitAgainOnlyMuchLaterStaysPending)
{
	insertion(1.0, [&] { weakHit(); });
	for (int k = 1; k <= 5; ++k) insertion(1.0 + 0.1 * k, [] {});  // the cell unseen
	insertion(1.6, [&] { weakHit(); });
	EXPECT_EQ(grid.event(floor), CellEvent::Leaving);
}

TEST_F(DetectorOnAGrid, CellThatFlipsBetweenHitAndFreeIsNoArrival)
{
	// Hit, free, then hit twice in a row: what pose error does to a cell in
	// front of a wall's face. Its second pending arrival dates from the
	// turn-down, too old for the next hit to confirm.
	insertion(1.0, [&] { weakHit(); });
	insertion(1.1, [&] { freeSight(); });
	EXPECT_EQ(grid.event(floor), CellEvent::None) << "turned down";
	for (int k = 2; k <= 4; ++k) insertion(1.0 + 0.1 * k, [] {});
	insertion(1.5, [&] { weakHit(); });
	insertion(1.6, [&] { weakHit(); });
	EXPECT_NE(grid.event(floor), CellEvent::Appeared);

	// Long after the turn-down (kFlipMemory insertions) the cell is a
	// floor cell like any other again.
	for (int k = 0; k < 45; ++k) insertion(2.0 + 0.1 * k, [&] { freeSight(); });
	insertion(7.0, [&] { weakHit(); });
	insertion(7.1, [&] { weakHit(); });
	EXPECT_EQ(grid.event(floor), CellEvent::Appeared);
}

TEST_F(DetectorOnAGrid, ScanWhoseImpactsMostlyLandOnFreeCellsSettlesNothing)
{
	// A strip of floor far from the wall, seen free.
	std::vector<std::size_t> strip;
	for (int cx = 0; cx < 20; ++cx) strip.push_back(grid.geometry().index(cx, 3));
	for (int k = 0; k < 3; ++k)
		insertion(0.6 + 0.1 * k, [&] {
			for (const std::size_t idx : strip) fuse(idx, Mass::simpleFree(0.7), false);
		});
	const auto hitStrip = [&](std::size_t hits) {
		for (std::size_t k = 0; k < hits; ++k) fuse(strip[k], Mass::simpleOccupied(0.9), true);
	};
	const auto arrivals = [&] {
		return std::count_if(strip.begin(), strip.end(), [&](std::size_t idx) {
			return grid.event(idx) == CellEvent::Appeared;
		});
	};
	// Ten of a scan's twenty impact cells on free floor: the scan's pose is
	// off, not the world.
	impactCells = 20;
	insertion(1.0, [&] { hitStrip(10); });
	EXPECT_EQ(arrivals(), 0);
	EXPECT_EQ(grid.event(strip[0]), CellEvent::None);
	// The same hits in a scan of a hundred impact cells: something arrived.
	for (int k = 0; k < 3; ++k)
		insertion(1.1 + 0.1 * k, [&] {
			for (const std::size_t idx : strip) fuse(idx, Mass::simpleFree(0.9), false);
		});
	impactCells = 100;
	insertion(1.5, [&] { hitStrip(10); });
	EXPECT_EQ(arrivals(), 10);
	// Too few arrivals to tell (a person in a scan that sees little else).
	for (int k = 0; k < 3; ++k)
		insertion(1.6 + 0.1 * k, [&] {
			for (const std::size_t idx : strip) fuse(idx, Mass::simpleFree(0.9), false);
		});
	ASSERT_EQ(arrivals(), 0);
	impactCells = CMotionDetector::kMisplacedArrivals - 1;
	insertion(2.0, [&] { hitStrip(impactCells); });
	EXPECT_EQ(arrivals(), static_cast<long>(CMotionDetector::kMisplacedArrivals - 1));
}

TEST_F(DetectorOnAGrid, ArrivalsStayListedWhileTheGridGrowsIntoItsRoom)
{
	// Outgrowing its block moves the cells; the room the grid then keeps
	// beyond the side that grew takes later growth without moving any.
	ASSERT_TRUE(grid.growToInclude(0.0, 1.2, 0.0, 1.0, 0.0, 100000));
	const std::size_t layout = grid.layout();
	const std::size_t cell = grid.geometry().index(3, 3);  // away from the wall
	for (int k = 0; k < 3; ++k)
		insertion(0.6 + 0.1 * k, [&] { fuse(cell, Mass::simpleFree(0.9), false); });
	insertion(1.0, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
	ASSERT_EQ(grid.event(cell), CellEvent::Appeared);

	ASSERT_TRUE(grid.growToInclude(0.0, 1.3, 0.0, 1.0, 0.0, 100000));
	ASSERT_EQ(grid.layout(), layout) << "grown into its room";
	ASSERT_EQ(grid.geometry().index(3, 3), cell);
	// A beam crosses the arrival within its free margin (no free evidence
	// for the cell): it left all the same.
	crossedInMargin = [&](std::size_t idx) { return idx == cell; };
	insertion(1.1, [] {});
	EXPECT_EQ(grid.event(cell), CellEvent::Disappeared);
}
