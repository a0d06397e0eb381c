/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/grid/CellBlock.h>
#include <mrpt_evidential/support/MemoryPages.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mrpt_evidential
{
namespace
{
/** Cells per stretch a copy tests for written cells: a page of memory. */
constexpr std::size_t kStretch = 4096 / sizeof(QuantizedCell);

bool allVacuous(const QuantizedCell* first, std::size_t n)
{
	// Reading a page never written maps the system's zero page: no memory.
	return std::all_of(first, first + n, [](const QuantizedCell& c) {
		return c.aside == 0 && c.free == 0 && c.occupied == 0 && c.stamp == 0;
	});
}
}  // namespace

CellBlock::CellBlock(const CellBlock& other)
	: m_cells(other.size()),
	  m_first(other.m_first),
	  m_rowLength(other.m_rowLength),
	  m_stride(other.m_stride),
	  m_rows(other.m_rows)
{
	for (std::size_t r = 0; r < m_rows; ++r)
	{
		const std::size_t at = m_first + r * m_stride;
		copyWritten(other.data() + at, m_rowLength, at);
	}
}

void CellBlock::setWritableRows(
	std::size_t first, std::size_t rowLength, std::size_t stride, std::size_t rows)
{
	const bool fits = rows == 0 ||
		(rowLength <= stride && first <= size() &&
		 (rows - 1) * stride + rowLength <= size() - first);
	if (!fits)
		throw std::out_of_range(
			"cell block: " + std::to_string(rows) + " rows of " + std::to_string(rowLength) +
			" cells " + std::to_string(stride) + " apart from " + std::to_string(first) +
			" leave its " + std::to_string(size()) + " cells");
	// Rows side by side are one: a copy then tests whole pages.
	if (rowLength == stride) rowLength *= rows, stride = rowLength, rows = rows > 0 ? 1 : 0;
	m_first = first, m_rowLength = rowLength, m_stride = stride, m_rows = rows;
}

void CellBlock::copyWritten(const QuantizedCell* from, std::size_t count, std::size_t to)
{
	// Runs of stretches that hold a written cell, each copied in one go.
	std::size_t runStart = 0;
	const auto copyRun = [&](std::size_t runEnd) {
		if (runEnd == runStart) return;
		detail::mapPagesForWriting(
			data() + to + runStart, (runEnd - runStart) * sizeof(QuantizedCell));
		std::copy_n(from + runStart, runEnd - runStart, data() + to + runStart);
	};
	for (std::size_t at = 0; at < count; at += kStretch)
	{
		const std::size_t n = std::min(kStretch, count - at);
		if (!allVacuous(from + at, n)) continue;
		copyRun(at);
		runStart = at + n;
	}
	copyRun(count);
}

CellBlock& CellBlock::operator=(const CellBlock& other)
{
	if (this != &other) *this = CellBlock(other);
	return *this;
}

}  // namespace mrpt_evidential
