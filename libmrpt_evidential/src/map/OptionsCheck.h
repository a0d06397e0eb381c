/* mrpt-evidential: internal: the rules every option of a saved map obeys. */
#pragma once

#include <mrpt_evidential/EvidentialGridOptions.h>

namespace mrpt_evidential::detail
{
/** Checks the options a map writes with its cells by the rules reading them
 * back applies, the polar grid's at the grid's own `resolution` (their
 * validate() checks those for cells of 1 m): a map that writes them must be
 * able to read them, and a map read back must be able to insert.
 * \throws std::invalid_argument describing the first invalid one. */
inline void validateSavedOptions(
	const TEvidentialInsertionOptions& insertion, const TEvidentialLikelihoodOptions& likelihood,
	const TEvidentialRenderingOptions& rendering, double resolution)
{
	insertion.validate();
	likelihood.validate();
	rendering.validate();
	insertion.sourceGridOptions(resolution).validate();
}
}  // namespace mrpt_evidential::detail
