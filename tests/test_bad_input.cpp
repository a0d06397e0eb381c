/* Bad input to CEvidentialGridMap2D: broken scans and poses, scans far away,
 * options set wrong in code, forged map files, and a million fusions at the
 * corners of the algebra and of the decay. Each gets a clear exception or a
 * documented safe behaviour, and the map stays valid (doc/reliability.md). */
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "support/map_bytes.h"
#include "support/whole_read_archive.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::serialize;
using mrpt_evidential::test::deserialize;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;
using mrpt::serialization::archiveFrom;

// ---------------------------------------------------------------------------
// The largest single allocation of this test program, to prove that forged
// sizes are not allocated. Requests above a gigabyte fail at once, so that a
// regression fails fast instead of filling gigabytes with zeros.
// ---------------------------------------------------------------------------
namespace
{
std::atomic<std::size_t> g_largestAllocation{0};
constexpr std::size_t kAllocationCeiling = std::size_t(1) << 30;
}  // namespace

void* operator new(std::size_t size)
{
	std::size_t seen = g_largestAllocation.load(std::memory_order_relaxed);
	while (size > seen && !g_largestAllocation.compare_exchange_weak(seen, size))
	{
	}
	if (size > kAllocationCeiling) throw std::bad_alloc();
	if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
	throw std::bad_alloc();
}
// Not inlined: g++ would then see new's pointer reach free() and warn.
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept
{
	std::free(p);
}

namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const double kDeg = M_PI / 180.0;

/** n beams over `aperture`, range rangeAt(beam angle), all flagged valid. */
CObservation2DRangeScan makeScan(
	std::size_t n, double aperture, const std::function<double(double)>& rangeAt,
	double time = 0.0)
{
	CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(aperture);
	scan.maxRange = 30.0f;
	scan.timestamp = mrpt::Clock::fromDouble(time);
	scan.resizeScan(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		scan.setScanRange(
			i, static_cast<float>(rangeAt(n > 1 ? scan.getScanAngle(i) : 0.0)));
		scan.setScanRangeValidity(i, true);
	}
	return scan;
}

CObservation2DRangeScan wall(double range = 3.0, double time = 0.0)
{
	return makeScan(181, M_PI, [range](double) { return range; }, time);
}

CEvidentialGridMap2D makeMap()
{
	return CEvidentialGridMap2D(-5, 5, -5, 5, 0.1);
}

/** Every cell a valid mass function, within the cell budget. */
::testing::AssertionResult mapIsValid(const CEvidentialGridMap2D& map)
{
	if (map.geometry().cellCount() > map.maxCells())
		return ::testing::AssertionFailure()
			<< map.geometry().cellCount() << " cells exceed the budget of "
			<< map.maxCells();
	for (std::size_t i = 0; i < map.geometry().cellCount(); ++i)
		if (!map.storage().read(i).isValid(1e-9))
			return ::testing::AssertionFailure()
				<< "cell " << i << " holds " << map.storage().read(i);
	return ::testing::AssertionSuccess();
}

/** Same geometry and the same cells, decayed reads included. */
::testing::AssertionResult sameCells(
	const CEvidentialGridMap2D& a, const CEvidentialGridMap2D& b, double tol = 0.0)
{
	if (a.getSizeX() != b.getSizeX() || a.getSizeY() != b.getSizeY() ||
		a.getXMin() != b.getXMin() || a.getYMin() != b.getYMin())
		return ::testing::AssertionFailure() << "geometries differ";
	for (std::size_t i = 0; i < a.geometry().cellCount(); ++i)
		if (maxAbsDifference(a.storage().read(i), b.storage().read(i)) > tol)
			return ::testing::AssertionFailure()
				<< "cell " << i << ": " << a.storage().read(i) << " vs "
				<< b.storage().read(i);
	return ::testing::AssertionSuccess();
}

std::size_t informedCells(const CEvidentialGridMap2D& map)
{
	std::size_t n = 0;
	for (std::size_t i = 0; i < map.geometry().cellCount(); ++i)
		if (map.storage().read(i) != Mass::vacuous()) ++n;
	return n;
}

/** Runs f and returns what it wrote to stderr. */
std::string stderrOf(const std::function<void()>& f)
{
	::testing::internal::CaptureStderr();
	f();
	return ::testing::internal::GetCapturedStderr();
}

/** Writes the checksum a stream's payload should have, as a forger would:
 * FNV-1a (64 bit) of everything between MRPT's header (class name and
 * version) and the checksum, which precedes MRPT's one-byte end marker. */
void reseal(std::vector<std::uint8_t>& bytes)
{
	const std::size_t begin = 1 + (bytes[0] & 0x7F) + 1, end = bytes.size() - 9;
	std::uint64_t h = 0xcbf29ce484222325ULL;
	for (std::size_t i = begin; i < end; ++i) h = (h ^ bytes[i]) * 0x100000001b3ULL;
	for (int i = 0; i < 8; ++i) bytes[end + i] = static_cast<std::uint8_t>(h >> (8 * i));
}

void putLE(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t v, int n)
{
	for (int i = 0; i < n; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
/** How many times `needle` occurs in `text`. */
std::size_t occurrences(const std::string& text, const std::string& needle)
{
	std::size_t n = 0;
	for (auto p = text.find(needle); p != std::string::npos;
		 p = text.find(needle, p + 1))
		++n;
	return n;
}
}  // namespace

// ---------------------------------------------------------------------------
// Scans
// ---------------------------------------------------------------------------

TEST(BadScan, NonFiniteNegativeAndZeroRangesAreNoReturn)
{
	// Beams flagged valid whose range is NaN, +-inf, negative or zero count
	// as beams without a return: the map equals the one where they are
	// flagged invalid.
	const std::vector<double> bad = {kNaN, kInf, -kInf, -1.0, -1e-30, 0.0, -0.0};
	auto scan = wall(3.0);
	auto flagged = scan;
	for (std::size_t i = 0; i < scan.getScanSize(); i += 3)
	{
		scan.setScanRange(i, static_cast<float>(bad[(i / 3) % bad.size()]));
		flagged.setScanRangeValidity(i, false);
	}
	for (const bool asFree : {false, true})
	{
		CEvidentialGridMap2D withBad = makeMap(), withFlags = makeMap();
		withBad.insertionOptions.invalidRangesAsFree = asFree;
		withFlags.insertionOptions.invalidRangesAsFree = asFree;
		ASSERT_TRUE(withBad.insertObservation(scan, CPose3D()));
		ASSERT_TRUE(withFlags.insertObservation(flagged, CPose3D()));
		EXPECT_TRUE(mapIsValid(withBad));
		EXPECT_TRUE(sameCells(withBad, withFlags)) << "invalidRangesAsFree " << asFree;
		EXPECT_GT(withBad.countDecisions().occupied, 20u);
	}
}

TEST(BadScan, EveryRayInvalidChangesNoCell)
{
	for (const double r : {kNaN, kInf, -2.0, 0.0})
	{
		CEvidentialGridMap2D map = makeMap();
		const auto scan = wall(r, 10.0);
		ASSERT_TRUE(map.insertObservation(scan, CPose3D()));
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_EQ(informedCells(map), 0u) << "range " << r;
		EXPECT_EQ(map.getSizeX(), 100);  // nothing to grow for
		// Read as free space when asked to: up to maxRange, nothing occupied.
		map.insertionOptions.invalidRangesAsFree = true;
		map.insertionOptions.maxRange = 2.0;
		ASSERT_TRUE(map.insertObservation(scan, CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_EQ(decide(map.getCellMasses(1.5, 0.0)), Decision::Free);
		EXPECT_EQ(map.getCellMasses(2.5, 0.0), Mass::vacuous());
		EXPECT_EQ(map.countDecisions().occupied, 0u);
	}
}

TEST(BadScan, EmptyScanIsInsertedAndChangesNoCell)
{
	CEvidentialGridMap2D map = makeMap();
	map.insertionOptions.decayRate = 0.5;
	ASSERT_TRUE(map.insertObservation(wall(3.0, 100.0), CPose3D()));
	const Mass before = map.getCellMasses(1.5, 0.0);
	CObservation2DRangeScan empty;
	empty.timestamp = mrpt::Clock::fromDouble(102.0);
	ASSERT_TRUE(map.insertObservation(empty, CPose3D()));
	// Its time counts (data time moves on, older evidence decays), nothing
	// else does.
	EXPECT_EQ(map.insertionCount(), 2u);
	EXPECT_NEAR(map.latestTime(), 102.0, 1e-6);
	EXPECT_MASS_NEAR(
		map.getCellMasses(1.5, 0.0), discount(before, 1.0 - std::exp(-1.0)),
		2.0 / kMassScale);
	EXPECT_TRUE(mapIsValid(map));
}

TEST(BadScan, SingleRayCoversItsAperture)
{
	// One beam covers the scan's aperture, centred straight ahead.
	CEvidentialGridMap2D map = makeMap();
	ASSERT_TRUE(map.insertObservation(
		makeScan(1, 10 * kDeg, [](double) { return 3.0; }), CPose3D()));
	EXPECT_TRUE(mapIsValid(map));
	EXPECT_EQ(decide(map.getCellMasses(1.5, 0.0)), Decision::Free);
	EXPECT_EQ(map.getCellMasses(1.5, 1.0), Mass::vacuous());  // 34 degrees off
	EXPECT_EQ(map.getCellMasses(-1.5, 0.0), Mass::vacuous());
	EXPECT_GT(map.countDecisions().occupied, 0u);
}

TEST(BadScan, ApertureOutOfRangeIsRejected)
{
	CEvidentialGridMap2D map = makeMap();
	ASSERT_TRUE(map.insertObservation(wall(3.0, 1.0), CPose3D()));
	const CEvidentialGridMap2D before = map;
	for (const double aperture : {0.0, -1.0, 2 * M_PI + 0.01, 7.0, 1e30, kNaN, kInf})
	{
		auto scan = wall(3.0, 2.0);
		scan.aperture = static_cast<float>(aperture);
		try
		{
			map.insertObservation(scan, CPose3D());
			ADD_FAILURE() << "aperture " << aperture << " was accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("aperture"), std::string::npos)
				<< e.what();
		}
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_EQ(map.latestTime(), before.latestTime());
		EXPECT_TRUE(sameCells(map, before)) << "aperture " << aperture;
	}
	// A full turn is fine.
	auto round = makeScan(360, 2 * M_PI, [](double) { return 3.0; }, 2.0);
	EXPECT_TRUE(map.insertObservation(round, CPose3D()));
	EXPECT_EQ(decide(map.getCellMasses(-1.5, 0.0)), Decision::Free);
	EXPECT_TRUE(mapIsValid(map));
}

TEST(BadScan, TinyApertureInformsNoMoreThanItsWedge)
{
	for (const double aperture : {1e-6, 1e-30})
	{
		CEvidentialGridMap2D map = makeMap();
		ASSERT_TRUE(map.insertObservation(
			makeScan(181, aperture, [](double) { return 3.0; }), CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_LT(informedCells(map), 40u) << "aperture " << aperture;
	}
}

TEST(BadScan, SingleRayApertureOutOfRangeIsRejected)
{
	CEvidentialGridMap2D map = makeMap();
	for (const double aperture : {0.0, -1.0, 2 * M_PI + 0.01, 7.0, 1e30, kInf, kNaN})
	{
		EXPECT_THROW(
			map.insertObservation(
				makeScan(1, aperture, [](double) { return 3.0; }), CPose3D()),
			std::invalid_argument)
			<< "aperture " << aperture;
		EXPECT_TRUE(map.isEmpty());
	}
}

TEST(BadScan, ValidityAlwaysAsLongAsTheRanges)
{
	// MRPT keeps the validity flags private and sizes them with the ranges
	// in every way a scan can be made, deserialization included; reading a
	// flag past the end throws. A shorter validity vector therefore cannot
	// reach the map: this pins the assumption.
	CObservation2DRangeScan scan;
	scan.resizeScan(7);
	EXPECT_THROW(scan.getScanRangeValidity(7), std::exception);
	scan.resizeScanAndAssign(9, 1.0f, true);
	const std::vector<float> ranges(11, 2.0f);
	const std::vector<char> valid(11, 1);
	scan.loadFromVectors(ranges.size(), ranges.data(), valid.data());
	EXPECT_EQ(scan.getScanSize(), 11u);
	EXPECT_NO_THROW(scan.getScanRangeValidity(10));

	// A stream cut anywhere, inside the validity flags included, is an
	// error, not a short vector. The cuts are read as evgrid reads files,
	// whole fields or nothing: over MRPT's CMemoryStream a cut inside the ray
	// count hands MRPT a count made of uninitialized bytes, and it allocated
	// up to 20 GB for it (see CWholeReadArchive).
	mrpt::io::CMemoryStream buf;
	archiveFrom(buf) << scan;
	const auto* p = static_cast<const std::uint8_t*>(buf.getRawBufferData());
	const std::vector<std::uint8_t> bytes(p, p + buf.getTotalBytesCount());
	for (std::size_t len = 0; len < bytes.size(); ++len)
	{
		test::CWholeReadArchive cut(bytes.data(), len);
		CObservation2DRangeScan back;
		EXPECT_THROW(cut >> back, std::exception) << "a scan cut at byte " << len << " was read";
	}
	test::CWholeReadArchive whole(bytes);
	CObservation2DRangeScan back;
	whole >> back;
	EXPECT_EQ(back.getScanSize(), 11u);
	EXPECT_NO_THROW(back.getScanRangeValidity(10));
}

TEST(BadScan, RangesBeyondMaxRangeOnlyProveFreeSpace)
{
	for (const double r : {25.0, 1e6, 1e30, double(std::numeric_limits<float>::max())})
	{
		CEvidentialGridMap2D map = makeMap();
		map.insertionOptions.maxRange = 4.0;
		map.insertionOptions.growthMargin = 1.0;
		ASSERT_TRUE(map.insertObservation(wall(r), CPose3D()));
		EXPECT_TRUE(mapIsValid(map));
		EXPECT_EQ(map.countDecisions().occupied, 0u) << "range " << r;
		EXPECT_EQ(decide(map.getCellMasses(3.5, 0.0)), Decision::Free);
		EXPECT_EQ(map.getCellMasses(4.5, 0.0), Mass::vacuous());
		EXPECT_EQ(map.getSizeX(), 100) << "grew for a return beyond maxRange";
	}
}

TEST(BadScan, ClockwiseScanEqualsReversedCounterclockwiseOne)
{
	// rightToLeft = false: beam i is at +aperture/2 - i * step.
	const auto range = [](double a) { return 2.0 + std::sin(3 * a) + 0.5 * (a > 0); };
	const auto ccw = makeScan(181, M_PI, range);
	CObservation2DRangeScan cw = ccw;
	cw.rightToLeft = false;
	for (std::size_t i = 0; i < 181; ++i)
		cw.setScanRange(i, ccw.getScanRange(180 - i));
	CEvidentialGridMap2D a = makeMap(), b = makeMap();
	ASSERT_TRUE(a.insertObservation(ccw, CPose3D(0.3, -0.2, 0, 0.4, 0, 0)));
	ASSERT_TRUE(b.insertObservation(cw, CPose3D(0.3, -0.2, 0, 0.4, 0, 0)));
	EXPECT_TRUE(mapIsValid(b));
	EXPECT_TRUE(sameCells(a, b, 2.0 / kMassScale));
}

TEST(BadScan, UpsideDownClockwiseSensorEqualsUprightCounterclockwiseOne)
{
	// Mounted upside down, a sensor that scans clockwise in its own frame
	// scans counterclockwise in the map: same ranges, same map.
	const auto range = [](double a) { return 2.0 + std::sin(3 * a) + 0.5 * (a > 0); };
	const auto upright = makeScan(181, M_PI, range);
	CObservation2DRangeScan flipped = upright;
	flipped.rightToLeft = false;
	flipped.sensorPose = CPose3D(0, 0, 0, 0, 0, M_PI);
	CEvidentialGridMap2D a = makeMap(), b = makeMap();
	ASSERT_TRUE(a.insertObservation(upright, CPose3D(-0.5, 0.5, 0, 1.0, 0, 0)));
	ASSERT_TRUE(b.insertObservation(flipped, CPose3D(-0.5, 0.5, 0, 1.0, 0, 0)));
	EXPECT_TRUE(mapIsValid(b));
	// The mirrored transform rounds differently at cells on a sector edge.
	EXPECT_TRUE(sameCells(a, b, 1e-3));
}

TEST(BadScan, TiltedSensorIsIgnoredWithOneNote)
{
	CEvidentialGridMap2D map = makeMap();
	const std::string err = stderrOf([&] {
		for (const CPose3D& sensorPose :
			 {CPose3D(0, 0, 0, 0, 5 * kDeg, 0), CPose3D(0, 0, 0, 0.3, 0, -10 * kDeg),
			  CPose3D(0, 0, 0, 0, 89 * kDeg, 0)})
		{
			auto scan = wall();
			scan.sensorPose = sensorPose;
			EXPECT_FALSE(map.insertObservation(scan, CPose3D()));
		}
		// A robot pitched on a ramp tilts its sensor just the same.
		EXPECT_FALSE(map.insertObservation(wall(), CPose3D(0, 0, 0, 0, 3 * kDeg, 0)));
	});
	EXPECT_EQ(occurrences(err, "horizontalTolerance"), 1u) << err;
	EXPECT_TRUE(map.isEmpty());
	EXPECT_EQ(informedCells(map), 0u);
}

// ---------------------------------------------------------------------------
// Poses
// ---------------------------------------------------------------------------

TEST(BadPose, NonFinitePoseThrowsAndChangesNothing)
{
	CEvidentialGridMap2D map = makeMap();
	ASSERT_TRUE(map.insertObservation(wall(3.0, 1.0), CPose3D()));
	const CEvidentialGridMap2D before = map;
	const std::vector<std::pair<CPose3D, CPose3D>> cases = {
		{CPose3D(kNaN, 0, 0, 0, 0, 0), CPose3D()},
		{CPose3D(0, kInf, 0, 0, 0, 0), CPose3D()},
		{CPose3D(0, 0, -kInf, 0, 0, 0), CPose3D()},
		{CPose3D(0, 0, 0, kNaN, 0, 0), CPose3D()},
		{CPose3D(0, 0, 0, 0, kNaN, 0), CPose3D()},
		{CPose3D(), CPose3D(0, 0, 0, 0, 0, kNaN)},
		{CPose3D(), CPose3D(kNaN, kNaN, kNaN, 0, 0, 0)}};
	for (const auto& [robot, sensorPose] : cases)
	{
		auto scan = wall(3.0, 2.0);
		scan.sensorPose = sensorPose;
		try
		{
			map.insertObservation(scan, robot);
			ADD_FAILURE() << "pose " << robot.asString() << " accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos)
				<< e.what();
		}
		EXPECT_EQ(map.insertionCount(), 1u);
		EXPECT_TRUE(sameCells(map, before));
		// Scoring at such a pose gives a number, never NaN.
		EXPECT_FALSE(std::isnan(map.computeObservationLikelihood(scan, robot)));
	}
}

TEST(BadPose, FarPoseIsInsertedOnlyWhereItOverlapsTheGrid)
{
	// 1000 km away at 0.1 m cells: growth would exceed the cell budget, so
	// the grid stays and the scan, which does not overlap it, changes nothing.
	for (const double far : {1e6, -1e6})
	{
		CEvidentialGridMap2D map = makeMap();
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, 0, 0, 0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(0, far, 0, 0, 0, 0)));
		EXPECT_EQ(map.getSizeX(), 100);
		EXPECT_EQ(map.getSizeY(), 100);
		EXPECT_EQ(informedCells(map), 0u);
		EXPECT_FALSE(std::isnan(
			map.computeObservationLikelihood(wall(), CPose3D(far, far, 0, 0, 0, 0))));
	}
}

TEST(BadPose, FarAndNaNPointsReadAsOutside)
{
	const CEvidentialGridMap2D map = makeMap();
	const GridGeometry& g = map.geometry();
	for (const double v : {1e300, -1e300, 1e10, kInf, -kInf, kNaN})
	{
		EXPECT_FALSE(g.inside(g.cellX(v), 0)) << v;
		EXPECT_FALSE(g.inside(0, g.cellY(v))) << v;
		EXPECT_EQ(map.getCellMasses(v, 0.0), Mass::vacuous());
		EXPECT_EQ(map.getCellBetP(0.0, v), 0.5);
	}
	EXPECT_EQ(g.cellX(1e300), std::numeric_limits<int>::max());
	EXPECT_EQ(g.cellX(-1e300), std::numeric_limits<int>::min());
	EXPECT_EQ(g.cellX(0.05), 50);
}

TEST(BadPose, PoseAtABillionMetresChangesNothing)
{
	for (const double far : {1e9, -1e9, 1e300})
	{
		CEvidentialGridMap2D map = makeMap();
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, 0, 0, 0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(0, far, 0, 2.0, 0, 0)));
		ASSERT_TRUE(map.insertObservation(wall(), CPose3D(far, far, 0, 0, 0, 0)));
		EXPECT_EQ(map.getSizeX(), 100);
		EXPECT_EQ(informedCells(map), 0u);
	}
}

// ---------------------------------------------------------------------------
// Growth
// ---------------------------------------------------------------------------

TEST(Growth, StopsAtTheCellBudgetWithOneWarning)
{
	CEvidentialGridMap2D map = makeMap();  // 10,000 cells
	map.setMaxCells(40'000);
	map.insertionOptions.growthMargin = 1.0;
	std::size_t largest = 0;
	const std::string err = stderrOf([&] {
		// Farther and farther: the first scans fit, the last ones cannot.
		for (const double x : {4.0, 8.0, 12.0, 50.0, 500.0, 5e4, 5e5})
		{
			ASSERT_TRUE(map.insertObservation(wall(), CPose3D(x, 0, 0, 0, 0, 0)));
			ASSERT_LE(map.geometry().cellCount(), map.maxCells()) << "at " << x;
			largest = std::max(largest, map.geometry().cellCount());
		}
	});
	EXPECT_GT(largest, 10'000u);  // it did grow while it could
	EXPECT_EQ(occurrences(err, "maxCells"), 1u) << err;
	EXPECT_TRUE(mapIsValid(map));
	// Scans within the grid still go in.
	const auto counts = map.countDecisions();
	ASSERT_TRUE(map.insertObservation(wall(2.0), CPose3D(0, 0, 0, M_PI, 0, 0)));
	EXPECT_GT(map.countDecisions().free, counts.free);
}

TEST(Growth, RandomWalkAwayNeverExceedsTheBudget)
{
	CEvidentialGridMap2D map = makeMap();
	map.setMaxCells(200'000);
	map.insertionOptions.growthMargin = 2.0;
	test::MassGenerator gen(3);
	std::normal_distribution<double> step(3.0, 10.0);
	double x = 0, y = 0;
	stderrOf([&] {
		for (int k = 0; k < 200; ++k)
		{
			x += step(gen.rng());
			y += step(gen.rng());
			ASSERT_TRUE(map.insertObservation(
				wall(1.0 + k % 7, k), CPose3D(x, y, 0, 0.1 * k, 0, 0)));
			ASSERT_LE(map.geometry().cellCount(), map.maxCells());
		}
	});
	EXPECT_TRUE(mapIsValid(map));
}

// ---------------------------------------------------------------------------
// Options set in code (the .ini readers are tested in test_map_ini.cpp)
// ---------------------------------------------------------------------------

TEST(BadOptions, InvalidInsertionOptionsStopInsertionNamingTheField)
{
	using Options = CEvidentialGridMap2D::TInsertionOptions;
	const std::vector<std::pair<std::string, std::function<void(Options&)>>> cases = {
		{"muF", [](Options& o) { o.muF = 1.5; }},
		{"muO", [](Options& o) { o.muO = kNaN; }},
		{"decayRate", [](Options& o) { o.decayRate = -1e-9; }},
		{"decayRate", [](Options& o) { o.decayRate = kInf; }},
		{"maxRange", [](Options& o) { o.maxRange = 0.0; }},
		{"imprecision", [](Options& o) { o.imprecision = -0.1; }},
		{"sectorWidth", [](Options& o) { o.sectorWidth = 7.0; }},
		{"horizontalTolerance", [](Options& o) { o.horizontalTolerance = -1.0; }},
		{"growthMargin", [](Options& o) { o.growthMargin = kNaN; }},
		{"fusionRule", [](Options& o) { o.fusionRule = static_cast<FusionRule>(17); }},
		{"sensorModel", [](Options& o) { o.sensorModel = static_cast<SensorModel>(9); }},
		{"conflictHandling",
		 [](Options& o) { o.conflictHandling = static_cast<ConflictHandling>(5); }},
	};
	for (const auto& [field, spoil] : cases)
	{
		CEvidentialGridMap2D map = makeMap();
		spoil(map.insertionOptions);
		try
		{
			map.insertObservation(wall(), CPose3D());
			ADD_FAILURE() << field << " accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find(field), std::string::npos)
				<< e.what();
		}
		EXPECT_TRUE(map.isEmpty()) << field;
		EXPECT_EQ(informedCells(map), 0u) << field;
	}
}

TEST(BadOptions, InvalidGeometryIsRejected)
{
	// Beyond the limits too: cells below a micrometre or above 1000 km,
	// bounds beyond 1e9 m.
	for (const auto& [x0, x1, res] : std::vector<std::tuple<double, double, double>>{
			 {0, 1, 0.0}, {0, 1, -0.1}, {0, 1, kNaN}, {0, 1, kInf}, {1, 1, 0.1},
			 {2, 1, 0.1}, {kNaN, 1, 0.1}, {-kInf, 1, 0.1}, {-1e9, 1e9, 1e-9},
			 {0, 1, 1e-7}, {0, 1e7, 1e7}, {2e9, 2e9 + 1, 0.5}, {-1e10, 0, 1e5}})
	{
		EXPECT_THROW(CEvidentialGridMap2D(x0, x1, 0, 1, res), std::invalid_argument)
			<< x0 << " " << x1 << " " << res;
		CEvidentialGridMap2D map = makeMap();
		EXPECT_THROW(map.setSize(x0, x1, 0, 1, res), std::invalid_argument);
		EXPECT_EQ(map.getSizeX(), 100);  // unchanged
	}
	CEvidentialGridMap2D map = makeMap();
	EXPECT_THROW(map.setMaxCells(0), std::invalid_argument);
	EXPECT_THROW(map.setMaxCells(9'999), std::invalid_argument);
	EXPECT_EQ(map.maxCells(), CEvidentialGridMap2D::kDefaultMaxCells);
}

TEST(BadOptions, WideLikelihoodMarginOnAThinMapAllocatesLittle)
{
	// A 10 km corridor of one row, and distances cut at 60 m: a margin of
	// 1024 cells on every side would make the field 2000 times the map.
	CEvidentialGridMap2D map(0, 10'000, 0, 0.05, 0.05);
	map.likelihoodOptions.maxCorrsDistance = 60.0;
	g_largestAllocation = 0;
	const double l = map.computeObservationLikelihood(wall(), CPose3D(5000, 0, 0, 0, 0, 0));
	EXPECT_TRUE(std::isfinite(l));
	EXPECT_LT(g_largestAllocation.load(), std::size_t(64) << 20);
}

TEST(BadOptions, ExtremeLikelihoodOptionsGiveNumbers)
{
	// Valid, if absurd: squares of these overflow.
	CEvidentialGridMap2D map = makeMap();
	ASSERT_TRUE(map.insertObservation(wall(), CPose3D()));
	auto& o = map.likelihoodOptions;
	for (const auto& [sigma, cut, zHit, zRandom, range] :
		 std::vector<std::tuple<double, double, double, double, double>>{
			 {7.5e252, 7.5e252, 5.5e16, 9.4e11, 9.4e78},
			 {1e-300, 1e300, 1.0, 0.0, 1e300},
			 {1e300, 1e-300, 0.0, 1e-300, 1e-300}})
	{
		o.sigma = sigma;
		o.maxCorrsDistance = cut;
		o.zHit = zHit;
		o.zRandom = zRandom;
		o.maxRange = range;
		const double l = map.computeObservationLikelihood(wall(), CPose3D());
		EXPECT_FALSE(std::isnan(l)) << "sigma " << sigma << " cut " << cut;
	}
}

TEST(BadOptions, LongMaxRangeAtFineResolutionAllocatesLittle)
{
	// Dense polar rows would take 1081 x 100,000 masses of 32 bytes (3.5 GB)
	// whatever the ranges; sparse rows hold a few bins per sector.
	CEvidentialGridMap2D map(-5, 5, -5, 5, 0.01);
	map.insertionOptions.maxRange = 1000.0;
	g_largestAllocation = 0;
	EXPECT_NO_THROW(map.insertObservation(
		makeScan(1081, 1.5 * M_PI, [](double) { return 3.0; }), CPose3D()));
	EXPECT_LT(g_largestAllocation.load(), std::size_t(1) << 20);
}

// ---------------------------------------------------------------------------
// Files (truncation, flipped bytes and unknown versions: test_map_io.cpp)
// ---------------------------------------------------------------------------

TEST(BadFile, ForgedHugeGridAllocatesOnlyWhatTheStreamHolds)
{
	// A stream whose header claims 30,000 x 30,000 cells (7.2 GB) within a
	// budget it also claims, then ends: the read must fail having allocated
	// about what the stream held, not the 7.2 GB.
	auto bytes = serialize(CEvidentialGridMap2D(0, 1, 0, 1, 0.5));
	// After MRPT's header: f64 xMin, yMin, resolution, i32 sizeX, sizeY,
	// u64 maxCells (little-endian).
	const std::size_t geometry = 1 + (bytes[0] & 0x7F) + 1;
	putLE(bytes, geometry + 24, 30'000, 4);
	putLE(bytes, geometry + 28, 30'000, 4);
	putLE(bytes, geometry + 32, 900'000'000, 8);
	for (const std::size_t keep : {bytes.size(), bytes.size() - 40})
	{
		mrpt::io::CMemoryStream in;
		in.assignMemoryNotOwn(bytes.data(), keep);
		CEvidentialGridMap2D target;
		g_largestAllocation = 0;
		try
		{
			archiveFrom(in) >> target;
			ADD_FAILURE() << "a forged stream was read";
		}
		catch (const std::bad_alloc&)
		{
			ADD_FAILURE() << "tried to allocate the claimed size";
		}
		catch (const std::exception&)
		{
		}
		EXPECT_LT(g_largestAllocation.load(), std::size_t(64) << 20) << keep << " bytes";
		EXPECT_EQ(target.getSizeX(), 200);  // unchanged
	}
}

TEST(BadFile, ResealedStreamsStillPassTheChecks)
{
	// A checksum stops damage, not a forger: what it covers is checked too.
	CEvidentialGridMap2D map(0, 1, 0, 1, 0.5);
	map.insertionOptions.decayRate = 0.1;
	ASSERT_TRUE(map.insertObservation(wall(0.6, 5.0), CPose3D()));
	ASSERT_TRUE(map.insertObservation(wall(0.6, 6.0), CPose3D()));
	const auto good = serialize(map);
	{
		auto bytes = good;
		reseal(bytes);
		ASSERT_EQ(bytes, good);  // reseal() computes what the map wrote
		CEvidentialGridMap2D back;
		deserialize(bytes, back);
		EXPECT_EQ(back.insertionCount(), 2u);
	}
	const std::size_t geometry = 1 + (good[0] & 0x7F) + 1;
	const std::size_t cells = static_cast<std::size_t>(map.getSizeX() * map.getSizeY());
	const std::size_t insertions = good.size() - 9 - cells * 8 - 16;
	struct Forgery
	{
		const char* what;
		std::size_t at;
		std::uint64_t value;
		int bytes;
	};
	for (const Forgery& f :
		 {Forgery{"cell budget", geometry + 32, std::uint64_t(1) << 62, 8},
		  Forgery{"insertion times", insertions, 0, 8}})
	{
		auto bytes = good;
		putLE(bytes, f.at, f.value, f.bytes);
		reseal(bytes);
		CEvidentialGridMap2D target;
		EXPECT_THROW(deserialize(bytes, target), std::exception) << f.what;
		EXPECT_TRUE(target.isEmpty());
	}
}

TEST(BadFile, InconsistentStorageIsRejected)
{
	EvidentialGridStorage s;
	// Geometries beyond the limits (found by fuzz_deserialize: 4 cells of
	// 5.6e243 m made the insertion's squared reach infinite).
	for (const GridGeometry& g :
		 {GridGeometry{1e308, 0.0, 1e308, 2, 2}, GridGeometry{-2.2e43, -1.0, 5.6e243, 2, 2},
		  GridGeometry{0.0, 0.0, 1e-9, 2, 2}, GridGeometry{9.9e8, 0.0, 1e7, 2, 2}})
		EXPECT_THROW(
			s.assign(g, std::vector<QuantizedCell>(4), {0.0}, 0, 0.0),
			std::invalid_argument)
			<< g.xMin << " " << g.resolution;
	// A file may hold several insertion times only once something was
	// inserted: the first insertion would start the times again and leave
	// the cells stamped beyond them.
	std::vector<QuantizedCell> cells(4);
	cells[3].stamp = 2;
	cells[3].free = 30000;
	EXPECT_THROW(
		s.assign({0.0, 0.0, 1.0, 2, 2}, cells, {1.0, 2.0, 3.0}, 0, 0.5),
		std::invalid_argument);
	EXPECT_NO_THROW(s.assign({0.0, 0.0, 1.0, 2, 2}, cells, {1.0, 2.0, 3.0}, 3, 0.5));
	s.beginInsertion(10.0);
	EXPECT_TRUE(s.read(3).isValid(1e-9));
}

// ---------------------------------------------------------------------------
// Numbers: a million fusions through the cells, every rule, every conflict
// handling, total conflict, and decay from none to absurd rates and steps.
// ---------------------------------------------------------------------------

TEST(Numbers, MillionFusionsThroughTheCellsStayValid)
{
	const std::vector<double> rates = {0.0, 1e-300, 1e-9, 0.7, 1e3, 1e9, 1e300};
	// Time steps: none, tiny, usual, huge, backwards, and 400 years.
	const std::vector<double> steps = {0.0, 1e-9, 0.05, 1.0, 1e4, -3.0, 1.3e10};
	const std::vector<Mass> corners = {
		Mass::vacuous(), Mass::degenerate(), {0, 1, 0, 0}, {0, 0, 1, 0},
		{0, 0.5, 0.5, 0}, Mass::simpleFree(1e-300), {1e-300, 0, 0, 1 - 1e-300}};
	const FusionRule rules[] = {
		FusionRule::Conjunctive, FusionRule::Dempster, FusionRule::Yager,
		FusionRule::DuboisPrade, FusionRule::Cautious};
	const ConflictHandling handlings[] = {
		ConflictHandling::Keep, ConflictHandling::ToUnknown,
		ConflictHandling::Normalize};
	const auto handle = [](Mass m, ConflictHandling h) {
		if (h == ConflictHandling::ToUnknown)
			m = {0.0, m.free, m.occupied, m.unknown + m.conflict};
		else if (h == ConflictHandling::Normalize)
		{
			const double k = m.free + m.occupied + m.unknown;
			m = k > kTotalConflictTolerance
				? Mass{0.0, m.free / k, m.occupied / k, m.unknown / k}
				: Mass::vacuous();
		}
		return m;
	};

	test::MassGenerator gen(1234);
	std::uniform_int_distribution<std::size_t> pick(0, 1 << 20);
	constexpr std::size_t kCells = 64, kPerInsertion = 32;
	const std::size_t configs = rates.size() * 5 * 3;
	const std::size_t insertions = 1'000'000 / (configs * kPerInsertion) + 1;
	std::size_t fusions = 0;
	for (const double rate : rates)
		for (const FusionRule rule : rules)
			for (const ConflictHandling handling : handlings)
			{
				EvidentialGridStorage s;
				s.reset(0, 8, 0, 8, 1.0, kCells);
				s.setDecayRate(rate);
				double t = 0.0;
				for (std::size_t k = 0; k < insertions; ++k)
				{
					t += steps[pick(gen.rng()) % steps.size()];
					s.beginInsertion(t);
					for (std::size_t j = 0; j < kPerInsertion; ++j, ++fusions)
					{
						const std::size_t idx = pick(gen.rng()) % kCells;
						const Mass obs = pick(gen.rng()) % 3 == 0
							? corners[pick(gen.rng()) % corners.size()]
							: gen();
						const Mass old = s.read(idx);
						ASSERT_TRUE(old.isValid(1e-9))
							<< "rate " << rate << " t " << t << ": " << old;
						const Mass fused = handle(combine(rule, old, obs), handling);
						ASSERT_TRUE(fused.isValid(1e-9)) << fused;
						s.write(idx, fused);
					}
				}
				for (std::size_t i = 0; i < kCells; ++i)
					ASSERT_TRUE(s.read(i).isValid(1e-9))
						<< "rate " << rate << ": " << s.read(i);
			}
	EXPECT_GE(fusions, 1'000'000u);
}

TEST(Numbers, MapWithExtremeDecayAndTimeJumpsStaysValid)
{
	// Through the map's own insertion: a scan without a time stamp (it reads
	// as time 0, 1970), then scans from now, some going back in time, with
	// decay rates from tiny to absurd.
	for (const double rate : {1e-12, 0.1, 1e6, 1e300})
		for (const FusionRule rule : {FusionRule::Conjunctive, FusionRule::Dempster})
		{
			CEvidentialGridMap2D map = makeMap();
			map.insertionOptions.decayRate = rate;
			map.insertionOptions.fusionRule = rule;
			auto first = wall(3.0);
			first.timestamp = mrpt::Clock::time_point();
			ASSERT_TRUE(map.insertObservation(first, CPose3D()));
			double t = 1.7e9;
			for (const double step : {0.0, 0.1, 1e-6, -10.0, 5.0, 1e5})
			{
				t += step;
				ASSERT_TRUE(map.insertObservation(wall(2.5, t), CPose3D()));
				ASSERT_TRUE(mapIsValid(map)) << "rate " << rate << " step " << step;
			}
			EXPECT_GT(map.countDecisions().free, 100u) << "rate " << rate;
		}
}
