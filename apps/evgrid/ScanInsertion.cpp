/* evgrid: inserting one scan into a map, with an error that names it. */

#include "ScanInsertion.h"

#include <stdexcept>

#include "CommandLine.h"

namespace evgrid
{
bool insertScan(
	mrpt::maps::CMetricMap& map, const mrpt::obs::CObservation2DRangeScan& scan,
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
			place + ": " + which + "cannot insert the scan: " + describe(e));
	}
}

}  // namespace evgrid
