/* The map tests' files: a map with every option group away from its
 * defaults, grown and decayed, and the check that two maps are the same in
 * everything a file keeps (test_map_io, test_map_io_versions). */
#pragma once

#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <sstream>

#include "scans.h"

namespace mrpt_evidential::test
{
/** How the map files' scans are taken: 181 rays over 180 degrees, maxRange
 * 10 m; each gives the time and the ranges, a function of the ray index. */
inline const ScanSetup kMapFileScans = ScanSetup().maxRange(10.0);
constexpr std::size_t kMapFileRays = 181;

/** A map with non-default options in every group and three scans inserted at
 * different poses and times, so that decay, stamps and growth all show. */
inline CEvidentialGridMap2D mapWithEveryOption(double resolution = 0.1)
{
	CEvidentialGridMap2D map(-2.0, 2.0, -2.0, 2.0, resolution);
	map.setMaxCells(2'000'000);
	map.insertionOptions.fusionRule = FusionRule::Yager;
	map.insertionOptions.decayRate = 0.05;
	map.insertionOptions.maxRange = 4.0;
	map.insertionOptions.growthMargin = 0.5;
	map.insertionOptions.muF = 0.6;
	map.insertionOptions.conflictHandling = ConflictHandling::ToUnknown;
	map.insertionOptions.groundRemoval = GroundRemoval::Height;
	map.insertionOptions.minObstacleHeight = 0.15;
	map.insertionOptions.maxObstacleHeight = 2.5;
	map.insertionOptions.groundReturns = GroundReturns::Nothing;
	map.insertionOptions.insertionThreads = 2;
	map.likelihoodOptions.sigma = 0.2;
	map.likelihoodOptions.decimation = 3;
	map.likelihoodOptions.unknownAsNeutral = false;
	map.renderingOptions.style = RenderStyle::Masses;
	map.renderingOptions.appearedColor = mrpt::img::TColor(1, 2, 3);
	map.renderingOptions.showUnknown = true;
	map.renderingOptions.height = 0.25;
	map.genericMapParams.enableObservationLikelihood = false;
	map.insertObservation(
		scanByIndex(
			kMapFileRays, kMapFileScans.at(1000.0), [](std::size_t i) { return 2.0 + 0.005 * i; }),
		mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0));
	map.insertObservation(
		scanByIndex(
			kMapFileRays, kMapFileScans.at(1001.5), [](std::size_t i) { return 2.5 - 0.004 * i; }),
		mrpt::poses::CPose3D(0.4, -0.3, 0, 0.5, 0, 0));
	map.insertObservation(
		scanByIndex(
			kMapFileRays, kMapFileScans.at(1003.25), [](std::size_t i) { return 1.5 + (i % 7) * 0.1; }),
		mrpt::poses::CPose3D(-0.2, 0.6, 0, -2.0, 0, 0));
	return map;
}

/** Geometry, options, generic parameters, stamps and every cell equal. */
inline void expectSameMap(const CEvidentialGridMap2D& a, const CEvidentialGridMap2D& b)
{
	EXPECT_EQ(a.getXMin(), b.getXMin());
	EXPECT_EQ(a.getYMin(), b.getYMin());
	EXPECT_EQ(a.getResolution(), b.getResolution());
	ASSERT_EQ(a.getSizeX(), b.getSizeX());
	ASSERT_EQ(a.getSizeY(), b.getSizeY());
	EXPECT_EQ(a.maxCells(), b.maxCells());

	const auto& ia = a.insertionOptions;
	const auto& ib = b.insertionOptions;
	EXPECT_EQ(ia.sensorModel, ib.sensorModel);
	EXPECT_EQ(ia.muF, ib.muF);
	EXPECT_EQ(ia.muO, ib.muO);
	EXPECT_EQ(ia.imprecision, ib.imprecision);
	EXPECT_EQ(ia.imprecisionProfile, ib.imprecisionProfile);
	EXPECT_EQ(ia.sectorWidth, ib.sectorWidth);
	EXPECT_EQ(ia.maxRange, ib.maxRange);
	EXPECT_EQ(ia.invalidRangesAsFree, ib.invalidRangesAsFree);
	EXPECT_EQ(ia.fusionRule, ib.fusionRule);
	EXPECT_EQ(ia.decayRate, ib.decayRate);
	EXPECT_EQ(ia.horizontalTolerance, ib.horizontalTolerance);
	EXPECT_EQ(ia.conflictHandling, ib.conflictHandling);
	EXPECT_EQ(ia.growthMargin, ib.growthMargin);
	EXPECT_EQ(ia.freeMargin, ib.freeMargin);
	EXPECT_EQ(ia.insertionThreads, ib.insertionThreads);
	EXPECT_EQ(ia.motionWindow, ib.motionWindow);
	EXPECT_EQ(ia.groundRemoval, ib.groundRemoval);
	EXPECT_EQ(ia.minObstacleHeight, ib.minObstacleHeight);
	EXPECT_EQ(ia.maxObstacleHeight, ib.maxObstacleHeight);
	EXPECT_EQ(ia.groundReturns, ib.groundReturns);

	const auto& la = a.likelihoodOptions;
	const auto& lb = b.likelihoodOptions;
	EXPECT_EQ(la.occupiedMass, lb.occupiedMass);
	EXPECT_EQ(la.maxCorrsDistance, lb.maxCorrsDistance);
	EXPECT_EQ(la.sigma, lb.sigma);
	EXPECT_EQ(la.zHit, lb.zHit);
	EXPECT_EQ(la.zRandom, lb.zRandom);
	EXPECT_EQ(la.maxRange, lb.maxRange);
	EXPECT_EQ(la.decimation, lb.decimation);
	EXPECT_EQ(la.unknownAsNeutral, lb.unknownAsNeutral);

	std::ostringstream ra, rb;
	a.renderingOptions.dumpToTextStream(ra);
	b.renderingOptions.dumpToTextStream(rb);
	EXPECT_EQ(ra.str(), rb.str());

	EXPECT_EQ(
		a.genericMapParams.enableSaveAs3DObject,
		b.genericMapParams.enableSaveAs3DObject);
	EXPECT_EQ(
		a.genericMapParams.enableObservationLikelihood,
		b.genericMapParams.enableObservationLikelihood);
	EXPECT_EQ(
		a.genericMapParams.enableObservationInsertion,
		b.genericMapParams.enableObservationInsertion);

	EXPECT_EQ(a.insertionCount(), b.insertionCount());
	EXPECT_EQ(a.latestTime(), b.latestTime());
	EXPECT_EQ(a.storage().decayRate(), b.storage().decayRate());
	EXPECT_EQ(a.storage().stampTimes(), b.storage().stampTimes());
	EXPECT_EQ(a.storage().packedCells(), b.storage().packedCells());
	for (int cy = 0; cy < a.getSizeY(); ++cy)
		for (int cx = 0; cx < a.getSizeX(); ++cx)
			ASSERT_EQ(
				a.getCellMassesByIndex(cx, cy), b.getCellMassesByIndex(cx, cy))
				<< "at (" << cx << ", " << cy << ")";
}
}  // namespace mrpt_evidential::test
