/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * The first invalid value of an options struct. Every options struct of the
 * library has one firstInvalid() that holds its rules; validate(), the .ini
 * loaders and the deserializer report what it finds. Standard library only;
 * shared by the grid, scan and map layers. */
#pragma once

#include <string>

namespace mrpt_evidential
{
struct TInvalidOption
{
	/** The field's name, also its .ini key. */
	std::string key;
	/** What it must be, e.g. "in [0, 1]". */
	std::string rule;
	/** Its value, in the struct's units. */
	double value = 0.0;

	/** "key must be rule, got value" (the value's shortest exact text). */
	std::string describe() const;
};
}  // namespace mrpt_evidential
