/* evgrid: inserting one scan into a map, as build, compare and score-motion
 * do: one home for the error that says which scan the map could not take,
 * and for the one that says the scans left the map empty. */
#pragma once

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>

#include <string>

namespace evgrid
{
/** map.insertObservation(obs, pose), for a 2-D scan or a 3-D cloud. Damaged
 * data can parse into one the map refuses (a sensor pose that is not a
 * number): the error names it.
 * \param place CInputWalker::place(), where the scan is in the input.
 * \param mapName which map, where there is more than one; else null.
 * \return what insertObservation() returns (false: the map declined it).
 * \throws std::runtime_error "PLACE: [MAP ]cannot insert the scan: WHY"
 *  ("the cloud" for other observations). */
bool insertScan(
	mrpt::maps::CMetricMap& map, const mrpt::obs::CObservation& scan,
	const mrpt::poses::CPose3D& pose, const std::string& place,
	const char* mapName = nullptr);

/** After a run that inserted `inserted` scans into `map`: those scans all
 * lay beyond the grid that maxCells lets it grow to, so that the map holds
 * nothing but unknown cells.
 * \throws std::runtime_error "INPUT: no cell of the map was seen: ..." then. */
void requireACellSeen(
	const mrpt_evidential::CEvidentialGridMap2D& map, std::size_t inserted,
	const std::string& input);

}  // namespace evgrid
