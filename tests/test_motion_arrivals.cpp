/* The motion layer's arrivals on hand-made fusions (src/insert/): arrivals
 * beside static structure (the inside of a wall included, and the spread in
 * front of a face next to them; not what the map saw free two cells away)
 * wait for a hit at the next insertions, beside a thing seen arriving in
 * the open whose face reaches them (at once when its face reached them at an
 * earlier insertion), and stay when hit again; the reach to a face, and to
 * cells never seen free, grows with the range; a thing that arrived long ago
 * is no structure, a cell that flips between hit and free does not become an
 * arrival (then or later), nor does a hit beside cells never seen free at
 * once; a scan whose impacts mostly land on free cells (a misplaced one)
 * settles nothing, and the list of recent arrivals outlives growth that
 * moves no cell. */
#include "motion_detector_fixture.h"

using namespace mrpt_evidential;
using motion_test::DetectorOnAGrid;

TEST_F(DetectorOnAGrid, ArrivalBesideStructureIsConfirmedByTheNextHit)
{
	insertion(1.0, [&] {
		weakHit();
		thingInTheOpen();
	});
	EXPECT_EQ(grid.event(floor), CellEvent::Leaving) << "pending beside the wall";
	insertion(1.1, [&] {
		weakHit();
		thingInTheOpen();
	});
	EXPECT_EQ(grid.event(floor), CellEvent::Appeared);
	EXPECT_DOUBLE_EQ(grid.eventTime(floor), 1.0) << "dated from the first hit";
}

TEST_F(DetectorOnAGrid, ArrivalBesideStructureApartFromAThingInTheOpenStaysPending)
{
	// Hits that stay within the wall's clearance, as pose error moves a
	// face by a cell (no thing that moves is that thin), while a thing
	// arrives in the open farther than thingCells (row 4), or within it but
	// with no arrival within faceGapCells of the floor cell (row 6: a person
	// who walks through a door beside the wall's end that the pose's error
	// flips): the floor cell is not confirmed.
	for (const int row : {4, 6})
	{
		SCOPED_TRACE(testing::Message() << "the thing in row " << row);
		SetUp();
		const std::size_t thing = grid.geometry().index(10, row);
		for (const double t : {1.0, 1.1})
			insertion(t, [&] {
				weakHit();
				fuse(thing, Mass::simpleOccupied(0.9), true);
			});
		EXPECT_EQ(grid.event(thing), CellEvent::Appeared);
		EXPECT_EQ(grid.event(floor), CellEvent::Leaving);
	}
}

TEST_F(DetectorOnAGrid, FirstHitBesideStructureExtendingAnEarlierArrivalIsAnArrivalAtOnce)
{
	// A thing seen arriving in the open at 1.0 s, its face reaching two
	// cells from the floor cell; at 1.1 s its face grows to the floor cell,
	// beside the wall: an arrival at once, not pending.
	insertion(1.0, [&] { thingInTheOpen(); });
	ASSERT_EQ(grid.event(grid.geometry().index(10, 8)), CellEvent::Appeared);
	insertion(1.1, [&] {
		weakHit();
		thingInTheOpen();
	});
	EXPECT_EQ(grid.event(floor), CellEvent::Appeared);
	EXPECT_DOUBLE_EQ(grid.eventTime(floor), 1.1);
	// With the thing arriving in the same scan, the same first hit is
	// pending (ArrivalBesideStructureIsConfirmedByTheNextHit).
}

TEST_F(DetectorOnAGrid, ArrivalBesideStructureHitAgainStaysAnArrival)
{
	for (const double t : {1.0, 1.1})
		insertion(t, [&] {
			weakHit();
			thingInTheOpen();
		});
	ASSERT_EQ(grid.event(floor), CellEvent::Appeared);
	// The third hit still conflicts with the free evidence the cell keeps:
	// the thing is still there, its arrival stays, with its time.
	insertion(1.2, [&] { weakHit(); });
	EXPECT_EQ(grid.event(floor), CellEvent::Appeared);
	EXPECT_DOUBLE_EQ(grid.eventTime(floor), 1.0);
}

TEST_F(DetectorOnAGrid, NewFaceIsNoStructureToItself)
{
	// A thing's face hit for the first time, in the open, on floor seen
	// free once: each cell leans occupied after its hit, and the next one,
	// settled after it, is no pose error beside structure.
	const GridGeometry& g = grid.geometry();
	insertion(1.0, [&] {
		for (const int x : {2, 3, 4}) fuse(g.index(x, 3), Mass::simpleOccupied(0.9), true);
	});
	for (const int x : {2, 3, 4})
	{
		ASSERT_TRUE(leansOccupied(grid.read(g.index(x, 3))));
		EXPECT_EQ(grid.event(g.index(x, 3)), CellEvent::Appeared) << "column " << x;
	}
}

TEST_F(DetectorOnAGrid, HitBesideCellsNeverSeenFreeIsNoArrivalAtOnce)
{
	// A block's corner seen for the first time: the beams crossed the free
	// part of its cell (seen free twice here), the cells behind it were
	// never seen free. Away from any structure a hit would be an arrival.
	grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
	const std::size_t corner = grid.geometry().index(5, 5);
	for (int k = 0; k < 2; ++k)
		insertion(0.1 * k, [&] { fuse(corner, Mass::simpleFree(0.9), false); });
	insertion(0.2, [&] { fuse(corner, Mass::simpleOccupied(0.9), true); });
	EXPECT_EQ(grid.event(corner), CellEvent::Leaving) << "pending";
	// Its neighbours seen free too: the same hit is an arrival.
	const std::size_t open = grid.geometry().index(15, 15);
	for (int k = 0; k < 2; ++k)
		insertion(0.3 + 0.1 * k, [&] {
			for (int y = 14; y <= 16; ++y)
				for (int x = 14; x <= 16; ++x)
					fuse(grid.geometry().index(x, y), Mass::simpleFree(0.9), false);
		});
	insertion(0.5, [&] { fuse(open, Mass::simpleOccupied(0.9), true); });
	EXPECT_EQ(grid.event(open), CellEvent::Appeared);
}

TEST_F(DetectorOnAGrid, InsideOfAWallIsStructure)
{
	// The inside of a wall: never seen free, occupied by the imprecision's
	// spread of the beams that end at its face, never an impact itself. A
	// hit two cells from it is pending, as beside any structure.
	grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
	const GridGeometry& g = grid.geometry();
	const std::size_t inside = g.index(5, 5), cell = g.index(7, 5), open = g.index(15, 15);
	for (int k = 0; k < 2; ++k)
		insertion(0.1 * k, [&] {
			for (const int dy : {-1, 0, 1})
				for (const int dx : {-1, 0, 1})
				{
					fuse(g.index(7 + dx, 5 + dy), Mass::simpleFree(0.9), false);
					fuse(g.index(15 + dx, 15 + dy), Mass::simpleFree(0.9), false);
				}
			fuse(inside, Mass::simpleOccupied(0.9), false);
		});
	ASSERT_TRUE(leansOccupied(grid.read(inside)));
	ASSERT_FALSE(grid.heldImpact(inside));
	insertion(0.2, [&] {
		fuse(cell, Mass::simpleOccupied(0.9), true);
		fuse(open, Mass::simpleOccupied(0.9), true);
	});
	EXPECT_EQ(grid.event(cell), CellEvent::Leaving) << "pending";
	EXPECT_EQ(grid.event(open), CellEvent::Appeared) << "the same hit in the open";
}

TEST_F(DetectorOnAGrid, ArrivalBesideWhatTheMapSawFreeBeforeItLeanedOccupied)
{
	// Two cells from the hit, a thing the map saw free before it leaned
	// occupied: the pose's error moves a face two cells only where the
	// face's spread lies along it (at a grazing angle), and such a face is
	// one no beam ever crossed. The hit is an arrival at once. Next to the
	// hit, the spread in front of a face (seen free, then occupied by the
	// imprecision of beams that end beside it, never an impact itself): the
	// face moved by the pose's error, pending.
	struct TCase
	{
		int column;
		bool impacts;
		CellEvent expected;
	};
	for (const TCase c : {TCase{5, true, CellEvent::Appeared}, TCase{6, false, CellEvent::Leaving}})
	{
		SCOPED_TRACE(testing::Message() << "standing in column " << c.column << ", the hit in 7");
		grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
		const GridGeometry& g = grid.geometry();
		const std::size_t standing = g.index(c.column, 5), cell = g.index(7, 5);
		standBesideSeenFreeFloor(standing, c.impacts);
		ASSERT_TRUE(leansOccupied(grid.read(standing)));
		ASSERT_EQ(grid.heldImpact(standing), c.impacts);
		ASSERT_EQ(grid.event(standing), CellEvent::None);
		insertion(1.0, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
		EXPECT_EQ(grid.event(cell), c.expected);
	}
}

// A degree of error in the heading moves a face 12 m away by 21 cm: there a
// change that close to structure is the pose's error.
TEST_F(DetectorOnAGrid, ArrivalsReachToAFaceGrowsWithTheRange)
{
	// A hit two cells from a thing that stands (as above).
	expectArrivalFromCloseByPendingFromAfar([&](const GridGeometry& g) {
		standBesideSeenFreeFloor(g.index(5, 5), true);
		return g.index(7, 5);
	});
}

TEST_F(DetectorOnAGrid, ArrivalsReachToCellsNeverSeenFreeGrowsWithTheRange)
{
	// A hit four cells from the edge of what was never seen free (an unseen
	// room's inside, columns 0 to 4), which a degree of the heading's error
	// moves by as much from 12 m.
	expectArrivalFromCloseByPendingFromAfar([&](const GridGeometry& g) {
		insertion(0.0, [&] {
			for (int y = 0; y < g.sizeY; ++y)
				for (int x = 5; x < g.sizeX; ++x) fuse(g.index(x, y), Mass::simpleFree(0.7), false);
		});
		return g.index(8, 10);
	});
}

TEST_F(DetectorOnAGrid, ThingThatArrivedLongAgoIsNoStructure)
{
	// A thing that came and stays keeps its arrival, however old: its side,
	// first hit later, is an arrival at once, not pending as beside a wall.
	const GridGeometry& g = grid.geometry();
	const std::size_t thing = g.index(3, 3), side = g.index(4, 3);
	thingStandsFromOneSecond(thing);
	ASSERT_EQ(grid.event(thing), CellEvent::Appeared);
	insertion(4.0, [&] { fuse(thing, Mass::simpleOccupied(0.9), true); });
	EXPECT_EQ(grid.event(thing), CellEvent::Appeared) << "seen after its window, still there";
	EXPECT_DOUBLE_EQ(grid.eventTime(thing), 1.0);
	insertion(4.1, [&] { fuse(side, Mass::simpleOccupied(0.9), true); });
	EXPECT_EQ(grid.event(side), CellEvent::Appeared);
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

	// The turn-down marked the cell: long after it (past kFlipMemory
	// insertions), two hits in a row beside the wall are still no arrival,
	// while a cell that never flipped is confirmed by them.
	EXPECT_TRUE(grid.flipped(floor));
	const std::size_t other = grid.geometry().index(12, 10);
	for (int k = 0; k < 45; ++k)
		insertion(2.0 + 0.1 * k, [&] {
			freeSight();
			fuse(other, Mass::simpleFree(0.7), false);
		});
	for (const double t : {7.0, 7.1})
		insertion(t, [&] {
			weakHit();
			fuse(other, Mass::simpleOccupied(0.55), true);
			thingInTheOpen();
		});
	EXPECT_EQ(grid.event(floor), CellEvent::Leaving);
	EXPECT_FALSE(grid.flipped(other));
	EXPECT_EQ(grid.event(other), CellEvent::Appeared);
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
	crossedWithoutFreeEvidence = [&](std::size_t idx) { return idx == cell; };
	insertion(1.1, [] {});
	EXPECT_EQ(grid.event(cell), CellEvent::Disappeared);
}

TEST_F(DetectorOnAGrid, ArrivalsStayListedWhenTheGridGrowsIntoANewBlock)
{
	// Growth to the left, beyond the block: every cell moves to another
	// index, and the list of arrivals follows it.
	const std::size_t before = grid.geometry().index(3, 3);  // away from the wall
	for (int k = 0; k < 3; ++k)
		insertion(0.6 + 0.1 * k, [&] { fuse(before, Mass::simpleFree(0.9), false); });
	insertion(1.0, [&] { fuse(before, Mass::simpleOccupied(0.9), true); });
	ASSERT_EQ(grid.event(before), CellEvent::Appeared);
	const std::size_t layout = grid.layout();

	ASSERT_TRUE(grid.growToInclude(-0.5, 1.0, 0.0, 1.0, 0.0, 100000));
	ASSERT_NE(grid.layout(), layout) << "a new block";
	const std::size_t cell = grid.geometry().index(13, 3);
	ASSERT_EQ(grid.indexAfterGrowth(before), cell);
	ASSERT_EQ(grid.event(cell), CellEvent::Appeared);
	crossedWithoutFreeEvidence = [&](std::size_t idx) { return idx == cell; };
	insertion(1.1, [] {});
	EXPECT_EQ(grid.event(cell), CellEvent::Disappeared);
}
