/* evgrid merge: maps of the same place from several runs fused into one. */

#include <mrpt/typemeta/TEnumType.h>

#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>
#include <vector>

#include <mrpt_evidential/support/AtomicFile.h>
#include <mrpt_evidential/support/NumberText.h>
#include "COutputFolder.h"
#include "CommandLine.h"
#include "Commands.h"
#include "MapFiles.h"
#include "StopSignal.h"
#include "MapOutputs.h"

using mrpt_evidential::CEvidentialGridMap2D;
using mrpt_evidential::ConflictHandling;
using mrpt_evidential::FusionRule;

namespace evgrid
{
namespace
{
const std::string kName = "evgrid merge";

template <typename Enum>
Enum enumNamed(const std::string& option, const std::string& name)
{
	try
	{
		return mrpt::typemeta::TEnumType<Enum>::name2value(name);
	}
	catch (const std::exception&)
	{
		throw UsageError(option + ": unknown value '" + name + "'");
	}
}

void writeSummary(
	const std::string& path, const std::vector<std::string>& inputs,
	const std::vector<CEvidentialGridMap2D::Ptr>& maps, FusionRule rule,
	ConflictHandling handling, const CEvidentialGridMap2D& merged)
{
	mrpt_evidential::detail::writeFileAtomically(path, [&](std::ostream& os) {
		os << kName << " summary\n\ninputs:\n";
		for (std::size_t i = 0; i < maps.size(); ++i)
			os << "  " << inputs[i] << ": " << maps[i]->getSizeX() << " x " << maps[i]->getSizeY()
			   << " cells, " << maps[i]->insertionCount() << " insertions, latest time "
			   << mrpt_evidential::detail::shortestText(maps[i]->latestTime()) << " s\n";
		os << "rule: " << mrpt::typemeta::TEnumType<FusionRule>::value2name(rule)
		   << ", conflict handling: "
		   << mrpt::typemeta::TEnumType<ConflictHandling>::value2name(handling) << "\n\nmap:\n"
		   << merged.geometryText("  ");
		printDecisionCounts(os, merged.countDecisions(), merged.geometry().cellCount());
	});
}
}  // namespace

int runMerge(int argc, char** argv, int first)
{
	TCLAP::CmdLine cmd(
		"Fuses saved maps (map.evgrid) of the same place, from several runs or "
		"robots, into one, cell by cell, in the frame they share: the maps must "
		"have the same resolution and cells on the same lattice (origins a "
		"whole number of cells apart); their extents may differ. Writes into "
		"the output folder map.evgrid, its pictures and summary.txt; a failed "
		"run leaves the folder as it was. With the default Keep handling the "
		"conflict picture shows what changed between the runs. See "
		"doc/evgrid.md.",
		' ', EVGRID_VERSION);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors.", cmd, false);
	TCLAP::ValueArg<std::string> argHandling(
		"", "conflict-handling",
		"What a cell does with the conflict between the runs: Keep (default), "
		"ToUnknown or Normalize.",
		false, "Keep", "HANDLING", cmd);
	TCLAP::ValueArg<std::string> argRule(
		"", "rule",
		"Combination rule: Conjunctive (default), Dempster, Yager, DuboisPrade "
		"or Cautious (for runs that may share observations).",
		false, "Conjunctive", "RULE", cmd);
	TCLAP::ValueArg<std::string> argOut(
		"o", "output", "Required. Output folder (created if missing).", false, "", "DIR", cmd);
	TCLAP::UnlabeledMultiArg<std::string> argMaps(
		"maps", "Required. Two or more saved maps (.evgrid).", false, "MAP", cmd);

	if (const auto exitCode = parse(cmd, kName, argc, argv, first)) return *exitCode;
	const std::vector<std::string>& inputs = argMaps.getValue();
	for (const auto& path : inputs) requireMapFile(path);
	if (inputs.size() < 2) throw UsageError("give two or more maps to merge");
	// A run fused with itself counts its evidence twice.
	std::set<std::filesystem::path> seen;
	for (const auto& path : inputs)
		if (!seen.insert(std::filesystem::weakly_canonical(path)).second)
			throw UsageError(path + " is given twice: a run merged with itself counts its evidence twice");
	if (argOut.getValue().empty()) throw UsageError("missing the output folder: -o DIR");
	const auto rule = enumNamed<FusionRule>("--rule", argRule.getValue());
	const auto handling = enumNamed<ConflictHandling>("--conflict-handling", argHandling.getValue());

	catchStopSignals();
	COutputFolder out(argOut.getValue());
	std::vector<CEvidentialGridMap2D::Ptr> maps;
	for (const auto& path : inputs)
	{
		maps.push_back(loadMap(path));
		throwIfStopRequested();
	}
	CEvidentialGridMap2D merged = *maps.front();
	for (std::size_t i = 1; i < maps.size(); ++i)
	{
		throwIfStopRequested();
		try
		{
			merged.fuseMap(*maps[i], rule, handling);
		}
		catch (const std::invalid_argument& e)
		{
			throw std::runtime_error(inputs[i] + ": " + e.what() + " (" + inputs.front() + ")");
		}
	}

	throwIfStopRequested();
	saveMap(merged, out.staged("map.evgrid"));
	throwIfStopRequested();
	savePicturesIn(merged, out.stagingFolder());
	writeSummary(out.staged("summary.txt"), inputs, maps, rule, handling, merged);
	std::vector<std::string> results{"map.evgrid"};
	for (const char* name : CEvidentialGridMap2D::pictureNames()) results.emplace_back(name);
	results.emplace_back("summary.txt");
	out.commit(results);
	if (!argQuiet.getValue())
	{
		const auto d = merged.countDecisions();
		std::cout << kName << ": " << inputs.size() << " maps into " << merged.getSizeX() << " x "
				  << merged.getSizeY() << " cells; free " << d.free << ", occupied "
				  << d.occupied << ", unknown " << d.unknown << ", conflict " << d.conflict
				  << "\nwrote " << out.final("map.evgrid") << ", pictures and "
				  << out.final("summary.txt") << "\n";
	}
	return 0;
}

}  // namespace evgrid
