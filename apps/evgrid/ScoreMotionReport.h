/* evgrid score-motion: the report, on the console and as a `key value`
 * file. */
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "CMotionScorer.h"
#include "CMotionTruth.h"
#include "ScoreMotionOptions.h"

namespace evgrid
{
/** What became of the input's 2-D scans: total = withoutPose + refused (by
 * the map, e.g. a tilted sensor) + scored. */
struct TReplayCounts
{
	std::size_t total = 0, withoutPose = 0, refused = 0, scored = 0;
};

/** Everything a finished run reports. */
struct TScoreMotionRecord
{
	/** CPoseSource::description() */
	std::string poses;
	/** What the scans' observed cells were traced at (true or map poses). */
	std::string tracedAt;
	/** The map's insertionOptions.motionWindow, seconds. */
	double motionWindow = 0;
	/** Cells of the truth's grid within which a prediction and a truth
	 * cell match. */
	int tolerance = 1;
	TReplayCounts scans;
	TMotionScore score;
};

/** The human-readable report. */
void printMotionReport(
	std::ostream& os, const TScoreMotionOptions& options,
	const CMotionTruth& truth, const TScoreMotionRecord& run);

/** The same numbers as `key value` lines, the same text for each number;
 * "n/a" for a ratio of nothing. */
void writeMotionKeyValues(
	std::ostream& os, const TScoreMotionOptions& options,
	const CMotionTruth& truth, const TScoreMotionRecord& run);

}  // namespace evgrid
