/* mrpt-evidential: internal: memory pages mapped ahead of a write, and pages
 * never touched. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt_evidential::detail
{
/** Asks the system to map the pages that hold bytes [first, first + bytes)
 * for writing, in one call (Linux 5.14 on, MADV_POPULATE_WRITE): a copy into
 * fresh memory then takes no fault per page, which on some virtual machines
 * costs several times the copy of the page. Only the pages those bytes lie on
 * are mapped. Does nothing for less than two pages (one fault costs no more
 * than the call), on other systems, or when the call fails: the write then
 * faults the pages in as usual. Never throws. */
void mapPagesForWriting(void* first, std::size_t bytes) noexcept;

/** Tells which pages of this process's private memory (from malloc, calloc
 * or a private anonymous mapping; never a file's) were never touched: no
 * page of memory is mapped for them and none is in swap, so that they read
 * as zeros. Reading such a page to find its zeros costs a fault, and on
 * kernels without a shared page of zeros (seen on a 6.18 VM) a page of its
 * own, where asking costs 8 bytes of the system's page map. Linux only
 * (/proc/self/pagemap); elsewhere nothing is known. Open one for a batch of
 * questions: it keeps the page map open. */
class CUntouchedPages
{
   public:
	/** Opens this process's page map; known() is false where there is none,
	 * or where it calls the page of the caller's stack untouched (a map that
	 * does not tell). Never throws. */
	CUntouchedPages() noexcept;
	~CUntouchedPages();
	CUntouchedPages(const CUntouchedPages&) = delete;
	CUntouchedPages& operator=(const CUntouchedPages&) = delete;

	/** The size of a page of memory, in bytes. */
	static std::size_t pageSize() noexcept;

	/** True when find() can answer. */
	bool known() const { return m_fd >= 0; }

	/** untouched[i] = 1 when the i-th page from the one holding `first` on
	 * (to the one holding byte first + bytes - 1) was never touched, 0
	 * otherwise (touched, or not known); one entry a page. Returns false,
	 * with every entry 0, when the system does not say. The answer holds
	 * as long as no other thread writes those pages meanwhile.
	 * \throws std::bad_alloc */
	bool find(const void* first, std::size_t bytes, std::vector<std::uint8_t>& untouched) const;

   private:
	int m_fd = -1;
};

}  // namespace mrpt_evidential::detail
