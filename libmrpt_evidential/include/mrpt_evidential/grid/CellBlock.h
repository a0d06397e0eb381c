/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The memory of a grid's cells, with room for growth that costs nothing
 * until it is used. */
#pragma once

#include <mrpt_evidential/grid/QuantizedMass.h>

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace mrpt_evidential
{
namespace detail
{
/** Memory from calloc, whose large blocks are fresh pages the system zeroes
 * when they are first touched; a value-initialized element is left as that
 * zeroed memory. Only for vectors made at their size and never regrown
 * within their capacity (memory a vector gets back is not zeroed again). */
template <typename T>
struct ZeroedAllocator
{
	using value_type = T;
	ZeroedAllocator() = default;
	template <typename U>
	ZeroedAllocator(const ZeroedAllocator<U>&) noexcept
	{
	}
	T* allocate(std::size_t n)
	{
		if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
		throw std::bad_alloc();
	}
	void deallocate(T* p, std::size_t) noexcept { std::free(p); }
	template <typename U>
	void construct(U*) noexcept
	{
	}
	template <typename U, typename... Args>
	void construct(U* p, Args&&... args)
	{
		::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
	}
	template <typename U>
	bool operator==(const ZeroedAllocator<U>&) const noexcept
	{
		return true;
	}
	template <typename U>
	bool operator!=(const ZeroedAllocator<U>&) const noexcept
	{
		return false;
	}
};
}  // namespace detail

/** A fixed number of cells, all vacuous (zero bits) when made. The memory of
 * cells never written stays untouched: a grid keeps room for growth around
 * its cells at no cost in time or resident memory until it grows into it,
 * and a copy writes only the stretches that hold a written cell. To find
 * them it reads the writable rows (setWritableRows()), less the pages the
 * system says were never touched (copyWrittenRows()); where it cannot say,
 * reading them is free where the kernel maps reads of untouched memory to a
 * shared page of zeros, as Linux does by default. */
class CellBlock
{
   public:
	CellBlock() = default;
	/** `count` vacuous cells. \throws std::bad_alloc */
	explicit CellBlock(std::size_t count)
		: m_cells(count), m_rowLength(count), m_stride(count), m_rows(count > 0 ? 1 : 0)
	{
	}
	/** \throws std::bad_alloc */
	CellBlock(const CellBlock& other);
	/** \throws std::bad_alloc */
	CellBlock& operator=(const CellBlock& other);
	CellBlock(CellBlock&&) noexcept = default;
	CellBlock& operator=(CellBlock&&) noexcept = default;

	std::size_t size() const { return m_cells.size(); }
	QuantizedCell& operator[](std::size_t i) { return m_cells[i]; }
	const QuantizedCell& operator[](std::size_t i) const { return m_cells[i]; }
	QuantizedCell* data() { return m_cells.data(); }
	const QuantizedCell* data() const { return m_cells.data(); }
	bool operator==(const CellBlock& other) const { return m_cells == other.m_cells; }

	/** Copies the `count` cells from `from` on to `to` on in this block,
	 * leaving out the stretches of vacuous cells: the memory of a block's
	 * cells that were never written stays untouched (the cells at `to` must
	 * be vacuous). Every stretch of `from` is read: memory that is not a
	 * block's may be a file's, whose pages never touched are no zeros. */
	void copyWritten(const QuantizedCell* from, std::size_t count, std::size_t to);

	/** copyWritten() of `rows` rows of `rowLength` cells of `source`, from
	 * cell `from` on, `fromStride` apart, to cell `to` on in this block,
	 * `toStride` apart (a grid's cells moved to a larger block). Where the
	 * system says which pages of `source` were never touched, their cells
	 * are known vacuous without reading them: on a kernel that gives each
	 * page read a page of its own, reading them was most of a growth's time.
	 * \throws std::out_of_range if the rows leave either block. */
	void copyWrittenRows(
		const CellBlock& source, std::size_t from, std::size_t fromStride, std::size_t to,
		std::size_t toStride, std::size_t rowLength, std::size_t rows);

	/** Says where cells may be written: `rows` rows of `rowLength` cells,
	 * `stride` apart, from index `first` on (a grid's cells in a block with
	 * room around them); the owner writes no other cell. A copy then reads
	 * those rows only: the room stays untouched even on a kernel that gives
	 * each page read a page of its own. A block is made with all its cells
	 * writable. \throws std::out_of_range if the rows leave the block. */
	void setWritableRows(
		std::size_t first, std::size_t rowLength, std::size_t stride, std::size_t rows);

   private:
	std::vector<QuantizedCell, detail::ZeroedAllocator<QuantizedCell>> m_cells;
	/** The writable rows (setWritableRows()). */
	std::size_t m_first = 0, m_rowLength = 0, m_stride = 0, m_rows = 0;
};

}  // namespace mrpt_evidential
