/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "insert/ScanImpacts.h"

#include <mrpt_evidential/support/CpuClones.h>

#include <algorithm>
#include <cmath>

namespace mrpt_evidential
{
namespace
{
/** Where up to kChunk impacts of one sector lie: each one's bin, and its
 * grid column and row (floors, in doubles). */
constexpr std::size_t kChunk = 64;
struct TPlaces
{
	double bin[kChunk], column[kChunk], row[kChunk];
};

/** Place i of `out`: the impact at range r along direction (c, s) from the
 * sensor, without branches. */
inline void placeInto(
	double r, double c, double s, const PlanarSensorPose& sensor, const GridGeometry& grid,
	double binSize, std::size_t binCount, TPlaces& out, std::size_t i)
{
	// detail::binOf(), in a double.
	const double x = r / binSize + 1e-9, bins = static_cast<double>(binCount);
	out.bin[i] = x < bins ? std::trunc(x) : bins;
	out.column[i] = std::floor((sensor.x + r * c - grid.xMin) / grid.resolution);
	out.row[i] = std::floor((sensor.y + r * s - grid.yMin) / grid.resolution);
}

/** The places of n <= kChunk impacts in one loop that vectorizes: a cloud's
 * thousands of impacts, three divisions each. */
MRPT_EVIDENTIAL_CPU_CLONES void placesInto(
	const double* ranges, std::size_t n, double c, double s, const PlanarSensorPose& sensor,
	const GridGeometry& grid, double binSize, std::size_t binCount, TPlaces& out)
{
	for (std::size_t i = 0; i < n; ++i)
		placeInto(ranges[i], c, s, sensor, grid, binSize, binCount, out, i);
}

/** The places of ranges [0, n), n <= kChunk: a few impacts (a 2-D scan's
 * sector holds one) are not worth a call to the vector copy. */
void placeImpacts(
	const double* ranges, std::size_t n, double c, double s, const PlanarSensorPose& sensor,
	const GridGeometry& grid, double binSize, std::size_t binCount, TPlaces& out)
{
	if (n >= 8)
		placesInto(ranges, n, c, s, sensor, grid, binSize, binCount, out);
	else
		for (std::size_t i = 0; i < n; ++i)
			placeInto(ranges[i], c, s, sensor, grid, binSize, binCount, out, i);
}
}  // namespace

void CScanImpacts::build(
	const CPolarSourceGrid& polar, const CPolarToCartesian& transform,
	const PlanarSensorPose& sensor, const GridGeometry& grid)
{
	m_cells.clear();
	m_rowOf.clear();
	if (transform.box().empty()) return;
	const double reach = static_cast<double>(polar.binCount()) * polar.binSize();
	TPlaces places;
	for (std::size_t s = 0; s < polar.sectorCount(); ++s)
	{
		const std::vector<double>& ranges = polar.impacts(s);
		// Sorted: the impacts within reach come first.
		const auto inReach = static_cast<std::size_t>(
			std::lower_bound(ranges.begin(), ranges.end(), reach) - ranges.begin());
		const auto [c, sn] = transform.sectorDirection(s);
		for (std::size_t i = 0; i < inReach; ++i)
		{
			const std::size_t k = i % kChunk;
			if (k == 0)
				placeImpacts(
					ranges.data() + i, std::min(kChunk, inReach - i), c, sn, sensor, grid,
					polar.binSize(), polar.binCount(), places);
			const double occupied =
				polar.massAt(s, static_cast<std::size_t>(places.bin[k])).occupied;
			if (!(occupied > 0.0)) continue;
			const double fx = places.column[k], fy = places.row[k];
			if (!(fx >= 0 && fy >= 0 && fx < grid.sizeX && fy < grid.sizeY)) continue;
			const std::size_t idx = grid.index(static_cast<int>(fx), static_cast<int>(fy));
			// A sector's impacts in one cell (a cloud's layers on one wall)
			// are one entry: the sort below has that much less to do.
			if (!m_cells.empty() && m_cells.back().index == idx)
				m_cells.back().occupied = std::max(m_cells.back().occupied, occupied);
			else
			{
				// Field by field: a cell built whole on the stack is read back
				// in one 16-byte load from two 8-byte stores, a stall.
				TImpactCell& cell = m_cells.emplace_back();
				cell.index = idx, cell.occupied = occupied;
				m_rowOf.push_back(static_cast<int>(fy));
			}
		}
	}
	sortByIndex();
	// Of a cell's entries, the first holds the largest occupied mass.
	m_cells.erase(
		std::unique(
			m_cells.begin(), m_cells.end(),
			[](const auto& a, const auto& b) { return a.index == b.index; }),
		m_cells.end());
}

void CScanImpacts::sortByIndex()
{
	const auto before = [](const TImpactCell& a, const TImpactCell& b) {
		return a.index < b.index || (a.index == b.index && a.occupied > b.occupied);
	};
	if (m_cells.size() < 2) return;
	// Bucketed by row (a linear pass: a cloud lists thousands of cells over
	// a few hundred rows), then each row's few cells sorted.
	const auto [low, high] = std::minmax_element(m_rowOf.begin(), m_rowOf.end());
	const int lowRow = *low;
	m_rowStart.assign(static_cast<std::size_t>(*high - lowRow) + 2, 0);
	for (const int row : m_rowOf) ++m_rowStart[static_cast<std::size_t>(row - lowRow) + 1];
	for (std::size_t k = 1; k < m_rowStart.size(); ++k) m_rowStart[k] += m_rowStart[k - 1];
	m_sorted.resize(m_cells.size());
	for (std::size_t i = 0; i < m_cells.size(); ++i)
		m_sorted[m_rowStart[static_cast<std::size_t>(m_rowOf[i] - lowRow)]++] = m_cells[i];
	// Each row's end is now where the next row began.
	for (std::size_t from = 0, k = 0; k + 1 < m_rowStart.size(); ++k)
	{
		const std::size_t to = m_rowStart[k];
		std::sort(m_sorted.begin() + static_cast<std::ptrdiff_t>(from),
				  m_sorted.begin() + static_cast<std::ptrdiff_t>(to), before);
		from = to;
	}
	m_cells.swap(m_sorted);
}

}  // namespace mrpt_evidential
