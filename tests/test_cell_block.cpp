/* The memory of a grid's cells: vacuous when made, copies cell for cell,
 * and the cells never written (a grid's room for growth) take no resident
 * memory, in the grid or in its copies. */
#include <mrpt_evidential/grid/CellBlock.h>
#include <mrpt_evidential/grid/EvidentialGridStorage.h>
#include <mrpt_evidential/support/MemoryPages.h>

#include <sys/mman.h>

#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "support/test_helpers.h"

using namespace mrpt_evidential;

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define EV_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
	__has_feature(memory_sanitizer)
#define EV_SANITIZED 1
#endif
#endif

namespace
{
/** This process's resident memory in bytes, 0 where the system does not
 * say (Linux's /proc/self/statm). */
std::size_t residentBytes()
{
	std::ifstream statm("/proc/self/statm");
	std::size_t pages = 0, resident = 0;
	if (!(statm >> pages >> resident)) return 0;
	return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

/** Whether reading memory never written leaves it untouched, as Linux does
 * by mapping one shared page of zeros. Some kernels (seen on a 6.18 VM)
 * give each page read a page of its own. */
bool readsOfUntouchedMemoryTakeNone()
{
	constexpr std::size_t kBytes = 32u << 20;
	void* p = mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	if (p == MAP_FAILED) return true;
	const std::size_t before = residentBytes();
	const auto* bytes = static_cast<const volatile char*>(p);
	long sum = 0;
	for (std::size_t at = 0; at < kBytes; at += 4096) sum += bytes[at];
	const std::size_t grew = residentBytes() - before;
	munmap(p, kBytes);
	return sum == 0 && grew < kBytes / 2;
}

QuantizedCell someCell(std::size_t i)
{
	return {0, static_cast<std::uint16_t>(i % 1000), static_cast<std::uint16_t>(i % 7),
			static_cast<std::uint16_t>(i % 3)};
}
}  // namespace

TEST(CellBlock, StartsVacuousAndCopiesCellForCell)
{
	CellBlock block(100'000);
	ASSERT_EQ(block.size(), 100'000u);
	for (std::size_t i = 0; i < block.size(); ++i) ASSERT_EQ(block[i], QuantizedCell{}) << i;
	// Written cells scattered so that some stretches of a copy hold one cell,
	// some several, some none, and one the last partial stretch.
	for (std::size_t i = 0; i < block.size(); i += 997) block[i] = someCell(i);
	block[block.size() - 1] = someCell(1);
	const CellBlock copy = block;
	EXPECT_TRUE(copy == block);
	CellBlock assigned(3);
	assigned = block;
	EXPECT_TRUE(assigned == block);
	assigned[5] = someCell(5);
	EXPECT_FALSE(assigned == block) << "a copy is its own memory";
	CellBlock written(block.size());
	written.copyWritten(block.data(), block.size(), 0);
	EXPECT_TRUE(written == block);
	// Into the middle of a larger block, as a grown grid's rows.
	CellBlock larger(block.size() + 1000);
	larger.copyWritten(block.data() + 10, 5000, 700);
	for (std::size_t i = 0; i < larger.size(); ++i)
		ASSERT_EQ(larger[i], i >= 700 && i < 5700 ? block[i - 690] : QuantizedCell{}) << i;
}

TEST(CellBlock, CopiesOnlyTheWritableRows)
{
	// Three rows of four cells, six apart, from cell 7, in a block of 24.
	CellBlock block(24);
	block.setWritableRows(7, 4, 6, 3);
	for (const std::size_t i : {7u, 10u, 13u, 19u}) block[i] = someCell(i + 1);
	const CellBlock copy(block);
	EXPECT_EQ(copy, block);
	// A cell outside the rows is the owner's broken promise: not copied.
	block[12] = someCell(5);
	EXPECT_EQ(CellBlock(block)[12], QuantizedCell{});
	EXPECT_THROW(block.setWritableRows(7, 4, 6, 4), std::out_of_range);
	EXPECT_THROW(block.setWritableRows(0, 7, 6, 2), std::out_of_range);
	EXPECT_THROW(block.setWritableRows(25, 0, 0, 1), std::out_of_range);
	EXPECT_NO_THROW(block.setWritableRows(0, 24, 24, 1));
}

TEST(CellBlock, RowsCopiedBetweenBlocksKeepEveryWrittenCell)
{
	// 8 MB, most pages never touched: 150 rows of 3000 cells, 5000 apart,
	// with cells written at the rows' ends, on both sides of page borders
	// and a few in between; copied to a larger block with rows 7000 apart.
	CellBlock block(1'000'000);
	const std::size_t first = 1234, length = 3000, stride = 5000, rows = 150;
	block.setWritableRows(first, length, stride, rows);
	const auto rowStart = [&](std::size_t r) { return first + r * stride; };
	const std::size_t page = 4096 / sizeof(QuantizedCell);
	for (std::size_t r = 0; r < rows; r += 7)
	{
		block[rowStart(r)] = someCell(r + 1);
		block[rowStart(r) + length - 1] = someCell(r + 2);
	}
	for (std::size_t border = page; border < block.size(); border += 37 * page)
		for (const std::size_t i : {border - 1, border})
			if (const std::size_t off = i - first; i >= first && off % stride < length &&
				off / stride < rows)
				block[i] = someCell(i);
	const CellBlock copy(block);
	EXPECT_TRUE(copy == block);
	CellBlock larger(1'200'000);
	larger.copyWrittenRows(block, first, stride, 999, 7000, length, rows);
	for (std::size_t r = 0; r < rows; ++r)
		for (std::size_t c = 0; c < length; ++c)
			ASSERT_EQ(larger[999 + r * 7000 + c], block[rowStart(r) + c]) << r << ", " << c;
	std::size_t written = 0;
	for (std::size_t i = 0; i < larger.size(); ++i) written += !(larger[i] == QuantizedCell{});
	std::size_t expected = 0;
	for (std::size_t i = 0; i < block.size(); ++i) expected += !(block[i] == QuantizedCell{});
	EXPECT_EQ(written, expected) << "nothing but the rows' cells written";
	EXPECT_THROW(larger.copyWrittenRows(block, first, stride, 999, 7000, length, 200),
				 std::out_of_range);
}

TEST(CellBlock, UntouchedPagesAreThoseNeverWrittenOrRead)
{
	const detail::CUntouchedPages pages;
	if (!pages.known()) GTEST_SKIP() << "this system does not say which pages were touched";
	const std::size_t page = detail::CUntouchedPages::pageSize();
	void* p = mmap(nullptr, 64 * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	ASSERT_NE(p, MAP_FAILED);
	auto* bytes = static_cast<volatile char*>(p);
	bytes[3 * page + 17] = 1;  // written
	const char read = bytes[20 * page];  // read: a page of zeros is mapped
	EXPECT_EQ(read, 0);
	std::vector<std::uint8_t> untouched;
	// From byte 100 of page 0 to byte 4 of page 40: 41 pages.
	ASSERT_TRUE(pages.find(static_cast<char*>(p) + 100, 40 * page - 95, untouched));
	ASSERT_EQ(untouched.size(), 41u);
	for (std::size_t i = 0; i < untouched.size(); ++i)
		EXPECT_EQ(untouched[i], i == 3 || i == 20 ? 0 : 1) << "page " << i;
	munmap(p, 64 * page);
}

TEST(CellBlock, CellsNeverWrittenTakeNoResidentMemory)
{
#ifdef EV_SANITIZED
	GTEST_SKIP() << "a sanitizer's allocator and shadow memory change what is resident";
#else
	if (residentBytes() == 0) GTEST_SKIP() << "no /proc/self/statm here";
	// Copies leave the pages never touched unread where the system says
	// which they are: then nothing is read that was not written.
	const bool untouchedStayFree =
		readsOfUntouchedMemoryTakeNone() || detail::CUntouchedPages().known();
	const std::size_t before = residentBytes();
	// A grid of 19 MB (50 x 120 m at 0.05 m) grown to 27 MB, into a block of
	// 134 MB with room beyond its east side; a few cells written. The room
	// stays untouched, in the grid (made, moved into the new block) and in
	// its copy, which reads the grid's rows only; so do the grid's cells
	// never written, where the copy knows them unread or reading them costs
	// nothing (elsewhere its reads of the grid's 27 MB make them resident).
	EvidentialGridStorage s;
	s.reset(0.0, 50.0, -60.0, 60.0, 0.05, 100'000'000);
	ASSERT_TRUE(s.growToInclude(0.0, 70.0, -60.0, 60.0, 0.0, 100'000'000));
	ASSERT_GT(s.cells().size(), 2 * s.geometry().cellCount()) << "room kept";
	s.beginInsertion(1.0);
	const GridGeometry& g = s.geometry();
	for (int cx = 0; cx < g.sizeX; cx += 50)
		s.write(g.index(cx, g.sizeY / 2), Mass::simpleOccupied(0.7));
	const EvidentialGridStorage copy = s;
	const std::size_t grew = residentBytes() - before;
	EXPECT_LT(grew, std::size_t{untouchedStayFree ? 8u : 40u} << 20)
		<< "blocks of " << 8 * s.cells().size() / (1 << 20) << " MB, "
		<< (untouchedStayFree ? "untouched memory left unread or read for free"
							  : "every page read a page");
	g.forEachIndex([&](std::size_t i) { ASSERT_EQ(copy.cells()[i], s.cells()[i]) << i; });
	// Growing again within the room moves nothing, and the copy follows.
	ASSERT_TRUE(s.growToInclude(0.0, 90.0, -60.0, 60.0, 0.0, 100'000'000));
	s.write(s.geometry().index(s.geometry().sizeX - 1, 0), Mass::simpleOccupied(0.7));
	const EvidentialGridStorage again = s;
	EXPECT_EQ(again.read(again.geometry().index(again.geometry().sizeX - 1, 0)).occupied,
			  s.read(s.geometry().index(s.geometry().sizeX - 1, 0)).occupied);
	EXPECT_GT(again.read(again.geometry().index(again.geometry().sizeX - 1, 0)).occupied, 0.5);
#endif
}

TEST(CellBlock, ACopyMapsOnlyThePagesItWrites)
{
#ifdef EV_SANITIZED
	GTEST_SKIP() << "a sanitizer's allocator and shadow memory change what is resident";
#else
	if (residentBytes() == 0) GTEST_SKIP() << "no /proc/self/statm here";
	// A 64 MB block whose writable cells are 3 MB from an unaligned cell, with
	// a written run of 1 MB in their middle: a copy asks the system for the
	// pages of that run in one call, and for no others.
	constexpr std::size_t kMB = (1 << 20) / sizeof(QuantizedCell);
	CellBlock block(64 * kMB);
	const std::size_t first = 20 * kMB + 3, run = kMB + 5;
	block.setWritableRows(first, 3 * kMB, 3 * kMB, 1);
	for (std::size_t i = 0; i < run; ++i) block[first + kMB + i] = someCell(i % 1000 + 1);
	const std::size_t before = residentBytes();
	const CellBlock copy(block);
	const std::size_t grew = residentBytes() - before;
	// The run's pages, and at most the writable cells read around it.
	EXPECT_LT(grew, std::size_t{5} << 20);
	EXPECT_EQ(copy[first + kMB - 1], QuantizedCell{});
	EXPECT_EQ(copy[first + kMB + run], QuantizedCell{});
	for (std::size_t i = 0; i < run; i += 997) ASSERT_EQ(copy[first + kMB + i], block[first + kMB + i]) << i;
	EXPECT_EQ(copy[first + kMB + run - 1], block[first + kMB + run - 1]);
#endif
}
