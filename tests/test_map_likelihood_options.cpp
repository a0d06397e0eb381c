/* The likelihood options of CEvidentialGridMap2D: every key read from an
 * .ini section, absent keys kept, bad values named with their key, and the
 * dump read back. */
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <sstream>
#include <string>
#include <vector>

using mrpt_evidential::CEvidentialGridMap2D;

namespace
{
using Options = CEvidentialGridMap2D::TLikelihoodOptions;

mrpt::config::CConfigFileMemory iniWith(const std::string& lines)
{
	return mrpt::config::CConfigFileMemory("[likelihoodOpts]\n" + lines);
}

TEST(LikelihoodOptions, LoadsEveryKey)
{
	const auto ini = iniWith(
		"occupiedMass = 0.45\nmaxCorrsDistance = 0.6\nsigma = 0.2\n"
		"zHit = 0.8\nzRandom = 0.2\nmaxRange = 30\ndecimation = 3\n"
		"unknownAsNeutral = false\n");
	Options o;
	o.loadFromConfigFile(ini, "likelihoodOpts");
	EXPECT_DOUBLE_EQ(o.occupiedMass, 0.45);
	EXPECT_DOUBLE_EQ(o.maxCorrsDistance, 0.6);
	EXPECT_DOUBLE_EQ(o.sigma, 0.2);
	EXPECT_DOUBLE_EQ(o.zHit, 0.8);
	EXPECT_DOUBLE_EQ(o.zRandom, 0.2);
	EXPECT_DOUBLE_EQ(o.maxRange, 30.0);
	EXPECT_EQ(o.decimation, 3u);
	EXPECT_FALSE(o.unknownAsNeutral);
}

TEST(LikelihoodOptions, AbsentKeysKeepTheirValues)
{
	Options o;
	o.sigma = 0.5;
	o.decimation = 7;
	o.unknownAsNeutral = false;
	o.loadFromConfigFile(iniWith("zHit = 0.9\n"), "likelihoodOpts");
	EXPECT_DOUBLE_EQ(o.zHit, 0.9);
	EXPECT_DOUBLE_EQ(o.sigma, 0.5);
	EXPECT_EQ(o.decimation, 7u);
	EXPECT_FALSE(o.unknownAsNeutral);
	EXPECT_DOUBLE_EQ(o.occupiedMass, Options().occupiedMass);
	// A missing section is all absent keys.
	Options untouched;
	untouched.loadFromConfigFile(iniWith(""), "noSuchSection");
	EXPECT_DOUBLE_EQ(untouched.maxRange, Options().maxRange);
}

TEST(LikelihoodOptions, InvalidValuesThrowNamingKeyAndValue)
{
	struct Case
	{
		std::string key, value;
	};
	const std::vector<Case> cases{
		{"occupiedMass", "0"},		 {"occupiedMass", "1.5"},
		{"occupiedMass", "nan"},	 {"maxCorrsDistance", "0"},
		{"maxCorrsDistance", "inf"}, {"maxCorrsDistance", "1000.5"},
		{"sigma", "-1"},
		{"sigma", "abc"},			 {"sigma", "0.3x"},
		{"zHit", "-0.1"},			 {"zRandom", "-2"},
		{"maxRange", "0"},			 {"maxRange", "-5"},
		{"decimation", "0"},		 {"decimation", "-3"},
		{"decimation", "2.5"},		 {"unknownAsNeutral", "maybe"}};
	for (const Case& c : cases)
	{
		Options o;
		const Options before = o;
		try
		{
			o.loadFromConfigFile(
				iniWith(c.key + " = " + c.value + "\n"), "likelihoodOpts");
			ADD_FAILURE() << c.key << " = " << c.value << " was accepted";
		}
		catch (const std::invalid_argument& e)
		{
			const std::string what = e.what();
			EXPECT_NE(what.find("likelihoodOpts"), std::string::npos) << what;
			EXPECT_NE(what.find(c.key), std::string::npos) << what;
			EXPECT_NE(what.find(c.value), std::string::npos) << what;
		}
		// A failed load changes nothing.
		EXPECT_DOUBLE_EQ(o.sigma, before.sigma);
		EXPECT_DOUBLE_EQ(o.occupiedMass, before.occupiedMass);
		EXPECT_EQ(o.decimation, before.decimation);
	}
	// Both weights at zero: the message names both.
	Options o;
	try
	{
		o.loadFromConfigFile(
			iniWith("zHit = 0\nzRandom = 0\n"), "likelihoodOpts");
		ADD_FAILURE() << "zHit = zRandom = 0 was accepted";
	}
	catch (const std::invalid_argument& e)
	{
		const std::string what = e.what();
		EXPECT_NE(what.find("zHit"), std::string::npos) << what;
		EXPECT_NE(what.find("zRandom"), std::string::npos) << what;
	}
	// validate() sees values set in code; the example message of the header.
	o = Options();
	o.sigma = -1;
	try
	{
		o.validate();
		ADD_FAILURE() << "sigma = -1 was accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_STREQ(
			e.what(), "likelihoodOpts: sigma must be > 0 and finite, got -1");
	}
}

TEST(LikelihoodOptions, DumpHasEveryKeyAndReadsBack)
{
	Options o;
	o.sigma = 0.25;
	o.decimation = 2;
	o.unknownAsNeutral = false;
	std::ostringstream out;
	o.dumpToTextStream(out);
	const std::string dump = out.str();
	for (const char* key :
		 {"occupiedMass", "maxCorrsDistance", "sigma", "zHit", "zRandom",
		  "maxRange", "decimation", "unknownAsNeutral"})
		EXPECT_NE(dump.find(key), std::string::npos) << key << "\n" << dump;
	EXPECT_NE(dump.find(" m"), std::string::npos) << dump;
	// The dump is valid .ini text.
	Options back;
	back.loadFromConfigFile(iniWith(dump), "likelihoodOpts");
	EXPECT_DOUBLE_EQ(back.sigma, 0.25);
	EXPECT_EQ(back.decimation, 2u);
	EXPECT_FALSE(back.unknownAsNeutral);
}

}  // namespace
