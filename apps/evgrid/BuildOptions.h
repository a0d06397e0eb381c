/* evgrid build: the settings of a run, as its command line gives them. */
#pragma once

#include <string>

#include "CGrowthRecorder.h"
#include "InputOptions.h"

namespace evgrid
{
/** What messages and the summary call the subcommand. */
constexpr const char* kBuildName = "evgrid build";
/** The scene evgrid build writes beside the map: the map and the path. */
constexpr const char* kSceneName = "map.3Dscene";

struct TBuildOptions
{
	TInputOptions source;
	std::string outputDir;
	TGrowthOptions growth;
	bool quiet = false;
	/** The command line, quoted for a shell, as the summary shows it. */
	std::string commandLine;
};

}  // namespace evgrid
