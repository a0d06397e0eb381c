/* The map's options: CEvidentialGridMap2D created from .ini files through
 * CMultiMetricMap, and options set wrong or absurdly in code. This suite
 * links support/largest_allocation.cpp. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "support/bad_input.h"
#include "support/largest_allocation.h"
#include "support/maps.h"
#include "support/test_helpers.h"

using namespace mrpt_evidential;
using namespace mrpt_evidential::test;
using mrpt::poses::CPose3D;

namespace
{
const std::string kIni = R"ini(
[Map]
evidentialGrid_count=1

[Map_evidentialGrid_00_creationOpts]
min_x=-5
max_x=7
min_y=-3
max_y=4
resolution=0.05
maxCells=2e6

[Map_evidentialGrid_00_insertOpts]
sensorModel=ImpreciseMultiEcho
muF=0.65
muO=0.85
imprecision=0.1
imprecisionProfile=Gaussian
sectorWidth=2
maxRange=12.5
invalidRangesAsFree=true
fusionRule=Yager
decayRate=0.05
horizontalTolerance=1.5
conflictHandling=ToUnknown
growthMargin=3
freeMargin=0.15
motionWindow=4.5
motionMinConflict=0.6
motionClearance=0.25
groundRemoval=Height
minObstacleHeight=0.3
maxObstacleHeight=3.5
groundReturns=Nothing
)ini";

mrpt::maps::CMultiMetricMap mapsFrom(const std::string& ini)
{
	mrpt::config::CConfigFileMemory cfg(ini);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(cfg, "Map");
	mrpt::maps::CMultiMetricMap maps;
	maps.setListOfMaps(inits);
	return maps;
}

/** The message of the exception that loading `ini` throws ("" if none). */
std::string loadError(const std::string& ini)
{
	try
	{
		mapsFrom(ini);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(MapIni, CreatedFromIniWithEveryOption)
{
	const auto maps = mapsFrom(kIni);
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map) << "evidentialGrid not created: is the class registered?";
	EXPECT_EQ(map->getXMin(), -5.0);
	EXPECT_NEAR(map->getXMax(), 7.0, 1e-9);
	EXPECT_EQ(map->getResolution(), 0.05);
	EXPECT_EQ(map->getSizeY(), 140);
	EXPECT_EQ(map->maxCells(), 2'000'000u);
	const auto& o = map->insertionOptions;
	EXPECT_EQ(o.sensorModel, SensorModel::ImpreciseMultiEcho);
	EXPECT_EQ(o.muF, 0.65);
	EXPECT_EQ(o.muO, 0.85);
	EXPECT_EQ(o.imprecision, 0.1);
	EXPECT_EQ(o.imprecisionProfile, ImprecisionProfile::Gaussian);
	EXPECT_NEAR(o.sectorWidth, 2 * M_PI / 180, 1e-12);
	EXPECT_EQ(o.maxRange, 12.5);
	EXPECT_TRUE(o.invalidRangesAsFree);
	EXPECT_EQ(o.fusionRule, FusionRule::Yager);
	EXPECT_EQ(o.decayRate, 0.05);
	EXPECT_NEAR(o.horizontalTolerance, 1.5 * M_PI / 180, 1e-12);
	EXPECT_EQ(o.conflictHandling, ConflictHandling::ToUnknown);
	EXPECT_EQ(o.growthMargin, 3.0);
	EXPECT_EQ(o.freeMargin, 0.15);
	EXPECT_EQ(o.motionWindow, 4.5);
	EXPECT_EQ(o.motionMinConflict, 0.6);
	EXPECT_EQ(o.motionClearance, 0.25);
	EXPECT_EQ(o.groundRemoval, GroundRemoval::Height);
	EXPECT_EQ(o.minObstacleHeight, 0.3);
	EXPECT_EQ(o.maxObstacleHeight, 3.5);
	EXPECT_EQ(o.groundReturns, GroundReturns::Nothing);
}

// CMetricMap::boundingBox() is a virtual since MRPT 2.11.3: through the base
// class there, through the map's own method before.
TEST(MapIni, BoundingBoxIsTheGridsExtent)
{
	const auto maps = mapsFrom(kIni);
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map);
#if MRPT_EVIDENTIAL_MRPT_SINCE_2_11_3
	const mrpt::maps::CMetricMap& asMetricMap = *map;
	const auto box = asMetricMap.boundingBox();
#else
	const auto box = map->boundingBox();
#endif
	EXPECT_FLOAT_EQ(box.min.x, -5.0f);
	EXPECT_FLOAT_EQ(box.max.x, 7.0f);
	EXPECT_FLOAT_EQ(box.min.y, -3.0f);
	EXPECT_FLOAT_EQ(box.max.y, 4.0f);
	EXPECT_EQ(box.min.z, 0.0f);
	EXPECT_EQ(box.max.z, 0.0f);

	// The box follows the grid when it grows.
	CEvidentialGridMap2D grown(-5, 7, -3, 4, 0.05);
	grown.setSize(-20, 30, -10, 15, 0.05);
	const auto after = grown.boundingBox();
	EXPECT_FLOAT_EQ(after.min.x, -20.0f);
	EXPECT_FLOAT_EQ(after.max.x, 30.0f);
	EXPECT_FLOAT_EQ(after.min.y, -10.0f);
	EXPECT_FLOAT_EQ(after.max.y, 15.0f);
}

TEST(MapIni, DefaultsWhenSectionsAreAbsent)
{
	const auto maps = mapsFrom("[Map]\nevidentialGrid_count=1\n");
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map);
	const CEvidentialGridMap2D::TInsertionOptions defaults;
	EXPECT_EQ(map->insertionOptions.sensorModel, defaults.sensorModel);
	EXPECT_EQ(map->insertionOptions.muF, defaults.muF);
	EXPECT_EQ(map->getResolution(), 0.10);
	EXPECT_EQ(map->maxCells(), CEvidentialGridMap2D::kDefaultMaxCells);
}

TEST(MapIni, AValueMayBeFollowedByAComment)
{
	const auto maps = mapsFrom(
		"[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_insertOpts]\n"
		"muO = 0.95   # the occupied mass\nmuF=0.55 ; the free mass\n"
		"maxRange = 12 // MRPT's own comment\n"
		"[Map_evidentialGrid_00_renderOpts]\nfreeColor = #112233 ; grey-blue\n");
	const auto map = maps.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(map);
	EXPECT_EQ(map->insertionOptions.muO, 0.95);
	EXPECT_EQ(map->insertionOptions.muF, 0.55);
	EXPECT_EQ(map->insertionOptions.maxRange, 12.0);
	EXPECT_EQ(map->renderingOptions.freeColor, mrpt::img::TColor(0x11, 0x22, 0x33));
	EXPECT_NE(
		loadError("[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_insertOpts]\nmuO=0,95\n")
			.find("the decimal mark is a point"),
		std::string::npos);

	// A comment right after the value, without a space; booleans in any
	// case, as MRPT's own maps read them.
	const auto tight = mapsFrom(
		"[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_insertOpts]\n"
		"muO=0.85;occupied\nmuF=0.6#free\nmaxRange=11//range\ninvalidRangesAsFree=True\n"
		"[Map_evidentialGrid_00_renderOpts]\nfreeColor=#445566;colour\nshowUnknown=YES\n");
	const auto tightMap = tight.mapByClass<CEvidentialGridMap2D>();
	ASSERT_TRUE(tightMap);
	EXPECT_EQ(tightMap->insertionOptions.muO, 0.85);
	EXPECT_EQ(tightMap->insertionOptions.muF, 0.6);
	EXPECT_EQ(tightMap->insertionOptions.maxRange, 11.0);
	EXPECT_TRUE(tightMap->insertionOptions.invalidRangesAsFree);
	EXPECT_EQ(tightMap->renderingOptions.freeColor, mrpt::img::TColor(0x44, 0x55, 0x66));
	EXPECT_TRUE(tightMap->renderingOptions.showUnknown);
	// Text that is no comment is still refused.
	EXPECT_NE(
		loadError("[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_insertOpts]\nmuO=0.9 x\n")
			.find("at most a comment"),
		std::string::npos);
	EXPECT_NE(
		loadError("[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_insertOpts]\nmuO=0.9x\n")
			.find("not a finite number"),
		std::string::npos);
}

TEST(MapIni, InsertionOptionsRoundTripThroughIni)
{
	CEvidentialGridMap2D::TInsertionOptions o;
	o.sensorModel = SensorModel::MultiEcho;
	o.muF = 0.123456789012345;
	o.muO = 0.987654321;
	o.imprecision = 0.07;
	o.imprecisionProfile = ImprecisionProfile::Gaussian;
	o.sectorWidth = 0.0123;
	o.maxRange = 33.3;
	o.invalidRangesAsFree = true;
	o.fusionRule = FusionRule::DuboisPrade;
	o.decayRate = 1.0 / 3.0;
	o.horizontalTolerance = 0.0456;
	o.conflictHandling = ConflictHandling::Normalize;
	o.growthMargin = 0.5;
	o.freeMargin = 0.123;
	o.motionWindow = 1.0 / 7.0;
	o.motionMinConflict = 0.45;
	o.motionClearance = 0.0;
	o.groundRemoval = GroundRemoval::None;
	o.minObstacleHeight = 1.0 / 9.0;
	o.maxObstacleHeight = 2.75;
	o.groundReturns = GroundReturns::Nothing;
	o.insertionThreads = 3;
	mrpt::config::CConfigFileMemory ini;
	o.saveToConfigFile(ini, "opts");
	CEvidentialGridMap2D::TInsertionOptions back;
	back.loadFromConfigFile(ini, "opts");
	std::ostringstream a, b;
	o.dumpToTextStream(a);
	back.dumpToTextStream(b);
	EXPECT_EQ(a.str(), b.str());
	EXPECT_EQ(back.muF, o.muF);
	EXPECT_NEAR(back.sectorWidth, o.sectorWidth, 1e-15);
	EXPECT_NEAR(back.horizontalTolerance, o.horizontalTolerance, 1e-15);
	EXPECT_EQ(back.decayRate, o.decayRate);
	EXPECT_EQ(back.fusionRule, o.fusionRule);
	EXPECT_EQ(back.freeMargin, o.freeMargin);
	EXPECT_EQ(back.motionWindow, o.motionWindow);
	EXPECT_EQ(back.motionMinConflict, o.motionMinConflict);
	EXPECT_EQ(back.motionClearance, o.motionClearance);
	EXPECT_EQ(back.groundRemoval, o.groundRemoval);
	EXPECT_EQ(back.minObstacleHeight, o.minObstacleHeight);
	EXPECT_EQ(back.maxObstacleHeight, o.maxObstacleHeight);
	EXPECT_EQ(back.groundReturns, o.groundReturns);
	EXPECT_EQ(back.insertionThreads, 3u);
	for (const char* key :
		 {"sensorModel", "muF", "muO", "imprecision", "imprecisionProfile",
		  "sectorWidth", "maxRange", "invalidRangesAsFree", "freeMargin", "fusionRule",
		  "decayRate", "horizontalTolerance", "conflictHandling", "growthMargin",
		  "motionWindow", "motionMinConflict", "motionClearance", "groundRemoval",
		  "minObstacleHeight", "maxObstacleHeight", "groundReturns", "insertionThreads"})
		EXPECT_NE(a.str().find(key), std::string::npos) << key;
}

TEST(MapIni, InvalidValuesAreRejectedNamingKeyAndValue)
{
	const std::vector<std::pair<std::string, std::string>> bad = {
		{"insertOpts", "muF=1.5"},
		{"insertOpts", "muO=-0.1"},
		{"insertOpts", "muF=abc"},
		{"insertOpts", "sensorModel=Sonar"},
		{"insertOpts", "sensorModel=7"},
		{"insertOpts", "fusionRule=Average"},
		{"insertOpts", "imprecisionProfile=Triangle"},
		{"insertOpts", "conflictHandling=Ignore"},
		{"insertOpts", "decayRate=-1"},
		{"insertOpts", "imprecision=-0.2"},
		{"insertOpts", "maxRange=0"},
		{"insertOpts", "sectorWidth=400"},
		{"insertOpts", "horizontalTolerance=100"},
		{"insertOpts", "invalidRangesAsFree=maybe"},
		{"insertOpts", "growthMargin=nan"},
		{"insertOpts", "freeMargin=-0.1"},
		{"insertOpts", "motionWindow=0"},
		{"insertOpts", "motionWindow=inf"},
		{"insertOpts", "motionMinConflict=1.5"},
		{"insertOpts", "motionClearance=-1"},
		{"insertOpts", "groundRemoval=Ransac"},
		{"insertOpts", "minObstacleHeight=-0.1"},
		{"insertOpts", "maxObstacleHeight=0.1"},
		{"insertOpts", "maxObstacleHeight=nan"},
		{"insertOpts", "groundReturns=Maybe"},
		{"insertOpts", "insertionThreads=0"},
		{"insertOpts", "insertionThreads=65"},
		{"insertOpts", "insertionThreads=1.5"},
		{"renderOpts", "style=Pretty"},
		{"renderOpts", "freeColor=#12345"},
		{"renderOpts", "occupiedColor=black"},
		{"renderOpts", "appearedColor=#FF8C00FF"},
		{"renderOpts", "showFree=perhaps"},
		{"renderOpts", "height=nan"},
		{"renderOpts", "height=1e4"},
		{"creationOpts", "resolution=0"},
		{"creationOpts", "resolution=-0.1"},
		{"creationOpts", "min_x=20"},
		{"creationOpts", "min_y=5\nmax_y=5"},
		{"creationOpts", "maxCells=0"},
		{"creationOpts", "maxCells=-3"},
		// More than a saved map may hold (it could not be read back).
		{"creationOpts", "maxCells=2e9"},
		{"creationOpts", "maxCells=1000000001"},
		// Values that only their own text names faithfully.
		{"insertOpts", "muO=-1e-9"},
		{"insertOpts", "muF=nan"},
		{"insertOpts", "decayRate=-1e-300"},
		{"insertOpts", "growthMargin=-2.5e-7"},
		{"insertOpts", "maxRange=-0.0001"},
		{"insertOpts", "horizontalTolerance=-1e-3"},
		{"creationOpts", "resolution=-1e-12"},
		{"creationOpts", "min_x=1e1\nmax_x=10"},
		// Grids beyond the budget, from either side, and beyond the limits.
		{"creationOpts", "maxCells=100"},
		{"creationOpts", "resolution=1e-5"},
		{"creationOpts", "resolution=1e-7"},
		{"creationOpts", "resolution=2e6"},
		{"creationOpts", "min_x=-2e9"},
		{"creationOpts", "max_y=1e10"},
		// Valid alone, but more than 1e7 range bins of the grid's 0.10 m
		// cells: refused when read, not at the first scan.
		{"insertOpts", "maxRange=2e6"},
		// A decimal comma, or more than one value: a reader that stopped at
		// the first comma or space would take 0, 1 and 0.6.
		{"insertOpts", "muO=0,95"},
		{"insertOpts", "maxRange=1,5"},
		{"insertOpts", "muF=0.6 0.7"},
		{"insertOpts", "sensorModel=Reinforced MultiEcho"},
		{"renderOpts", "freeColor=#112233,#445566"},
		{"creationOpts", "resolution=0,05"},
	};
	for (const auto& [section, line] : bad)
	{
		const std::string first = line.substr(0, line.find('\n'));
		const std::string key = first.substr(0, first.find('='));
		const std::string value = first.substr(first.find('=') + 1);
		const std::string message = loadError(
			"[Map]\nevidentialGrid_count=1\n[Map_evidentialGrid_00_" + section +
			"]\n" + line + "\n");
		EXPECT_NE(message.find(key), std::string::npos)
			<< line << " gave: '" << message << "'";
		EXPECT_NE(message.find("'" + value + "'"), std::string::npos)
			<< line << " gave: '" << message << "'";
	}
}

// ---------------------------------------------------------------------------
// Options set in code (their .ini readers: above)
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
		{"freeMargin", [](Options& o) { o.freeMargin = kInf; }},
		{"motionWindow", [](Options& o) { o.motionWindow = -1.0; }},
		{"motionMinConflict", [](Options& o) { o.motionMinConflict = 0.0; }},
		{"motionClearance", [](Options& o) { o.motionClearance = kNaN; }},
		{"minObstacleHeight", [](Options& o) { o.minObstacleHeight = kInf; }},
		{"maxObstacleHeight", [](Options& o) { o.maxObstacleHeight = o.minObstacleHeight; }},
		{"groundRemoval",
		 [](Options& o) { o.groundRemoval = static_cast<GroundRemoval>(4); }},
		{"groundReturns",
		 [](Options& o) { o.groundReturns = static_cast<GroundReturns>(2); }},
		{"insertionThreads", [](Options& o) { o.insertionThreads = 0; }},
		{"fusionRule", [](Options& o) { o.fusionRule = static_cast<FusionRule>(17); }},
		{"sensorModel", [](Options& o) { o.sensorModel = static_cast<SensorModel>(9); }},
		{"conflictHandling",
		 [](Options& o) { o.conflictHandling = static_cast<ConflictHandling>(5); }},
	};
	for (const auto& [field, spoil] : cases)
	{
		CEvidentialGridMap2D map = smallMap();
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
		CEvidentialGridMap2D map = smallMap();
		EXPECT_THROW(map.setSize(x0, x1, 0, 1, res), std::invalid_argument);
		EXPECT_EQ(map.getSizeX(), 100);  // unchanged
	}
	CEvidentialGridMap2D map = smallMap();
	EXPECT_THROW(map.setMaxCells(0), std::invalid_argument);
	EXPECT_THROW(map.setMaxCells(9'999), std::invalid_argument);
	// A saved map holds at most 1e9 cells: a map given more could not be read.
	EXPECT_THROW(map.setMaxCells(1'000'000'001), std::invalid_argument);
	EXPECT_EQ(map.maxCells(), CEvidentialGridMap2D::kDefaultMaxCells);
	map.setMaxCells(1'000'000'000);
	EXPECT_EQ(map.maxCells(), 1'000'000'000u);
}

TEST(BadOptions, WideLikelihoodMarginOnAThinMapAllocatesLittle)
{
	// A 10 km corridor of one row, and distances cut at 60 m: a margin of
	// 1024 cells on every side would make the field 2000 times the map.
	CEvidentialGridMap2D map(0, 10'000, 0, 0.05, 0.05);
	map.likelihoodOptions.maxCorrsDistance = 60.0;
	resetLargestAllocation();
	const double l = map.computeObservationLikelihood(wall(), CPose3D(5000, 0, 0, 0, 0, 0));
	EXPECT_TRUE(std::isfinite(l));
	EXPECT_LT(largestAllocation(), std::size_t(64) << 20);
}

TEST(BadOptions, ExtremeLikelihoodOptionsGiveNumbers)
{
	// Valid, if absurd: squares of these overflow (the cut at most 1000 m).
	CEvidentialGridMap2D map = smallMap();
	ASSERT_TRUE(map.insertObservation(wall(), CPose3D()));
	auto& o = map.likelihoodOptions;
	for (const auto& [sigma, cut, zHit, zRandom, range] :
		 std::vector<std::tuple<double, double, double, double, double>>{
			 {7.5e252, 1000.0, 5.5e16, 9.4e11, 9.4e78},
			 {1e-300, 1000.0, 1.0, 0.0, 1e300},
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
	// whatever the ranges; sparse rows hold the bins around the impacts (21
	// per sector for the default imprecision of 0.1 m in 1 cm bins).
	CEvidentialGridMap2D map(-5, 5, -5, 5, 0.01);
	map.insertionOptions.maxRange = 1000.0;
	resetLargestAllocation();
	EXPECT_NO_THROW(map.insertObservation(
		arcScan(1081, 3.0, kBadInputSetup.aperture(1.5 * M_PI)), CPose3D()));
	EXPECT_LT(largestAllocation(), std::size_t(4) << 20);
}
