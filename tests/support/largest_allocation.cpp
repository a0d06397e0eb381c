/* The replacement of the global operator new behind largest_allocation.h. */
#include "largest_allocation.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
std::atomic<std::size_t> g_largestAllocation{0};
constexpr std::size_t kAllocationCeiling = std::size_t(1) << 30;
}  // namespace

std::size_t mrpt_evidential::test::largestAllocation()
{
	return g_largestAllocation.load();
}

void mrpt_evidential::test::resetLargestAllocation() { g_largestAllocation = 0; }

void* operator new(std::size_t size)
{
	std::size_t seen = g_largestAllocation.load(std::memory_order_relaxed);
	while (size > seen && !g_largestAllocation.compare_exchange_weak(seen, size))
	{
	}
	if (size > kAllocationCeiling) throw std::bad_alloc();
	if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
	throw std::bad_alloc();
}
// Not inlined: g++ would then see new's pointer reach free() and warn.
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept
{
	std::free(p);
}
// The nothrow forms too: a program that mixes them with the replaced delete
// (GoogleTest 1.15 does) must get its memory from the same malloc, or
// AddressSanitizer reports the mismatch.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
	try
	{
		return ::operator new(size);
	}
	catch (const std::bad_alloc&)
	{
		return nullptr;
	}
}
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
