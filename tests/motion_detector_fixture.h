/* The fixture of the motion layer's tests on hand-made fusions
 * (test_motion_arrivals.cpp, test_motion_departures.cpp): a small grid, a
 * wall cell and a floor cell, and insertions made of fusions as the map
 * makes them. */
#pragma once

#include <gtest/gtest.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include "insert/MotionDetector.h"

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace motion_test
{
using namespace mrpt_evidential;

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
	/** The same hit seen from close by (a sensor within a metre, where the
	 * clearances are the rules' own) and from 12 m (where a degree of the
	 * heading's error moves a face by four cells): on a fresh grid that
	 * `prepare` readies, returning the cell to hit, an arrival at once from
	 * close by and only pending from afar. */
	void expectArrivalFromCloseByPendingFromAfar(
		const std::function<std::size_t(const GridGeometry&)>& prepare)
	{
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
			const std::size_t cell = prepare(grid.geometry());
			insertion(1.0, [&] { fuse(cell, Mass::simpleOccupied(0.9), true); });
			EXPECT_EQ(grid.event(cell), c.arrival);
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
}  // namespace motion_test
