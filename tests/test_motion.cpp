/* The motion layer (issue 11): the conflict of each fusion split by its
 * cause, a box that moves in a simulated room flagged where it left and where
 * it came (with weaker and, pushed slowly, with stronger masses too), no
 * arrival kept at the edge of a moved thing's new shadow, the
 * walls left alone under pose noise and by scans whose pose is off, the
 * window, and what survives a copy and a file (the layer goes on after
 * either as in the original). */
#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/box_world.h"
#include "support/map_bytes.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt::poses::CPose3D;

namespace
{
const test::ScanSetup kSetup = test::ScanSetup().maxRange(15.0);

/** The robot's pose at scan k: it sways around (0, -2), looking north. */
CPose3D swayingPose(int k)
{
	const double s = 0.05 * k;
	return CPose3D(0.5 * std::sin(s), -2.0 + 0.3 * std::cos(s), 0.0, M_PI / 2 + 0.3 * std::sin(0.7 * s), 0, 0);
}

const test::TBox kBoxBefore{-1.2, -0.2, -0.8, 0.2}, kBoxAfter{1.0, 0.8, 1.4, 1.2};

/** The room with the box where it stands at scan k (before at scans < 60). */
std::vector<test::TBox> worldAt(int k)
{
	std::vector<test::TBox> boxes = test::roomWalls();
	boxes.push_back(k < 60 ? kBoxBefore : kBoxAfter);
	return boxes;
}

/** Scans first .. last (inclusive) of the moving box, at 10 Hz; the robot
 * stands still after scan `stopAt`. */
void replayMovingBox(CEvidentialGridMap2D& map, int first, int last, int stopAt = 1000)
{
	for (int k = first; k <= last; ++k)
	{
		const CPose3D pose = swayingPose(std::min(k, stopAt));
		map.insertObservation(test::scanOfBoxes(worldAt(k), pose, kSetup.at(0.1 * k)), pose);
	}
}

/** True when (x, y) lies within `margin` of the box. */
bool near(const test::TBox& b, double x, double y, double margin)
{
	return test::TBox{b.xMin - margin, b.yMin - margin, b.xMax + margin, b.yMax + margin}
		.contains(x, y);
}

struct TFlags
{
	int atBefore = 0, atAfter = 0, elsewhere = 0;
};
/** Counts the cells of `which` motion near the box's two places and
 * elsewhere. */
TFlags flags(const CEvidentialGridMap2D& map, Motion which)
{
	TFlags f;
	for (const auto& [x, y] : which == Motion::Appeared ? map.getAppearedCellCenters()
														 : map.getDisappearedCellCenters())
	{
		if (near(kBoxBefore, x, y, 0.1)) ++f.atBefore;
		else if (near(kBoxAfter, x, y, 0.1)) ++f.atAfter;
		else ++f.elsewhere;
	}
	return f;
}

CEvidentialGridMap2D roomMap()
{
	CEvidentialGridMap2D map(-5, 5, -4, 4, 0.05);
	map.insertionOptions.maxRange = 15.0;
	return map;
}
}  // namespace

TEST(MotionAlgebra, SplitOfHandComputedFusions)
{
	const Mass before{0.0, 0.6, 0.1, 0.3};
	// Occupied now where it was mostly free: appeared 0.6 x 0.9.
	ConflictSplit s = splitConflict(before, Mass::simpleOccupied(0.9));
	EXPECT_DOUBLE_EQ(s.appeared, 0.54);
	EXPECT_DOUBLE_EQ(s.disappeared, 0.0);
	// Free now: disappeared 0.1 x 0.7.
	s = splitConflict(before, Mass::simpleFree(0.7));
	EXPECT_DOUBLE_EQ(s.appeared, 0.0);
	EXPECT_DOUBLE_EQ(s.disappeared, 0.07);
	// Both causes at once; together they are the conjunctive rule's conflict.
	const Mass mixed{0.0, 0.2, 0.5, 0.3};
	s = splitConflict(before, mixed);
	EXPECT_DOUBLE_EQ(s.appeared, 0.3);
	EXPECT_DOUBLE_EQ(s.disappeared, 0.02);
	EXPECT_NEAR(s.appeared + s.disappeared, conjunctive(before, mixed).conflict, 1e-15);
}

TEST(MotionStorage, NormalizedFusionReturnsTheSplitAndDempstersMass)
{
	EvidentialGridStorage grid;
	grid.reset(0, 1, 0, 1, 0.5, 4);
	grid.setKeepsConflict(false);
	grid.beginInsertion(1.0);
	grid.write(0, {0.0, 0.6, 0.1, 0.3});
	const Mass before = grid.read(0);
	grid.beginInsertion(2.0);
	const Mass observed{0.0, 0.2, 0.5, 0.3};
	const ConflictSplit s = grid.fuseNormalized(0, observed);
	const ConflictSplit exact = splitConflict(before, observed);
	EXPECT_NEAR(s.appeared, exact.appeared, 1e-12);
	EXPECT_NEAR(s.disappeared, exact.disappeared, 1e-12);
	ASSERT_MASS_NEAR_AT(grid.read(0), dempster(before, observed), 1.0 / kMassScale, 0, 0);
	EXPECT_EQ(grid.read(0).conflict, 0.0);
	// No cell gets surer than the ceiling, so that evidence against it can
	// always win.
	for (int i = 0; i < 100; ++i) grid.fuseNormalized(1, Mass::simpleOccupied(0.9));
	EXPECT_LE(grid.read(1).occupied, EvidentialGridStorage::kMaxCertainty + 1e-5);
	for (int i = 0; i < 20 && grid.read(1).occupied > grid.read(1).free; ++i)
		grid.fuseNormalized(1, Mass::simpleFree(0.7));
	EXPECT_GT(grid.read(1).free, grid.read(1).occupied);
}

TEST(Motion, BoxThatMovesIsFlaggedAtBothPlacesAndNothingElse)
{
	CEvidentialGridMap2D map = roomMap();
	replayMovingBox(map, 0, 59);
	EXPECT_EQ(map.countMotion().appeared + map.countMotion().disappeared, 0u)
		<< "a static scene seen by a swaying robot";
	replayMovingBox(map, 60, 64);
	const TFlags appeared = flags(map, Motion::Appeared);
	EXPECT_GE(appeared.atAfter, 6) << "the box's new place";
	EXPECT_EQ(appeared.atBefore, 0);
	EXPECT_EQ(appeared.elsewhere, 0);
	// The old place, hit for six seconds, still leans occupied after five
	// free sights: its departure is reported once it no longer does.
	EXPECT_EQ(map.countMotion().disappeared, 0u);
	replayMovingBox(map, 65, 69);
	const TFlags disappeared = flags(map, Motion::Disappeared);
	EXPECT_GE(disappeared.atBefore, 4) << "the box's old place";
	// At most the cell beside the new place's corner that one beam's end
	// reached (an arrival seen free again: gone, by the layer's rule).
	EXPECT_LE(disappeared.atAfter, 1);
	EXPECT_EQ(disappeared.elsewhere, 0);
	EXPECT_EQ(flags(map, Motion::Appeared).elsewhere, 0);
	// Each event is dated within the scans that saw it: a departure from
	// the first free sight.
	for (const auto& [x, y] :
		 {map.getAppearedCellCenters().front(), map.getDisappearedCellCenters().front()})
	{
		EXPECT_GE(map.getCellMotionTime(x, y), 6.0 - 1e-9);
		EXPECT_LE(map.getCellMotionTime(x, y), 6.4 + 1e-9);
	}
	EXPECT_EQ(map.getCellMotion(100.0, 0.0), Motion::None);
	// A second later the static map has moved on: the face of the box seen
	// at its new place reads occupied, its old place free.
	const auto [ax, ay] = map.getAppearedCellCenters().front();
	const auto [dx, dy] = map.getDisappearedCellCenters().front();
	replayMovingBox(map, 70, 79);
	EXPECT_EQ(map.getCellDecision(ax, ay), Decision::Occupied);
	EXPECT_EQ(map.getCellDecision(dx, dy), Decision::Free);
	EXPECT_TRUE(std::isnan(map.getCellMotionTime(0.0, -2.0)));
}

TEST(Motion, BoxThatMovesIsFlaggedWithWeakerMasses)
{
	// With muF 0.6 no free sight reaches a conflict of 0.65 (m(O) 0.9999 x
	// 0.6), with muO 0.6 no hit does: the least conflict is lowered to what
	// such a sight reaches from a cell as sure as the defaults ask.
	for (const auto& [muF, muO] : {std::pair{0.6, 0.9}, std::pair{0.7, 0.6}})
	{
		SCOPED_TRACE("muF " + std::to_string(muF) + ", muO " + std::to_string(muO));
		CEvidentialGridMap2D map = roomMap();
		map.insertionOptions.muF = muF;
		map.insertionOptions.muO = muO;
		replayMovingBox(map, 0, 59);
		EXPECT_EQ(map.countMotion().appeared + map.countMotion().disappeared, 0u);
		replayMovingBox(map, 60, 64);
		const TFlags appeared = flags(map, Motion::Appeared);
		EXPECT_GE(appeared.atAfter, 6) << "the box's new place";
		EXPECT_EQ(appeared.atBefore + appeared.elsewhere, 0);
		// Weaker free sights turn the old place free a few scans later.
		replayMovingBox(map, 65, 74);
		const TFlags disappeared = flags(map, Motion::Disappeared);
		EXPECT_GE(disappeared.atBefore, 4) << "the box's old place";
		EXPECT_EQ(disappeared.elsewhere, 0);
		EXPECT_EQ(flags(map, Motion::Appeared).elsewhere, 0);
	}
}

TEST(Motion, BoxPushedAwaySlowlyLeavesDeparturesWithStrongerMasses)
{
	// A box 3 m before a robot that does not move is pushed away from it at
	// 3 cm a scan. With strong masses its old face turns free after three
	// or four free sights, while the box's body still stands within the
	// clearance: those departures wait for the box to move on instead of
	// being taken for the pose's error at once.
	CEvidentialGridMap2D map = roomMap();
	map.insertionOptions.muF = 0.9;
	map.insertionOptions.muO = 0.98;
	const CPose3D robot(0.0, -2.5, 0.0, M_PI / 2, 0, 0);
	const auto boxAt = [](int k) {
		const double pushed = 0.03 * std::clamp(k - 29, 0, 10);
		return test::TBox{-0.2, 0.5 + pushed, 0.2, 0.9 + pushed};
	};
	int atOldFace = 0, elsewhere = 0;
	for (int k = 0; k < 50; ++k)
	{
		std::vector<test::TBox> world = test::roomWalls();
		world.push_back(boxAt(k));
		map.insertObservation(test::scanOfBoxes(world, robot, kSetup.at(0.1 * k)), robot);
		if (k == 29)
		{
			ASSERT_EQ(map.countMotion().disappeared, 0u) << "nothing has moved yet";
		}
	}
	for (const auto& [x, y] : map.getDisappearedCellCenters())
		(std::abs(x) < 0.25 && y > 0.45 && y < 0.85 ? atOldFace : elsewhere)++;
	EXPECT_GE(atOldFace, 4) << "the cells the box's face left";
	EXPECT_EQ(elsewhere, 0);
}

TEST(Motion, ThingThatMovedLeavesNoArrivalAtItsNewShadowsEdge)
{
	// A thing stands 3 m before a robot that does not move, then steps a
	// metre nearer and to the west: its old face east of the new place's
	// shadow is seen free again, but the cells at the shadow's very edge lie
	// between a sector that passes them and one that stops at the thing's
	// new face in front of them, where free evidence stops. One beam crossed
	// them: their arrival is over all the same.
	CEvidentialGridMap2D map = roomMap();
	const CPose3D robot(0.0, -2.5, 0.0, M_PI / 2, 0, 0);
	const test::TBox before{-0.2, 0.5, 0.2, 0.9}, after{-0.4, -0.5, 0.0, -0.1};
	for (int k = 0; k < 50; ++k)
	{
		std::vector<test::TBox> world = test::roomWalls();
		if (k >= 30) world.push_back(k < 40 ? before : after);
		map.insertObservation(test::scanOfBoxes(world, robot, kSetup.at(0.1 * k)), robot);
		if (k == 39)
		{
			ASSERT_GT(map.countMotion().appeared, 5u) << "the thing's face";
		}
	}
	// Arrivals left outside the new place: only those its shadow hides.
	const double shadowEast = std::atan2(after.yMin - robot.y(), after.xMax - robot.x());
	for (const auto& [x, y] : map.getAppearedCellCenters())
	{
		if (near(after, x, y, 0.1)) continue;
		EXPECT_GT(std::atan2(y - robot.y(), x - robot.x()), shadowEast)
			<< "a stale arrival at (" << x << ", " << y << ")";
	}
}

TEST(Motion, WindowExpires)
{
	CEvidentialGridMap2D map = roomMap();
	map.insertionOptions.motionWindow = 1.0;
	replayMovingBox(map, 0, 69);
	ASSERT_GT(map.countMotion().appeared, 0u);
	ASSERT_GT(map.countMotion().disappeared, 0u);
	// 1.6 s later, the box and the robot standing still: nothing is new.
	replayMovingBox(map, 70, 85, 69);
	EXPECT_EQ(map.countMotion().appeared, 0u);
	EXPECT_EQ(map.countMotion().disappeared, 0u);
	// An arrival stays while its thing does (it is no structure): a longer
	// window read back shows it again, dated from when the box came.
	map.insertionOptions.motionWindow = 1.0;
	replayMovingBox(map, 86, 90, 69);
	map.insertionOptions.motionWindow = 10.0;
	const auto arrived = map.getAppearedCellCenters();
	EXPECT_GT(arrived.size(), 0u);
	for (const auto& [x, y] : arrived)
	{
		EXPECT_GE(map.getCellMotionTime(x, y), 6.0 - 1e-9);
		EXPECT_LE(map.getCellMotionTime(x, y), 6.9 + 1e-9);
		EXPECT_EQ(map.getCellDecision(x, y), Decision::Occupied);
	}
}

TEST(Motion, PoseNoiseDoesNotFlagWalls)
{
	// A static room scanned from poses with the error of a SLAM front end:
	// up to 3 cm and 1 degree, changing at every scan.
	CEvidentialGridMap2D map = roomMap();
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> metres(-0.03, 0.03), radians(-M_PI / 180, M_PI / 180);
	std::vector<test::TBox> room = test::roomWalls();
	room.push_back(kBoxBefore);
	std::size_t flagged = 0, worst = 0;
	for (int k = 0; k < 300; ++k)
	{
		const CPose3D truth = swayingPose(k);
		const CPose3D believed(
			truth.x() + metres(rng), truth.y() + metres(rng), 0.0,
			truth.yaw() + radians(rng), 0, 0);
		map.insertObservation(test::scanOfBoxes(room, truth, kSetup.at(0.1 * k)), believed);
		const auto counts = map.countMotion();
		flagged += counts.appeared + counts.disappeared;
		worst = std::max<std::size_t>(worst, counts.appeared + counts.disappeared);
	}
	// The target: at most 0.5 % of the walls' cells flagged at any scan (the
	// room's inner faces are some 560 cells), and under 0.1 % in the mean
	// over the 300 scans (measured: 0.01 % with GCC's arithmetic, 0.04 % with
	// Clang's, arrivals that two hits beside a wall confirm).
	EXPECT_LE(worst, 3u) << "cells flagged at the worst scan";
	EXPECT_LE(flagged, 150u) << "cells flagged, summed over 300 scans";
	// The walls read occupied nonetheless.
	EXPECT_EQ(map.getCellDecision(0.0, 3.02), Decision::Occupied);
	EXPECT_EQ(map.getCellDecision(-1.0, -0.21), Decision::Occupied);
}

TEST(Motion, ScansWhosePoseIsOffFlagNothing)
{
	// The static room mapped with good poses, then scanned from poses off by
	// more than motionClearance (a SLAM front end's jump, which it mends
	// four scans later): the scans disagree with the whole map, not with a
	// part of it.
	CEvidentialGridMap2D map = roomMap();
	std::vector<test::TBox> room = test::roomWalls();
	room.push_back(kBoxBefore);
	for (int k = 0; k < 60; ++k)
		map.insertObservation(test::scanOfBoxes(room, swayingPose(k), kSetup.at(0.1 * k)), swayingPose(k));
	std::size_t flagged = 0;
	for (int k = 60; k < 64; ++k)
	{
		const CPose3D truth = swayingPose(k);
		const CPose3D believed(truth.x() + 0.25, truth.y() - 0.15, 0.0, truth.yaw() + 0.06, 0, 0);
		map.insertObservation(test::scanOfBoxes(room, truth, kSetup.at(0.1 * k)), believed);
		const auto counts = map.countMotion();
		flagged += counts.appeared + counts.disappeared;
	}
	EXPECT_EQ(flagged, 0u);
	// Back on good poses, the box that moves is found as before, and the
	// misplaced scans' evidence flags nothing elsewhere.
	replayMovingBox(map, 64, 74);
	const TFlags appeared = flags(map, Motion::Appeared);
	const TFlags disappeared = flags(map, Motion::Disappeared);
	EXPECT_GE(appeared.atAfter, 6);
	EXPECT_EQ(appeared.elsewhere, 0);
	EXPECT_GE(disappeared.atBefore, 4);
	EXPECT_EQ(disappeared.elsewhere, 0);
}

TEST(Motion, MapThatKeepsConflictHasNoMotionLayer)
{
	CEvidentialGridMap2D map = roomMap();
	map.insertionOptions.conflictHandling = ConflictHandling::Keep;
	replayMovingBox(map, 0, 64);
	EXPECT_EQ(map.countMotion().appeared + map.countMotion().disappeared, 0u);
	EXPECT_GT(map.countDecisions().conflict, 0u) << "the conflict is its motion evidence";
}

TEST(Motion, EventsSurviveCopiesAndFiles)
{
	CEvidentialGridMap2D map = roomMap();
	replayMovingBox(map, 0, 63);
	ASSERT_GT(map.countMotion().appeared, 0u);
	CEvidentialGridMap2D copy = map, back;
	test::deserialize(test::serialize(map), back);
	for (const CEvidentialGridMap2D* other : {&copy, &back})
	{
		EXPECT_EQ(other->insertionOptions.motionWindow, map.insertionOptions.motionWindow);
		const GridGeometry& g = map.geometry();
		for (int cy = 0; cy < g.sizeY; ++cy)
			for (int cx = 0; cx < g.sizeX; ++cx)
				ASSERT_EQ(other->getCellMotionByIndex(cx, cy), map.getCellMotionByIndex(cx, cy));
		// The layer goes on from where it was.
		CEvidentialGridMap2D next = *other;
		replayMovingBox(next, 64, 64);
		EXPECT_GE(next.countMotion().appeared, map.countMotion().appeared);
	}
}

TEST(Motion, CopiesAndFilesGoOnAsTheOriginal)
{
	// The detector's lists (recent arrivals, departures under way) decide
	// later scans: a copy (a particle of rbpf-slam), a moved map and a map
	// read back from its file must decide them as the original does.
	for (const int cut : {60, 61, 62, 64, 66})
	{
		CEvidentialGridMap2D map = roomMap();
		replayMovingBox(map, 0, cut);
		CEvidentialGridMap2D copy = map, assigned, back, source = map;
		assigned = map;
		CEvidentialGridMap2D moved = std::move(source);
		test::deserialize(test::serialize(map), back);
		replayMovingBox(map, cut + 1, 80);
		const std::vector<std::uint8_t> expected = test::serialize(map);
		for (CEvidentialGridMap2D* other : {&copy, &assigned, &moved, &back})
		{
			replayMovingBox(*other, cut + 1, 80);
			EXPECT_TRUE(test::serialize(*other) == expected) << "cut after scan " << cut;
		}
	}
}
