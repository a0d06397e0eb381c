/* The motion layer's decisions on hand-made fusions (src/insert/): arrivals
 * beside static structure (the inside of a wall included, and the spread in
 * front of a face next to them; not what the map saw free two cells away)
 * wait for a hit at the next insertions, beside a thing seen arriving in
 * the open whose face reaches them (at once when its face reached them
 * at an earlier insertion), and stay when hit again, a thing that arrived long ago
 * is no structure, a cell that flips between hit and free does not become
 * an arrival (then or later), nor does a hit beside cells never seen free at
 * once, a departure waits until the cell no longer leans occupied and is
 * none beside a wall's unseen inside or behind a thin thing's grazed
 * face (never reported while it waits there), one sight is not enough for the
 * default rules, a scan whose impacts mostly land on free cells (a
 * misplaced one) settles nothing, and the list of recent arrivals outlives
 * growth that moves no cell. */
#include <gtest/gtest.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include "insert/MotionDetector.h"

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

using namespace mrpt_evidential;

namespace
{
/** A 1 x 1 m grid without conflict, 5 cm cells, seen free once, with a wall
 * cell that beams ended in for a while and a floor cell two cells from it,
 * seen free. */
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
		insertion(-0.1, [&] {
			for (std::size_t idx = 0; idx < grid.geometry().cellCount(); ++idx)
				if (idx != wall) fuse(idx, Mass::simpleFree(0.7), false);
		});
		for (int k = 0; k < 5; ++k)
			insertion(0.1 * k, [&] {
				fuse(wall, Mass::simpleOccupied(0.9), true);
				fuse(floor, Mass::simpleFree(0.7), false);
			});
	}
	/** One insertion at data time t, whose fusions `fusions` makes, as the
	 * map makes it: the recent arrivals that its beams cross without free
	 * evidence (crossedWithoutFreeEvidence) judged first. */
	void insertion(double t, const std::function<void()>& fusions)
	{
		grid.beginInsertion(t);
		detector.begin(rules);
		detector.judgeCrossedArrivals(grid, crossedWithoutFreeEvidence);
		fusions();
		detector.settle(grid, impactCells, sensor.first, sensor.second);
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
	/** Free sights of `cells`, one insertion a tenth of a second from data
	 * time t on, until none of them leans occupied (30 at most), as rays
	 * that cross them; returns the data time of the next insertion. */
	double seeFreeUntilNoneLeansOccupied(double t, const std::vector<std::size_t>& cells)
	{
		const auto anyLeans = [&] {
			return std::any_of(cells.begin(), cells.end(), [&](std::size_t idx) {
				return leansOccupied(grid.read(idx));
			});
		};
		for (int k = 0; k < 30 && anyLeans(); ++k, t += 0.1)
			insertion(t, [&] {
				for (const std::size_t idx : cells) fuse(idx, Mass::simpleFree(0.7), false);
			});
		return t;
	}
	/** A face beside structure that turned free waits as a departure under
	 * way, never reported, while rays keep crossing it from data time t on,
	 * until the wait is over. */
	void expectNoDepartureWhileTheFaceWaits(double t, std::size_t face)
	{
		for (std::size_t k = 0; k < CMotionDetector::kDepartureWait; ++k, t += 0.1)
		{
			insertion(t, [&] { fuse(face, Mass::simpleFree(0.7), false); });
			EXPECT_NE(grid.event(face), CellEvent::Disappeared) << "insertion " << k;
		}
	}
	void freeSight() { fuse(floor, Mass::simpleFree(0.7), false); }
	/** A thing that stands in `cell` from data time 1 s: beams end in it
	 * at ten insertions, a tenth of a second apart. */
	void thingStandsFromOneSecond(std::size_t cell)
	{
		for (int k = 0; k < 10; ++k)
			insertion(1.0 + 0.1 * k, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
	}
	/** The cells around (6, 5) seen free twice, then
	 * `standing` hit by three insertions' beams (or, without `impacts`,
	 * reached by their spread only), fused as the map fuses cells that no
	 * event is judged in, until it leans occupied. */
	void standBesideSeenFreeFloor(std::size_t standing, bool impacts)
	{
		const GridGeometry& g = grid.geometry();
		for (int k = 0; k < 2; ++k)
			insertion(0.1 * k, [&] {
				for (int y = 3; y <= 7; ++y)
					for (int x = 3; x <= 9; ++x) grid.fuseNormalized(g.index(x, y), Mass::simpleFree(0.9));
			});
		for (int k = 0; k < 3; ++k)
		{
			grid.beginInsertion(0.2 + 0.1 * k);
			grid.fuseNormalized(standing, Mass::simpleOccupied(0.9));
			if (impacts) grid.markImpact(standing);
		}
	}
	/** Beams' ends on a thing's face in the open, from four cells from the
	 * floor cell (within thingCells) and six from the wall to two from the
	 * floor cell (within faceGapCells): the part of a thing that moves which
	 * reaches out of the wall's clearance, and the face that joins it to the
	 * floor cell. */
	void thingInTheOpen()
	{
		for (const int y : {6, 7, 8}) fuse(grid.geometry().index(10, y), Mass::simpleOccupied(0.9), true);
	}

	EvidentialGridStorage grid;
	CMotionDetector detector;
	const TMotionRules rules{0.5, 0.5, 2, 4, 2.0};
	std::size_t wall = 0, floor = 0;
	/** Cells the beams of each insertion ended in, for settle(). */
	std::size_t impactCells = 100;
	/** Where the beams come from (metres): within a metre of every cell, so
	 * that the clearances are the rules' own. */
	std::pair<double, double> sensor{0.5, 0.5};
	std::function<bool(std::size_t)> crossedWithoutFreeEvidence = [](std::size_t) { return false; };
};
}  // namespace

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

TEST_F(DetectorOnAGrid, DepartureWaitsUntilTheCellNoLongerLeansOccupied)
{
	// A thing that stood for a second, away from the wall, then left.
	const std::size_t cell = grid.geometry().index(3, 3);
	thingStandsFromOneSecond(cell);
	ASSERT_EQ(grid.event(cell), CellEvent::Appeared) << "it came";
	ASSERT_TRUE(leansOccupied(grid.read(cell)));
	// Its first free sights leave it leaning occupied: a ray that grazed it
	// looks the same, so nothing is reported yet.
	insertion(2.0, [&] { fuse(cell, Mass::simpleFree(0.7), false); });
	EXPECT_EQ(grid.event(cell), CellEvent::Leaving);
	int sights = 1;
	for (; sights < 20 && leansOccupied(grid.read(cell)); ++sights)
	{
		EXPECT_EQ(grid.event(cell), CellEvent::Leaving) << sights << " free sights";
		insertion(2.0 + 0.1 * sights, [&] { fuse(cell, Mass::simpleFree(0.7), false); });
	}
	ASSERT_FALSE(leansOccupied(grid.read(cell)));
	EXPECT_GT(sights, 2);
	EXPECT_EQ(grid.event(cell), CellEvent::Disappeared);
	EXPECT_DOUBLE_EQ(grid.eventTime(cell), 2.0) << "dated from the first free sight";
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

TEST_F(DetectorOnAGrid, DepartureBesideWhereTheThingStepsIsReported)
{
	// A thing stood a second in (3, 3), then moves by a cell: its old cell
	// turns free while the next one is hit for the first time and leans
	// occupied. That cell is the thing, not structure the old cell's free
	// sights could be the pose's error beside.
	const GridGeometry& g = grid.geometry();
	const std::size_t before = g.index(3, 3), after = g.index(4, 3);
	thingStandsFromOneSecond(before);
	ASSERT_EQ(grid.event(before), CellEvent::Appeared);
	// Free sights while the next one still leaves it leaning occupied.
	const auto nextSightTurnsIt = [&] {
		EvidentialGridStorage trial = grid;
		trial.fuseNormalized(before, Mass::simpleFree(0.7));
		return !leansOccupied(trial.read(before));
	};
	double t = 2.0;
	for (; t < 4.0 && !nextSightTurnsIt(); t += 0.1)
		insertion(t, [&] { fuse(before, Mass::simpleFree(0.7), false); });
	ASSERT_EQ(grid.event(before), CellEvent::Leaving);
	// The sight that turns it, with the thing's first hit next door (its
	// candidate settled after the departure's).
	insertion(t, [&] {
		fuse(before, Mass::simpleFree(0.7), false);
		fuse(after, Mass::simpleOccupied(0.9), true);
	});
	ASSERT_TRUE(leansOccupied(grid.read(after)));
	EXPECT_EQ(grid.event(after), CellEvent::Appeared);
	EXPECT_EQ(grid.event(before), CellEvent::Disappeared);
}

TEST(MotionRules, LeastConflictWithinReachOfTheSensorsMasses)
{
	// The default masses leave the threshold as it is.
	EXPECT_EQ(TMotionRules::reachableConflict(0.65, 0.9), 0.65);
	EXPECT_EQ(TMotionRules::reachableConflict(0.65, 0.7), 0.65);
	// A free sight of 0.6 conflicts with a cell at the ceiling by 0.6 at most:
	// it asks as sure a cell as the defaults do.
	EXPECT_DOUBLE_EQ(TMotionRules::reachableConflict(0.65, 0.6), 0.93 * 0.6);
	// A sight without mass makes no conflict, and 0 would make every fusion
	// an event.
	EXPECT_EQ(TMotionRules::reachableConflict(0.65, 0.0), 0.65);
}

TEST_F(DetectorOnAGrid, DefaultRulesNeedTwoSightsBeforeAChange)
{
	// With the default masses (muF 0.7, muO 0.9), one free sight then a hit
	// conflicts by 0.63: a cell seen once, as the first beams that reach a
	// corner see it, is no arrival. Seen free twice, it is.
	const double mapDefault = CEvidentialGridMap2D::TInsertionOptions().motionMinConflict;
	const TMotionRules defaults{mapDefault, mapDefault, 2, 10, 2.0};
	ASSERT_EQ(TMotionRules().minAppeared, mapDefault) << "the detector's default is the map's";
	ASSERT_EQ(TMotionRules().minLeft, mapDefault);
	const std::size_t once = grid.geometry().index(3, 3), twice = grid.geometry().index(3, 17);
	const auto insertWithDefaults = [&](double t, const std::function<void()>& fusions) {
		grid.beginInsertion(t);
		detector.begin(defaults);
		fusions();
		detector.settle(grid, impactCells, sensor.first, sensor.second);
	};
	// The fixture saw every cell free once.
	insertWithDefaults(1.1, [&] { fuse(twice, Mass::simpleFree(0.7), false); });
	insertWithDefaults(1.2, [&] {
		fuse(once, Mass::simpleOccupied(0.9), true);
		fuse(twice, Mass::simpleOccupied(0.9), true);
	});
	EXPECT_EQ(grid.event(once), CellEvent::None);
	EXPECT_EQ(grid.event(twice), CellEvent::Appeared);
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
	// A hit two cells from a thing that stands: an arrival at once seen from
	// close by (as above), pending seen from 12 m.
	struct TCase
	{
		double sensorX;
		CellEvent arrival;
	};
	for (const TCase c : {TCase{0.5, CellEvent::Appeared}, TCase{-11.5, CellEvent::Leaving}})
	{
		SCOPED_TRACE(testing::Message() << "sensor at x " << c.sensorX);
		sensor = {c.sensorX, 0.5};
		grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
		const GridGeometry& g = grid.geometry();
		const std::size_t standing = g.index(5, 5), cell = g.index(7, 5);
		standBesideSeenFreeFloor(standing, true);
		insertion(1.0, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
		EXPECT_EQ(grid.event(cell), c.arrival);
	}
}

TEST_F(DetectorOnAGrid, DepartureThreeCellsFromAWallSeenFromCloseByIsReported)
{
	const std::size_t thing = grid.geometry().index(10, 9);
	thingStandsFromOneSecond(thing);
	ASSERT_EQ(grid.event(thing), CellEvent::Appeared);
	const double t = seeFreeUntilNoneLeansOccupied(2.0, {thing});
	insertion(t, [&] { fuse(thing, Mass::simpleFree(0.7), false); });
	EXPECT_EQ(grid.event(thing), CellEvent::Disappeared);
}

TEST_F(DetectorOnAGrid, DepartureThreeCellsFromAWallSeenFromAfarIsThePosesError)
{
	// The thing arrives seen from close by, and leaves seen from 12 m.
	const std::size_t thing = grid.geometry().index(10, 9);
	thingStandsFromOneSecond(thing);
	ASSERT_EQ(grid.event(thing), CellEvent::Appeared);
	sensor = {-11.5, 0.5};
	const double t = seeFreeUntilNoneLeansOccupied(2.0, {thing});
	insertion(t, [&] { fuse(thing, Mass::simpleFree(0.7), false); });
	EXPECT_NE(grid.event(thing), CellEvent::Disappeared);
}

TEST_F(DetectorOnAGrid, GrazedFaceBesideAWallsUnseenInsideIsNoDeparture)
{
	// A wall's face that beams ended in, whose inside no beam reached: rays
	// that graze it (the pose's error) turn it free. A thing that stood on
	// floor seen free and left is turned free the same way, and is gone.
	grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
	const GridGeometry& g = grid.geometry();
	const std::size_t face = g.index(5, 5), thing = g.index(15, 15);
	insertion(0.0, [&] {
		for (int dy = -2; dy <= 2; ++dy)
			for (int dx = -2; dx <= 2; ++dx)
				fuse(g.index(15 + dx, 15 + dy), Mass::simpleFree(0.9), false);
	});
	for (int k = 0; k < 10; ++k)
		insertion(0.1 + 0.1 * k, [&] {
			fuse(face, Mass::simpleOccupied(0.9), true);
			fuse(thing, Mass::simpleOccupied(0.9), true);
		});
	const double turnedFreeAt = seeFreeUntilNoneLeansOccupied(1.1, {face, thing});
	ASSERT_FALSE(leansOccupied(grid.read(face)));
	ASSERT_FALSE(leansOccupied(grid.read(thing)));
	EXPECT_EQ(grid.event(thing), CellEvent::Disappeared);
	expectNoDepartureWhileTheFaceWaits(turnedFreeAt, face);
	EXPECT_EQ(grid.event(face), CellEvent::None);
	EXPECT_TRUE(grid.flipped(face));
}

TEST_F(DetectorOnAGrid, GrazedFaceOfAThinThingIsNoDeparture)
{
	// A door's leaf two cells thick, seen from one side: beams end in its
	// face row, the row behind it is occupied by their imprecision and was
	// crossed by a ray once, and what lies beyond was never seen. Rays that
	// graze the face turn its cells free: the unseen cells two rows behind
	// (within the clearance) say it is a face, not a thing that left.
	grid.reset(0.0, 1.0, 0.0, 1.0, 0.05, 1000);
	const GridGeometry& g = grid.geometry();
	const std::size_t face = g.index(10, 10), behind = g.index(10, 11);
	insertion(0.0, [&] {
		for (int dy = -2; dy <= 1; ++dy)
			for (int dx = -2; dx <= 2; ++dx)
				fuse(g.index(10 + dx, 10 + dy), Mass::simpleFree(dy < 0 ? 0.9 : 0.3), false);
	});
	for (int k = 0; k < 10; ++k)
		insertion(0.1 + 0.1 * k, [&] {
			for (int dx = -2; dx <= 2; ++dx)
			{
				fuse(g.index(10 + dx, 10), Mass::simpleOccupied(0.9), true);
				if (k < 3) fuse(g.index(10 + dx, 11), Mass::simpleOccupied(0.9), false);
			}
		});
	ASSERT_TRUE(leansOccupied(grid.read(behind)));
	ASSERT_FALSE(grid.neverSeenFree(behind));
	ASSERT_TRUE(grid.neverSeenFree(g.index(10, 12)));
	std::vector<std::size_t> faceRow;
	for (int dx = -2; dx <= 2; ++dx) faceRow.push_back(g.index(10 + dx, 10));
	const double turnedFreeAt = seeFreeUntilNoneLeansOccupied(1.1, faceRow);
	ASSERT_FALSE(leansOccupied(grid.read(face)));
	expectNoDepartureWhileTheFaceWaits(turnedFreeAt, face);
	EXPECT_EQ(grid.event(face), CellEvent::None);
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
