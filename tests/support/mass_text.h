/* Masses as text, for failure messages of the tests and the fuzz targets
 * (no GoogleTest, no MRPT: the algebra alone). */
#pragma once

#include <mrpt_evidential/algebra/Mass.h>

#include <ostream>

namespace mrpt_evidential
{
inline std::ostream& operator<<(std::ostream& os, const Mass& m)
{
	return os << "{conflict " << m.conflict << ", free " << m.free
			  << ", occupied " << m.occupied << ", unknown " << m.unknown << "}";
}
}  // namespace mrpt_evidential
