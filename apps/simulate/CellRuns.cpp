/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * Lists of grid cells as text. */
#include "CellRuns.h"

#include <cstdio>

namespace mrpt_evidential::simulate
{
void appendCellRun(std::string& out, int first, int last, const char* suffix)
{
	char item[48];
	if (first == last)
		std::snprintf(item, sizeof(item), " %d%s", first, suffix);
	else
		std::snprintf(item, sizeof(item), " %d-%d%s", first, last, suffix);
	out += item;
}

std::string cellRuns(const std::vector<uint8_t>& flags)
{
	std::string runs;
	std::size_t count = 0;
	for (int i = 0, n = static_cast<int>(flags.size()); i < n; ++i)
	{
		if (!flags[i]) continue;
		int last = i;
		while (last + 1 < n && flags[last + 1])
			++last;
		appendCellRun(runs, i, last, "");
		count += static_cast<std::size_t>(last - i + 1);
		i = last;
	}
	return std::to_string(count) + runs;
}

}  // namespace mrpt_evidential::simulate
