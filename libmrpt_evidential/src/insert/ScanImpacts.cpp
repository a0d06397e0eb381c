/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include "insert/ScanImpacts.h"

#include <mrpt_evidential/scan/SensorModel.h>
#include <mrpt_evidential/support/CpuClones.h>

#include <algorithm>
#include <cmath>

namespace mrpt_evidential
{
namespace
{
/** Where an impact lies: its bin, and its grid column and row (floors, in
 * doubles, so that loops over many vectorize). */
struct TPlace
{
	double bin, column, row;
};

/** The place of the impact at range r along direction (c, s) from the
 * sensor, without branches. */
inline TPlace placeOf(
	double r, double c, double s, const PlanarSensorPose& sensor, const GridGeometry& grid,
	double binSize, double bins)
{
	return {rangeBin(r, binSize, bins),
			std::floor((sensor.x + r * c - grid.xMin) / grid.resolution),
			std::floor((sensor.y + r * s - grid.yMin) / grid.resolution)};
}

/** The places of up to kChunk impacts of one sector, for sectors of
 * kChunkFrom impacts or more (fewer are not worth a call to the vector
 * copy). */
constexpr std::size_t kChunk = 64, kChunkFrom = 8;
struct TPlaces
{
	double bin[kChunk], column[kChunk], row[kChunk];
};

/** The places of n <= kChunk impacts in one loop that vectorizes: a cloud's
 * thousands of impacts, three divisions each. */
MRPT_EVIDENTIAL_CPU_CLONES void placesInto(
	const double* ranges, std::size_t n, double c, double s, const PlanarSensorPose& sensor,
	const GridGeometry& grid, double binSize, std::size_t binCount, TPlaces& out)
{
	const auto bins = static_cast<double>(binCount);
	for (std::size_t i = 0; i < n; ++i)
	{
		const TPlace p = placeOf(ranges[i], c, s, sensor, grid, binSize, bins);
		out.bin[i] = p.bin, out.column[i] = p.column, out.row[i] = p.row;
	}
}

/** The places of the n sectors' nearest impacts (`nearest`, +inf for a
 * sector without one, whose place no one reads) in one loop that
 * vectorizes: a 2-D scan's impacts,
 * one a sector, three divisions each. `directions` holds each sector's
 * centre line as (x, y) pairs. */
MRPT_EVIDENTIAL_CPU_CLONES void nearestPlacesInto(
	const double* nearest, const double* directions, std::size_t n,
	const PlanarSensorPose& sensor, const GridGeometry& grid, double binSize,
	std::size_t binCount, double* bin, double* column, double* row)
{
	const auto bins = static_cast<double>(binCount);
	for (std::size_t s = 0; s < n; ++s)
	{
		const TPlace p = placeOf(
			nearest[s], directions[2 * s], directions[2 * s + 1], sensor, grid, binSize, bins);
		bin[s] = p.bin, column[s] = p.column, row[s] = p.row;
	}
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
	// Each sector's nearest impact placed in one vector loop beforehand (a
	// 2-D scan has no other).
	const std::size_t n = polar.sectorCount();
	m_nearestPlaces.resize(3 * n);
	double *const nearestBin = m_nearestPlaces.data(), *const nearestColumn = nearestBin + n,
				  *const nearestRow = nearestColumn + n;
	nearestPlacesInto(
		transform.nearestImpacts(), transform.sectorDirections(), n, sensor, grid,
		polar.binSize(), polar.binCount(), nearestBin, nearestColumn, nearestRow);
	TPlaces places;
	for (std::size_t s = 0; s < n; ++s)
	{
		const TImpactRanges ranges = polar.impacts(s);
		if (ranges.empty() || !(ranges.front() < reach)) continue;
		const auto [c, sn] = transform.sectorDirection(s);
		// A sector of many impacts (a cloud's) has them placed in chunks by
		// the vector code; a few have their first placed above, the rest one
		// by one.
		const bool chunked = ranges.size() >= kChunkFrom;
		for (std::size_t i = 0; i < ranges.size(); ++i)
		{
			if (!(ranges[i] < reach)) break;  // sorted: the rest lie beyond too
			const std::size_t k = i % kChunk;
			if (chunked && k == 0)
				placesInto(
					ranges.data() + i, std::min(kChunk, ranges.size() - i), c, sn, sensor, grid,
					polar.binSize(), polar.binCount(), places);
			const TPlace place = chunked ? TPlace{places.bin[k], places.column[k], places.row[k]}
				: i == 0 ? TPlace{nearestBin[s], nearestColumn[s], nearestRow[s]}
						 : placeOf(ranges[i], c, sn, sensor, grid, polar.binSize(),
								   static_cast<double>(polar.binCount()));
			const double occupied = polar.massAt(s, static_cast<std::size_t>(place.bin)).occupied;
			if (!(occupied > 0.0)) continue;
			const double fx = place.column, fy = place.row;
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
