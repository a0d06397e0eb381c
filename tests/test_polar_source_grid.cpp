/* The polar SourceGrid of synthetic MRPT scans, and what it assumes of
 * MRPT's scans. */
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/scan/CPolarSourceGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/scans.h"
#include "support/test_helpers.h"
#include "support/whole_read_archive.h"

using namespace mrpt_evidential;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::serialization::archiveFrom;
using mrpt_evidential::test::CWholeReadArchive;

namespace
{
constexpr double kMuF = 0.7, kMuO = 0.9, kBin = 0.05;

/** The range beam i returns, as the scan stores it (float). */
double beamRange(std::size_t i)
{
	return static_cast<float>(2.0 + 0.01 * static_cast<double>(i));
}

/** 181 beams over 180 degrees; beam i returns at 2 + 0.01 i metres. */
CObservation2DRangeScan syntheticScan(bool rightToLeft = true)
{
	return test::scanByIndex(
		181, test::ScanSetup().maxRange(30.0).rightToLeft(rightToLeft), beamRange);
}

TSourceGridOptions options()
{
	TSourceGridOptions o;
	o.sensorModel.model = SensorModel::ReinforcedMultiEcho;
	o.sensorModel.muF = kMuF;
	o.sensorModel.muO = kMuO;
	o.binSize = kBin;
	o.maxRange = 10.0;
	return o;
}

/** The bin of a range, as SensorModel.h defines it. */
std::size_t binOf(double r) { return static_cast<std::size_t>(r / kBin + 1e-9); }

/** Free before the impact's bin, occupied at it, vacuous behind. */
void expectSingleImpactRow(const CPolarSourceGrid& grid, std::size_t s, double r)
{
	const std::size_t hit = binOf(r);
	for (std::size_t b = 0; b < grid.binCount(); ++b)
	{
		const Mass m = grid.at(s, b);
		ASSERT_TRUE(m.isValid());
		if (b < hit)
			ASSERT_MASS_NEAR_AT(m, Mass::simpleFree(kMuF), 1e-12, s, b);
		else if (b == hit)
			ASSERT_MASS_NEAR_AT(m, Mass::simpleOccupied(kMuO), 1e-12, s, b);
		else
			ASSERT_MASS_NEAR_AT(m, Mass::vacuous(), 1e-12, s, b);
	}
}
}  // namespace

TEST(PolarSourceGrid, OneSectorPerBeam)
{
	CPolarSourceGrid grid;
	grid.build(syntheticScan(), options());
	ASSERT_EQ(grid.sectorCount(), 181u);
	EXPECT_EQ(grid.binCount(), 200u);
	EXPECT_NEAR(grid.firstSectorAngle(), -M_PI / 2, 1e-6);
	EXPECT_NEAR(grid.sectorSpacing(), M_PI / 180, 1e-6);
	for (std::size_t s = 0; s < 181; ++s)
	{
		EXPECT_TRUE(grid.sectorObserved(s));
		expectSingleImpactRow(grid, s, beamRange(s));
	}
}

TEST(PolarSourceGrid, SectorAnglesGrowWhateverTheScanDirection)
{
	CPolarSourceGrid grid;
	grid.build(syntheticScan(false), options());
	// Clockwise scan: beam 0 is at +90 degrees, in the last sector.
	for (std::size_t s = 0; s < 181; ++s)
		expectSingleImpactRow(grid, s, beamRange(180 - s));
}

TEST(PolarSourceGrid, InvalidRangesProveNothingByDefault)
{
	CObservation2DRangeScan scan = syntheticScan();
	scan.setScanRangeValidity(10, false);
	scan.setScanRange(20, std::numeric_limits<float>::quiet_NaN());
	scan.setScanRange(30, -1.0f);
	scan.setScanRange(40, 0.0f);
	CPolarSourceGrid grid;
	grid.build(scan, options());
	for (const std::size_t s : {10u, 20u, 30u, 40u})
	{
		EXPECT_FALSE(grid.sectorObserved(s)) << s;
		for (std::size_t b = 0; b < grid.binCount(); ++b)
			ASSERT_EQ(grid.at(s, b), Mass::vacuous());
	}
	expectSingleImpactRow(grid, 11, beamRange(11));

	TSourceGridOptions asFree = options();
	asFree.invalidRangesAsFree = true;
	grid.build(scan, asFree);
	for (const std::size_t s : {10u, 20u, 30u, 40u})
	{
		EXPECT_TRUE(grid.sectorObserved(s));
		for (std::size_t b = 0; b < grid.binCount(); ++b)
			ASSERT_MASS_NEAR_AT(grid.at(s, b), Mass::simpleFree(kMuF), 1e-12, s, b);
	}
}

TEST(PolarSourceGrid, ReturnsBeyondMaxRangeOnlyProveFreeSpace)
{
	CObservation2DRangeScan scan = syntheticScan();
	scan.setScanRange(5, 25.0f);
	CPolarSourceGrid grid;
	grid.build(scan, options());
	for (std::size_t b = 0; b < grid.binCount(); ++b)
		ASSERT_MASS_NEAR_AT(grid.at(5, b), Mass::simpleFree(kMuF), 1e-12, 5, b);
}

TEST(PolarSourceGrid, WideSectorsGatherSeveralBeams)
{
	TSourceGridOptions o = options();
	o.sectorWidth = 3 * M_PI / 180;  // three beams each
	CPolarSourceGrid grid;
	grid.build(syntheticScan(), o);
	ASSERT_EQ(grid.sectorCount(), 61u);
	EXPECT_NEAR(grid.sectorSpacing(), o.sectorWidth, 1e-9);
	// Sector 10 is centred on beam 30 and holds beams 29, 30 and 31.
	const double ranges[] = {beamRange(29), beamRange(30), beamRange(31)};
	const double free3 = 1 - std::pow(1 - kMuF, 3);
	for (std::size_t b = 0; b < binOf(ranges[0]); ++b)
		ASSERT_MASS_NEAR_AT(grid.at(10, b), Mass::simpleFree(free3), 1e-12, 10, b);
	// Each impact's bin holds muO, or 1 - (1 - muO)^2 where two share a bin.
	std::vector<int> hits(grid.binCount(), 0);
	for (const double r : ranges) ++hits[binOf(r)];
	for (std::size_t b = binOf(ranges[0]); b < grid.binCount(); ++b)
	{
		const double o = 1 - std::pow(1 - kMuO, hits[b]);
		ASSERT_MASS_NEAR_AT(grid.at(10, b), Mass::simpleOccupied(o), 1e-12, 10, b);
	}
	// A width below the beam spacing is raised to it.
	o.sectorWidth = 0.1 * M_PI / 180;
	grid.build(syntheticScan(), o);
	EXPECT_EQ(grid.sectorCount(), 181u);
}

TEST(PolarSourceGrid, BeamsMidwayBetweenSectorsAllGoTheSameWay)
{
	// 0.5-degree beams in sectors of 1, 2 or 3 degrees: a beam at a sector
	// border lies midway between two centres. Each goes to the sector at the
	// greater angle, whatever the rounding of its own angle, so that every
	// sector inside the aperture gathers the same number of beams and has
	// the same free mass (the stock scan's 2-degree sectors had 3, 4 or 5).
	for (const bool rightToLeft : {true, false})
		for (const int perSector : {2, 4, 6})
		{
			TSourceGridOptions o = options();
			o.sectorWidth = 0.5 * perSector * M_PI / 180;
			const auto scan = test::scanByIndex(
				361, test::ScanSetup().maxRange(30.0).rightToLeft(rightToLeft),
				[](std::size_t) { return 5.0; });
			CPolarSourceGrid grid;
			grid.build(scan, o);
			const std::size_t n = grid.sectorCount();
			ASSERT_EQ(n, 360u / perSector + 1);
			const double inside = 1 - std::pow(1 - kMuF, perSector);
			// Sector 0, centred on the first beam, has only its upper half
			// (its midway beam goes up); the last sector its lower half with
			// its midway beam.
			const double first = 1 - std::pow(1 - kMuF, perSector / 2);
			const double last = 1 - std::pow(1 - kMuF, perSector / 2 + 1);
			for (std::size_t s = 0; s < n; ++s)
			{
				const double expected = s == 0 ? first : (s + 1 == n ? last : inside);
				ASSERT_MASS_NEAR_AT(
					grid.at(s, 0), Mass::simpleFree(expected), 1e-12, s, perSector);
			}
		}
}

TEST(PolarSourceGrid, SparseRowsMatchTheFullRowsScanAfterScan)
{
	// One sector gathers every beam of a narrow scan (sectorWidth above the
	// aperture), so its row must equal sectorMasses() of the valid ranges:
	// close and far impacts, overlapping imprecise bands, returns beyond
	// maxRange and no returns, on one grid reused scan after scan.
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> range(0.01, 12.0), unit(0.0, 1.0);
	CPolarSourceGrid grid;
	for (int trial = 0; trial < 300; ++trial)
	{
		TSourceGridOptions o = options();
		o.sectorWidth = 1.0;
		o.sensorModel.model = static_cast<SensorModel>(trial % 3);
		o.sensorModel.imprecision = 0.5 * unit(rng);
		o.sensorModel.profile = trial % 2 ? ImprecisionProfile::Gaussian
										  : ImprecisionProfile::Box;
		o.invalidRangesAsFree = trial % 4 == 0;
		const std::size_t n = 1 + static_cast<std::size_t>(unit(rng) * 30);
		std::vector<float> ranges;
		std::vector<bool> validity;
		std::vector<double> impacts;
		for (std::size_t i = 0; i < n; ++i)
		{
			const bool valid = unit(rng) > 0.2;
			const auto r = static_cast<float>(range(rng));
			ranges.push_back(r);
			validity.push_back(valid);
			if (valid)
				impacts.push_back(r);
			else if (o.invalidRangesAsFree)
				impacts.push_back(std::numeric_limits<double>::infinity());
		}
		grid.build(
			test::scanFromRanges(ranges, validity, test::ScanSetup().aperture(0.01f)), o);
		ASSERT_EQ(grid.sectorCount(), 1u);
		const std::vector<Mass> expected =
			sectorMasses(o.sensorModel, impacts, kBin, grid.binCount());
		std::size_t informed = 0;
		for (std::size_t b = 0; b < grid.binCount(); ++b)
		{
			ASSERT_MASS_NEAR_AT(grid.at(0, b), expected[b], 1e-12, trial, b);
			if (!(expected[b] == Mass::vacuous())) informed = b + 1;
		}
		EXPECT_GE(grid.informedBins(0), informed) << trial;
		EXPECT_LE(grid.freeBins(0), grid.informedBins(0)) << trial;
	}
}

TEST(PolarSourceGrid, EachSectorHoldsItsOwnBeamsSorted)
{
	// Scans of 181 and then fewer beams into one grid (its storage reused),
	// half and full turns, both turning directions, sectors of several
	// beams, beams without a return: each sector's impacts are the ranges of
	// the beams nearest its centre that give evidence, sorted, and nothing
	// else.
	std::mt19937 rng(11);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	CPolarSourceGrid grid;
	for (int trial = 0; trial < 40; ++trial)
	{
		TSourceGridOptions o = options();
		o.sectorWidth = (1 + trial % 7) * M_PI / 180;
		o.invalidRangesAsFree = trial % 3 == 0;
		const std::size_t n = 181 - static_cast<std::size_t>(trial);
		const double aperture = trial % 2 ? 2 * M_PI : M_PI;
		std::vector<float> ranges;
		std::vector<bool> validity;
		for (std::size_t i = 0; i < n; ++i)
		{
			// Distinct ranges, so that each impact names its beam.
			ranges.push_back(static_cast<float>(1.0 + 0.03 * static_cast<double>(i)));
			validity.push_back(unit(rng) > 0.25);
		}
		const CObservation2DRangeScan scan = test::scanFromRanges(
			ranges, validity,
			test::ScanSetup().aperture(aperture).rightToLeft(trial % 4 < 2));
		grid.build(scan, o);
		SCOPED_TRACE(testing::Message() << "trial " << trial);

		std::vector<double> expected, found;
		for (std::size_t i = 0; i < n; ++i)
			if (validity[i])
				expected.push_back(ranges[i]);
			else if (o.invalidRangesAsFree)
				expected.push_back(std::numeric_limits<double>::infinity());
		for (std::size_t s = 0; s < grid.sectorCount(); ++s)
		{
			const TImpactRanges impacts = grid.impacts(s);
			EXPECT_TRUE(std::is_sorted(impacts.begin(), impacts.end())) << s;
			EXPECT_EQ(grid.sectorObserved(s), !impacts.empty()) << s;
			for (const double r : impacts)
			{
				found.push_back(r);
				if (!std::isfinite(r)) continue;
				// The beam of that range lies within half a sector of the
				// sector's centre (a full turn's last beam joins sector 0).
				const auto beam = static_cast<std::size_t>(std::lround((r - 1.0) / 0.03));
				const double off = std::remainder(
					test::beamAngle(scan, beam) - grid.sectorAngle(s), 2 * M_PI);
				EXPECT_LE(std::abs(off), 0.5 * grid.sectorSpacing() + 1e-6) << s;
			}
		}
		std::sort(expected.begin(), expected.end());
		std::sort(found.begin(), found.end());
		EXPECT_EQ(found, expected);
		EXPECT_THROW(grid.impacts(grid.sectorCount()), std::out_of_range);
		EXPECT_THROW(grid.sectorObserved(grid.sectorCount()), std::out_of_range);
	}
}

TEST(PolarSourceGrid, EmptyAndSingleBeamScans)
{
	CPolarSourceGrid grid;
	grid.build(test::scanFromRanges({}, {}), options());
	EXPECT_EQ(grid.sectorCount(), 0u);

	grid.build(test::arcScan(1, 1.0), options());
	ASSERT_EQ(grid.sectorCount(), 1u);
	EXPECT_EQ(grid.sectorAngle(0), 0.0);
	expectSingleImpactRow(grid, 0, 1.0);
}

TEST(PolarSourceGrid, RejectsBadOptionsAndApertures)
{
	CPolarSourceGrid grid;
	TSourceGridOptions o = options();
	o.maxRange = 0;
	EXPECT_THROW(grid.build(syntheticScan(), o), std::invalid_argument);
	o = options();
	o.binSize = -1;
	EXPECT_THROW(grid.build(syntheticScan(), o), std::invalid_argument);
	o = options();
	o.sensorModel.muF = 2;
	EXPECT_THROW(grid.build(syntheticScan(), o), std::invalid_argument);
	CObservation2DRangeScan scan = syntheticScan();
	scan.aperture = 0;
	EXPECT_THROW(grid.build(scan, options()), std::invalid_argument);
	scan.aperture = 7;
	EXPECT_THROW(grid.build(scan, options()), std::invalid_argument);
	EXPECT_THROW(grid.at(181, 0), std::out_of_range);
	grid.build(syntheticScan(), options());
	EXPECT_THROW(grid.at(0, 200), std::out_of_range);
}

// ---------------------------------------------------------------------------
// What the source grid assumes of MRPT's scans
// ---------------------------------------------------------------------------

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
		CWholeReadArchive cut(bytes.data(), len);
		CObservation2DRangeScan back;
		EXPECT_THROW(cut >> back, std::exception) << "a scan cut at byte " << len << " was read";
	}
	CWholeReadArchive whole(bytes);
	CObservation2DRangeScan back;
	whole >> back;
	EXPECT_EQ(back.getScanSize(), 11u);
	EXPECT_NO_THROW(back.getScanRangeValidity(10));
}
