/* evgrid diff: what appeared and what disappeared between two runs of the
 * same place. */

#include <mrpt/img/CImage.h>

#include <iomanip>
#include <iostream>
#include <stdexcept>

#include <mrpt_evidential/support/AtomicFile.h>
#include <mrpt_evidential/support/NumberText.h>
#include "COutputFolder.h"
#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"
#include "StopSignal.h"

using mrpt_evidential::CEvidentialGridMap2D;
using mrpt_evidential::detail::writeFileAtomically;

namespace evgrid
{
namespace
{
const std::string kName = "evgrid diff";

/** "x y" of each cell's centre, one per line: what
 * CSimplePointsMap::load2D_from_text_file() reads. */
void writePoints(
	const std::string& path, const CEvidentialGridMap2D& map, const std::vector<std::size_t>& cells)
{
	writeFileAtomically(path, [&](std::ostream& os) {
		const auto& g = map.geometry();
		const auto sx = static_cast<std::size_t>(g.sizeX);
		os << std::fixed << std::setprecision(4);
		for (const std::size_t idx : cells)
			os << g.cellCenterX(static_cast<int>(idx % sx)) << ' '
			   << g.cellCenterY(static_cast<int>(idx / sx)) << '\n';
	});
}
}  // namespace

int runDiff(int argc, char** argv, int first)
{
	TCLAP::CmdLine cmd(
		"What changed between two saved maps (map.evgrid) of the same place: "
		"the cells both runs saw where something appeared (free in EARLIER, "
		"occupied in LATER) or disappeared, ignoring changes next to what "
		"stands in both (walls seen with two runs' pose errors). Writes "
		"changes.png (LATER in grey, appeared orange, disappeared teal, with a legend), "
		"appeared.txt and disappeared.txt (x y of each cell's centre, one per "
		"line) and summary.txt into the output folder; a failed run leaves "
		"the folder as it was. The maps must have the same resolution and "
		"cells on the same lattice. See doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors.", cmd, false);
	TCLAP::ValueArg<double> argClearance(
		"", "clearance",
		"Metres: a change this close to a cell occupied in both runs is taken "
		"for pose error. In [0, 10], default 0.1.",
		false, 0.1, "M", cmd);
	TCLAP::ValueArg<double> argMinConflict(
		"", "min-conflict",
		"Least conflict of one cause, m_earlier(F) m_later(O) or m_earlier(O) "
		"m_later(F), for a change. In (0, 1], default 0.5.",
		false, 0.5, "K", cmd);
	TCLAP::ValueArg<std::string> argOut(
		"o", "output", "Required. Output folder (created if missing).", false, "", "DIR", cmd);
	TCLAP::UnlabeledMultiArg<std::string> argMaps(
		"maps", "Required. EARLIER and LATER, the two runs' saved maps (.evgrid).", false,
		"MAP", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first)) return *exitCode;
	const std::vector<std::string>& maps = argMaps.getValue();
	for (const auto& path : maps) requireMapFile(path);
	if (maps.size() != 2)
		throw UsageError("give the two maps to compare, EARLIER and LATER");
	const std::string& earlierPath = maps[0];
	const std::string& laterPath = maps[1];
	if (argOut.getValue().empty()) throw UsageError("missing the output folder: -o DIR");
	const double minConflict = argMinConflict.getValue(), clearance = argClearance.getValue();
	if (!(minConflict > 0.0 && minConflict <= 1.0))
		throw UsageError("--min-conflict must be in (0, 1], got " + mrpt_evidential::detail::shortestText(minConflict));
	if (!(clearance >= 0.0 && clearance <= 10.0))
		throw UsageError("--clearance must be in [0, 10], got " + mrpt_evidential::detail::shortestText(clearance));

	catchStopSignals();
	COutputFolder out(argOut.getValue());
	const auto earlier = loadMap(earlierPath);
	throwIfStopRequested();
	const auto later = loadMap(laterPath);
	throwIfStopRequested();
	CEvidentialGridMap2D::TMapChanges changes;
	try
	{
		changes = later->changesSince(*earlier, minConflict, clearance);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(laterPath + ": " + e.what() + " (" + earlierPath + ")");
	}

	throwIfStopRequested();
	mrpt::img::CImage img;
	later->getAsChangesImage(changes, img, true);
	if (!img.saveToFile(out.staged("changes.png")))
		throw std::runtime_error(out.staged("changes.png") + ": cannot write");
	writePoints(out.staged("appeared.txt"), *later, changes.appeared);
	writePoints(out.staged("disappeared.txt"), *later, changes.disappeared);
	writeFileAtomically(out.staged("summary.txt"), [&](std::ostream& os) {
		os << kName << " summary\n\nearlier: " << earlierPath
		   << "\nlater: " << laterPath << "\nmin conflict: " << minConflict
		   << ", clearance: " << clearance << " m\ncells both runs saw: " << changes.compared
		   << "\nappeared: " << changes.appeared.size()
		   << " cells\ndisappeared: " << changes.disappeared.size() << " cells\n";
	});
	out.commit({"changes.png", "appeared.txt", "disappeared.txt", "summary.txt"});
	// "Nothing changed" and "nothing compared" read the same in the counts.
	if (changes.compared == 0)
		std::cerr << kName
				  << ": warning: no cell was seen by both runs: the maps cover different "
					 "places, and nothing was compared\n";
	if (!argQuiet.getValue())
		std::cout << kName << ": " << changes.compared << " cells seen by both runs; appeared "
				  << changes.appeared.size() << ", disappeared " << changes.disappeared.size()
				  << "\nwrote " << out.final("changes.png") << ", appeared.txt, disappeared.txt, "
				  << out.final("summary.txt") << "\n";
	return 0;
}

}  // namespace evgrid
