/* mrpt-evidential: the cells of one class as rectangles. */

#include "render/CellRectangles.h"

#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>

namespace mrpt_evidential::detail
{
std::vector<CellRectangle> rectanglesOf(
	const std::vector<std::uint8_t>& labels, int sizeX, int sizeY, std::uint8_t label,
	int maxSide)
{
	if (maxSide < 1) throw std::invalid_argument("rectanglesOf: maxSide must be at least 1");
	std::vector<CellRectangle> done;
	// The rectangles still growing, by their run [cx0, cx1] in the row below.
	std::map<std::pair<int, int>, CellRectangle> open, next;
	for (int cy = 0; cy < sizeY; ++cy)
	{
		const std::uint8_t* row = labels.data() + static_cast<std::size_t>(cy) * sizeX;
		for (int cx = 0; cx < sizeX;)
		{
			if (row[cx] != label)
			{
				++cx;
				continue;
			}
			const int first = cx;
			while (cx < sizeX && cx - first < maxSide && row[cx] == label) ++cx;
			const std::pair<int, int> run{first, cx - 1};
			const auto below = open.find(run);
			if (below != open.end() && below->second.cy1 - below->second.cy0 + 1 == maxSide)
			{
				done.push_back(below->second);
				open.erase(below);
				next.emplace(run, CellRectangle{first, cy, cx - 1, cy});
			}
			else if (below != open.end())
			{
				below->second.cy1 = cy;
				next.insert(*below);
				open.erase(below);
			}
			else
				next.emplace(run, CellRectangle{first, cy, cx - 1, cy});
		}
		// Runs the row did not continue are finished.
		for (const auto& [run, r] : open) done.push_back(r);
		open.swap(next);
		next.clear();
	}
	for (const auto& [run, r] : open) done.push_back(r);
	return done;
}

}  // namespace mrpt_evidential::detail
