/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * evgrid-simulate: writes a small synthetic rawlog of a changing room, scanned
 * by MRPT's laser simulator along a known path, or of a street, scanned by a
 * multi-layer lidar, with its ground truth. */
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "COutputFolder.h"
#include "CRoomScene.h"
#include "CSceneFiles.h"
#include "CSlamError.h"
#include "Odometry.h"
#include "SceneCatalog.h"
#include "SimulationClock.h"
#include "StopSignal.h"
#include "StreetRun.h"

namespace sim = mrpt_evidential::simulate;

namespace
{
using sim::kRate;
using sim::kStartTime;

// The room's scanner: a 180-degree planar lidar, 1 degree between rays, at
// kRate, mounted 0.2 m ahead of the robot's centre.
constexpr std::size_t kRays = 181;
constexpr float kMaxRange = 20.0f;
constexpr float kRangeNoise = 0.01f;
// The scene that is no room, and the bounds of its options.
constexpr const char* kStreet = "street";
constexpr unsigned int kMaxLayers = 128;
constexpr double kMinAzimuthStep = 0.01, kMaxAzimuthStep = 90;
constexpr double kMinDuration = 0.1;

struct TOptions
{
	std::string prefix;
	std::string scene = "room_door_box";
	unsigned int seed = 1;
	unsigned int laps = 2;
	/** The street's own options (its prefix and seed are the above). */
	sim::TStreetRunOptions street;
	/** Which options were given, to refuse those of another scene. */
	bool lapsGiven = false, streetOptionGiven = false;
};

void printHelp(const char* program)
{
	std::printf(
		"Usage: %s [--scene NAME] [--seed N] [--laps N] OUTPUT_PREFIX\n"
		"       %s --scene street [--seed N] [--duration S] [--layers N]\n"
		"           [--azimuth-step DEG] OUTPUT_PREFIX\n"
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
		program, program, 100 * sim::CSlamError::kMaxShift,
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
		"  street (another world, sensor and files)\n"
		"    a vehicle drives east down a 90 m street at %g m/s for\n"
		"    --duration (at most %g s): flat, then a %g-degree hill from\n"
		"    x = %g to %g m; houses, parked cars, lamp posts, %g m kerbs, a\n"
		"    gantry %g m over the road, a tree; a person crosses, another\n"
		"    walks, a car comes the other way. The lidar: --layers over -15\n"
		"    to +15 degrees, a firing every --azimuth-step degrees, 0.5 to\n"
		"    100 m, range noise 0.02 m, %g m above the vehicle, at %g Hz;\n"
		"    the vehicle pitches and rolls with the ground. Besides .gt.txt,\n"
		"    .slam.txt and .motion.gz, it writes:\n"
		"      OUTPUT_PREFIX.rawlog        one odometry increment and one\n"
		"                                  CObservationPointCloud VELODYNE\n"
		"                                  (points in the sensor's frame) a\n"
		"                                  step\n"
		"      OUTPUT_PREFIX.gt3d.txt      the vehicle's true 3-D pose, as\n"
		"                                  time x y z yaw pitch roll\n"
		"      OUTPUT_PREFIX.footprint.gz  the static footprint truth\n",
		sim::CStreetScene::kSpeed, sim::CStreetScene::kMaxDuration,
		sim::CStreetScene::kRampDegrees, sim::CStreetScene::kRampStartX,
		sim::CStreetScene::kRampEndX, sim::CStreetScene::kKerbHeight,
		sim::CStreetScene::kGantryBottom, sim::CStreetScene::kSensorHeight,
		kRate);
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
		"OUTPUT_PREFIX.footprint.gz (street) is gzip-compressed text:\n"
		"  evgrid-simulate footprint 1\n"
		"  scene NAME\n"
		"  grid X0 Y0 RES NX NY  the grid of motion.gz\n"
		"  heights LOW HIGH      m above the ground at the cell's centre\n"
		"  obstacle C ITEMS      cells where something stands between LOW\n"
		"                        and HIGH\n"
		"  low C ITEMS           cells with something only below LOW (kerbs)\n"
		"  overhang C ITEMS      cells with something only above HIGH\n"
		"Other cells are ground. Moving things are all obstacles: scan k's\n"
		"are its occupied line in motion.gz.\n"
		"\n"
		"Options:\n"
		"  --scene NAME  the scene (default room_door_box)\n"
		"  --seed N      seed of the noise (default 1): equal seeds, equal\n"
		"                files\n"
		"  --laps N      number of loops, >= 1 (default 2); not for street\n"
		"  --duration S  street: seconds of driving, %g to %g (default %g)\n"
		"  --layers N    street: lidar layers, 1 to %u (default 16)\n"
		"  --azimuth-step DEG\n"
		"                street: degrees between firings, %g to %g (default\n"
		"                0.2), rounded to a whole number a turn\n"
		"  --help        this text\n",
		kMinDuration, sim::CStreetScene::kMaxDuration,
		sim::CStreetScene::kDefaultDuration, kMaxLayers, kMinAzimuthStep,
		kMaxAzimuthStep);
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

/** A decimal number in [min, max], or false. */
bool parseNumber(const std::string& text, double min, double max, double& out)
{
	char* end = nullptr;
	const double value = std::strtod(text.c_str(), &end);
	if (text.empty() || *end != '\0' || !(value >= min && value <= max))
		return false;
	out = value;
	return true;
}

/** Parses the command line; returns the exit code to stop with, or -1. */
int parseCommandLine(int argc, char** argv, TOptions& opts)
{
	sim::TStreetRunOptions& street = opts.street;
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		const char* value = i + 1 < argc ? argv[i + 1] : "";
		if (arg == "--help" || arg == "-h")
		{
			printHelp(argv[0]);
			return 0;
		}
		if (arg == "--scene")
		{
			if (value != std::string(kStreet) && !sim::findScene(value))
			{
				std::string names;
				for (const sim::TSceneEntry& scene : sim::sceneCatalog())
					names += std::string(" ") + scene.name;
				std::fprintf(
					stderr, "%s: --scene needs one of:%s %s\n", argv[0],
					names.c_str(), kStreet);
				return 2;
			}
			opts.scene = value;
			++i;
		}
		else if (arg == "--seed" || arg == "--laps" || arg == "--layers")
		{
			const bool seed = arg == "--seed", laps = arg == "--laps";
			unsigned int n = 0;
			if (!parseUnsigned(value, seed ? 0 : 1, n) ||
				(!seed && !laps && n > kMaxLayers))
			{
				const std::string bound = seed ? ""
					: laps ? " >= 1"
						   : " from 1 to " + std::to_string(kMaxLayers);
				std::fprintf(
					stderr, "%s: %s needs a whole number%s\n", argv[0],
					arg.c_str(), bound.c_str());
				return 2;
			}
			if (seed)
				opts.seed = n;
			else if (laps)
				opts.laps = n;
			else
				street.layers = n;
			opts.lapsGiven |= laps;
			opts.streetOptionGiven |= !seed && !laps;
			++i;
		}
		else if (arg == "--duration" || arg == "--azimuth-step")
		{
			const bool duration = arg == "--duration";
			const double min = duration ? kMinDuration : kMinAzimuthStep,
						 max = duration ? sim::CStreetScene::kMaxDuration
										: kMaxAzimuthStep;
			if (!parseNumber(
					value, min, max,
					duration ? street.duration : street.azimuthStepDegrees))
			{
				std::fprintf(
					stderr, "%s: %s needs a number from %g to %g\n", argv[0],
					arg.c_str(), min, max);
				return 2;
			}
			opts.streetOptionGiven = true;
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
	const bool isStreet = opts.scene == kStreet;
	if (isStreet ? opts.lapsGiven : opts.streetOptionGiven)
	{
		std::fprintf(
			stderr, "%s: %s (see --help)\n", argv[0],
			isStreet ? "--laps is not for the street: give --duration"
					 : "--duration, --layers and --azimuth-step are for "
					   "--scene street only");
		return 2;
	}
	return -1;
}

/** Writes the room's files under `prefix`; returns what they hold. */
std::string simulateRoom(const TOptions& opts, const std::string& prefix)
{
	// The laser simulator draws its noise from MRPT's global generator: seed
	// it, and draw the odometry noise from it too, so one seed fixes all.
	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(opts.seed);

	const std::unique_ptr<sim::CScene> scene =
		sim::findScene(opts.scene)->make();
	const auto steps = static_cast<std::size_t>(
		std::lround(opts.laps * scene->lapPeriod() * kRate));
	sim::CSceneFiles files(prefix, opts.seed, *scene, opts.scene, steps);
	mrpt::poses::CPose2D previousPose = scene->robotPoseAt(0.0);
	for (std::size_t k = 0; k < steps; ++k)
	{
		const double t = static_cast<double>(k) / kRate;
		const auto stamp = mrpt::Clock::fromDouble(kStartTime + t);
		const mrpt::poses::CPose2D pose = scene->robotPoseAt(t);

		// The increment since the previous scan, in the robot's frame (zero
		// before the first scan), as the odometry measured it.
		const mrpt::obs::CActionCollection actions =
			sim::odometryAction(pose - previousPose, stamp, rng);
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

		files.writeScan(k, pose, actions, frame);
	}
	files.close();
	char what[160];
	std::snprintf(
		what, sizeof(what), "scene %s, %zu scans, %g s", opts.scene.c_str(), steps,
		static_cast<double>(steps) / kRate);
	return what;
}

/** The files of `prefix`'s run, written into a staging folder beside them
 * and moved into place once all are complete: a run that fails or is
 * stopped (Ctrl-C) leaves an earlier run's files as they were. */
void simulate(TOptions& opts)
{
	evgrid::catchStopSignals();
	const std::filesystem::path prefix(opts.prefix);
	if (const auto name = prefix.filename(); name.empty() || name == "." || name == "..")
		throw std::runtime_error(
			opts.prefix + ": OUTPUT_PREFIX needs a file name (DIR/NAME), not a folder");
	evgrid::COutputFolder folder(
		prefix.has_parent_path() ? prefix.parent_path().string() : std::string("."));
	const std::string staged = folder.staged(prefix.filename().string());
	std::string what, files;
	if (opts.scene == kStreet)
	{
		opts.street.prefix = staged;
		opts.street.seed = opts.seed;
		what = sim::simulateStreet(opts.street);
		files = "{rawlog,gt.txt,gt3d.txt,slam.txt,motion.gz,footprint.gz}";
	}
	else
	{
		what = simulateRoom(opts, staged);
		files = "{rawlog,gt.txt,slam.txt,motion.gz}";
	}
	std::vector<std::string> names;
	for (const auto& entry : std::filesystem::directory_iterator(folder.stagingFolder()))
		names.push_back(entry.path().filename().string());
	std::sort(names.begin(), names.end());
	folder.commit(names);
	std::printf(
		"evgrid-simulate: %s: %s.%s\n", what.c_str(), opts.prefix.c_str(), files.c_str());
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
