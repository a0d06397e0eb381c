/* mrpt-evidential: the legend strip of saved pictures. */

#include "render/PictureLegend.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>

#include <mrpt_evidential/support/NumberText.h>

namespace mrpt_evidential::detail
{
namespace
{
/** One of MRPT's bitmap fonts and the strip's measures that go with it. */
struct Style
{
	const char* font;
	int charWidth, rowHeight, swatch, gap;
};
// Pictures of large maps are shown scaled down: their legend uses the
// larger font.
constexpr Style kSmall{"6x13", 6, 18, 12, 14}, kLarge{"9x15", 9, 22, 15, 20};
constexpr int kLargeFrom = 900;
constexpr int kPadding = 6;
const mrpt::img::TColor kInk{0x20, 0x20, 0x20};
const mrpt::img::TColor kPaper{0xFF, 0xFF, 0xFF};
const mrpt::img::TColor kBackdrop{0x40, 0x40, 0x40};


/** One item of the strip, placed in rows by layout(). */
struct Item
{
	int width = 0;
	int x = 0, row = 0;
};

/** Places items left to right, a new row when one would pass `width`;
 * returns the number of rows. */
int layout(std::vector<Item>& items, int width, int gap)
{
	int x = kPadding, row = 0;
	for (Item& it : items)
	{
		if (x > kPadding && x + it.width > width - kPadding) x = kPadding, ++row;
		it.x = x, it.row = row;
		x += it.width + gap;
	}
	return row + 1;
}
}  // namespace

double scaleBarLength(double resolution, int maxPixels)
{
	const double maxMetres = resolution * std::max(maxPixels, 1);
	double best = resolution;
	const double decade = std::pow(10.0, std::floor(std::log10(maxMetres)));
	for (const double f : {5.0, 2.0, 1.0})
		if (f * decade <= maxMetres * (1 + 1e-9))
		{
			best = std::max(best, f * decade);
			break;
		}
	return best;
}

mrpt::img::CImage withLegend(
	const mrpt::img::CImage& picture, double resolution,
	const std::vector<LegendEntry>& entries, int width, int height)
{
	const bool fixedSize = width > 0 && height > 0;
	const mrpt::img::CImage colour = picture.isColor() ? picture : picture.colorImage();
	if (!fixedSize) width = std::max(static_cast<int>(colour.getWidth()), kMinLegendWidth);

	// The strip's layout depends only on the width and the bar, whose length
	// in pixels depends on the picture's scale: in a fixed frame, on the
	// height left above the strip, known once the strip's rows are.
	const Style& st = width >= kLargeFrom ? kLarge : kSmall;
	const auto textWidth = [&st](const std::string& t) {
		return st.charWidth * static_cast<int>(t.size());
	};
	const auto stripHeight = [&st](int rows) { return rows * st.rowHeight + 2 * kPadding; };
	std::vector<Item> items(entries.size() + 1);
	for (std::size_t i = 0; i < entries.size(); ++i)
		items[i].width = st.swatch + 4 + textWidth(entries[i].label);
	const int maxBar = std::min(width / 4, 10 * st.rowHeight);
	// Room for the longest label a bar gets ("0.0005 m").
	items.back().width = maxBar + 4 + 8 * st.charWidth;
	const int rows = layout(items, width, st.gap);

	mrpt::img::CImage map = colour;
	double metresPerPixel = resolution;
	int mapTop = 0, mapLeft = 0, mapAreaHeight = static_cast<int>(colour.getHeight());
	if (fixedSize)
	{
		mapAreaHeight = height - stripHeight(rows);
		// No room for a legend: it would take more than half the frame, or
		// its widest entry would be cut at the frame's edge.
		const int widest =
			std::max_element(items.begin(), items.end(), [](const Item& a, const Item& b) {
				return a.width < b.width;
			})->width;
		if (mapAreaHeight < height / 2 || widest > width - 2 * kPadding) mapAreaHeight = height;
		const double scale = std::min(
			static_cast<double>(width) / colour.getWidth(),
			static_cast<double>(mapAreaHeight) / colour.getHeight());
		const unsigned w = static_cast<unsigned>(std::clamp(
			static_cast<int>(colour.getWidth() * scale), 1, width));
		const unsigned h = static_cast<unsigned>(std::clamp(
			static_cast<int>(colour.getHeight() * scale), 1, mapAreaHeight));
		// Averaging when shrinking keeps thin walls visible; blocks when
		// enlarging keep cells sharp.
		colour.scaleImage(
			map, w, h, scale < 1.0 ? mrpt::img::IMG_INTERP_AREA : mrpt::img::IMG_INTERP_NN);
		metresPerPixel = resolution * colour.getWidth() / w;
		mapLeft = (width - static_cast<int>(w)) / 2;
		mapTop = (mapAreaHeight - static_cast<int>(h)) / 2;
	}
	const int totalHeight = fixedSize ? height : mapAreaHeight + stripHeight(rows);

	mrpt::img::CImage out(
		static_cast<unsigned>(width), static_cast<unsigned>(totalHeight), mrpt::img::CH_RGB);
	out.filledRectangle(0, 0, width - 1, totalHeight - 1, kPaper);
	if (fixedSize) out.filledRectangle(0, 0, width - 1, mapAreaHeight - 1, kBackdrop);
	out.drawImage(mapLeft, mapTop, map);
	if (mapAreaHeight >= totalHeight) return out;
	// MRPT loads its bitmap fonts into a global table on first use, without
	// a lock: pictures drawn in several threads at once take turns.
	static std::mutex fontMutex;
	const std::lock_guard<std::mutex> lock(fontMutex);
	out.selectTextFont(st.font);

	const auto rowTop = [&](int row) { return mapAreaHeight + kPadding + row * st.rowHeight; };
	const int textDown = (st.rowHeight - st.swatch) / 2 + 1;
	for (std::size_t i = 0; i < entries.size(); ++i)
	{
		const Item& it = items[i];
		const int y = rowTop(it.row) + (st.rowHeight - st.swatch) / 2;
		out.filledRectangle(it.x, y, it.x + st.swatch - 1, y + st.swatch - 1, entries[i].color);
		out.rectangle(it.x, y, it.x + st.swatch - 1, y + st.swatch - 1, kInk);
		out.textOut(it.x + st.swatch + 4, rowTop(it.row) + textDown, entries[i].label, kInk);
	}
	// The bar: a line with end ticks, its length in metres beside it.
	const double barMetres = scaleBarLength(metresPerPixel, maxBar);
	const int barPixels = std::max(1, static_cast<int>(std::lround(barMetres / metresPerPixel)));
	const Item& bar = items.back();
	const int mid = rowTop(bar.row) + st.rowHeight / 2;
	out.filledRectangle(bar.x, mid - 1, bar.x + barPixels - 1, mid, kInk);
	out.filledRectangle(bar.x, mid - 4, bar.x, mid + 3, kInk);
	out.filledRectangle(bar.x + barPixels - 1, mid - 4, bar.x + barPixels - 1, mid + 3, kInk);
	out.textOut(bar.x + barPixels + 4, rowTop(bar.row) + textDown, shortestText(barMetres) + " m", kInk);
	return out;
}

}  // namespace mrpt_evidential::detail
