/* evgrid export: a saved map in other formats. */

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <iostream>
#include <vector>

#include <mrpt_evidential/support/AtomicFile.h>
#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"
#include "MapOutputs.h"

using mrpt_evidential::CEvidentialGridMap2D;
using mrpt_evidential::detail::writeFileAtomicallyByName;

namespace evgrid
{
namespace
{
const std::string kName = "evgrid export";

/** The format MRPT programs read as `.gridmap` (e.g. pf-localization's
 * map_file): the COccupancyGridMap2D object in MRPT's serialization,
 * gzip-compressed. */
void writeGridmap(const CEvidentialGridMap2D& map, const std::string& path)
{
	mrpt::maps::COccupancyGridMap2D grid;
	map.getAsOccupancyGrid(grid);
	writeFileAtomicallyByName(path, [&grid](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f(tmp);
		auto archive = mrpt::serialization::archiveFrom(f);
		archive << grid;
		f.close();
		return true;
	});
}
}  // namespace

int runExport(int argc, char** argv, int first)
{
	TCLAP::CmdLine cmd(
		"Writes a saved map (map.evgrid) in other formats; give at least one "
		"of --png, --gridmap, --ros. Each file is written under a temporary "
		"name and renamed, so a failure leaves the previous one in place. See "
		"doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::SwitchArg argQuiet(
		"q", "quiet", "Do not list the files written.", cmd, false);
	TCLAP::ValueArg<std::string> argRos(
		"", "ros",
		"ROS map_server pair PREFIX.pgm + PREFIX.yaml: occupancy = BetP, "
		"trinary (0 occupied above 0.65, 254 free below 0.196, 205 unknown).",
		false, "", "PREFIX", cmd);
	TCLAP::ValueArg<std::string> argGridmap(
		"", "gridmap",
		"MRPT occupancy grid (COccupancyGridMap2D, gzip-compressed, as "
		"pf-localization's map_file reads it); cell occupancy = BetP.",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argPng(
		"", "png",
		"Folder (created if missing) for evidential.png, betp.png and "
		"conflict.png, one pixel per cell, north up.",
		false, "", "DIR", cmd);
	TCLAP::UnlabeledValueArg<std::string> argMap(
		"map", "Required. The saved map (.evgrid, plain or gzip-compressed).",
		false, "", "MAP", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first))
		return *exitCode;
	requireMapFile(argMap.getValue());
	if (!argPng.isSet() && !argGridmap.isSet() && !argRos.isSet())
		throw UsageError("nothing to do: give --png, --gridmap and/or --ros");
	for (auto* arg : {&argPng, &argGridmap, &argRos})
		if (arg->isSet() && arg->getValue().empty())
			throw UsageError("--" + arg->getName() + " needs a non-empty value");

	const auto map = loadMap(argMap.getValue());
	for (auto* arg : {&argGridmap, &argRos})
		if (arg->isSet())
			createFolder(
				std::filesystem::path(arg->getValue()).parent_path().string());
	std::vector<std::string> written;
	if (argPng.isSet())
		for (const auto& path : savePicturesIn(*map, argPng.getValue()))
			written.push_back(path);
	if (argGridmap.isSet())
	{
		writeGridmap(*map, argGridmap.getValue());
		written.push_back(argGridmap.getValue());
	}
	if (argRos.isSet())
	{
		map->saveAsROSMap(argRos.getValue());
		written.push_back(argRos.getValue() + ".pgm");
		written.push_back(argRos.getValue() + ".yaml");
	}
	if (!argQuiet.getValue())
		for (const auto& path : written) std::cout << "wrote " << path << "\n";
	return 0;
}

}  // namespace evgrid
