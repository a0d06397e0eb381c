/* evgrid score-motion: the report, on the console and as a `key value`
 * file. */

#include "ScoreMotionReport.h"

#include <mrpt_evidential/support/NumberText.h>

#include <iomanip>
#include <optional>

#include "Report.h"

using mrpt_evidential::detail::shortestText;

namespace evgrid
{
namespace
{
/** Every number goes through fixedText() and these, so that the console and
 * the file show the same text. */
std::string text(const std::optional<double>& ratio)
{
	return ratio ? fixedText(*ratio, 4) : "n/a";
}

std::optional<double> ratio(std::size_t part, std::size_t whole)
{
	if (whole == 0) return std::nullopt;
	return static_cast<double>(part) / static_cast<double>(whole);
}

/** Precision, recall and F1 = 2PR / (P + R) (0 when both are 0). */
struct TRatios
{
	std::optional<double> precision, recall, f1;
	explicit TRatios(const TKindScore& k)
		: precision(ratio(k.truePositives, k.predicted)),
		  recall(ratio(k.recalled, k.truth))
	{
		if (!precision || !recall) return;
		const double sum = *precision + *recall;
		f1 = sum > 0 ? 2 * *precision * *recall / sum : 0.0;
	}
};

/** What the console says of each frame. */
std::string motionFrameText(MotionFrame frame)
{
	return frame == MotionFrame::Scan
		? "scan (each truth cell where the scan's pose estimate puts it; walls at their cells)"
		: "world (the truth's cells themselves)";
}

/** What the console says of each dating. */
std::string truthTimesText(TruthTimes times)
{
	return std::string(truthTimesName(times)) +
		(times == TruthTimes::Physical
			 ? " (each event from when it happened, seen or not)"
			 : " (each event from the first scan that saw it)");
}

std::string percent(double share) { return fixedText(100 * share, 2); }
std::string overallStaticPct(const TStaticScore& s)
{
	const auto r = ratio(s.flagged, s.observed);
	return r ? percent(*r) : "n/a";
}
std::string meanStaticPct(const TStaticScore& s)
{
	if (s.scans == 0) return "n/a";
	return percent(s.shareSum / static_cast<double>(s.scans));
}

/** The worst scan's flagged static cells, "x,y" (m, three decimals) apart
 * by spaces; "none" when it flagged none, "n/a" when no scan saw a static
 * cell. */
std::string worstCells(const TStaticScore& s)
{
	if (s.scans == 0) return "n/a";
	if (s.worstCells.empty()) return "none";
	std::string out;
	for (const auto& [x, y] : s.worstCells)
		out += (out.empty() ? "" : " ") + fixedText(x, 3) + "," + fixedText(y, 3);
	return out;
}

std::string truthGrid(const TTruthGrid& g)
{
	return fixedText(g.x0, 2) + " " + fixedText(g.y0, 2) + " " +
		shortestText(g.resolution) + " " + std::to_string(g.sizeX) + " " +
		std::to_string(g.sizeY);
}

using KindValue = std::string (*)(const TKindScore&);
std::string count(std::size_t n) { return std::to_string(n); }
struct TKindRow
{
	const char* label;
	KindValue value;
};
const TKindRow kKindRows[] = {
	{"truth cells", [](const TKindScore& k) { return count(k.truth); }},
	{"recalled", [](const TKindScore& k) { return count(k.recalled); }},
	{"recall", [](const TKindScore& k) { return text(TRatios(k).recall); }},
	{"predicted (observed)",
	 [](const TKindScore& k) { return count(k.predicted); }},
	{"true positives",
	 [](const TKindScore& k) { return count(k.truePositives); }},
	{"precision",
	 [](const TKindScore& k) { return text(TRatios(k).precision); }},
	{"F1", [](const TKindScore& k) { return text(TRatios(k).f1); }},
	{"map's cells (all)",
	 [](const TKindScore& k) { return count(k.mapCells); }}};
}  // namespace

void printMotionReport(
	std::ostream& os, const TScoreMotionOptions& options,
	const CMotionTruth& truth, const TScoreMotionRecord& run)
{
	const TReplayCounts& n = run.scans;
	const TMotionScore& s = run.score;
	const TTruthGrid& g = truth.grid();
	os << kScoreMotionName
	   << ": the map's motion layer against the ground truth, after every "
		  "scan\n"
	   << "input: " << options.source.input << "\n"
	   << "poses: " << run.poses << "\n"
	   << "config: " << configDescription(options.source) << "\n"
	   << "truth: " << truth.path() << " (scene " << truth.scene() << ", "
	   << truth.scans().size() << " scans, grid " << g.sizeX << " x "
	   << g.sizeY << " cells of " << shortestText(g.resolution)
	   << " m from (" << fixedText(g.x0, 2) << ", " << fixedText(g.y0, 2) << "))\n"
	   << "scans: " << n.total << " 2-D scans: " << n.withoutPose
	   << " without a pose, " << n.refused << " refused by the map, "
	   << n.scored << " inserted and scored\n"
	   << "motion window: " << shortestText(run.motionWindow)
	   << " s (the map's motionWindow); tolerance: " << run.tolerance
	   << (run.tolerance == 1 ? " cell" : " cells") << " (Chebyshev)"
	   << (options.tolerance ? "" : ", one map cell") << "\n"
	   << "truth times: " << truthTimesText(options.truthTimes) << "\n"
	   << "observed cells traced at: " << run.tracedAt << "\n"
	   << "motion read at: " << motionFrameText(options.motionFrame) << "\n"
	   << "observed cells, summed over the scans: " << s.hitCells
	   << " hit (a beam's end), " << s.crossedCells << " crossed\n\n";

	os << std::left << std::setw(24) << "motion" << std::right
	   << std::setw(10) << "appeared" << std::setw(13) << "disappeared"
	   << "\n";
	for (const TKindRow& row : kKindRows)
		os << "  " << std::left << std::setw(22) << row.label << std::right
		   << std::setw(10) << row.value(s.appeared) << std::setw(13)
		   << row.value(s.disappeared) << "\n";

	const TStaticScore& st = s.statics;
	os << "\nstatic structure (walls, furniture: " << truth.staticCells().size()
	   << " cells) the map flags as moving, where the scans saw it\n"
	   << "  observed, summed over the scans: " << st.observed << " cells, "
	   << st.flagged << " flagged\n"
	   << "  overall share %: " << overallStaticPct(st) << "\n"
	   << "  mean share per scan %: " << meanStaticPct(st) << " over "
	   << st.scans << " scans\n";
	if (st.scans == 0)
		os << "  worst scan: n/a (no scan saw a static cell)\n";
	else
		os << "  worst scan %: " << percent(st.worstShare) << " at scan "
		   << st.worstScan << " (" << fixedText(st.worstTime, 2) << " s), flagged cells (x,y m): "
		   << worstCells(st) << "\n";
}

void writeMotionKeyValues(
	std::ostream& os, const TScoreMotionOptions& options,
	const CMotionTruth& truth, const TScoreMotionRecord& run)
{
	const TReplayCounts& n = run.scans;
	const TMotionScore& s = run.score;
	const TStaticScore& st = s.statics;
	os << "input " << options.source.input << "\n"
	   << "poses " << run.poses << "\n"
	   << "config " << configDescription(options.source) << "\n"
	   << "truth " << truth.path() << "\n"
	   << "truth_scene " << truth.scene() << "\n"
	   << "truth_scans " << truth.scans().size() << "\n"
	   << "truth_grid " << truthGrid(truth.grid()) << "\n"
	   << "motion_window_s " << shortestText(run.motionWindow) << "\n"
	   << "tolerance_cells " << run.tolerance << "\n"
	   << "truth_times " << truthTimesName(options.truthTimes) << "\n"
	   << "traced_at " << run.tracedAt << "\n"
	   << "motion_frame " << motionFrameName(options.motionFrame) << "\n"
	   << "scans_total " << n.total << "\n"
	   << "scans_without_pose " << n.withoutPose << "\n"
	   << "scans_refused " << n.refused << "\n"
	   << "scans_scored " << n.scored << "\n"
	   << "observed_hit_cells " << s.hitCells << "\n"
	   << "observed_crossed_cells " << s.crossedCells << "\n";
	for (const auto& [prefix, kind] :
		 {std::pair{"appeared", &s.appeared},
		  std::pair{"disappeared", &s.disappeared}})
	{
		const TRatios r(*kind);
		os << prefix << "_truth " << kind->truth << "\n"
		   << prefix << "_recalled " << kind->recalled << "\n"
		   << prefix << "_predicted " << kind->predicted << "\n"
		   << prefix << "_true_positives " << kind->truePositives << "\n"
		   << prefix << "_map_cells " << kind->mapCells << "\n"
		   << prefix << "_precision " << text(r.precision) << "\n"
		   << prefix << "_recall " << text(r.recall) << "\n"
		   << prefix << "_f1 " << text(r.f1) << "\n";
	}
	os << "static_cells " << truth.staticCells().size() << "\n"
	   << "static_observed " << st.observed << "\n"
	   << "static_flagged " << st.flagged << "\n"
	   << "static_flagged_pct " << overallStaticPct(st) << "\n"
	   << "static_scans " << st.scans << "\n"
	   << "static_mean_pct " << meanStaticPct(st) << "\n"
	   << "static_worst_pct "
	   << (st.scans ? percent(st.worstShare) : "n/a") << "\n"
	   << "static_worst_scan "
	   << (st.scans ? std::to_string(st.worstScan) : "n/a") << "\n"
	   << "static_worst_time_s "
	   << (st.scans ? fixedText(st.worstTime, 2) : "n/a") << "\n"
	   << "static_worst_cells " << worstCells(st) << "\n";
}

}  // namespace evgrid
