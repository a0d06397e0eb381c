/* evgrid build: an evidential grid from a rawlog or a simplemap. This file
 * reads the command line and runs the parts in order: input, poses,
 * insertion, outputs, report. */

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_evidential/support/NumberText.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "BuildOptions.h"
#include "BuildReport.h"
#include "CGrowthRecorder.h"
#include "CInputWalker.h"
#include "COutputFolder.h"
#include "CPoseSource.h"
#include "CProgress.h"
#include "CScopedTimer.h"
#include "CommandLine.h"
#include "Commands.h"
#include "InputOptions.h"
#include "MapFiles.h"
#include "MapOutputs.h"
#include "ScanInsertion.h"
#include "StopSignal.h"

using mrpt::poses::CPose3D;
using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
namespace
{
std::string joinCommandLine(int argc, char** argv, int first)
{
	std::string s = kBuildName;
	for (int i = first; i < argc; ++i)
	{
		const std::string arg = argv[i];
		const bool plain =
			arg.find_first_of(" \t'\"\\$") == std::string::npos && !arg.empty();
		s += " " + (plain ? arg : "'" + arg + "'");
	}
	return s;
}

/** "800x600" */
bool parseSize(const std::string& text, int& width, int& height)
{
	char x = 0;
	std::string rest;
	std::istringstream in(text);
	return (in >> width >> x >> height) && (x == 'x' || x == 'X') &&
		!(in >> rest);
}

/** Fills `options` from the command line.
 * \return as parse(): nothing when the run should go ahead, else the exit
 *  code. \throws UsageError for values that make no sense. */
std::optional<int> parseOptions(
	int argc, char** argv, int first, TBuildOptions& options)
{
	TCLAP::CmdLine cmd(
		std::string("Builds an evidential grid map from a rawlog (action/sensory-frame or "
					"observation-only format, plain or .gz) or a simplemap: its 2-D scans (") +
			kScanClassName + ") and 3-D clouds (" + kCloudClassNames +
			"; other observations "
		"are counted, not inserted). It writes "
		"into the output folder: map.evgrid (the serialized map), "
		"map.3Dscene (the map and the path, for SceneViewer3D), the pictures "
		"map.png, evidential.png, betp.png, conflict.png, motion.png and "
		"summary.txt; with --every, "
		"frames/; with --animation, growth.avi. A failed run leaves the folder "
		"as it was. See doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::SwitchArg argQuiet(
		"q", "quiet", "Print nothing but errors.", cmd, false);
	TCLAP::ValueArg<double> argFps(
		"", "animation-fps",
		"Frame rate of growth.avi, a whole number from 1 to 1000. Default: 25.", false,
		25.0, "FPS", cmd);
	TCLAP::ValueArg<std::string> argAnimationSize(
		"", "animation-size",
		"Frame size of growth.avi in pixels; the map is scaled to fit above "
		"its legend. "
		"Default: 720x720.",
		false, "720x720", "WxH", cmd);
	TCLAP::ValueArg<int> argAnimationEvery(
		"", "animation-every",
		"One animation frame every N inserted scans. Default: 1.", false, 1,
		"N", cmd);
	TCLAP::SwitchArg argAnimation(
		"", "animation",
		"Also write growth.avi (MJPG): map.png as the map grows.",
		cmd, false);
	TCLAP::ValueArg<int> argEvery(
		"", "every",
		"Also write frames/frame_NNNNNN_map.png every N inserted scans "
		"(NNNNNN = scans inserted so far). The frames/ folder of an earlier "
		"run is replaced as a whole.",
		false, 0, "N", cmd);
	TCLAP::ValueArg<std::string> argOutput(
		"o", "output-dir",
		"Required. Output folder, created if missing; checked for writing "
		"before any work.",
		false, "", "DIR", cmd);
	CInputArgs inputArgs(cmd);

	if (const auto exitCode = parse(cmd, kBuildName, argc, argv, first))
		return exitCode;

	options.source = inputArgs.values();
	if (argOutput.getValue().empty())
		throw UsageError("missing the output folder: -o DIR");

	options.outputDir = argOutput.getValue();
	options.quiet = argQuiet.getValue();
	options.commandLine = joinCommandLine(argc, argv, first);
	TGrowthOptions& growth = options.growth;
	growth.frameEvery = argEvery.getValue();
	growth.animation = argAnimation.getValue();
	growth.animationEvery = argAnimationEvery.getValue();
	growth.animationFps = argFps.getValue();

	if (argEvery.isSet()) requireAtLeast("--every", growth.frameEvery, 1);
	requireAtLeast("--animation-every", growth.animationEvery, 1);
	if (!parseSize(
			argAnimationSize.getValue(), growth.animationWidth,
			growth.animationHeight) ||
		growth.animationWidth < 16 || growth.animationHeight < 16 ||
		growth.animationWidth > 8192 || growth.animationHeight > 8192)
		throw UsageError(
			"--animation-size must be WIDTHxHEIGHT, each 16 to 8192 pixels, "
			"got '" + argAnimationSize.getValue() + "'");
	// OpenCV's AVI writer takes whole rates only (it rounds, and refuses
	// less than 1).
	if (!(growth.animationFps >= 1.0 && growth.animationFps <= 1000.0 &&
		  growth.animationFps == std::floor(growth.animationFps)))
		throw UsageError(
			"--animation-fps must be a whole number of frames per second, 1 to 1000, got " +
			mrpt_evidential::detail::shortestText(growth.animationFps));
	if (!growth.animation &&
		(argAnimationEvery.isSet() || argAnimationSize.isSet() || argFps.isSet()))
		throw UsageError(
			"--animation-every, --animation-size and --animation-fps need "
			"--animation");
	return std::nullopt;
}

/** Inserts the scans the input walker hands on, counting what becomes of
 * them, and lets the growth recorder see the map after each insertion. */
class CScanInserter
{
   public:
	CScanInserter(
		CEvidentialGridMap2D& map, const CInputWalker& input,
		CGrowthRecorder& growth)
		: m_map(map), m_input(input), m_growth(growth)
	{
	}

	/** A 2-D scan or a 3-D cloud. */
	void insert(const mrpt::obs::CObservation& obs, const std::optional<CPose3D>& pose)
	{
		TScanCounts& counts =
			dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs) ? m_scans : m_clouds;
		++counts.total;
		if (!pose)
		{
			++counts.withoutPose;
			return;
		}
		bool taken = false;
		{
			CScopedTimer t(m_seconds);
			taken = insertScan(m_map, obs, *pose, m_input.place());
		}
		if (!taken)
		{
			++counts.rejected;
			return;
		}
		++counts.inserted;
		m_path.emplace_back(pose->x(), pose->y(), pose->z());
		m_growth.afterInsertion(m_map, inserted());
	}

	const TScanCounts& scans() const { return m_scans; }
	const TScanCounts& clouds() const { return m_clouds; }
	std::size_t inserted() const { return m_scans.inserted + m_clouds.inserted; }
	/** Seconds spent in the map's insertion. */
	double seconds() const { return m_seconds; }
	/** The robot's position at each inserted observation. */
	const std::vector<mrpt::math::TPoint3D>& path() const { return m_path; }

   private:
	CEvidentialGridMap2D& m_map;
	const CInputWalker& m_input;
	CGrowthRecorder& m_growth;
	TScanCounts m_scans, m_clouds;
	double m_seconds = 0;
	std::vector<mrpt::math::TPoint3D> m_path;
};

/** Writes the map, its pictures and summary.txt into the staging folder,
 * then moves everything the run wrote into place. */
void writeResults(
	const TBuildOptions& options, TBuildRecord& run,
	const CEvidentialGridMap2D& map, COutputFolder& out,
	SteadyClock::time_point start)
{
	{
		CScopedTimer t(run.times.writing);
		saveMap(map, out.staged("map.evgrid"));
		savePicturesIn(map, out.stagingFolder());
		map.saveAsScene(out.staged(kSceneName), run.path);
	}
	run.times.total = secondsSince(start);
	run.decisions = map.countDecisions();
	{
		const std::string path = out.staged("summary.txt");
		std::ofstream f(path);
		writeSummary(f, options, run, map);
		f.close();
		if (!f) throw std::runtime_error(path + ": cannot write the summary");
	}
	// summary.txt last: it marks a complete run.
	std::vector<std::string> results{"map.evgrid", kSceneName};
	for (const char* name : CEvidentialGridMap2D::pictureNames())
		results.emplace_back(name);
	results.insert(results.end(), {"frames", "growth.avi", "summary.txt"});
	out.commit(results);
}

/** The run itself, `start` being when the program started. */
void build(const TBuildOptions& options, SteadyClock::time_point start)
{
	// Everything that can be checked without reading the input, first: the
	// output folder, then the small files.
	COutputFolder out(options.outputDir);
	const std::unique_ptr<CEvidentialGridMap2D> map = createMap(options.source);
	CPoseSource poses = createPoseSource(options.source);

	CProgress progress(CProgress::modeFor(options.quiet), kBuildName);
	CInputWalker input(options.source.input, poses);
	CGrowthRecorder growth(options.growth, out);
	CScanInserter inserter(*map, input, growth);
	input.walk(
		{[] { throwIfStopRequested(); },
		 [&inserter](const auto& scan, const auto& pose) {
			 inserter.insert(scan, pose);
		 },
		 [&](double fraction) { progress.update(fraction, inserter.inserted()); },
		 [&inserter](const auto& cloud, const auto& pose) { inserter.insert(cloud, pose); }});
	progress.finish();
	if (inserter.inserted() == 0)
	{
		// An input without any observation the map reads is told apart from
		// one whose scans all lacked a pose or were refused.
		const bool nothingToRead = inserter.scans().total == 0 && inserter.clouds().total == 0;
		throw std::runtime_error(
			options.source.input + ": no scan was inserted (" +
			(nothingToRead ? std::string("the input holds no 2-D scan and no 3-D cloud the map "
										 "reads: ") +
					 kScanClassName + ", " + kCloudClassNames
						   : scanAccount(inserter.scans())) +
			(inserter.clouds().total > 0
				 ? "; " + scanAccount(inserter.clouds(), "3-D clouds")
				 : std::string()) +
			notInsertedAccount(input.counts()) +
			// Which poses were asked for: a step-keyed file with a gap reads as
			// time stamps under --poses-format auto, and no scan finds its time.
			(inserter.scans().withoutPose + inserter.clouds().withoutPose > 0
				 ? "; poses: " + poses.description()
				 : std::string()) +
			")");
	}
	// No map of nothing but unknown cells in place of a good one.
	requireACellSeen(*map, inserter.inserted(), options.source.input);
	growth.finish(*map, inserter.inserted());

	TBuildRecord run;
	run.input = input.counts();
	run.poses = poses.description();
	run.scans = inserter.scans();
	run.clouds = inserter.clouds();
	run.frames = growth.frames();
	run.animationFrames = growth.animationFrames();
	run.times.reading = input.readingSeconds();
	run.times.insertion = inserter.seconds();
	run.times.writing = growth.writingSeconds();
	run.path = inserter.path();
	writeResults(options, run, *map, out, start);

	if (!options.quiet) printConsoleSummary(std::cout, run, *map, out);
}
}  // namespace

int runBuild(int argc, char** argv, int first)
{
	const auto start = SteadyClock::now();
	TBuildOptions options;
	if (const auto exitCode = parseOptions(argc, argv, first, options))
		return *exitCode;

	// From here on temporary files exist: a stop request must let the run
	// remove them.
	catchStopSignals();
	build(options, start);
	return 0;
}

}  // namespace evgrid
