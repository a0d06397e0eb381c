/* mrpt-evidential: internal: memory pages mapped ahead of a write, and pages
 * never touched. */

#include <mrpt_evidential/support/MemoryPages.h>

#include <algorithm>
#include <cerrno>
#include <vector>

#if defined(__linux__)
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace mrpt_evidential::detail
{
std::size_t CUntouchedPages::pageSize() noexcept
{
#if defined(__linux__)
	static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
	return page;
#else
	return 4096;
#endif
}

void mapPagesForWriting(void* first, std::size_t bytes) noexcept
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
	const auto page = static_cast<std::uintptr_t>(CUntouchedPages::pageSize());
	if (bytes < 2 * page) return;
	const auto at = reinterpret_cast<std::uintptr_t>(first);
	const std::uintptr_t begin = at & ~(page - 1), end = (at + bytes + page - 1) & ~(page - 1);
	(void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
	(void)first, (void)bytes;
#endif
}

CUntouchedPages::CUntouchedPages() noexcept
{
#if defined(__linux__)
	m_fd = ::open("/proc/self/pagemap", O_RDONLY | O_CLOEXEC);
	if (m_fd < 0) return;
	// A page map that calls a page just written untouched (a sandbox that
	// fills it with zeros) would have copies drop written cells: trust it
	// only once it has seen the stack this runs on.
	volatile char written = 1;
	std::vector<std::uint8_t> untouched;
	bool trusted = false;
	try
	{
		trusted = find(const_cast<const char*>(&written), 1, untouched) && untouched[0] == 0;
	}
	catch (...)
	{
	}
	if (!trusted) ::close(m_fd), m_fd = -1;
#endif
}

CUntouchedPages::~CUntouchedPages()
{
#if defined(__linux__)
	if (m_fd >= 0) ::close(m_fd);
#endif
}

bool CUntouchedPages::find(
	const void* first, std::size_t bytes, std::vector<std::uint8_t>& untouched) const
{
	const std::size_t page = pageSize();
	const auto at = reinterpret_cast<std::uintptr_t>(first);
	const std::size_t firstPage = at / page;
	const std::size_t pages = bytes == 0 ? 0 : (at + bytes - 1) / page - firstPage + 1;
	untouched.assign(pages, 0);
#if defined(__linux__)
	if (m_fd < 0) return false;
	// One 64-bit entry a page: bit 63 a page mapped, 62 in swap, 61 a
	// file's or shared page. None of them: the page was never touched (or
	// was given back, which for private memory also reads as zeros).
	constexpr std::uint64_t kTouched = 7ull << 61;
	constexpr std::size_t kChunk = 512;
	std::uint64_t entries[kChunk];
	for (std::size_t done = 0; done < pages;)
	{
		const std::size_t want = std::min(kChunk, pages - done);
		const auto offset = static_cast<off_t>((firstPage + done) * sizeof(std::uint64_t));
		const ssize_t got = ::pread(m_fd, entries, want * sizeof(std::uint64_t), offset);
		if (got < 0 && errno == EINTR) continue;
		if (got <= 0 || got % static_cast<ssize_t>(sizeof(std::uint64_t)) != 0)
		{
			std::fill(untouched.begin(), untouched.end(), std::uint8_t{0});
			return false;
		}
		const auto n = static_cast<std::size_t>(got) / sizeof(std::uint64_t);
		for (std::size_t i = 0; i < n; ++i)
			untouched[done + i] = (entries[i] & kTouched) == 0 ? 1 : 0;
		done += n;
	}
	return true;
#else
	return false;
#endif
}

}  // namespace mrpt_evidential::detail
