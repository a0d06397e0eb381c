/* evgrid-bench: the 2-D cases' inputs. */

#include "ScanInputs.h"

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/stock_observations.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>

#include "../tests/support/scans.h"

#ifndef MRPT_DATASETS_DIR
#define MRPT_DATASETS_DIR "/usr/share/mrpt/datasets"
#endif

using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;
using namespace mrpt_evidential;

namespace bench
{
const char* name(ScanKind k)
{
	switch (k)
	{
		case ScanKind::Stock: return "stock";
		case ScanKind::Sena: return "sena";
		case ScanKind::Wide: return "wide";
		case ScanKind::SenaOneDegree: return "sena1deg";
	}
	return "";
}

namespace
{
/** The scan's beams 0, 2, 4, ... over the same aperture. */
CObservation2DRangeScan everyOtherBeam(const CObservation2DRangeScan& scan)
{
	CObservation2DRangeScan out = scan;
	const std::size_t n = (scan.getScanSize() + 1) / 2;
	out.resizeScan(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		out.setScanRange(i, scan.getScanRange(2 * i));
		out.setScanRangeValidity(i, scan.getScanRangeValidity(2 * i));
	}
	return out;
}
}  // namespace

const std::vector<CObservation2DRangeScan>& scans(ScanKind kind)
{
	static std::map<ScanKind, std::vector<CObservation2DRangeScan>> cache;
	auto& out = cache[kind];
	if (!out.empty()) return out;
	if (kind == ScanKind::Stock)
	{
		out.emplace_back();
		mrpt::obs::stock_observations::example2DRangeScan(out.back());
	}
	else if (kind == ScanKind::Wide)
	{
		// A sensor in a 37 x 27 m hall, off its centre: ranges 7 to 30 m.
		const auto setup = test::ScanSetup().aperture(1.5 * M_PI).maxRange(30.0);
		out.push_back(test::scanByAngle(1081, setup, [](double a) {
			const double c = std::cos(a), d = std::sin(a);
			const double tx = c > 0 ? 25.0 / c : (c < 0 ? -12.0 / c : HUGE_VAL);
			const double ty = d > 0 ? 18.0 / d : (d < 0 ? -9.0 / d : HUGE_VAL);
			return std::min({tx, ty, 29.9});
		}));
	}
	else if (kind == ScanKind::SenaOneDegree)
		for (const TRunStep& step : runOf(RunLog::Sena)) out.push_back(everyOtherBeam(step.scan));
	else
		for (const TRunStep& step : runOf(RunLog::Sena)) out.push_back(step.scan);
	return out;
}

const char* name(RunLog log)
{
	switch (log)
	{
		case RunLog::Sena: return "sena";
		case RunLog::Malaga: return "malaga";
		case RunLog::Localization: return "localization";
		case RunLog::Simul: return "simul";
	}
	return "";
}

const std::vector<RunLog>& runLogs()
{
	static const std::vector<RunLog> all{
		RunLog::Sena, RunLog::Malaga, RunLog::Localization, RunLog::Simul};
	return all;
}

namespace
{
void appendScans(
	const mrpt::obs::CSensoryFrame& frame, const CPose3D& pose, std::vector<TRunStep>& out)
{
	for (const auto& o : frame)
		if (const auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(o))
			out.push_back({*scan, pose});
}

std::vector<TRunStep> rawlogRun(const std::string& path)
{
	std::vector<TRunStep> out;
	mrpt::io::CFileGZInputStream file(path);
	auto archive = mrpt::serialization::archiveFrom(file);
	mrpt::obs::CActionCollection::Ptr actions;
	mrpt::obs::CSensoryFrame::Ptr frame;
	mrpt::obs::CObservation::Ptr obs;
	std::size_t entry = 0;
	mrpt::poses::CPose2D odometry;
	while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(
		archive, actions, frame, obs, entry))
	{
		if (actions)
			if (const auto move = actions->getBestMovementEstimation(); move && move->poseChange)
				odometry = odometry + move->poseChange->getMeanVal();
		if (frame) appendScans(*frame, CPose3D(odometry), out);
		if (const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
			odometry = odo->odometry;
		else if (const auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(obs))
			out.push_back({*scan, CPose3D(odometry)});
	}
	return out;
}

std::vector<TRunStep> simplemapRun(const std::string& path)
{
	std::vector<TRunStep> out;
	mrpt::maps::CSimpleMap simplemap;
	mrpt::io::CFileGZInputStream file(path);
	mrpt::serialization::archiveFrom(file) >> simplemap;
	for (const auto& keyframe : simplemap)
		if (keyframe.sf && keyframe.pose)
			appendScans(*keyframe.sf, keyframe.pose->getMeanVal(), out);
	return out;
}
}  // namespace

const std::vector<TRunStep>& runOf(RunLog log)
{
	static std::map<RunLog, std::vector<TRunStep>> cache;
	auto& run = cache[log];
	if (!run.empty()) return run;
	const std::string dir = MRPT_DATASETS_DIR;
	switch (log)
	{
		case RunLog::Sena:
			run = rawlogRun(dir + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog");
			break;
		case RunLog::Malaga: run = simplemapRun(dir + "/malaga-cs-fac-building.simplemap.gz"); break;
		case RunLog::Localization: run = rawlogRun(dir + "/localization_demo.rawlog"); break;
		case RunLog::Simul:
			run = rawlogRun(dir + "/graphslam-engine-demos/action_observations_map/simul.rawlog");
			break;
	}
	if (run.empty())
		throw std::runtime_error(std::string("no 2-D scans in the log of run ") + name(log));
	return run;
}

double maxRangeOf(ScanKind kind) { return kind == ScanKind::Wide ? 30.0 : 15.0; }
double halfSizeOf(ScanKind kind) { return kind == ScanKind::Wide ? 40.0 : 20.0; }

const std::vector<CPose3D>& poses()
{
	static const std::vector<CPose3D> out = [] {
		std::mt19937 rng(2026);
		std::uniform_real_distribution<double> xy(-1.0, 1.0), yaw(-M_PI, M_PI);
		std::vector<CPose3D> p;
		for (int i = 0; i < kInsertions; ++i)
			p.emplace_back(xy(rng), xy(rng), 0.0, yaw(rng), 0.0, 0.0);
		return p;
	}();
	return out;
}

CObservation2DRangeScan scanAt(ScanKind kind, std::size_t i)
{
	const auto& all = scans(kind);
	CObservation2DRangeScan s = all[i % all.size()];
	s.timestamp = mrpt::Clock::fromDouble(1000.0 + 0.1 * static_cast<double>(i));
	return s;
}

double halfSizeFor(ScanKind kind, double maxRange)
{
	return std::max(halfSizeOf(kind), maxRange + 2.0);
}

std::unique_ptr<mrpt::maps::COccupancyGridMap2D> mrptMap(
	ScanKind kind, double resolution, bool widening, double maxRange)
{
	const double range = maxRange > 0 ? maxRange : maxRangeOf(kind);
	const double h = halfSizeFor(kind, range);
	auto map = std::make_unique<mrpt::maps::COccupancyGridMap2D>(
		-h, h, -h, h, resolution);
	map->insertionOptions.maxDistanceInsertion = static_cast<float>(range);
	map->insertionOptions.wideningBeamsWithDistance = widening;
	return map;
}

std::unique_ptr<CEvidentialGridMap2D> ourMap(
	ScanKind kind, double resolution, const OurOptions& o, double halfSize)
{
	const double range = o.maxRange > 0 ? o.maxRange : maxRangeOf(kind);
	const double h = halfSize > 0 ? halfSize : halfSizeFor(kind, range);
	auto map = std::make_unique<CEvidentialGridMap2D>(-h, h, -h, h, resolution);
	map->setMaxCells(std::max<std::size_t>(map->geometry().cellCount(), 100'000'000));
	auto& io = map->insertionOptions;
	io.sensorModel = o.model;
	io.fusionRule = o.rule;
	io.imprecision = o.model == SensorModel::ImpreciseMultiEcho ? resolution : 0.0;
	io.decayRate = !o.decay ? 0.0 : o.decayRate > 0 ? o.decayRate : 0.01;
	io.maxRange = range;
	if (o.muF > 0) io.muF = o.muF;
	if (o.muO > 0) io.muO = o.muO;
	if (o.sectorWidthDegrees > 0) io.sectorWidth = o.sectorWidthDegrees * M_PI / 180.0;
	io.insertionThreads = o.threads;
	io.conflictHandling = o.handling;
	return map;
}

std::string label(ScanKind kind, double resolution)
{
	char s[64];
	std::snprintf(s, sizeof(s), "%s/%.2fm", name(kind), resolution);
	return s;
}
}  // namespace bench
