/* Pictures, conversions and files of CEvidentialGridMap2D: colours of cells
 * of known masses, occupancy-grid and ROS map conversions, the saved
 * representation and its atomic writing (the 3-D view and the legends:
 * test_map_rendering.cpp). */

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include <mrpt_evidential/support/AtomicFile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "support/scans.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
namespace fs = std::filesystem;

namespace
{
/** How these tests take scans: 181 rays over 180 degrees, maxRange 10 m. */
const test::ScanSetup kSetup = test::ScanSetup().maxRange(10.0);
constexpr std::size_t kRays = 181;

/** A map that saw a wall 2 m ahead: free, occupied and unknown cells. */
CEvidentialGridMap2D scannedMap()
{
	CEvidentialGridMap2D map(-3.0, 3.0, -3.0, 3.0, 0.1);
	map.insertionOptions.growthMargin = 0.0;
	map.insertObservation(test::arcScan(kRays, 2.0, kSetup.at(10.0)), mrpt::poses::CPose3D());
	return map;
}

/** A map where the wall moved from 2 m to 3 m: the cells at 2 m were seen
 * occupied, then free, and keep the conflict (conjunctive rule, Keep). */
CEvidentialGridMap2D conflictingMap()
{
	CEvidentialGridMap2D map(-4.0, 4.0, -4.0, 4.0, 0.1);
	map.insertionOptions.growthMargin = 0.0;
	map.insertionOptions.conflictHandling = ConflictHandling::Keep;
	map.insertObservation(test::arcScan(kRays, 2.0, kSetup.at(10.0)), mrpt::poses::CPose3D());
	map.insertObservation(test::arcScan(kRays, 3.0, kSetup.at(11.0)), mrpt::poses::CPose3D());
	return map;
}

std::uint8_t toByte(double v)
{
	return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

/** Channel indices of red, green and blue in a CImage colour pixel, found
 * through CImage's documented setPixel(0x00RRGGBB). */
struct ChannelOrder
{
	unsigned r, g, b;
};
ChannelOrder channelOrder()
{
	mrpt::img::CImage probe(1, 1, mrpt::img::CH_RGB);
	probe.setPixel(0, 0, 0x00010203);  // R = 1, G = 2, B = 3
	ChannelOrder o{};
	for (unsigned ch = 0; ch < 3; ++ch)
	{
		const auto v = probe.at<std::uint8_t>(0, 0, ch);
		(v == 1 ? o.r : v == 2 ? o.g : o.b) = ch;
	}
	return o;
}

/** The image row of cell row cy: row 0 holds the largest y. */
unsigned rowOf(const CEvidentialGridMap2D& map, int cy)
{
	return static_cast<unsigned>(map.getSizeY() - 1 - cy);
}

std::string readText(const fs::path& path)
{
	std::ifstream f(path, std::ios::binary);
	return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(MapPictures, EvidentialColoursFollowTheMasses)
{
	const CEvidentialGridMap2D map = scannedMap();
	mrpt::img::CImage img;
	map.getAsEvidentialImage(img);
	ASSERT_TRUE(img.isColor());
	ASSERT_EQ(img.getWidth(), static_cast<std::size_t>(map.getSizeX()));
	ASSERT_EQ(img.getHeight(), static_cast<std::size_t>(map.getSizeY()));

	const ChannelOrder ch = channelOrder();
	std::size_t free = 0, occupied = 0, unknown = 0;
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
		{
			const Mass m = map.getCellMassesByIndex(cx, cy);
			const unsigned x = static_cast<unsigned>(cx), y = rowOf(map, cy);
			ASSERT_EQ(img.at<std::uint8_t>(x, y, ch.r), toByte(m.occupied + m.conflict))
				<< cx << ", " << cy;
			ASSERT_EQ(img.at<std::uint8_t>(x, y, ch.g), toByte(m.free + m.conflict))
				<< cx << ", " << cy;
			ASSERT_EQ(img.at<std::uint8_t>(x, y, ch.b), toByte(m.unknown + m.conflict))
				<< cx << ", " << cy;
			free += decide(m) == Decision::Free;
			occupied += decide(m) == Decision::Occupied;
			unknown += decide(m) == Decision::Unknown;
		}
	// The picture shows all three kinds of cells, so the loop above tested
	// each colour.
	EXPECT_GT(free, 0u);
	EXPECT_GT(occupied, 0u);
	EXPECT_GT(unknown, 0u);

	// Known places: the wall 2 m ahead is red, the space before it green,
	// behind the robot blue (unseen).
	const auto pixel = [&](double x, double y) {
		const auto& g = map.geometry();
		const unsigned px = static_cast<unsigned>(g.cellX(x));
		const unsigned py = rowOf(map, g.cellY(y));
		return std::array<int, 3>{
			img.at<std::uint8_t>(px, py, ch.r), img.at<std::uint8_t>(px, py, ch.g),
			img.at<std::uint8_t>(px, py, ch.b)};
	};
	const auto wall = pixel(2.02, 0.03), before = pixel(1.0, 0.03),
			   behind = pixel(-1.5, 0.03);
	EXPECT_GT(wall[0], wall[1]);
	EXPECT_GT(before[1], before[0]);
	EXPECT_EQ(behind, (std::array<int, 3>{0, 0, 255}));
	// Without conflict the channels share 255 (up to rounding).
	EXPECT_NEAR(wall[0] + wall[1] + wall[2], 255, 2);
	EXPECT_NEAR(before[0] + before[1] + before[2], 255, 2);
}

TEST(MapPictures, EmptyMapPictures)
{
	const CEvidentialGridMap2D map(0.0, 1.0, 0.0, 0.5, 0.1);
	mrpt::img::CImage evidential, bet, conflict;
	map.getAsEvidentialImage(evidential);
	map.getAsBetPImage(bet);
	map.getAsConflictImage(conflict);
	const ChannelOrder ch = channelOrder();
	ASSERT_EQ(evidential.getWidth(), 10u);
	ASSERT_EQ(evidential.getHeight(), 5u);
	for (unsigned y = 0; y < 5; ++y)
		for (unsigned x = 0; x < 10; ++x)
		{
			EXPECT_EQ(evidential.at<std::uint8_t>(x, y, ch.r), 0);
			EXPECT_EQ(evidential.at<std::uint8_t>(x, y, ch.g), 0);
			EXPECT_EQ(evidential.at<std::uint8_t>(x, y, ch.b), 255);
			EXPECT_EQ(bet.at<std::uint8_t>(x, y), toByte(0.5));
			EXPECT_EQ(conflict.at<std::uint8_t>(x, y), 0);
		}
}

TEST(MapPictures, FramesOfAbsurdSizesAreRefused)
{
	const CEvidentialGridMap2D map(0.0, 1.0, 0.0, 0.5, 0.1);
	mrpt::img::CImage img;
	for (const auto& [w, h] : {std::pair(100000, 100000), {-1, 100}, {100, 8193}})
		EXPECT_THROW(map.getAsPicture(0, img, true, w, h), std::invalid_argument) << w << " x " << h;
	map.getAsPicture(0, img, true, 64, 64);
	EXPECT_EQ(img.getWidth(), 64u);
}

TEST(MapPictures, BetPAndConflictGreyLevels)
{
	const CEvidentialGridMap2D map = conflictingMap();
	mrpt::img::CImage bet, conflict, evidential;
	map.getAsBetPImage(bet);
	map.getAsConflictImage(conflict);
	map.getAsEvidentialImage(evidential);
	ASSERT_FALSE(bet.isColor());
	ASSERT_FALSE(conflict.isColor());
	ASSERT_EQ(bet.getWidth(), static_cast<std::size_t>(map.getSizeX()));
	ASSERT_EQ(conflict.getHeight(), static_cast<std::size_t>(map.getSizeY()));

	double maxConflict = 0.0;
	int maxX = 0, maxY = 0;
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
		{
			const Mass m = map.getCellMassesByIndex(cx, cy);
			const unsigned x = static_cast<unsigned>(cx), y = rowOf(map, cy);
			ASSERT_EQ(bet.at<std::uint8_t>(x, y), toByte(1.0 - betP(m)));
			ASSERT_EQ(conflict.at<std::uint8_t>(x, y), toByte(m.conflict));
			if (m.conflict > maxConflict) maxConflict = m.conflict, maxX = cx, maxY = cy;
		}

	// The old wall is mostly conflict: white in the conflict picture and
	// brightened towards white in the evidential one.
	ASSERT_GT(maxConflict, 0.5);
	const unsigned x = static_cast<unsigned>(maxX), y = rowOf(map, maxY);
	EXPECT_GE(conflict.at<std::uint8_t>(x, y), 128);
	for (unsigned c = 0; c < 3; ++c)
		EXPECT_GE(evidential.at<std::uint8_t>(x, y, c), toByte(maxConflict));
	// The free space near the robot is white (BetP near 0), the new wall dark.
	const auto& g = map.geometry();
	EXPECT_GT(bet.at<std::uint8_t>(
				  static_cast<unsigned>(g.cellX(1.0)), rowOf(map, g.cellY(0.03))),
			  200);
	EXPECT_LT(bet.at<std::uint8_t>(
				  static_cast<unsigned>(g.cellX(3.02)), rowOf(map, g.cellY(0.03))),
			  80);
}

TEST(MapPictures, OccupiedCellCenters)
{
	const CEvidentialGridMap2D map = conflictingMap();
	const auto centers = map.getOccupiedCellCenters();
	EXPECT_EQ(centers.size(), map.countDecisions().occupied);
	ASSERT_FALSE(centers.empty());
	const auto& g = map.geometry();
	for (const auto& [x, y] : centers)
	{
		EXPECT_EQ(map.getCellDecision(x, y), Decision::Occupied);
		EXPECT_NEAR(x, g.cellCenterX(g.cellX(x)), 1e-9);
		EXPECT_NEAR(y, g.cellCenterY(g.cellY(y)), 1e-9);
	}
	EXPECT_TRUE(CEvidentialGridMap2D().getOccupiedCellCenters().empty());
}

TEST(MapPictures, OccupancyGridHoldsBetP)
{
	const CEvidentialGridMap2D map = conflictingMap();
	mrpt::maps::COccupancyGridMap2D grid;
	map.getAsOccupancyGrid(grid);
	ASSERT_EQ(grid.getSizeX(), static_cast<unsigned>(map.getSizeX()));
	ASSERT_EQ(grid.getSizeY(), static_cast<unsigned>(map.getSizeY()));
	EXPECT_NEAR(grid.getXMin(), map.getXMin(), 1e-5);
	EXPECT_NEAR(grid.getYMax(), map.getYMax(), 1e-5);
	EXPECT_NEAR(grid.getResolution(), map.getResolution(), 1e-6);
	// The grid stores log-odds in 8 bits: about 1/64 of error near 0.5.
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
			ASSERT_NEAR(
				1.0 - grid.getCell(cx, cy), betP(map.getCellMassesByIndex(cx, cy)),
				0.02)
				<< cx << ", " << cy;
}

TEST(MapPictures, OccupancyGridFarFromTheOriginHoldsOurCellsOneToOne)
{
	// At UTM coordinates MRPT's float cell centres repeat (floats are 0.5 m
	// apart at 4.2e6 m): sampled there, one row of ours would fill ten of its.
	const double x0 = 5e5 + 0.35, y0 = -4.2e6 + 0.15;
	CEvidentialGridMap2D map(x0, x0 + 8.0, y0, y0 + 8.0, 0.05);
	map.insertionOptions.growthMargin = 0.0;
	map.insertObservation(
		test::arcScan(kRays, 2.5, kSetup.at(1.0)), mrpt::poses::CPose3D(x0 + 4.0, y0 + 4.0, 0, 0.3, 0, 0));
	mrpt::maps::COccupancyGridMap2D grid;
	map.getAsOccupancyGrid(grid);
	ASSERT_EQ(grid.getSizeX(), static_cast<unsigned>(map.getSizeX()));
	ASSERT_EQ(grid.getSizeY(), static_cast<unsigned>(map.getSizeY()));
	for (int cy = 0; cy < map.getSizeY(); ++cy)
		for (int cx = 0; cx < map.getSizeX(); ++cx)
			ASSERT_NEAR(
				1.0 - grid.getCell(cx, cy), betP(map.getCellMassesByIndex(cx, cy)), 0.02)
				<< cx << ", " << cy;
}

TEST(MapPictures, OccupancyGridWithAnUnalignedOrigin)
{
	// COccupancyGridMap2D snaps its bounds to multiples of the resolution:
	// each of its cells holds the BetP of the cell under its centre.
	CEvidentialGridMap2D map(-2.03, 2.97, -1.96, 3.04, 0.1);
	map.insertionOptions.growthMargin = 0.0;
	map.insertObservation(
		test::arcScan(kRays, 1.5, kSetup.at(1.0)), mrpt::poses::CPose3D(0.2, 0.4, 0, 0.3, 0, 0));
	mrpt::maps::COccupancyGridMap2D grid;
	map.getAsOccupancyGrid(grid);
	for (unsigned cy = 0; cy < grid.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < grid.getSizeX(); ++cx)
			ASSERT_NEAR(
				1.0 - grid.getCell(static_cast<int>(cx), static_cast<int>(cy)),
				map.getCellBetP(grid.idx2x(cx), grid.idx2y(cy)), 0.02);
}

TEST(MapPictures, RosMapFiles)
{
	const fs::path dir = test::scratchDir("map_pictures", "ros");
	const CEvidentialGridMap2D map = scannedMap();
	map.saveAsROSMap((dir / "office").string());
	EXPECT_EQ(test::filesIn(dir), (std::set<std::string>{"office.pgm", "office.yaml"}));

	std::ifstream pgm(dir / "office.pgm", std::ios::binary);
	std::string magic, comment;
	pgm >> magic;
	ASSERT_EQ(magic, "P5");
	pgm >> std::ws;
	if (pgm.peek() == '#') std::getline(pgm, comment);
	int w = 0, h = 0, maxval = 0;
	pgm >> w >> h >> maxval;
	pgm.get();  // the single white space before the pixels
	ASSERT_EQ(w, map.getSizeX());
	ASSERT_EQ(h, map.getSizeY());
	ASSERT_EQ(maxval, 255);
	const std::string pixels{
		std::istreambuf_iterator<char>(pgm), std::istreambuf_iterator<char>()};
	ASSERT_EQ(pixels.size(), static_cast<std::size_t>(w) * h);
	std::set<int> seen;
	for (int row = 0; row < h; ++row)
		for (int cx = 0; cx < w; ++cx)
		{
			const int v = static_cast<unsigned char>(pixels[row * w + cx]);
			const double p = betP(map.getCellMassesByIndex(cx, h - 1 - row));
			const int expected = p > 0.65 ? 0 : p < 0.196 ? 254 : 205;
			ASSERT_EQ(v, expected) << cx << ", " << row;
			seen.insert(v);
		}
	EXPECT_EQ(seen, (std::set<int>{0, 205, 254}));

	const std::string yaml = readText(dir / "office.yaml");
	EXPECT_NE(yaml.find("image: office.pgm\n"), std::string::npos) << yaml;
	EXPECT_NE(yaml.find("resolution: 0.1\n"), std::string::npos) << yaml;
	EXPECT_NE(yaml.find("origin: [-3, -3, 0.0]\n"), std::string::npos) << yaml;
	EXPECT_NE(yaml.find("negate: 0\n"), std::string::npos) << yaml;
	EXPECT_NE(yaml.find("occupied_thresh: 0.65\n"), std::string::npos) << yaml;
	EXPECT_NE(yaml.find("free_thresh: 0.196\n"), std::string::npos) << yaml;

	// Numbers with an exponent keep a point: YAML 1.1 (PyYAML) reads "1e+06"
	// as a string.
	const CEvidentialGridMap2D far(1e6, 1e6 + 0.01, -4.2e6, -4.2e6 + 0.01, 5e-5);
	far.saveAsROSMap((dir / "far").string());
	const std::string farYaml = readText(dir / "far.yaml");
	EXPECT_NE(farYaml.find("resolution: 5.0e-05\n"), std::string::npos) << farYaml;
	EXPECT_NE(farYaml.find("origin: [1.0e+06, -4200000, 0.0]\n"), std::string::npos) << farYaml;
}

TEST(MapPictures, SavedRepresentationWritesEightFilesAndNoTemporary)
{
	const fs::path dir = test::scratchDir("map_pictures", "representation");
	const CEvidentialGridMap2D map = conflictingMap();
	const std::string prefix = (dir / "run1").string();
	map.saveMetricMapRepresentationToFile(prefix);
	EXPECT_EQ(
		test::filesIn(dir),
		(std::set<std::string>{
			"run1_map.png", "run1_evidential.png", "run1_betp.png", "run1_conflict.png",
			"run1_motion.png", "run1_info.txt", "run1.evgrid", "run1.3Dscene"}));

	mrpt::img::CImage loaded, expected;
	ASSERT_TRUE(loaded.loadFromFile(prefix + "_evidential.png"));
	map.getAsEvidentialImage(expected);
	// The picture at the top left, its legend below: PNG is lossless and the
	// file keeps the colours, every byte of the picture is equal.
	ASSERT_GE(loaded.getWidth(), expected.getWidth());
	ASSERT_GT(loaded.getHeight(), expected.getHeight());
	for (unsigned y = 0; y < expected.getHeight(); ++y)
		for (unsigned x = 0; x < expected.getWidth(); ++x)
			for (unsigned c = 0; c < 3; ++c)
				ASSERT_EQ(loaded.at<std::uint8_t>(x, y, c), expected.at<std::uint8_t>(x, y, c));

	const std::string info = readText(prefix + "_info.txt");
	const auto counts = map.countDecisions();
	EXPECT_NE(info.find("insertions: 2"), std::string::npos) << info;
	EXPECT_NE(info.find("latest time: 11 s"), std::string::npos) << info;
	EXPECT_NE(
		info.find("occupied " + std::to_string(counts.occupied)), std::string::npos)
		<< info;
	EXPECT_NE(info.find("fusionRule"), std::string::npos) << info;
	EXPECT_NE(info.find("sigma"), std::string::npos) << info;

	// Writing again replaces the files, still without leftovers.
	map.saveMetricMapRepresentationToFile(prefix);
	EXPECT_EQ(test::filesIn(dir).size(), 8u);

	// A prefix naming a folder would write hidden files: refused before
	// anything is written.
	for (const std::string& folder : {(dir / "").string(), std::string()})
		EXPECT_THROW(map.saveMetricMapRepresentationToFile(folder), std::invalid_argument)
			<< "'" << folder << "'";
	EXPECT_EQ(test::filesIn(dir).size(), 8u);
}

TEST(MapPictures, GeometryTextGivesLengthsToTheNanometre)
{
	// -0.1 - 0.2 is -0.30000000000000004 in binary and -0.7 - 0.2 is
	// -0.8999999999999999, as edges summed from growth margins are: the
	// text a reader sees is -0.3 and -0.9.
	const CEvidentialGridMap2D map(-0.1 - 0.2, 0.7, -0.7 - 0.2, 1.0, 0.05);
	const std::string text = map.geometryText("  ");
	EXPECT_NE(text.find("  x: [-0.3, 0.7] m\n"), std::string::npos) << text;
	EXPECT_NE(text.find("  y: [-0.9, 1] m\n"), std::string::npos) << text;
	EXPECT_NE(text.find("  resolution: 0.05 m\n"), std::string::npos) << text;
}

TEST(MapPictures, WritesReplaceTheFileALinkLeadsToAndRefuseDevices)
{
	// Renaming over a link would replace the link; over a pipe or a device
	// (/dev/null as root) it would put a plain file in its place.
	const fs::path dir = test::scratchDir("map_pictures", "links");
	const auto write = [](const fs::path& path, const std::string& text) {
		detail::writeFileAtomically(path.string(), [&text](std::ostream& os) { os << text; });
	};
	write(dir / "real.txt", "old");
	fs::create_symlink("real.txt", dir / "link.txt");
	write(dir / "link.txt", "new");
	EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
	EXPECT_EQ(readText(dir / "real.txt"), "new");

	ASSERT_EQ(mkfifo((dir / "pipe.txt").c_str(), 0600), 0);
	fs::create_symlink("/dev/null", dir / "null.txt");
	for (const char* name : {"pipe.txt", "null.txt"})
	{
		try
		{
			write(dir / name, "x");
			ADD_FAILURE() << name << " was written";
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos)
				<< e.what();
		}
	}
	EXPECT_EQ(fs::status(dir / "pipe.txt").type(), fs::file_type::fifo);
	EXPECT_TRUE(fs::is_symlink(dir / "null.txt"));
	EXPECT_EQ(
		test::filesIn(dir),
		(std::set<std::string>{"real.txt", "link.txt", "pipe.txt", "null.txt"}));
}

TEST(MapPictures, FailedWritesThrowAndLeaveNothing)
{
	const fs::path dir = test::scratchDir("map_pictures", "failures");
	const CEvidentialGridMap2D map = scannedMap();
	const fs::path missing = dir / "no_such_dir";
	EXPECT_THROW(
		map.saveMetricMapRepresentationToFile((missing / "x").string()),
		std::runtime_error);
	EXPECT_THROW(map.saveAsROSMap((missing / "x").string()), std::runtime_error);
	EXPECT_FALSE(fs::exists(missing));

	// A target that cannot be replaced (a directory in its place): the
	// temporary file written next to it is removed.
	fs::create_directory(dir / "y_info.txt");
	try
	{
		map.saveMetricMapRepresentationToFile((dir / "y").string());
		FAIL() << "replacing a directory succeeded";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("y_info.txt"), std::string::npos)
			<< e.what();
	}
	// All or none: the pictures and the scene written before the failure
	// are not left either.
	EXPECT_EQ(test::filesIn(dir), (std::set<std::string>{"y_info.txt"}));
	EXPECT_TRUE(fs::is_directory(dir / "y_info.txt"));
}

TEST(MapPictures, AFailedSaveLeavesTheEarlierFilesTogether)
{
	// A save that fails at its last file (the map's, a folder in its place
	// here; a full disk in use) replaces none of an earlier save's files:
	// no new pictures beside the file of another map.
	const fs::path dir = test::scratchDir("map_pictures", "together");
	const std::string prefix = (dir / "z").string();
	scannedMap().saveMetricMapRepresentationToFile(prefix);
	std::map<std::string, std::string> before;
	for (const std::string& name : test::filesIn(dir))
		before[name] = readText(dir / name);
	fs::remove(dir / "z.evgrid");
	fs::create_directory(dir / "z.evgrid");
	CEvidentialGridMap2D other = conflictingMap();
	EXPECT_THROW(other.saveMetricMapRepresentationToFile(prefix), std::runtime_error);
	for (const auto& [name, bytes] : before)
	{
		if (name != "z.evgrid")
		{
			EXPECT_EQ(readText(dir / name), bytes) << name;
		}
	}
	EXPECT_EQ(test::filesIn(dir).size(), before.size()) << "no temporary file left";
}
