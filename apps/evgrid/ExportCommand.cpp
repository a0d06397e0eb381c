/* evgrid export: a saved map in other formats. */

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <iostream>
#include <vector>

#include <mrpt_evidential/support/AtomicFile.h>
#include "CPoseFile.h"
#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"
#include "MapOutputs.h"
#include "StopSignal.h"

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
		"of --png, --gridmap, --ros, --scene. Each file is written under a temporary "
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
	TCLAP::ValueArg<std::string> argPath(
		"", "path",
		"With --scene: the robot's path to draw over the map, a text file of "
		"lines `key x y phi` (icp-slam's log_estimated_path.txt, a ground "
		"truth file).",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argScene(
		"", "scene",
		"A scene for MRPT's SceneViewer3D (FILE.3Dscene): the map as its 3-D "
		"view draws it (its renderOpts), and the --path if given.",
		false, "", "FILE", cmd);
	TCLAP::SwitchArg argBare(
		"", "bare", "With --png: the pictures without their legend strip.", cmd, false);
	TCLAP::ValueArg<std::string> argPng(
		"", "png",
		"Folder (created if missing) for map.png, evidential.png, betp.png, "
		"conflict.png and motion.png: one pixel per cell, north up, above a "
		"legend and a scale bar.",
		false, "", "DIR", cmd);
	TCLAP::UnlabeledValueArg<std::string> argMap(
		"map", "Required. The saved map (.evgrid, plain or gzip-compressed).",
		false, "", "MAP", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first))
		return *exitCode;
	requireMapFile(argMap.getValue());
	if (argPath.isSet() && !argScene.isSet()) throw UsageError("--path needs --scene");
	if (argBare.isSet() && !argPng.isSet()) throw UsageError("--bare needs --png");
	if (!argPng.isSet() && !argGridmap.isSet() && !argRos.isSet() && !argScene.isSet())
		throw UsageError("nothing to do: give --png, --gridmap, --ros and/or --scene");
	for (auto* arg : {&argPng, &argGridmap, &argRos, &argScene, &argPath})
		if (arg->isSet() && arg->getValue().empty())
			throw UsageError("--" + arg->getName() + " needs a non-empty value");

	// Each file is written whole under a temporary name and renamed: a stop
	// request waits for the file being written, then ends the command.
	catchStopSignals();
	const auto map = loadMap(argMap.getValue());
	std::vector<std::string> written;
	bool anyWritten = false;
	const auto stopIfRequested = [&] {
		if (!argQuiet.getValue())
			for (const auto& file : written) std::cout << "wrote " << file << "\n";
		anyWritten = anyWritten || !written.empty();
		written.clear();
		throwIfStopRequested(
			anyWritten ? "the files listed were written whole, the others left as they were"
					   : "no file was written");
	};
	std::vector<mrpt::math::TPoint3D> path;
	if (argPath.isSet())
	{
		const CPoseFile poses = CPoseFile::load(argPath.getValue(), CPoseFile::Kind::Auto);
		for (const auto& p : poses.poses()) path.emplace_back(p.x, p.y, 0.0);
	}
	// Every file to write, checked before the first is written: none may be
	// the map or the path read, a folder, a device or a pipe.
	if (argRos.isSet() && std::filesystem::path(argRos.getValue()).filename().empty())
		throw UsageError("--ros needs a file prefix (DIR/NAME), not a folder: " + argRos.getValue());
	std::vector<std::string> outputs;
	if (argGridmap.isSet()) outputs.push_back(argGridmap.getValue());
	if (argRos.isSet())
		for (const char* extension : {".pgm", ".yaml"})
			outputs.push_back(argRos.getValue() + extension);
	if (argScene.isSet()) outputs.push_back(argScene.getValue());
	if (argPng.isSet())
		for (const char* name : CEvidentialGridMap2D::pictureNames())
			outputs.push_back((std::filesystem::path(argPng.getValue()) / name).string());
	for (const auto& output : outputs)
		checkOutputFile(output, {argMap.getValue(), argPath.isSet() ? argPath.getValue() : ""});
	if (argPng.isSet())
	{
		stopIfRequested();
		for (const auto& file : savePicturesIn(*map, argPng.getValue(), !argBare.getValue()))
			written.push_back(file);
	}
	if (argGridmap.isSet())
	{
		stopIfRequested();
		writeGridmap(*map, argGridmap.getValue());
		written.push_back(argGridmap.getValue());
	}
	if (argRos.isSet())
	{
		stopIfRequested();
		map->saveAsROSMap(argRos.getValue());
		written.push_back(argRos.getValue() + ".pgm");
		written.push_back(argRos.getValue() + ".yaml");
	}
	if (argScene.isSet())
	{
		stopIfRequested();
		map->saveAsScene(argScene.getValue(), path);
		written.push_back(argScene.getValue());
	}
	stopIfRequested();
	return 0;
}

}  // namespace evgrid
