/* mrpt-evidential: internal: the strip under each saved picture, with what
 * its colours mean and a scale bar. */
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/img/TColor.h>

#include <string>
#include <vector>

namespace mrpt_evidential::detail
{
/** A colour of a picture and what it means. */
struct LegendEntry
{
	mrpt::img::TColor color;
	std::string label;
};

/** `picture` (one pixel per cell of `resolution` metres, grey or RGB) at the
 * top left of an RGB picture at least kMinLegendWidth wide, above a white
 * strip holding the entries (a swatch and its label each, wrapped into rows)
 * and a scale bar of a round length.
 * With `width` and `height` > 0 (a video's frames), the result has that size
 * instead: the strip at the bottom, the picture scaled to fit above it,
 * centred on dark grey; when the strip would leave less than half the
 * height, or the frame is narrower than its widest entry, the picture alone
 * fills the frame. */
mrpt::img::CImage withLegend(
	const mrpt::img::CImage& picture, double resolution,
	const std::vector<LegendEntry>& entries, int width = 0, int height = 0);

/** The narrowest picture withLegend() makes, pixels: room for a few
 * entries per row. */
constexpr int kMinLegendWidth = 320;

/** The scale bar's length for cells of `resolution` metres, when it may be
 * at most `maxPixels` long: the largest 1, 2 or 5 times a power of ten
 * metres that fits (at least one cell). */
double scaleBarLength(double resolution, int maxPixels);

}  // namespace mrpt_evidential::detail
