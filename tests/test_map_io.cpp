/* Serialization of CEvidentialGridMap2D: round trips through memory, files
 * and CMultiMetricMap copies; corrupted, truncated and unknown-version streams
 * are rejected, and so are forged ones that carry a valid checksum. This
 * suite links support/largest_allocation.cpp. */

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/grid/QuantizedMass.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "support/bad_input.h"
#include "support/bounded_child.h"
#include "support/largest_allocation.h"
#include "support/map_bytes.h"
#include "support/maps.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::deserialize;
using mrpt_evidential::test::largestAllocation;
using mrpt_evidential::test::resetLargestAllocation;
using mrpt_evidential::test::serialize;
using mrpt_evidential::test::wall;
using mrpt::poses::CPose3D;
using mrpt::serialization::archiveFrom;
namespace fs = std::filesystem;

namespace
{
/** How these tests take scans: 181 rays over 180 degrees, maxRange 10 m;
 * each test gives the time and the ranges, a function of the ray index. */
const test::ScanSetup kSetup = test::ScanSetup().maxRange(10.0);
constexpr std::size_t kRays = 181;

/** A map with non-default options in every group and three scans inserted at
 * different poses and times, so that decay, stamps and growth all show. */
CEvidentialGridMap2D makeMap(double resolution = 0.1)
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
	map.likelihoodOptions.sigma = 0.2;
	map.likelihoodOptions.decimation = 3;
	map.likelihoodOptions.unknownAsNeutral = false;
	map.renderingOptions.style = RenderStyle::Masses;
	map.renderingOptions.appearedColor = mrpt::img::TColor(1, 2, 3);
	map.renderingOptions.showUnknown = true;
	map.renderingOptions.height = 0.25;
	map.genericMapParams.enableObservationLikelihood = false;
	map.insertObservation(
		test::scanByIndex(
			kRays, kSetup.at(1000.0), [](std::size_t i) { return 2.0 + 0.005 * i; }),
		mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0));
	map.insertObservation(
		test::scanByIndex(
			kRays, kSetup.at(1001.5), [](std::size_t i) { return 2.5 - 0.004 * i; }),
		mrpt::poses::CPose3D(0.4, -0.3, 0, 0.5, 0, 0));
	map.insertObservation(
		test::scanByIndex(
			kRays, kSetup.at(1003.25), [](std::size_t i) { return 1.5 + (i % 7) * 0.1; }),
		mrpt::poses::CPose3D(-0.2, 0.6, 0, -2.0, 0, 0));
	return map;
}

/** Geometry, options, generic parameters, stamps and every cell equal. */
void expectSameMap(const CEvidentialGridMap2D& a, const CEvidentialGridMap2D& b)
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

/** Writes the checksum a stream's payload should have, as a forger would:
 * over everything between MRPT's header (class name and version) and the
 * checksum, which precedes MRPT's one-byte end marker. */
void reseal(std::vector<std::uint8_t>& bytes)
{
	const std::size_t begin = 1 + (bytes[0] & 0x7F) + 1, end = bytes.size() - 9;
	const std::uint64_t h = test::payloadChecksum(bytes.data() + begin, end - begin);
	for (int i = 0; i < 8; ++i) bytes[end + i] = static_cast<std::uint8_t>(h >> (8 * i));
}

/** Puts the n low bytes of v at `at`, little-endian. */
void putLE(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t v, int n)
{
	for (int i = 0; i < n; ++i) bytes[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

/** groundRemoval, minObstacleHeight, maxObstacleHeight, groundReturns. */
constexpr std::size_t kCloudOptionBytes = 1 + 8 + 8 + 1;

/** Index in `bytes` (a serialized map) of the high byte of the stamp of the
 * cell numbered `packed` (cx + sizeX cy). */
std::size_t stampHighByte(
	const std::vector<std::uint8_t>& bytes, const CEvidentialGridMap2D& map, std::size_t packed)
{
	const std::size_t firstCell = bytes.size() - 9 - 8 * map.geometry().cellCount();
	return firstCell + 8 * packed + 7;
}

/** The map as version 4 wrote it: the same layout, no cell marked as one
 * that flips. */
std::vector<std::uint8_t> asVersion4(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = test::serialize(map);
	const std::size_t header = 1 + (bytes[0] & 0x7F) + 1;
	bytes[header - 1] = 4;
	for (std::size_t i = 0; i < map.geometry().cellCount(); ++i)
		bytes[stampHighByte(bytes, map, i)] &= 0x7F;
	reseal(bytes);
	return bytes;
}

/** The map as version 3 wrote it: no rendering options after the
 * likelihood options (offsets of the layout in the io source). */
std::vector<std::uint8_t> asVersion3(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion4(map);
	const std::size_t header = 1 + (bytes[0] & 0x7F) + 1;
	bytes[header - 1] = 3;
	const std::size_t insertionBytes = 1 + 8 + 8 + 8 + 1 + 8 + 8 + 1 + 8 + 1 + 8 + 8 + 1 +
		8 + 24 + kCloudOptionBytes;
	const std::size_t likelihoodBytes = 6 * 8 + 4 + 1;
	const std::size_t rendering = header + 32 + 8 + insertionBytes + likelihoodBytes;
	const std::size_t renderingBytes = 1 + 6 * 3 + 5 + 8;
	bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(rendering),
				bytes.begin() + static_cast<std::ptrdiff_t>(rendering + renderingBytes));
	reseal(bytes);
	return bytes;
}

/** The bytes version 1 would have written for `map` (whose stamp table fits
 * version 1): today's layout without freeMargin, the motion options and
 * keepsConflict, and stamps without their impact flag. */
std::vector<std::uint8_t> asVersion1(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion3(map);
	const std::size_t header = 1 + (bytes[0] & 0x7F) + 1;
	bytes[header - 1] = 1;
	const std::size_t cells = map.geometry().cellCount();
	const std::size_t firstCell = bytes.size() - 9 - 8 * cells;
	for (std::size_t i = 0; i < cells; ++i)
		bytes[firstCell + 8 * i + 7] &= 0x3F;  // the stamp's flag bits
	// From the back, so that the positions in front stay put: keepsConflict
	// before the cells, the motion options after growthMargin, freeMargin
	// after invalidRangesAsFree (offsets of the layout in the io source).
	bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(firstCell - 1));
	const std::size_t insertion = header + 32 + 8;
	const std::size_t freeMargin = insertion + 1 + 8 + 8 + 8 + 1 + 8 + 8 + 1;
	const std::size_t motion = freeMargin + 8 + 1 + 8 + 8 + 1 + 8;
	const auto cut = [&](std::size_t at, std::size_t n) {
		bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(at),
					bytes.begin() + static_cast<std::ptrdiff_t>(at + n));
	};
	cut(motion + 24, kCloudOptionBytes);
	cut(motion, 24);
	cut(freeMargin, 8);
	reseal(bytes);
	return bytes;
}

/** The map as version 2 wrote it: no cloud options after the motion
 * options. */
std::vector<std::uint8_t> asVersion2(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion3(map);
	const std::size_t header = 1 + (bytes[0] & 0x7F) + 1;
	bytes[header - 1] = 2;
	const std::size_t insertion = header + 32 + 8;
	const std::size_t clouds = insertion + 1 + 8 + 8 + 8 + 1 + 8 + 8 + 1 + 8 + 1 + 8 + 8 +
		1 + 8 + 24;
	bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(clouds),
				bytes.begin() + static_cast<std::ptrdiff_t>(clouds + kCloudOptionBytes));
	reseal(bytes);
	return bytes;
}

/** A small map that keeps conflict and holds some. */
CEvidentialGridMap2D conflictingMap()
{
	CEvidentialGridMap2D map(-2.0, 2.0, -2.0, 2.0, 0.1);
	map.insertionOptions.conflictHandling = ConflictHandling::Keep;
	map.insertObservation(test::arcScan(181, 1.5, kSetup.at(1.0)), CPose3D());
	map.insertObservation(test::arcScan(181, 1.8, kSetup.at(2.0)), CPose3D());
	return map;
}
}  // namespace

TEST(MapIO, BuiltMapIsNotTrivial)
{
	// The round trips below prove something only if the map holds evidence,
	// decayed to several stamps, and grew beyond its initial bounds.
	const CEvidentialGridMap2D map = makeMap();
	EXPECT_EQ(map.insertionCount(), 3u);
	EXPECT_GT(map.storage().stampTimes().size(), 1u);
	EXPECT_GT(map.getSizeX(), 40);
	const auto counts = map.countDecisions();
	EXPECT_GT(counts.free, 0u);
	EXPECT_GT(counts.occupied, 0u);
}

TEST(MapIO, MemoryRoundTripKeepsEverything)
{
	const CEvidentialGridMap2D original = makeMap();
	CEvidentialGridMap2D copy;
	deserialize(serialize(original), copy);
	expectSameMap(original, copy);
	// The copy keeps working as a map: the next insertion decays and fuses
	// exactly as in the original.
	CEvidentialGridMap2D next = original;
	const auto scan = test::arcScan(kRays, 1.8, kSetup.at(1004.0));
	next.insertObservation(scan, mrpt::poses::CPose3D());
	copy.insertObservation(scan, mrpt::poses::CPose3D());
	expectSameMap(next, copy);
}

TEST(MapIO, EmptyMapRoundTrip)
{
	const CEvidentialGridMap2D original(-1.0, 3.0, 0.5, 2.5, 0.25);
	CEvidentialGridMap2D copy = makeMap();
	deserialize(serialize(original), copy);
	expectSameMap(original, copy);
	EXPECT_TRUE(copy.isEmpty());
}

TEST(MapIO, GenericObjectReadFindsTheClass)
{
	const CEvidentialGridMap2D original = makeMap();
	const auto bytes = serialize(original);
	mrpt::io::CMemoryStream buf;
	buf.assignMemoryNotOwn(bytes.data(), bytes.size());
	auto obj = archiveFrom(buf).ReadObject();
	const auto map = std::dynamic_pointer_cast<CEvidentialGridMap2D>(obj);
	ASSERT_TRUE(map);
	expectSameMap(original, *map);
}

TEST(MapIO, FileRoundTripThroughSavedRepresentation)
{
	const fs::path dir = test::scratchDir("map_io", "file_round_trip");
	const CEvidentialGridMap2D original = makeMap();
	const std::string prefix = (dir / "saved").string();
	original.saveMetricMapRepresentationToFile(prefix);
	// CFileGZInputStream reads plain files as well as compressed ones.
	mrpt::io::CFileGZInputStream f(prefix + ".evgrid");
	CEvidentialGridMap2D copy;
	archiveFrom(f) >> copy;
	expectSameMap(original, copy);
}

TEST(MapIO, EveryFlippedByteIsDetected)
{
	// Coarse cells keep the stream small enough to try every position.
	const CEvidentialGridMap2D original = makeMap(0.3);
	const auto bytes = serialize(original);
	ASSERT_LT(bytes.size(), 20000u);
	const CEvidentialGridMap2D pristine(-1.0, 1.0, -1.0, 1.0, 0.5);
	// MRPT's object header starts with the class name, which MRPT looks up
	// without its namespace when the full name is unknown: damage to the
	// namespace is forgiven by MRPT, not by this map, and the object read is
	// intact. Every other byte must be caught.
	const std::string ns = "mrpt_evidential::";
	ASSERT_EQ(std::string(bytes.begin() + 1, bytes.begin() + 1 + ns.size()), ns);
	for (std::size_t pos = 0; pos < bytes.size(); ++pos)
	{
		if (pos >= 1 && pos < ns.size() - 1) continue;  // the namespace's name
		auto corrupted = bytes;
		corrupted[pos] ^= 0xFF;
		CEvidentialGridMap2D target(-1.0, 1.0, -1.0, 1.0, 0.5);
		EXPECT_ANY_THROW(deserialize(corrupted, target)) << "byte " << pos;
		// A failed read leaves the map as it was, except when the damage is
		// in MRPT's end marker, checked after the object has been read.
		if (pos + 1 < bytes.size())
		{
			ASSERT_EQ(target.getSizeX(), pristine.getSizeX()) << "byte " << pos;
			ASSERT_EQ(target.insertionCount(), 0u) << "byte " << pos;
			ASSERT_EQ(target.insertionOptions.fusionRule, FusionRule::Conjunctive)
				<< "byte " << pos;
		}
	}
}

TEST(MapIO, EveryTruncationIsDetected)
{
	// Read through MRPT's own memory stream, as a user's program would: a cut
	// inside a field leaves the rest of it uninitialized (see
	// support/whole_read_archive.h), so the sizes the map reads may be
	// garbage. In a child whose address space may grow by 256 MB, a map that
	// allocated what such a size claims would fail.
	const CEvidentialGridMap2D original = makeMap(0.3);
	const auto bytes = serialize(original);
	const auto end = test::runInBoundedChild(std::size_t(256) << 20, [&] {
		for (std::size_t len = 0; len < bytes.size(); ++len)
		{
			const std::string at = "length " + std::to_string(len) + ": ";
			const std::vector<std::uint8_t> truncated(bytes.begin(), bytes.begin() + len);
			CEvidentialGridMap2D target;
			try
			{
				deserialize(truncated, target);
				return at + "read without an error";
			}
			catch (const std::bad_alloc&)
			{
				return at + "ran out of memory";
			}
			catch (const std::exception&)
			{
			}
			// Only a missing end marker, checked by MRPT after the object has
			// been read, can leave the map changed.
			if (len + 1 < bytes.size() && !target.isEmpty())
				return at + "the map changed";
		}
		return std::string();
	});
	EXPECT_TRUE(end.exited) << "the child ended by signal " << end.signal;
	EXPECT_EQ(end.report, "");
}

TEST(MapIO, CellsThatFlipAreKeptInFiles)
{
	// The motion layer's mark (bit 15 of a cell's stamp), set here in the
	// stream as a forger would, reads back and is written again.
	const CEvidentialGridMap2D original = makeMap();
	auto bytes = serialize(original);
	const std::size_t packed = 7 + 3 * static_cast<std::size_t>(original.getSizeX());
	bytes[stampHighByte(bytes, original, packed)] |= 0x80;
	reseal(bytes);
	CEvidentialGridMap2D back;
	deserialize(bytes, back);
	const GridGeometry& g = back.geometry();
	for (std::size_t i = 0; i < g.cellCount(); ++i)
		EXPECT_EQ(back.storage().flipped(g.indexOfPacked(i)), i == packed) << "cell " << i;
	EXPECT_EQ(serialize(back), bytes);
}

TEST(MapIO, VersionFourFilesStillLoad)
{
	// Version 4 marked no cell as one that flips; one that does is a
	// damaged file.
	const CEvidentialGridMap2D original = makeMap();
	CEvidentialGridMap2D back;
	deserialize(asVersion4(original), back);
	expectSameMap(original, back);
	auto bytes = asVersion4(original);
	bytes[stampHighByte(bytes, original, 0)] |= 0x80;
	reseal(bytes);
	CEvidentialGridMap2D target;
	EXPECT_ANY_THROW(deserialize(bytes, target));
	EXPECT_TRUE(target.isEmpty());
}

TEST(MapIO, VersionThreeFilesStillLoad)
{
	// Version 3 had no rendering options: they read as the defaults.
	CEvidentialGridMap2D original = conflictingMap();
	original.renderingOptions.style = RenderStyle::Masses;
	original.renderingOptions.height = 2.0;
	CEvidentialGridMap2D back;
	deserialize(asVersion3(original), back);
	original.renderingOptions = CEvidentialGridMap2D::TRenderingOptions();
	expectSameMap(original, back);
}

TEST(MapIO, VersionTwoFilesStillLoad)
{
	// Version 2 had no cloud options: they read as the defaults, and the
	// rest as it was.
	CEvidentialGridMap2D original = conflictingMap();
	original.insertionOptions.groundRemoval = GroundRemoval::None;
	original.insertionOptions.maxObstacleHeight = 4.0;
	CEvidentialGridMap2D back;
	deserialize(asVersion2(original), back);
	const CEvidentialGridMap2D::TInsertionOptions defaults;
	EXPECT_EQ(back.insertionOptions.groundRemoval, defaults.groundRemoval);
	EXPECT_EQ(back.insertionOptions.minObstacleHeight, defaults.minObstacleHeight);
	EXPECT_EQ(back.insertionOptions.maxObstacleHeight, defaults.maxObstacleHeight);
	EXPECT_EQ(back.insertionOptions.groundReturns, defaults.groundReturns);
	original.insertionOptions.groundRemoval = defaults.groundRemoval;
	original.insertionOptions.maxObstacleHeight = defaults.maxObstacleHeight;
	expectSameMap(original, back);
}

TEST(MapIO, VersionOneFilesStillLoad)
{
	// Version 1 had no free margin, no motion layer and cells that always
	// kept conflict. A map that keeps conflict reads back as it was, with
	// freeMargin 0 (what it was built with); its cells that lean occupied
	// are taken to have held impacts, as the likelihood field needs.
	const CEvidentialGridMap2D original = conflictingMap();
	ASSERT_GT(original.countDecisions().conflict, 0u);
	CEvidentialGridMap2D back;
	deserialize(asVersion1(original), back);
	EXPECT_TRUE(back.storage().keepsConflict());
	EXPECT_EQ(back.insertionOptions.freeMargin, 0.0);
	const std::size_t cells = original.geometry().cellCount();
	ASSERT_EQ(back.geometry().cellCount(), cells);
	for (std::size_t i = 0; i < cells; ++i)
	{
		ASSERT_EQ(back.storage().read(i), original.storage().read(original.geometry().indexOfPacked(i))) << i;
		const Mass m = back.storage().read(i);
		ASSERT_EQ(back.storage().heldImpact(i), m.occupied > m.free) << i;
	}

	// A map of another conflict handling loses its (rounding-level)
	// conflict and gets a motion layer, with no event yet.
	CEvidentialGridMap2D other = conflictingMap();
	other.insertionOptions.conflictHandling = ConflictHandling::Normalize;
	CEvidentialGridMap2D motion;
	deserialize(asVersion1(other), motion);
	EXPECT_FALSE(motion.storage().keepsConflict());
	for (std::size_t i = 0; i < cells; ++i)
	{
		const Mass m = motion.storage().read(i);
		ASSERT_EQ(m.conflict, 0.0);
		ASSERT_MASS_NEAR_AT(m, normalized(original.storage().read(original.geometry().indexOfPacked(i))), 2e-4, i, 0);
		ASSERT_EQ(motion.storage().event(i), CellEvent::None);
	}
}

TEST(MapIO, VersionZeroFilesStillLoad)
{
	// Version 0 stored m(empty), m(F) and m(O) themselves in the cells;
	// version 1 the conflict and the normal part (issue 14), in the same
	// layout. A map with conflict, written as version 0 would have written
	// it, reads back with the same masses within the two formats' roundings.
	const CEvidentialGridMap2D original = conflictingMap();
	ASSERT_GT(original.countDecisions().conflict, 0u);

	auto bytes = asVersion1(original);
	const std::size_t versionPos = 1 + (bytes[0] & 0x7F);
	bytes[versionPos] = 0;
	const std::size_t cells = original.geometry().cellCount();
	const std::size_t first = bytes.size() - 9 - 8 * cells;  // checksum, end marker
	const auto put = [&](std::size_t at, double v) {
		putLE(bytes, at, quantizeMass(v), 2);
	};
	for (std::size_t i = 0; i < cells; ++i)
	{
		// Version 0's cell: the masses rounded, the stamp as it was. These
		// masses round to values that never pass the scale together.
		const Mass m = decodeMass(original.storage().packedCells()[i]);
		put(first + 8 * i, m.conflict);
		put(first + 8 * i + 2, m.free);
		put(first + 8 * i + 4, m.occupied);
	}
	reseal(bytes);
	CEvidentialGridMap2D back;
	deserialize(bytes, back);
	ASSERT_EQ(back.geometry().cellCount(), cells);
	for (std::size_t i = 0; i < cells; ++i)
		ASSERT_MASS_NEAR_AT(
			back.storage().read(i), original.storage().read(original.geometry().indexOfPacked(i)), 2.0 / kMassScale, i,
			0);

	// A version-0 cell whose masses pass 1 together is refused, as before.
	putLE(bytes, first, 40000, 2);
	putLE(bytes, first + 2, 40000, 2);
	reseal(bytes);
	CEvidentialGridMap2D refused;
	EXPECT_ANY_THROW(deserialize(bytes, refused));
}

TEST(MapIO, OptionsThatTheGridCannotInsertWithAreRejected)
{
	// maxRange 2e5 m is valid for cells of 1 m, but at 1 cm it would take
	// 2e7 range bins: a map read back with it could not insert a scan.
	CEvidentialGridMap2D map(-1.0, 1.0, -1.0, 1.0, 0.01);
	map.insertionOptions.maxRange = 2e5;
	ASSERT_NO_THROW(map.insertionOptions.validate());
	CEvidentialGridMap2D back;
	EXPECT_ANY_THROW(deserialize(serialize(map), back));
	EXPECT_TRUE(back.isEmpty());
	map.insertionOptions.maxRange = 20.0;
	EXPECT_NO_THROW(deserialize(serialize(map), back));
}

TEST(MapIO, UnknownVersionIsRejected)
{
	auto bytes = serialize(makeMap(0.3));
	// MRPT's object header: 0x80 | name length, the class name, the version.
	const std::size_t versionPos = 1 + (bytes[0] & 0x7F);
	ASSERT_EQ(bytes[versionPos], 5);
	for (const std::uint8_t v : {6, 7, 0x7F, 0xFF})
	{
		bytes[versionPos] = v;
		CEvidentialGridMap2D target;
		EXPECT_ANY_THROW(deserialize(bytes, target)) << "version " << int(v);
		EXPECT_TRUE(target.isEmpty());
	}
}

TEST(MapIO, HugeSizeIsRejectedBeforeAllocating)
{
	// sizeX and sizeY as large as an int32 allows: rejected from the header
	// (the message names the budget), not by a failed 32 EB allocation.
	auto bytes = serialize(makeMap(0.3));
	const std::size_t geometryPos = 1 + (bytes[0] & 0x7F) + 1;
	for (std::size_t i = 0; i < 8; ++i)
		bytes[geometryPos + 24 + i] = (i % 4 == 3) ? 0x7F : 0xFF;
	CEvidentialGridMap2D target;
	try
	{
		deserialize(bytes, target);
		FAIL() << "a huge grid was accepted";
	}
	catch (const std::bad_alloc&)
	{
		FAIL() << "the size was not checked before allocating";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("budget"), std::string::npos)
			<< e.what();
	}
}

TEST(MapIO, MultiMetricMapCopyHoldsTheSameCells)
{
	mrpt::config::CConfigFileMemory ini(std::string(
		"[MAP]\n"
		"evidentialGrid_count=1\n"
		"[MAP_evidentialGrid_00_creationOpts]\n"
		"min_x=-3\nmax_x=3\nmin_y=-3\nmax_y=3\nresolution=0.1\n"
		"[MAP_evidentialGrid_00_insertOpts]\n"
		"fusionRule=Dempster\ndecayRate=0.2\ngrowthMargin=1\n"
		"[MAP_evidentialGrid_00_likelihoodOpts]\n"
		"sigma=0.25\n"));
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "MAP");
	mrpt::maps::CMultiMetricMap original(inits);
	const auto map = original.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map);
	EXPECT_EQ(map->insertionOptions.fusionRule, FusionRule::Dempster);
	map->genericMapParams.enableObservationLikelihood = false;
	original.insertObservation(
		test::scanByIndex(
			kRays, kSetup.at(50.0), [](std::size_t i) { return 2.0 + 0.01 * i; }),
		mrpt::poses::CPose3D(0.1, 0.2, 0, 0.3, 0, 0));
	original.insertObservation(
		test::scanByIndex(
			kRays, kSetup.at(51.0), [](std::size_t i) { return 2.2 - 0.003 * i; }),
		mrpt::poses::CPose3D(-0.3, 0.1, 0, 1.0, 0, 0));
	ASSERT_EQ(map->insertionCount(), 2u);

	const mrpt::maps::CMultiMetricMap copy = original;
	const auto copied = copy.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(copied);
	EXPECT_NE(copied.get(), map.get());
	expectSameMap(*map, *copied);
}

// ---------------------------------------------------------------------------
// Forged files: damage a checksum cannot see
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
		resetLargestAllocation();
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
		EXPECT_LT(largestAllocation(), std::size_t(64) << 20) << keep << " bytes";
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
	const std::size_t insertions = good.size() - 9 - cells * 8 - 17;
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
