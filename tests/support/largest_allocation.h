/* The largest single allocation of a test program, to prove that a size
 * read from a file or derived from options is not allocated.
 *
 * Only a suite that links largest_allocation.cpp has it: that file replaces
 * the global operator new of the whole program, and also makes every request
 * above a gigabyte fail at once with std::bad_alloc, so that a regression
 * fails fast instead of filling gigabytes with zeros. tests/CMakeLists.txt
 * lists the suites that link it. */
#pragma once

#include <cstddef>

namespace mrpt_evidential::test
{
/** The largest single request to operator new since the last reset, bytes. */
std::size_t largestAllocation();
/** Starts a new measurement. */
void resetLargestAllocation();
}  // namespace mrpt_evidential::test
