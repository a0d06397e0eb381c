/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * CPolarToCartesian::RowSpans: a polygon's cells, row by row, as spans of
 * columns. */

#include <algorithm>
#include <functional>

#include "insert/PolarToCartesian.h"

namespace mrpt_evidential
{
namespace
{
/** True, with [first, last) sorted, when it was a sorted sequence turned
 * about one point (the outline's start cut the row's crossings in two):
 * `before` orders it. */
template <typename Before>
bool sortedByTurning(double* first, double* last, Before before)
{
	double* cut = std::is_sorted_until(first, last, before);
	if (cut == last) return true;
	if (before(*first, *(last - 1)) || !std::is_sorted(cut, last, before)) return false;
	std::rotate(first, cut, last);
	return true;
}

/** Sorts a row's crossings. They arrive in the outline's order: around the
 * sensor that is the order of their angles, so each row's crossings run
 * forwards or backwards along it, cut in two where the row meets the
 * outline's start. Those are put in order in linear time; what is left
 * (a vacuous band's outline, whose inner arc runs back) is nearly sorted,
 * which insertion sorts in a few steps (std::sort moves them with a library
 * call per element). */
void sortCrossings(double* first, double* last)
{
	if (last - first < 2) return;  // an empty row may come as two null pointers
	if (last - first == 2)  // most rows
	{
		if (*first > *(first + 1)) std::swap(*first, *(first + 1));
		return;
	}
	if (sortedByTurning(first, last, std::less<double>())) return;
	if (sortedByTurning(first, last, std::greater<double>()))
	{
		std::reverse(first, last);
		return;
	}
	if (*first > *(last - 1)) std::reverse(first, last);
	if (last - first > 64)
	{
		std::sort(first, last);
		return;
	}
	for (double* i = first + 1; i < last; ++i)
	{
		const double x = *i;
		double* j = i;
		for (; j > first && *(j - 1) > x; --j) *j = *(j - 1);
		*j = x;
	}
}
}  // namespace

MRPT_EVIDENTIAL_CPU_CLONES void CPolarToCartesian::RowSpans::fill(
	const std::vector<double>& polygon, const GridGeometry& grid, int first,
	int last)
{
	const double res = grid.resolution;
	const std::size_t nRows = static_cast<std::size_t>(last - first + 1);
	// Each edge crosses the centre lines y in [lower end, upper end): a vertex
	// is counted once, so every row holds an even number of crossings. The
	// edges that cross a row are listed once, then walked once.
	const std::size_t nPoints = polygon.size() / 2;
	const double invRes = 1.0 / res;
	// The first row whose centre line lies at or above each corner.
	vertexRow.resize(nPoints);
	for (std::size_t i = 0; i < nPoints; ++i)
		vertexRow[i] = detail::clampToInt(
			std::ceil((polygon[2 * i + 1] - grid.yMin) * invRes - 0.5), first,
			last + 1);
	edges.clear();
	for (std::size_t i = 0; i < nPoints; ++i)
	{
		const std::size_t j = i + 1 == nPoints ? 0 : i + 1;
		if (vertexRow[i] == vertexRow[j]) continue;  // crosses no centre line
		const std::size_t lo = vertexRow[i] < vertexRow[j] ? i : j;
		const std::size_t hi = lo == i ? j : i;
		const double x0 = polygon[2 * lo], y0 = polygon[2 * lo + 1];
		const double slope = (polygon[2 * hi] - x0) / (polygon[2 * hi + 1] - y0);
		const int r0 = vertexRow[lo];
		// x in columns (from the first column's centre, in cells): the
		// crossings then round to their columns as they are.
		edges.push_back(
			{r0 - first, vertexRow[hi] - first,
			 (x0 + (grid.cellCenterY(r0) - y0) * slope - grid.xMin) * invRes - 0.5, slope});
	}
	// Each row's count of crossings from the edges' ends alone (+1 where an
	// edge begins, -1 past its last row: unsigned wrap-around cancels out),
	// then the rows' offsets.
	start.assign(nRows + 1, 0);
	for (const Edge& e : edges)
		++start[static_cast<std::size_t>(e.row0)], --start[static_cast<std::size_t>(e.row1)];
	for (std::size_t k = 0, covering = 0, offset = 0; k <= nRows; ++k)
	{
		covering += start[k];
		start[k] = offset;
		offset += covering;
	}
	// The work arrays only grow: zeroing their new ends every scan would
	// cost a write to each (they are read only up to start[nRows]).
	std::vector<double>& xs = crossingX;
	if (xs.size() < start[nRows]) xs.resize(start[nRows]);
	cursor.assign(start.begin(), start.end() - 1);
	for (const Edge& e : edges)
	{
		double x = e.x;
		for (int r = e.row0; r < e.row1; ++r, x += e.dxPerRow)
			xs[cursor[static_cast<std::size_t>(r)]++] = x;
	}

	// Crossings to spans of columns whose centres lie between two of them;
	// `start` is rewritten to index the spans.
	// At most a span for each two crossings, written in place.
	if (columns.size() < start[nRows]) columns.resize(start[nRows]);
	int* out = columns.data();
	const double lastColumn = grid.sizeX - 1;
	std::size_t from = 0;
	for (std::size_t k = 0; k < nRows; ++k)
	{
		const std::size_t to = start[k + 1];
		sortCrossings(xs.data() + from, xs.data() + to);
		start[k] = static_cast<std::size_t>(out - columns.data());
		for (std::size_t c = from; c + 1 < to; c += 2)
		{
			const int c0 =
				static_cast<int>(std::min(lastColumn + 1, std::max(0.0, std::ceil(xs[c]))));
			const int c1 =
				static_cast<int>(std::min(lastColumn, std::max(-1.0, std::floor(xs[c + 1]))));
			out[0] = c0;
			out[1] = c1;
			out += c0 <= c1 ? 2 : 0;
		}
		from = to;
	}
	start[nRows] = static_cast<std::size_t>(out - columns.data());
}

void CPolarToCartesian::RowSpans::assignDifference(
	const RowSpans& outer, const RowSpans& inner)
{
	const std::size_t nRows = outer.start.size() - 1;
	start.resize(nRows + 1);
	columns.clear();
	for (std::size_t k = 0; k < nRows; ++k)
	{
		start[k] = columns.size();
		std::size_t i = inner.start[k];
		for (std::size_t o = outer.start[k]; o < outer.start[k + 1]; o += 2)
			detail::forEachPieceOutside(
				inner.columns, i, inner.start[k + 1], outer.columns[o], outer.columns[o + 1],
				[this](int from, int to) {
					columns.push_back(from);
					columns.push_back(to);
				});
	}
	start[nRows] = columns.size();
}

}  // namespace mrpt_evidential
