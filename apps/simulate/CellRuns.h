/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Lists of grid cells as text, for the ground truth files. */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_evidential::simulate
{
/** Appends " first-last" for a run of consecutive cell indices, " first"
 * for one, each followed by suffix. */
void appendCellRun(std::string& out, int first, int last, const char* suffix);

/** "C ITEMS": the number of set flags, then their indices as runs. */
std::string cellRuns(const std::vector<uint8_t>& flags);

}  // namespace mrpt_evidential::simulate
