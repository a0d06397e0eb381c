/* mrpt-evidential: internal: memory pages mapped ahead of a write. */

#include <mrpt_evidential/support/MemoryPages.h>

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace mrpt_evidential::detail
{
void mapPagesForWriting(void* first, std::size_t bytes) noexcept
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
	static const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
	if (bytes < 2 * page) return;
	const auto at = reinterpret_cast<std::uintptr_t>(first);
	const std::uintptr_t begin = at & ~(page - 1), end = (at + bytes + page - 1) & ~(page - 1);
	(void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
	(void)first, (void)bytes;
#endif
}

}  // namespace mrpt_evidential::detail
