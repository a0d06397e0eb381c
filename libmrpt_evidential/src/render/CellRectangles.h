/* mrpt-evidential: internal: the cells of one class of a grid as few
 * rectangles, so that the 3-D view draws each class as its own opaque
 * geometry (no texture whose transparent texels would hide another class). */
#pragma once

#include <cstdint>
#include <vector>

namespace mrpt_evidential::detail
{
/** Cells [cx0, cx1] x [cy0, cy1], bounds included. */
struct CellRectangle
{
	int cx0, cy0, cx1, cy1;
};

/** Rectangles that cover exactly the cells of `labels` (sizeX x sizeY, row
 * by row from cy = 0) equal to `label`, none overlapping: the runs of each
 * row, cut every `maxSide` cells, a run extended upwards while the next row
 * has the same run, up to `maxSide` rows. (Slivers hundreds of cells long
 * leave cracks of a pixel between them where Mesa's rasterizer clips them.)
 * \throws std::invalid_argument if maxSide < 1. */
std::vector<CellRectangle> rectanglesOf(
	const std::vector<std::uint8_t>& labels, int sizeX, int sizeY, std::uint8_t label,
	int maxSide);

}  // namespace mrpt_evidential::detail
