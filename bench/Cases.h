/* evgrid-bench: how a case is timed, and its registration, for every file
 * of cases. */
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string>

namespace bench
{
/** How a case is timed. Each case runs several times, and the ratios take
 * the median of the runs: a run that the machine slowed (the first cases of
 * a process often are, and a path's first writes to new memory vary on a
 * virtual machine) then moves no ratio. */
enum class Timing
{
	/** A fixed number of insertions in each run (into a fresh map). */
	Insertions,
	/** The insertions of a whole path in each run, from a fresh map: the
	 * grid's growth along the path is what it measures. */
	WholePath,
	/** As many calls as fit in a fixed time, in each run. */
	Calls
};
/** Registers a case. */
void addCase(const std::string& name, std::function<void(benchmark::State&)> fn, Timing timing);
}  // namespace bench
