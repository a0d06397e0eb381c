/* mrpt-evidential: internal: memory pages mapped ahead of a write. */
#pragma once

#include <cstddef>

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

}  // namespace mrpt_evidential::detail
