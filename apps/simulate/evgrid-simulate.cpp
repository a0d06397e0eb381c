/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * evgrid-simulate: writes a small synthetic rawlog of a changing room, scanned
 * by MRPT's laser simulator along a known path, with its ground truth. */
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "CMotionTruthWriter.h"
#include "CRoomScene.h"
#include "CSlamError.h"
#include "SceneCatalog.h"

namespace sim = mrpt_evidential::simulate;

namespace
{
// The scanner: a 180-degree planar lidar, 1 degree between rays, at 10 Hz,
// mounted 0.2 m ahead of the robot's centre.
constexpr double kRate = 10.0;
constexpr std::size_t kRays = 181;
constexpr float kMaxRange = 20.0f;
constexpr float kRangeNoise = 0.01f;
// First timestamp, Unix seconds. Its fractional part keeps every time in the
// ground truth off whole seconds, which is how MRPT's pf-localization tells
// a column of times from a column of rawlog indices.
constexpr double kStartTime = 1700000000.05;
// Odometry errors: a random error per increment, and a 2 % over-estimate of
// rotations (a wheel base slightly off) that makes the path drift.
constexpr double kOdoScaleStd = 0.02, kOdoLateralStd = 0.002;
constexpr double kOdoRotationBias = 1.02, kOdoRotationStd = 0.2 * M_PI / 180;

struct TOptions
{
	std::string prefix;
	std::string scene = "room_door_box";
	unsigned int seed = 1;
	unsigned int laps = 2;
};

void printHelp(const char* program)
{
	std::printf(
		"Usage: %s [--scene NAME] [--seed N] [--laps N] OUTPUT_PREFIX\n"
		"\n"
		"Simulates a robot driving loops in a room that changes, scanned by\n"
		"MRPT's laser simulator, and writes:\n"
		"  OUTPUT_PREFIX.rawlog     actions and sensory frames (gzip): one\n"
		"                           odometry increment and one scan a step\n"
		"  OUTPUT_PREFIX.gt.txt     the robot's true pose at each scan, as\n"
		"                           time x y phi (Unix s, metres, radians)\n"
		"  OUTPUT_PREFIX.slam.txt   the same with a SLAM-like error, slowly\n"
		"                           varying within %g cm and %g degree (for\n"
		"                           evgrid build -p)\n"
		"  OUTPUT_PREFIX.motion.gz  what moves, cell by cell at each scan\n"
		"\n"
		"The room (x in [-5, 5], y in [-4, 4] m) has a door in its east wall\n"
		"to a corridor. The robot drives counter-clockwise around an\n"
		"ellipse, one loop every %g s. The scanner: %zu rays over 180\n"
		"degrees at %g Hz, range noise %g m, range %g m. Odometry has random\n"
		"errors and over-estimates rotations by 2 %%. Scenes (times from the\n"
		"first scan):\n",
		program, 100 * sim::CSlamError::kMaxShift,
		sim::CSlamError::kMaxTurn * 180 / M_PI, sim::CRoomScene::kLapPeriod,
		kRays, kRate, static_cast<double>(kRangeNoise),
		static_cast<double>(kMaxRange));
	for (const sim::TSceneEntry& scene : sim::sceneCatalog())
	{
		std::string summary = scene.summary;
		// Indent the summary's lines under the name.
		for (std::size_t i = 0;
			 (i = summary.find('\n', i)) != std::string::npos; i += 5)
			summary.replace(i, 1, "\n    ");
		std::printf("  %s\n    %s\n", scene.name, summary.c_str());
	}
	std::printf(
		"\n"
		"OUTPUT_PREFIX.motion.gz is gzip-compressed text: a header\n"
		"  evgrid-simulate motion 1\n"
		"  scene NAME\n"
		"  start T0         Unix time of scan 0; times below are s from it\n"
		"  grid X0 Y0 RES NX NY\n"
		"                   cell (cx, cy) spans x in [X0 + cx RES,\n"
		"                   X0 + (cx + 1) RES), y likewise; index cx + NX cy\n"
		"  scans N\n"
		"  sample DT        moving things are sampled every DT s\n"
		"  static C ITEMS   cells of walls and furniture\n"
		"then for each scan k = 0 .. N - 1\n"
		"  scan k T         the scan's time\n"
		"  occupied C ITEMS cells a moving thing covers at T\n"
		"  left C ITEMS:TL  cells moving things stopped covering after scan\n"
		"                   k - 1, each at time TL (<= T)\n"
		"C counts the cells; an ITEM is a cell index I or a run I-J of them.\n"
		"A cell counts when a thing covers part of it; static cells are never\n"
		"listed as moving; all cells are listed, seen by the scanner or not.\n"
		"A cell stays left (at its latest TL) until listed occupied again.\n"
		"\n"
		"Options:\n"
		"  --scene NAME  the scene (default room_door_box)\n"
		"  --seed N      seed of the noise (default 1): equal seeds, equal\n"
		"                files\n"
		"  --laps N      number of loops, >= 1 (default 2)\n"
		"  --help        this text\n");
}

/** A whole decimal number in [min, 2^32), or false. */
bool parseUnsigned(
	const std::string& text, unsigned long min, unsigned int& out)
{
	if (text.empty() ||
		text.find_first_not_of("0123456789") != std::string::npos ||
		text.size() > 10)
		return false;
	const unsigned long long value = std::stoull(text);
	if (value < min || value > 0xFFFFFFFFull) return false;
	out = static_cast<unsigned int>(value);
	return true;
}

/** Parses the command line; returns the exit code to stop with, or -1. */
int parseCommandLine(int argc, char** argv, TOptions& opts)
{
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		if (arg == "--help" || arg == "-h")
		{
			printHelp(argv[0]);
			return 0;
		}
		if (arg == "--scene")
		{
			if (i + 1 >= argc || !sim::findScene(argv[i + 1]))
			{
				std::string names;
				for (const sim::TSceneEntry& scene : sim::sceneCatalog())
					names += std::string(" ") + scene.name;
				std::fprintf(
					stderr, "%s: --scene needs one of:%s\n", argv[0],
					names.c_str());
				return 2;
			}
			opts.scene = argv[++i];
		}
		else if (arg == "--seed" || arg == "--laps")
		{
			const bool seed = arg == "--seed";
			if (i + 1 >= argc ||
				!parseUnsigned(
					argv[i + 1], seed ? 0 : 1, seed ? opts.seed : opts.laps))
			{
				std::fprintf(
					stderr, "%s: %s needs a whole number%s\n", argv[0],
					arg.c_str(), seed ? "" : " >= 1");
				return 2;
			}
			++i;
		}
		else if (!arg.empty() && arg[0] == '-')
		{
			std::fprintf(
				stderr, "%s: unknown option %s (see --help)\n", argv[0],
				arg.c_str());
			return 2;
		}
		else if (opts.prefix.empty())
			opts.prefix = arg;
		else
		{
			std::fprintf(
				stderr, "%s: one OUTPUT_PREFIX only (see --help)\n", argv[0]);
			return 2;
		}
	}
	if (opts.prefix.empty())
	{
		std::fprintf(
			stderr, "%s: OUTPUT_PREFIX missing (see --help)\n", argv[0]);
		return 2;
	}
	return -1;
}

/** What the robot's odometry reports for a true increment. */
mrpt::poses::CPose2D noisyOdometry(
	const mrpt::poses::CPose2D& truth, mrpt::random::CRandomGenerator& rng)
{
	return {
		truth.x() * (1.0 + kOdoScaleStd * rng.drawGaussian1D_normalized()),
		truth.y() + kOdoLateralStd * rng.drawGaussian1D_normalized(),
		truth.phi() * kOdoRotationBias +
			kOdoRotationStd * rng.drawGaussian1D_normalized()};
}

/** A pose file of lines "time x y phi", as evgrid build -p reads. */
class CPoseWriter
{
   public:
	explicit CPoseWriter(std::string path)
		: m_path(std::move(path)), m_file(m_path)
	{
		if (!m_file) throw std::runtime_error("cannot write " + m_path);
		m_file << "% time x y phi\n";
	}
	void write(double time, const mrpt::poses::CPose2D& pose)
	{
		char line[128];
		std::snprintf(
			line, sizeof(line), "%.3f %.6f %.6f %.6f\n", time, pose.x(),
			pose.y(), pose.phi());
		m_file << line;
	}
	void close()
	{
		m_file.close();
		if (!m_file) throw std::runtime_error("cannot write " + m_path);
	}

   private:
	std::string m_path;
	std::ofstream m_file;
};

void simulate(const TOptions& opts)
{
	// The laser simulator draws its noise from MRPT's global generator: seed
	// it, and draw the odometry noise from it too, so one seed fixes all.
	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(opts.seed);

	const std::string rawlogFile = opts.prefix + ".rawlog";
	mrpt::io::CFileGZOutputStream rawlogStream;
	if (std::string error; !rawlogStream.open(rawlogFile, 9, error))
		throw std::runtime_error("cannot write " + rawlogFile + ": " + error);
	auto rawlog = mrpt::serialization::archiveFrom(rawlogStream);
	CPoseWriter truth(opts.prefix + ".gt.txt"), slam(opts.prefix + ".slam.txt");
	sim::CSlamError slamError(opts.seed);

	const std::unique_ptr<sim::CScene> scene =
		sim::findScene(opts.scene)->make();
	const auto steps = static_cast<std::size_t>(
		std::lround(opts.laps * scene->lapPeriod() * kRate));
	sim::CMotionTruthWriter motion(
		opts.prefix + ".motion.gz", *scene, opts.scene, kStartTime,
		1.0 / kRate, steps);
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel;
	mrpt::poses::CPose2D previousPose = scene->robotPoseAt(0.0);
	for (std::size_t k = 0; k < steps; ++k)
	{
		const double t = static_cast<double>(k) / kRate;
		const auto stamp = mrpt::Clock::fromDouble(kStartTime + t);
		const mrpt::poses::CPose2D pose = scene->robotPoseAt(t);

		// The increment since the previous scan, in the robot's frame (zero
		// before the first scan), as the odometry measured it.
		mrpt::obs::CActionRobotMovement2D odometry;
		odometry.timestamp = stamp;
		odometry.computeFromOdometry(
			noisyOdometry(pose - previousPose, rng), motionModel);
		mrpt::obs::CActionCollection actions;
		actions.insert(odometry);
		previousPose = pose;

		auto scan = mrpt::obs::CObservation2DRangeScan::Create();
		scan->sensorLabel = "LASER";
		scan->timestamp = stamp;
		scan->aperture = static_cast<float>(M_PI);
		scan->rightToLeft = true;
		scan->maxRange = kMaxRange;
		scan->stdError = kRangeNoise;
		scan->sensorPose = mrpt::poses::CPose3D(0.20, 0, 0.30, 0, 0, 0);
		scene->worldAt(t).laserScanSimulator(
			*scan, pose, 0.6f, kRays, kRangeNoise);
		mrpt::obs::CSensoryFrame frame;
		frame.insert(scan);

		rawlog << actions << frame;
		truth.write(kStartTime + t, pose);
		slam.write(kStartTime + t, slamError.estimate(pose));
		motion.writeScan(k);
	}
	rawlogStream.close();
	truth.close();
	slam.close();
	motion.close();
	std::printf(
		"evgrid-simulate: scene %s, %zu scans, %g s: %s.{rawlog,gt.txt,"
		"slam.txt,motion.gz}\n",
		opts.scene.c_str(), steps, static_cast<double>(steps) / kRate,
		opts.prefix.c_str());
}
}  // namespace

int main(int argc, char** argv)
{
	TOptions opts;
	if (const int code = parseCommandLine(argc, argv, opts); code >= 0)
		return code;
	try
	{
		simulate(opts);
		return 0;
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "evgrid-simulate: %s\n", e.what());
		return 1;
	}
}
