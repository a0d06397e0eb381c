/* evgrid score-motion: replays a simulated rawlog into the map scan by scan
 * and scores its motion layer against the simulator's ground truth after
 * every scan. This file reads the command line, matches the input's scans to
 * the truth's records and runs the parts in order. */

#include <mrpt/core/Clock.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "CInputWalker.h"
#include "CMotionScorer.h"
#include "CMotionTruth.h"
#include "CObservedCells.h"
#include "CPoseFile.h"
#include "CProgress.h"
#include "CTruthEvents.h"
#include "CommandLine.h"
#include "Commands.h"
#include "InputOptions.h"
#include "MapOutputs.h"
#include "ScanInsertion.h"
#include "ScoreMotionOptions.h"
#include "ScoreMotionReport.h"

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
namespace
{
/** The truth writes times from scan 0 with two decimals and scan 0's Unix
 * time with three: a scan and its record are this close. */
constexpr double kTimeTolerance = 0.006;

std::optional<int> parseOptions(
	int argc, char** argv, int first, TScoreMotionOptions& options)
{
	TCLAP::CmdLine cmd(
		"Builds the map from a rawlog of evgrid-simulate scan by scan and, "
		"after each scan, scores its motion layer (getCellMotion: Appeared, "
		"Disappeared) against the simulator's ground truth "
		"(PREFIX.motion.gz) among the cells the scan observed: precision, "
		"recall and F1 of each kind summed over the scans, and the share of "
		"walls and furniture the map flags as moving. See doc/evgrid.md.",
		' ', EVGRID_VERSION);
	CReportArgs reportArgs(cmd);
	TCLAP::ValueArg<int> argTolerance(
		"", "tolerance",
		"A predicted cell and a truth cell of the same kind match within "
		"this many cells of the truth's grid (Chebyshev distance). At least "
		"0; default: one cell of the map (1 for a map of the truth's "
		"resolution, 2 for one twice as coarse).",
		false, 1, "CELLS", cmd);
	TCLAP::ValueArg<std::string> argTruth(
		"", "truth",
		"Required. The ground truth of what moves, PREFIX.motion.gz as "
		"evgrid-simulate writes it beside PREFIX.rawlog.",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argTruthTimes(
		"", "truth-times",
		"How the truth dates its events: 'observed' (default), at the first "
		"scan that saw the thing appear or go, counting only what the scans "
		"could tell (a cell seen free before it was hit, a cell hit before it "
		"was seen free again); 'physical', when the simulator says it "
		"happened, seen or not.",
		false, "observed", "observed|physical", cmd);
	TCLAP::ValueArg<std::string> argTruthPoses(
		"", "truth-poses",
		"The robot's true poses, PREFIX.gt.txt as evgrid-simulate writes it "
		"(lines 'time x y phi'): the cells each scan observed are traced "
		"from there, where its beams really went, while the map is built at "
		"the poses of -p. Without it they are traced at the map's poses, and "
		"the map's pose error also displaces the truth.",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argMotionFrame(
		"", "motion-frame",
		"Where the map's motion is read for a cell of the truth: 'world' "
		"(default), at the cell itself; 'scan', where the scored scan's pose "
		"estimate (-p) puts the cell, that is the cell moved by that "
		"estimate's error against the true pose (needs --truth-poses). The "
		"map puts what a scan saw where its pose estimate says: 'scan' leaves "
		"that error out of the motion's scores. Walls and furniture are read "
		"at their own cells either way (the static map averages the errors "
		"of many scans).",
		false, "world", "world|scan", cmd);
	CInputArgs inputArgs(cmd);

	if (const auto exitCode = parse(cmd, kScoreMotionName, argc, argv, first))
		return exitCode;
	options.source = inputArgs.values();
	options.truth = argTruth.getValue();
	if (options.truth.empty())
		throw UsageError("missing the truth: --truth PREFIX.motion.gz");
	// The choices spelled as the report spells them.
	const auto named = [](auto value, auto name) { return std::pair{name(value), value}; };
	options.truthTimes = oneOf<TruthTimes>(
		"--truth-times", argTruthTimes.getValue(),
		{named(TruthTimes::Observed, truthTimesName), named(TruthTimes::Physical, truthTimesName)});
	options.truthPoses = argTruthPoses.getValue();
	options.motionFrame = oneOf<MotionFrame>(
		"--motion-frame", argMotionFrame.getValue(),
		{named(MotionFrame::World, motionFrameName), named(MotionFrame::Scan, motionFrameName)});
	if (options.motionFrame == MotionFrame::Scan && options.truthPoses.empty())
		throw UsageError(
			"--motion-frame scan needs the true poses: --truth-poses PREFIX.gt.txt");
	if (argTolerance.isSet())
	{
		options.tolerance = argTolerance.getValue();
		requireAtLeast("--tolerance", *options.tolerance, 0);
	}
	options.report = reportArgs.values();
	return std::nullopt;
}

/** Takes the input's 2-D scans one by one: checks each against its truth
 * record, replays the record, inserts the scan and scores the map. */
class CReplay
{
   public:
	CReplay(
		CEvidentialGridMap2D& map, const CMotionTruth& truth,
		const TScoreMotionOptions& options, const CInputWalker& input)
		: m_map(map),
		  m_truth(truth),
		  m_inputPath(options.source.input),
		  m_input(input),
		  m_events(CTruthEvents::create(
			  options.truthTimes, truth.grid(),
			  map.insertionOptions.motionWindow)),
		  m_truePoses(
			  options.truthPoses.empty()
				  ? std::nullopt
				  : std::optional(CPoseFile::load(options.truthPoses, CPoseFile::Kind::Time))),
		  m_motionFrame(options.motionFrame),
		  m_seen(truth.grid()),
		  m_tolerance(options.tolerance.value_or(std::max(
			  1, static_cast<int>(std::lround(map.getResolution() / truth.grid().resolution))))),
		  m_scorer(truth, m_tolerance)
	{
	}

	void take(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const std::optional<mrpt::poses::CPose3D>& pose)
	{
		const std::size_t k = m_counts.total++;
		const auto& records = m_truth.scans();
		if (k >= records.size())
			throw std::runtime_error(
				m_truth.path() + ": holds " + std::to_string(records.size()) +
				" scans, but " + m_input.place() + " is 2-D scan " +
				std::to_string(k) + ": not the truth of this input");
		if (scan.timestamp == INVALID_TIMESTAMP)
			throw std::runtime_error(
				m_input.place() +
				": a scan without a time stamp, which matches it to the truth");
		const double stamp = mrpt::Clock::toDouble(scan.timestamp);
		const double expected = m_truth.startTime() + records[k].time;
		if (!(std::abs(stamp - expected) <= kTimeTolerance))
			throw std::runtime_error(
				m_truth.path() + ": scan " + std::to_string(k) + " is at " +
				fixedText(expected, 3) + " s but " + m_input.place() +
				" (2-D scan " + std::to_string(k) + ") at " +
				fixedText(stamp, 3) + " s: not the truth of this input");
		m_events->apply(k, records[k]);
		if (!pose)
		{
			++m_counts.withoutPose;
			return;
		}
		if (!insertScan(m_map, scan, *pose, m_input.place()))
		{
			++m_counts.refused;
			return;
		}
		++m_counts.scored;
		const mrpt::poses::CPose3D traced = tracedPose(k, stamp, *pose);
		m_seen.trace(scan, traced, m_map.insertionOptions.maxRange);
		m_events->observe(m_seen);
		// The estimate's error: a point where the scan really saw it to
		// where the estimate puts it.
		const mrpt::poses::CPose2D toMap = m_motionFrame == MotionFrame::Scan
			? mrpt::poses::CPose2D(*pose) + (-mrpt::poses::CPose2D(traced))
			: mrpt::poses::CPose2D();
		m_scorer.score(m_map, m_seen, *m_events, k, records[k].time, toMap);
	}

	/** \throws std::runtime_error if the input has fewer scans than the
	 *  truth, or none was scored. */
	void finish() const
	{
		if (m_counts.total != m_truth.scans().size())
			throw std::runtime_error(
				m_truth.path() + ": holds " +
				std::to_string(m_truth.scans().size()) + " scans, but " +
				m_inputPath + " has " + std::to_string(m_counts.total) +
				" 2-D scans: not the truth of this input");
		if (m_counts.scored == 0)
			throw std::runtime_error(
				m_truth.path() + ": no scan was scored (" +
				std::to_string(m_counts.total) + " 2-D scans, " +
				std::to_string(m_counts.withoutPose) + " without a pose, " +
				std::to_string(m_counts.refused) + " refused by the map)");
	}

	const TReplayCounts& counts() const { return m_counts; }
	/** What the report says the scans were traced at. */
	std::string tracedAt() const
	{
		return m_truePoses ? "true poses, " + m_truePoses->path() : "the map's poses";
	}
	const TMotionScore& score() const { return m_scorer.totals(); }
	int tolerance() const { return m_tolerance; }

   private:
	/** \throws std::runtime_error if the true poses have none at the scan's
	 *  time. */
	mrpt::poses::CPose3D tracedPose(
		std::size_t k, double stamp, const mrpt::poses::CPose3D& mapPose) const
	{
		if (!m_truePoses) return mapPose;
		const auto truePose = m_truePoses->atTime(stamp, kTimeTolerance);
		if (!truePose)
			throw std::runtime_error(
				m_truePoses->path() + ": no pose at the time of 2-D scan " +
				std::to_string(k) + " (" + fixedText(stamp, 3) +
				" s): not the true poses of this input");
		return mrpt::poses::CPose3D(mrpt::poses::CPose2D(*truePose));
	}

	CEvidentialGridMap2D& m_map;
	const CMotionTruth& m_truth;
	const std::string& m_inputPath;
	const CInputWalker& m_input;
	std::unique_ptr<CTruthEvents> m_events;
	std::optional<CPoseFile> m_truePoses;
	MotionFrame m_motionFrame;
	CObservedCells m_seen;
	int m_tolerance;
	CMotionScorer m_scorer;
	TReplayCounts m_counts;
};

void scoreMotion(const TScoreMotionOptions& options)
{
	// The small files first, so that their errors come before the long walk.
	if (!options.report.output.empty())
		checkOutputFile(
			options.report.output,
			{options.source.input, options.source.poses, options.source.config, options.truth,
			 options.truthPoses});
	const std::unique_ptr<CEvidentialGridMap2D> map = createMap(options.source);
	CPoseSource poses = createPoseSource(options.source);
	const CMotionTruth truth = CMotionTruth::load(options.truth);

	CInputWalker input(options.source.input, poses);
	CReplay replay(*map, truth, options, input);
	CProgress progress(CProgress::modeFor(options.report.quiet), kScoreMotionName);
	input.walk(
		{[] {},
		 [&replay](const auto& scan, const auto& pose) {
			 replay.take(scan, pose);
		 },
		 [&](double fraction) {
			 progress.update(fraction, replay.counts().scored);
		 },
		 // 2-D scans only: clouds count among the other observations.
		 {}});
	progress.finish();
	replay.finish();
	requireACellSeen(*map, replay.counts().scored, options.source.input);

	TScoreMotionRecord run;
	run.poses = poses.description();
	run.tracedAt = replay.tracedAt();
	run.motionWindow = map->insertionOptions.motionWindow;
	run.tolerance = replay.tolerance();
	run.scans = replay.counts();
	run.score = replay.score();
	writeReport(
		options.report,
		[&](std::ostream& os) {
			writeMotionKeyValues(os, options, truth, run);
		},
		[&](std::ostream& os) { printMotionReport(os, options, truth, run); });
	// Scores of nothing read as a layer that flagged wrong: say why.
	if (run.score.appeared.truth == 0 && run.score.disappeared.truth == 0 &&
		run.score.appeared.predicted + run.score.disappeared.predicted > 0)
		std::cerr << kScoreMotionName
				  << ": warning: no truth cell lay where the scans looked, though the map "
					 "flagged cells: are the map and the truth in one frame? (without -p the "
					 "map follows the odometry from (0, 0, 0); give the simulator's "
					 "PREFIX.slam.txt or PREFIX.gt.txt)\n";
}
}  // namespace

int runScoreMotion(int argc, char** argv, int first)
{
	TScoreMotionOptions options;
	if (const auto exitCode = parseOptions(argc, argv, first, options))
		return *exitCode;
	scoreMotion(options);
	return 0;
}

}  // namespace evgrid
