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

}  // namespace evgrid
