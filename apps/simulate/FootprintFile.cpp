/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The static footprint truth of a 3-D scene. */
#include "FootprintFile.h"

#include <mrpt/io/CFileGZOutputStream.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "CellRuns.h"

namespace mrpt_evidential::simulate
{
void writeFootprint(
	const std::string& path, const TFootprintGrid& grid,
	const std::string& sceneName)
{
	const TGridGeometry& g = grid.geometry;
	char header[256];
	std::snprintf(
		header, sizeof(header),
		"evgrid-simulate footprint 1\nscene %s\ngrid %.2f %.2f %.2f %d %d\n"
		"heights %.2f %.2f\n",
		sceneName.c_str(), g.xMin, g.yMin, g.resolution, g.sizeX, g.sizeY,
		TFootprintGrid::kLow, TFootprintGrid::kHigh);
	std::string text = header;
	const std::pair<const char*, EFootprint> classes[] = {
		{"obstacle", EFootprint::Obstacle},
		{"low", EFootprint::Low},
		{"overhang", EFootprint::Overhang}};
	for (const auto& [name, value] : classes)
	{
		std::vector<uint8_t> flags(grid.cells.size());
		for (std::size_t i = 0; i < flags.size(); ++i)
			flags[i] = grid.cells[i] == value;
		text += std::string(name) + " " + cellRuns(flags) + "\n";
	}

	mrpt::io::CFileGZOutputStream file;
	if (std::string error; !file.open(path, 9, error))
		throw std::runtime_error("cannot write " + path + ": " + error);
	if (file.Write(text.data(), text.size()) != text.size())
		throw std::runtime_error("cannot write " + path);
	file.close();
}

}  // namespace mrpt_evidential::simulate
