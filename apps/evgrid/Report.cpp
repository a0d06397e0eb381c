/* evgrid: what compare and score-motion share about their report. */

#include "Report.h"

#include <mrpt_evidential/support/AtomicFile.h>

#include <cstdio>
#include <iostream>

#include "CommandLine.h"

namespace evgrid
{
CReportArgs::CReportArgs(TCLAP::CmdLine& cmd)
	: m_quiet(
		  "q", "quiet",
		  "Print nothing but errors (the report goes only to --output).", cmd,
		  false),
	  m_output(
		  "", "output",
		  "Also write the report's numbers to this file as 'key value' lines, "
		  "atomically (a failed run leaves an earlier file as it was).",
		  false, "", "FILE", cmd)
{
}

TReportOptions CReportArgs::values()
{
	TReportOptions options;
	options.output = m_output.getValue();
	if (m_output.isSet() && options.output.empty())
		throw UsageError("--output needs a non-empty value");
	options.quiet = m_quiet.getValue();
	return options;
}

void writeReport(
	const TReportOptions& options,
	const std::function<void(std::ostream&)>& keyValues,
	const std::function<void(std::ostream&)>& console)
{
	if (!options.output.empty())
		mrpt_evidential::detail::writeFileAtomically(options.output, keyValues);
	if (!options.quiet) console(std::cout);
}

std::string fixedText(double value, int decimals)
{
	char text[64];
	std::snprintf(text, sizeof(text), "%.*f", decimals, value);
	return text;
}

}  // namespace evgrid
