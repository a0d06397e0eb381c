/* mrpt-evidential: Dempster-Shafer occupancy grids for MRPT.
 * What the motion layer says of a cell. */
#pragma once

namespace mrpt_evidential
{
/** As of the latest insertion, within the map's motionWindow of data time:
 * something appeared in the cell (seen free before, occupied now), left it
 * (seen occupied before, free now), or neither. */
enum class Motion
{
	None,
	Appeared,
	Disappeared
};

/** "None", "Appeared" or "Disappeared". */
inline const char* motionName(Motion m) noexcept
{
	switch (m)
	{
		case Motion::Appeared: return "Appeared";
		case Motion::Disappeared: return "Disappeared";
		case Motion::None: break;
	}
	return "None";
}

}  // namespace mrpt_evidential
