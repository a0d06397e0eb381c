/* Map files of every earlier version still load, as what those versions
 * wrote (each made from today's bytes by undoing what came since); and the
 * latest versions' additions (the cells that flip, the motion layer's
 * memory) are kept in files and checked when read. */

#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "support/map_bytes.h"
#include "support/map_files.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::deserialize;
using mrpt_evidential::test::expectSameMap;
using mrpt_evidential::test::firstCellPosition;
using mrpt_evidential::test::kMapFileScans;
using mrpt_evidential::test::mapWithEveryOption;
using mrpt_evidential::test::payloadStart;
using mrpt_evidential::test::putLE;
using mrpt_evidential::test::reseal;
using mrpt_evidential::test::serialize;
using mrpt_evidential::test::versionPosition;
using mrpt::poses::CPose3D;

namespace
{
/** The layout of the insertion options in a map's stream, in bytes from
 * their start (the io source's order): freeMargin after invalidRangesAsFree,
 * the motion options after growthMargin, the cloud options after them. */
constexpr std::size_t kFreeMarginAt = 1 + 8 + 8 + 8 + 1 + 8 + 8 + 1;
constexpr std::size_t kMotionAt = kFreeMarginAt + 8 + 1 + 8 + 8 + 1 + 8;
constexpr std::size_t kMotionBytes = 8 + 8 + 8;
constexpr std::size_t kCloudsAt = kMotionAt + kMotionBytes;
/** groundRemoval, minObstacleHeight, maxObstacleHeight, groundReturns. */
constexpr std::size_t kCloudOptionBytes = 1 + 8 + 8 + 1;
/** The likelihood and rendering options, whole. */
constexpr std::size_t kLikelihoodBytes = 6 * 8 + 4 + 1;
constexpr std::size_t kRenderingBytes = 1 + 6 * 3 + 5 + 8;

/** Where the insertion options begin: after the geometry (xMin, yMin,
 * resolution, sizeX, sizeY: 32 bytes) and maxCells. */
std::size_t insertionStart(const std::vector<std::uint8_t>& bytes)
{
	return payloadStart(bytes) + 32 + 8;
}

/** Takes n bytes out at `at`. */
void cut(std::vector<std::uint8_t>& bytes, std::size_t at, std::size_t n)
{
	bytes.erase(
		bytes.begin() + static_cast<std::ptrdiff_t>(at),
		bytes.begin() + static_cast<std::ptrdiff_t>(at + n));
}

/** Index in `bytes` (a serialized map) of the high byte of the stamp of the
 * cell numbered `packed` (cx + sizeX cy). */
std::size_t stampHighByte(
	const std::vector<std::uint8_t>& bytes, const CEvidentialGridMap2D& map, std::size_t packed)
{
	return firstCellPosition(bytes, map.geometry().cellCount()) + 8 * packed + 7;
}

/** The little-endian u64 at `at`. */
std::uint64_t getLE64(const std::vector<std::uint8_t>& bytes, std::size_t at)
{
	std::uint64_t v = 0;
	for (int i = 7; i >= 0; --i) v = (v << 8) | bytes[at + static_cast<std::size_t>(i)];
	return v;
}

/** The map as version 5 wrote it: no insertionThreads and no motion memory
 * after the cloud options. */
std::vector<std::uint8_t> asVersion5(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = serialize(map);
	bytes[versionPosition(bytes)] = 5;
	const std::size_t threads = insertionStart(bytes) + kCloudsAt + kCloudOptionBytes;
	// The memory: a count and its cells, twice, then the kept length.
	const std::size_t arrivals = threads + 4;
	const std::size_t leaving = arrivals + 8 + 8 * getLE64(bytes, arrivals);
	const std::size_t end = leaving + 8 + 8 * getLE64(bytes, leaving) + 8;
	cut(bytes, threads, end - threads);
	reseal(bytes);
	return bytes;
}

/** The map as version 4 wrote it: the layout of version 5, no cell marked
 * as one that flips. */
std::vector<std::uint8_t> asVersion4(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion5(map);
	bytes[versionPosition(bytes)] = 4;
	for (std::size_t i = 0; i < map.geometry().cellCount(); ++i)
		bytes[stampHighByte(bytes, map, i)] &= 0x7F;
	reseal(bytes);
	return bytes;
}

/** The map as version 3 wrote it: no rendering options after the
 * likelihood options. */
std::vector<std::uint8_t> asVersion3(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion4(map);
	bytes[versionPosition(bytes)] = 3;
	cut(bytes, insertionStart(bytes) + kCloudsAt + kCloudOptionBytes + kLikelihoodBytes,
		kRenderingBytes);
	reseal(bytes);
	return bytes;
}

/** The bytes version 1 would have written for `map` (whose stamp table fits
 * version 1): version 3's layout without freeMargin, the motion options and
 * keepsConflict, and stamps without their impact flag. */
std::vector<std::uint8_t> asVersion1(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion3(map);
	bytes[versionPosition(bytes)] = 1;
	const std::size_t cells = map.geometry().cellCount();
	const std::size_t firstCell = firstCellPosition(bytes, cells);
	for (std::size_t i = 0; i < cells; ++i)
		bytes[firstCell + 8 * i + 7] &= 0x3F;  // the stamp's flag bits
	// From the back, so that the positions in front stay put: keepsConflict
	// just before the cells, then the insertion options'.
	cut(bytes, firstCell - 1, 1);
	const std::size_t insertion = insertionStart(bytes);
	cut(bytes, insertion + kCloudsAt, kCloudOptionBytes);
	cut(bytes, insertion + kMotionAt, kMotionBytes);
	cut(bytes, insertion + kFreeMarginAt, 8);
	reseal(bytes);
	return bytes;
}

/** The map as version 2 wrote it: no cloud options after the motion
 * options. */
std::vector<std::uint8_t> asVersion2(const CEvidentialGridMap2D& map)
{
	std::vector<std::uint8_t> bytes = asVersion3(map);
	bytes[versionPosition(bytes)] = 2;
	cut(bytes, insertionStart(bytes) + kCloudsAt, kCloudOptionBytes);
	reseal(bytes);
	return bytes;
}

/** A small map that keeps conflict and holds some. */
CEvidentialGridMap2D conflictingMap()
{
	CEvidentialGridMap2D map(-2.0, 2.0, -2.0, 2.0, 0.1);
	map.insertionOptions.conflictHandling = ConflictHandling::Keep;
	map.insertObservation(test::arcScan(181, 1.5, kMapFileScans.at(1.0)), CPose3D());
	map.insertObservation(test::arcScan(181, 1.8, kMapFileScans.at(2.0)), CPose3D());
	return map;
}
}  // namespace

TEST(MapIO, CellsThatFlipAreKeptInFiles)
{
	// The motion layer's mark (bit 15 of a cell's stamp), set here in the
	// stream as a forger would, reads back and is written again.
	const CEvidentialGridMap2D original = mapWithEveryOption();
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

TEST(MapIO, VersionFiveFilesStillLoad)
{
	// Version 5 kept no insertionThreads (it reads as 1) and no motion
	// memory (its lists start again).
	CEvidentialGridMap2D original = mapWithEveryOption();
	ASSERT_EQ(original.insertionOptions.insertionThreads, 2u);
	CEvidentialGridMap2D back;
	deserialize(asVersion5(original), back);
	original.insertionOptions.insertionThreads = 1;
	expectSameMap(original, back);
}

TEST(MapIO, MotionMemoryReadsBackAndIsChecked)
{
	// The lists, forged into a grown map's stream (its cells' indices in
	// memory are not the file's packed ones), read back and are written
	// again as they were.
	CEvidentialGridMap2D map = mapWithEveryOption();
	map.insertObservation(
		test::arcScan(181, 1.0, kMapFileScans.at(1010.0)), CPose3D(3.0, 1.0, 0, 0, 0, 0));
	ASSERT_NE(map.geometry().stride(), static_cast<std::size_t>(map.geometry().sizeX));
	const std::size_t cells = map.geometry().cellCount();
	const auto withMemory = [&](std::vector<std::uint64_t> arrivals,
								std::vector<std::uint64_t> leaving, std::uint64_t kept) {
		std::vector<std::uint8_t> bytes = asVersion5(map);
		bytes[versionPosition(bytes)] = 6;
		std::vector<std::uint8_t> added(4);
		putLE(added, 0, map.insertionOptions.insertionThreads, 4);
		const auto append = [&](std::uint64_t v) {
			added.resize(added.size() + 8);
			putLE(added, added.size() - 8, v, 8);
		};
		for (const auto* list : {&arrivals, &leaving})
		{
			append(list->size());
			for (const std::uint64_t idx : *list) append(idx);
		}
		append(kept);
		const auto at = static_cast<std::ptrdiff_t>(
			insertionStart(bytes) + kCloudsAt + kCloudOptionBytes);
		bytes.insert(bytes.begin() + at, added.begin(), added.end());
		reseal(bytes);
		return bytes;
	};
	const std::vector<std::uint8_t> good = withMemory({cells - 1, 0, 17}, {3, 40, cells - 2}, 2);
	CEvidentialGridMap2D back;
	deserialize(good, back);
	EXPECT_EQ(serialize(back), good);

	for (const auto& bad :
		 {withMemory({cells}, {}, 0), withMemory({}, {5, 5}, 0), withMemory({}, {6, 5}, 0),
		  withMemory({}, {}, cells + 1)})
	{
		CEvidentialGridMap2D target;
		try
		{
			deserialize(bad, target);
			ADD_FAILURE() << "a forged motion memory was read";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find("corrupted"), std::string::npos) << e.what();
		}
		EXPECT_TRUE(target.isEmpty());
	}
	// A count beyond the grid is refused before its cells are looked for.
	std::vector<std::uint8_t> huge = withMemory({}, {}, 0);
	putLE(huge, insertionStart(huge) + kCloudsAt + kCloudOptionBytes + 4, std::uint64_t(1) << 60, 8);
	reseal(huge);
	CEvidentialGridMap2D target;
	EXPECT_ANY_THROW(deserialize(huge, target));
}

TEST(MapIO, VersionFourFilesStillLoad)
{
	// Version 4 marked no cell as one that flips; one that does is a
	// damaged file.
	CEvidentialGridMap2D original = mapWithEveryOption();
	original.insertionOptions.insertionThreads = 1;  // not kept before version 6
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
	bytes[versionPosition(bytes)] = 0;
	const std::size_t cells = original.geometry().cellCount();
	const std::size_t first = firstCellPosition(bytes, cells);
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
