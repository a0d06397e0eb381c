/* evgrid build: what a run tells when it is done, in summary.txt and on the
 * console. */
#pragma once

#include <mrpt/math/TPoint3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "BuildOptions.h"
#include "CInputWalker.h"

namespace evgrid
{
class COutputFolder;

/** What became of the input's 2-D scans. */
struct TScanCounts
{
	/** Every 2-D scan (or 3-D cloud) of the input; the three counts below
	 * add up to it. */
	std::size_t total = 0;
	std::size_t inserted = 0, withoutPose = 0, rejected = 0;
};

/** "225 2-D scans: 225 inserted, 0 without a pose, 0 refused by the map";
 * `what` names the observations ("2-D scans", "3-D clouds"). */
std::string scanAccount(const TScanCounts& scans, const char* what = "2-D scans");

/** Wall time of a run and of its phases, in seconds. */
struct TBuildTimes
{
	double reading = 0, insertion = 0, writing = 0, total = 0;
};

/** Everything a finished run reports besides the map itself. */
struct TBuildRecord
{
	TInputCounts input;
	/** CPoseSource::description() */
	std::string poses;
	TScanCounts scans;
	/** The 3-D observations read as clouds. */
	TScanCounts clouds;
	/** Scans and clouds inserted. */
	std::size_t inserted() const { return scans.inserted + clouds.inserted; }
	std::size_t frames = 0, animationFrames = 0;
	TBuildTimes times;
	/** The robot's position at each inserted observation. */
	std::vector<mrpt::math::TPoint3D> path;
	mrpt_evidential::CEvidentialGridMap2D::TDecisionCounts decisions;
};

/** The contents of summary.txt. */
void writeSummary(
	std::ostream& os, const TBuildOptions& options, const TBuildRecord& run,
	const mrpt_evidential::CEvidentialGridMap2D& map);

/** The few lines printed at the end of a run that is not quiet. */
void printConsoleSummary(
	std::ostream& os, const TBuildRecord& run,
	const mrpt_evidential::CEvidentialGridMap2D& map, const COutputFolder& out);

}  // namespace evgrid
