/* Insertion on several threads (insertionOptions.insertionThreads) gives
 * the map of one thread, bit for bit. Const methods of CEvidentialGridMap2D
 * from several threads at once, while
 * no thread changes the map: reading masses, pictures, asString, counts, the
 * occupancy-grid conversion, occupied cells, serialization, copies, saving
 * to files and the likelihood, its field built on first use by whichever
 * thread comes first. Run under ThreadSanitizer by the
 * reliability_tsan_threads test (doc/reliability.md); results must equal
 * those of one thread. */
#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/box_world.h"
#include "support/map_bytes.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::serialize;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;

namespace
{
constexpr int kThreads = 4;

/** A square room of half-width 3 m seen from (x, y, yaw), 270 degrees. */
CObservation2DRangeScan roomScan(double x, double y, double yaw, double t)
{
	const auto setup = test::ScanSetup().aperture(1.5 * M_PI).at(t);
	return test::scanByAngle(271, setup, [x, y, yaw](double angle) {
		const double a = yaw + angle;
		const double c = std::cos(a), s = std::sin(a);
		double r = 1e9;
		if (c > 1e-9) r = std::min(r, (3.0 - x) / c);
		if (c < -1e-9) r = std::min(r, (-3.0 - x) / c);
		if (s > 1e-9) r = std::min(r, (3.0 - y) / s);
		if (s < -1e-9) r = std::min(r, (-3.0 - y) / s);
		return r;
	});
}

/** Everything the const methods give, to compare threads with one thread. */
struct Readings
{
	std::vector<Mass> masses;
	std::vector<std::uint8_t> evidential, betp, conflict;
	std::string text;
	std::size_t occupied = 0;
	std::vector<float> occupancy;
	std::vector<double> likelihoods;
	std::vector<std::pair<double, double>> occupiedCentres;
	std::vector<std::uint8_t> serialized, copySerialized;
};

std::vector<std::uint8_t> pixels(const mrpt::img::CImage& img)
{
	std::vector<std::uint8_t> out;
	for (unsigned row = 0; row < img.getHeight(); ++row)
	{
		const auto* line = img.ptrLine<std::uint8_t>(row);
		out.insert(out.end(), line, line + img.getWidth() * img.channelCount());
	}
	return out;
}

/** Everything, and the saved files under `prefix` when it is not empty. */
Readings readAll(
	const CEvidentialGridMap2D& map, const CObservation2DRangeScan& scan,
	const std::vector<CPose3D>& poses, const std::string& prefix = "")
{
	Readings r;
	// Likelihood first, so that threads race to build the field.
	for (const CPose3D& p : poses)
		r.likelihoods.push_back(map.computeObservationLikelihood(scan, p));
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
			r.masses.push_back(map.getCellMassesByIndex(cx, cy));
	mrpt::img::CImage img;
	map.getAsEvidentialImage(img);
	r.evidential = pixels(img);
	map.getAsBetPImage(img);
	r.betp = pixels(img);
	map.getAsConflictImage(img);
	r.conflict = pixels(img);
	r.text = map.asString();
	r.occupied = map.countDecisions().occupied;
	mrpt::maps::COccupancyGridMap2D grid;
	map.getAsOccupancyGrid(grid);
	for (unsigned cy = 0; cy < grid.getSizeY(); cy += 7)
		for (unsigned cx = 0; cx < grid.getSizeX(); cx += 7)
			r.occupancy.push_back(grid.getCell(static_cast<int>(cx), static_cast<int>(cy)));
	r.occupiedCentres = map.getOccupiedCellCenters();
	r.serialized = serialize(map);
	const CEvidentialGridMap2D copy = map;
	r.copySerialized = serialize(copy);
	if (!prefix.empty()) map.saveMetricMapRepresentationToFile(prefix);
	return r;
}

void expectEqual(const Readings& a, const Readings& b, int thread)
{
	EXPECT_EQ(a.likelihoods, b.likelihoods) << "thread " << thread;
	EXPECT_TRUE(a.masses == b.masses) << "thread " << thread;
	EXPECT_TRUE(a.evidential == b.evidential) << "thread " << thread;
	EXPECT_TRUE(a.betp == b.betp) << "thread " << thread;
	EXPECT_TRUE(a.conflict == b.conflict) << "thread " << thread;
	EXPECT_EQ(a.text, b.text) << "thread " << thread;
	EXPECT_EQ(a.occupied, b.occupied) << "thread " << thread;
	EXPECT_EQ(a.occupancy, b.occupancy) << "thread " << thread;
	EXPECT_EQ(a.occupiedCentres, b.occupiedCentres) << "thread " << thread;
	EXPECT_TRUE(a.serialized == b.serialized) << "thread " << thread;
	EXPECT_TRUE(a.copySerialized == b.serialized) << "thread " << thread;
}
}  // namespace

TEST(Threads, ConstMethodsRunConcurrentlyWithColdAndWarmCaches)
{
	CEvidentialGridMap2D map(-4, 4, -4, 4, 0.05);
	map.insertionOptions.decayRate = 0.05;  // reads go through the decay
	const CObservation2DRangeScan probe = roomScan(0.3, -0.2, 0.5, 10.0);
	const std::vector<CPose3D> poses = {
		CPose3D(0.3, -0.2, 0, 0.5, 0, 0), CPose3D(0.5, -0.2, 0, 0.5, 0, 0),
		CPose3D(0.3, -0.2, 0, 0.6, 0, 0), CPose3D(9.0, 9.0, 0, 0, 0, 0)};
	const std::string scratch = std::string(TEST_SCRATCH_DIR) + "/threads";
	std::filesystem::create_directories(scratch);
	for (int round = 0; round < 3; ++round)
	{
		// One more scan per round (no thread reads meanwhile): the field is
		// dropped, and the next round builds it again concurrently.
		ASSERT_TRUE(map.insertObservation(
			roomScan(0.4 * round - 0.4, 0.2 * round, 0.3 * round, round),
			CPose3D(0.4 * round - 0.4, 0.2 * round, 0, 0.3 * round, 0, 0)));
		if (round == 2) map.likelihoodOptions.decimation = 2;
		// The expected values from a copy, so that the map's own field stays
		// unbuilt until the threads start.
		const CEvidentialGridMap2D copy = map;
		const Readings expected = readAll(copy, probe, poses);
		ASSERT_GT(expected.occupied, 100u);

		std::vector<Readings> got(kThreads);
		test::runTogether(kThreads, [&](int t) {
			got[t] = readAll(map, probe, poses, scratch + "/thread" + std::to_string(t));
		});
		for (int t = 0; t < kThreads; ++t) expectEqual(got[t], expected, t);
	}
}

namespace
{
/** A room where a box slides and a person walks (events within the motion
 * window at the end), scanned by a robot that sways and
 * turns (so that bands meet moving things, walls and impacts), into a map
 * of the given settings. */
CEvidentialGridMap2D mapOfMovingBox(
	unsigned threads, ConflictHandling handling, FusionRule rule, double decayRate)
{
	// Cells of 2 cm: each scan's box of some 130,000 cells is worth three
	// bands (smaller scans keep to one thread).
	CEvidentialGridMap2D map(-5, 5, -4, 4, 0.02);
	auto& io = map.insertionOptions;
	io.maxRange = 15.0;
	io.conflictHandling = handling;
	io.fusionRule = rule;
	io.decayRate = decayRate;
	io.insertionThreads = threads;
	const test::ScanSetup setup = test::ScanSetup().maxRange(15.0);
	for (int k = 0; k < 60; ++k)
	{
		// The box slides 0.1 m a scan from scan 40 on, a person walks across.
		std::vector<test::TBox> boxes = test::roomWalls();
		const double slide = 0.1 * std::max(0, k - 40);
		boxes.push_back({-1.2 + slide, -0.2, -0.8 + slide, 0.2});
		const double walk = -3.0 + 0.12 * k;
		boxes.push_back({walk, 1.5, walk + 0.4, 1.9});
		const double s = 0.1 * k;
		const mrpt::poses::CPose3D pose(
			0.5 * std::sin(s), -2.0 + 0.3 * std::cos(s), 0.0, M_PI / 2 + 1.2 * std::sin(0.7 * s),
			0, 0);
		map.insertObservation(test::scanOfBoxes(boxes, pose, setup.at(0.1 * k)), pose);
	}
	return map;
}
}  // namespace

TEST(Threads, InsertionOnSeveralThreadsGivesTheMapOfOne)
{
	struct TCase
	{
		ConflictHandling handling;
		FusionRule rule;
		double decayRate;
	};
	for (const TCase& c :
		 {TCase{ConflictHandling::Normalize, FusionRule::Conjunctive, 0.05},
		  TCase{ConflictHandling::Normalize, FusionRule::Conjunctive, 0.0},
		  TCase{ConflictHandling::Keep, FusionRule::Conjunctive, 0.05},
		  TCase{ConflictHandling::ToUnknown, FusionRule::Yager, 0.0}})
	{
		const CEvidentialGridMap2D one = mapOfMovingBox(1, c.handling, c.rule, c.decayRate);
		const auto expected = serialize(one);
		if (c.handling != ConflictHandling::Keep)
		{
			ASSERT_GT(one.countMotion().appeared + one.countMotion().disappeared, 0u)
				<< "the box's move must give the bands motion events to agree on";
		}
		for (const unsigned threads : {2u, 3u, 8u})
		{
			CEvidentialGridMap2D many = mapOfMovingBox(threads, c.handling, c.rule, c.decayRate);
			// The same cells and motion memory; the files differ by the option.
			many.insertionOptions.insertionThreads = 1;
			EXPECT_TRUE(serialize(many) == expected)
				<< threads << " threads, handling " << int(c.handling) << ", rule "
				<< int(c.rule) << ", decay " << c.decayRate;
		}
	}
}
