/* evgrid-bench: each case's time kept as the runs are reported, and the
 * lines of the ratio report, for the 2-D cases and the clouds alike. */
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace bench
{
/** Google Benchmark's console table, keeping each case's time per iteration
 * (the median of its runs, or its one run) in microseconds, by the case's
 * name without the suffixes Google Benchmark adds. */
class RecordingReporter : public benchmark::ConsoleReporter
{
   public:
	std::map<std::string, double> microseconds;
	void ReportRuns(const std::vector<Run>& runs) override;
};

/** How a ratio meets its target. */
enum class Bound
{
	AtMost,  //!< ratio <= target
	Below  //!< ratio < target
};

/** Prints "what  a us / b us = ratio  (target <= t: met)" for cases `ours`
 * (a) and `theirs` (b); nothing when either did not run (a filter left it
 * out). */
void printRatio(
	const std::map<std::string, double>& microseconds, const std::string& what,
	const std::string& ours, const std::string& theirs, double target,
	Bound bound = Bound::AtMost);
}  // namespace bench
