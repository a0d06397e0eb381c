/* evgrid score-motion: the settings of a run, as its command line gives
 * them. */
#pragma once

#include <string>

#include "InputOptions.h"

namespace evgrid
{
/** What messages and the report call the subcommand. */
constexpr const char* kScoreMotionName = "evgrid score-motion";

struct TScoreMotionOptions
{
	TInputOptions source;
	/** The motion truth, PREFIX.motion.gz. */
	std::string truth;
	/** Cells (Chebyshev) within which a prediction and a truth cell match,
	 * >= 0. */
	int tolerance = 1;
	/** The `key value` file; empty: none. */
	std::string output;
	bool quiet = false;
};

}  // namespace evgrid
