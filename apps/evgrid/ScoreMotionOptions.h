/* evgrid score-motion: the settings of a run, as its command line gives
 * them. */
#pragma once

#include <optional>
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

/** Where the map's motion is read for a cell of the truth: World, at the
 * cell itself; Scan, where the scored scan's pose estimate puts it (the
 * cell moved by that estimate's error against the true pose). */
enum class MotionFrame
{
	World,
	Scan
};

/** The value of --motion-frame that selects `frame`. */
inline const char* motionFrameName(MotionFrame frame)
{
	return frame == MotionFrame::Scan ? "scan" : "world";
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
	/** Scan needs truthPoses. */
	MotionFrame motionFrame = MotionFrame::World;
	/** Cells of the truth's grid (Chebyshev) within which a prediction and
	 * a truth cell match, >= 0; unset: one cell of the map (the map places
	 * nothing more finely). */
	std::optional<int> tolerance;
	TReportOptions report;
};

}  // namespace evgrid
