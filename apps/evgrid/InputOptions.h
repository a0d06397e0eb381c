/* evgrid: the options build and compare share: the input, the map's .ini
 * and the poses. */
#pragma once

#include <mrpt_evidential/CEvidentialGridMap2D.h>

#include <memory>
#include <string>

#include "CPoseFile.h"
#include "CPoseSource.h"
#include "CommandLine.h"

namespace evgrid
{
struct TInputOptions
{
	/** The rawlog or simplemap. */
	std::string input;
	/** The map's .ini file and its section; no file: the map's defaults. */
	std::string config, section;
	/** A pose file; empty: the input's own poses. */
	std::string poses;
	CPoseFile::Kind posesKind = CPoseFile::Kind::Auto;
	/** Seconds, for pose files by time stamp. */
	double poseTolerance = 0.1;
};

/** The command-line options of TInputOptions (-i, -c, -s, -p,
 * --poses-format, --pose-tolerance), added to `cmd`. TCLAP's --help lists
 * the options added last first: create this after the subcommand's own
 * options, so that the input comes first. */
class CInputArgs
{
   public:
	explicit CInputArgs(TCLAP::CmdLine& cmd);

	/** The values, after parse(). \throws UsageError for a missing input
	 *  and values that make no sense. */
	TInputOptions values();

   private:
	TCLAP::ValueArg<double> m_tolerance;
	TCLAP::ValueArg<std::string> m_posesFormat, m_poses, m_section, m_config,
		m_input;
};

/** The map the options ask for: from the .ini, or with the map's defaults.
 * \throws std::runtime_error as createMapFromConfig(). */
std::unique_ptr<mrpt_evidential::CEvidentialGridMap2D> createMap(
	const TInputOptions& options);

/** The pose source, with the pose file loaded if there is one.
 * \throws std::runtime_error as CPoseFile::load(). */
CPoseSource createPoseSource(const TInputOptions& options);

/** "none (the map's defaults)" or "FILE, section [SECTION]". */
std::string configDescription(const TInputOptions& options);

}  // namespace evgrid
