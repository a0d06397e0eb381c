/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT. */
#include <mrpt_evidential/TInvalidOption.h>
#include <mrpt_evidential/support/NumberText.h>

namespace mrpt_evidential
{
std::string TInvalidOption::describe() const
{
	return key + " must be " + rule + ", got " + detail::shortestText(value);
}
}  // namespace mrpt_evidential
