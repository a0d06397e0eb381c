/* evgrid: the options build and compare share: the input, the map's .ini
 * and the poses. */

#include "InputOptions.h"

#include <optional>
#include <utility>

#include "MapFiles.h"

using mrpt_evidential::CEvidentialGridMap2D;

namespace evgrid
{
// Members are initialized, hence added to `cmd`, in the order of their
// declaration: the tolerance first, the input last.
CInputArgs::CInputArgs(TCLAP::CmdLine& cmd)
	: m_tolerance(
		  "", "pose-tolerance",
		  "For pose files by time stamp: a scan farther than this from the "
		  "nearest pose of the file gets no pose and is skipped (and "
		  "counted). Seconds, default 0.1.",
		  false, 0.1, "SECONDS", cmd),
	  m_posesFormat(
		  "", "poses-format",
		  "How --poses is keyed: 'time' (lines 'time x y phi', e.g. MRPT "
		  "ground truth), 'step' (lines 'step x y phi', icp-slam's "
		  "log_estimated_path.txt) or 'auto' (step when the first column "
		  "counts up from 0 by one). Default: auto.",
		  false, "auto", "auto|time|step", cmd),
	  m_poses(
		  "p", "poses",
		  "Robot poses from this text file instead of the odometry (rawlog) "
		  "or the keyframe poses (simplemap). Lines 'key x y phi' in metres "
		  "and radians; see --poses-format.",
		  false, "", "FILE", cmd),
	  m_section(
		  "s", "section",
		  std::string("Section of the .ini that lists the maps (as "
					  "CMultiMetricMap reads it: evidentialGrid_count=1 and "
					  "[SECTION_evidentialGrid_00_creationOpts] etc.). "
					  "Default: ") +
			  kDefaultSection + ".",
		  false, kDefaultSection, "SECTION", cmd),
	  m_config(
		  "c", "config",
		  "The map's .ini file (e.g. rawlogs/evgrid.ini); without it the map "
		  "takes its built-in defaults (0.10 m cells).",
		  false, "", "FILE.ini", cmd),
	  m_input(
		  "i", "input",
		  "Required. Rawlog (.rawlog, .rawlog.gz) or simplemap (.simplemap, "
		  ".simplemap.gz); the kind is read from the file's content.",
		  false, "", "FILE", cmd)
{
}

TInputOptions CInputArgs::values()
{
	if (m_input.getValue().empty())
		throw UsageError("missing the input: -i FILE (a rawlog or simplemap)");
	TInputOptions options;
	options.input = m_input.getValue();
	options.config = m_config.getValue();
	options.section = m_section.getValue();
	options.poses = m_poses.getValue();
	options.poseTolerance = m_tolerance.getValue();

	options.posesKind = oneOf<CPoseFile::Kind>(
		"--poses-format", m_posesFormat.getValue(),
		{{"auto", CPoseFile::Kind::Auto},
		 {"time", CPoseFile::Kind::Time},
		 {"step", CPoseFile::Kind::Step}});
	if (m_posesFormat.isSet() && options.poses.empty())
		throw UsageError("--poses-format needs --poses");
	if (!(options.poseTolerance >= 0.0))
		throw UsageError("--pose-tolerance must be >= 0 seconds");
	return options;
}

std::unique_ptr<CEvidentialGridMap2D> createMap(const TInputOptions& options)
{
	if (options.config.empty()) return std::make_unique<CEvidentialGridMap2D>();
	return createMapFromConfig(options.config, options.section);
}

CPoseSource createPoseSource(const TInputOptions& options)
{
	std::optional<CPoseFile> file;
	if (!options.poses.empty())
		file = CPoseFile::load(options.poses, options.posesKind);
	return CPoseSource(std::move(file), options.poseTolerance);
}

std::string configDescription(const TInputOptions& options)
{
	if (options.config.empty()) return "none (the map's defaults)";
	return options.config + ", section [" + options.section + "]";
}

}  // namespace evgrid
