/* evgrid: build, inspect, export and compare evidential (Dempster-Shafer)
 * occupancy grid maps, and score their motion layer. `evgrid <subcommand>
 * --help` documents each subcommand. */

#include <iostream>
#include <string>

#include "CommandLine.h"
#include "Commands.h"

namespace
{
void printOverview(std::ostream& out)
{
	out << "evgrid " EVGRID_VERSION
		   " - evidential (Dempster-Shafer) occupancy grid maps for MRPT\n\n"
		   "Usage: evgrid <subcommand> [options]\n\n"
		   "Subcommands:\n"
		   "  build    build a map from a rawlog or a simplemap: map.evgrid, "
		   "pictures, summary\n"
		   "  inspect  print a saved map's geometry, options and counts per "
		   "decision, or one cell\n"
		   "  export   write a saved map as PNG pictures, an MRPT .gridmap, or "
		   "a ROS map_server PGM + YAML pair\n"
		   "  compare  build our map and MRPT's COccupancyGridMap2D from the "
		   "same scans; report\n"
		   "           how their cells agree and each map's localization hit "
		   "rate\n"
		   "  score-motion  replay a rawlog of evgrid-simulate scan by scan; "
		   "score the map's\n"
		   "           motion layer (Appeared, Disappeared) against the "
		   "simulator's ground truth\n"
		   "  merge    fuse saved maps of the same place from several runs "
		   "into one\n"
		   "  diff     what appeared and what disappeared between two runs' "
		   "maps\n\n"
		   "'evgrid <subcommand> --help' lists a subcommand's options.\n"
		   "Exit codes: 0 success, 1 failure (the message names the file), 2 "
		   "bad command line.\n";
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 2)
	{
		printOverview(std::cerr);
		return evgrid::kExitUsage;
	}
	const std::string sub = argv[1];
	if (sub == "--help" || sub == "-h" || sub == "help")
	{
		printOverview(std::cout);
		return 0;
	}
	if (sub == "--version")
	{
		std::cout << "evgrid " EVGRID_VERSION "\n";
		return 0;
	}

	int (*run)(int, char**, int) = nullptr;
	if (sub == "build") run = evgrid::runBuild;
	else if (sub == "inspect") run = evgrid::runInspect;
	else if (sub == "export") run = evgrid::runExport;
	else if (sub == "compare") run = evgrid::runCompare;
	else if (sub == "score-motion") run = evgrid::runScoreMotion;
	else if (sub == "merge") run = evgrid::runMerge;
	else if (sub == "diff") run = evgrid::runDiff;
	else
	{
		evgrid::printError("evgrid", "unknown subcommand '" + sub + "'");
		std::cerr << "Try 'evgrid --help'.\n";
		return evgrid::kExitUsage;
	}

	const std::string name = "evgrid " + sub;
	try
	{
		return run(argc, argv, 2);
	}
	catch (const evgrid::UsageError& e)
	{
		evgrid::printError(name, e.what());
		std::cerr << "Try '" << name << " --help'.\n";
		return evgrid::kExitUsage;
	}
	catch (const std::exception& e)
	{
		evgrid::printError(name, evgrid::describe(e));
		return evgrid::kExitFailure;
	}
}
