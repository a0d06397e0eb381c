/* Serialization of CEvidentialGridMap2D: round trips through memory, files
 * and CMultiMetricMap copies; corrupted, truncated and unknown-version streams
 * are rejected, and so are forged ones that carry a valid checksum (earlier
 * versions' files: test_map_io_versions). This suite links
 * support/largest_allocation.cpp. */

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
#include <functional>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "support/bad_input.h"
#include "support/bounded_child.h"
#include "support/largest_allocation.h"
#include "support/map_bytes.h"
#include "support/map_files.h"
#include "support/maps.h"
#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using mrpt_evidential::test::deserialize;
using mrpt_evidential::test::expectSameMap;
using mrpt_evidential::test::firstCellPosition;
using mrpt_evidential::test::kMapFileRays;
using mrpt_evidential::test::kMapFileScans;
using mrpt_evidential::test::largestAllocation;
using mrpt_evidential::test::mapWithEveryOption;
using mrpt_evidential::test::payloadStart;
using mrpt_evidential::test::putLE;
using mrpt_evidential::test::reseal;
using mrpt_evidential::test::resetLargestAllocation;
using mrpt_evidential::test::serialize;
using mrpt_evidential::test::versionPosition;
using mrpt_evidential::test::wall;
using mrpt::poses::CPose3D;
using mrpt::serialization::archiveFrom;
namespace fs = std::filesystem;

TEST(MapIO, BuiltMapIsNotTrivial)
{
	// The round trips below prove something only if the map holds evidence,
	// decayed to several stamps, and grew beyond its initial bounds.
	const CEvidentialGridMap2D map = mapWithEveryOption();
	EXPECT_EQ(map.insertionCount(), 3u);
	EXPECT_GT(map.storage().stampTimes().size(), 1u);
	EXPECT_GT(map.getSizeX(), 40);
	const auto counts = map.countDecisions();
	EXPECT_GT(counts.free, 0u);
	EXPECT_GT(counts.occupied, 0u);
}

TEST(MapIO, MemoryRoundTripKeepsEverything)
{
	const CEvidentialGridMap2D original = mapWithEveryOption();
	CEvidentialGridMap2D copy;
	deserialize(serialize(original), copy);
	expectSameMap(original, copy);
	// The copy keeps working as a map: the next insertion decays and fuses
	// exactly as in the original.
	CEvidentialGridMap2D next = original;
	const auto scan = test::arcScan(kMapFileRays, 1.8, kMapFileScans.at(1004.0));
	next.insertObservation(scan, mrpt::poses::CPose3D());
	copy.insertObservation(scan, mrpt::poses::CPose3D());
	expectSameMap(next, copy);
}

TEST(MapIO, EmptyMapRoundTrip)
{
	const CEvidentialGridMap2D original(-1.0, 3.0, 0.5, 2.5, 0.25);
	CEvidentialGridMap2D copy = mapWithEveryOption();
	deserialize(serialize(original), copy);
	expectSameMap(original, copy);
	EXPECT_TRUE(copy.isEmpty());
}

TEST(MapIO, GenericObjectReadFindsTheClass)
{
	const CEvidentialGridMap2D original = mapWithEveryOption();
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
	const CEvidentialGridMap2D original = mapWithEveryOption();
	const std::string prefix = (dir / "saved").string();
	original.saveMetricMapRepresentationToFile(prefix);
	// CFileGZInputStream reads plain files as well as compressed ones.
	mrpt::io::CFileGZInputStream f(prefix + ".evgrid");
	CEvidentialGridMap2D copy;
	archiveFrom(f) >> copy;
	expectSameMap(original, copy);
}

TEST(MapIO, OptionsSetWrongInCodeAreRefusedBeforeWriting)
{
	// A file the map would refuse to read back is never written.
	const fs::path dir = test::scratchDir("map_io", "wrong_options");
	using Spoil = std::function<void(CEvidentialGridMap2D&)>;
	const std::vector<std::pair<std::string, Spoil>> spoil = {
		{"muF", [](CEvidentialGridMap2D& m) { m.insertionOptions.muF = 5.0; }},
		{"sigma", [](CEvidentialGridMap2D& m) { m.likelihoodOptions.sigma = -1.0; }},
		{"height", [](CEvidentialGridMap2D& m) { m.renderingOptions.height = std::nan(""); }},
		// Valid for cells of 1 m, too many range bins for cells of 0.1 m.
		{"maxRange", [](CEvidentialGridMap2D& m) { m.insertionOptions.maxRange = 2e6; }}};
	for (std::size_t k = 0; k < spoil.size(); ++k)
	{
		CEvidentialGridMap2D map = mapWithEveryOption();
		spoil[k].second(map);
		// MRPT's archive wraps what the map throws in its own exception.
		try
		{
			serialize(map);
			ADD_FAILURE() << "case " << k << " serialized";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find(spoil[k].first), std::string::npos) << e.what();
		}
		const std::string prefix = (dir / ("case" + std::to_string(k))).string();
		EXPECT_THROW(map.saveMetricMapRepresentationToFile(prefix), std::invalid_argument)
			<< "case " << k;
		EXPECT_TRUE(fs::is_empty(dir)) << "case " << k << " wrote a file";
	}
}

TEST(MapIO, EveryFlippedByteIsDetected)
{
	// Coarse cells keep the stream small enough to try every position.
	const CEvidentialGridMap2D original = mapWithEveryOption(0.3);
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
	const CEvidentialGridMap2D original = mapWithEveryOption(0.3);
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
	auto bytes = serialize(mapWithEveryOption(0.3));
	const std::size_t versionPos = versionPosition(bytes);
	ASSERT_EQ(bytes[versionPos], 6);
	for (const std::uint8_t v : {7, 8, 0x7F, 0xFF})
	{
		bytes[versionPos] = v;
		CEvidentialGridMap2D target;
		try
		{
			deserialize(bytes, target);
			ADD_FAILURE() << "version " << int(v) << " was read";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(
				std::string(e.what()).find(
					"a map of format version " + std::to_string(v) +
					", saved by a newer mrpt-evidential"),
				std::string::npos)
				<< e.what();
		}
		EXPECT_TRUE(target.isEmpty());
	}
}

TEST(MapIO, HugeSizeIsRejectedBeforeAllocating)
{
	// sizeX and sizeY as large as an int32 allows: rejected from the header
	// (the message names the budget), not by a failed 32 EB allocation.
	auto bytes = serialize(mapWithEveryOption(0.3));
	const std::size_t geometryPos = payloadStart(bytes);
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
			kMapFileRays, kMapFileScans.at(50.0), [](std::size_t i) { return 2.0 + 0.01 * i; }),
		mrpt::poses::CPose3D(0.1, 0.2, 0, 0.3, 0, 0));
	original.insertObservation(
		test::scanByIndex(
			kMapFileRays, kMapFileScans.at(51.0), [](std::size_t i) { return 2.2 - 0.003 * i; }),
		mrpt::poses::CPose3D(-0.3, 0.1, 0, 1.0, 0, 0));
	ASSERT_EQ(map->insertionCount(), 2u);

	const mrpt::maps::CMultiMetricMap copy = original;
	const auto copied = copy.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(copied);
	EXPECT_NE(copied.get(), map.get());
	expectSameMap(*map, *copied);
}

TEST(MapIO, MovesLeaveAnEmptyMapThatStillWorks)
{
	const CEvidentialGridMap2D original = [] {
		CEvidentialGridMap2D m = mapWithEveryOption();
		m.genericMapParams.enableObservationLikelihood = true;  // off there
		return m;
	}();
	const auto scan = test::scanByIndex(
		kMapFileRays, kMapFileScans.at(60.0), [](std::size_t i) { return 1.0 + 0.004 * i; });
	const mrpt::poses::CPose3D pose(0.2, 0.1, 0, 0.4, 0, 0);
	// The likelihood of an empty grid with the same options, which never had
	// a field: a moved-from map must score so, not with the field it cached.
	CEvidentialGridMap2D blank;
	blank.likelihoodOptions = original.likelihoodOptions;
	const CEvidentialGridMap2D blankSink(std::move(blank));
	const double emptyScore = blank.computeObservationLikelihood(scan, pose);
	ASSERT_NE(original.computeObservationLikelihood(scan, pose), emptyScore);
	const auto expectUsable = [&](CEvidentialGridMap2D& m) {
		// An empty grid: every cell read is vacuous, the likelihood that of
		// an empty grid, and it takes scans again.
		EXPECT_EQ(m.getSizeX() * m.getSizeY(), 0);
		EXPECT_EQ(m.getCellMasses(0.5, 0.5).unknown, 1.0);
		EXPECT_EQ(m.countDecisions().occupied, 0u);
		EXPECT_EQ(m.computeObservationLikelihood(scan, pose), emptyScore);
		m.setSize(-2, 2, -2, 2, 0.1);
		EXPECT_TRUE(m.insertObservation(scan, pose));
		EXPECT_GT(m.countDecisions().occupied, 0u);
	};

	CEvidentialGridMap2D from = original;
	(void)from.computeObservationLikelihood(scan, pose);  // a cached field
	CEvidentialGridMap2D to(std::move(from));
	expectSameMap(original, to);
	expectUsable(from);

	CEvidentialGridMap2D assigned;
	CEvidentialGridMap2D source = original;
	assigned = std::move(source);
	expectSameMap(original, assigned);
	expectUsable(source);

	// Into itself: nothing changes.
	CEvidentialGridMap2D self = original;
	CEvidentialGridMap2D& alias = self;
	self = std::move(alias);
	expectSameMap(original, self);
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
	const std::size_t geometry = payloadStart(bytes);
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
	const std::size_t geometry = payloadStart(good);
	const std::size_t cells = static_cast<std::size_t>(map.getSizeX() * map.getSizeY());
	const std::size_t insertions = firstCellPosition(good, cells) - 17;
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
