/* evgrid: creating a map from an .ini file, and reading a saved map. */

#include "MapFiles.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/TMetricMapInitializer.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <stdexcept>

#include "CObjectFileReader.h"
#include "CommandLine.h"

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
std::unique_ptr<CEvidentialGridMap2D> createMapFromConfig(
	const std::string& iniPath, const std::string& section)
{
	// CConfigFile reads a missing file as an empty one: check first.
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

	for (const auto& init : initializers)
	{
		const auto* definition =
			dynamic_cast<const CEvidentialGridMap2D::TMapDefinition*>(
				init.get());
		if (!definition) continue;
		try
		{
			return std::unique_ptr<CEvidentialGridMap2D>(
				CEvidentialGridMap2D::CreateFromMapDefinition(*definition));
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
	return map;
}

void printDecisionCounts(
	std::ostream& os,
	const mrpt_evidential::CEvidentialGridMap2D::TDecisionCounts& counts,
	std::size_t cellCount)
{
	const auto flags = os.flags();
	const auto precision = os.precision();
	const auto line = [&](const char* what, std::size_t n) {
		os << "  " << std::left << std::setw(9) << what << std::right
		   << std::setw(12) << n << "  " << std::fixed << std::setprecision(2)
		   << std::setw(6)
		   << 100.0 * static_cast<double>(n) / static_cast<double>(cellCount)
		   << "%\n";
	};
	line("free", counts.free);
	line("occupied", counts.occupied);
	line("unknown", counts.unknown);
	line("conflict", counts.conflict);
	os.flags(flags);
	os.precision(precision);
}

}  // namespace evgrid
