/* evgrid score-motion: the settings of a run, as its command line gives
 * them. */
#pragma once

#include <string>

#include "CTruthEvents.h"
#include "InputOptions.h"
#include "Report.h"

namespace evgrid
{
/** What messages and the report call the subcommand. */
constexpr const char* kScoreMotionName = "evgrid score-motion";

/** The value of --truth-times that selects `times`. */
inline const char* truthTimesName(TruthTimes times)
{
	return times == TruthTimes::Physical ? "physical" : "observed";
}

struct TScoreMotionOptions
{
	TInputOptions source;
	/** The motion truth, PREFIX.motion.gz. */
	std::string truth;
	TruthTimes truthTimes = TruthTimes::Observed;
	/** The scene's true poses (PREFIX.gt.txt, by time stamp) that the scans'
	 * cells are traced at; empty: at the map's own poses. */
	std::string truthPoses;
	/** Cells (Chebyshev) within which a prediction and a truth cell match,
	 * >= 0. */
	int tolerance = 1;
	TReportOptions report;
};

}  // namespace evgrid
