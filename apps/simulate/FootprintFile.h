/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The static footprint truth of a 3-D scene: PREFIX.footprint.gz. */
#pragma once

#include <string>

#include "TFootprintGrid.h"

namespace mrpt_evidential::simulate
{
/** Writes the grid as gzip-compressed text (format in rawlogs/README.md
 * and evgrid-simulate --help): a header, then the cells of each class but
 * Ground as runs of indices, as PREFIX.motion.gz lists cells.
 * \throws std::runtime_error if the file cannot be written. */
void writeFootprint(
	const std::string& path, const TFootprintGrid& grid,
	const std::string& sceneName);

}  // namespace mrpt_evidential::simulate
