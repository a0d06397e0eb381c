/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/grid/CellBlock.h>
#include <mrpt_evidential/support/MemoryPages.h>

#include <algorithm>
#include <cstdint>
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
	return std::all_of(first, first + n, [](const QuantizedCell& c) {
		return c.aside == 0 && c.free == 0 && c.occupied == 0 && c.stamp == 0;
	});
}

/** Copies runs of the cells from `from` on that hold a written cell into
 * fresh memory from `to` on. Stretches start where the source's address is a
 * multiple of a stretch's bytes (a page, on most systems), so that a
 * stretch lies on the pages the system can say were never touched. */
class CRowCopier
{
   public:
	/** `pages` null: every stretch is read. */
	explicit CRowCopier(const detail::CUntouchedPages* pages) : m_pages(pages) {}

	void copy(const QuantizedCell* from, std::size_t count, QuantizedCell* to)
	{
		const bool known = m_pages && m_pages->known() &&
			m_pages->find(from, count * sizeof(QuantizedCell), m_untouched);
		const std::uintptr_t page = detail::CUntouchedPages::pageSize();
		const auto firstPage = reinterpret_cast<std::uintptr_t>(from) / page;
		const auto untouched = [&](std::size_t at, std::size_t n) {
			if (!known) return false;
			const auto begin = reinterpret_cast<std::uintptr_t>(from + at);
			const std::uintptr_t last = (begin + n * sizeof(QuantizedCell) - 1) / page;
			for (std::uintptr_t p = begin / page; p <= last; ++p)
				if (!m_untouched[p - firstPage]) return false;
			return true;
		};
		std::size_t runStart = 0;
		const auto copyRun = [&](std::size_t runEnd) {
			if (runEnd == runStart) return;
			detail::mapPagesForWriting(
				to + runStart, (runEnd - runStart) * sizeof(QuantizedCell));
			std::copy_n(from + runStart, runEnd - runStart, to + runStart);
		};
		constexpr std::uintptr_t kStretchBytes = kStretch * sizeof(QuantizedCell);
		const auto misalign = reinterpret_cast<std::uintptr_t>(from) % kStretchBytes;
		std::size_t n = misalign % sizeof(QuantizedCell) == 0
			? (kStretchBytes - misalign) / sizeof(QuantizedCell)
			: kStretch;
		for (std::size_t at = 0; at < count; at += n, n = kStretch)
		{
			n = std::min(n, count - at);
			if (!untouched(at, n) && !allVacuous(from + at, n)) continue;
			copyRun(at);
			runStart = at + n;
		}
		copyRun(count);
	}

   private:
	const detail::CUntouchedPages* m_pages;
	std::vector<std::uint8_t> m_untouched;
};

/** Whether `rows` rows of `length` cells, `stride` apart from `first`, lie
 * within `size` cells. */
bool rowsFit(
	std::size_t first, std::size_t length, std::size_t stride, std::size_t rows,
	std::size_t size)
{
	return rows == 0 ||
		(length <= stride && first <= size && (rows - 1) * stride + length <= size - first);
}
}  // namespace

CellBlock::CellBlock(const CellBlock& other) : m_cells(other.size())
{
	copyWrittenRows(
		other, other.m_first, other.m_stride, other.m_first, other.m_stride,
		other.m_rowLength, other.m_rows);
	m_first = other.m_first, m_rowLength = other.m_rowLength;
	m_stride = other.m_stride, m_rows = other.m_rows;
}

void CellBlock::setWritableRows(
	std::size_t first, std::size_t rowLength, std::size_t stride, std::size_t rows)
{
	if (!rowsFit(first, rowLength, stride, rows, size()))
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
	CRowCopier(nullptr).copy(from, count, data() + to);
}

void CellBlock::copyWrittenRows(
	const CellBlock& source, std::size_t from, std::size_t fromStride, std::size_t to,
	std::size_t toStride, std::size_t rowLength, std::size_t rows)
{
	if (!rowsFit(from, rowLength, fromStride, rows, source.size()) ||
		!rowsFit(to, rowLength, toStride, rows, size()))
		throw std::out_of_range("cell block: rows copied leave a block");
	// Rows side by side in both blocks are one.
	if (rowLength == fromStride && rowLength == toStride)
		rowLength *= rows, rows = rows > 0 ? 1 : 0;
	const detail::CUntouchedPages pages;
	CRowCopier copier(&pages);
	for (std::size_t r = 0; r < rows; ++r)
		copier.copy(
			source.data() + from + r * fromStride, rowLength, data() + to + r * toStride);
}

CellBlock& CellBlock::operator=(const CellBlock& other)
{
	if (this != &other) *this = CellBlock(other);
	return *this;
}

}  // namespace mrpt_evidential
