/* evgrid build: an evidential grid from a rawlog or a simplemap. */

#include <mrpt/core/Clock.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_streams.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "CGrowthAnimation.h"
#include "CObjectFileReader.h"
#include "COutputFolder.h"
#include "CPoseFile.h"
#include "CProgress.h"
#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"

using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;
using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
namespace
{
const std::string kName = "evgrid build";

/** Set by SIGINT / SIGTERM: the run stops at the next entry and cleans up
 * its temporary files instead of dying with them in place. */
volatile std::sig_atomic_t g_stopSignal = 0;
void onStopSignal(int signal) { g_stopSignal = signal; }

using SteadyClock = std::chrono::steady_clock;

double secondsSince(SteadyClock::time_point start)
{
	return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

/** Adds the duration of its scope to a counter. */
class CScopedTimer
{
   public:
	explicit CScopedTimer(double& total) : m_total(total) {}
	~CScopedTimer() { m_total += secondsSince(m_start); }
	CScopedTimer(const CScopedTimer&) = delete;
	CScopedTimer& operator=(const CScopedTimer&) = delete;

   private:
	double& m_total;
	SteadyClock::time_point m_start = SteadyClock::now();
};

struct TBuildOptions
{
	std::string input, outputDir, config, section, poses;
	CPoseFile::Kind posesKind = CPoseFile::Kind::Auto;
	double poseTolerance = 0.1;
	int every = 0;
	bool animation = false;
	int animationEvery = 1, animationWidth = 720, animationHeight = 720;
	double animationFps = 25.0;
	bool quiet = false;
	std::string commandLine;
};

/** What a run did, for the summary. */
struct TBuildStats
{
	std::size_t entries = 0, actions = 0, sensoryFrames = 0, observations = 0;
	std::size_t scans = 0, inserted = 0, withoutPose = 0, rejected = 0;
	std::size_t frames = 0, animationFrames = 0;
	std::map<std::string, std::size_t> otherObservations;
	bool simplemap = false;
	/** The rawlog ends with an action that has no sensory frame after it. */
	bool trailingAction = false;
	// Seconds of wall time.
	double reading = 0, insertion = 0, writing = 0, total = 0;
};

/** "1.2 s (34%)" */
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

/** Reads the input, places each scan and inserts it; writes the frames and
 * the animation into the staging folder as it goes. */
class CMapBuilder
{
   public:
	CMapBuilder(
		const TBuildOptions& options, COutputFolder& out,
		CEvidentialGridMap2D& map, const std::optional<CPoseFile>& poseFile)
		: m_options(options),
		  m_out(out),
		  m_map(map),
		  m_poseFile(poseFile),
		  m_progress(CProgress::modeFor(options.quiet), kName)
	{
	}

	void run()
	{
		CObjectFileReader reader(m_options.input);
		mrpt::serialization::CSerializable::Ptr object;
		{
			CScopedTimer t(m_stats.reading);
			object = reader.next();
		}
		if (!object)
			throw std::runtime_error(m_options.input + ": the file is empty");
		m_compressed = reader.isCompressed();
		if (m_options.animation) openAnimation();

		if (auto simplemap =
				std::dynamic_pointer_cast<mrpt::maps::CSimpleMap>(object))
			insertSimplemap(*simplemap);
		else
			insertRawlog(reader, object);
		m_progress.finish();

		if (m_stats.inserted == 0)
			throw std::runtime_error(
				m_options.input + ": no scan was inserted (" +
				scanAccount() + ")");
		if (m_animation)
		{
			CScopedTimer t(m_stats.writing);
			m_animation->close();
		}
	}

	TBuildStats& stats() { return m_stats; }
	bool compressed() const { return m_compressed; }

	/** "224 2-D scans: 224 inserted, 0 without a pose, 0 refused" */
	std::string scanAccount() const
	{
		return std::to_string(m_stats.scans) + " 2-D scans: " +
			std::to_string(m_stats.inserted) + " inserted, " +
			std::to_string(m_stats.withoutPose) + " without a pose, " +
			std::to_string(m_stats.rejected) + " refused by the map";
	}

	std::string inputKind() const
	{
		if (m_stats.simplemap) return "simplemap";
		const bool pairs = m_stats.actions + m_stats.sensoryFrames > 0;
		const bool single = m_stats.observations > 0;
		if (pairs && single)
			return "rawlog (actions/sensory frames and observations)";
		return single ? "rawlog (observations)"
					  : "rawlog (actions/sensory frames)";
	}

	std::string posesDescription() const
	{
		if (m_poseFile)
		{
			std::ostringstream s;
			s << m_poseFile->path() << ", " << m_poseFile->size() << " poses, ";
			if (m_poseFile->kind() == CPoseFile::Kind::Step)
				s << "by step number (icp-slam path)";
			else
				s << "by time stamp (interpolated, tolerance "
				  << m_options.poseTolerance << " s)";
			return s.str();
		}
		if (m_stats.simplemap) return "the simplemap's (mean of each keyframe)";
		if (m_stats.actions > 0)
			return "odometry (sum of the actions' movement increments)";
		return "odometry (latest CObservationOdometry reading)";
	}

   private:
	void openAnimation()
	{
		m_animation.emplace(
			m_out.staged("growth.avi"), m_options.animationWidth,
			m_options.animationHeight, m_options.animationFps);
	}

	void insertSimplemap(const mrpt::maps::CSimpleMap& simplemap)
	{
		m_stats.simplemap = true;
		m_stats.entries = simplemap.size();
		if (m_poseFile && m_poseFile->kind() == CPoseFile::Kind::Step)
			throw std::runtime_error(
				m_poseFile->path() +
				": holds poses by step number (as icp-slam writes them), "
				"which count rawlog entries; a simplemap needs time stamps");
		std::size_t done = 0;
		for (const auto& keyframe : simplemap)
		{
			checkStopSignal();
			m_where = "keyframe " + std::to_string(done);
			++done;
			if (!keyframe.sf) continue;
			std::optional<CPose3D> pose;
			if (keyframe.pose) pose = keyframe.pose->getMeanVal();
			for (const auto& obs : *keyframe.sf)
				insertObservation(obs, std::nullopt, pose);
			m_progress.update(
				static_cast<double>(done) / static_cast<double>(simplemap.size()),
				m_stats.inserted);
		}
	}

	void insertRawlog(
		CObjectFileReader& reader, mrpt::serialization::CSerializable::Ptr object)
	{
		using namespace mrpt::obs;
		// icp-slam numbers the (action, sensory frame) pairs and the single
		// observations it reads; a sensory frame not preceded by an action
		// is skipped by MRPT's reader and gets no step number.
		std::size_t nextStep = 0;
		bool actionPending = false;
		CPose2D odometry;  // sum of the actions' increments
		std::optional<CPose2D> odometryReading;  // observation-only rawlogs

		while (object)
		{
			checkStopSignal();
			m_where = "entry " + std::to_string(reader.entryIndex());
			++m_stats.entries;
			if (const auto actions =
					std::dynamic_pointer_cast<CActionCollection>(object))
			{
				++m_stats.actions;
				if (const auto move = actions->getBestMovementEstimation();
					move && move->poseChange)
					odometry = odometry + move->poseChange->getMeanVal();
				actionPending = true;
			}
			else if (const auto frame =
						 std::dynamic_pointer_cast<CSensoryFrame>(object))
			{
				++m_stats.sensoryFrames;
				std::optional<std::size_t> step;
				if (actionPending) step = nextStep++;
				actionPending = false;
				for (const auto& obs : *frame)
					insertObservation(obs, step, CPose3D(odometry));
			}
			else if (const auto obs =
						 std::dynamic_pointer_cast<CObservation>(object))
			{
				++m_stats.observations;
				if (const auto reading =
						std::dynamic_pointer_cast<CObservationOdometry>(obs))
					odometryReading = reading->odometry;
				std::optional<CPose3D> pose;
				if (odometryReading) pose = CPose3D(*odometryReading);
				insertObservation(obs, nextStep++, pose);
			}
			else
				throw std::runtime_error(
					m_options.input + ": " + m_where + " is a " +
					object->GetRuntimeClass()->className +
					", which has no place in a rawlog");

			m_progress.update(reader.fractionRead(), m_stats.inserted);
			CScopedTimer t(m_stats.reading);
			object = reader.next();
		}
		// Some of MRPT's own datasets end so (simul.rawlog): not an error.
		m_stats.trailingAction = actionPending;
	}

	void insertObservation(
		const mrpt::obs::CObservation::Ptr& obs,
		std::optional<std::size_t> step,
		const std::optional<CPose3D>& framePose)
	{
		if (!obs) return;
		const auto* scan =
			dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(obs.get());
		if (!scan)
		{
			++m_stats.otherObservations[obs->GetRuntimeClass()->className];
			return;
		}
		++m_stats.scans;
		const auto pose = poseFor(*scan, step, framePose);
		if (!pose)
		{
			++m_stats.withoutPose;
			return;
		}
		bool inserted = false;
		try
		{
			CScopedTimer t(m_stats.insertion);
			inserted = m_map.insertObservation(*scan, *pose);
		}
		catch (const std::exception& e)
		{
			// Damaged data can parse into a scan the map refuses (a sensor
			// pose that is not a number): say which one.
			throw std::runtime_error(
				m_options.input + ": " + m_where +
				": cannot insert the scan: " + describe(e));
		}
		if (!inserted)
		{
			++m_stats.rejected;
			return;
		}
		++m_stats.inserted;
		writeGrowth();
	}

	std::optional<CPose3D> poseFor(
		const mrpt::obs::CObservation& scan, std::optional<std::size_t> step,
		const std::optional<CPose3D>& framePose) const
	{
		if (!m_poseFile) return framePose;
		std::optional<mrpt::math::TPose2D> pose;
		if (m_poseFile->kind() == CPoseFile::Kind::Step)
		{
			if (step) pose = m_poseFile->atStep(*step);
		}
		else if (scan.timestamp != INVALID_TIMESTAMP)
			pose = m_poseFile->atTime(
				mrpt::Clock::toDouble(scan.timestamp), m_options.poseTolerance);
		if (!pose) return std::nullopt;
		return CPose3D(CPose2D(*pose));
	}

	/** The frame pictures and the animation, after an insertion. */
	void writeGrowth()
	{
		const std::size_t n = m_stats.inserted;
		const bool frame = m_options.every > 0 &&
			n % static_cast<std::size_t>(m_options.every) == 0;
		const bool video = m_animation &&
			n % static_cast<std::size_t>(m_options.animationEvery) == 0;
		if (!frame && !video) return;

		CScopedTimer t(m_stats.writing);
		mrpt::img::CImage picture;
		m_map.getAsEvidentialImage(picture);
		if (frame)
		{
			char name[64];
			std::snprintf(name, sizeof(name), "frame_%06zu_evidential.png", n);
			const std::string folder = m_out.staged("frames");
			std::filesystem::create_directories(folder);
			const std::string path = folder + "/" + name;
			if (!picture.saveToFile(path))
				throw std::runtime_error(path + ": cannot write the picture");
			++m_stats.frames;
		}
		if (video)
		{
			m_animation->add(picture);
			++m_stats.animationFrames;
		}
	}

	void checkStopSignal() const
	{
		if (g_stopSignal != 0)
			throw std::runtime_error(
				"interrupted by signal " + std::to_string(g_stopSignal) +
				"; the output folder is unchanged");
	}

	const TBuildOptions& m_options;
	COutputFolder& m_out;
	CEvidentialGridMap2D& m_map;
	const std::optional<CPoseFile>& m_poseFile;
	CProgress m_progress;
	std::optional<CGrowthAnimation> m_animation;
	TBuildStats m_stats;
	bool m_compressed = false;
	/** The entry or keyframe being inserted, for error messages. */
	std::string m_where;
};

void writeSummary(
	std::ostream& os, const TBuildOptions& options, const CMapBuilder& builder,
	const TBuildStats& stats, const CEvidentialGridMap2D& map,
	const CEvidentialGridMap2D::TDecisionCounts& counts)
{
	const auto& g = map.geometry();
	os << "evgrid build summary\n\n"
	   << "command: " << options.commandLine << "\n"
	   << "input: " << options.input << "\n"
	   << "  " << builder.inputKind()
	   << (builder.compressed() ? ", gzip-compressed" : "") << ", "
	   << stats.entries << (stats.simplemap ? " keyframes" : " entries")
	   << (stats.trailingAction
			   ? " (the last, an action, has no sensory frame after it)"
			   : "")
	   << "\n"
	   << "poses: " << builder.posesDescription() << "\n"
	   << "config: "
	   << (options.config.empty() ? "none (the map's defaults)"
								  : options.config + ", section [" +
				   options.section + "]")
	   << "\n\n";

	os << "scans: " << builder.scanAccount() << "\n";
	if (stats.otherObservations.empty())
		os << "other observations: none\n";
	for (const auto& [cls, n] : stats.otherObservations)
		os << "other observations: " << n << " " << cls << " (not inserted)\n";
	if (stats.frames > 0)
		os << "frames: " << stats.frames << " pictures in frames/, one every "
		   << options.every << " scans\n";
	if (stats.animationFrames > 0)
		os << "animation: growth.avi, " << stats.animationFrames
		   << " frames of " << options.animationWidth << " x "
		   << options.animationHeight << " at " << options.animationFps
		   << " frames/s\n";

	os << std::defaultfloat << std::setprecision(10) << "\nmap:\n"
	   << "  x: [" << g.xMin << ", " << g.xMax() << "] m\n"
	   << "  y: [" << g.yMin << ", " << g.yMax() << "] m\n"
	   << "  resolution: " << g.resolution << " m\n"
	   << "  cells: " << g.sizeX << " x " << g.sizeY << "\n"
	   << "  insertions: " << map.insertionCount() << "\n"
	   << "  latest time: " << std::fixed << std::setprecision(6)
	   << map.latestTime() << " s\n"
	   << "cells by decision:\n";
	printDecisionCounts(os, counts, g.cellCount());

	os << std::fixed << std::setprecision(1) << "\ntiming:\n"
	   << "  total: " << std::setprecision(3) << stats.total << " s, "
	   << std::setprecision(1) << perSecond(stats.inserted, stats.total)
	   << " scans/s (insertion alone: "
	   << perSecond(stats.inserted, stats.insertion) << " scans/s)\n"
	   << "  reading: " << share(stats.reading, stats.total) << "\n"
	   << "  insertion: " << share(stats.insertion, stats.total) << "\n"
	   << "  writing: " << share(stats.writing, stats.total) << "\n"
	   << "  other: "
	   << share(
			  std::max(
				  0.0, stats.total - stats.reading - stats.insertion -
					  stats.writing),
			  stats.total)
	   << "\n\noptions:\n";
	os << std::defaultfloat;
	map.insertionOptions.dumpToTextStream(os);
	map.likelihoodOptions.dumpToTextStream(os);
}

std::string joinCommandLine(int argc, char** argv, int first)
{
	std::string s = kName;
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
}  // namespace

int runBuild(int argc, char** argv, int first)
{
	const auto start = SteadyClock::now();
	TCLAP::CmdLine cmd(
		"Builds an evidential grid map from a rawlog (action/sensory-frame or "
		"observation-only format, plain or .gz) or a simplemap, and writes "
		"into the output folder: map.evgrid (the serialized map), "
		"evidential.png, betp.png, conflict.png and summary.txt; with --every, "
		"frames/; with --animation, growth.avi. A failed run leaves the folder "
		"as it was. See doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::SwitchArg argQuiet(
		"q", "quiet", "Print nothing but errors.", cmd, false);
	TCLAP::ValueArg<double> argFps(
		"", "animation-fps", "Frame rate of growth.avi. Default: 25.", false,
		25.0, "FPS", cmd);
	TCLAP::ValueArg<std::string> argAnimationSize(
		"", "animation-size",
		"Frame size of growth.avi in pixels; each picture is scaled to fit. "
		"Default: 720x720.",
		false, "720x720", "WxH", cmd);
	TCLAP::ValueArg<int> argAnimationEvery(
		"", "animation-every",
		"One animation frame every N inserted scans. Default: 1.", false, 1,
		"N", cmd);
	TCLAP::SwitchArg argAnimation(
		"", "animation",
		"Also write growth.avi (MJPG): the evidential picture as the map grows.",
		cmd, false);
	TCLAP::ValueArg<int> argEvery(
		"", "every",
		"Also write frames/frame_NNNNNN_evidential.png every N inserted scans "
		"(NNNNNN = scans inserted so far). The frames/ folder of an earlier "
		"run is replaced as a whole.",
		false, 0, "N", cmd);
	TCLAP::ValueArg<double> argTolerance(
		"", "pose-tolerance",
		"For pose files by time stamp: a scan farther than this from the "
		"nearest pose of the file gets no pose and is skipped (counted in the "
		"summary). Seconds, default 0.1.",
		false, 0.1, "SECONDS", cmd);
	TCLAP::ValueArg<std::string> argPosesFormat(
		"", "poses-format",
		"How --poses is keyed: 'time' (lines 'time x y phi', e.g. MRPT ground "
		"truth), 'step' (lines 'step x y phi', icp-slam's "
		"log_estimated_path.txt) or 'auto' (step when the first column counts "
		"up from 0 by one). Default: auto.",
		false, "auto", "auto|time|step", cmd);
	TCLAP::ValueArg<std::string> argPoses(
		"p", "poses",
		"Robot poses from this text file instead of the odometry (rawlog) or "
		"the keyframe poses (simplemap). Lines 'key x y phi' in metres and "
		"radians; see --poses-format.",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argSection(
		"s", "section",
		std::string("Section of the .ini that lists the maps (as "
					"CMultiMetricMap reads it: evidentialGrid_count=1 and "
					"[SECTION_evidentialGrid_00_creationOpts] etc.). "
					"Default: ") +
			kDefaultSection + ".",
		false, kDefaultSection, "SECTION", cmd);
	TCLAP::ValueArg<std::string> argConfig(
		"c", "config",
		"The map's .ini file (e.g. rawlogs/evgrid.ini); without it the map "
		"takes its built-in defaults (0.10 m cells).",
		false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argOutput(
		"o", "output-dir",
		"Required. Output folder, created if missing; checked for writing "
		"before any work.",
		false, "", "DIR", cmd);
	TCLAP::ValueArg<std::string> argInput(
		"i", "input",
		"Required. Rawlog (.rawlog, .rawlog.gz) or simplemap (.simplemap, "
		".simplemap.gz); the kind is read from the file's content.",
		false, "", "FILE", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first))
		return *exitCode;

	if (argInput.getValue().empty())
		throw UsageError("missing the input: -i FILE (a rawlog or simplemap)");
	if (argOutput.getValue().empty())
		throw UsageError("missing the output folder: -o DIR");

	TBuildOptions options;
	options.input = argInput.getValue();
	options.outputDir = argOutput.getValue();
	options.config = argConfig.getValue();
	options.section = argSection.getValue();
	options.poses = argPoses.getValue();
	options.poseTolerance = argTolerance.getValue();
	options.every = argEvery.getValue();
	options.animation = argAnimation.getValue();
	options.animationEvery = argAnimationEvery.getValue();
	options.animationFps = argFps.getValue();
	options.quiet = argQuiet.getValue();
	options.commandLine = joinCommandLine(argc, argv, first);

	const std::string& format = argPosesFormat.getValue();
	if (format == "auto") options.posesKind = CPoseFile::Kind::Auto;
	else if (format == "time") options.posesKind = CPoseFile::Kind::Time;
	else if (format == "step") options.posesKind = CPoseFile::Kind::Step;
	else
		throw UsageError(
			"--poses-format must be auto, time or step, got '" + format + "'");
	if (argPosesFormat.isSet() && options.poses.empty())
		throw UsageError("--poses-format needs --poses");
	if (!(options.poseTolerance >= 0.0))
		throw UsageError("--pose-tolerance must be >= 0 seconds");
	if (argEvery.isSet()) requireAtLeast("--every", options.every, 1);
	requireAtLeast("--animation-every", options.animationEvery, 1);
	if (!parseSize(
			argAnimationSize.getValue(), options.animationWidth,
			options.animationHeight) ||
		options.animationWidth < 16 || options.animationHeight < 16 ||
		options.animationWidth > 8192 || options.animationHeight > 8192)
		throw UsageError(
			"--animation-size must be WIDTHxHEIGHT, each 16 to 8192 pixels, "
			"got '" + argAnimationSize.getValue() + "'");
	if (!(options.animationFps > 0.0 && options.animationFps <= 1000.0))
		throw UsageError("--animation-fps must be in (0, 1000]");
	if (!options.animation &&
		(argAnimationEvery.isSet() || argAnimationSize.isSet() || argFps.isSet()))
		throw UsageError(
			"--animation-every, --animation-size and --animation-fps need "
			"--animation");

	// From here on temporary files exist: a stop request must let the run
	// remove them.
	std::signal(SIGINT, onStopSignal);
	std::signal(SIGTERM, onStopSignal);

	// Everything that can be checked without reading the input, first: the
	// output folder, then the small files.
	COutputFolder out(options.outputDir);
	std::unique_ptr<CEvidentialGridMap2D> map =
		options.config.empty()
		? std::make_unique<CEvidentialGridMap2D>()
		: createMapFromConfig(options.config, options.section);
	std::optional<CPoseFile> poseFile;
	if (!options.poses.empty())
		poseFile = CPoseFile::load(options.poses, options.posesKind);

	CMapBuilder builder(options, out, *map, poseFile);
	builder.run();
	TBuildStats& stats = builder.stats();

	{
		CScopedTimer t(stats.writing);
		{
			const std::string path = out.staged("map.evgrid");
			std::ofstream f(path, std::ios::binary);
			auto archive = mrpt::serialization::archiveFrom<std::ostream>(f);
			archive << *map;
			f.close();
			if (!f) throw std::runtime_error(path + ": cannot write the map");
		}
		mrpt::img::CImage picture;
		const auto save = [&](const std::string& name) {
			if (!picture.saveToFile(out.staged(name)))
				throw std::runtime_error(
					out.final(name) + ": cannot write the picture");
		};
		map->getAsEvidentialImage(picture);
		save("evidential.png");
		map->getAsBetPImage(picture);
		save("betp.png");
		map->getAsConflictImage(picture);
		save("conflict.png");
	}
	stats.total = secondsSince(start);
	const auto counts = map->countDecisions();
	{
		const std::string path = out.staged("summary.txt");
		std::ofstream f(path);
		writeSummary(f, options, builder, stats, *map, counts);
		f.close();
		if (!f) throw std::runtime_error(path + ": cannot write the summary");
	}
	out.commit(
		{"map.evgrid", "evidential.png", "betp.png", "conflict.png", "frames",
		 "growth.avi", "summary.txt"});

	if (!options.quiet)
	{
		const auto percent = [&stats](double part) {
			return std::to_string(static_cast<int>(
					   std::lround(100.0 * part / stats.total))) +
				"%";
		};
		std::cout << kName << ": " << builder.scanAccount() << "; "
				  << std::fixed << std::setprecision(2) << stats.total
				  << " s, " << std::setprecision(1)
				  << perSecond(stats.inserted, stats.total) << " scans/s\n"
				  << "time: reading " << percent(stats.reading)
				  << ", insertion " << percent(stats.insertion)
				  << ", writing " << percent(stats.writing) << "\n"
				  << "map: " << map->getSizeX() << " x " << map->getSizeY()
				  << " cells of " << std::defaultfloat
				  << map->getResolution() << " m; free " << counts.free
				  << ", occupied " << counts.occupied << ", unknown "
				  << counts.unknown << ", conflict " << counts.conflict << "\n"
				  << "pictures: " << out.final("evidential.png") << ", "
				  << out.final("betp.png") << ", " << out.final("conflict.png")
				  << "\nsummary: " << out.final("summary.txt") << "\n";
	}
	return 0;
}

}  // namespace evgrid
