/* CEvidentialGridMap2D created from .ini files through CMultiMetricMap. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <sstream>

#include "support/test_helpers.h"

using namespace mrpt_evidential;

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
	for (const char* key :
		 {"sensorModel", "muF", "muO", "imprecision", "imprecisionProfile",
		  "sectorWidth", "maxRange", "invalidRangesAsFree", "fusionRule",
		  "decayRate", "horizontalTolerance", "conflictHandling", "growthMargin"})
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
		{"creationOpts", "resolution=0"},
		{"creationOpts", "resolution=-0.1"},
		{"creationOpts", "min_x=20"},
		{"creationOpts", "min_y=5\nmax_y=5"},
		{"creationOpts", "maxCells=0"},
		{"creationOpts", "maxCells=-3"},
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
