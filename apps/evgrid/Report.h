/* evgrid: what compare and score-motion share about their report: the
 * --quiet and --output options, where the report goes, and the text of its
 * numbers. One home, so that both commands behave and print alike. */
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <functional>
#include <ostream>
#include <string>

namespace evgrid
{
struct TReportOptions
{
	/** The `key value` file; empty: none. */
	std::string output;
	bool quiet = false;
};

/** The command-line options of TReportOptions (-q, --output), added to
 * `cmd`. */
class CReportArgs
{
   public:
	explicit CReportArgs(TCLAP::CmdLine& cmd);

	/** The values, after parse(). \throws UsageError for an empty --output. */
	TReportOptions values();

   private:
	TCLAP::SwitchArg m_quiet;
	TCLAP::ValueArg<std::string> m_output;
};

/** Writes the `key value` lines to options.output (if any), atomically, then
 * the console report to stdout unless options.quiet. */
void writeReport(
	const TReportOptions& options,
	const std::function<void(std::ostream&)>& keyValues,
	const std::function<void(std::ostream&)>& console);

/** `value` with `decimals` digits after the point ("%.*f"): every number a
 * report shows goes through this, so the console and the file agree. */
std::string fixedText(double value, int decimals);

}  // namespace evgrid
