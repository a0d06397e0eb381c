/* evgrid: inserting one scan into a map, with an error that names it. */

#include "ScanInsertion.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <stdexcept>

#include "CommandLine.h"

namespace evgrid
{
bool insertScan(
	mrpt::maps::CMetricMap& map, const mrpt::obs::CObservation& scan,
	const mrpt::poses::CPose3D& pose, const std::string& place,
	const char* mapName)
{
	try
	{
		return map.insertObservation(scan, pose);
	}
	catch (const std::exception& e)
	{
		const std::string which = mapName ? std::string(mapName) + " " : "";
		throw std::runtime_error(
			place + ": " + which + "cannot insert the " +
			(dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&scan) ? "scan"
																			 : "cloud") +
			": " + describe(e));
	}
}

void requireACellSeen(
	const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted,
	const std::string& input)
{
	const auto counts = map.countDecisions();
	if (inserted == 0 || map.partlyInsertedCount() != inserted ||
		counts.free + counts.occupied + counts.conflict > 0)
		return;
	throw std::runtime_error(
		input + ": no cell of the map was seen: all " + std::to_string(inserted) +
		" scans inserted lay beyond the grid that maxCells (" + std::to_string(map.maxCells()) +
		" cells) lets it grow to (poses far from the grid's place? see the warning above)");
}

}  // namespace evgrid
