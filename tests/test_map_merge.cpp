/* mrpt-evidential tests: maps from many runs: fuseMap() and changesSince()
 * on runs of a known world (tests/support/scans.h). */
#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>

#include "support/scans.h"

using namespace mrpt_evidential;
using mrpt::poses::CPose3D;

namespace
{
/** A run in a world of a flat wall 3 m ahead, with a box `boxAt` metres
 * ahead across the beams within 5 degrees of the axis (none if 0): ten
 * scans from the robot at (x0, 0). */
CEvidentialGridMap2D run(double boxAt, double x0 = 0.0, double t0 = 1.0)
{
	CEvidentialGridMap2D map(-4.0, 4.0, -4.0, 4.0, 0.05);
	for (int k = 0; k < 10; ++k)
	{
		const auto scan = test::scanByAngle(181, test::ScanSetup().aperture(0.8 * M_PI).at(t0 + 0.1 * k),
			[&](double a) {
				const double wall = (3.0 - x0) / std::cos(a);
				return boxAt > 0 && std::abs(a) < 5 * M_PI / 180 ? boxAt / std::cos(a) : wall;
			});
		map.insertObservation(scan, CPose3D(x0, 0, 0, 0, 0, 0));
	}
	return map;
}

/** Decision at (x, y). */
Decision at(const CEvidentialGridMap2D& map, double x, double y) { return map.getCellDecision(x, y); }

/** The centre of a cell index of `map`. */
std::pair<double, double> centre(const CEvidentialGridMap2D& map, std::size_t idx)
{
	const GridGeometry& g = map.geometry();
	const auto sx = static_cast<std::size_t>(g.sizeX);
	return {g.cellCenterX(static_cast<int>(idx % sx)), g.cellCenterY(static_cast<int>(idx / sx))};
}
}  // namespace

TEST(MapMerge, FusingIntoAnEmptyMapCopies)
{
	const CEvidentialGridMap2D a = run(0.0);
	CEvidentialGridMap2D merged(-1.0, 1.0, -1.0, 1.0, 0.05);
	merged.fuseMap(a, FusionRule::Dempster, ConflictHandling::Normalize);
	EXPECT_EQ(merged.latestTime(), a.latestTime());
	for (const double x : {1.0, 2.0, 3.02})
	{
		const Mass ma = a.getCellMasses(x, 0.02), mm = merged.getCellMasses(x, 0.02);
		EXPECT_NEAR(ma.free, mm.free, 1e-4) << x;
		EXPECT_NEAR(ma.occupied, mm.occupied, 1e-4) << x;
	}
	EXPECT_EQ(merged.countDecisions().occupied, a.countDecisions().occupied);
	EXPECT_EQ(merged.countMotion().appeared + merged.countMotion().disappeared, 0u);
}

TEST(MapMerge, TwoRunsAgreeingReinforceAndDisagreeingKeepConflict)
{
	const CEvidentialGridMap2D a = run(0.0), b = run(1.5, 0.0, 50.0);
	CEvidentialGridMap2D agree = a;
	agree.fuseMap(a, FusionRule::Dempster, ConflictHandling::Normalize);
	EXPECT_GE(agree.getCellMasses(2.0, 0.02).free, a.getCellMasses(2.0, 0.02).free);
	// Keep: the conflict between the runs stays where the box stood in one.
	CEvidentialGridMap2D kept = a;
	kept.fuseMap(b, FusionRule::Conjunctive, ConflictHandling::Keep);
	EXPECT_EQ(kept.insertionOptions.conflictHandling, ConflictHandling::Keep);
	EXPECT_GT(kept.getCellMasses(1.52, 0.02).conflict, 0.3);
	EXPECT_LT(kept.getCellMasses(1.0, 0.02).conflict, 0.01);
	EXPECT_EQ(kept.latestTime(), b.latestTime());
}

TEST(MapMerge, DifferentExtentsGrowTheMap)
{
	CEvidentialGridMap2D small(-1.0, 1.0, -1.0, 1.0, 0.05);
	small.fuseMap(run(0.0), FusionRule::Dempster, ConflictHandling::Normalize);
	EXPECT_LE(small.getXMin(), -4.0 + 1e-9);
	EXPECT_GE(small.getXMax(), 4.0 - 1e-9);
	EXPECT_EQ(at(small, 3.02, 0.02), Decision::Occupied);
}

TEST(MapMerge, MapsOnOtherLatticesAreRefusedUnchanged)
{
	const CEvidentialGridMap2D a = run(0.0);
	CEvidentialGridMap2D coarse(-4.0, 4.0, -4.0, 4.0, 0.10);
	CEvidentialGridMap2D shifted(-4.02, 4.0, -4.0, 4.0, 0.05);
	for (CEvidentialGridMap2D* m : {&coarse, &shifted})
	{
		const auto before = m->countDecisions();
		try
		{
			m->fuseMap(a, FusionRule::Dempster, ConflictHandling::Normalize);
			ADD_FAILURE() << "fused a map of another lattice";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("do not share a lattice"), std::string::npos) << e.what();
		}
		EXPECT_EQ(m->countDecisions().unknown, before.unknown);
		EXPECT_ANY_THROW(m->changesSince(a));
	}
	EXPECT_ANY_THROW(a.changesSince(a, 0.0));
	EXPECT_ANY_THROW(a.changesSince(a, 0.5, -1.0));
}

TEST(MapMerge, UnknownRulesAndHandlingsAreRefusedUnchanged)
{
	const CEvidentialGridMap2D a = run(0.0);
	CEvidentialGridMap2D b = run(0.5);
	const auto before = b.countDecisions();
	const ConflictHandling handlingBefore = b.insertionOptions.conflictHandling;
	EXPECT_THROW(
		b.fuseMap(a, static_cast<FusionRule>(99), ConflictHandling::Keep), std::invalid_argument);
	EXPECT_THROW(
		b.fuseMap(a, FusionRule::Conjunctive, static_cast<ConflictHandling>(99)),
		std::invalid_argument);
	EXPECT_EQ(b.countDecisions().occupied, before.occupied);
	EXPECT_EQ(b.countDecisions().free, before.free);
	EXPECT_EQ(b.insertionOptions.conflictHandling, handlingBefore);
}

TEST(MapMerge, ChangesBetweenRunsAreFoundAndNotOnTheWall)
{
	// The box stands 1.5 m ahead in the second run only; the second run's
	// robot is one cell off (pose error), which moves the wall in its map.
	const CEvidentialGridMap2D before = run(0.0), after = run(1.5, 0.05, 50.0);
	const auto appeared = after.changesSince(before);
	ASSERT_GT(appeared.appeared.size(), 3u);
	for (const std::size_t i : appeared.appeared)
	{
		const auto [x, y] = centre(after, i);
		EXPECT_NEAR(x, 1.55, 0.25) << y;
		EXPECT_LT(std::abs(y), 0.25) << x;
	}
	EXPECT_TRUE(appeared.disappeared.empty());
	EXPECT_GT(appeared.compared, 10000u);
	// The other way round the box left.
	const auto left = before.changesSince(after);
	EXPECT_TRUE(left.appeared.empty());
	ASSERT_GT(left.disappeared.size(), 3u);
	for (const std::size_t i : left.disappeared) EXPECT_NEAR(centre(before, i).first, 1.55, 0.25);
	// The picture shows them.
	mrpt::img::CImage img;
	after.getAsChangesImage(appeared, img);
	EXPECT_EQ(img.getWidth(), static_cast<std::size_t>(after.getSizeX()));
}

TEST(MapMerge, ChangesPictureMarksEachChangedCellOfAGrownMap)
{
	// The second run goes on east: its grid grows and keeps room beyond that
	// side, so its cells' indices leave room between rows, while the changes
	// number the cells cx + sizeX cy.
	const CEvidentialGridMap2D before = run(0.0);
	CEvidentialGridMap2D after = run(1.5, 0.05, 50.0);
	after.insertObservation(
		test::arcScan(181, 3.0, test::ScanSetup().at(52.0)), CPose3D(3.5, 0, 0, 0, 0, 0));
	ASSERT_GT(after.storage().cells().size(), after.geometry().cellCount()) << "room kept";
	const auto changes = after.changesSince(before);
	ASSERT_GT(changes.appeared.size(), 3u);
	// Magenta reads the same in RGB and BGR, and no grey level is magenta.
	after.renderingOptions.appearedColor = mrpt::img::TColor(255, 0, 255);
	mrpt::img::CImage img;
	after.getAsChangesImage(changes, img);
	const auto magenta = [&](int x, int y) {
		return img.at<std::uint8_t>(x, y, 0) == 255 && img.at<std::uint8_t>(x, y, 1) == 0 &&
			img.at<std::uint8_t>(x, y, 2) == 255;
	};
	const int sizeX = after.geometry().sizeX, sizeY = after.geometry().sizeY;
	for (const std::size_t i : changes.appeared)
	{
		const int cx = static_cast<int>(i % static_cast<std::size_t>(sizeX));
		const int cy = static_cast<int>(i / static_cast<std::size_t>(sizeX));
		EXPECT_TRUE(magenta(cx, sizeY - 1 - cy)) << cx << " " << cy;
	}
	std::size_t painted = 0;
	for (int y = 0; y < sizeY; ++y)
		for (int x = 0; x < sizeX; ++x) painted += magenta(x, y);
	EXPECT_EQ(painted, changes.appeared.size());
}

TEST(MapMerge, CellsOneRunNeverSawAreNotCompared)
{
	// A run behind the other: its map sees nothing beyond its own wall.
	CEvidentialGridMap2D far(-4.0, 4.0, -4.0, 4.0, 0.05);
	const auto scan = test::arcScan(181, 1.0, test::ScanSetup().at(5.0));
	far.insertObservation(scan, CPose3D(-3.5, 0, 0, M_PI, 0, 0));
	const auto changes = run(1.5).changesSince(far);
	EXPECT_EQ(changes.compared, 0u);
	EXPECT_TRUE(changes.appeared.empty() && changes.disappeared.empty());
}
