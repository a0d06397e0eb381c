/* evgrid compare: our evidential grid against MRPT's COccupancyGridMap2D,
 * built from the same scans at the same poses. This file reads the command
 * line and runs the parts in order: both maps, the cell agreement, the
 * localization test, the report. */

#include <optional>
#include <utility>

#include "CInputWalker.h"
#include "CProgress.h"
#include "CSideBySideMaps.h"
#include "CommandLine.h"
#include "CompareOptions.h"
#include "CompareReport.h"
#include "Commands.h"
#include "InputOptions.h"
#include "MapFiles.h"
#include "MapOutputs.h"

namespace evgrid
{
namespace
{
std::optional<int> parseOptions(
	int argc, char** argv, int first, TCompareOptions& options)
{
	TCLAP::CmdLine cmd(
		"Builds, from one input, our evidential grid (settings from the .ini) "
		"and MRPT's COccupancyGridMap2D (the insertion and likelihood options "
		"of the .ini's occupancyGrid if it lists one, else MRPT's defaults; our "
		"map's resolution) side by side, inserting the same scans at the same "
		"poses, and reports (1) how our map's decisions agree with MRPT's "
		"occupied (getCell < 0.4) and free (getCell > 0.6) cells, and (2) the "
		"localization hit rate of each map on the scans held out of both. "
		"See doc/evgrid.md.",
		' ', EVGRID_VERSION);
	CReportArgs reportArgs(cmd);
	TCLAP::ValueArg<int> argHoldout(
		"", "holdout",
		"Hold every N-th scan with a pose out of both maps, for the "
		"localization test. At least 2, default 10.",
		false, 10, "N", cmd);
	CInputArgs inputArgs(cmd);

	if (const auto exitCode = parse(cmd, kCompareName, argc, argv, first))
		return exitCode;
	options.source = inputArgs.values();
	options.holdout = argHoldout.getValue();
	requireAtLeast("--holdout", options.holdout, 2);
	options.report = reportArgs.values();
	return std::nullopt;
}

void compare(const TCompareOptions& options)
{
	if (!options.report.output.empty())
		checkOutputFile(
			options.report.output,
			{options.source.input, options.source.poses, options.source.config});
	auto ours = createMap(options.source);
	// MRPT's grid as the same .ini configures it for icp-slam and the other
	// programs, when it lists one.
	const auto mrptOptions = options.source.config.empty()
		? std::nullopt
		: occupancyGridFromConfig(options.source.config, options.source.section);
	TCompareRecord run;
	run.mrptOptions = mrptOptions
		? "the .ini's first occupancyGrid (its insertOpts and likelihoodOpts; our map's cells)"
		: "MRPT's defaults";
	CPoseSource poses = createPoseSource(options.source);
	CInputWalker input(options.source.input, poses);
	CSideBySideMaps maps(std::move(ours), mrptOptions, options.holdout, input);

	const auto mode = CProgress::modeFor(options.report.quiet);
	CProgress building(mode, std::string(kCompareName) + " (maps)");
	input.walk(
		{[] {},
		 [&maps](const auto& scan, const auto& pose) {
			 maps.offer(scan, pose);
		 },
		 [&](double fraction) {
			 building.update(fraction, maps.counts().offered);
		 },
		 // 2-D scans only: clouds count among the other observations.
		 {}});
	building.finish();
	const TSideBySideCounts& n = maps.counts();
	if (n.oursInserted == 0 || n.mrptInserted == 0)
		throw std::runtime_error(
			options.source.input + ": a map took no scan (" +
			std::to_string(n.total) + " 2-D scans, " +
			std::to_string(n.withoutPose) + " without a pose, " +
			std::to_string(n.heldOut) + " held out; ours took " +
			std::to_string(n.oursInserted) + ", MRPT " +
			std::to_string(n.mrptInserted) + notInsertedAccount(input.counts()) + ")");
	maps.finish();

	run.poses = poses.description();
	run.agreement = compareCells(maps.mrpt(), maps.ours());
	CProgress localizing(mode, std::string(kCompareName) + " (localization)");
	const double steps = 2.0 * static_cast<double>(maps.heldOut().size());
	std::size_t done = 0;
	const auto afterScan = [&] {
		++done;
		localizing.update(static_cast<double>(done) / steps, done);
	};
	run.ours = scoreLocalization(maps.ours(), maps.heldOut(), afterScan);
	run.mrpt = scoreLocalization(maps.mrpt(), maps.heldOut(), afterScan);
	localizing.finish();

	writeReport(
		options.report,
		[&](std::ostream& os) { writeKeyValues(os, options, maps, run); },
		[&](std::ostream& os) { printReport(os, options, maps, run); });
}
}  // namespace

int runCompare(int argc, char** argv, int first)
{
	TCompareOptions options;
	if (const auto exitCode = parseOptions(argc, argv, first, options))
		return *exitCode;
	compare(options);
	return 0;
}

}  // namespace evgrid
