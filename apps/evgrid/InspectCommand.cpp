/* evgrid inspect: what a saved map holds. */

#include <mrpt/core/Clock.h>
#include <mrpt/system/datetime.h>

#include <iomanip>
#include <iostream>
#include <optional>

#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"
#include "MapOutputs.h"

using mrpt_evidential::CEvidentialGridMap2D;
using mrpt_evidential::Decision;

namespace evgrid
{
namespace
{
const std::string kName = "evgrid inspect";

struct TPoint
{
	double x, y;
};

std::optional<TPoint> parsePoint(const std::string& text)
{
	const auto comma = text.find(',');
	if (comma == std::string::npos) return std::nullopt;
	const auto x = toNumber(text.substr(0, comma));
	const auto y = toNumber(text.substr(comma + 1));
	if (!x || !y) return std::nullopt;
	return TPoint{*x, *y};
}

const char* decisionName(Decision d)
{
	switch (d)
	{
		case Decision::Free: return "Free";
		case Decision::Occupied: return "Occupied";
		case Decision::Conflict: return "Conflict";
		case Decision::Unknown: break;
	}
	return "Unknown";
}

void printCell(const CEvidentialGridMap2D& map, const TPoint& p)
{
	const auto& g = map.geometry();
	const int cx = g.cellX(p.x), cy = g.cellY(p.y);
	std::cout << std::fixed << std::setprecision(6) << "cell at (" << p.x
			  << ", " << p.y << ") m: ";
	if (!g.inside(cx, cy))
		std::cout << "outside the map (never seen)\n";
	else
		std::cout << "index (" << cx << ", " << cy << "), centre ("
				  << g.cellCenterX(cx) << ", " << g.cellCenterY(cy) << ")\n";
	const mrpt_evidential::Mass m = map.getCellMasses(p.x, p.y);
	std::cout << "  m(empty) " << m.conflict << "  m(F) " << m.free << "  m(O) "
			  << m.occupied << "  m(Omega) " << m.unknown << "\n"
			  << "  BetP " << map.getCellBetP(p.x, p.y) << "  decision "
			  << decisionName(map.getCellDecision(p.x, p.y)) << "\n";
	const mrpt_evidential::Motion motion = map.getCellMotion(p.x, p.y);
	std::cout << "  motion " << mrpt_evidential::motionName(motion);
	if (motion != mrpt_evidential::Motion::None)
		std::cout << " at " << map.getCellMotionTime(p.x, p.y) << " s ("
				  << map.latestTime() - map.getCellMotionTime(p.x, p.y)
				  << " s before the latest insertion)";
	else if (map.storage().keepsConflict())
		std::cout << " (the map keeps conflict: it has no motion layer)";
	std::cout << "\n";
}

void printMap(const std::string& path, const CEvidentialGridMap2D& map)
{
	std::cout << "map: " << path << "\n"
			  << map.geometryText()
			  << "insertions: " << map.insertionCount() << "\n"
			  << "latest time: ";
	if (map.insertionCount() == 0)
		std::cout << "none\n";
	else
		std::cout << std::fixed << std::setprecision(6) << map.latestTime()
				  << " s ("
				  << mrpt::system::dateTimeToString(
						 mrpt::Clock::fromDouble(map.latestTime()))
				  << " UTC)\n";
	printDecisionCounts(
		std::cout, map.countDecisions(), map.geometry().cellCount());
	printMotionCounts(std::cout, map);
	std::cout << "\n";
	printMapOptions(std::cout, map);
}
}  // namespace

int runInspect(int argc, char** argv, int first)
{
	TCLAP::CmdLine cmd(
		"Prints a saved map's (map.evgrid, or the .evgrid a stock MRPT program "
		"wrote) geometry, insertion count, latest data time, counts of cells "
		"per decision and options; with --cell, only the given cells. See "
		"doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::MultiArg<std::string> argCell(
		"", "cell",
		"Print only the cell holding world point X,Y (metres): its four masses "
		"m(empty) (conflict), m(F), m(O), m(Omega), its BetP (pignistic "
		"probability of occupancy) and its decision. May be repeated.",
		false, "X,Y", cmd);
	TCLAP::UnlabeledValueArg<std::string> argMap(
		"map", "Required. The saved map (.evgrid, plain or gzip-compressed).",
		false, "", "MAP", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first))
		return *exitCode;
	requireMapFile(argMap.getValue());
	std::vector<TPoint> cells;
	for (const std::string& text : argCell.getValue())
	{
		const auto p = parsePoint(text);
		if (!p)
			throw UsageError(
				"--cell must be X,Y in metres (e.g. --cell 1.5,-2), got '" +
				text + "'");
		cells.push_back(*p);
	}

	const auto map = loadMap(argMap.getValue());
	if (cells.empty()) printMap(argMap.getValue(), *map);
	for (const TPoint& p : cells) printCell(*map, p);
	return 0;
}

}  // namespace evgrid
