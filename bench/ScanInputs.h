/* evgrid-bench: the 2-D cases' inputs, shared by every case: the scans of
 * each kind, the robot poses, and the two maps built with the same range and
 * size. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace bench
{
/** Insertions per case, as mrpt-performance's grid test does. */
constexpr int kInsertions = 2000;

enum class ScanKind
{
	Stock,	//!< MRPT's example scan: 361 rays over 180 degrees
	Sena,  //!< the SENA rawlog's real scans, in turn
	Wide,  //!< synthetic: 1081 rays over 270 degrees, ranges up to 30 m
	/** SENA's scans with every other beam: 181 rays at 1 degree, as the SICK
	 * scanners of many public logs are set (issue 15's held-out logs have
	 * 180 to 361 rays); the sectors are twice as wide at every range. */
	SenaOneDegree
};
const char* name(ScanKind k);

/** The scans of a kind; the insertion loop cycles through them. */
const std::vector<mrpt::obs::CObservation2DRangeScan>& scans(ScanKind kind);
/** The same maximum range for both maps. */
double maxRangeOf(ScanKind kind);
/** Half-size of the square map, metres, enough for the scans at every pose. */
double halfSizeOf(ScanKind kind);
/** Half-size of a square map that holds a scan of range `maxRange`
 * anywhere within 1 m of the origin. */
double halfSizeFor(ScanKind kind, double maxRange);
/** kInsertions robot poses within 1 m of the origin, any heading (fixed
 * seed). */
const std::vector<mrpt::poses::CPose3D>& poses();
/** The scan to insert at step i, timestamped 0.1 s after the previous. */
mrpt::obs::CObservation2DRangeScan scanAt(ScanKind kind, std::size_t i);

/** MRPT's grid for a kind; `maxRange` 0: the kind's. */
std::unique_ptr<mrpt::maps::COccupancyGridMap2D> mrptMap(
	ScanKind kind, double resolution, bool widening, double maxRange = 0);

/** What a case sets; the settings of the sweep keep the map's defaults
 * unless given (0). */
struct OurOptions
{
	mrpt_evidential::SensorModel model = mrpt_evidential::SensorModel::ReinforcedMultiEcho;
	mrpt_evidential::FusionRule rule = mrpt_evidential::FusionRule::Conjunctive;
	bool decay = true;
	/** 0: each case's own (the kind's maxRange, the map's masses, 0.01/s
	 * decay, one sector a beam). */
	double maxRange = 0, muF = 0, muO = 0, sectorWidthDegrees = 0, decayRate = 0;
	unsigned threads = 1;
	mrpt_evidential::ConflictHandling handling = mrpt_evidential::ConflictHandling::Normalize;
};
/** Our map for a kind, as the case sets it; `halfSize` 0: halfSizeFor(). */
std::unique_ptr<mrpt_evidential::CEvidentialGridMap2D> ourMap(
	ScanKind kind, double resolution, const OurOptions& o, double halfSize = 0);

/** One scan of a run and the robot's pose when it was taken. */
struct TRunStep
{
	mrpt::obs::CObservation2DRangeScan scan;
	mrpt::poses::CPose3D pose;
};
/** The logs of mrpt-common whose whole runs the bench times: SENA (225
 * scans, a building's halls), Malaga's simplemap (99 keyframes, corridors
 * and offices), the localization demo's rawlog (37 scans, small rooms: the
 * smallest scans) and graphslam-engine's simul.rawlog (1733 simulated scans
 * of a large building). */
enum class RunLog
{
	Sena,
	Malaga,
	Localization,
	Simul
};
const char* name(RunLog log);
/** Every RunLog. */
const std::vector<RunLog>& runLogs();
/** A log's scans along the robot's path, as a user builds a map of it: a
 * rawlog's odometry, a simplemap's keyframe poses. */
const std::vector<TRunStep>& runOf(RunLog log);

/** "stock/0.05m": a case's kind and resolution in its name. */
std::string label(ScanKind kind, double resolution);
}  // namespace bench
