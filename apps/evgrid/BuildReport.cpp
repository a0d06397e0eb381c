/* evgrid build: what a run tells when it is done, in summary.txt and on the
 * console. */

#include "BuildReport.h"

#include <mrpt_evidential/support/NumberText.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "COutputFolder.h"
#include "MapOutputs.h"

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
namespace
{
/** "1.234 s (34%)" */
std::string share(double part, double total)
{
	std::ostringstream s;
	s << std::fixed << std::setprecision(3) << part << " s ("
	  << std::setprecision(0) << (total > 0 ? 100.0 * part / total : 0.0)
	  << "%)";
	return s.str();
}

double perSecond(std::size_t count, double seconds)
{
	return seconds > 0 ? static_cast<double>(count) / seconds : 0.0;
}

std::string inputKind(const TInputCounts& input)
{
	if (input.simplemap) return "simplemap";
	const bool pairs = input.actions + input.sensoryFrames > 0;
	const bool single = input.observations > 0;
	if (pairs && single)
		return "rawlog (actions/sensory frames and observations)";
	return single ? "rawlog (observations)" : "rawlog (actions/sensory frames)";
}

void writeSources(
	std::ostream& os, const TBuildOptions& options, const TBuildRecord& run)
{
	const TInputCounts& input = run.input;
	os << "command: " << options.commandLine << "\n"
	   << "input: " << options.source.input << "\n"
	   << "  " << inputKind(input)
	   << (input.compressed ? ", gzip-compressed" : "") << ", "
	   << input.entries << (input.simplemap ? " keyframes" : " entries")
	   << (input.trailingAction
			   ? " (the last, an action, has no sensory frame after it)"
			   : "")
	   << "\n"
	   << "poses: " << run.poses << "\n"
	   << "config: " << configDescription(options.source) << "\n";
}

void writeProducts(
	std::ostream& os, const TGrowthOptions& growth, const TBuildRecord& run)
{
	os << "scans: " << scanAccount(run.scans) << "\n";
	if (run.clouds.total > 0)
	{
		os << "clouds: " << scanAccount(run.clouds, "3-D clouds") << " (";
		const char* separator = "";
		for (const auto& [cls, n] : run.input.cloudObservations)
			os << separator << n << " " << cls, separator = ", ";
		os << ")\n";
	}
	if (run.input.otherObservations.empty()) os << "other observations: none\n";
	for (const auto& [cls, n] : run.input.otherObservations)
		os << "other observations: " << n << " " << cls << " (not inserted)\n";
	if (growth.frameEvery > 0)
		os << "frames: " << run.frames << " pictures in frames/, one every "
		   << growth.frameEvery << " scans"
		   << (run.frames == 0 ? " (fewer scans were inserted: frames/ is empty)" : "") << "\n";
	if (run.animationFrames > 0)
		os << "animation: growth.avi, " << run.animationFrames
		   << " frames of " << growth.animationWidth << " x "
		   << growth.animationHeight << " at " << growth.animationFps
		   << " frames/s\n";
}

void writeTiming(std::ostream& os, const TBuildRecord& run)
{
	const TBuildTimes& t = run.times;
	const double other =
		std::max(0.0, t.total - t.reading - t.insertion - t.writing);
	os << std::fixed << "timing:\n"
	   << "  total: " << std::setprecision(3) << t.total << " s, "
	   << std::setprecision(1) << perSecond(run.inserted(), t.total)
	   << " scans/s (insertion alone: "
	   << perSecond(run.inserted(), t.insertion) << " scans/s)\n"
	   << "  reading: " << share(t.reading, t.total) << "\n"
	   << "  insertion: " << share(t.insertion, t.total) << "\n"
	   << "  writing: " << share(t.writing, t.total) << "\n"
	   << "  other: " << share(other, t.total) << "\n";
}
}  // namespace

std::string scanAccount(const TScanCounts& scans, const char* what)
{
	return std::to_string(scans.total) + " " + what + ": " +
		std::to_string(scans.inserted) + " inserted, " +
		std::to_string(scans.withoutPose) + " without a pose, " +
		std::to_string(scans.rejected) + " refused by the map";
}

void writeSummary(
	std::ostream& os, const TBuildOptions& options, const TBuildRecord& run,
	const CEvidentialGridMap2D& map)
{
	os << kBuildName << " summary\n\n";
	writeSources(os, options, run);
	os << "\n";
	writeProducts(os, options.growth, run);
	os << "\nmap:\n"
	   << map.geometryText("  ") << "  insertions: " << map.insertionCount()
	   << "\n";
	if (map.partlyInsertedCount() > 0)
		os << "  partly inserted: " << map.partlyInsertedCount()
		   << " (beyond what maxCells lets the grid grow to: used where they overlap it)\n";
	os << "  latest time: " << std::fixed << std::setprecision(6)
	   << map.latestTime() << " s\n";
	printDecisionCounts(os, run.decisions, map.geometry().cellCount());
	printMotionCounts(os, map);
	os << "\n";
	writeTiming(os, run);
	os << "\n";
	printMapOptions(os, map);
}

void printConsoleSummary(
	std::ostream& os, const TBuildRecord& run, const CEvidentialGridMap2D& map,
	const COutputFolder& out)
{
	const TBuildTimes& t = run.times;
	const auto percent = [&t](double part) {
		return std::to_string(
				   static_cast<int>(std::lround(100.0 * part / t.total))) +
			"%";
	};
	const auto& d = run.decisions;
	os << kBuildName << ": " << scanAccount(run.scans) << "; ";
	if (run.clouds.total > 0) os << scanAccount(run.clouds, "3-D clouds") << "; ";
	os << std::fixed << std::setprecision(2) << t.total << " s, " << std::setprecision(1)
	   << perSecond(run.inserted(), t.total) << " scans/s\n"
	   << "time: reading " << percent(t.reading) << ", insertion "
	   << percent(t.insertion) << ", writing " << percent(t.writing) << "\n"
	   << "map: " << map.getSizeX() << " x " << map.getSizeY() << " cells of "
	   << mrpt_evidential::detail::shortestText(map.getResolution()) << " m; free " << d.free
	   << ", occupied " << d.occupied << ", unknown " << d.unknown
	   << ", conflict " << d.conflict << "\n";
	if (map.partlyInsertedCount() > 0)
		os << "warning: " << map.partlyInsertedCount()
		   << " scans reached beyond the cell budget (creationOpts maxCells) and were "
			  "used only where they overlap the grid\n";
	printMotionCounts(os, map);
	os << "pictures: ";
	const char* separator = "";
	for (const char* name : CEvidentialGridMap2D::pictureNames())
	{
		os << separator << out.final(name);
		separator = ", ";
	}
	os << "\nscene: " << out.final(kSceneName) << "\nsummary: " << out.final("summary.txt") << "\n";
}

}  // namespace evgrid
