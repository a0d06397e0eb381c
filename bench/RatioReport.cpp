/* evgrid-bench: the recording reporter and the report's ratio lines. */

#include "RatioReport.h"

#include <mrpt_evidential/MrptCompat.h>

#include <cstdio>

namespace bench
{
namespace
{
/** A run's name without the suffixes Google Benchmark adds. */
std::string caseName(const std::string& runName)
{
	return runName.substr(0, runName.find("/iterations:")).substr(0, runName.find("/min_time:"));
}
}  // namespace

void RecordingReporter::ReportRuns(const std::vector<Run>& runs)
{
	for (const Run& r : runs)
		if (!mrpt_evidential::compat::benchmarkRunFailed(r) &&
			(r.aggregate_name == "median" || (r.aggregate_name.empty() && r.repetitions <= 1)))
			microseconds[caseName(r.run_name.str())] = r.GetAdjustedRealTime();
	ConsoleReporter::ReportRuns(runs);
}

void printRatio(
	const std::map<std::string, double>& microseconds, const std::string& what,
	const std::string& ours, const std::string& theirs, double target, Bound bound)
{
	const auto a = microseconds.find(ours), b = microseconds.find(theirs);
	if (a == microseconds.end() || b == microseconds.end()) return;
	const double ratio = a->second / b->second;
	const bool met = bound == Bound::AtMost ? ratio <= target : ratio < target;
	std::printf(
		"%-58s %8.1f us / %8.1f us = %5.2f  (target %s %.2f: %s)\n", what.c_str(), a->second,
		b->second, ratio, bound == Bound::AtMost ? "<=" : "<", target, met ? "met" : "NOT met");
}
}  // namespace bench
