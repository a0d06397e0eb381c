/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * When every scene of evgrid-simulate scans. */
#pragma once

namespace mrpt_evidential::simulate
{
/** Scans a second. */
constexpr double kRate = 10.0;
/** Scan 0's timestamp, Unix seconds. Its fractional part keeps every time
 * in the ground truth off whole seconds, which is how MRPT's
 * pf-localization tells a column of times from a column of rawlog
 * indices. */
constexpr double kStartTime = 1700000000.05;

}  // namespace mrpt_evidential::simulate
