/* evgrid compare: the report, on the console and as a `key value` file. */
#pragma once

#include <ostream>
#include <string>

#include "CompareOptions.h"
#include "CSideBySideMaps.h"
#include "LocalizationTest.h"
#include "MapAgreement.h"

namespace evgrid
{
/** Everything a finished run reports. */
struct TCompareRecord
{
	/** CPoseSource::description() */
	std::string poses;
	/** Where MRPT's grid took its insertion and likelihood options. */
	std::string mrptOptions;
	TMapAgreement agreement;
	TLocalizationScore ours, mrpt;
};

/** The human-readable report. */
void printReport(
	std::ostream& os, const TCompareOptions& options,
	const CSideBySideMaps& maps, const TCompareRecord& run);

/** The same numbers as `key value` lines, the same text for each number;
 * "n/a" for a share or mean of nothing. */
void writeKeyValues(
	std::ostream& os, const TCompareOptions& options,
	const CSideBySideMaps& maps, const TCompareRecord& run);

}  // namespace evgrid
