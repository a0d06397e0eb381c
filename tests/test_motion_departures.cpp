/* The motion layer's departures and its rules on hand-made fusions
 * (src/insert/): a departure waits until the cell no longer leans occupied,
 * is reported beside where the thing steps, and is none beside a wall's
 * unseen inside or behind a thin thing's grazed face (never reported while
 * it waits there), nor is a pending arrival turned down, wherever it lies;
 * its clearance grows with the range; the least conflict stays within reach
 * of the sensor's masses, and one sight is not enough for the default
 * rules. */
#include "motion_detector_fixture.h"

using namespace mrpt_evidential;
using motion_test::DetectorOnAGrid;

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

TEST_F(DetectorOnAGrid, PendingArrivalTurnedDownIsNoDepartureInTheOpenEither)
{
	// A hit four cells from the wall seen from 12 m is pending: a degree of
	// the heading's error moves the wall by that much there. Seen free from
	// close by, where nothing stands within the clearance, it is no
	// departure: it was never reported. The cell flips.
	sensor = {-11.5, 0.5};
	const std::size_t cell = grid.geometry().index(10, 8);
	insertion(1.0, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
	ASSERT_EQ(grid.event(cell), CellEvent::Leaving) << "pending";
	sensor = {0.5, 0.5};
	insertion(1.1, [&] { fuse(cell, Mass::simpleFree(0.7), false); });
	EXPECT_EQ(grid.event(cell), CellEvent::None);
	EXPECT_TRUE(grid.flipped(cell));
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

TEST_F(DetectorOnAGrid, DepartureUnderWayFollowsTheGridIntoANewBlock)
{
	// A thing that stood leaves; while its cell still leans occupied the
	// grid grows into a new block, moving every cell. Its departure is
	// reported all the same, not taken for a pending arrival turned down.
	const std::size_t thing = grid.geometry().index(10, 9);
	thingStandsFromOneSecond(thing);
	insertion(2.0, [&] { fuse(thing, Mass::simpleFree(0.7), false); });
	ASSERT_TRUE(leansOccupied(grid.read(thing)));
	ASSERT_EQ(grid.event(thing), CellEvent::Leaving);

	ASSERT_TRUE(grid.growToInclude(-0.5, 1.0, 0.0, 1.0, 0.0, 100000));
	const std::size_t cell = grid.geometry().index(20, 9);
	ASSERT_EQ(grid.event(cell), CellEvent::Leaving);
	const double t = seeFreeUntilNoneLeansOccupied(2.1, {cell});
	insertion(t, [&] { fuse(cell, Mass::simpleFree(0.7), false); });
	EXPECT_EQ(grid.event(cell), CellEvent::Disappeared);
}
