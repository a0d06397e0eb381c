/* evgrid-bench: whole runs: the grid's growth along long paths, and the
 * whole logs of mrpt-common. */

#include "RunCases.h"

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include "insert/PolarToCartesian.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "RatioReport.h"
#include "ScanInputs.h"

using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;
using namespace mrpt_evidential;

namespace bench
{
namespace
{
/** A path of kInsertions scans, from a grid of 10 x 10 m (or, `presized`,
 * one that holds the whole path from the start): the cost of growing the
 * grid as a long run does. Straight along +x, 0.5 m a scan (1 km); diagonal,
 * 0.25 m a scan (500 m, a grid that grows along both axes: the largest a
 * 0.05 m grid holds within the default budget of cells); or a square spiral
 * outwards, 0.25 m a scan, the scan facing the way it goes, legs of 20, 20,
 * 40, 40, 60 m... (500 m: a run that explores, growing each way in turn). */
struct TPath
{
	std::string name;
	std::function<CPose3D(std::size_t)> poseAt;
};
CPose3D spiralPose(std::size_t i)
{
	constexpr double kStep = 0.25, kLegGrowth = 20.0;
	double x = 0, y = 0, walked = 0;
	const double target = kStep * static_cast<double>(i);
	for (int leg = 0;; ++leg)
	{
		const double length = kLegGrowth * (leg / 2 + 1);
		const double yaw = (leg % 4) * M_PI / 2;
		const double along = std::min(length, target - walked);
		x += along * std::cos(yaw), y += along * std::sin(yaw), walked += along;
		if (walked >= target) return CPose3D(x, y, 0.0, yaw, 0.0, 0.0);
	}
}
const std::vector<TPath>& paths()
{
	const auto straight = [](double dx, double dy) {
		return [dx, dy](std::size_t i) {
			const auto k = static_cast<double>(i);
			return CPose3D(dx * k, dy * k, 0.0, 0.0, 0.0, 0.0);
		};
	};
	static const std::vector<TPath> all{
		{"path", straight(0.5, 0.0)},
		{"diagonalpath", straight(0.25 * M_SQRT1_2, 0.25 * M_SQRT1_2)},
		{"spiralpath", spiralPose}};
	return all;
}

template <typename Map>
void pathLoop(benchmark::State& state, Map& map, const TPath& path)
{
	std::size_t i = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		const CObservation2DRangeScan scan = scanAt(ScanKind::Stock, i);
		const CPose3D pose = path.poseAt(i);
		state.ResumeTiming();
		map.insertObservation(scan, pose);
		++i;
	}
}

/** The box a path's scans reach: its poses with the stock scan's range
 * around them. */
Box pathExtent(const TPath& path)
{
	const double r = maxRangeOf(ScanKind::Stock) + 1.0;
	Box box;
	for (std::size_t i = 0; i < static_cast<std::size_t>(kInsertions); ++i)
	{
		const CPose3D p = path.poseAt(i);
		box.add(p.x() - r, p.y() - r);
		box.add(p.x() + r, p.y() + r);
	}
	return box;
}

void mrptPath(benchmark::State& state, const TPath& path, bool presized)
{
	const Box b = pathExtent(path);
	mrpt::maps::COccupancyGridMap2D map(
		presized ? b.xMin : -5.0, presized ? b.xMax : 5.0, presized ? b.yMin : -5.0,
		presized ? b.yMax : 5.0, 0.05);
	map.insertionOptions.maxDistanceInsertion = static_cast<float>(maxRangeOf(ScanKind::Stock));
	map.insertionOptions.wideningBeamsWithDistance = true;
	pathLoop(state, map, path);
}

void ourPath(benchmark::State& state, const TPath& path, bool presized)
{
	auto map = ourMap(ScanKind::Stock, 0.05, OurOptions{}, 5.0);
	if (presized)
	{
		const Box b = pathExtent(path);
		map->setSize(b.xMin, b.xMax, b.yMin, b.yMax, 0.05);
	}
	pathLoop(state, *map, path);
}

/** A log's whole run along its path into a grid of 20 x 20 m that grows,
 * as a user builds the map of a log: ours with the map's defaults (those of
 * rawlogs/evgrid.ini: imprecise model, maxRange 20 m, no decay, motion
 * layer), MRPT's with its own and the same range. Each pass over the log
 * starts a fresh map (made and dropped outside the timing), so that the
 * runs' growth and first writes to new ground are timed scan by scan. */
template <typename Map>
void runLoop(
	benchmark::State& state, RunLog log, const std::function<std::unique_ptr<Map>()>& make)
{
	const std::vector<TRunStep>& run = runOf(log);
	std::unique_ptr<Map> map = make();
	std::size_t i = 0;
	for (auto _ : state)
	{
		if (i == run.size())
		{
			state.PauseTiming();
			map = make();
			i = 0;
			state.ResumeTiming();
		}
		map->insertObservation(run[i].scan, run[i].pose);
		++i;
	}
}
constexpr double kRunRange = 20.0;

void ourRun(benchmark::State& state, RunLog log)
{
	runLoop<CEvidentialGridMap2D>(state, log, [] {
		auto map = std::make_unique<CEvidentialGridMap2D>(-10.0, 10.0, -10.0, 10.0, 0.05);
		map->insertionOptions.maxRange = kRunRange;
		return map;
	});
}

void mrptRun(benchmark::State& state, RunLog log, bool widening)
{
	runLoop<mrpt::maps::COccupancyGridMap2D>(state, log, [widening] {
		auto map = std::make_unique<mrpt::maps::COccupancyGridMap2D>(-10.0, 10.0, -10.0, 10.0, 0.05);
		map->insertionOptions.maxDistanceInsertion = static_cast<float>(kRunRange);
		map->insertionOptions.wideningBeamsWithDistance = widening;
		return map;
	});
}

/** "senarun": a log's run in the cases' names (SENA's name kept from before
 * the other logs came). */
std::string runName(RunLog log) { return std::string(name(log)) + "run"; }
}  // namespace

void registerRunCases()
{
	for (const TPath& path : paths())
		for (const bool presized : {false, true})
		{
			const std::string at = path.name + (presized ? "/presized" : "/growing") + "/stock/0.05m";
			addCase("mrpt/" + at, [=](benchmark::State& s) { mrptPath(s, path, presized); },
				Timing::WholePath);
			addCase("ours/" + at, [=](benchmark::State& s) { ourPath(s, path, presized); },
				Timing::WholePath);
		}
	for (const RunLog log : runLogs())
	{
		const std::string run = runName(log);
		addCase("mrpt/" + run + "/plain/0.05m",
			[log](benchmark::State& s) { mrptRun(s, log, false); }, Timing::WholePath);
		addCase("mrpt/" + run + "/widening/0.05m",
			[log](benchmark::State& s) { mrptRun(s, log, true); }, Timing::WholePath);
		addCase("ours/" + run + "/growing/0.05m", [log](benchmark::State& s) { ourRun(s, log); },
			Timing::WholePath);
	}
}

void printRunRatios(const std::map<std::string, double>& microseconds)
{
	const auto print = [&microseconds](
						   const std::string& what, const std::string& ours,
						   const std::string& theirs, double target) {
		printRatio(microseconds, what, ours, theirs, target);
	};
	print("1 km path, growing vs presized grid", "ours/path/growing/stock/0.05m",
			   "ours/path/presized/stock/0.05m", 1.1);
	print("1 km path, growing grid vs MRPT's growing", "ours/path/growing/stock/0.05m",
			   "mrpt/path/growing/stock/0.05m", 1.0);
	print("500 m diagonal, growing vs presized grid",
			   "ours/diagonalpath/growing/stock/0.05m", "ours/diagonalpath/presized/stock/0.05m", 1.1);
	print("500 m diagonal, growing grid vs MRPT's growing",
			   "ours/diagonalpath/growing/stock/0.05m", "mrpt/diagonalpath/growing/stock/0.05m", 1.0);
	for (const RunLog log : runLogs())
	{
		const std::string run = runName(log), ours = "ours/" + run + "/growing/0.05m",
						  what = std::string(name(log)) + "'s whole run (map defaults) vs ";
		print(what + "widening", ours, "mrpt/" + run + "/widening/0.05m", 1.0);
		print(what + "plain", ours, "mrpt/" + run + "/plain/0.05m", 2.0);
	}
	print("500 m spiral, growing vs presized grid",
			   "ours/spiralpath/growing/stock/0.05m", "ours/spiralpath/presized/stock/0.05m", 1.1);
	print("500 m spiral, growing grid vs MRPT's growing",
			   "ours/spiralpath/growing/stock/0.05m", "mrpt/spiralpath/growing/stock/0.05m", 1.0);
}

}  // namespace bench
