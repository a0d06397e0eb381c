/* evgrid: creating a map from an .ini file, and reading and saving map files. */

#include "MapFiles.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_streams.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "CObjectFileReader.h"
#include "CommandLine.h"

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
namespace
{
/** The maps a CMultiMetricMap would create from `section` of `iniPath`.
 * \throws std::runtime_error naming the file if it cannot be read or has no
 *  such section. */
mrpt::maps::TSetOfMetricMapInitializers readInitializers(
	const std::string& iniPath, const std::string& section)
{
	// CConfigFile reads a missing file as an empty one, and fails on a
	// folder with a bare allocation error: check first.
	std::error_code ec;
	if (std::filesystem::is_directory(iniPath, ec))
		throw std::runtime_error(iniPath + ": is a directory, not a config file");
	if (!std::ifstream(iniPath))
		throw std::runtime_error(
			iniPath + ": cannot open the config file: " + std::strerror(errno));

	mrpt::maps::TSetOfMetricMapInitializers initializers;
	try
	{
		mrpt::config::CConfigFile ini(iniPath);
		if (!ini.sectionExists(section))
			throw std::runtime_error(
				"no section [" + section +
				"] (use --section to name the one that lists the maps)");
		initializers.loadFromConfigFile(ini, section);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(iniPath + ": " + describe(e));
	}
	return initializers;
}
}  // namespace

std::unique_ptr<CEvidentialGridMap2D> createMapFromConfig(
	const std::string& iniPath, const std::string& section)
{
	const mrpt::maps::TSetOfMetricMapInitializers initializers =
		readInitializers(iniPath, section);
	for (const auto& init : initializers)
	{
		const auto* definition =
			dynamic_cast<const CEvidentialGridMap2D::TMapDefinition*>(
				init.get());
		if (!definition) continue;
		try
		{
			return CEvidentialGridMap2D::fromDefinition(*definition);
		}
		catch (const std::exception& e)
		{
			throw std::runtime_error(iniPath + ": " + describe(e));
		}
	}
	throw std::runtime_error(
		iniPath + ": section [" + section +
		"] creates no evidential grid (it needs evidentialGrid_count=1 and "
		"the sections [" +
		section + "_evidentialGrid_00_creationOpts], _insertOpts, "
				  "_likelihoodOpts)");
}

namespace
{
/** MRPT reads its grid's options unchecked: a zero LF_decimation loops
 * forever in its likelihood, a zero or negative spread or range scores
 * nothing. \throws std::runtime_error naming the key. */
void checkMrptGridOptions(
	const mrpt::maps::COccupancyGridMap2D::TMapDefinition& definition, const std::string& iniPath)
{
	using Grid = mrpt::maps::COccupancyGridMap2D;
	const auto& lo = definition.likelihoodOpts;
	const auto& io = definition.insertionOpts;
	const auto refuse = [&iniPath](const std::string& key, const std::string& rule) {
		throw std::runtime_error(
			iniPath + ": the occupancyGrid's " + key + " " + rule +
			" (MRPT reads it unchecked; evgrid compare would hang or score nothing)");
	};
	if (lo.LF_decimation < 1) refuse("LF_decimation", "must be at least 1");
	if (!(lo.LF_stdHit > 0)) refuse("LF_stdHit", "must be positive");
	if (!(lo.LF_maxCorrsDistance > 0)) refuse("LF_maxCorrsDistance", "must be positive");
	if (!(lo.LF_maxRange > 0)) refuse("LF_maxRange", "must be positive");
	if (!(io.maxDistanceInsertion > 0)) refuse("maxDistanceInsertion", "must be positive");
	if (lo.likelihoodMethod < Grid::lmMeanInformation ||
		lo.likelihoodMethod > Grid::lmConsensusOWA)
		refuse("likelihoodMethod", "is no method MRPT knows");
}
}  // namespace

std::optional<mrpt::maps::COccupancyGridMap2D::TMapDefinition> occupancyGridFromConfig(
	const std::string& iniPath, const std::string& section)
{
	for (const auto& init : readInitializers(iniPath, section))
		if (const auto* definition =
				dynamic_cast<const mrpt::maps::COccupancyGridMap2D::TMapDefinition*>(
					init.get()))
		{
			checkMrptGridOptions(*definition, iniPath);
			return *definition;
		}
	return std::nullopt;
}

CEvidentialGridMap2D::Ptr loadMap(const std::string& path)
{
	CObjectFileReader reader(path);
	const auto object = reader.next();
	if (!object) throw std::runtime_error(path + ": the file is empty");
	auto map = std::dynamic_pointer_cast<CEvidentialGridMap2D>(object);
	if (!map)
		throw std::runtime_error(
			path + ": holds a " + object->GetRuntimeClass()->className +
			", not an evidential grid map");
	// Two map files joined (cat a b > c) would read as the first alone.
	if (reader.next())
		throw std::runtime_error(
			path + ": holds more than the map (another object after it: files joined?)");
	return map;
}

void saveMap(const CEvidentialGridMap2D& map, const std::string& path)
{
	std::ofstream f(path, std::ios::binary);
	try
	{
		auto archive = mrpt::serialization::archiveFrom<std::ostream>(f);
		archive << map;
	}
	catch (const std::exception& e)
	{
		// MRPT's archive fails on a full disk without naming the file.
		throw std::runtime_error(path + ": cannot write the map (" + describe(e) + ")");
	}
	f.close();
	if (!f) throw std::runtime_error(path + ": cannot write the map");
}

}  // namespace evgrid
