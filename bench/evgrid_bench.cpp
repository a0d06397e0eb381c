/* evgrid-bench: the evidential grid against MRPT's COccupancyGridMap2D, on the
 * same scans and poses, in one process. After Google Benchmark's table it
 * prints the ratios that matter (ours / MRPT's) and the memory per cell.
 *
 *   evgrid-bench [--smoke] [Google Benchmark flags]
 *
 * --smoke runs every case for a few iterations only (CTest uses it so that
 * the program cannot rot); timings from it mean nothing. */

#include <benchmark/benchmark.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt_evidential/CEvidentialGridMap2D.h>
#include "insert/PolarToCartesian.h"

#include "CloudCases.h"
#include "RunCases.h"
#include "RatioReport.h"
#include "ScanInputs.h"
#include "TransformLoop.h"

#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using mrpt::obs::CObservation2DRangeScan;
using mrpt::poses::CPose3D;
using namespace mrpt_evidential;
using namespace bench;

namespace
{
bool smoke = false;
/** Runs per case, each of kInsertions insertions (a path's, for a whole
 * path) or of kCallSeconds of calls: each run starts from a fresh map, so
 * that a run holds as many first writes to a cell as a single run would. */
constexpr int kRepetitions = 3;
constexpr double kCallSeconds = 0.5;

// ---------------------------------------------------------------------------
// Cases
// ---------------------------------------------------------------------------

/** One insertion per iteration, at the next pose; the map keeps growing
 * denser as in a real run. */
template <typename Map>
void insertionLoop(benchmark::State& state, Map& map, ScanKind kind)
{
	std::size_t i = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		const CObservation2DRangeScan scan = scanAt(kind, i);
		const CPose3D& pose = poses()[i % poses().size()];
		state.ResumeTiming();
		map.insertObservation(scan, pose);
		++i;
	}
}

void mrptInsert(
	benchmark::State& state, ScanKind kind, double res, bool widening, double maxRange = 0)
{
	auto map = mrptMap(kind, res, widening, maxRange);
	insertionLoop(state, *map, kind);
}

void ourInsert(benchmark::State& state, ScanKind kind, double res, OurOptions o)
{
	auto map = ourMap(kind, res, o);
	insertionLoop(state, *map, kind);
}

void ourInsertMapSize(benchmark::State& state, double halfSize)
{
	auto map = ourMap(ScanKind::Stock, 0.05, OurOptions{}, halfSize);
	insertionLoop(state, *map, ScanKind::Stock);
}

/** Both maps built from the same 200 insertions, then one scan scored per
 * iteration at the next pose (the likelihood caches warm up first). */
template <typename Map>
void likelihoodLoop(benchmark::State& state, Map& map, ScanKind kind)
{
	for (std::size_t i = 0; i < 200; ++i) map.insertObservation(scanAt(kind, i), poses()[i]);
	const CObservation2DRangeScan scan = scanAt(kind, 0);
	for (const auto& p : poses()) benchmark::DoNotOptimize(map.computeObservationLikelihood(scan, p));
	std::size_t i = 0;
	for (auto _ : state)
	{
		benchmark::DoNotOptimize(
			map.computeObservationLikelihood(scan, poses()[i % poses().size()]));
		++i;
	}
}

void mrptLikelihood(benchmark::State& state, ScanKind kind, double res)
{
	auto map = mrptMap(kind, res, false);
	likelihoodLoop(state, *map, kind);
}

void ourLikelihood(benchmark::State& state, ScanKind kind, double res)
{
	auto map = ourMap(kind, res, OurOptions{});
	likelihoodLoop(state, *map, kind);
}

TSourceGridOptions sourceOptions(ScanKind kind, double res)
{
	CEvidentialGridMap2D::TInsertionOptions io;
	io.maxRange = maxRangeOf(kind);
	return io.sourceGridOptions(res);
}

void ourSourceGrid(benchmark::State& state, ScanKind kind, double res)
{
	CPolarSourceGrid polar;
	const auto options = sourceOptions(kind, res);
	const auto& scan = scans(kind).front();
	for (auto _ : state)
	{
		polar.build(scan, options);
		benchmark::DoNotOptimize(polar.maxInformedBins());
	}
}

void ourPolarToCartesian(benchmark::State& state, ScanKind kind, double res)
{
	CPolarSourceGrid polar;
	polar.build(scans(kind).front(), sourceOptions(kind, res));
	bench::transformLoop(state, polar, {0.3, -0.2, 0.4, false}, halfSizeOf(kind), res);
}

// ---------------------------------------------------------------------------
// Registration and the ratio report
// ---------------------------------------------------------------------------

const char* name(SensorModel m)
{
	switch (m)
	{
		case SensorModel::MultiEcho: return "MultiEcho";
		case SensorModel::ReinforcedMultiEcho: return "Reinforced";
		case SensorModel::ImpreciseMultiEcho: return "Imprecise";
	}
	return "";
}
std::string name(FusionRule r)
{
	return mrpt::typemeta::TEnumType<FusionRule>::value2name(r);
}

}  // namespace

void bench::addCase(
	const std::string& caseName, std::function<void(benchmark::State&)> fn, Timing timing)
{
	auto* b = benchmark::RegisterBenchmark(caseName.c_str(), std::move(fn));
	b->Unit(benchmark::kMicrosecond);
	if (smoke)
	{
		b->Iterations(3);
		return;
	}
	if (timing == Timing::Calls)
		b->MinTime(kCallSeconds);
	else
		b->Iterations(kInsertions);
	b->Repetitions(kRepetitions)->ReportAggregatesOnly(true);
}

namespace
{
using bench::Timing;
template <typename Fn>
void add(const std::string& caseName, Fn fn, Timing timing)
{
	bench::addCase(caseName, fn, timing);
}

/** The settings users change (issue 15), one at a time, against MRPT's grid
 * with widening beams and the same maxRange: SENA's real scans (returns up to
 * 80 m) for maxRange, as they are and with every other beam (a scanner of 1
 * degree), the stock scan for the masses and the sector width;
 * then the issue's own example of them together. */
struct SweepCase
{
	std::string setting;
	ScanKind kind;
	OurOptions ours;
};
const std::vector<SweepCase>& sweepCases()
{
	static const std::vector<SweepCase> cases = [] {
		std::vector<SweepCase> out;
		for (const double range : {10.0, 30.0, 80.0})
		{
			OurOptions o;
			o.maxRange = range;
			out.push_back({"maxRange" + std::to_string(int(range)), ScanKind::Sena, o});
			out.push_back({"maxRange" + std::to_string(int(range)), ScanKind::SenaOneDegree, o});
		}
		for (const auto& [muF, muO] : {std::pair{0.6, 0.85}, std::pair{0.9, 0.98}})
		{
			OurOptions o;
			o.muF = muF, o.muO = muO;
			char name[32];
			std::snprintf(name, sizeof(name), "muF%.2g-muO%.2g", muF, muO);
			out.push_back({name, ScanKind::Stock, o});
		}
		// The seed's conjunctive grid, which keeps conflict (no motion layer).
		for (const ScanKind kind : {ScanKind::Stock, ScanKind::Sena})
		{
			OurOptions o;
			o.handling = ConflictHandling::Keep;
			out.push_back({"keepConflict", kind, o});
		}
		for (const double degrees : {0.25, 2.0})
		{
			OurOptions o;
			o.sectorWidthDegrees = degrees;
			char name[32];
			std::snprintf(name, sizeof(name), "sector%.2gdeg", degrees);
			out.push_back({name, ScanKind::Stock, o});
		}
		// Issue 15's own example of common settings, all at once.
		OurOptions o;
		o.maxRange = 30.0, o.decayRate = 0.05, o.muF = 0.6, o.muO = 0.85;
		out.push_back({"maxRange30-decay0.05-muF0.6-muO0.85", ScanKind::Stock, o});
		return out;
	}();
	return cases;
}
std::string sweepName(const char* who, const SweepCase& c)
{
	return std::string(who) + "/sweep/" + c.setting + "/" + name(c.kind) + "/0.05m";
}

void registerSweep()
{
	for (const SweepCase& c : sweepCases())
	{
		add(sweepName("ours", c), [=](benchmark::State& s) { ourInsert(s, c.kind, 0.05, c.ours); },
			Timing::Insertions);
		add(sweepName("mrpt", c),
			[=](benchmark::State& s) { mrptInsert(s, c.kind, 0.05, true, c.ours.maxRange); },
			Timing::Insertions);
	}
}

void registerCases()
{
	for (const ScanKind kind : {ScanKind::Stock, ScanKind::Sena, ScanKind::Wide})
		for (const double res : {0.05, 0.10})
		{
			const std::string at = label(kind, res);
			add("mrpt/insert/plain/" + at,
				[=](benchmark::State& s) { mrptInsert(s, kind, res, false); }, Timing::Insertions);
			add("mrpt/insert/widening/" + at,
				[=](benchmark::State& s) { mrptInsert(s, kind, res, true); }, Timing::Insertions);
			for (const SensorModel model :
				 {SensorModel::MultiEcho, SensorModel::ReinforcedMultiEcho,
				  SensorModel::ImpreciseMultiEcho})
				for (const bool decay : {true, false})
				{
					const OurOptions o{model, FusionRule::Conjunctive, decay};
					add(std::string("ours/insert/") + name(model) + "/Conjunctive/" +
							(decay ? "decay/" : "nodecay/") + at,
						[=](benchmark::State& s) { ourInsert(s, kind, res, o); },
						Timing::Insertions);
				}
			for (const FusionRule rule :
				 {FusionRule::Dempster, FusionRule::Yager, FusionRule::DuboisPrade,
				  FusionRule::Cautious})
			{
				const OurOptions o{SensorModel::ReinforcedMultiEcho, rule, true};
				add(std::string("ours/insert/Reinforced/") + name(rule) + "/decay/" + at,
					[=](benchmark::State& s) { ourInsert(s, kind, res, o); }, Timing::Insertions);
			}
			// Reported apart: the single-thread ratios are the ones that count.
			OurOptions twoThreads;
			twoThreads.threads = 2;
			add("ours/threads/2/" + at,
				[=](benchmark::State& s) { ourInsert(s, kind, res, twoThreads); },
				Timing::Insertions);
			add("mrpt/likelihood/" + at,
				[=](benchmark::State& s) { mrptLikelihood(s, kind, res); }, Timing::Calls);
			add("ours/likelihood/" + at,
				[=](benchmark::State& s) { ourLikelihood(s, kind, res); }, Timing::Calls);
			add("ours/sourcegrid/" + at,
				[=](benchmark::State& s) { ourSourceGrid(s, kind, res); }, Timing::Calls);
			add("ours/polar2cart/" + at,
				[=](benchmark::State& s) { ourPolarToCartesian(s, kind, res); }, Timing::Calls);
		}
	add("ours/mapsize/40m/stock/0.05m",
		[](benchmark::State& s) { ourInsertMapSize(s, 20.0); }, Timing::Insertions);
	add("ours/mapsize/400m/stock/0.05m",
		[](benchmark::State& s) { ourInsertMapSize(s, 200.0); }, Timing::Insertions);
	registerSweep();
	bench::registerRunCases();
	bench::registerCloudCases();
}

void printReport(const bench::RecordingReporter& reporter)
{
	const auto printRatio = [&reporter](
								const std::string& what, const std::string& ours,
								const std::string& theirs, double target) {
		bench::printRatio(reporter.microseconds, what, ours, theirs, target);
	};
	std::printf("\nRatios (ours / reference, lower is better):\n");
	const std::string ours = "ours/insert/Reinforced/Conjunctive/decay/";
	for (const char* at : {"stock/0.05m", "stock/0.10m", "sena/0.05m", "wide/0.05m"})
	{
		printRatio(std::string("insert reinforced+decay vs widening, ") + at,
				   ours + at, std::string("mrpt/insert/widening/") + at, 1.0);
		printRatio(std::string("insert reinforced+decay vs plain, ") + at,
				   ours + at, std::string("mrpt/insert/plain/") + at, 2.0);
		printRatio(std::string("likelihood, ") + at,
				   std::string("ours/likelihood/") + at,
				   std::string("mrpt/likelihood/") + at, 1.5);
		// The other rules, reinforced model with decay as above.
		for (const char* rule : {"Dempster", "Yager", "DuboisPrade", "Cautious"})
			printRatio(std::string("insert ") + rule + " vs widening, " + at,
					   std::string("ours/insert/Reinforced/") + rule + "/decay/" + at,
					   std::string("mrpt/insert/widening/") + at, 1.5);
	}
	printRatio("insert into 400 x 400 m vs 40 x 40 m map",
			   "ours/mapsize/400m/stock/0.05m", "ours/mapsize/40m/stock/0.05m", 1.1);
	for (const SweepCase& c : sweepCases())
		printRatio("insert vs widening, " + c.setting + ", " + name(c.kind) + "/0.05m",
				   sweepName("ours", c), sweepName("mrpt", c), 1.0);
	bench::printRunRatios(reporter.microseconds);
	bench::printCloudRatios(reporter.microseconds);
	std::printf("\nOn two threads (insertionThreads=2; apart from the targets):\n");
	for (const char* at :
		 {"stock/0.05m", "stock/0.10m", "sena/0.05m", "sena/0.10m", "wide/0.05m", "wide/0.10m"})
	{
		printRatio(std::string("2 threads vs 1, ") + at, std::string("ours/threads/2/") + at,
				   ours + at, 1.0);
		printRatio(std::string("2 threads vs widening, ") + at,
				   std::string("ours/threads/2/") + at,
				   std::string("mrpt/insert/widening/") + at, 1.0);
	}

	std::printf(
		"\nMemory per cell: ours %zu bytes (masses and time stamp), plus 1 byte "
		"while the likelihood field is in use;\n"
		"                 COccupancyGridMap2D %zu byte, plus %zu bytes while its "
		"likelihood cache is in use.\n",
		sizeof(QuantizedCell), sizeof(mrpt::maps::COccupancyGridMap2D::cellType),
		sizeof(double));
}
}  // namespace

int main(int argc, char** argv)
{
	// The repetitions of all cases in a random order unless asked otherwise
	// (a later flag wins): a slow minute of this kind of machine then falls
	// on one run of several cases, which their medians leave out, instead of
	// on every run of one case, which would move its ratio.
	static char interleave[] = "--benchmark_enable_random_interleaving=true";
	// Our own flag first: Google Benchmark rejects flags it does not know.
	std::vector<char*> args;
	for (int i = 0; i < argc; ++i)
	{
		if (std::strcmp(argv[i], "--smoke") == 0)
			smoke = true;
		else
			args.push_back(argv[i]);
		if (i == 0) args.push_back(interleave);
	}
	int n = static_cast<int>(args.size());
	benchmark::Initialize(&n, args.data());
	if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 2;
	registerCases();
	bench::RecordingReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);
	printReport(reporter);
	benchmark::Shutdown();
	return 0;
}
