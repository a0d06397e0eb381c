/* evgrid build: the settings of a run, as its command line gives them. */
#pragma once

#include <string>

#include "CGrowthRecorder.h"
#include "CPoseFile.h"

namespace evgrid
{
/** What messages and the summary call the subcommand. */
constexpr const char* kBuildName = "evgrid build";

struct TBuildOptions
{
	std::string input, outputDir;
	/** The map's .ini file and its section; no file: the map's defaults. */
	std::string config, section;
	/** A pose file; empty: the input's own poses. */
	std::string poses;
	CPoseFile::Kind posesKind = CPoseFile::Kind::Auto;
	/** Seconds, for pose files by time stamp. */
	double poseTolerance = 0.1;
	TGrowthOptions growth;
	bool quiet = false;
	/** The command line, quoted for a shell, as the summary shows it. */
	std::string commandLine;
};

}  // namespace evgrid
