/* evgrid compare: the report, on the console and as a `key value` file. */

#include "CompareReport.h"

#include <mrpt_evidential/support/NumberText.h>

#include <cstddef>
#include <iomanip>

#include "Report.h"

using mrpt_evidential::detail::shortestText;
using P = evgrid::TPerturbations;

namespace evgrid
{
namespace
{
/** Every number goes through fixedText() and these, so that the console and
 * the file show the same text. */
std::string percent(std::size_t part, std::size_t whole)
{
	if (whole == 0) return "n/a";
	return fixedText(
		100.0 * static_cast<double>(part) / static_cast<double>(whole), 2);
}
std::string mean(double sum, std::size_t n, int decimals)
{
	if (n == 0) return "n/a";
	return fixedText(sum / static_cast<double>(n), decimals);
}
std::string meanDistance(const TLocalizationScore& s)
{
	return mean(s.distanceSum, s.scans, 4);
}
std::string meanAngle(const TLocalizationScore& s)
{
	return mean(s.angleSumDeg, s.scans, 2);
}

/** "x -10.00 to 10.00 m, y -8.00 to 8.00 m" */
template <class MAP>
std::string extent(const MAP& map)
{
	return "x " + fixedText(map.getXMin(), 2) + " to " +
		fixedText(map.getXMax(), 2) + " m, y " + fixedText(map.getYMin(), 2) +
		" to " + fixedText(map.getYMax(), 2) + " m";
}

struct TDecisionRow
{
	const char* name;
	std::size_t TDecisionTally::*count;
};
constexpr TDecisionRow kDecisionRows[] = {
	{"occupied", &TDecisionTally::occupied},
	{"free", &TDecisionTally::free},
	{"unknown", &TDecisionTally::unknown},
	{"conflict", &TDecisionTally::conflict}};

void printTally(
	std::ostream& os, const char* what, double threshold, const char* relation,
	const TDecisionTally& tally)
{
	os << "  MRPT " << what << " (getCell " << relation << " "
	   << shortestText(threshold) << "): " << tally.total() << " cells";
	if (tally.total() == 0)
	{
		os << ", none to compare\n";
		return;
	}
	os << "; ours calls them\n";
	for (const TDecisionRow& row : kDecisionRows)
		os << "    " << std::left << std::setw(9) << row.name << std::right
		   << std::setw(12) << tally.*row.count << "  " << std::setw(6)
		   << percent(tally.*row.count, tally.total()) << "%\n";
}

void printLocalization(std::ostream& os, const TCompareRecord& run, int holdout)
{
	const double xy = P::kStepsXY * P::kStepXY;
	const double phi = P::kStepsPhi * P::kStepPhiDeg;
	os << "localization: every " << holdout
	   << "-th scan with a pose is held out of both maps and scored\n"
	   << "  at its pose p and at p + (dx, dy, dphi): dx, dy " << fixedText(-xy, 2)
	   << " to " << fixedText(xy, 2) << " m step " << fixedText(P::kStepXY, 2)
	   << ",\n  dphi " << shortestText(-phi) << " to " << shortestText(phi)
	   << " deg step " << shortestText(P::kStepPhiDeg) << ". A hit: the best "
		  "(first maximum;\n  dx outermost, dphi innermost) lies within "
	   << fixedText(P::kHitDistance, 2) << " m and "
	   << shortestText(P::kHitAngleDeg) << " deg of p.\n";
	if (run.ours.scans == 0)
	{
		os << "  no scan was held out (fewer than " << holdout
		   << " scans with a pose)\n";
		return;
	}
	const auto row = [&os](
						 const char* name, const std::string& ours,
						 const std::string& mrpt) {
		os << "  " << std::left << std::setw(22) << name << std::right
		   << std::setw(10) << ours << std::setw(10) << mrpt << "\n";
	};
	row("", "ours", "MRPT");
	row("held-out scans", std::to_string(run.ours.scans),
		std::to_string(run.mrpt.scans));
	row("hits", std::to_string(run.ours.hits), std::to_string(run.mrpt.hits));
	row("hit rate %", percent(run.ours.hits, run.ours.scans),
		percent(run.mrpt.hits, run.mrpt.scans));
	row("mean position error m", meanDistance(run.ours),
		meanDistance(run.mrpt));
	row("mean heading error deg", meanAngle(run.ours), meanAngle(run.mrpt));
}
}  // namespace

void printReport(
	std::ostream& os, const TCompareOptions& options,
	const CSideBySideMaps& maps, const TCompareRecord& run)
{
	const TSideBySideCounts& n = maps.counts();
	const auto& ours = maps.ours();
	const auto& mrpt = maps.mrpt();
	const TMapAgreement& a = run.agreement;
	os << kCompareName
	   << ": our evidential grid and MRPT's COccupancyGridMap2D, same scans, "
		  "same poses\n"
	   << "input: " << options.source.input << "\n"
	   << "poses: " << run.poses << "\n"
	   << "config: " << configDescription(options.source) << "\n"
	   << "MRPT's options: " << run.mrptOptions << "\n"
	   << "scans: " << n.total << " 2-D scans: " << n.withoutPose
	   << " without a pose, " << n.heldOut << " held out, " << n.offered
	   << " given to both maps (ours took " << n.oursInserted << ", MRPT "
	   << n.mrptInserted << ")\n"
	   << "grids (cells of " << shortestText(ours.getResolution())
	   << " m):\n"
	   << "  ours " << ours.getSizeX() << " x " << ours.getSizeY()
	   << " cells, " << extent(ours) << "\n"
	   << "  MRPT " << mrpt.getSizeX() << " x " << mrpt.getSizeY()
	   << " cells, " << extent(mrpt) << "\n\n"
	   << "static map: MRPT's " << a.mrptCells
	   << " cells, ours read at their centres (getCellDecision)\n";
	printTally(os, "occupied", kMrptOccupiedBelow, "<", a.mrptOccupied);
	if (a.mrptOccupied.total() > 0)
		os << "    occupied in ours within one cell (the cell or a neighbour): "
		   << a.mrptOccupiedNearOurs << "  "
		   << percent(a.mrptOccupiedNearOurs, a.mrptOccupied.total()) << "%\n";
	printTally(os, "free", kMrptFreeAbove, ">", a.mrptFree);
	os << "  MRPT neither: " << a.mrptUncertain
	   << " cells (never seen, or not certain enough)\n\n";
	printLocalization(os, run, options.holdout);
}

void writeKeyValues(
	std::ostream& os, const TCompareOptions& options,
	const CSideBySideMaps& maps, const TCompareRecord& run)
{
	const TSideBySideCounts& n = maps.counts();
	const TMapAgreement& a = run.agreement;
	os << "input " << options.source.input << "\n"
	   << "poses " << run.poses << "\n"
	   << "config " << configDescription(options.source) << "\n"
	   << "mrpt_options " << run.mrptOptions << "\n"
	   << "holdout " << options.holdout << "\n"
	   << "resolution " << shortestText(maps.ours().getResolution()) << "\n"
	   << "scans_total " << n.total << "\n"
	   << "scans_without_pose " << n.withoutPose << "\n"
	   << "scans_held_out " << n.heldOut << "\n"
	   << "scans_given_to_maps " << n.offered << "\n"
	   << "scans_inserted_ours " << n.oursInserted << "\n"
	   << "scans_inserted_mrpt " << n.mrptInserted << "\n"
	   << "mrpt_occupied_below " << shortestText(kMrptOccupiedBelow) << "\n"
	   << "mrpt_free_above " << shortestText(kMrptFreeAbove) << "\n"
	   << "mrpt_cells " << a.mrptCells << "\n"
	   << "mrpt_neither_cells " << a.mrptUncertain << "\n";
	for (const auto& [prefix, tally] :
		 {std::pair{"mrpt_occupied", &a.mrptOccupied},
		  std::pair{"mrpt_free", &a.mrptFree}})
	{
		os << prefix << "_cells " << tally->total() << "\n";
		for (const TDecisionRow& row : kDecisionRows)
			os << prefix << "_ours_" << row.name << " " << tally->*row.count
			   << "\n"
			   << prefix << "_ours_" << row.name << "_pct "
			   << percent(tally->*row.count, tally->total()) << "\n";
	}
	os << "mrpt_occupied_near_ours_occupied " << a.mrptOccupiedNearOurs << "\n"
	   << "mrpt_occupied_near_ours_occupied_pct "
	   << percent(a.mrptOccupiedNearOurs, a.mrptOccupied.total()) << "\n";
	for (const auto& [prefix, score] :
		 {std::pair{"ours", &run.ours}, std::pair{"mrpt", &run.mrpt}})
		os << prefix << "_localization_scans " << score->scans << "\n"
		   << prefix << "_hits " << score->hits << "\n"
		   << prefix << "_hit_rate_pct " << percent(score->hits, score->scans)
		   << "\n"
		   << prefix << "_mean_position_error_m " << meanDistance(*score)
		   << "\n"
		   << prefix << "_mean_heading_error_deg " << meanAngle(*score)
		   << "\n";
}

}  // namespace evgrid
