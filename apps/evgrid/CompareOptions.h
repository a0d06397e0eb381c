/* evgrid compare: the settings of a run, as its command line gives them. */
#pragma once

#include <string>

#include "InputOptions.h"
#include "Report.h"

namespace evgrid
{
/** What messages and the report call the subcommand. */
constexpr const char* kCompareName = "evgrid compare";

struct TCompareOptions
{
	TInputOptions source;
	/** Every N-th scan with a pose is held out of both maps, N >= 2. */
	int holdout = 10;
	TReportOptions report;
};

}  // namespace evgrid
