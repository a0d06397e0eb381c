/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */

#include <mrpt_evidential/grid/CellBlock.h>

#include <algorithm>

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

CellBlock::CellBlock(const CellBlock& other) : m_cells(other.size())
{
	copyWritten(other.data(), other.size(), 0);
}

void CellBlock::copyWritten(const QuantizedCell* from, std::size_t count, std::size_t to)
{
	for (std::size_t at = 0; at < count; at += kStretch)
	{
		const std::size_t n = std::min(kStretch, count - at);
		if (!allVacuous(from + at, n)) std::copy_n(from + at, n, data() + to + at);
	}
}

CellBlock& CellBlock::operator=(const CellBlock& other)
{
	if (this != &other) *this = CellBlock(other);
	return *this;
}

}  // namespace mrpt_evidential
