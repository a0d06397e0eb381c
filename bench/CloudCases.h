/* evgrid-bench: the cases of 3-D clouds (issue 12), beside the 2-D ones. */
#pragma once

#include "Cases.h"

#include <functional>
#include <map>
#include <string>

namespace bench
{
/** The cloud cases: a simulated 16-layer scan of about 30,000 points and the
 * real VLP-16 one, into our map and, flattened into one 360-degree scan,
 * into COccupancyGridMap2D with widening beams, at 0.05 and 0.10 m. */
void registerCloudCases();
/** Their ratios, from the microseconds per case. */
void printCloudRatios(const std::map<std::string, double>& microseconds);
}  // namespace bench
