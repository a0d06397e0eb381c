/* Const methods of CEvidentialGridMap2D from several threads at once, while
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
