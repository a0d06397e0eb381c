/* evgrid-bench: whole runs (issue 15): stock scans along long paths from a
 * small grid that grows, against a grid that holds the path from the start,
 * and whole logs of mrpt-common along their paths, ours and MRPT's grid. */
#pragma once

#include "Cases.h"

#include <map>
#include <string>

namespace bench
{
/** Registers the paths' and the logs' runs. */
void registerRunCases();
/** Their ratios, from the microseconds per case. */
void printRunRatios(const std::map<std::string, double>& microseconds);
}  // namespace bench
