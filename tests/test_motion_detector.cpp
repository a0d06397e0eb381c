/* The motion layer's decisions on hand-made fusions (src/insert/): arrivals
 * beside static structure wait for a hit at the next insertions, and a cell
 * that flips between hit and free does not become an arrival. */
#include <gtest/gtest.h>
#include "insert/MotionDetector.h"

#include <functional>

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
	/** One insertion at data time t, whose fusions `fusions` makes. */
	void insertion(double t, const std::function<void()>& fusions)
	{
		grid.beginInsertion(t);
		detector.begin(rules);
		fusions();
		detector.settle(grid);
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
