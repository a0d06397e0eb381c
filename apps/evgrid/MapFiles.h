/* evgrid: creating a map from an .ini file, and reading and saving map files. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <memory>
#include <optional>
#include <string>

namespace evgrid
{
/** The .ini section evgrid reads by default: the one icp-slam, rbpf-slam and
 * observations2map read their maps from, so one file serves them all. */
constexpr const char* kDefaultSection = "MappingApplication";

/** Creates the first evidential grid that a CMultiMetricMap would create from
 * `section` of the .ini file `iniPath` (`evidentialGrid_count` and the
 * `<section>_evidentialGrid_00_*` sections). Other maps of the section are
 * ignored. \throws std::runtime_error naming the file if it cannot be read,
 *  a value is invalid, or it creates no evidential grid. */
std::unique_ptr<mrpt_evidential::CEvidentialGridMap2D> createMapFromConfig(
	const std::string& iniPath, const std::string& section);

/** The options of the first COccupancyGridMap2D that a CMultiMetricMap would
 * create from the same section (`occupancyGrid_count` and the
 * `<section>_occupancyGrid_00_*` sections), or nothing when it creates none.
 * \throws std::runtime_error as createMapFromConfig() for a file it cannot
 *  read. */
std::optional<mrpt::maps::COccupancyGridMap2D::TMapDefinition> occupancyGridFromConfig(
	const std::string& iniPath, const std::string& section);

/** Reads a map saved by `evgrid build` or by saveMetricMapRepresentationToFile
 * (`.evgrid`, plain or gzip-compressed). \throws std::runtime_error naming
 * the file if it cannot be read or does not hold an evidential grid. */
mrpt_evidential::CEvidentialGridMap2D::Ptr loadMap(
	const std::string& path);

/** Writes `map` serialized, as loadMap() reads it back.
 * \throws std::runtime_error naming `path` if it cannot be written. */
void saveMap(
	const mrpt_evidential::CEvidentialGridMap2D& map, const std::string& path);

}  // namespace evgrid
