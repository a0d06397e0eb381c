/* Plain checks of a map's cells, for the map suites and the fuzz targets
 * (no GoogleTest); map_assertions.h wraps them for GoogleTest. */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <sstream>
#include <string>

#include "mass_text.h"

namespace mrpt_evidential::test
{
/** What is wrong with a map: "" when the grid is within its cell budget and
 * every cell holds a valid mass function, else the first fault found. */
inline std::string mapDefect(const CEvidentialGridMap2D& map)
{
	std::ostringstream out;
	const std::size_t cells = map.geometry().cellCount();
	if (cells > map.maxCells())
		out << cells << " cells exceed the budget of " << map.maxCells();
	else
		map.geometry().forEachIndex([&](std::size_t i) {
			if (out.tellp() == 0 && !map.storage().read(i).isValid(1e-9))
				out << "cell " << i << " holds " << map.storage().read(i);
		});
	return out.str();
}

/** How many cells hold anything but the vacuous mass. */
inline std::size_t informedCells(const CEvidentialGridMap2D& map)
{
	std::size_t n = 0;
	map.geometry().forEachIndex([&](std::size_t i) {
		if (map.storage().read(i) != Mass::vacuous()) ++n;
	});
	return n;
}
}  // namespace mrpt_evidential::test
